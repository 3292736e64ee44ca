// Data blocks 44-45 of tests/reference straight from the JSON (not through the deck reader), for
// the hardover and autopilot-design tests.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "support/reference_data.hpp"
#include "tolip/core/constants.hpp"
#include "tolip/hardover/hardover.hpp"

namespace tolip::test {

inline constexpr double kFtPerInch = 1.0 / 12.0;

inline void fill_table(const nlohmann::json& x, const nlohmann::json& y, HardoverTable* table) {
  table->clear();
  for (std::size_t i = 0; i < x.size(); ++i)
    ASSERT_EQ(table->append(x[i].get<double>(), y[i].get<double>()), Status::kOk);
  ASSERT_EQ(table->finalize(), Status::kOk);
}

// Blocks 44-45 of tests/reference straight from the JSON (not through the deck reader).
inline HardoverData reference_hardover() {
  const nlohmann::json& h = test::scout_reference()["hardover"];
  const nlohmann::json& w = h["block45"];
  HardoverData d;
  for (int k = 0; k < 3; ++k) {
    const nlohmann::json& iyy = h["block44_pitch_inertia_slug_ft2"]["stage_" + std::to_string(k + 1)];
    fill_table(iyy["stage_time_s"], iyy["iyy_slug_ft2"], &d.stages[k].pitch_inertia_slug_ft2);
  }
  const nlohmann::json& cmq = h["block44_stage1_pitch_damping_CMQ_per_rad"];
  fill_table(cmq["mach"], cmq["cmq_per_rad"], &d.pitch_damping_per_rad);
  d.max_qbar_alpha_lbf_rad_ft2 = w["w02_max_qbar_alpha_lb_deg_per_ft2"].get<double>() * kDegToRad;
  d.fin_vane_deflection_rad = w["w11_stage1_fin_and_vane_deflection_deg"].get<double>() * kDegToRad;
  d.output_interval_s = w["w20_output_interval_s"];
  HardoverStage& s1 = d.stages[0];
  s1.every_nth_step = w["w01_stage1_every_nth_step"];
  s1.max_attitude_step_rad = w["w03_max_attitude_step_deg"].get<double>() * kDegToRad;
  s1.max_step_s = w["w04_max_step_s"];
  s1.min_step_s = w["w05_min_step_s"];
  s1.max_steps_per_turn = w["w06_max_steps_per_turn"];
  s1.thrust_misalignment_rad = w["w07_stage1_thrust_misalignment_deg"].get<double>() * kDegToRad;
  s1.thrust_station_ft = w["w10_stage1_thrust_application_station_in"].get<double>() * kFtPerInch;
  const char* misalignment[] = {"w08_stage2_thrust_misalignment_deg", "w09_stage3_thrust_misalignment_deg"};
  const char* single[] = {"w12_modeB_stage2_control_jet_force_lb", "w13_modeB_stage3_control_jet_force_lb"};
  const char* pair[] = {"w14_modeC_stage2_control_jet_force_lb", "w15_modeC_stage3_control_jet_force_lb"};
  const char* thrust_station[] = {"w16_stage2_thrust_application_station_in",
                                  "w17_stage3_thrust_application_station_in"};
  const char* jet_station[] = {"w18_stage2_control_jet_station_in", "w19_stage3_control_jet_station_in"};
  const char* nth[] = {"w21_stage2_every_nth_step", "w22_stage3_every_nth_step"};
  for (int k = 1; k < 3; ++k) {
    HardoverStage& s = d.stages[k];
    s.every_nth_step = w[nth[k - 1]];
    s.max_attitude_step_rad = w["w23_upper_max_attitude_step_deg"].get<double>() * kDegToRad;
    s.max_step_s = w["w24_upper_max_step_s"];
    s.min_step_s = w["w25_upper_min_step_s"];
    s.max_steps_per_turn = w["w26_upper_max_steps_per_turn"];
    s.thrust_misalignment_rad = w[misalignment[k - 1]].get<double>() * kDegToRad;
    s.single_jet_force_lbf = w[single[k - 1]];
    s.pitch_yaw_jet_force_lbf = w[pair[k - 1]];
    s.thrust_station_ft = w[thrust_station[k - 1]].get<double>() * kFtPerInch;
    s.control_jet_station_ft = w[jet_station[k - 1]].get<double>() * kFtPerInch;
  }
  return d;
}

}  // namespace tolip::test
