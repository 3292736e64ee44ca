// Sec. 8, 12: performance exchange ratios (option IP(3)), checked against re-optimization.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "support/reference_mission.hpp"
#include "tolip/optimizer/exchange_ratios.hpp"
#include "tolip/optimizer/steepest_descent.hpp"

namespace tolip {
namespace {

OptimizerWorkspace& workspace() {
  static OptimizerWorkspace ws;
  return ws;
}

// Tight convergence (DA13(2) = 0.02 lb, a budget of 200) from the reference optimum's program.
void reference_case(Mission* mission) {
  test::build_reference_mission(test::ReferenceProgram::kOptimum, mission);
  mission->convergence.stop_improvement = 0.02;
  mission->convergence.max_forward_trajectories = 200;
}

// The optimized reference case and its exchange ratios, computed once for the suite.
struct Baseline {
  Mission mission;
  OptimizerResult result;
  ExchangeRatioScratch scratch;
  ExchangeRatios ratios;
  OptimizerWorkspace final_ws;
  double seconds = 0.0;
  Status status = Status::kNotPrepared;
};

const Baseline& baseline() {
  static Baseline* b = [] {
    static Baseline base;
    reference_case(&base.mission);
    base.status = optimize_trajectory(base.mission, &workspace(), &base.result);
    if (!ok(base.status)) return &base;
    base.final_ws = workspace();
    const auto start = std::chrono::steady_clock::now();
    base.status = compute_exchange_ratios(base.final_ws, base.result, &base.scratch, &base.ratios);
    base.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return &base;
  }();
  return *b;
}

// The exchange ratios' runs resume at the perturbed stage's ignition: for every powered stage and
// every parameter that acts from there, the resumed flight equals the full flight bit for bit.
TEST(Sec8ExchangeRatios, RunsResumedAtTheStageIgnitionEqualFullFlightsBitForBit) {
  const Baseline& b = baseline();
  ASSERT_EQ(b.status, Status::kOk);
  const OptimizerWorkspace& ws = b.final_ws;
  static Mission changed;
  static PreparedCase prepared;
  static PreparedCase base_prepared;
  static Trajectory base;
  static Trajectory full;
  static Trajectory resumed;
  ASSERT_EQ(prepare_case(ws.mission, &base_prepared), Status::kOk);
  ASSERT_EQ(fly_trajectory(ws.mission, base_prepared, ws.program, &base), Status::kOk);
  int compared = 0;
  for (int slot = 1; slot < ws.prepared.stage_count; ++slot) {
    const int code = ws.prepared.timeline[slot].code;
    if (code < 1 || code > 5) continue;  // powered stages
    for (ExchangeParameter parameter :
         {ExchangeParameter::kBurnRate, ExchangeParameter::kSpecificImpulse, ExchangeParameter::kDrag}) {
      ASSERT_EQ(perturb_stage_parameter(ws.mission, code, parameter, 1.0, &changed), Status::kOk);
      ASSERT_EQ(prepare_case(changed, &prepared), Status::kOk);
      ASSERT_EQ(fly_trajectory(changed, prepared, ws.program, &full), Status::kOk);
      FlightInputs inputs;
      inputs.program = &ws.program;
      inputs.resume_from = &base;
      inputs.resume_stage_slot = slot;
      ASSERT_EQ(fly_trajectory(changed, prepared, inputs, &resumed), Status::kOk);
      ASSERT_EQ(resumed.point_count, full.point_count);
      ASSERT_EQ(resumed.step_count, full.step_count);
      ASSERT_EQ(resumed.stage_count, full.stage_count);
      for (int k = 0; k < full.point_count; ++k) {
        ASSERT_EQ(resumed.points[k].time_s, full.points[k].time_s) << "stage " << code << " point " << k;
        for (int i = 0; i < 6; ++i) ASSERT_EQ(resumed.points[k].state[i], full.points[k].state[i]) << k;
        ASSERT_EQ(resumed.points[k].weight_lb, full.points[k].weight_lb) << k;
      }
      EXPECT_EQ(resumed.heat_integral_btu_ft2, full.heat_integral_btu_ft2);
      for (int k = 0; k < full.stage_count; ++k) {
        EXPECT_EQ(resumed.stages[k].weight_after_jettison_lb, full.stages[k].weight_after_jettison_lb);
      }
      ++compared;
    }
  }
  EXPECT_EQ(compared, 3 * 3);  // stages 2, 3, 4
  // The points before the stage really come from `resume_from` (not flown again): a mark put there
  // is carried over.
  static Trajectory marked;
  marked = base;
  marked.points[1].weight_lb += 1.0;
  FlightInputs inputs;
  inputs.program = &ws.program;
  inputs.resume_from = &marked;
  inputs.resume_stage_slot = 2;
  ASSERT_EQ(fly_trajectory(ws.mission, base_prepared, inputs, &resumed), Status::kOk);
  EXPECT_EQ(resumed.points[1].weight_lb, base.points[1].weight_lb + 1.0);
  EXPECT_EQ(resumed.final_point().state, base.final_point().state);
  // A resume that cannot be honoured is refused, never flown wrong.
  FlightInputs bad;
  bad.program = &ws.program;
  bad.resume_from = &base;
  bad.resume_stage_slot = 0;
  EXPECT_EQ(fly_trajectory(ws.mission, base_prepared, bad, &resumed), Status::kResumeStageSlotInvalid);
  bad.resume_stage_slot = base.stage_count;
  EXPECT_EQ(fly_trajectory(ws.mission, base_prepared, bad, &resumed), Status::kResumeStageSlotInvalid);
  bad.resume_stage_slot = 2;
  bad.injection_point = 3;
  EXPECT_EQ(fly_trajectory(ws.mission, base_prepared, bad, &resumed), Status::kResumeInputsIncompatible);
}

int slot_of(const ExchangeRatios& r, int code) {
  for (int s = 0; s < r.stage_count; ++s) {
    if (r.stage_codes[s] == code) return s;
  }
  return -1;
}

TEST(Sec8ExchangeRatios, ReferenceRatiosHaveTheSignsIntuitionAsks) {
  const Baseline& b = baseline();
  ASSERT_EQ(b.status, Status::kOk);
  const ExchangeRatios& r = b.ratios;
  std::printf("payload %.4f lb; kappa (payload stationarity) %.5f; %d forward runs in %.2f ms\n",
              b.result.payload_lb, r.payload_stationarity, r.forward_runs, 1e3 * b.seconds);
  std::printf(" stage  burn rate lb/%%  propellant lb/lb  Isp lb/%%  drag lb/ft^2  jettison lb/lb\n");
  for (int s = 0; s < r.stage_count; ++s) {
    std::printf("   %d   %12.4f  %15.5f  %9.4f  %12.4f  %14.5f\n", r.stage_codes[s], r.burn_rate[s],
                r.propellant_weight[s], r.specific_impulse[s], r.drag[s], r.jettison_weight[s]);
  }
  ASSERT_EQ(r.stage_count, 4);  // sequence 1 6 2 7 3 8 4: the powered stages in flight order
  for (int s = 0; s < 4; ++s) EXPECT_EQ(r.stage_codes[s], s + 1);
  // The partials price the payload's own constraint effect at nearly 1 lb per lb near the optimum.
  EXPECT_GT(r.payload_stationarity, 0.9);
  EXPECT_LE(r.payload_stationarity, 1.0 + 1e-6);
  for (int s = 0; s < 4; ++s) {
    EXPECT_GT(r.specific_impulse[s], 0.0) << "more Isp, more payload: stage " << s + 1;
    EXPECT_GT(r.propellant_weight[s], 0.0) << "more propellant (same Isp) pays for itself: stage " << s + 1;
    EXPECT_LT(r.jettison_weight[s], 0.0) << "more inert weight, less payload: stage " << s + 1;
    if (s > 0)
      EXPECT_LT(r.jettison_weight[s], r.jettison_weight[s - 1]) << "upper-stage inert weight costs more";
  }
  EXPECT_LT(r.drag[0], 0.0);
  EXPECT_LT(r.drag[1], 0.0);
  EXPECT_EQ(r.drag[2], 0.0);  // stages 3 and 4 have no drag table (block 31: stages 1, 6, 2)
  EXPECT_EQ(r.drag[3], 0.0);
  // The payload is part of the last stage's jettison weight (Sec. 14): 1 lb more inert weight there
  // is 1 lb less payload for the same trajectory. Only the Sec. 14 re-derivation differs.
  EXPECT_NEAR(r.jettison_weight[3], -1.0, 1e-3);
  // kappa (base and +1 lb with the optimizer's prepared case), the re-prepared base, then one run
  // per parameter: 4 parameters x 4 stages + 2 drag (one-sided differences).
  EXPECT_EQ(r.forward_runs, 2 + 1 + (4 * 4 + 2));
}

// The proof: change a stage characteristic in the mission, re-optimize with tight convergence, and
// compare the change of the payoff with the exchange ratio. The optimizer's stopping noise is up to
// ~0.3 lb per optimization, so the steps are taken on both sides and large enough that the payoff
// moves by several lb; the payoff compared is the corrected payoff (eq. 9-21) because the reference
// deadbands are wide (20,000 ft, 1 deg, 20 ft/s).
struct Change {
  const char* name;
  int stage;
  double step;  // parameter units
  double (ExchangeRatios::*ratio)[kMaxPoweredStages];
};

// Independent of perturb_stage_parameter: the change as a user would make it in the deck.
void apply(const Change& c, double units, Mission* m) {
  StageData& stage = m->vehicle.stages[stage_index(c.stage)];
  if (c.ratio == &ExchangeRatios::specific_impulse) {
    for (int i = 0; i < stage.vacuum_thrust_lbf.size(); ++i) {
      stage.vacuum_thrust_lbf.set_y(i, stage.vacuum_thrust_lbf.y(i) * (1.0 + units / 100.0));
    }
    ASSERT_EQ(stage.vacuum_thrust_lbf.finalize(), Status::kOk);
  } else if (c.ratio == &ExchangeRatios::propellant_weight) {
    const double k = (stage.consumable_weight_lb.y(0) + units) / stage.consumable_weight_lb.y(0);
    for (int i = 0; i < stage.consumable_weight_lb.size(); ++i) {
      stage.consumable_weight_lb.set_y(i, stage.consumable_weight_lb.y(i) * k);
    }
    for (int i = 0; i < stage.vacuum_thrust_lbf.size(); ++i) {
      stage.vacuum_thrust_lbf.set_y(i, stage.vacuum_thrust_lbf.y(i) * k);
    }
    ASSERT_EQ(stage.consumable_weight_lb.finalize(), Status::kOk);
    ASSERT_EQ(stage.vacuum_thrust_lbf.finalize(), Status::kOk);
  } else if (c.ratio == &ExchangeRatios::drag) {
    for (int i = 0; i < stage.drag_coefficient.size(); ++i) {
      stage.drag_coefficient.set_y(i, stage.drag_coefficient.y(i) + units / stage.reference_area_ft2);
    }
    ASSERT_EQ(stage.drag_coefficient.finalize(), Status::kOk);
  } else {
    stage.jettison_weight_lb += units;
  }
}

TEST(Sec8ExchangeRatios, AgreeWithReoptimizationWithinFivePercent) {
  const Baseline& b = baseline();
  ASSERT_EQ(b.status, Status::kOk);
  const Change changes[] = {
      {"stage-1 specific impulse (lb per 1%)", 1, 1.0, &ExchangeRatios::specific_impulse},
      {"stage-2 drag area (lb per ft^2)", 2, 2.0, &ExchangeRatios::drag},
      {"stage-3 propellant weight (lb per lb)", 3, 20.0, &ExchangeRatios::propellant_weight},
      {"stage-3 jettison weight (lb per lb)", 3, 20.0, &ExchangeRatios::jettison_weight},
      {"stage-4 specific impulse (lb per 1%)", 4, 1.0, &ExchangeRatios::specific_impulse},
      {"stage-4 jettison weight (lb per lb)", 4, 5.0, &ExchangeRatios::jettison_weight},
  };
  static Mission changed;
  static OptimizerResult result;
  for (const Change& c : changes) {
    double corrected[2] = {};
    double payload[2] = {};
    for (int side = 0; side < 2; ++side) {
      changed = b.mission;
      apply(c, side == 0 ? c.step : -c.step, &changed);
      MissionFault fault;
      ASSERT_EQ(validate_mission(changed, &fault), Status::kOk) << c.name;
      ASSERT_EQ(optimize_trajectory(changed, &workspace(), &result), Status::kOk) << c.name;
      corrected[side] = result.corrected_payoff;
      payload[side] = result.payload_lb;
    }
    const double measured = (corrected[0] - corrected[1]) / (2.0 * c.step);
    const double measured_payload = (payload[0] - payload[1]) / (2.0 * c.step);
    const double predicted = (b.ratios.*c.ratio)[slot_of(b.ratios, c.stage)];
    const double relative = std::fabs(predicted - measured) / std::fabs(measured);
    std::printf("%-40s predicted %9.5f  re-optimized %9.5f (payload alone %9.5f)  difference %.1f%%\n",
                c.name, predicted, measured, measured_payload, 100.0 * relative);
    EXPECT_LE(relative, 0.05) << c.name;
  }
}

// Velocity payoff (IP(1) = 1) for a fixed payload: the ratios are in ft/s and include the direct
// change of the payoff on the final trajectory.
TEST(Sec8ExchangeRatios, VelocityPayoffRatiosAgreeWithReoptimization) {
  static Mission mission;
  static OptimizerResult result;
  static ExchangeRatioScratch scratch;
  static ExchangeRatios ratios;
  reference_case(&mission);
  mission.options.ip[1] = 1;  // payoff: inertial velocity at stage-4 burnout
  ConstraintList& c = mission.constraints;
  c.count = 3;
  c.codes[0] = 1;
  c.desired[0] = 0.0;
  c.codes[1] = 7;
  c.desired[1] = 1822834.647;
  c.deadband_optimization[0] = 2000.0;  // altitude, ft
  c.codes[2] = 2;
  c.desired[2] = 0.0;
  c.deadband_optimization[1] = 0.002;  // gamma_I, rad
  mission.convergence.initial_payoff_improvement = 50.0;
  mission.convergence.stop_improvement = 0.1;  // ft/s
  ASSERT_EQ(optimize_trajectory(mission, &workspace(), &result), Status::kOk);
  ASSERT_EQ(compute_exchange_ratios(workspace(), result, &scratch, &ratios), Status::kOk);
  EXPECT_EQ(ratios.payload_stationarity, 0.0);  // payload payoff only
  for (int s = 0; s < ratios.stage_count; ++s) {
    std::printf(
        "stage %d: burn rate %.3f ft/s/%%  propellant %.4f ft/s/lb  Isp %.3f ft/s/%%  drag %.3f ft/s/ft^2  "
        "jettison %.4f ft/s/lb\n",
        ratios.stage_codes[s], ratios.burn_rate[s], ratios.propellant_weight[s], ratios.specific_impulse[s],
        ratios.drag[s], ratios.jettison_weight[s]);
    EXPECT_GT(ratios.specific_impulse[s], 0.0);
    EXPECT_LT(ratios.jettison_weight[s], 0.0);
  }
  // Re-optimize with the stage-4 jettison weight +-20 lb and stage-3 Isp +-1%.
  const Change changes[] = {
      {"stage-4 jettison weight (ft/s per lb)", 4, 20.0, &ExchangeRatios::jettison_weight},
      {"stage-3 specific impulse (ft/s per 1%)", 3, 1.0, &ExchangeRatios::specific_impulse},
  };
  static Mission changed;
  static OptimizerResult reoptimized;
  for (const Change& change : changes) {
    double corrected[2] = {};
    for (int side = 0; side < 2; ++side) {
      changed = mission;
      apply(change, side == 0 ? change.step : -change.step, &changed);
      ASSERT_EQ(optimize_trajectory(changed, &workspace(), &reoptimized), Status::kOk) << change.name;
      corrected[side] = reoptimized.corrected_payoff;
    }
    const double measured = (corrected[0] - corrected[1]) / (2.0 * change.step);
    const double predicted = (ratios.*change.ratio)[slot_of(ratios, change.stage)];
    const double relative = std::fabs(predicted - measured) / std::fabs(measured);
    std::printf("%-40s predicted %9.4f  re-optimized %9.4f  difference %.1f%%\n", change.name, predicted,
                measured, 100.0 * relative);
    EXPECT_LE(relative, 0.05) << change.name;
  }
}

// The parameter definitions of perturb_stage_parameter.
TEST(Sec8ExchangeRatios, ParameterChangesKeepWhatTheirDefinitionsKeep) {
  static Mission base;
  static Mission out;
  reference_case(&base);
  const StageData& in = base.vehicle.stages[stage_index(2)];
  const StageData& s = out.vehicle.stages[stage_index(2)];
  const auto impulse = [](const ThrustTable& t) {
    double sum = 0.0;
    for (int i = 0; i + 1 < t.size(); ++i) sum += 0.5 * (t.y(i) + t.y(i + 1)) * (t.x(i + 1) - t.x(i));
    return sum;
  };

  // Burn rate +1%: thrust x1.01 over times /1.01, same total impulse and consumed weight.
  ASSERT_EQ(perturb_stage_parameter(base, 2, ExchangeParameter::kBurnRate, 1.0, &out), Status::kOk);
  EXPECT_NEAR(impulse(s.vacuum_thrust_lbf), impulse(in.vacuum_thrust_lbf),
              1e-9 * impulse(in.vacuum_thrust_lbf));
  EXPECT_NEAR(s.duration_s, in.duration_s / 1.01, 1e-12);
  EXPECT_NEAR(s.vacuum_thrust_lbf.last_x(), s.duration_s, 1e-12);
  EXPECT_DOUBLE_EQ(s.consumable_weight_lb.y(0), in.consumable_weight_lb.y(0));
  EXPECT_NEAR(s.vacuum_thrust_lbf(10.0 / 1.01), 1.01 * in.vacuum_thrust_lbf(10.0), 1e-6);
  MissionFault fault;
  EXPECT_EQ(validate_mission(out, &fault), Status::kOk);
  // Stage 1's burn rate carries the zero-alpha window (which must lie in stage 1) along.
  ASSERT_EQ(perturb_stage_parameter(base, 1, ExchangeParameter::kBurnRate, 1.0, &out), Status::kOk);
  EXPECT_NEAR(out.control.zero_alpha_end_s, base.control.zero_alpha_end_s / 1.01, 1e-12);
  EXPECT_EQ(validate_mission(out, &fault), Status::kOk);

  // Propellant +1 lb: initial consumable +1 lb, thrust / mass flow (Isp) and burn time unchanged.
  ASSERT_EQ(perturb_stage_parameter(base, 2, ExchangeParameter::kPropellantWeight, 1.0, &out), Status::kOk);
  EXPECT_NEAR(s.consumable_weight_lb.y(0), in.consumable_weight_lb.y(0) + 1.0, 1e-9);
  const double isp_in =
      impulse(in.vacuum_thrust_lbf) / (in.consumable_weight_lb.y(0) - in.consumable_weight_lb.last_y());
  const double isp_out =
      impulse(s.vacuum_thrust_lbf) / (s.consumable_weight_lb.y(0) - s.consumable_weight_lb.last_y());
  EXPECT_NEAR(isp_out, isp_in, 1e-9 * isp_in);
  EXPECT_DOUBLE_EQ(s.duration_s, in.duration_s);

  // Isp +1%: thrust x1.01, the weight table unchanged.
  ASSERT_EQ(perturb_stage_parameter(base, 2, ExchangeParameter::kSpecificImpulse, 1.0, &out), Status::kOk);
  EXPECT_NEAR(s.vacuum_thrust_lbf.y(5), 1.01 * in.vacuum_thrust_lbf.y(5), 1e-9);
  EXPECT_DOUBLE_EQ(s.consumable_weight_lb.y(3), in.consumable_weight_lb.y(3));

  // Drag +1 ft^2: C_D S grows by 1 ft^2 at every Mach number.
  ASSERT_EQ(perturb_stage_parameter(base, 2, ExchangeParameter::kDrag, 1.0, &out), Status::kOk);
  for (double mach : {0.3, 0.9, 1.2, 3.0, 8.0}) {
    EXPECT_NEAR(
        s.drag_coefficient(mach) * s.reference_area_ft2 - in.drag_coefficient(mach) * in.reference_area_ft2,
        1.0, 1e-12);
  }

  // Jettison +1 lb.
  ASSERT_EQ(perturb_stage_parameter(base, 2, ExchangeParameter::kJettisonWeight, 1.0, &out), Status::kOk);
  EXPECT_DOUBLE_EQ(s.jettison_weight_lb, in.jettison_weight_lb + 1.0);

  // Named failures.
  EXPECT_EQ(perturb_stage_parameter(base, 6, ExchangeParameter::kJettisonWeight, 1.0, &out),
            Status::kUnknownStageCode);
  EXPECT_EQ(perturb_stage_parameter(base, 5, ExchangeParameter::kJettisonWeight, 1.0, &out),
            Status::kUnknownStageCode);
  EXPECT_EQ(perturb_stage_parameter(base, 2, ExchangeParameter::kBurnRate, -100.0, &out),
            Status::kExchangePercentChangeTooNegative);
  EXPECT_EQ(perturb_stage_parameter(base, 2, ExchangeParameter::kJettisonWeight, 1.0, &base),
            Status::kOutputAliasesInput);
}

TEST(Sec8ExchangeRatios, RefusesAnUnfinishedOptimization) {
  const Baseline& b = baseline();
  ASSERT_EQ(b.status, Status::kOk);
  static OptimizerResult unfinished;  // constraint_count 0: optimize_trajectory never reached its summary
  static ExchangeRatioScratch scratch;
  static ExchangeRatios ratios;
  EXPECT_EQ(compute_exchange_ratios(b.final_ws, unfinished, &scratch, &ratios),
            Status::kOptimizerResultIncomplete);
  EXPECT_EQ(ratios.stage_count, 0);
}

}  // namespace
}  // namespace tolip
