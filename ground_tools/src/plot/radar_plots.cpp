// The radar figures of `tolip plot` (plot.hpp radar_figures): one per station of the member
// "radar" (docs/cli.md), azimuth and elevation against time from launch.
#include <cctype>
#include <cmath>
#include <limits>
#include <string>

#include "plot_json.hpp"
#include "tolip_ground/plot.hpp"

namespace tolip::ground {
namespace {

constexpr double kGap = std::numeric_limits<double>::quiet_NaN();

// The result-document accessors (json, fail, required, required_array, ...): plot_json.hpp.
using namespace plot_json;

std::string file_stem(const std::string& id) {
  std::string stem = "radar_";
  for (const char c : id) {
    const unsigned char u = static_cast<unsigned char>(c);
    stem += std::isalnum(u) ? static_cast<char>(std::tolower(u)) : '_';
  }
  return stem;
}

}  // namespace

std::vector<Figure> radar_figures(const nlohmann::json& document) {
  std::vector<Figure> figures;
  const json* radar = optional_object(document, "radar");
  if (radar == nullptr) return figures;
  const json& stations = required_array(*radar, "stations", "radar");
  for (std::size_t s = 0; s < stations.size(); ++s) {
    const std::string field = "radar.stations[" + std::to_string(s) + "]";
    const json& station = stations[s];
    if (!station.is_object()) fail(field, "an object", station);
    const json& id = required(station, "id", field);
    if (!id.is_string()) fail(field + ".id", "a string", id);
    const json& points = required_array(station, "points", field);
    if (points.empty()) continue;

    PlotSeries azimuth, above, below;
    azimuth.title = "azimuth (left axis)";
    above.title = "elevation (right axis)";
    above.second_axis = true;
    below.title = "elevation below the horizon (right axis)";
    below.second_axis = true;
    below.dash_type = 2;
    bool any_above = false, any_below = false;
    double previous_azimuth = kGap, previous_elevation = kGap, previous_time = kGap;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const std::string at = field + ".points[" + std::to_string(i) + "]";
      const json& point = points[i];
      if (!point.is_object()) fail(at, "an object", point);
      const double t = number_or_gap(point, "time_s", at);
      const double az = number_or_gap(point, "azimuth_deg", at);
      const double el = number_or_gap(point, "elevation_deg", at);
      // The azimuth wraps at north: break the line there rather than draw a jump across the plot.
      if (std::fabs(az - previous_azimuth) > 180.0) {
        azimuth.x.push_back(kGap);
        azimuth.y.push_back(kGap);
      }
      azimuth.x.push_back(t);
      azimuth.y.push_back(az);
      // Above and below the horizon as two curves that meet where the elevation crosses zero.
      const bool is_above = el >= 0.0;
      if (std::isfinite(previous_elevation) && (previous_elevation >= 0.0) != is_above && std::isfinite(el)) {
        const double crossing =
            previous_time + (t - previous_time) * previous_elevation / (previous_elevation - el);
        for (PlotSeries* series : {&above, &below}) {
          series->x.push_back(crossing);
          series->y.push_back(0.0);
        }
      }
      above.x.push_back(t);
      above.y.push_back(is_above ? el : kGap);
      below.x.push_back(t);
      below.y.push_back(is_above || !std::isfinite(el) ? kGap : el);
      any_above = any_above || (is_above && std::isfinite(el));
      any_below = any_below || (!is_above && std::isfinite(el));
      previous_azimuth = az;
      previous_elevation = el;
      previous_time = t;
    }

    Figure figure;
    figure.name = file_stem(id.get<std::string>());
    std::string name;
    if (const auto n = station.find("name"); n != station.end() && n->is_string())
      name = n->get<std::string>();
    figure.title = "Radar station " + id.get<std::string>() + (name.empty() ? "" : " (" + name + ")") +
                   ": azimuth and elevation";
    figure.x_label = "time from launch (s)";
    figure.y_label = "azimuth (deg, clockwise from north)";
    figure.y2_label = "elevation (deg)";
    figure.y_min = 0.0;
    figure.y_max = 360.0;
    figure.series.push_back(std::move(azimuth));
    if (any_above) figure.series.push_back(std::move(above));
    if (any_below) figure.series.push_back(std::move(below));
    figure.y_lines.push_back({0.0, true, "horizon (right axis: 0 deg)"});
    figures.push_back(std::move(figure));
  }
  return figures;
}

}  // namespace tolip::ground
