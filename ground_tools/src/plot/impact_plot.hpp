// The impact-locus figure of `tolip plot` (plot.hpp; private to ground_tools/src/plot): the impact
// points of the member "impact" and the nominal ground track of "trajectory" on a latitude /
// longitude grid with the launch site, one symbol per failure kind.
#pragma once

#include <optional>

#include <nlohmann/json.hpp>

#include "tolip_ground/plot.hpp"

namespace tolip::ground::plot_detail {

std::optional<Figure> impact_locus_figure(const nlohmann::json& document);

}  // namespace tolip::ground::plot_detail
