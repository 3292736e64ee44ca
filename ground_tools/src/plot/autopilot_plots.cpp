// The autopilot figures of `tolip plot` (plot.hpp autopilot_figures): the designed gains and the
// margins at the actuator against time, from the member "autopilot" (docs/cli.md; issue 16).
#include <limits>
#include <string>

#include "plot_json.hpp"
#include "tolip_ground/plot.hpp"

namespace tolip::ground {
namespace {

// The result-document accessors (json, fail, required, required_array, ...): plot_json.hpp.
using namespace plot_json;

}  // namespace

std::vector<Figure> autopilot_figures(const nlohmann::json& document) {
  std::vector<Figure> figures;
  const json* autopilot = optional_object(document, "autopilot");
  if (autopilot == nullptr) return figures;
  const json& points = required_array(*autopilot, "points", "autopilot");
  if (points.empty()) return figures;
  auto series = [](const char* title, bool second_axis) {
    PlotSeries s;
    s.title = title;
    s.style = SeriesStyle::kLinesPoints;
    s.second_axis = second_axis;
    return s;
  };
  PlotSeries k_theta = series("K_theta (deg/deg)", false);
  PlotSeries k_q = series("K_q (s)", true);
  PlotSeries gain_margin = series("upper gain margin (dB)", false);
  PlotSeries phase_margin = series("phase margin (deg)", true);
  int previous_stage = -1;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::string field = "autopilot.points[" + std::to_string(i) + "]";
    const json& p = points[i];
    if (!p.is_object()) fail(field, "an object", p);
    const json& stage = required(p, "stage", field);
    if (!stage.is_number_integer()) fail(field + ".stage", "an integer", stage);
    if (previous_stage >= 0 && stage.get<int>() != previous_stage) {
      // A gap between stages: the schedule does not interpolate across a staging.
      const double nan = std::numeric_limits<double>::quiet_NaN();
      for (PlotSeries* s : {&k_theta, &k_q, &gain_margin, &phase_margin}) {
        s->x.push_back(nan);
        s->y.push_back(nan);
      }
    }
    previous_stage = stage.get<int>();
    const double t = number_or_gap(p, "time_s", field);
    k_theta.x.push_back(t);
    k_theta.y.push_back(number_or_gap(p, "k_theta", field));
    k_q.x.push_back(t);
    k_q.y.push_back(number_or_gap(p, "k_q_s", field));
    gain_margin.x.push_back(t);
    gain_margin.y.push_back(number_or_gap(p, "upper_gain_margin_db", field));
    phase_margin.x.push_back(t);
    phase_margin.y.push_back(number_or_gap(p, "phase_margin_deg", field));
  }
  Figure gains;
  gains.name = "autopilot_gains";
  gains.title = "Designed autopilot gains along the trajectory";
  gains.x_label = "time from launch (s)";
  gains.y_label = "K_theta (deg/deg)";
  gains.y2_label = "K_q (s)";
  gains.series = {std::move(k_theta), std::move(k_q)};
  figures.push_back(std::move(gains));
  Figure margins;
  margins.name = "autopilot_margins";
  margins.title = "Autopilot margins at the actuator";
  margins.x_label = "time from launch (s)";
  margins.y_label = "upper gain margin (dB)";
  margins.y2_label = "phase margin (deg)";
  margins.series = {std::move(gain_margin), std::move(phase_margin)};
  figures.push_back(std::move(margins));
  return figures;
}

}  // namespace tolip::ground
