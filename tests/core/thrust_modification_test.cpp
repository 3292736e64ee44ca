// Manual Sec. 14 (subroutine REIN): the ideal velocities A (input table) and B (re-tabulated
// table) are the exact integrals of g0 T / W for piecewise-linear thrust and weight (issue 17).
// Truth not written by the code under test: the rocket equation for a constant-thrust,
// constant-mass-flow stage, and a fine composite Simpson integration on misaligned breakpoints.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "support/reference_mission.hpp"
#include "tolip/vehicle/prepared_case.hpp"

namespace tolip {
namespace {

constexpr int kLongBurnCode = 4;  // the last powered stage of the reference sequence

// The reference mission with stage 4 replaced by a two-point constant-thrust table over a long burn
// and a two-point (constant mass flow) consumable table.
void long_constant_thrust_stage(Mission* mission, double thrust_lbf, double burn_s, double consumable_lb) {
  test::build_reference_mission(test::ReferenceProgram::kOptimum, mission);
  StageData& stage = test::stage(*mission, kLongBurnCode);
  stage.duration_s = burn_s;
  stage.integration_steps = 50;
  stage.vacuum_thrust_lbf.clear();
  ASSERT_EQ(stage.vacuum_thrust_lbf.append(0.0, thrust_lbf), Status::kOk);
  ASSERT_EQ(stage.vacuum_thrust_lbf.append(burn_s, thrust_lbf), Status::kOk);
  ASSERT_EQ(stage.vacuum_thrust_lbf.finalize(), Status::kOk);
  stage.consumable_weight_lb.clear();
  ASSERT_EQ(stage.consumable_weight_lb.append(0.0, consumable_lb), Status::kOk);
  ASSERT_EQ(stage.consumable_weight_lb.append(burn_s, 0.0), Status::kOk);
  ASSERT_EQ(stage.consumable_weight_lb.finalize(), Status::kOk);
}

TEST(Sec14ThrustModification, Sec14_ConstantThrustStageKeepsItsThrustExactly) {
  static Mission mission;
  static PreparedCase prepared;
  const double thrust_lbf = 6000.0;
  const double burn_s = 663.0;  // the long burn, where one Simpson interval gave +1.3 %
  const double consumable_lb = 1500.0;
  long_constant_thrust_stage(&mission, thrust_lbf, burn_s, consumable_lb);
  ASSERT_EQ(prepare_case(mission, &prepared), Status::kOk);

  const ModifiedThrustTable& table = prepared.modified_thrust_lbf[stage_index(kLongBurnCode)];
  ASSERT_EQ(table.size(), 51);
  double worst = 0.0;
  for (int i = 0; i < table.size(); ++i) worst = std::fmax(worst, std::fabs(table.y(i) / thrust_lbf - 1.0));
  EXPECT_LT(worst, 1e-9) << "worst relative thrust change";

  // Rocket equation: Isp = T / (mdot g0) with mdot = consumable / (g0 burn), so Isp g0 = T burn / consumable,
  // and the ideal velocity is Isp g0 ln(m0 / m1) (weights and masses have the same ratio).
  const double g0 = mission.constants.g0_ft_s2;
  const double w0_lb = vehicle_weight_lb(mission.vehicle, kLongBurnCode, 0.0);
  const double w1_lb = w0_lb - consumable_lb;
  const double mass_flow_slug_s = consumable_lb / g0 / burn_s;
  const double isp_s = thrust_lbf / mass_flow_slug_s / g0;
  const double rocket_ft_s = isp_s * g0 * std::log(w0_lb / w1_lb);
  const ThrustModification& mod = prepared.thrust_modification[stage_index(kLongBurnCode)];
  std::printf("A %.12f B %.12f rocket %.12f ft/s; scale - 1 = %.3e\n", mod.ideal_velocity_input_ft_s,
              mod.ideal_velocity_grid_ft_s, rocket_ft_s, mod.scale - 1.0);
  EXPECT_NEAR(mod.ideal_velocity_input_ft_s / rocket_ft_s, 1.0, 1e-9);
  EXPECT_NEAR(mod.ideal_velocity_grid_ft_s / rocket_ft_s, 1.0, 1e-9);
  EXPECT_NEAR(mod.scale, 1.0, 1e-9);
}

// The degenerate pieces of the exact integral: the propellant burns out at half the burn and the
// weight table is held past its end (k = 0 there, where the closed form divides 0 by 0), and its
// end falls inside the single thrust interval (merged breakpoints). Truth by hand: T/q ln(W0/W1)
// over the burning half (q = consumable / (burn / 2)), then T (burn / 2) / W1 at constant weight.
TEST(Sec14ThrustModification, Sec14_WeightHeldPastItsTableEndIsIntegratedAtConstantWeight) {
  static Mission mission;
  static PreparedCase prepared;
  const double thrust_lbf = 6000.0;
  const double burn_s = 100.0;
  const double consumable_lb = 1500.0;
  long_constant_thrust_stage(&mission, thrust_lbf, burn_s, consumable_lb);
  StageData& stage = test::stage(mission, kLongBurnCode);
  stage.consumable_weight_lb.clear();
  ASSERT_EQ(stage.consumable_weight_lb.append(0.0, consumable_lb), Status::kOk);
  ASSERT_EQ(stage.consumable_weight_lb.append(0.5 * burn_s, 0.0), Status::kOk);
  ASSERT_EQ(stage.consumable_weight_lb.finalize(), Status::kOk);
  ASSERT_EQ(prepare_case(mission, &prepared), Status::kOk);

  const double g0 = mission.constants.g0_ft_s2;
  const double w0_lb = vehicle_weight_lb(mission.vehicle, kLongBurnCode, 0.0);
  const double w1_lb = w0_lb - consumable_lb;
  const double q_lb_s = consumable_lb / (0.5 * burn_s);
  const double truth_ft_s =
      g0 * (thrust_lbf / q_lb_s * std::log(w0_lb / w1_lb) + thrust_lbf * 0.5 * burn_s / w1_lb);
  const ThrustModification& mod = prepared.thrust_modification[stage_index(kLongBurnCode)];
  ASSERT_TRUE(std::isfinite(mod.ideal_velocity_input_ft_s) && std::isfinite(mod.ideal_velocity_grid_ft_s));
  EXPECT_NEAR(mod.ideal_velocity_input_ft_s / truth_ft_s, 1.0, 1e-13);
  // The grid (every 2 s) has a breakpoint at the burnout, so B is the same integral and T unchanged.
  EXPECT_NEAR(mod.ideal_velocity_grid_ft_s / truth_ft_s, 1.0, 1e-13);
  const ModifiedThrustTable& table = prepared.modified_thrust_lbf[stage_index(kLongBurnCode)];
  for (int i = 0; i < table.size(); ++i) EXPECT_NEAR(table.y(i) / thrust_lbf, 1.0, 1e-12) << i;
}

// Composite Simpson's rule of g0 T / W with n intervals on each piece between consecutive
// breakpoints of the thrust and weight tables (merged here, independently of the core's walk):
// on a piece the integrand is smooth (T linear over W linear), so the rule converges as h^4 and
// the kinks at the breakpoints cost nothing. Its own error is measured by halving n.
template <typename ThrustTableT>
double fine_ideal_velocity(const Mission& mission, int code, const ThrustTableT& thrust, int n) {
  const double g0 = mission.constants.g0_ft_s2;
  const WeightTable& weight = mission.vehicle.stages[stage_index(code)].consumable_weight_lb;
  std::vector<double> nodes;
  for (int i = 0; i < thrust.size(); ++i) nodes.push_back(thrust.x(i));
  for (int i = 0; i < weight.size(); ++i) {
    if (weight.x(i) > thrust.first_x() && weight.x(i) < thrust.last_x()) nodes.push_back(weight.x(i));
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  const auto f = [&](double t) { return g0 * thrust(t) / vehicle_weight_lb(mission.vehicle, code, t); };
  double total = 0.0;
  for (size_t k = 0; k + 1 < nodes.size(); ++k) {
    const double a = nodes[k];
    const double h = (nodes[k + 1] - a) / n;
    double sum = f(a) + f(nodes[k + 1]);
    for (int i = 1; i < n; ++i) sum += ((i % 2 == 1) ? 4.0 : 2.0) * f(a + i * h);
    total += sum * h / 3.0;
  }
  return total;
}

// The reference Scout's tables (thrust and weight breakpoints not aligned): A and B against the
// piecewise composite Simpson integration above with 256 and 512 intervals per piece.
TEST(Sec14ThrustModification, Sec14_IdealVelocityMatchesFineQuadratureOnEveryReferenceStage) {
  static Mission mission;
  static PreparedCase prepared;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &mission);
  ASSERT_EQ(prepare_case(mission, &prepared), Status::kOk);
  for (const int code : {1, 2, 3, 4}) {
    const ThrustModification& mod = prepared.thrust_modification[stage_index(code)];
    const ThrustTable& input = mission.vehicle.stages[stage_index(code)].vacuum_thrust_lbf;
    const double fine = fine_ideal_velocity(mission, code, input, 512);
    const double coarse = fine_ideal_velocity(mission, code, input, 256);
    // B over the grid table before its scale.
    const ModifiedThrustTable& scaled = prepared.modified_thrust_lbf[stage_index(code)];
    ModifiedThrustTable grid;
    for (int i = 0; i < scaled.size(); ++i)
      ASSERT_EQ(grid.append(scaled.x(i), scaled.y(i) / mod.scale), Status::kOk);
    ASSERT_EQ(grid.finalize(), Status::kOk);
    const double fine_grid = fine_ideal_velocity(mission, code, grid, 512);
    std::printf(
        "stage %d: A %.12f fine %.12f ft/s, relative %.2e (fine's own, by halving: %.2e); B relative %.2e\n",
        code, mod.ideal_velocity_input_ft_s, fine, mod.ideal_velocity_input_ft_s / fine - 1.0,
        fine / coarse - 1.0, mod.ideal_velocity_grid_ft_s / fine_grid - 1.0);
    EXPECT_LT(std::fabs(fine / coarse - 1.0), 1e-14)
        << "stage " << code << ": the check itself is not converged";
    EXPECT_NEAR(mod.ideal_velocity_input_ft_s / fine, 1.0, 1e-14) << "stage " << code;
    EXPECT_NEAR(mod.ideal_velocity_grid_ft_s / fine_grid, 1.0, 1e-14) << "stage " << code;
  }
}

}  // namespace
}  // namespace tolip
