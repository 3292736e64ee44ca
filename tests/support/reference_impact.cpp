#include "support/reference_impact.hpp"

#include <gtest/gtest.h>

#include <string>

#include "support/reference_data.hpp"

namespace tolip::test {

void build_reference_impact_data(ImpactLocusData* data) {
  const nlohmann::json& impact = scout_reference().at("impact");
  const auto fill = [](const nlohmann::json& table, ImpactBody* body, bool casing) {
    body->present = true;
    body->drag_coefficient.clear();
    const nlohmann::json& mach = table.at("mach");
    const nlohmann::json& cd = table.at("cd");
    for (std::size_t i = 0; i < mach.size(); ++i) {
      ASSERT_EQ(body->drag_coefficient.append(mach[i].get<double>(), cd[i].get<double>()), Status::kOk);
    }
    ASSERT_EQ(body->drag_coefficient.finalize(), Status::kOk);
    body->reference_area_ft2 = table.at("reference_area_ft2").get<double>();
    body->casing_weight_lb = casing ? table.at("casing_weight_lb").get<double>() : 0.0;
  };
  const nlohmann::json& every =
      scout_reference().at("body_dynamics_6D").at("block33_DA6D").at("impact_every_nth_step");
  for (int stage = 1; stage <= kImpactStages; ++stage) {
    const std::string key = "stage_" + std::to_string(stage);
    fill(impact.at("block42_failure_mode_cd").at(key), &data->failure_mode[stage - 1], false);
    fill(impact.at("block43_expended_casing_cd").at(key), &data->expended_casing[stage - 1], true);
    data->every_nth_point[stage - 1] = every.at(key).get<int>();
  }
}

}  // namespace tolip::test
