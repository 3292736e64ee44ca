// The impact-locus figure (impact_plot.hpp).
#include "impact_plot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "plot_json.hpp"
#include "plot_map.hpp"

namespace tolip::ground::plot_detail {
namespace {

using json = nlohmann::json;

constexpr double kGap = std::numeric_limits<double>::quiet_NaN();

using plot_json::fail;
// A number of an object; null (a non-finite value) gives a gap; anything else is malformed.
double number_at(const json& object, const char* key, const std::string& field) {
  const auto it = object.find(key);
  if (it == object.end()) throw PlotDataError(field + "." + key + ": missing");
  if (it->is_null()) return kGap;
  if (!it->is_number()) fail(field + "." + key, "a number or null", *it);
  return it->get<double>();
}

}  // namespace

std::optional<Figure> impact_locus_figure(const json& document) {
  const auto impact = document.find("impact");
  if (impact == document.end() || !impact->is_object()) return std::nullopt;
  const auto cases = impact->find("cases");
  if (cases == impact->end()) return std::nullopt;
  if (!cases->is_array()) fail("impact.cases", "an array", *cases);
  if (cases->empty()) return std::nullopt;

  Figure figure;
  figure.name = "impact_locus";
  figure.title = "Impact locus (thrust failure and expended casings)";
  figure.x_label = "longitude (deg east)";
  figure.y_label = "geodetic latitude (deg north)";

  // The nominal's ground track, broken where it crosses the 180 deg meridian.
  PlotSeries track;
  track.title = "nominal ground track";
  track.color = 8;
  const auto points = document.find("trajectory");
  if (points != document.end() && points->is_array()) {
    for (std::size_t i = 0; i < points->size(); ++i) {
      const std::string field = "trajectory[" + std::to_string(i) + "]";
      const json& p = (*points)[i];
      if (!p.is_object()) fail(field, "an object", p);
      const double lon = number_at(p, "longitude_deg", field);
      const double lat = number_at(p, "geodetic_latitude_deg", field);
      if (!track.x.empty() && std::fabs(lon - track.x.back()) > 180.0) {
        track.x.push_back(kGap);
        track.y.push_back(kGap);
      }
      track.x.push_back(lon);
      track.y.push_back(lat);
    }
  }

  // One series per stage and failure kind: a filled circle for a thrust failure, a filled triangle
  // for an expended casing, the stage's colour for both.
  PlotSeries series[2][3];
  for (int kind = 0; kind < 2; ++kind) {
    for (int stage = 1; stage <= 3; ++stage) {
      PlotSeries& s = series[kind][stage - 1];
      s.title = std::string(kind == 0 ? "thrust failure, stage " : "expended casing, stage ") +
                std::to_string(stage);
      s.style = SeriesStyle::kPoints;
      s.point_type = kind == 0 ? 7 : 9;
      s.color = stage;
    }
  }
  for (std::size_t i = 0; i < cases->size(); ++i) {
    const std::string field = "impact.cases[" + std::to_string(i) + "]";
    const json& c = (*cases)[i];
    if (!c.is_object()) fail(field, "an object", c);
    const auto kind = c.find("kind");
    const auto stage = c.find("stage");
    if (kind == c.end() || !kind->is_string()) throw PlotDataError(field + ".kind: expected a string");
    if (stage == c.end() || !stage->is_number_integer())
      throw PlotDataError(field + ".stage: expected an integer");
    const int k = kind->get<std::string>() == "thrust_failure" ? 0 : 1;
    const long s = stage->get<long>();
    if (s < 1 || s > 3) throw PlotDataError(field + ".stage: expected 1-3");
    if (c.find("longitude_deg") == c.end()) continue;  // not computed (its status says why)
    series[k][s - 1].x.push_back(number_at(c, "longitude_deg", field));
    series[k][s - 1].y.push_back(number_at(c, "geodetic_latitude_deg", field));
  }

  // The launch site, and a map of true shape around everything drawn.
  plot_map::MapBounds bounds;
  const auto site = impact->find("launch_site");
  if (site != impact->end() && site->is_object()) {
    const double lat = number_at(*site, "geodetic_latitude_deg", "impact.launch_site");
    const double lon = number_at(*site, "longitude_deg", "impact.launch_site");
    figure.points.push_back({lon, lat, "launch site " + plot_map::place_text(lat, lon), 0});
    bounds.extend(lon, lat);
  }
  for (const auto& row : series) {
    for (const PlotSeries& s : row) {
      for (std::size_t i = 0; i < s.x.size(); ++i) bounds.extend(s.x[i], s.y[i]);
    }
  }
  // The track only where it is near the impacts (an orbit's track would dwarf them).
  plot_map::frame_map(bounds, 0.1, &figure);
  if (!track.x.empty()) figure.series.push_back(std::move(track));
  for (auto& row : series) {
    for (PlotSeries& s : row) {
      if (!s.x.empty()) figure.series.push_back(std::move(s));
    }
  }
  return figure;
}

}  // namespace tolip::ground::plot_detail
