// What the commands that run every case of a deck (simulate, optimize) share: the per-case name
// of an output file and the prefix of a case's diagnostics. Internal to ground_tools/src/commands.
#pragma once

#include <cstddef>
#include <string>

namespace tolip::ground {

// FILE for a deck of one case; for several, FILE with ".caseN" before the extension
// ("points.csv" -> "points.case2.csv", "points" -> "points.case2").
std::string case_file_path(const std::string& path, int case_number, std::size_t cases);

// "case N: " before a case's diagnostics when the deck has several cases, "" otherwise (a
// one-case deck keeps the messages it always had).
std::string case_message_prefix(int case_number, std::size_t cases);

}  // namespace tolip::ground
