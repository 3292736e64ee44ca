// Number formatting shared by the reports.
#include "number_format.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace tolip::ground::report_detail {

std::string round_trip(double value) {
  if (!std::isfinite(value)) return {};
  char buffer[64];
  const std::to_chars_result result = std::to_chars(buffer, buffer + sizeof buffer, value);
  if (result.ec != std::errc()) return {};
  return std::string(buffer, result.ptr);
}

std::string fixed_cell(double value, int decimals, int width) {
  if (!std::isfinite(value)) return std::string(static_cast<std::size_t>(width - 1), ' ') + "-";
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "%*.*f", width, decimals, value);
  if (static_cast<int>(std::strlen(buffer)) > width || buffer[0] != ' ') {
    // Too wide for the column: scientific notation with as many digits as fit.
    const int precision = width >= 11 ? width - 8 : 1;  // "-d.ddde+XX" plus the separator
    std::snprintf(buffer, sizeof buffer, "%*.*E", width, precision, value);
  }
  return buffer;
}

nlohmann::ordered_json json_number(double value) {
  return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr);
}

std::string right_aligned(const std::string& text, int width) {
  if (static_cast<int>(text.size()) >= width) return text;
  return std::string(static_cast<std::size_t>(width) - text.size(), ' ') + text;
}

std::string left_aligned(const std::string& text, int width) {
  if (static_cast<int>(text.size()) >= width) return text;
  return text + std::string(static_cast<std::size_t>(width) - text.size(), ' ');
}

std::string card_text(const char* text, int capacity) {
  std::size_t length = 0;
  while (length < static_cast<std::size_t>(capacity) && text[length] != '\0') ++length;
  while (length > 0 && (text[length - 1] == ' ' || text[length - 1] == '\t')) --length;
  return std::string(text, length);
}

std::string card_text(const std::string& text) {
  return card_text(text.c_str(), static_cast<int>(text.size()));
}

}  // namespace tolip::ground::report_detail
