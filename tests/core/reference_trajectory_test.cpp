// Sec. 4, 14, 19: the forward trajectory of the reference mission against the independent oracle.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/reference_data.hpp"
#include "support/reference_mission.hpp"
#include "tolip/trajectory/liftoff.hpp"
#include "tolip/trajectory/trajectory.hpp"

namespace tolip {
namespace {

struct Flown {
  Mission mission;
  PreparedCase prepared;         // the core's Sec. 14 tables (exact A and B)
  PreparedCase oracle_prepared;  // the same case with the oracle's Sec. 14 tables
  Trajectory trajectory;         // flown with the oracle's tables
  Trajectory exact_trajectory;   // flown with the core's
};

// One flight of the oracle optimum, shared by the tests (the storage is large: static, not stack).
// The trajectory comparisons fly the oracle's own Sec. 14 tables (test::use_oracle_thrust_tables):
// the oracle integrated A and B by Simpson's rule, the core exactly, and the two tables' difference
// (measured and explained by Sec14ThrustModification.MatchesOracleTablesIdealVelocitiesAndScale)
// is not the integrator's; with the same tables the trajectories agree to round-off.
const Flown& reference_flight() {
  static Flown* flown = [] {
    static Flown f;
    test::build_reference_mission(test::ReferenceProgram::kOptimum, &f.mission);
    EXPECT_EQ(prepare_case(f.mission, &f.prepared), Status::kOk);
    f.oracle_prepared = f.prepared;
    test::use_oracle_thrust_tables(&f.oracle_prepared);
    EXPECT_EQ(fly_trajectory(f.mission, f.oracle_prepared, &f.trajectory), Status::kOk);
    EXPECT_EQ(fly_trajectory(f.mission, f.prepared, &f.exact_trajectory), Status::kOk);
    return &f;
  }();
  return *flown;
}

// Simpson's rule per table interval of g0 T / W (W the total vehicle weight), as the oracle
// integrated A and B (tests/reference README, choice 8), written here from that description.
double per_interval_simpson_ft_s(const Mission& mission, int code, const ModifiedThrustTable& thrust) {
  const double g0 = mission.constants.g0_ft_s2;
  const auto f = [&](double t) { return g0 * thrust(t) / vehicle_weight_lb(mission.vehicle, code, t); };
  double sum = 0.0;
  for (int i = 0; i + 1 < thrust.size(); ++i) {
    const double a = thrust.x(i);
    const double b = thrust.x(i + 1);
    sum += (b - a) / 6.0 * (f(a) + 4.0 * f(0.5 * (a + b)) + f(b));
  }
  return sum;
}

// The core's A and B are exact integrals (Sec14_IdealVelocityMatchesFineQuadratureOnEveryReferenceStage),
// the oracle's are Simpson's rule per interval, so the tables differ by the ratio of the two scales.
// Both of the oracle's quadratures are redone here on the core's input and (unscaled) grid tables:
// they reproduce the oracle's A, B, scale and every entry to its printed digits (the tolerances
// this test had before the exact integral: 1e-6 ft/s, 1e-11, 1e-6 lbf), which proves that the whole
// difference is the oracle's quadrature error; that error (exact minus Simpson) is printed per stage
// (docs/theory/thrust-modification.md quotes it).
TEST(Sec14ThrustModification, MatchesOracleTablesIdealVelocitiesAndScale) {
  const Flown& f = reference_flight();
  const auto& tables = test::scout_reference()["oracle_solution"]["modified_thrust_tables_section14"];
  for (const auto& [key, t] : tables.items()) {
    const int code = std::stoi(key);
    const ModifiedThrustTable& mine = f.prepared.modified_thrust_lbf[stage_index(code)];
    const ThrustModification& mod = f.prepared.thrust_modification[stage_index(code)];
    ASSERT_EQ(mine.size(), static_cast<int>(t["time_s"].size())) << "stage " << code;
    // The input table as a ModifiedThrustTable (same values), and the grid table before the scale.
    const ThrustTable& input_table = f.mission.vehicle.stages[stage_index(code)].vacuum_thrust_lbf;
    ModifiedThrustTable input;
    for (int i = 0; i < input_table.size(); ++i)
      ASSERT_EQ(input.append(input_table.x(i), input_table.y(i)), Status::kOk);
    ASSERT_EQ(input.finalize(), Status::kOk);
    ModifiedThrustTable grid;
    for (int i = 0; i < mine.size(); ++i)
      ASSERT_EQ(grid.append(mine.x(i), mine.y(i) / mod.scale), Status::kOk);
    ASSERT_EQ(grid.finalize(), Status::kOk);
    const double simpson_a = per_interval_simpson_ft_s(f.mission, code, input);
    const double simpson_b = per_interval_simpson_ft_s(f.mission, code, grid);
    const double simpson_scale = simpson_a / simpson_b;
    EXPECT_NEAR(simpson_a, t["ideal_velocity_input_fps"].get<double>(), 1e-6) << "stage " << code;
    EXPECT_NEAR(simpson_b, t["ideal_velocity_grid_fps"].get<double>(), 1e-6) << "stage " << code;
    EXPECT_NEAR(simpson_scale, t["scale"].get<double>(), 1e-11) << "stage " << code;
    for (int i = 0; i < mine.size(); ++i) {
      EXPECT_NEAR(mine.x(i), t["time_s"][i].get<double>(), 1e-9) << code << " " << i;
      EXPECT_NEAR(grid.y(i) * simpson_scale, t["vacuum_thrust_lbf"][i].get<double>(), 1e-6)
          << code << " " << i;
    }
    std::printf(
        "stage %d: exact minus the oracle's Simpson, relative: A %.2e, B %.2e, scale (every entry) %.2e\n",
        code, mod.ideal_velocity_input_ft_s / simpson_a - 1.0, mod.ideal_velocity_grid_ft_s / simpson_b - 1.0,
        mod.scale / simpson_scale - 1.0);
  }
}

TEST(Sec4Liftoff, ClosedFormMatchesOracle) {
  const Flown& f = reference_flight();
  LiftoffResult liftoff;
  ASSERT_EQ(closed_form_liftoff(f.mission, f.oracle_prepared, &liftoff), Status::kOk);
  const auto& ref = test::scout_reference()["oracle_solution"]["liftoff"];
  EXPECT_NEAR(liftoff.acceleration_at_0_ft_s2, ref["acceleration_at_0_fps2"].get<double>(), 1e-9);
  EXPECT_NEAR(liftoff.acceleration_at_end_ft_s2, ref["acceleration_at_TL_fps2"].get<double>(), 1e-9);
  EXPECT_NEAR(liftoff.velocity_ft_s, ref["V_L_fps"].get<double>(), 1e-8);
  EXPECT_NEAR(liftoff.height_ft, ref["h_L_ft"].get<double>(), 1e-8);
  EXPECT_NEAR(liftoff.c23, ref["C23_at_liftoff"].get<double>(), 1e-12);
}

TEST(Sec4Trajectory, EveryIntegrationPointMatchesOracle) {
  const Flown& f = reference_flight();
  const auto& rows = test::scout_reference()["oracle_solution"]["trajectory"]["rows"];
  double worst[6] = {};
  int matched = 0;
  for (const auto& row : rows) {
    const double t = row[0];
    const int code = row[1];
    // Find my point at (t, stage).
    const TrajectoryPoint* mine = nullptr;
    for (int i = 0; i < f.trajectory.point_count; ++i) {
      const TrajectoryPoint& p = f.trajectory.points[i];
      if (p.stage_code == code && std::fabs(p.time_s - t) < 1e-6) {
        mine = &p;
        break;
      }
    }
    if (mine == nullptr) {
      // The oracle lists each stage boundary once, as the start of the next stage.
      continue;
    }
    ++matched;
    const double ref[6] = {row[3],
                           row[4].get<double>() * kDegToRad,
                           row[6],
                           row[5].get<double>() * kDegToRad,
                           row[8].get<double>() * kDegToRad,
                           row[9].get<double>() * kDegToRad};
    for (int k = 0; k < 6; ++k) {
      worst[k] = std::fmax(worst[k], std::fabs(mine->state[k] - ref[k]));
    }
  }
  std::printf(
      "matched %d of %zu; worst |dV| %.3e ft/s, dgamma %.3e rad, dr %.3e ft, dpsi %.3e, dlat %.3e, dtau "
      "%.3e\n",
      matched, rows.size(), worst[0], worst[1], worst[2], worst[3], worst[4], worst[5]);
  EXPECT_EQ(matched, static_cast<int>(rows.size()));
  // The oracle's rows carry 12 significant digits: 1e-4 ft in r is their rounding.
  EXPECT_LT(worst[kStateV], 1e-6);
  EXPECT_LT(worst[kStateGamma], 1e-11);
  EXPECT_LT(worst[kStateR], 1e-3);
  EXPECT_LT(worst[kStatePsi], 1e-10);
  EXPECT_LT(worst[kStateLambda], 1e-11);
  EXPECT_LT(worst[kStateTau], 1e-11);
}

TEST(Sec4Trajectory, BurnoutStateMatchesOracle) {
  const Flown& f = reference_flight();
  const auto& ref = test::scout_reference()["oracle_solution"]["burnout_state"];
  const TrajectoryPoint& p = f.trajectory.final_point();
  const auto& x = ref["state_vector_rad_order_V_gamma_r_psi_lambda_tau"];
  std::printf("burnout: t %.6f vs %.6f; V %.6f vs %.6f; h %.4f vs %.4f; gamma %.3e; W %.6f\n", p.time_s,
              ref["time_from_launch_s"].get<double>(), p.state[0], x[0].get<double>(), p.altitude_ft,
              ref["altitude_ft"].get<double>(), p.state[1], p.weight_lb);
  EXPECT_NEAR(p.time_s, ref["time_from_launch_s"].get<double>(), 1e-9);
  // Same model choices, step counts and Sec. 14 tables: agreement to round-off, far inside "a few feet".
  EXPECT_NEAR(p.state[kStateV], x[0].get<double>(), 1e-6);
  EXPECT_NEAR(p.state[kStateGamma], x[1].get<double>(), 1e-11);
  EXPECT_NEAR(p.state[kStateR], x[2].get<double>(), 1e-4);
  EXPECT_NEAR(p.state[kStatePsi], x[3].get<double>(), 1e-11);
  EXPECT_NEAR(p.state[kStateLambda], x[4].get<double>(), 1e-11);
  EXPECT_NEAR(p.state[kStateTau], x[5].get<double>(), 1e-11);
  EXPECT_NEAR(p.altitude_ft, ref["altitude_ft"].get<double>(), 1e-4);
  // With the core's exact tables instead (the case as `tolip simulate` flies it), for the record.
  const TrajectoryPoint& e = f.exact_trajectory.final_point();
  std::printf("burnout with the exact Sec. 14 tables minus the oracle's: V %+.4f ft/s, h %+.3f ft\n",
              e.state[kStateV] - x[0].get<double>(), e.altitude_ft - ref["altitude_ft"].get<double>());
  EXPECT_NEAR(p.weight_lb, test::scout_reference()["oracle_solution"]["final_weight_lb"].get<double>(), 1e-6);
}

}  // namespace
}  // namespace tolip

namespace tolip {
namespace {

// The crude starting program of the optimization case flies through every stage to burnout.
TEST(Sec22Trajectory, CrudeInitialNominalFliesEveryStage) {
  static Mission mission;
  static PreparedCase prepared;
  static Trajectory trajectory;
  test::build_reference_mission(test::ReferenceProgram::kInitialNominal, &mission);
  ASSERT_EQ(prepare_case(mission, &prepared), Status::kOk);
  ASSERT_EQ(fly_trajectory(mission, prepared, &trajectory), Status::kOk);
  EXPECT_EQ(trajectory.stage_count, 7);
  EXPECT_NEAR(trajectory.final_point().time_s, 45.0 + 5.0 + 38.0 + 6.0 + 36.0 + 450.0 + 28.0, 1e-9);
  EXPECT_NEAR(trajectory.final_point().weight_lb, 125.0 + 250.0, 1e-9);
  // Stage events: weight drops by the jettison weight between a stage's end and the next start.
  EXPECT_NEAR(trajectory.stages[0].burnout_weight_lb - trajectory.stages[0].weight_after_jettison_lb, 4800.0,
              1e-9);
}

// A NaN in the case reaches the integrator only through a bypassed validation; it must come back as
// a named status, with no NaN stored.
TEST(Sec4Trajectory, NonFiniteInputEndsWithNamedStatusAndNoNaNStored) {
  static Mission mission;
  static PreparedCase prepared;
  static Trajectory trajectory;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &mission);
  ASSERT_EQ(prepare_case(mission, &prepared), Status::kOk);
  mission.control.zero_alpha_end_s = 46.0;
  mission.vehicle.stages[stage_index(6)].reference_area_ft2 = std::nan("");
  const Status status = fly_trajectory(mission, prepared, &trajectory);
  EXPECT_EQ(status, Status::kNonFiniteState);
  EXPECT_GT(trajectory.point_count, 40);  // stage 1 was flown and kept
  for (int i = 0; i < trajectory.point_count; ++i) {
    const TrajectoryPoint& p = trajectory.points[i];
    EXPECT_TRUE(p.state.allFinite() && std::isfinite(p.drag_lbf) && std::isfinite(p.lift_lbf) &&
                std::isfinite(p.alpha_rad) && std::isfinite(p.weight_lb))
        << i;
  }
}

}  // namespace
}  // namespace tolip
