// Sec. 16: failure-mode hardover turns. The closed-form constant-angular-acceleration solution
// (zero aerodynamic moment, zero damping), the signs of the turn, the stops, and bad data named.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/reference_data.hpp"
#include "support/reference_hardover.hpp"
#include "support/reference_mission.hpp"
#include "tolip/hardover/hardover.hpp"
#include "tolip/trajectory/trajectory.hpp"

namespace tolip {
namespace {

using test::reference_hardover;

struct Flown {
  Mission mission;
  PreparedCase prepared;
  Trajectory trajectory;
  HardoverData data;
  HardoverResult result;
};

const Flown& reference_turns() {
  static Flown* flown = [] {
    static Flown f;
    test::build_reference_mission(test::ReferenceProgram::kOptimum, &f.mission);
    EXPECT_EQ(prepare_case(f.mission, &f.prepared), Status::kOk);
    EXPECT_EQ(fly_trajectory(f.mission, f.prepared, &f.trajectory), Status::kOk);
    f.data = reference_hardover();
    HardoverFault fault;
    EXPECT_EQ(compute_hardover_turns(f.mission, f.prepared, f.trajectory, f.data, &f.result, &fault),
              Status::kOk);
    return &f;
  }();
  return *flown;
}

// A point of stage `code` about `fraction` of the way through it.
int point_in_stage(const Trajectory& trajectory, int code, double fraction) {
  for (int e = 0; e < trajectory.stage_count; ++e) {
    const StageEvent& event = trajectory.stages[e];
    if (event.code == code) {
      return event.first_point + static_cast<int>(fraction * (event.last_point - event.first_point));
    }
  }
  return -1;
}

TEST(Sec16Hardover, ZeroAerodynamicMomentAndZeroDampingGiveTheConstantAccelerationSolution) {
  static Flown f;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &f.mission);
  // Stage 2, mode 2 (a single control jet, no atmosphere in the upper stages): a constant c.g.,
  // a constant I_yy and the thrust applied at the c.g. make the jet damping zero and the moment
  // T_C (X_TAC - X_CG) constant, so eta-ddot = T_C (X_TAC - X_CG) / I_yy exactly.
  CgTable& cg = f.mission.body_dynamics.cg_station_ft[1];
  cg.clear();
  ASSERT_EQ(cg.append(0.0, 40.0), Status::kOk);
  ASSERT_EQ(cg.append(100.0, 40.0), Status::kOk);
  ASSERT_EQ(cg.finalize(), Status::kOk);
  ASSERT_EQ(prepare_case(f.mission, &f.prepared), Status::kOk);
  ASSERT_EQ(fly_trajectory(f.mission, f.prepared, &f.trajectory), Status::kOk);
  f.data = reference_hardover();
  HardoverStage& s2 = f.data.stages[1];
  const double iyy = 50000.0;
  s2.pitch_inertia_slug_ft2.clear();
  ASSERT_EQ(s2.pitch_inertia_slug_ft2.append(0.0, iyy), Status::kOk);
  ASSERT_EQ(s2.pitch_inertia_slug_ft2.append(100.0, iyy), Status::kOk);
  ASSERT_EQ(s2.pitch_inertia_slug_ft2.finalize(), Status::kOk);
  s2.thrust_station_ft = 40.0;
  s2.control_jet_station_ft = 40.5;  // a small moment: no tumbling in ten seconds
  s2.max_step_s = 1e-3;
  s2.min_step_s = 1e-4;
  s2.max_attitude_step_rad = 1.0;  // the time step limits, not the attitude step
  s2.max_steps_per_turn = 1000000;
  const double acceleration = s2.single_jet_force_lbf * (40.5 - 40.0) / iyy;
  const int point = point_in_stage(f.trajectory, 2, 0.2);
  HardoverTurn& turn = f.result.turns[0];
  ASSERT_EQ(compute_hardover_turn(f.mission, f.prepared, f.trajectory, f.data, point,
                                  HardoverMode::kSingleJet, HardoverDirection::kNoseUp, &turn),
            Status::kOk);
  ASSERT_GT(turn.sample_count, 10);
  double worst_rate = 0.0, worst_attitude = 0.0;
  for (int i = 0; i < turn.sample_count; ++i) {
    const HardoverSample& s = turn.samples[i];
    // Euler on eta-ddot = a: eta-dot = a t exactly, eta = a t (t - dt) / 2 at a fixed step dt.
    worst_rate = std::fmax(worst_rate, std::fabs(s.attitude_rate_rad_s - acceleration * s.time_s));
    worst_attitude = std::fmax(worst_attitude,
                               std::fabs(s.attitude_change_rad - 0.5 * acceleration * s.time_s * s.time_s) /
                                   (0.5 * acceleration * s.time_s * s2.max_step_s + 1e-300));
  }
  std::printf(
      "closed form: eta-ddot %.6e rad/s^2, worst |d eta-dot| %.3e rad/s, eta error / (a t dt / 2) %.6f\n",
      acceleration, worst_rate, worst_attitude);
  EXPECT_LT(worst_rate, 1e-12);
  EXPECT_LT(worst_attitude, 1.0 + 1e-6);  // the Euler error bound, nothing more
  EXPECT_EQ(turn.stop, HardoverStop::kTimeLimit);
  EXPECT_NEAR(turn.last().time_s, 10.0, 1e-9);
  EXPECT_GT(turn.last().change_in_gamma_rad, 0.0) << "nose up: the velocity follows the nose";
}

TEST(Sec16Hardover, NoseDownLowersGammaAndNoseUpRaisesItInEveryStage) {
  const Flown& f = reference_turns();
  static HardoverTurn up, down;
  for (const auto& [code, mode] :
       {std::pair{1, HardoverMode::kFinsAndVanes}, std::pair{2, HardoverMode::kSingleJet},
        std::pair{2, HardoverMode::kThrustMisalignment}, std::pair{3, HardoverMode::kPitchAndYawJets}}) {
    const int point = point_in_stage(f.trajectory, code, 0.5);
    ASSERT_EQ(compute_hardover_turn(f.mission, f.prepared, f.trajectory, f.data, point, mode,
                                    HardoverDirection::kNoseUp, &up),
              Status::kOk);
    ASSERT_EQ(compute_hardover_turn(f.mission, f.prepared, f.trajectory, f.data, point, mode,
                                    HardoverDirection::kNoseDown, &down),
              Status::kOk);
    EXPECT_GT(up.last().change_in_gamma_rad, 0.0) << code;
    EXPECT_LT(down.last().change_in_gamma_rad, 0.0) << code;
    EXPECT_GT(up.last().attitude_change_rad, 0.0) << code;
    EXPECT_LT(down.last().attitude_change_rad, 0.0) << code;
  }
}

TEST(Sec16Hardover, EveryTurnOfTheReferenceStopsWithinTenSecondsForANamedReason) {
  const Flown& f = reference_turns();
  ASSERT_GT(f.result.turn_count, 10);
  int per_stage[4] = {}, qbar_stops = 0;
  double largest_deg[4] = {};
  for (int k = 0; k < f.result.turn_count; ++k) {
    const HardoverTurn& t = f.result.turns[k];
    ++per_stage[t.stage];
    EXPECT_LE(t.last().time_s, 10.0 + 1e-9);
    EXPECT_EQ(t.samples[0].time_s, 0.0);
    EXPECT_EQ(t.samples[0].change_in_gamma_rad, 0.0);
    EXPECT_EQ(t.stage == 1, t.mode == HardoverMode::kFinsAndVanes);
    if (t.stop == HardoverStop::kQbarAlphaLimit) {
      ++qbar_stops;
      EXPECT_EQ(t.stage, 1);
    }
    if (t.stop == HardoverStop::kTimeLimit) {
      EXPECT_NEAR(t.last().time_s, 10.0, 1e-9);
    }
    if (t.stage > 1) {
      EXPECT_EQ(t.last().qbar_alpha_lbf_rad_ft2, 0.0) << "no atmosphere";
    }
    largest_deg[t.stage] =
        std::fmax(largest_deg[t.stage], std::fabs(t.last().change_in_gamma_rad) * kRadToDeg);
  }
  std::printf(
      "turns: stage 1 %d, stage 2 %d, stage 3 %d; q-bar alpha stops %d; largest change in gamma %.2f, %.2f, "
      "%.2f deg\n",
      per_stage[1], per_stage[2], per_stage[3], qbar_stops, largest_deg[1], largest_deg[2], largest_deg[3]);
  EXPECT_GT(per_stage[1], 0);
  EXPECT_EQ(per_stage[2] % 3, 0) << "modes 1-3 from every point";
  EXPECT_EQ(per_stage[3] % 3, 0);
  EXPECT_GT(qbar_stops, 0) << "the fins hard over at high q-bar exceed (q-bar alpha)max";
}

TEST(Sec16Hardover, BadDataIsNamedByBlockWordAndStage) {
  const Flown& f = reference_turns();
  HardoverFault fault;
  HardoverData d = f.data;
  d.stages[1].every_nth_step = 0;
  EXPECT_EQ(validate_hardover_data(f.mission, d, &fault), Status::kHardoverEveryNthStepInvalid);
  EXPECT_EQ(fault.data_block, 45);
  EXPECT_EQ(fault.word, 21);
  EXPECT_EQ(fault.stage, 2);
  d = f.data;
  d.stages[0].min_step_s = 1.0;
  EXPECT_EQ(validate_hardover_data(f.mission, d, &fault), Status::kHardoverStepLimitsInvalid);
  EXPECT_EQ(fault.word, 5);
  d = f.data;
  d.stages[2].pitch_inertia_slug_ft2.clear();
  EXPECT_EQ(validate_hardover_data(f.mission, d, &fault), Status::kHardoverInertiaMissing);
  EXPECT_EQ(fault.data_block, 44);
  EXPECT_EQ(fault.stage, 3);
  d = f.data;
  d.output_interval_s = 0.01;
  EXPECT_EQ(validate_hardover_data(f.mission, d, &fault), Status::kHardoverOutputIntervalTooSmall);
  EXPECT_EQ(fault.word, 20);
  d = f.data;
  d.pitch_damping_per_rad.clear();
  EXPECT_EQ(validate_hardover_data(f.mission, d, &fault), Status::kHardoverDampingTableMissing);
  EXPECT_EQ(fault.stage, 4);
  static HardoverResult result;
  EXPECT_EQ(compute_hardover_turns(f.mission, f.prepared, f.trajectory, d, &result, &fault),
            Status::kHardoverDampingTableMissing);
  EXPECT_EQ(result.turn_count, 0);
  static HardoverTurn turn;
  EXPECT_EQ(compute_hardover_turn(f.mission, f.prepared, f.trajectory, f.data, 0, HardoverMode::kFinsAndVanes,
                                  HardoverDirection::kNoseUp, &turn),
            Status::kHardoverPointInvalid)
      << "the pad point does not move";
  EXPECT_EQ(
      compute_hardover_turn(f.mission, f.prepared, f.trajectory, f.data, point_in_stage(f.trajectory, 2, 0.5),
                            HardoverMode::kFinsAndVanes, HardoverDirection::kNoseUp, &turn),
      Status::kHardoverPointInvalid)
      << "fins and vanes are stage 1's";
}

}  // namespace
}  // namespace tolip
