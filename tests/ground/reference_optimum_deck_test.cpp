// The bundled example deck (examples/scout/reference_optimum.toml) flown by the core reproduces the
// independent oracle's burnout state and orbit: the deck, its reader and the core agree end to end.
// It flies the oracle's own Sec. 14 tables, as tests/core/reference_trajectory_test.cpp does and
// for the same reason (test::use_oracle_thrust_tables): the oracle's A and B are Simpson's rule,
// the core's exact; the deck's tables are first checked to give the core's reference-case tables.
#include <gtest/gtest.h>

#include <memory>

#include "support/reference_data.hpp"
#include "support/reference_mission.hpp"
#include "tolip/orbit/orbit_elements.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip_ground/deck.hpp"

namespace tolip {
namespace {

TEST(Sec4ReferenceDeck, SimulateReproducesOracleBurnoutAndOrbit) {
  auto mission = ground::make_mission();
  ground::DeckError error;
  ASSERT_TRUE(
      ground::load_toml_deck(test::example_path("scout/reference_optimum.toml"), mission.get(), &error))
      << error.to_string();
  auto prepared = std::make_unique<PreparedCase>();
  auto trajectory = std::make_unique<Trajectory>();
  ASSERT_EQ(prepare_case(*mission, prepared.get()), Status::kOk);
  // The deck read gives the same Sec. 14 tables as the reference case built from the JSON.
  auto reference = std::make_unique<Mission>();
  auto reference_prepared = std::make_unique<PreparedCase>();
  test::build_reference_mission(test::ReferenceProgram::kOptimum, reference.get());
  ASSERT_EQ(prepare_case(*reference, reference_prepared.get()), Status::kOk);
  for (int code = 1; code <= 4; ++code) {
    const ModifiedThrustTable& from_deck = prepared->modified_thrust_lbf[stage_index(code)];
    const ModifiedThrustTable& from_json = reference_prepared->modified_thrust_lbf[stage_index(code)];
    ASSERT_EQ(from_deck.size(), from_json.size()) << "stage " << code;
    for (int i = 0; i < from_deck.size(); ++i) {
      EXPECT_NEAR(from_deck.x(i), from_json.x(i), 1e-9) << code << " " << i;
      EXPECT_NEAR(from_deck.y(i), from_json.y(i), 1e-6) << code << " " << i;
    }
  }
  test::use_oracle_thrust_tables(prepared.get());
  ASSERT_EQ(fly_trajectory(*mission, *prepared, trajectory.get()), Status::kOk);

  const auto& oracle = test::scout_reference()["oracle_solution"];
  const auto& x = oracle["burnout_state"]["state_vector_rad_order_V_gamma_r_psi_lambda_tau"];
  const TrajectoryPoint& p = trajectory->final_point();
  EXPECT_NEAR(p.time_s, oracle["burnout_state"]["time_from_launch_s"].get<double>(), 1e-9);
  EXPECT_NEAR(p.state[kStateV], x[0].get<double>(), 1e-6);
  EXPECT_NEAR(p.state[kStateR], x[2].get<double>(), 1e-4);
  EXPECT_NEAR(p.altitude_ft, oracle["burnout_state"]["altitude_ft"].get<double>(), 1e-4);
  EXPECT_NEAR(p.weight_lb, oracle["final_weight_lb"].get<double>(), 1e-6);

  OrbitElements e;
  ASSERT_EQ(
      compute_orbit_elements(mission->constants, p.state, mission->launch.launch_space_age_date_days, &e),
      Status::kOk);
  const auto& o = oracle["orbit_elements"];
  EXPECT_NEAR(e.inertial.velocity_ft_s, o["VI_fps"].get<double>(), 1e-6);
  EXPECT_NEAR(e.inclination_rad * kRadToDeg, o["inclination_deg"].get<double>(), 1e-9);
  EXPECT_NEAR(e.node_longitude_rad * kRadToDeg, o["longitude_of_node_deg"].get<double>(), 1e-8);
  EXPECT_NEAR(e.period_s / 60.0, o["period_min"].get<double>(), 1e-8);
  // The orbit is circular to 1e-16: r_p = H / (mu/H + sqrt(2E + (mu/H)^2)) goes through the square
  // root of a difference that vanishes, so a 1e-6 ft/s difference in V moves r_p by tenths of a foot.
  EXPECT_NEAR(e.perigee_radius_ft, o["perigee_radius_ft"].get<double>(), 1.0);
}

}  // namespace
}  // namespace tolip
