// Reading a result document for `tolip plot`: the few accessors every figure family uses, each
// fault named by its field path (PlotDataError, plot.hpp). Written once here; the figure files
// (hardover_plots.cpp, radar_plots.cpp, autopilot_plots.cpp, impact_plot.cpp, plot_catalogue.cpp)
// include it.
#pragma once

#include <limits>
#include <string>

#include "tolip_ground/plot.hpp"

namespace tolip::ground::plot_json {

using json = nlohmann::json;

// A value of the wrong JSON type at `field`.
[[noreturn]] inline void fail(const std::string& field, const std::string& expected, const json& found) {
  throw PlotDataError(field + ": expected " + expected + ", found " + found.type_name());
}

// The member `key` of `object` (at `field`), which must be present.
inline const json& required(const json& object, const char* key, const std::string& field) {
  const auto it = object.find(key);
  if (it == object.end()) throw PlotDataError(field + ": no member '" + key + "'");
  return *it;
}

// A required number; null (the reports write null for a non-finite value) gives a gap (NaN).
inline double number_or_gap(const json& object, const char* key, const std::string& field) {
  const json& value = required(object, key, field);
  if (value.is_null()) return std::numeric_limits<double>::quiet_NaN();
  if (!value.is_number()) fail(field + "." + key, "a number or null", value);
  return value.get<double>();
}

// The member `key` of a result document that a figure family draws: nullptr when the document has
// none (absent or null: no figure, not an error); else it must be an object.
inline const json* optional_object(const json& document, const char* key) {
  const auto it = document.find(key);
  if (it == document.end() || it->is_null()) return nullptr;
  if (!it->is_object()) fail(key, "an object", *it);
  return &*it;
}

// The member `key` of `object` (at `field`), which must be present and an array.
inline const json& required_array(const json& object, const char* key, const std::string& field) {
  const json& value = required(object, key, field);
  if (!value.is_array()) fail(field + "." + key, "an array", value);
  return value;
}

}  // namespace tolip::ground::plot_json
