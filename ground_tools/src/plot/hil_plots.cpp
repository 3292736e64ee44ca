// The HIL bench figures of `tolip plot` (plot.hpp hil_figures): from the member "hil_series" of a
// `tolip hil --json` document (docs/cli.md): commanded against flown theta, the attitude tracking
// error, the actuator positions, against time from lift-off.
#include <string>

#include "tolip_ground/plot.hpp"

namespace tolip::ground {
namespace {

using json = nlohmann::json;

std::vector<double> column(const json& series, const char* key) {
  const auto it = series.find(key);
  if (it == series.end()) throw PlotDataError(std::string("hil_series: no member '") + key + "'");
  if (!it->is_array()) throw PlotDataError(std::string("hil_series.") + key + ": expected an array");
  std::vector<double> values;
  for (std::size_t i = 0; i < it->size(); ++i) {
    const json& v = (*it)[i];
    if (v.is_null()) {
      values.push_back(std::numeric_limits<double>::quiet_NaN());
    } else if (v.is_number()) {
      values.push_back(v.get<double>());
    } else {
      throw PlotDataError(std::string("hil_series.") + key + "[" + std::to_string(i) +
                          "]: expected a number");
    }
  }
  return values;
}

PlotSeries curve(const std::string& title, const std::vector<double>& x, const std::vector<double>& y,
                 int color, int dash = 1) {
  PlotSeries s;
  s.title = title;
  s.color = color;
  s.dash_type = dash;
  s.x = x;
  s.y = y;
  return s;
}

}  // namespace

std::vector<Figure> hil_figures(const nlohmann::json& document) {
  std::vector<Figure> figures;
  const auto series = document.find("hil_series");
  if (series == document.end() || series->is_null()) return figures;
  if (!series->is_object()) throw PlotDataError("hil_series: expected an object");
  const std::vector<double> t = column(*series, "time_s");
  if (t.empty()) return figures;
  const auto same_length = [&](const std::vector<double>& v, const char* key) {
    if (v.size() != t.size())
      throw PlotDataError(std::string("hil_series.") + key + ": not as long as time_s");
    return v;
  };
  const std::vector<double> theta_c = same_length(column(*series, "theta_command_deg"), "theta_command_deg");
  const std::vector<double> theta = same_length(column(*series, "theta_true_deg"), "theta_true_deg");
  const std::vector<double> pitch_error = same_length(column(*series, "pitch_error_deg"), "pitch_error_deg");
  const std::vector<double> yaw_error = same_length(column(*series, "yaw_error_deg"), "yaw_error_deg");
  const std::vector<double> pitch = same_length(column(*series, "pitch_actuator"), "pitch_actuator");
  const std::vector<double> yaw = same_length(column(*series, "yaw_actuator"), "yaw_actuator");

  Figure attitude;
  attitude.name = "hil_theta";
  attitude.title = "HIL bench: commanded and flown pitch attitude";
  attitude.x_label = "time from lift-off (s)";
  attitude.y_label = "theta (deg)";
  attitude.series.push_back(curve("commanded theta_c", t, theta_c, 1, 2));
  attitude.series.push_back(curve("flown theta (plant)", t, theta, 2));
  figures.push_back(std::move(attitude));

  Figure error;
  error.name = "hil_tracking_error";
  error.title = "HIL bench: attitude tracking error (commanded - flown)";
  error.x_label = "time from lift-off (s)";
  error.y_label = "error (deg)";
  error.series.push_back(curve("pitch", t, pitch_error, 1));
  error.series.push_back(curve("yaw", t, yaw_error, 3));
  figures.push_back(std::move(error));

  Figure actuators;
  actuators.name = "hil_actuators";
  actuators.title = "HIL bench: actuators (stage 1 fins and vanes, upper-stage jets)";
  actuators.x_label = "time from lift-off (s)";
  actuators.y_label = "fins: deflection (deg); jets: % of full force";
  actuators.series.push_back(curve("pitch", t, pitch, 1));
  actuators.series.push_back(curve("yaw", t, yaw, 3));
  figures.push_back(std::move(actuators));
  return figures;
}

}  // namespace tolip::ground
