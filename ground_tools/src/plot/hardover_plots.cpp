// The hardover figure of `tolip plot` (plot.hpp hardover_figures): the change in flight-path angle
// against time from the failure, every turn of the member "hardover" (docs/cli.md), a colour per
// stage and mode.
#include <string>

#include "plot_json.hpp"
#include "tolip_ground/plot.hpp"

namespace tolip::ground {
namespace {

// The result-document accessors (json, fail, required, required_array, ...): plot_json.hpp.
using namespace plot_json;

}  // namespace

std::vector<Figure> hardover_figures(const nlohmann::json& document) {
  std::vector<Figure> figures;
  const json* hardover = optional_object(document, "hardover");
  if (hardover == nullptr) return figures;
  const json& turns = required_array(*hardover, "turns", "hardover");
  if (turns.empty()) return figures;
  Figure figure;
  figure.name = "hardover_gamma";
  figure.title = "Hardover turns: change in flight-path angle after the failure";
  figure.x_label = "time from the failure (s)";
  figure.y_label = "change in flight-path angle (deg)";
  const char* const kinds[] = {"stage 1, fins and vanes", "mode 1, thrust misalignment", "mode 2, single jet",
                               "mode 3, pitch and yaw jets"};
  bool used[4] = {};
  for (std::size_t k = 0; k < turns.size(); ++k) {
    const std::string field = "hardover.turns[" + std::to_string(k) + "]";
    const json& turn = turns[k];
    if (!turn.is_object()) fail(field, "an object", turn);
    const json& mode = required(turn, "mode", field);
    if (!mode.is_number_integer() || mode.get<int>() < 0 || mode.get<int>() > 3)
      fail(field + ".mode", "0-3", mode);
    const json& stage = required(turn, "stage", field);
    if (!stage.is_number_integer()) fail(field + ".stage", "an integer", stage);
    const json& samples = required_array(turn, "samples", field);
    const int m = mode.get<int>();
    PlotSeries series;
    series.color = m + 1;
    // Stage 3's upper-stage modes dashed, stage 2's solid.
    series.dash_type = stage.get<int>() == 3 ? 2 : 1;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const std::string at = field + ".samples[" + std::to_string(i) + "]";
      if (!samples[i].is_object()) fail(at, "an object", samples[i]);
      series.x.push_back(number_or_gap(samples[i], "time_s", at));
      series.y.push_back(number_or_gap(samples[i], "change_in_gamma_deg", at));
    }
    used[m] = true;
    figure.series.push_back(std::move(series));
  }
  for (int m = 0; m < 4; ++m) {
    if (used[m]) figure.key_entries.push_back({kinds[m], SeriesStyle::kLines, m + 1, 1, 7});
  }
  if (used[1] || used[2] || used[3])
    figure.key_entries.push_back({"stage 3 (stage 2 solid)", SeriesStyle::kLines, 0, 2, 7});
  figures.push_back(std::move(figure));
  return figures;
}

}  // namespace tolip::ground
