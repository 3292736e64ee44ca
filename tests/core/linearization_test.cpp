// Sec. 6, 10: linearization of the optimum pitch program of the reference mission.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/linearized_reference.hpp"

namespace tolip {
namespace {

using test::LinearizedCase;

// The reference optimized from its crude program, then linearized (built once): with the rate
// limits of its data block 22, or without the two minimum-rate limits.
const LinearizedCase& linearized_reference(bool reference_rate_limits) {
  if (reference_rate_limits) return test::linearized_reference();
  static LinearizedCase relaxed;
  static const bool built = [] {
    test::optimize_reference(&relaxed, [](Mission& m) {
      m.control.min_pitch_rate_rad_s = 0.0;
      m.control.min_pitch_rate_change_rad_s = 0.0;
    });
    test::linearize_optimum(&relaxed);
    return true;
  }();
  static_cast<void>(built);
  return relaxed;
}

double rate_between(const LinearProgram& p, int s) {
  return (p.theta_rad[s + 1] - p.theta_rad[s]) / (p.break_time_s[s + 1] - p.break_time_s[s]);
}

// With every rate limit of the reference's data block 22 (maximum 5, minimum 0.05 and minimum
// change 0.05 deg/s, a single positive rate), the nine segments of data block 18 meet every
// terminal constraint within the linearization deadbands; the payload, which linearization does
// not impose, absorbs the loss and stays within 0.5% of the optimum.
TEST(Sec6Linearization, NineSegmentsMeetEveryRateLimitAndConstraintWithinHalfAPercentOfTheOptimum) {
  const LinearizedCase& r = linearized_reference(true);
  const Mission& mission = r.mission;
  const OptimizerResult& optimum = r.optimum;
  const LinearizationResult& result = r.result;
  const LinearizationWorkspace& workspace = r.workspace;
  ASSERT_EQ(r.optimizer_status, Status::kOk);
  ASSERT_EQ(r.status, Status::kOk) << status_name(result.status);
  std::printf("linearized in %d forward runs (%d programs); payoff %.3f lb vs optimum %.3f lb (%.3f%%)\n",
              result.forward_runs, result.programs_computed, result.payoff, optimum.payload_lb,
              100.0 * (result.payoff / optimum.payload_lb - 1.0));
  EXPECT_TRUE(result.constraints_met);
  EXPECT_TRUE(result.rate_limits_met);
  EXPECT_TRUE(result.finished);
  for (int j = 0; j < result.constraint_count; ++j) {
    EXPECT_LE(std::fabs(result.desired[j] - result.achieved[j]), result.tolerance[j])
        << "code " << result.codes[j];
    EXPECT_TRUE(result.met[j]) << "code " << result.codes[j];
  }
  EXPECT_GE(result.payoff, 0.995 * optimum.payload_lb);
  EXPECT_LE(result.payoff, optimum.payload_lb * (1.0 + 1e-4));
  EXPECT_FALSE(result.coast7_below_min_rate);         // coast 7 is a segment: the limits hold there too
  EXPECT_FALSE(result.coast7_below_min_rate_change);  // straight segments cannot beat the optimum
  EXPECT_LE(result.forward_runs, mission.convergence.max_linearization_iterations);
  const LinearProgram& p = result.program;
  EXPECT_EQ(p.segment_count, 9);
  EXPECT_NEAR(p.theta_rad[0], 0.5 * kPi, 1e-12);  // 90 deg at the end of lift-off
  int positives = 0;
  for (int s = 0; s < p.segment_count; ++s) {
    EXPECT_LE(std::fabs(p.rate_rad_s[s]), mission.control.max_pitch_rate_rad_s * (1.0 + 1e-6))
        << "segment " << s;
    positives += p.rate_rad_s[s] > 1e-7 ? 1 : 0;
  }
  EXPECT_LE(positives, 1);
  // Minimum rate and minimum change of rate (a break whose rate does not change is a merge: Sec. 10
  // "in effect, eliminates a segment").
  for (int s = 0; s < p.segment_count; ++s) {
    EXPECT_GE(std::fabs(rate_between(p, s)), mission.control.min_pitch_rate_rad_s * (1.0 - 1e-6))
        << "segment " << s;
    if (s == 0) continue;
    const double change = std::fabs(rate_between(p, s) - rate_between(p, s - 1));
    EXPECT_TRUE(change < 1e-9 || change >= mission.control.min_pitch_rate_change_rad_s * (1.0 - 1e-6))
        << "segments " << s - 1 << ", " << s << ": change " << change;
  }
  // The linearized trajectory really flies the segments: its command theta is linear between the
  // breaks (with the reference's IP(6) = 1 the flown attitude in stage 1 and coast 6 is the
  // autopilot's steady state about it, Sec. 7; elsewhere the command itself).
  const Trajectory& t = workspace.nominal;
  for (int k = 1; k < t.point_count; ++k) {
    const double time = t.points[k].time_s;
    for (int s = 0; s < p.segment_count; ++s) {
      if (time < p.break_time_s[s] || time > p.break_time_s[s + 1]) continue;
      const double expected = p.theta_rad[s] + p.rate_rad_s[s] * (time - p.break_time_s[s]);
      EXPECT_NEAR(workspace.program.theta_rad[k], expected, 1e-9) << "t = " << time;
      if (!t.points[k].body_dynamics)
        EXPECT_EQ(t.points[k].theta_rad, workspace.program.theta_rad[k]) << "t = " << time;
      break;
    }
  }
}

// IP(6) = 1 (Sec. 10, 11): the accepted point-mass program, flown with body dynamics in stage 1 and
// coast 6, misses the constraints far outside the deadbands (the autopilot lags the 5 deg/s
// pitch-over by K_q/K_theta times the rate); the 6D re-linearization brings every constraint and
// rate limit back within the same DA13(4) budget, and the payoff stays within 0.5% of the optimum.
TEST(Sec10Linearization, SixDRelinearizationMeetsEveryLimitAndConstraintAgain) {
  const LinearizedCase& r = linearized_reference(true);
  ASSERT_EQ(r.mission.options.body_dynamics_6d(), 1);
  ASSERT_EQ(r.status, Status::kOk) << status_name(r.result.status);
  const LinearizationResult& result = r.result;
  EXPECT_TRUE(result.point_mass_met);
  EXPECT_TRUE(result.body_dynamics);
  EXPECT_EQ(result.reference_flights, 1);
  EXPECT_LE(result.forward_runs, r.mission.convergence.max_linearization_iterations);
  bool missed = false;
  for (int j = 0; j < result.constraint_count; ++j) {
    const double pm_error = std::fabs(result.point_mass_achieved[j] - result.desired[j]);
    const double six_d_error = std::fabs(result.point_mass_program_6d_achieved[j] - result.desired[j]);
    EXPECT_LE(pm_error, result.tolerance[j]) << "code " << result.codes[j];
    missed = missed || six_d_error > 5.0 * result.tolerance[j];
    EXPECT_LE(std::fabs(result.achieved[j] - result.desired[j]), result.tolerance[j])
        << "code " << result.codes[j];
    std::printf("code %3d: point-mass program, point mass %.6g, 6D %.6g; 6D program %.6g (desired %.6g)\n",
                result.codes[j], result.point_mass_achieved[j], result.point_mass_program_6d_achieved[j],
                result.achieved[j], result.desired[j]);
  }
  EXPECT_TRUE(missed) << "body dynamics must matter on this case";
  std::printf("payoff: point mass %.4f lb, 6D %.4f lb (difference %.4f lb); optimum %.4f lb\n",
              result.point_mass_payoff, result.payoff, result.payoff - result.point_mass_payoff,
              r.optimum.payload_lb);
  EXPECT_GE(result.payoff, 0.995 * r.optimum.payload_lb);
  EXPECT_GE(result.point_mass_payoff, 0.995 * r.optimum.payload_lb);
  // The flown 6D trajectory really has body dynamics in stage 1 (and only in stage 1 / coast 6).
  int six_d_points = 0;
  for (int k = 0; k < r.workspace.nominal.point_count; ++k) {
    const TrajectoryPoint& point = r.workspace.nominal.points[k];
    if (point.body_dynamics) {
      ++six_d_points;
      EXPECT_TRUE(point.stage_code == 1 || point.stage_code == 6) << "t = " << point.time_s;
    }
  }
  EXPECT_GT(six_d_points, 20);
}

// Without the minimum-rate limits the fit stays closer to the optimum: fewer repairs, a smaller
// payoff loss than with them, and every constraint still met.
TEST(Sec6Linearization, RelaxingTheMinimumRateLimitsLosesLessPayoff) {
  const LinearizedCase& strict = linearized_reference(true);
  const LinearizedCase& relaxed = linearized_reference(false);
  ASSERT_EQ(strict.status, Status::kOk);
  ASSERT_EQ(relaxed.status, Status::kOk);
  EXPECT_TRUE(relaxed.result.constraints_met);
  EXPECT_LT(relaxed.result.program.rate_repair_count, strict.result.program.rate_repair_count);
  EXPECT_GE(relaxed.result.payoff, strict.result.payoff - 1e-6);
}

// Sec. 10's coast-7 messages on hand-made programs: stage 2 (-0.5 deg/s), coast 7, stage 3
// (-0.2 deg/s), limits 0.05 deg/s for both the rate and its change.
TEST(Sec10Linearization, Coast7ChecksFlagARateBelowTheMinimumAndATooSmallChange) {
  static Mission mission;
  mission.control.min_pitch_rate_rad_s = 0.05 * kDegToRad;
  mission.control.min_pitch_rate_change_rad_s = 0.05 * kDegToRad;
  const auto program_with_coast_rate = [](double coast_rate_deg_s) {
    LinearProgram p;
    p.segment_count = 3;
    const double times[4] = {50.0, 88.0, 94.0, 130.0};
    const double rates[3] = {-0.5, coast_rate_deg_s, -0.2};
    const int stages[3] = {2, 7, 3};
    p.theta_rad[0] = 30.0 * kDegToRad;
    for (int s = 0; s < 3; ++s) {
      p.break_time_s[s] = times[s];
      p.stage_code[s] = stages[s];
      p.theta_rad[s + 1] = p.theta_rad[s] + rates[s] * kDegToRad * (times[s + 1] - times[s]);
    }
    p.break_time_s[3] = times[3];
    return p;
  };
  LinearizationResult r;
  check_coast7_rates(mission, program_with_coast_rate(-0.3), &r);
  EXPECT_FALSE(r.coast7_below_min_rate);
  EXPECT_FALSE(r.coast7_below_min_rate_change);
  check_coast7_rates(mission, program_with_coast_rate(-0.03), &r);
  EXPECT_TRUE(r.coast7_below_min_rate);
  EXPECT_FALSE(r.coast7_below_min_rate_change);
  check_coast7_rates(mission, program_with_coast_rate(-0.22), &r);  // 0.02 deg/s from stage 3's rate
  EXPECT_FALSE(r.coast7_below_min_rate);
  EXPECT_TRUE(r.coast7_below_min_rate_change);
  check_coast7_rates(mission, program_with_coast_rate(-0.2), &r);  // the same rate: a merged break
  EXPECT_FALSE(r.coast7_below_min_rate_change);
}

}  // namespace
}  // namespace tolip
