// Guidance executor (tolip/table/guidance_executor.hpp) and the attitude control law
// (tolip/table/control_law.hpp), on hand-made tables.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "support/guidance_table_fixture.hpp"
#include "tolip/table/control_law.hpp"
#include "tolip/table/guidance_executor.hpp"
#include "tolip/table/table_service.hpp"

namespace tolip {
namespace {

constexpr double kHalfPi = 0.5 * kPi;

class Executor : public ::testing::Test {
 protected:
  void SetUp() override { load(test::make_test_table()); }

  void load(const GuidanceTable& table) {
    table_ = table;
    std::vector<std::uint8_t> image(kTableImageSize);
    ASSERT_EQ(encode_table_image(table, image.data(), image.size()), Status::kOk);
    ASSERT_EQ(service_.load(image.data(), image.size()), Status::kOk);
  }

  // Fires the events of the test timeline up to time t (inclusive).
  void advance_events(GuidanceExecutor* executor, double t) {
    for (const test::TestStageStart& event : test::kTestTimeline) {
      if (event.start_s <= t &&
          flight_order_index(event.code) > flight_order_index(executor->stage_in_force())) {
        ASSERT_EQ(executor->stage_event(event.code, event.start_s), Status::kOk);
      }
    }
  }

  GuidanceCommand command_at(double t) {
    GuidanceExecutor executor(service_);
    advance_events(&executor, t);
    GuidanceCommand command;
    EXPECT_EQ(executor.step(t, &command), Status::kOk) << t;
    return command;
  }

  GuidanceTable table_;
  GuidanceTableService service_;
};

TEST_F(Executor, HoldsNinetyDegreesThroughLiftoff) {
  GuidanceExecutor executor(service_);
  for (int k = 0; k < 300; ++k) {
    const double t = k / 100.0;  // 0 .. 2.99 s
    GuidanceCommand command;
    ASSERT_EQ(executor.step(t, &command), Status::kOk);
    EXPECT_EQ(command.mode, GuidanceMode::kLiftoffHold) << t;
    EXPECT_EQ(command.theta_rad, kHalfPi) << t;
    EXPECT_EQ(command.theta_dot_rad_s, 0.0) << t;
    EXPECT_EQ(command.chi_rad, 0.0) << t;
    EXPECT_EQ(command.stage_code, 1);
    EXPECT_EQ(command.k_theta, table_.gains[0].k_theta);
    EXPECT_EQ(command.k_q_s, table_.gains[0].k_q_s);
    EXPECT_EQ(command.max_deflection_rad, table_.max_deflection_rad);
  }
  // At the end of the lift-off the first segment takes over (it starts at 3 s with 90 deg).
  GuidanceCommand command;
  ASSERT_EQ(executor.step(3.0, &command), Status::kOk);
  EXPECT_EQ(command.mode, GuidanceMode::kSegment);
  EXPECT_EQ(command.segment_index, 0);
  EXPECT_DOUBLE_EQ(command.theta_rad, 90.0 * kDegToRad);
  EXPECT_EQ(command.theta_dot_rad_s, -2.0 * kDegToRad);
}

TEST_F(Executor, StepsThroughSegmentsInFlightOrder) {
  struct Expect {
    double t;
    int stage;
    int segment;
    double theta_deg;
  };
  const Expect expects[] = {
      {3.0, 1, 0, 90.0},   {5.5, 1, 0, 85.0},   {9.999, 1, 0, 90.0 - 2.0 * 6.999},
      {10.0, 1, 1, 76.0},  {44.0, 1, 1, 59.0},  {45.0, 6, 2, 60.0},
      {49.5, 6, 2, 60.0},  {50.0, 2, 3, 60.0},  {60.0, 2, 3, 50.0},
      {70.0, 2, 4, 40.0},  {87.0, 2, 4, 44.25}, {88.0, 7, 5, 45.0},
      {94.0, 3, 5, 45.0},  {98.0, 3, 5, 45.0},  {99.0, 3, 6, 38.0},
      {129.0, 3, 6, 35.0}, {130.0, 8, 7, 35.0}, {549.0, 8, 7, 35.0},
  };
  for (const Expect& e : expects) {
    const GuidanceCommand command = command_at(e.t);
    EXPECT_EQ(command.stage_code, e.stage) << e.t;
    EXPECT_EQ(command.segment_index, e.segment) << e.t;
    EXPECT_EQ(command.mode, GuidanceMode::kSegment) << e.t;
    EXPECT_NEAR(command.theta_rad * kRadToDeg, e.theta_deg, 1e-12) << e.t;
    EXPECT_EQ(command.theta_dot_rad_s, table_.segments[e.segment].rate_rad_s) << e.t;
    EXPECT_EQ(command.chi_rad, 0.0) << e.t;
    EXPECT_EQ(command.k_theta, table_.gains[e.stage - 1].k_theta) << e.t;
    EXPECT_EQ(command.k_q_s, table_.gains[e.stage - 1].k_q_s) << e.t;
  }
}

TEST_F(Executor, ASegmentContinuesAcrossAStageBoundaryUntilTheNextStarts) {
  // Segment 5 (coast 7, hold 45 deg) is still in force in stage 3 until segment 6 starts at
  // stage time 5 s; segment 4 (stage 2, +0.25 deg/s) in a table without the coast-7 hold runs on.
  GuidanceTable table = test::make_test_table();
  for (int i = 5; i + 1 < table.segment_count; ++i) table.segments[i] = table.segments[i + 1];
  --table.segment_count;
  load(table);
  const GuidanceCommand command = command_at(92.0);  // coast 7, 22 s after segment 4 started
  EXPECT_EQ(command.stage_code, 7);
  EXPECT_EQ(command.segment_index, 4);
  EXPECT_NEAR(command.theta_rad * kRadToDeg, 40.0 + 0.25 * 22.0, 1e-12);
  EXPECT_EQ(command.k_theta, table.gains[6].k_theta);  // the gains follow the stage in force
}

TEST_F(Executor, HoldsSpunAttitudesInStagesFourAndFive) {
  for (double t : {550.0, 560.0, 577.9}) {
    const GuidanceCommand c = command_at(t);
    EXPECT_EQ(c.stage_code, 4);
    EXPECT_EQ(c.mode, GuidanceMode::kSpunHold);
    EXPECT_EQ(c.theta_rad, table_.stage4_theta_rad);
    EXPECT_EQ(c.chi_rad, table_.stage4_chi_rad);
    EXPECT_EQ(c.theta_dot_rad_s, 0.0);
    EXPECT_EQ(c.segment_index, -1);
  }
  const GuidanceCommand coast9 = command_at(590.0);
  EXPECT_EQ(coast9.stage_code, 9);
  EXPECT_EQ(coast9.theta_rad, table_.stage4_theta_rad);
  EXPECT_EQ(coast9.chi_rad, table_.stage4_chi_rad);
  for (double t : {600.0, 640.0}) {
    const GuidanceCommand c = command_at(t);
    EXPECT_EQ(c.mode, GuidanceMode::kSpunHold);
    EXPECT_EQ(c.theta_rad, table_.stage5_theta_rad);
    EXPECT_EQ(c.chi_rad, table_.stage5_chi_rad);
    EXPECT_EQ(c.k_theta, table_.gains[c.stage_code - 1].k_theta);
  }
}

// Sec. 22 IP(9) = 2: stage 4 flies its segments (and coast 9 the last one, held), stage 5 and coast
// 10 stay spun; IP(9) = 3: stage 5 flies segments too.
TEST_F(Executor, Sec22_IP9FliesSegmentsInTheContinuousUpperStagesAndHoldsTheSpunOnes) {
  GuidanceTable table = test::make_test_table();
  table.spin_option = 2;
  table.stage4_theta_rad = 0.0;
  table.stage4_chi_rad = 0.0;
  const int stage4 = table.segment_count;
  table.segments[table.segment_count++] = GuidanceSegment{4, 0.0, -0.35, -0.001};
  table.segments[table.segment_count++] = GuidanceSegment{9, 0.0, -0.38, 0.0};
  load(table);
  for (double t : {550.0, 560.0, 577.9}) {
    const GuidanceCommand c = command_at(t);
    EXPECT_EQ(c.stage_code, 4);
    EXPECT_EQ(c.mode, GuidanceMode::kSegment) << t;
    EXPECT_EQ(c.segment_index, stage4) << t;
    EXPECT_NEAR(c.theta_rad, -0.35 - 0.001 * (t - 550.0), 1e-15) << t;
    EXPECT_EQ(c.theta_dot_rad_s, -0.001);
  }
  const GuidanceCommand coast9 = command_at(590.0);
  EXPECT_EQ(coast9.mode, GuidanceMode::kSegment);
  EXPECT_EQ(coast9.theta_rad, -0.38);
  for (double t : {600.0, 640.0}) {
    const GuidanceCommand c = command_at(t);
    EXPECT_EQ(c.mode, GuidanceMode::kSpunHold) << t;
    EXPECT_EQ(c.theta_rad, table.stage5_theta_rad);
  }
  table.spin_option = 3;
  load(table);
  const GuidanceCommand stage5 = command_at(610.0);
  EXPECT_EQ(stage5.stage_code, 5);
  EXPECT_EQ(stage5.mode, GuidanceMode::kSegment);  // the coast-9 hold stays in force
  EXPECT_EQ(stage5.theta_rad, -0.38);
}

TEST_F(Executor, HoldsVerticalAfterLiftoffUntilTheFirstSegmentStarts) {
  GuidanceTable table = test::make_test_table();
  table.segments[0].start_stage_time_s = 6.0;
  table.segments[0].theta_start_rad = 84.0 * kDegToRad;
  load(table);
  const GuidanceCommand before = command_at(4.0);
  EXPECT_EQ(before.mode, GuidanceMode::kHoldBeforeSegments);
  EXPECT_EQ(before.theta_rad, kHalfPi);
  EXPECT_EQ(before.segment_index, -1);
  const GuidanceCommand after = command_at(6.5);
  EXPECT_EQ(after.segment_index, 0);
  EXPECT_NEAR(after.theta_rad * kRadToDeg, 83.0, 1e-12);
}

TEST_F(Executor, ASkippedStageContributesNoSegment) {
  GuidanceExecutor executor(service_);
  ASSERT_EQ(executor.stage_event(2, 50.0), Status::kOk);  // coast 6 never reported
  GuidanceCommand command;
  ASSERT_EQ(executor.step(55.0, &command), Status::kOk);
  EXPECT_EQ(command.segment_index, 3);
  EXPECT_NEAR(command.theta_rad * kRadToDeg, 55.0, 1e-12);
}

TEST_F(Executor, RejectsEventsOutOfOrderAndNonFiniteTimesWithoutChangingState) {
  GuidanceExecutor executor(service_);
  ASSERT_EQ(executor.stage_event(2, 50.0), Status::kOk);
  EXPECT_EQ(executor.stage_event(6, 60.0), Status::kStageEventOutOfOrder);  // earlier in flight order
  EXPECT_EQ(executor.stage_event(7, 40.0), Status::kStageEventOutOfOrder);  // earlier in time
  EXPECT_EQ(executor.stage_event(2, 51.0), Status::kStageEventOutOfOrder);  // stage 2 again, other time
  EXPECT_EQ(executor.stage_event(2, 50.0), Status::kOk);                    // repeated signal
  EXPECT_EQ(executor.stage_event(0, 60.0), Status::kUnknownStageCode);
  EXPECT_EQ(executor.stage_event(11, 60.0), Status::kUnknownStageCode);
  EXPECT_EQ(executor.stage_event(7, std::numeric_limits<double>::quiet_NaN()), Status::kValueNotFinite);
  EXPECT_EQ(executor.stage_in_force(), 2);
  EXPECT_EQ(executor.stage_start_s(2), 50.0);
  GuidanceCommand command;
  command.theta_rad = -7.0;
  EXPECT_EQ(executor.step(std::numeric_limits<double>::infinity(), &command), Status::kValueNotFinite);
  EXPECT_EQ(executor.step(49.0, &command), Status::kStageEventOutOfOrder);  // before the stage in force
  EXPECT_EQ(command.theta_rad, -7.0);
  executor.reset();
  EXPECT_EQ(executor.stage_in_force(), 1);
}

TEST_F(Executor, WorstCasePathOverAFullTableIsDeterministic) {
  // Fifteen stage-1 segments: the command past the last start scans the whole table, the bound.
  GuidanceTable table = test::make_test_table();
  table.segment_count = kMaxLinearSegments;
  for (int i = 0; i < kMaxLinearSegments; ++i) {
    table.segments[i] = GuidanceSegment{1, 3.0 + 2.0 * i, (90.0 - 2.0 * i) * kDegToRad, -1.0 * kDegToRad};
  }
  load(table);
  GuidanceExecutor executor(service_);
  GuidanceCommand first;
  ASSERT_EQ(executor.step(40.0, &first), Status::kOk);
  EXPECT_EQ(first.segment_index, kMaxLinearSegments - 1);
  EXPECT_NEAR(first.theta_rad * kRadToDeg, 62.0 - 9.0, 1e-12);
  for (int repeat = 0; repeat < 1000; ++repeat) {
    GuidanceCommand again;
    ASSERT_EQ(executor.step(40.0, &again), Status::kOk);
    ASSERT_EQ(std::bit_cast<std::uint64_t>(again.theta_rad), std::bit_cast<std::uint64_t>(first.theta_rad));
  }
}

TEST_F(Executor, FollowsANewlyCommittedTableOnTheNextCycle) {
  GuidanceExecutor executor(service_);
  GuidanceCommand before;
  ASSERT_EQ(executor.step(20.0, &before), Status::kOk);
  load(test::make_test_table(1));
  GuidanceCommand after;
  ASSERT_EQ(executor.step(20.0, &after), Status::kOk);
  EXPECT_NEAR((after.theta_rad - before.theta_rad) * kRadToDeg, 1.5, 1e-12);
}

// ---- control law ---------------------------------------------------------------------------------

GuidanceCommand control_command() {
  GuidanceCommand command;
  command.theta_rad = 0.5;
  command.k_theta = 1.2;
  command.k_q_s = 0.35;
  command.max_deflection_rad = 10.0 * kDegToRad;
  return command;
}

TEST(ControlLaw, IsKThetaTimesAttitudeErrorMinusKqTimesRate) {
  const GuidanceCommand command = control_command();
  ControlDeflection out;
  ASSERT_EQ(attitude_control_deflection(command, 0.48, 0.01, &out), Status::kOk);
  EXPECT_DOUBLE_EQ(out.deflection_rad, 1.2 * (0.5 - 0.48) - 0.35 * 0.01);
  EXPECT_EQ(out.deflection_rad, out.unlimited_rad);
  EXPECT_FALSE(out.saturated);
  ASSERT_EQ(attitude_control_deflection(command, 0.5, 0.0, &out), Status::kOk);
  EXPECT_EQ(out.deflection_rad, 0.0);
}

TEST(ControlLaw, LimitsTheDeflectionSymmetrically) {
  const GuidanceCommand command = control_command();
  ControlDeflection out;
  ASSERT_EQ(attitude_control_deflection(command, 0.0, 0.0, &out), Status::kOk);  // 0.6 rad demanded
  EXPECT_EQ(out.deflection_rad, command.max_deflection_rad);
  EXPECT_TRUE(out.saturated);
  EXPECT_DOUBLE_EQ(out.unlimited_rad, 0.6);
  ASSERT_EQ(attitude_control_deflection(command, 1.0, 0.5, &out), Status::kOk);
  EXPECT_EQ(out.deflection_rad, -command.max_deflection_rad);
  EXPECT_TRUE(out.saturated);
}

TEST(ControlLaw, NonFiniteInputGivesANeutralDeflectionAndNamesTheFault) {
  const GuidanceCommand command = control_command();
  ControlDeflection out;
  out.deflection_rad = 0.3;
  EXPECT_EQ(attitude_control_deflection(command, std::numeric_limits<double>::quiet_NaN(), 0.0, &out),
            Status::kValueNotFinite);
  EXPECT_EQ(out.deflection_rad, 0.0);
  EXPECT_FALSE(out.saturated);
  EXPECT_EQ(attitude_control_deflection(command, 0.0, std::numeric_limits<double>::infinity(), &out),
            Status::kValueNotFinite);
}

}  // namespace
}  // namespace tolip
