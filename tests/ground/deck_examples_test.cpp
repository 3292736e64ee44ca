// The bundled Scout decks load, validate and carry the reference mission's values (manual Sec. 22).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "deck_test_support.hpp"
#include "support/repository_paths.hpp"
#include "tolip/core/constants.hpp"
#include "tolip/mission/mission.hpp"

namespace tolip::test {
namespace {

using ground::DeckError;
using ground::DeckExtras;

struct Loaded {
  std::unique_ptr<Mission> mission = ground::make_mission();
  DeckExtras extras;
};

Loaded load_example(const std::string& name) {
  Loaded loaded;
  DeckError error;
  const bool ok_load =
      ground::load_toml_deck(example_path(name), loaded.mission.get(), &loaded.extras, &error);
  EXPECT_TRUE(ok_load) << error.to_string();
  return loaded;
}

double deg(double value) { return value * kDegToRad; }

void expect_table(const Table<kMaxThrustPoints>& table, const nlohmann::json& x, const nlohmann::json& y) {
  ASSERT_EQ(table.size(), static_cast<int>(x.size()));
  EXPECT_TRUE(table.finalized());
  for (int i = 0; i < table.size(); ++i) {
    EXPECT_EQ(table.x(i), x[static_cast<std::size_t>(i)].get<double>()) << "point " << i;
    EXPECT_EQ(table.y(i), y[static_cast<std::size_t>(i)].get<double>()) << "point " << i;
  }
}

TEST(Sec22Deck, LoadsScoutMissionExampleAndValidates) {
  Loaded loaded = load_example("scout/mission.toml");
  MissionFault fault;
  EXPECT_EQ(validate_mission(*loaded.mission, &fault), Status::kOk) << fault.data_block << " " << fault.field;
}

TEST(Sec22Deck, LoadsReferenceOptimumExampleAndValidates) {
  Loaded loaded = load_example("scout/reference_optimum.toml");
  MissionFault fault;
  EXPECT_EQ(validate_mission(*loaded.mission, &fault), Status::kOk) << fault.data_block << " " << fault.field;
}

TEST(Sec22Deck, LoadsThroughTheMissionOnlyOverload) {
  auto mission = ground::make_mission();
  DeckError error;
  ASSERT_TRUE(ground::load_toml_deck(example_path("scout/mission.toml"), mission.get(), &error))
      << error.to_string();
  EXPECT_EQ(mission->vehicle.sequence.count, 7);
}

TEST(Sec22Deck, MissionExampleCarriesTheReferenceVehicle) {
  const nlohmann::json& ref = scout_reference();
  Loaded loaded = load_example("scout/mission.toml");
  const Mission& m = *loaded.mission;

  // Block 5 (the card's terminating 0 dropped).
  const int expected_sequence[] = {1, 6, 2, 7, 3, 8, 4};
  ASSERT_EQ(m.vehicle.sequence.count, 7);
  for (int k = 0; k < 7; ++k) EXPECT_EQ(m.vehicle.sequence.codes[k], expected_sequence[k]);
  for (int code = 1; code <= kMaxStages; ++code) {
    const bool listed = code != 5 && code != 9 && code != 10;
    EXPECT_EQ(m.vehicle.stages[stage_index(code)].in_sequence, listed) << "stage " << code;
  }

  // Blocks 16, 30, 38, 39 of every powered stage, exactly.
  for (int code : {1, 2, 3, 4}) {
    SCOPED_TRACE("stage " + std::to_string(code));
    const nlohmann::json& stage = ref["vehicle"]["stages"][std::to_string(code)];
    const StageData& data = m.vehicle.stages[stage_index(code)];
    EXPECT_EQ(data.duration_s, stage["duration_s"].get<double>());
    EXPECT_EQ(data.integration_steps, stage["integration_steps"].get<int>());
    EXPECT_EQ(data.jettison_weight_lb, stage["jettison_weight_lb"].get<double>());
    EXPECT_EQ(data.reference_area_ft2, stage["reference_area_ft2"].get<double>());
    EXPECT_EQ(data.nozzle_exit_area_ft2, stage["nozzle_exit_area_ft2"].get<double>());
    expect_table(data.vacuum_thrust_lbf, stage["thrust_table"]["time_s"],
                 stage["thrust_table"]["vacuum_thrust_lbf"]);
    expect_table(data.consumable_weight_lb, stage["consumable_weight_table"]["time_s"],
                 stage["consumable_weight_table"]["consumable_weight_remaining_lb"]);
  }
  // Coasts: block 16 and 39; coast 8 starts from the crude 450 s.
  EXPECT_EQ(m.vehicle.stages[stage_index(6)].duration_s, 5.0);
  EXPECT_EQ(m.vehicle.stages[stage_index(6)].reference_area_ft2, 5.2414);
  EXPECT_EQ(m.vehicle.stages[stage_index(7)].integration_steps, 4);
  EXPECT_EQ(m.vehicle.stages[stage_index(8)].duration_s,
            ref["oracle_solution"]["tth_block40_initial_nominal"]["coast8_s"].get<double>());
  EXPECT_EQ(m.vehicle.stages[stage_index(8)].integration_steps, 40);

  // Blocks 31 and 32.
  const nlohmann::json& aero = ref["vehicle"]["aerodynamics"];
  for (int code : {1, 6, 2}) {
    const AeroTable& drag = m.vehicle.stages[stage_index(code)].drag_coefficient;
    const nlohmann::json& table = aero["drag_coefficient_tables"]["stage_" + std::to_string(code)];
    ASSERT_EQ(drag.size(), static_cast<int>(table["mach"].size()));
    EXPECT_EQ(drag.x(4), table["mach"][4].get<double>());
    EXPECT_EQ(drag.y(4), table["cd"][4].get<double>());
  }
  for (int code : {3, 4, 7, 8}) EXPECT_TRUE(m.vehicle.stages[stage_index(code)].drag_coefficient.empty());
  EXPECT_EQ(m.vehicle.lift_curve_slope_per_rad.size(), 10);
  EXPECT_EQ(m.vehicle.lift_curve_slope_per_rad.y(3), 4.1);
  EXPECT_TRUE(m.vehicle.stages[stage_index(1)].uses_lift_table);
  EXPECT_TRUE(m.vehicle.stages[stage_index(6)].uses_lift_table);
  EXPECT_FALSE(m.vehicle.stages[stage_index(2)].uses_lift_table);

  // The crude starting payload.
  EXPECT_EQ(m.vehicle.payload_lb,
            ref["oracle_solution"]["tth_block40_initial_nominal"]["payload_lb"].get<double>());
}

TEST(Sec22Deck, MissionExampleCarriesTheReferenceMissionData) {
  const nlohmann::json& ref = scout_reference();
  const nlohmann::json& mission = ref["mission"];
  Loaded loaded = load_example("scout/mission.toml");
  const Mission& m = *loaded.mission;

  EXPECT_EQ(loaded.extras.listing.title, "SCOUT-CLASS 4-STAGE, WALLOPS ISLAND TO 300 NMI CIRCULAR ORBIT");
  EXPECT_EQ(loaded.extras.listing.date, "1966-07-01");

  // Block 4.
  EXPECT_EQ(m.options.payoff(), 0);
  EXPECT_TRUE(m.options.exchange_ratios());
  EXPECT_EQ(m.options.body_dynamics_6d(), 1);
  EXPECT_TRUE(m.options.linearization());
  EXPECT_EQ(m.options.spin_stages_4_5(), 1);
  EXPECT_TRUE(m.options.zero_alpha_window());
  EXPECT_TRUE(m.options.alpha_zero_at_stage2_ignition());
  EXPECT_TRUE(m.options.print_input());
  EXPECT_TRUE(m.options.dispersions() && m.options.hardover() && m.options.impact() && m.options.radar());
  EXPECT_FALSE(m.options.heating_constraint());

  // Blocks 10-14 as in the reference (= the manual's nominal values).
  const nlohmann::json& ct1 = ref["constants_block10_CT1"];
  EXPECT_EQ(m.constants.gravitational_parameter_ft3_s2,
            ct1["gravitational_parameter_ft3_per_s2"].get<double>());
  EXPECT_EQ(m.constants.gas_constant_ft2_s2_R, ct1["gas_constant_ft2_per_s2_R"].get<double>());
  EXPECT_EQ(m.constants.j2, ct1["j2"].get<double>());
  EXPECT_EQ(m.atmosphere.base_density_slug_ft3[7],
            ref["atmosphere_blocks11_14_ARDC"]["base_density_slug_per_ft3"][7].get<double>());

  // Blocks 20, 21: degrees in the deck, radians in the core.
  const nlohmann::json& ic = mission["initial_conditions_block21"];
  EXPECT_EQ(m.launch.liftoff_duration_s, mission["liftoff_duration_s_block20_word1"].get<double>());
  EXPECT_EQ(m.launch.launch_space_age_date_days,
            mission["launch_date_space_age_days_block20_word2"].get<double>());
  EXPECT_EQ(m.launch.altitude_ft, ic["altitude_ft"].get<double>());
  EXPECT_DOUBLE_EQ(m.launch.geocentric_latitude_rad, deg(ic["geocentric_latitude_deg"].get<double>()));
  EXPECT_NEAR(m.launch.geocentric_latitude_rad, 0.657173006127, 1e-12);  // the oracle's state vector
  EXPECT_DOUBLE_EQ(m.launch.longitude_rad, deg(ic["longitude_deg"].get<double>()));
  EXPECT_DOUBLE_EQ(m.launch.azimuth_rad, deg(ic["azimuth_deg"].get<double>()));
  EXPECT_DOUBLE_EQ(m.launch.flight_path_angle_rad, 0.5 * kPi);
  EXPECT_EQ(m.launch.velocity_ft_s, 0.0);
  EXPECT_EQ(m.launch.heading_hold_until_s, mission["heading_hold_until_s"].get<double>());

  // Block 22 (deg/s -> rad/s) and block 17.
  EXPECT_EQ(m.control.zero_alpha_start_s, 15.0);
  EXPECT_EQ(m.control.zero_alpha_end_s, 45.0);
  EXPECT_DOUBLE_EQ(m.control.max_pitch_rate_rad_s, deg(5.0));
  EXPECT_DOUBLE_EQ(m.control.min_pitch_rate_change_rad_s, deg(0.05));
  EXPECT_DOUBLE_EQ(m.misc.stage4_theta_rad, deg(-20.0));
  EXPECT_EQ(m.misc.nose_radius_ft, 0.85);
  EXPECT_EQ(m.misc.coast_change_limit_s, 100.0);
  EXPECT_EQ(m.misc.payload_weighting_factor, 1.0);

  // Blocks 8, 19, 29: the payoff, then altitude, gamma_I, V_I - V_circ.
  const nlohmann::json& terminal = mission["terminal_constraints"];
  ASSERT_EQ(m.constraints.count, 4);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(m.constraints.codes[i], terminal["block8_codes"][i + 1].get<int>());
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(m.constraints.desired[i], terminal["block19_desired_values"][i].get<double>(), 1e-15);
  }
  for (int i = 0; i < 3; ++i) {
    const double optimization = terminal["block29_allowed_deviations_optimization"][i].get<double>();
    const double linearization = terminal["block29_allowed_deviations_linearization"][i].get<double>();
    EXPECT_NEAR(m.constraints.deadband_optimization[i], optimization, 1e-15 * std::abs(optimization));
    EXPECT_NEAR(m.constraints.deadband_linearization[i], linearization, 1e-15 * std::abs(linearization));
  }

  // Blocks 6, 27; 18, 26; 28; 9.
  ASSERT_EQ(m.adjustable.count, 2);
  EXPECT_EQ(m.adjustable.codes[0], 1);
  EXPECT_EQ(m.adjustable.weights[0], 10.0);
  EXPECT_EQ(m.adjustable.codes[1], 3);
  EXPECT_EQ(m.adjustable.weights[1], 1e-4);
  const nlohmann::json& tlin = mission["pitch_program_definition"]["tlin_block18"];
  EXPECT_EQ(m.linearization.segment_count, tlin[0].get<int>());
  for (int i = 0; i + 1 < static_cast<int>(tlin.size()); ++i) {
    // TLIN codes 100 n + t; the core holds n and t.
    const double coded = tlin[static_cast<std::size_t>(i) + 1].get<double>();
    const double stage = std::floor(coded / 100.0);
    EXPECT_EQ(m.linearization.boundaries[i].stage, static_cast<int>(stage));
    EXPECT_EQ(m.linearization.boundaries[i].time_from_ignition_s, coded - 100.0 * stage);
  }
  EXPECT_EQ(m.linearization.segment_weights[0], 1.0);
  EXPECT_EQ(m.convergence.initial_payoff_improvement, 15.0);
  EXPECT_EQ(m.convergence.stop_improvement, 0.5);
  EXPECT_EQ(m.convergence.max_forward_trajectories, 30);
  for (int i = 0; i < kMaxStages; ++i) EXPECT_EQ(loaded.extras.listing.output.final_trajectory[i], 1);

  // Block 40: the crude initial program, in radians.
  const nlohmann::json& tth = ref["oracle_solution"]["tth_block40_initial_nominal"];
  ASSERT_EQ(m.pitch_program_rad.size(), static_cast<int>(tth["time_s"].size()));
  for (int i = 0; i < m.pitch_program_rad.size(); ++i) {
    EXPECT_EQ(m.pitch_program_rad.x(i), tth["time_s"][static_cast<std::size_t>(i)].get<double>());
    EXPECT_DOUBLE_EQ(m.pitch_program_rad.y(i),
                     deg(tth["theta_deg"][static_cast<std::size_t>(i)].get<double>()));
  }
}

TEST(Sec22Deck, ReferenceOptimumCarriesTheOracleSolution) {
  const nlohmann::json& oracle = scout_reference()["oracle_solution"];
  Loaded loaded = load_example("scout/reference_optimum.toml");
  const Mission& m = *loaded.mission;
  EXPECT_EQ(m.vehicle.payload_lb, oracle["payload_lb"].get<double>());
  EXPECT_DOUBLE_EQ(m.misc.stage4_theta_rad, deg(oracle["stage4_theta_deg"].get<double>()));
  EXPECT_EQ(m.vehicle.stages[stage_index(8)].duration_s, oracle["coast8_duration_s"].get<double>());
  EXPECT_EQ(m.vehicle.stages[stage_index(8)].integration_steps, 40);

  const double node_times[] = {0, 3, 8, 15, 45, 50, 69, 88, 94, 112, 130};
  ASSERT_EQ(m.pitch_program_rad.size(), 11);
  EXPECT_DOUBLE_EQ(m.pitch_program_rad.y(0), 0.5 * kPi);
  for (int i = 0; i < 11; ++i) EXPECT_EQ(m.pitch_program_rad.x(i), node_times[i]);
  for (int i = 1; i < 11; ++i) {
    EXPECT_DOUBLE_EQ(
        m.pitch_program_rad.y(i),
        deg(oracle["pitch_program"]["theta_deg_as_flown"][static_cast<std::size_t>(i) - 1].get<double>()));
  }
}

TEST(Sec22Deck, ExampleExtrasCarryTheOptionalComputationData) {
  const nlohmann::json& ref = scout_reference();
  Loaded loaded = load_example("scout/mission.toml");
  const DeckExtras& x = loaded.extras;

  // Blocks 33-37: in the core's Mission (stations in ft), DA6D(12-19) ground side.
  const nlohmann::json& da6d = ref["body_dynamics_6D"]["block33_DA6D"];
  const BodyDynamicsBlocks& b = loaded.mission->body_dynamics;
  ASSERT_TRUE(x.body_dynamics.present);
  ASSERT_TRUE(b.present);
  EXPECT_EQ(b.position_gain[0], 1.2);
  EXPECT_DOUBLE_EQ(b.control_station_ft[2], 296.0 / 12.0);
  EXPECT_DOUBLE_EQ(
      b.jet_vane_effectiveness_per_rad,
      da6d["jet_vane_effectiveness_lb_per_lb_vacuum_thrust_per_deg_per_vane"].get<double>() / kDegToRad);
  EXPECT_EQ(b.reference_length_ft, da6d["reference_length_ft"].get<double>());
  EXPECT_EQ(x.body_dynamics.impact_every_nth_step[1], 2);
  EXPECT_EQ(b.pitching_moment_per_rad.size(), 10);
  EXPECT_EQ(b.pitching_moment_per_rad.y(2), -9.165);
  EXPECT_EQ(b.fin_normal_force_per_rad.size(), 9);
  EXPECT_EQ(b.fin_pitching_moment_per_rad.y(0), -1.815);
  EXPECT_DOUBLE_EQ(b.cg_station_ft[0].y(0), 515.0 / 12.0);
  EXPECT_EQ(b.cg_station_ft[3].x(b.cg_station_ft[3].size() - 1), 28.0);

  // Block 41.
  ASSERT_EQ(x.radar_stations.size(), 6u);
  EXPECT_EQ(x.radar_stations[1].id, "BERMUDA");
  EXPECT_DOUBLE_EQ(x.radar_stations[5].geodetic_latitude_rad, deg(-7.95));
  EXPECT_DOUBLE_EQ(x.radar_stations[5].longitude_rad, deg(-14.4));
  EXPECT_EQ(x.radar_stations[4].altitude_ft, 150.0);

  // Blocks 42-43.
  ASSERT_TRUE(x.impact.present);
  EXPECT_EQ(x.impact.failure_mode[2].cd_vs_mach.y.front(), 1.1);
  EXPECT_EQ(x.impact.expended_casing[1].casing_weight_lb, 1650.0);
  EXPECT_EQ(x.impact.expended_casing[0].reference_area_ft2, 8.7266);

  // Blocks 44-45.
  ASSERT_TRUE(x.hardover.present);
  EXPECT_EQ(x.hardover.pitch_inertia_slug_ft2[0].y.front(), 420000.0);
  EXPECT_EQ(x.hardover.stage1_pitch_damping_per_rad.y[2], -520.0);
  EXPECT_EQ(x.hardover.stage1_every_nth_step, 5);
  EXPECT_DOUBLE_EQ(x.hardover.max_qbar_alpha_lb_rad_ft2, deg(6000.0));
  EXPECT_EQ(x.hardover.mode_c_jet_force_lb[1], 57.0);
  EXPECT_EQ(x.hardover.upper_max_steps_per_turn, 2000);

  // Blocks 46-55: codes 1-38 and 40, in order, with their signs.
  ASSERT_EQ(x.dispersions.size(), 39u);
  for (std::size_t i = 0; i < 38; ++i) EXPECT_EQ(x.dispersions[i].code, static_cast<int>(i) + 1);
  EXPECT_EQ(x.dispersions.back().code, 40);
  EXPECT_EQ(x.dispersions.back().title, "NOMINAL TRAJ");
  const nlohmann::json& high1 =
      ref["dispersions"]["codes_1_8_vacuum_thrust_variation"]["tables"]["stage_1_high"];
  EXPECT_EQ(x.dispersions[0].stage, 1);
  EXPECT_EQ(x.dispersions[0].vacuum_thrust_lbf.x.back(), high1["time_s"].back().get<double>());
  EXPECT_EQ(x.dispersions[0].vacuum_thrust_lbf.y[3], high1["vacuum_thrust_lbf"][3].get<double>());
  EXPECT_EQ(x.dispersions[7].stage, 4);
  EXPECT_EQ(x.dispersions[8].weight_increment_lb, 150.0);                    // code 9
  EXPECT_EQ(x.dispersions[9].weight_increment_lb, -150.0);                   // code 10
  EXPECT_EQ(x.dispersions[15].stage, 4);                                     // code 16
  EXPECT_EQ(x.dispersions[17].drag_variation_fraction, -0.1);                // code 18
  EXPECT_NEAR(x.dispersions[18].pitching_moment_per_rad.y[0], -7.2, 1e-12);  // code 19: x_cp 690 in
  EXPECT_NEAR(x.dispersions[19].pitching_moment_per_rad.y[0], -8.8, 1e-12);  // code 20: x_cp 710 in
  EXPECT_DOUBLE_EQ(x.dispersions[21].misalignment_rad, deg(-0.25));          // code 22
  EXPECT_EQ(x.dispersions[20].thrust_station_in, 864.0);
  EXPECT_EQ(x.dispersions[26].stage, 3);                                 // code 27
  EXPECT_DOUBLE_EQ(x.dispersions[30].tipoff_rad, deg(-2.0));             // code 31
  EXPECT_DOUBLE_EQ(x.dispersions[32].launch_change_rad, deg(0.5));       // code 33
  EXPECT_DOUBLE_EQ(x.dispersions[34].launch_change_rad, deg(-0.3));      // code 35
  EXPECT_EQ(x.dispersions[35].wind_speed_ft_s.y[7], 250.0);              // code 36
  EXPECT_DOUBLE_EQ(x.dispersions[37].wind_azimuth_rad.y[0], deg(10.0));  // code 38
}

// The committed decks are what the generator writes from the reference (no hand edits).
TEST(Sec22Deck, ExamplesMatchTheirGenerator) {
  if (std::system("python3 -c 'import json' > /dev/null 2>&1") != 0) GTEST_SKIP() << "python3 not available";
  const std::string out = std::string(tolip::repository_paths::binary_dir()) + "/generated_scout_examples";
  const std::string command = "python3 '" + std::string(tolip::repository_paths::source_dir()) +
                              "/scripts/make_scout_examples.py'" + " --reference '" +
                              std::string(tolip::repository_paths::reference_dir()) +
                              "/scout_reference.json'" + " --out '" + out + "' > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  for (const char* name :
       {"mission.toml", "reference_optimum.toml", "mission_qalpha.toml", "mission.dat", "cases.dat"}) {
    EXPECT_EQ(read_text(out + "/" + name), read_text(example_path(std::string("scout/") + name)))
        << name << " differs from scripts/make_scout_examples.py output";
  }
}

}  // namespace
}  // namespace tolip::test
