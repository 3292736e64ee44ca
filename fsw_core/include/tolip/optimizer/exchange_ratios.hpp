// Performance exchange ratios (manual Sec. 8 and 12, option IP(3)): for every powered stage of the
// sequence, the first-order change of the payoff of a RE-OPTIMIZED trajectory per unit change of
// five vehicle characteristics — burn rate (1%), propellant weight (1 lb), specific impulse (1%),
// drag area C_D S (1 ft^2) and jettison weight (1 lb) — in payoff units (lb, ft/s or ft).
//
//   ratio = d payoff - price * sum_i payoff_partials_i * d c_i        (eq. 8-17 to first order)
//
// d payoff and d c_i are the linear effect of the parameter on the final optimized trajectory
// (same per-point pitch program, same adjustable parameters, same payload): one-sided differences
// of a forward run of the final optimized case with the parameter at +1 unit, re-prepared
// (Sec. 14 thrust tables). payoff_partials are eq. 9-22's (OptimizerResult::payoff_partials; eq.
// 8-18's U). price is 1 for velocity and altitude payoffs; for the payload payoff (where d payoff
// is 0: the payload is a control) it is 1 / kappa, kappa = sum_i partials_i d c_i / d payload:
// the eq. 9-22 partials are kappa times the multipliers because the payload shares the correction
// step with the pitch program (DA2(15)); kappa -> 1 at a true optimum. The manual integrates the
// same first-order effects with the adjoint (the L and R arrays of eqs. 8-19..8-21); differences of
// forward runs of the model that was optimized are an equivalent first-order computation that needs
// no added adjoint forcing terms. docs/theory/exchange-ratios.md gives the definitions, the
// derivation of kappa, the signs and the measured agreement with re-optimization.
#pragma once

#include "tolip/core/capacity.hpp"
#include "tolip/core/status.hpp"
#include "tolip/mission/mission.hpp"
#include "tolip/optimizer/steepest_descent.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip/vehicle/prepared_case.hpp"

namespace tolip {

// The five stage characteristics of Sec. 8, in the manual's order of output.
enum class ExchangeParameter : int {
  kBurnRate,          // %: thrust x (1 + u/100), every thrust and weight table time / (1 + u/100)
  kPropellantWeight,  // lb: consumable table x (W0 + u) / W0, thrust x the same (Isp and burn time kept)
  kSpecificImpulse,   // %: thrust x (1 + u/100), weight table unchanged (mass flow and burn time kept)
  kDrag,              // ft^2 of drag area: u / S added to every C_D entry of the stage's table
  kJettisonWeight,    // lb: the stage's jettison weight + u
};

// Exchange ratios by powered stage, in flight order. Units: payoff unit (lb for payload, ft/s for
// velocity, ft for altitude) per 1% of burn rate, per lb of propellant, per 1% of specific impulse,
// per ft^2 of drag area C_D S, per lb of jettison weight.
struct ExchangeRatios {
  int stage_count = 0;
  int stage_codes[kMaxPoweredStages] = {};
  double burn_rate[kMaxPoweredStages] = {};
  double propellant_weight[kMaxPoweredStages] = {};
  double specific_impulse[kMaxPoweredStages] = {};
  double drag[kMaxPoweredStages] = {};  // 0 for a stage without a drag table (block 31)
  double jettison_weight[kMaxPoweredStages] = {};
  // Payload payoff only (else 0): kappa = sum_i partials_i d c_i / d payload, the partials' price of
  // 1 lb of payload (flown as the optimizer changes the payload: no Sec. 14 re-derivation). It is
  // 1 at a true optimum; below 1 when the payload shares the correction step with the pitch
  // program. The ratios are divided by it, so the last stage's jettison weight comes out -1 lb/lb.
  double payload_stationarity = 0.0;
  int forward_runs = 0;  // forward runs made
};

// Caller-owned storage for the perturbed runs (large: keep it static or on the heap).
struct ExchangeRatioScratch {
  Mission mission;
  PreparedCase prepared;
  Trajectory trajectory;
  // The re-prepared unperturbed flight: a change of a stage's burn rate, specific impulse or drag
  // acts from that stage's ignition only, so its run resumes from this one there.
  Trajectory base;
};

// *out = base with powered stage `stage_code`'s characteristic changed by `units` (percent for the
// burn rate and the specific impulse, lb for propellant and jettison weight, ft^2 of C_D S for the
// drag). A burn-rate change of stage 1 also scales the zero-alpha window (IP(11), data block 22,
// which must lie in stage 1) with the stage's time. `out` must not be `base`.
// Fails with kUnknownStageCode (not a powered stage of the sequence), kExchangePercentChangeTooNegative
// or kExchangePropellantChangeTooNegative (a factor not positive), kExchangeStageWithoutPropellant,
// kReferenceAreaMissing (drag on a stage with a reference area of 0), kOutputAliasesInput
// (out == &base), kUnknownExchangeParameter, or a table status.
Status perturb_stage_parameter(const Mission& base, int stage_code, ExchangeParameter parameter, double units,
                               Mission* out);

// The exchange ratios of the optimized case in `final_ws` (after optimize_trajectory: mission,
// prepared, program, nominal) with its `result` (constraint list, achieved values, eq. 9-22
// partials; every listed constraint counts, as in eq. 9-22). Fails with kFinalTrajectoryMissing when
// the final trajectory failed, kControlProgramSizeMismatch when the program does not match it,
// kOptimizerResultIncomplete when the optimizer did not reach its summary (result.constraint_count
// == 0), or the status of a perturbed run.
Status compute_exchange_ratios(const OptimizerWorkspace& final_ws, const OptimizerResult& result,
                               ExchangeRatioScratch* scratch, ExchangeRatios* out);

}  // namespace tolip
