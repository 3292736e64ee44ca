// Sec. 5, 9, 22 IP(9) = 2 and 3: stages 4 and 5 steered by the pitch program. The adjoint
// sensitivities to the pitch program in those stages (and to the state there) agree with central
// differences of forward runs; a constant program over a continuous stage 4 flies the spun
// trajectory bit for bit and its summed gradient is the spun-attitude sensitivity; the optimizer
// steers stage 4 under IP(9) = 2; validation names what IP(9) forbids.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/adjoint_check.hpp"
#include "support/reference_mission.hpp"
#include "tolip/mission/adjustable_parameter.hpp"
#include "tolip/optimizer/backward_run.hpp"
#include "tolip/optimizer/steepest_descent.hpp"

namespace tolip {
namespace {

using test::kTerminalCount;

using Case = test::AdjointCase;

// The reference optimum with stage 4 continuous (IP(9) = 2): the spun attitude code leaves data
// block 6, and stage 4 joins data block 18 (ignition and burnout).
void make_stage4_continuous(Mission* m) {
  m->options.ip[9] = 2;
  int kept = 0;
  for (int p = 0; p < m->adjustable.count; ++p) {
    if (m->adjustable.codes[p] == adjustable_parameter_code(AdjustableParameter::kStage4Theta)) continue;
    m->adjustable.codes[kept] = m->adjustable.codes[p];
    m->adjustable.weights[kept] = m->adjustable.weights[p];
    ++kept;
  }
  for (int p = kept; p < m->adjustable.count; ++p) {
    m->adjustable.codes[p] = 0;
    m->adjustable.weights[p] = 0.0;
  }
  m->adjustable.count = kept;
  LinearizationData& l = m->linearization;
  l.boundaries[l.segment_count + 1] = SegmentBoundary{4, 0.0};  // the deck's 400
  l.boundaries[l.segment_count + 2] = SegmentBoundary{4, m->vehicle.stages[stage_index(4)].duration_s};
  l.segment_weights[l.segment_count] = 1.0;
  l.segment_weights[l.segment_count + 1] = 1.0;
  l.segment_count += 2;
}

// A fifth stage after a short coast 9: a small solid kick motor (illustrative: 1,500 lbf for 15 s,
// 80 lb of propellant, Isp 281 s), 12 steps, so that the powered steps stay within kMaxPoweredSteps.
void add_stage5(Mission* m) {
  Vehicle& v = m->vehicle;
  v.sequence.codes[v.sequence.count++] = 9;
  v.sequence.codes[v.sequence.count++] = 5;
  StageData& coast = v.stages[stage_index(9)];
  coast.in_sequence = true;
  coast.duration_s = 6.0;
  coast.integration_steps = 3;
  StageData& s5 = v.stages[stage_index(5)];
  s5.in_sequence = true;
  s5.duration_s = 15.0;
  s5.integration_steps = 12;
  s5.jettison_weight_lb = 30.0;
  s5.reference_area_ft2 = 1.0;
  s5.nozzle_exit_area_ft2 = 0.3;
  const double times[] = {0.0, 0.2, 14.8, 15.0};
  const double thrust[] = {0.0, 1500.0, 1500.0, 0.0};
  const double weight[] = {80.0, 79.99, 0.01, 0.0};
  for (int i = 0; i < 4; ++i) {
    ASSERT_EQ(s5.vacuum_thrust_lbf.append(times[i], thrust[i]), Status::kOk);
    ASSERT_EQ(s5.consumable_weight_lb.append(times[i], weight[i]), Status::kOk);
  }
  ASSERT_EQ(s5.vacuum_thrust_lbf.finalize(), Status::kOk);
  ASSERT_EQ(s5.consumable_weight_lb.finalize(), Status::kOk);
}

// Flies the case with the data block 40 table, then with a program in which every point of the
// continuous upper stages (and the coasts around them) holds `upper_theta_rad`, and runs the
// backward run of the terminal quantities along it.
void fly_and_run_backward(Case* c, double upper_theta_rad) {
  ASSERT_EQ(prepare_case(c->mission, &c->prepared), Status::kOk);
  ASSERT_EQ(fly_trajectory(c->mission, c->prepared, &c->nominal), Status::kOk);
  c->program.point_count = c->nominal.point_count;
  for (int i = 0; i < c->nominal.point_count; ++i) {
    const int code = c->nominal.points[i].stage_code;
    c->program.theta_rad[i] = (code == 4 || code == 5 || code == 9 || code == 10)
                                  ? upper_theta_rad
                                  : c->nominal.points[i].theta_rad;
  }
  ASSERT_EQ(fly_trajectory(c->mission, c->prepared, c->program, &c->nominal), Status::kOk);
  ConstraintTerminal terminals[kTerminalCount];
  test::terminal_partials(c->mission.constants, c->nominal, terminals);
  ASSERT_EQ(run_backward(c->mission, c->prepared, c->nominal, kTerminalCount, terminals, &c->backward),
            Status::kOk);
}

struct StageSpan {
  double start_s = 0.0;
  double end_s = 0.0;
};

StageSpan span_of(const Trajectory& t, int code) {
  for (int s = 0; s < t.stage_count; ++s) {
    if (t.stages[s].code == code)
      return {t.points[t.stages[s].first_point].time_s, t.points[t.stages[s].last_point].time_s};
  }
  ADD_FAILURE() << "stage " << code << " not flown";
  return {};
}

// Windows of theta (offsets from the stage's ignition, s) and state injections at a point of the
// stage: adjoint against central differences.
void expect_stage_sensitivities_match(Case* c, int code) {
  const StageSpan span = span_of(c->nominal, code);
  const double length = span.end_s - span.start_s;
  const double windows[][2] = {{0.0, 0.25 * length}, {0.4 * length, 0.6 * length}, {0.75 * length, length}};
  const double d_theta = 1e-3;  // rad
  int steered = 0;
  for (const auto& w : windows) {
    const auto inside = [&](int i) {
      const TrajectoryPoint& p = c->nominal.points[i];
      return p.stage_code == code && p.time_s >= span.start_s + w[0] - 1e-9 &&
             p.time_s <= span.start_s + w[1] + 1e-9;
    };
    for (int i = 0; i < c->nominal.point_count; ++i) {
      if (inside(i)) ++steered;
    }
    char what[64];
    std::snprintf(what, sizeof what, "stage %d theta +%.1f-%.1f s", code, w[0], w[1]);
    double fd[kTerminalCount];
    test::expect_theta_change_matches(c, inside, d_theta, what, fd);
    EXPECT_GT(std::fabs(fd[1]), 1e-6) << what << ": the window must turn gamma_I (a test that cannot fail)";
  }
  EXPECT_GT(steered, 6);

  // The state in mid-stage.
  int point = 0;
  for (int i = 0; i < c->nominal.point_count; ++i) {
    if (c->nominal.points[i].stage_code == code && c->nominal.points[i].time_s <= span.start_s + 0.5 * length)
      point = i;
  }
  char label[48];
  std::snprintf(label, sizeof label, "stage %d t=%.2f", code, c->nominal.points[point].time_s);
  test::expect_state_injections_match(c, point, label);
}

TEST(Sec5Adjoint, Sec22_IP9Is2_Stage4PitchProgramSensitivitiesMatchCentralDifferences) {
  static Case c;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &c.mission);
  make_stage4_continuous(&c.mission);
  MissionFault fault;
  ASSERT_EQ(validate_mission(c.mission, &fault), Status::kOk) << fault.field;
  fly_and_run_backward(&c, c.mission.misc.stage4_theta_rad);
  expect_stage_sensitivities_match(&c, 4);
}

// The spun stage 4 of IP(9) = 1 is the continuous stage 4 of IP(9) = 2 with a constant program: the
// two trajectories are the same bit for bit, and the pitch gradient summed over stage 4 is the
// backward run's spun-attitude sensitivity (Sec. 9: "These integrals are evaluated over the
// respective stages").
TEST(Sec9Adjoint, Sec22_ConstantContinuousStage4FliesTheSpunStageAndSumsToItsSensitivity) {
  static Case spun;
  static Case continuous;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &spun.mission);
  continuous.mission = spun.mission;
  make_stage4_continuous(&continuous.mission);
  ASSERT_EQ(spun.mission.misc.stage4_chi_rad, 0.0);  // the pitch program flies chi = 0
  fly_and_run_backward(&spun, spun.mission.misc.stage4_theta_rad);
  fly_and_run_backward(&continuous, spun.mission.misc.stage4_theta_rad);
  ASSERT_EQ(spun.nominal.point_count, continuous.nominal.point_count);
  const StateVector& a = spun.nominal.final_point().state;
  const StateVector& b = continuous.nominal.final_point().state;
  for (int i = 0; i < 6; ++i) EXPECT_EQ(a[i], b[i]) << i;
  for (int j = 0; j < kTerminalCount; ++j) {
    double summed = 0.0;
    for (int i = 0; i < continuous.nominal.point_count; ++i) {
      if (continuous.nominal.points[i].stage_code == 4) summed += continuous.backward.theta_gradient[i](j);
      if (spun.nominal.points[i].stage_code == 4) EXPECT_EQ(spun.backward.theta_gradient[i](j), 0.0);
    }
    EXPECT_NEAR(summed, spun.backward.spun_theta(j), 1e-9 * std::fabs(spun.backward.spun_theta(j)) + 1e-15)
        << test::kTerminalNames[j];
  }
  EXPECT_TRUE(continuous.backward.spun_theta.isZero());  // nothing is spun under IP(9) = 2 here
}

TEST(Sec5Adjoint, Sec22_IP9Is3_FiveStageVehicleStage5PitchProgramSensitivitiesMatchCentralDifferences) {
  static Case c;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &c.mission);
  make_stage4_continuous(&c.mission);
  add_stage5(&c.mission);
  c.mission.options.ip[9] = 3;
  LinearizationData& l = c.mission.linearization;
  l.boundaries[l.segment_count + 1] = SegmentBoundary{5, 0.0};   // the deck's 500
  l.boundaries[l.segment_count + 2] = SegmentBoundary{5, 15.0};  // 515
  l.segment_weights[l.segment_count] = 1.0;
  l.segment_weights[l.segment_count + 1] = 1.0;
  l.segment_count += 2;
  MissionFault fault;
  ASSERT_EQ(validate_mission(c.mission, &fault), Status::kOk) << fault.field << " " << fault.data_block;
  // The five stages within the powered-step capacity (data block 16: 168); one step more is a
  // named fault.
  int powered_steps = 0;
  for (int code = 1; code <= kMaxPoweredStages; ++code)
    powered_steps += c.mission.vehicle.stages[stage_index(code)].integration_steps;
  EXPECT_LE(powered_steps, kMaxPoweredSteps);
  static Mission over;
  over = c.mission;
  over.vehicle.stages[stage_index(5)].integration_steps += kMaxPoweredSteps - powered_steps + 1;
  EXPECT_EQ(validate_mission(over, &fault), Status::kTooManyPoweredSteps);
  EXPECT_EQ(fault.data_block, 16);

  fly_and_run_backward(&c, c.mission.misc.stage4_theta_rad);
  expect_stage_sensitivities_match(&c, 5);
  expect_stage_sensitivities_match(&c, 4);
}

// Sec. 22: IP(9) and data blocks 6 and 18 must agree; each disagreement is a named fault.
TEST(Sec22Validation, SpinOptionIP9MustFitTheSequenceTheSpunAttitudeCodesAndTheBlock18Times) {
  static Mission base;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &base);
  MissionFault fault;
  ASSERT_EQ(validate_mission(base, &fault), Status::kOk);

  static Mission m;
  m = base;
  m.options.ip[9] = 0;  // stage 4 flown, neither spun nor continuous
  EXPECT_EQ(validate_mission(m, &fault), Status::kSpinOptionInconsistent);
  EXPECT_EQ(fault.data_block, 4);
  EXPECT_EQ(fault.index, 9);
  m.options.ip[9] = 3;  // "Set = 3 only when there are five stages"
  EXPECT_EQ(validate_mission(m, &fault), Status::kSpinOptionInconsistent);

  m = base;
  m.options.ip[9] = 2;  // adjustable code 1 (spun stage-4 theta) with a continuous stage 4
  EXPECT_EQ(validate_mission(m, &fault), Status::kAdjustableAttitudeNotSpun);
  EXPECT_EQ(fault.data_block, 6);
  EXPECT_EQ(fault.stage_code, 4);

  m = base;
  make_stage4_continuous(&m);
  EXPECT_EQ(validate_mission(m, &fault), Status::kOk);
  // Without the stage-4 coded times the linearized trajectory would fly stage 4 at one attitude.
  m.linearization.boundaries[m.linearization.segment_count] = SegmentBoundary{};
  m.linearization.boundaries[m.linearization.segment_count - 1] = SegmentBoundary{};
  m.linearization.segment_count -= 2;
  EXPECT_EQ(validate_mission(m, &fault), Status::kSteeredStageWithoutSegments);
  EXPECT_EQ(fault.data_block, 18);
  EXPECT_EQ(fault.stage_code, 4);

  m = base;  // a coded time in the spun stage 4 (IP(9) = 1)
  LinearizationData& l = m.linearization;
  l.boundaries[l.segment_count + 1] = SegmentBoundary{4, 10.0};  // the deck's 410
  l.segment_weights[l.segment_count] = 1.0;
  l.segment_count += 1;
  EXPECT_EQ(validate_mission(m, &fault), Status::kCodedTimeInSpunStage);
  EXPECT_EQ(fault.data_block, 18);
  EXPECT_EQ(fault.stage_code, 4);

  m = base;  // stage-5 attitude codes: only for a stage 5 spun on its own (IP(9) = 2)
  m.adjustable.codes[m.adjustable.count] = adjustable_parameter_code(AdjustableParameter::kStage5Theta);
  m.adjustable.weights[m.adjustable.count] = 10.0;
  ++m.adjustable.count;
  EXPECT_EQ(validate_mission(m, &fault), Status::kAdjustableAttitudeNotSpun);
  EXPECT_EQ(fault.stage_code, 5);
}

// Sec. 22 IP(10), "Stage 5 chi: 0 fewer than 5 stages, 1 chi5 = chi4, 2 chi5 independent of chi4":
// on a five-stage vehicle whose stage 5 is spun apart from a continuous stage 4 (IP(9) = 2) the spun
// stage 5 and its coast yaw at DA2(10) under 2 and at DA2(6) under 1 (the continuous stage 4 itself
// flies the pitch program at chi 0), and the trajectory follows; IP(10) is rejected, naming IP(10),
// where it has no such meaning, and adjustable code 9 where IP(10) = 1 leaves DA2(10) unflown.
TEST(Sec22Validation, StageFiveYawIP10ActsWhereStageFiveIsSpunApartAndIsRejectedElsewhere) {
  static Mission m;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &m);
  make_stage4_continuous(&m);
  add_stage5(&m);
  m.misc.stage5_theta_rad = 10.0 * kDegToRad;
  m.misc.stage4_chi_rad = -2.0 * kDegToRad;
  m.misc.stage5_chi_rad = 3.0 * kDegToRad;
  MissionFault fault;
  m.options.ip[10] = 0;  // "fewer than 5 stages", with a spun stage 5 flown
  EXPECT_EQ(validate_mission(m, &fault), Status::kStage5YawOptionInconsistent);
  EXPECT_EQ(fault.data_block, 4);
  EXPECT_EQ(fault.index, 10);

  static PreparedCase prepared;
  static Trajectory independent;
  static Trajectory coupled;
  const auto fly = [&](int ip10, Trajectory* t) {
    m.options.ip[10] = ip10;
    ASSERT_EQ(validate_mission(m, &fault), Status::kOk) << fault.field << " " << fault.index;
    ASSERT_EQ(prepare_case(m, &prepared), Status::kOk);
    ASSERT_EQ(fly_trajectory(m, prepared, t), Status::kOk);
  };
  fly(2, &independent);
  fly(1, &coupled);
  int stage5_points = 0;
  for (const Trajectory* t : {&independent, &coupled}) {
    const double chi5 = (t == &independent) ? 3.0 * kDegToRad : -2.0 * kDegToRad;
    for (int i = 0; i < t->point_count; ++i) {
      const TrajectoryPoint& p = t->points[i];
      if (p.stage_code == 5 || p.stage_code == 10) {
        EXPECT_EQ(p.chi_rad, chi5) << "stage " << p.stage_code << " point " << i;
        EXPECT_EQ(p.theta_rad, m.misc.stage5_theta_rad);
        ++stage5_points;
      } else if (p.stage_code == 4) {
        EXPECT_EQ(p.chi_rad, 0.0);
      }
    }
  }
  EXPECT_GT(stage5_points, 20);
  // 5 deg of yaw over the 15 s burn turns the final inertial heading.
  EXPECT_GT(std::fabs(independent.points[independent.point_count - 1].state(kStatePsi) -
                      coupled.points[coupled.point_count - 1].state(kStatePsi)),
            1e-4);

  // Adjustable code 9 (stage-5 yaw) needs DA2(10) flown: IP(10) = 2, not 1.
  m.adjustable.codes[m.adjustable.count] = adjustable_parameter_code(AdjustableParameter::kStage5Chi);
  m.adjustable.weights[m.adjustable.count] = 10.0;
  ++m.adjustable.count;
  m.options.ip[10] = 2;
  EXPECT_EQ(validate_mission(m, &fault), Status::kOk) << fault.field;
  m.options.ip[10] = 1;
  EXPECT_EQ(validate_mission(m, &fault), Status::kAdjustableAttitudeNotSpun);
  EXPECT_EQ(fault.data_block, 6);
  EXPECT_EQ(fault.stage_code, 5);
  --m.adjustable.count;

  // IP(9) = 1 spins stage 5 on stage 4's attitudes (chi5 = chi4): IP(10) = 2 contradicts it.
  static Mission spun;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &spun);
  add_stage5(&spun);
  spun.options.ip[10] = 2;
  EXPECT_EQ(validate_mission(spun, &fault), Status::kStage5YawOptionInconsistent);
  EXPECT_EQ(fault.index, 10);
  spun.options.ip[10] = 1;
  EXPECT_EQ(validate_mission(spun, &fault), Status::kOk) << fault.field;
  // IP(9) = 3: stage 5 flies the pitch program, IP(10) stays 0.
  m.options.ip[9] = 3;
  m.options.ip[10] = 1;
  EXPECT_EQ(validate_mission(m, &fault), Status::kStage5YawOptionInconsistent);
  EXPECT_EQ(fault.index, 10);
}

// The optimizer steers the stage-4 pitch program under IP(9) = 2: from the oracle's optimum, with
// stage 4 starting at its constant spun attitude, the converged stage 4 flies a program.
TEST(Sec22Optimizer, Sec5_IP9Is2SteersTheStage4PitchProgram) {
  static OptimizerWorkspace ws;
  static OptimizerResult result;
  static Mission mission;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &mission);
  make_stage4_continuous(&mission);
  // The table holds its last node (18 deg at 130 s) through stage 4: start it at the spun attitude.
  ASSERT_EQ(mission.pitch_program_rad.append(380.0, mission.misc.stage4_theta_rad), Status::kOk);
  ASSERT_EQ(mission.pitch_program_rad.finalize(), Status::kOk);
  MissionFault fault;
  ASSERT_EQ(validate_mission(mission, &fault), Status::kOk) << fault.field;
  const Status status = optimize_trajectory(mission, &ws, &result);
  std::printf("IP(9) = 2: %s, payload %.4f lb in %d forward runs\n", status_name(status), result.payload_lb,
              result.forward_runs);
  ASSERT_EQ(status, Status::kOk);
  double lowest = 1e9, highest = -1e9;
  for (int i = 0; i < ws.nominal.point_count; ++i) {
    if (ws.nominal.points[i].stage_code != 4) continue;
    lowest = std::fmin(lowest, ws.nominal.points[i].theta_rad);
    highest = std::fmax(highest, ws.nominal.points[i].theta_rad);
  }
  std::printf("stage-4 theta from %.4f to %.4f deg\n", lowest * kRadToDeg, highest * kRadToDeg);
  EXPECT_GT(highest - lowest, 0.01 * kDegToRad);  // a program, not the initial constant
}

}  // namespace
}  // namespace tolip
