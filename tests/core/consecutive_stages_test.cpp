// Issue 17, manual Sec. 22 data block 5: powered stages directly after each other (a coast left out
// of the sequence, hot staging or parallel boosters), on the reference mission without coast 6
// (sequence 1 2 7 3 8 4): it validates and flies, the burnt-out stage 1 is jettisoned at the
// boundary and stage 2 ignites at the same time and state; with a coast of vanishing length
// epsilon instead the flight differs only by the adjoint's coast sensitivity times epsilon; the
// adjoint (Sec. 5, 9) across the boundary matches central differences of forward runs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "support/adjoint_check.hpp"
#include "support/reference_mission.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/optimizer/backward_run.hpp"
#include "tolip/optimizer/steepest_descent.hpp"
#include "tolip/orbit/orbit_elements.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip/vehicle/prepared_case.hpp"

namespace tolip {
namespace {

// Removes `code` from the sequence of data block 5.
void leave_out_of_sequence(Mission* mission, int code) {
  StageSequence& sequence = mission->vehicle.sequence;
  int kept = 0;
  for (int k = 0; k < sequence.count; ++k) {
    if (sequence.codes[k] != code) sequence.codes[kept++] = sequence.codes[k];
  }
  for (int k = kept; k < sequence.count; ++k) sequence.codes[k] = 0;
  sequence.count = kept;
  mission->vehicle.stages[stage_index(code)].in_sequence = false;
}

// Data block 18 without the entries that became the instant before them (stage n's burnout
// coded beside stage n+1's ignition once the coast between them is left out), as a deck must.
void drop_repeated_staging_instants(Mission* mission) {
  LinearizationData& l = mission->linearization;
  const auto instant = [&](const SegmentBoundary& boundary) {
    double start = 0.0;
    for (int k = 0; k < mission->vehicle.sequence.count; ++k) {
      const int listed = mission->vehicle.sequence.codes[k];
      if (listed == boundary.stage) break;
      start += mission->vehicle.stages[stage_index(listed)].duration_s;
    }
    return start + boundary.time_from_ignition_s;
  };
  for (int i = 1; i <= l.segment_count;) {
    if (instant(l.boundaries[i]) > instant(l.boundaries[i - 1])) {
      ++i;
      continue;
    }
    for (int j = i; j < kMaxLinearSegments; ++j) l.boundaries[j] = l.boundaries[j + 1];
    l.boundaries[kMaxLinearSegments] = SegmentBoundary{};
    for (int j = i - 1; j + 1 < kMaxLinearSegments; ++j) l.segment_weights[j] = l.segment_weights[j + 1];
    --l.segment_count;
  }
}

using test::kTerminalCount;
using test::kTerminalNames;
using test::terminal;
using test::terminal_partials;

// The reference optimum without coast 6, flown with its own per-point program, and its backward run.
test::AdjointCase& fixture() {
  static test::AdjointCase* f = [] {
    static test::AdjointCase c;
    test::build_reference_mission(test::ReferenceProgram::kOptimum, &c.mission);
    leave_out_of_sequence(&c.mission, 6);
    drop_repeated_staging_instants(&c.mission);
    EXPECT_EQ(validate_mission(c.mission, nullptr), Status::kOk);
    test::fly_nominal_and_run_backward(&c);
    return &c;
  }();
  return *f;
}

TEST(Sec22Block5ConsecutiveStages, SequenceWithoutTheCoastAfterStage1FliesWithTheJettisonAtTheBoundary) {
  test::AdjointCase& f = fixture();
  ASSERT_EQ(f.nominal.status, Status::kOk);
  const int expected[] = {1, 2, 7, 3, 8, 4};
  ASSERT_EQ(f.nominal.stage_count, 6);
  for (int s = 0; s < 6; ++s) EXPECT_EQ(f.nominal.stages[s].code, expected[s]);
  const StageEvent& stage1 = f.nominal.stages[0];
  const StageEvent& stage2 = f.nominal.stages[1];
  const TrajectoryPoint& burnout = f.nominal.points[stage1.last_point];
  const TrajectoryPoint& ignition = f.nominal.points[stage2.first_point];
  EXPECT_EQ(stage2.first_point, stage1.last_point + 1);
  // Stage 2 ignites at stage 1's burnout: same time, same state, stage time 0.
  EXPECT_EQ(ignition.time_s, burnout.time_s);
  EXPECT_EQ(ignition.stage_time_s, 0.0);
  EXPECT_EQ(ignition.state, burnout.state);
  EXPECT_NEAR(burnout.time_s, f.mission.vehicle.stages[0].duration_s, 1e-9);
  // The burnt-out stage 1 leaves with exactly its jettison weight (there is no coast 6 in between).
  const double jettison = f.mission.vehicle.stages[0].jettison_weight_lb;
  EXPECT_GT(jettison, 0.0);
  EXPECT_NEAR(stage1.burnout_weight_lb - stage1.weight_after_jettison_lb, jettison, 1e-9);
  EXPECT_NEAR(ignition.weight_lb, stage1.burnout_weight_lb - jettison, 1e-9);
  EXPECT_GT(ignition.vacuum_thrust_lbf, 0.0);  // stage 2 burns from its first point
  // The timeline: stage 2 starts where stage 1 ends, 5 stage events later the last stage ends.
  EXPECT_EQ(f.prepared.timeline[1].code, 2);
  EXPECT_EQ(f.prepared.timeline[1].start_s, f.prepared.timeline[0].duration_s);
  std::printf("stage 1 burnout %.3f s, %.3f lb; stage 2 ignition %.3f lb; final V %.3f ft/s, h %.1f ft\n",
              burnout.time_s, stage1.burnout_weight_lb, ignition.weight_lb,
              f.nominal.final_point().state[kStateV], f.nominal.final_point().altitude_ft);
}

// An epsilon coast against no coast: both fly the same per-point pitch program (the epsilon
// coast's two points removed), so to first order the flights differ by dX/dT_coast * epsilon,
// the coast sensitivity of the backward run (the flight after the coast starts epsilon later and
// from a state moved by f epsilon). With epsilon = 1e-6 s the second-order term is ~1e-12 of the
// first; the two runs' round-off is ~1e-10 relative to the terminal values; the first-order
// prediction itself is accurate to the backward run's 1e-3 (tests/core/backward_run_test.cpp).
// Both runs fly the per-point program, the epsilon case too: the data block 40 table flight is
// not that program's flight, because a point's recorded theta is the attitude of the step that
// starts there, and where the zero-alpha window starts (t = 15 s) that is the alpha = 0 attitude,
// not the table's value the step before it ended on (1.5e-7 rad apart on the reference tables).
TEST(Sec22Block5ConsecutiveStages, AbsentCoastAgreesWithAnEpsilonCoastToFirstOrder) {
  test::AdjointCase& absent = fixture();
  static Mission eps_mission;
  static PreparedCase eps_prepared;
  static Trajectory eps_table_flight;
  static ControlProgram eps_program;
  static Trajectory eps_flight;
  static BackwardRun eps_backward;
  static ControlProgram program;
  static Trajectory absent_flight;
  const double epsilon = 1e-6;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &eps_mission);
  eps_mission.vehicle.stages[stage_index(6)].duration_s = epsilon;
  eps_mission.vehicle.stages[stage_index(6)].integration_steps = 1;
  ASSERT_EQ(validate_mission(eps_mission, nullptr), Status::kOk);
  ASSERT_EQ(prepare_case(eps_mission, &eps_prepared), Status::kOk);
  ASSERT_EQ(fly_trajectory(eps_mission, eps_prepared, &eps_table_flight), Status::kOk);
  eps_program.point_count = eps_table_flight.point_count;
  for (int i = 0; i < eps_table_flight.point_count; ++i)
    eps_program.theta_rad[i] = eps_table_flight.points[i].theta_rad;
  ASSERT_EQ(fly_trajectory(eps_mission, eps_prepared, eps_program, &eps_flight), Status::kOk);
  ASSERT_EQ(eps_flight.stages[1].code, 6);
  ASSERT_EQ(eps_flight.stages[1].last_point - eps_flight.stages[1].first_point, 1);
  ConstraintTerminal terminals[kTerminalCount];
  terminal_partials(eps_mission.constants, eps_flight, terminals);
  ASSERT_EQ(run_backward(eps_mission, eps_prepared, eps_flight, kTerminalCount, terminals, &eps_backward),
            Status::kOk);

  // The same program without the coast's two points.
  program.point_count = 0;
  for (int i = 0; i < eps_flight.point_count; ++i) {
    if (eps_flight.points[i].stage_code == 6) continue;
    program.theta_rad[program.point_count++] = eps_program.theta_rad[i];
  }
  ASSERT_EQ(program.point_count, trajectory_point_count(absent.prepared));
  ASSERT_EQ(fly_trajectory(absent.mission, absent.prepared, program, &absent_flight), Status::kOk);

  for (int j = 0; j < kTerminalCount; ++j) {
    const double with_eps = terminal(eps_mission.constants, eps_flight.final_point().state, j);
    const double without = terminal(absent.mission.constants, absent_flight.final_point().state, j);
    const double predicted = -eps_backward.coast_duration[stage_index(6)](j) * epsilon;
    const double difference = without - with_eps;
    std::printf("%-12s eps coast % .12e  absent % .12e  diff % .3e  predicted % .3e\n", kTerminalNames[j],
                with_eps, without, difference, predicted);
    EXPECT_NEAR(difference, predicted, 0.02 * std::fabs(predicted) + 1e-10 * std::fabs(with_eps) + 1e-12)
        << kTerminalNames[j];
  }
}

TEST(Sec5AdjointConsecutiveStages, StatePerturbationsAcrossTheStage1To2BoundaryMatchCentralDifferences) {
  test::AdjointCase& f = fixture();
  const StageEvent& stage1 = f.nominal.stages[0];
  const StageEvent& stage2 = f.nominal.stages[1];
  // The last step of stage 1 (its start point), stage 2's first point (the state stage 1 burnt
  // out with, now with stage 2's weight and thrust) and the one after it.
  const int points[] = {stage1.last_point - 1, stage2.first_point, stage2.first_point + 1};
  for (int point : points) {
    char label[48];
    std::snprintf(label, sizeof label, "pt %d (stage %d)", point, f.nominal.points[point].stage_code);
    test::expect_state_injections_match(&f, point, label);
  }
  // The adjoint is continuous across the boundary: stage 1's end point and stage 2's first point
  // share the state.
  for (int j = 0; j < kTerminalCount; ++j) {
    for (int i = 0; i < 6; ++i) {
      EXPECT_EQ(f.backward.lambda[stage1.last_point](i, j), f.backward.lambda[stage2.first_point](i, j));
    }
  }
}

TEST(Sec5AdjointConsecutiveStages, PitchAcrossTheBoundaryAndPayloadMatchCentralDifferences) {
  test::AdjointCase& f = fixture();
  const double boundary_s = f.nominal.points[f.nominal.stages[0].last_point].time_s;
  // Theta over the last 3 s of stage 1 and the first 3 s of stage 2.
  const double d_theta = 1e-3;
  const auto about_staging = [&](int i) {
    const double t = f.nominal.points[i].time_s;
    return t >= boundary_s - 3.0 && t <= boundary_s + 3.0;
  };
  double fd[kTerminalCount];
  test::expect_theta_change_matches(&f, about_staging, d_theta, "theta +-3 s about staging", fd);

  // Payload: the mass adjoint carried through the jettison at the boundary.
  test::expect_payload_change_matches(&f, 1.0, "payload 1 lb");
}

TEST(Sec22Block5ConsecutiveStages, ZeroLengthCoastIsRejectedTellingToLeaveItOut) {
  static Mission mission;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &mission);
  mission.vehicle.stages[stage_index(7)].duration_s = 0.0;
  MissionFault fault;
  EXPECT_EQ(validate_mission(mission, &fault), Status::kZeroLengthCoast);
  EXPECT_EQ(fault.data_block, 16);
  EXPECT_EQ(fault.stage_code, 7);
  EXPECT_STREQ(fault.field, "duration_s");
  EXPECT_NE(std::string(status_message(Status::kZeroLengthCoast)).find("data block 5"), std::string::npos);
  // A negative coast stays a non-positive duration.
  mission.vehicle.stages[stage_index(7)].duration_s = -1.0;
  EXPECT_EQ(validate_mission(mission, &fault), Status::kNonPositiveDuration);
}

TEST(Sec22Block5ConsecutiveStages, OrderIsKeptAndNoPoweredStageIsSkipped) {
  static Mission mission;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &mission);  // 1 6 2 7 3 8 4
  static Mission edited;
  MissionFault fault;
  // Every coast left out: 1 2 3 4.
  edited = mission;
  for (int code : {6, 7, 8}) leave_out_of_sequence(&edited, code);
  edited.adjustable.count = 1;  // code 1, the stage-4 attitude; coast 8's length (code 3) is gone
  edited.adjustable.codes[0] = 1;
  drop_repeated_staging_instants(&edited);
  EXPECT_EQ(validate_mission(edited, &fault), Status::kOk) << status_name(validate_mission(edited, &fault));
  // Block 18 still coding a burnout and the next ignition at one instant is refused.
  edited = mission;
  leave_out_of_sequence(&edited, 6);
  EXPECT_EQ(validate_mission(edited, &fault), Status::kTableNotMonotonic);
  EXPECT_EQ(fault.data_block, 18);
  // A powered stage skipped (1 6 3 ...) or a coast out of place (1 7 ...) stays invalid.
  edited = mission;
  edited.vehicle.sequence.codes[2] = 3;
  EXPECT_EQ(validate_mission(edited, &fault), Status::kStageSequenceInvalid);
  EXPECT_EQ(fault.data_block, 5);
  edited = mission;
  edited.vehicle.sequence.codes[1] = 7;
  edited.vehicle.stages[stage_index(6)].in_sequence = false;
  EXPECT_EQ(validate_mission(edited, &fault), Status::kStageSequenceInvalid);
  EXPECT_EQ(fault.index, 1);
}

TEST(Sec22Block6ConsecutiveStages, CoastLengthOfAnAbsentCoastIsRejectedNamingBlock6) {
  static Mission mission;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &mission);
  leave_out_of_sequence(&mission, 7);
  mission.adjustable.count = 1;
  mission.adjustable.codes[0] = 4;  // the length of coast 7
  mission.adjustable.weights[0] = 1.0;
  MissionFault fault;
  EXPECT_EQ(validate_mission(mission, &fault), Status::kAdjustableCoastNotInSequence);
  EXPECT_EQ(fault.data_block, 6);
  EXPECT_EQ(fault.stage_code, 7);
  EXPECT_NE(std::string(status_message(Status::kAdjustableCoastNotInSequence)).find("data block 6"),
            std::string::npos);
  // The optimizer checks it too, before flying anything.
  static OptimizerWorkspace workspace;
  static OptimizerResult result;
  EXPECT_EQ(optimize_trajectory(mission, &workspace, &result), Status::kAdjustableCoastNotInSequence);
  EXPECT_EQ(result.status, Status::kAdjustableCoastNotInSequence);
}

}  // namespace
}  // namespace tolip
