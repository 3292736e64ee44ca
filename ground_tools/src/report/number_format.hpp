// Number formatting shared by the reports (private to ground_tools/src/report).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace tolip::ground::report_detail {

// Shortest text that reads back to the same double ("" for a non-finite value).
std::string round_trip(double value);

// Right-aligned in `width` characters with `decimals` fixed decimals; when that does not fit in
// width - 1 characters (one blank separates columns) the value is printed in E format instead.
// Non-finite values print as "-".
std::string fixed_cell(double value, int decimals, int width);

// A finite value as a JSON number, anything else as null (JSON has no NaN or infinity).
nlohmann::ordered_json json_number(double value);

// `text` padded with blanks to `width` characters: on the left (right_aligned) or on the right
// (left_aligned); a text of `width` characters or more is returned unchanged.
std::string right_aligned(const std::string& text, int width);
std::string left_aligned(const std::string& text, int width);

// Copies a fixed, NUL-padded card field (title, heading, date) and strips trailing blanks.
std::string card_text(const char* text, int capacity);
std::string card_text(const std::string& text);  // the same for a text the deck reader kept

}  // namespace tolip::ground::report_detail
