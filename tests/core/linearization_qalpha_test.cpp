// Sec. 6, 10 with the q-bar x alpha load limit (issue 15, a TOLIP extension;
// docs/theory/linearization.md "The q-bar x alpha limit"): the linearization keeps the limit the
// optimizer kept, through the excess integral's row (code 200) in the eq. 6-22 fit, whose
// sensitivity to the break values is proved here against central differences of forward runs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/linearized_reference.hpp"
#include "tolip/optimizer/backward_run.hpp"
#include "tolip/optimizer/constraint_parameters.hpp"
#include "tolip/optimizer/qbar_alpha.hpp"

namespace tolip {
namespace {

constexpr double kLimitLbDegFt2 = 3500.0;  // examples/scout/mission_qalpha.toml
constexpr double kLbDegPerLbRad = 180.0 / kPi;

// The reference mission with the example's limit and forward-run budget (the two changes
// scripts/make_scout_examples.py makes for mission_qalpha.toml), optimized and linearized once.
const test::LinearizedCase& linearized_qalpha() {
  static test::LinearizedCase r;
  static const bool built = [] {
    test::optimize_reference(&r, [](Mission& m) {
      m.options.qbar_alpha_limit_lbf_rad_ft2 = kLimitLbDegFt2 / kLbDegPerLbRad;
      m.convergence.max_forward_trajectories = 40;
      // Its data block 18: stage 1 cut in the load window (QALPHA_TLIN of the generator).
      const double coded[] = {103.0, 106.0, 109.0, 112.0, 115.0, 122.0, 130.0, 138.0,
                              145.0, 200.0, 219.0, 238.0, 300.0, 318.0, 336.0};
      m.linearization.segment_count = 14;
      for (int b = 0; b <= 14; ++b) {
        m.linearization.boundaries[b].stage = static_cast<int>(coded[b] / 100.0);
        m.linearization.boundaries[b].time_from_ignition_s = coded[b] - 100.0 * (int)(coded[b] / 100.0);
      }
      for (int s = 0; s < 14; ++s) m.linearization.segment_weights[s] = 1.0;
    });
    test::linearize_optimum(&r);
    return true;
  }();
  static_cast<void>(built);
  return r;
}

// The largest |q-bar alpha| over the points with aerodynamic lift (stages with the lift table and
// q-bar > 0), written out here from the points' own q-bar and alpha.
double lift_phase_peak_lbf_rad_ft2(const Mission& m, const Trajectory& t, double* time_s) {
  double peak = 0.0;
  for (int k = 0; k < t.point_count; ++k) {
    const TrajectoryPoint& p = t.points[k];
    if (!(p.dynamic_pressure_lbf_ft2 > 0.0) || !m.vehicle.stages[stage_index(p.stage_code)].uses_lift_table)
      continue;
    const double value = std::fabs(p.dynamic_pressure_lbf_ft2 * p.alpha_rad);
    if (value > peak) {
      peak = value;
      *time_s = p.time_s;
    }
  }
  return peak;
}

// The linearized program of the limited optimum keeps the limit: code 200 is in its constraint
// list and met (the excess integral within the optimizer's deadband), with every other
// constraint and rate limit, and the payload it carries is reported.
TEST(Sec6QAlphaLinearization, LinearizedProgramKeepsTheLimitWithinTheOptimizersCriterion) {
  const test::LinearizedCase& r = linearized_qalpha();
  ASSERT_EQ(r.optimizer_status, Status::kOk);
  const LinearizationResult& result = r.result;
  ASSERT_TRUE(result.finished) << status_name(r.status);
  int row = -1;
  for (int j = 0; j < result.constraint_count; ++j) {
    std::printf("code %3d achieved % .6e desired % .6e tolerance %.3e met %d\n", result.codes[j],
                result.achieved[j], result.desired[j], result.tolerance[j], result.met[j] ? 1 : 0);
    if (result.codes[j] == kQbarAlphaConstraintCode) row = j;
  }
  ASSERT_GE(row, 0) << "the q-bar x alpha excess (code 200) is a linearization constraint";
  double time_s = 0.0;
  const double peak = lift_phase_peak_lbf_rad_ft2(r.workspace.mission, r.workspace.nominal, &time_s);
  std::printf(
      "linearized: %s in %d forward runs (%d programs, %d repairs, 6D %d), payload %.4f lb "
      "(optimum %.4f lb), peak %.1f lb deg/ft^2 at %.2f s, excess %.3e s\n",
      status_name(r.status), result.forward_runs, result.programs_computed, result.program.rate_repair_count,
      result.body_dynamics ? 1 : 0, result.payoff, r.optimum.payload_lb, peak * kLbDegPerLbRad, time_s,
      result.achieved[row]);
  EXPECT_EQ(r.status, Status::kOk) << status_name(r.status);
  EXPECT_TRUE(result.constraints_met);
  EXPECT_TRUE(result.rate_limits_met);
  EXPECT_TRUE(result.met[row]);
  EXPECT_LE(result.achieved[row], kQbarAlphaExcessDeadbandS);
  // The row's value is the excess integral of the trajectory the result describes.
  EXPECT_EQ(result.achieved[row], qbar_alpha_excess_s(r.workspace.mission, r.workspace.nominal));
  // Within the deadband of the excess integral (1e-4 s: about a 1 % excess held for 1 s).
  EXPECT_LE(peak * kLbDegPerLbRad, 1.01 * kLimitLbDegFt2);
  // The straight segments cost payload against the limited optimum, but not much.
  EXPECT_LE(result.payoff, r.optimum.payload_lb * (1.0 + 1e-4));
  EXPECT_GE(result.payoff, 0.98 * r.optimum.payload_lb);
}

// The peak row's sensitivity (qbar_alpha_peak_gradients: an adjoint column started at the peak
// from qbar_alpha_point_partials, summed over the fit's hat functions, plus the point's own
// attitude) to every break value, and its payload column, against central differences of forward
// runs, about the linearized program flown point mass at its largest peak.
TEST(Sec6QAlphaLinearization, Sec6_QAlphaPeakSensitivityMatchesFiniteDifference) {
  const test::LinearizedCase& r = linearized_qalpha();
  ASSERT_TRUE(r.result.finished) << status_name(r.status);
  static Mission mission;
  mission = r.workspace.mission;
  mission.options.ip[6] = 0;  // point mass: the backward run below linearizes a point-mass flight
  const LinearProgram& p = r.result.program;
  static ControlProgram program;
  static Trajectory nominal;
  static Trajectory perturbed;
  static BackwardRun backward;
  // The linearized program at the points (hat functions, written here), flown point mass.
  program.point_count = r.workspace.nominal.point_count;
  for (int k = 0; k < program.point_count; ++k) {
    const double t = r.workspace.nominal.points[k].time_s;
    double theta = r.workspace.nominal.points[k].theta_rad;  // outside the breaks: as flown
    for (int s = 0; s < p.segment_count; ++s) {
      if (t >= p.break_time_s[s] && t <= p.break_time_s[s + 1]) {
        const double f = (t - p.break_time_s[s]) / (p.break_time_s[s + 1] - p.break_time_s[s]);
        theta = p.theta_rad[s] + f * (p.theta_rad[s + 1] - p.theta_rad[s]);
        break;
      }
    }
    program.theta_rad[k] = theta;
  }
  ASSERT_EQ(fly_trajectory(mission, r.workspace.prepared, program, &nominal), Status::kOk);
  const QbarAlphaPeak peak = peak_qbar_alpha(mission, nominal, true);
  ASSERT_GT(peak.point, 0);
  ConstraintTerminal terminal;
  terminal.point = peak.point;
  StateVector ds_dx;
  double direct = 0.0;
  ASSERT_EQ(qbar_alpha_point_partials(mission, r.workspace.prepared, nominal, peak.point, &ds_dx, &direct),
            Status::kOk);
  terminal.partials.head<6>() = ds_dx;
  ASSERT_EQ(run_backward(mission, r.workspace.prepared, nominal, 1, &terminal, &backward), Status::kOk);
  double gradient[kMaxBreakPoints] = {};
  qbar_alpha_peak_gradients(backward, nominal, p, 0, peak.point, direct, gradient);

  const auto hat = [&](int b, double t) {
    if (b > 0 && t >= p.break_time_s[b - 1] && t <= p.break_time_s[b])
      return (t - p.break_time_s[b - 1]) / (p.break_time_s[b] - p.break_time_s[b - 1]);
    if (b < p.segment_count && t >= p.break_time_s[b] && t <= p.break_time_s[b + 1])
      return (p.break_time_s[b + 1] - t) / (p.break_time_s[b + 1] - p.break_time_s[b]);
    return 0.0;
  };
  const auto s_at_peak = [&](const Trajectory& t) { return qbar_alpha_lbf_rad_ft2(t.points[peak.point]); };
  static ControlProgram changed;
  const double d_theta = 1e-5;  // rad
  int checked = 0;
  double worst = 0.0;
  for (int b = 0; b <= p.segment_count; ++b) {
    double value[2] = {};
    for (int side = 0; side < 2; ++side) {
      changed = program;
      for (int k = 0; k < program.point_count; ++k)
        changed.theta_rad[k] += (side == 0 ? 1.0 : -1.0) * d_theta * hat(b, nominal.points[k].time_s);
      ASSERT_EQ(fly_trajectory(mission, r.workspace.prepared, changed, &perturbed), Status::kOk);
      value[side] = s_at_peak(perturbed);
    }
    const double fd = (value[0] - value[1]) / (2.0 * d_theta);
    std::printf("break %2d at %7.2f s: ds/dtheta adjoint % .6e  fd % .6e\n", b, p.break_time_s[b],
                gradient[b], fd);
    // Breaks after the peak's segment do not reach it: both zero.
    if (p.break_time_s[b] > nominal.points[peak.point].time_s &&
        (b == 0 || p.break_time_s[b - 1] >= nominal.points[peak.point].time_s)) {
      EXPECT_EQ(gradient[b], 0.0) << "break " << b;
      EXPECT_EQ(fd, 0.0) << "break " << b;
      continue;
    }
    ++checked;
    worst = std::fmax(worst, std::fabs(gradient[b] - fd) / std::fabs(fd));
    EXPECT_LE(std::fabs(gradient[b] - fd), 0.01 * std::fabs(fd)) << "break " << b;
  }
  EXPECT_GE(checked, 3);  // the peak's own segment and the breaks before it

  // The payload column (per lb), which the fit uses when the payload is free.
  const double d_payload_lb = 0.5;
  double value[2] = {};
  for (int side = 0; side < 2; ++side) {
    static Mission heavier;
    heavier = mission;
    heavier.vehicle.payload_lb += (side == 0 ? 1.0 : -1.0) * d_payload_lb;
    static PreparedCase prepared;
    ASSERT_EQ(prepare_case(heavier, &prepared), Status::kOk);
    ASSERT_EQ(fly_trajectory(heavier, prepared, program, &perturbed), Status::kOk);
    value[side] = s_at_peak(perturbed);
  }
  const double fd = (value[0] - value[1]) / (2.0 * d_payload_lb);
  std::printf("peak %.1f lb deg/ft^2 at %.2f s; payload: ds/dW adjoint % .6e  fd % .6e; worst break %.2e\n",
              peak.value_lbf_rad_ft2 * kLbDegPerLbRad, peak.time_s, backward.payload(0), fd, worst);
  EXPECT_GT(std::fabs(fd), 0.0);
  EXPECT_LE(std::fabs(backward.payload(0) - fd), 0.01 * std::fabs(fd));
}

// Without a limit the linearization's constraint list has no code 200 (and the reference's
// results are bit for bit those before the limit existed: its pinned figures elsewhere).
TEST(Sec6QAlphaLinearization, WithoutALimitTheLinearizationHasNoQAlphaRow) {
  const test::LinearizedCase& r = test::linearized_reference();
  ASSERT_FALSE(r.mission.options.qbar_alpha_constraint());
  ASSERT_EQ(r.optimizer_status, Status::kOk);
  ASSERT_EQ(r.status, Status::kOk);
  for (int j = 0; j < r.result.constraint_count; ++j) EXPECT_NE(r.result.codes[j], kQbarAlphaConstraintCode);
}

}  // namespace
}  // namespace tolip
