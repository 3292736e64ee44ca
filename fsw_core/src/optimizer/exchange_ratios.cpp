// Performance exchange ratios (manual Sec. 8, 12; docs/theory/exchange-ratios.md).
#include "tolip/optimizer/exchange_ratios.hpp"

#include "tolip/optimizer/constraint_parameters.hpp"
#include "tolip/optimizer/constraint_set.hpp"

namespace tolip {
namespace {

// Each ratio is a one-sided difference over +1 unit of its parameter (1% or 1 lb or 1 ft^2): small
// against every stage's values (the smallest is stage 4's 560 lb of propellant), and large enough
// that the constraint changes stand far above the forward runs' rounding.
constexpr double kStepUnits = 1.0;

// Copies `in` into *out with every abscissa multiplied by time_factor and every value by
// value_factor.
template <int N>
Status rescale_table(const Table<N>& in, double time_factor, double value_factor, Table<N>* out) {
  out->clear();
  for (int i = 0; i < in.size(); ++i) {
    const Status status = out->append(in.x(i) * time_factor, in.y(i) * value_factor);
    if (!ok(status)) return status;
  }
  return out->finalize();
}

template <int N>
Status scale_values(double factor, Table<N>* table) {
  for (int i = 0; i < table->size(); ++i) table->set_y(i, table->y(i) * factor);
  return table->finalize();
}

bool in_sequence(const Mission& mission, int code) {
  const StageSequence& sequence = mission.vehicle.sequence;
  for (int k = 0; k < sequence.count; ++k) {
    if (sequence.codes[k] == code) return true;
  }
  return false;
}

// The optimizer's constraint list as it finished (the heating constraint included if it joined).
// Every listed constraint counts, inequalities too: the eq. 9-22 partials were computed with all of
// them held (an inequality that the optimum does not need has a partial near 0).
// The optimizer's final constraint list (tolip/optimizer/constraint_set.hpp), rebuilt from its result.
Status make_constraint_set(const Mission& mission, const OptimizerResult& result, ConstraintSet* set) {
  if (result.constraint_count <= 0 || result.constraint_count > kMaxConstraints) {
    return Status::kOptimizerResultIncomplete;
  }
  set->count = result.constraint_count;
  for (int i = 0; i < set->count; ++i) {
    const Status status = decode_constraint_code(result.codes[i], &set->codes[i]);
    if (!ok(status)) return status;
    set->desired[i] = result.desired[i];
    set->deadband[i] = (i == 0) ? 1.0 : result.tolerance[i];
    set->inequality[i] = result.inequality[i];
  }
  set->payload_payoff = mission.options.payoff() == 0 && set->codes[0].kind == ConstraintQuantity::kPayload;
  return Status::kOk;
}

// Flies scratch->mission with the final program into `out`, with `prepared` (nullptr: re-prepared
// from the mission, Sec. 14 tables included), resumed from scratch->base at timeline slot
// `resume_slot` when it is > 0.
Status fly_and_evaluate(const OptimizerWorkspace& ws, const ConstraintSet& set, const PreparedCase* prepared,
                        int resume_slot, ExchangeRatioScratch* scratch, Trajectory* out,
                        double values[kMaxConstraints]) {
  if (prepared == nullptr) {
    const Status status = prepare_case(scratch->mission, &scratch->prepared);
    if (!ok(status)) return status;
    prepared = &scratch->prepared;
  }
  FlightInputs inputs;
  inputs.program = &ws.program;
  if (resume_slot > 0) {
    inputs.resume_from = &scratch->base;
    inputs.resume_stage_slot = resume_slot;
  }
  const Status status = fly_trajectory(scratch->mission, *prepared, inputs, out);
  if (!ok(status)) return status;
  return evaluate_constraints(set, scratch->mission, *out, values);
}

// The timeline slot where a change of `parameter` of stage `code` starts to act: its ignition for
// the burn rate, the specific impulse and the drag (nothing before the stage uses them); 0 (launch)
// for the weights, which every earlier stage carries.
int first_affected_slot(const OptimizerWorkspace& ws, int code, ExchangeParameter parameter) {
  if (parameter != ExchangeParameter::kBurnRate && parameter != ExchangeParameter::kSpecificImpulse &&
      parameter != ExchangeParameter::kDrag) {
    return 0;
  }
  for (int k = 0; k < ws.prepared.stage_count; ++k) {
    if (ws.prepared.timeline[k].code == code) return k;
  }
  return 0;
}

// The partial-weighted constraint change per unit step, sum_i partials_i d c_i, from the values of
// the run at +step and of the base run.
double priced_constraint_change(const ConstraintSet& set, const OptimizerResult& result,
                                const double plus[kMaxConstraints], const double base[kMaxConstraints],
                                double step) {
  double priced = 0.0;
  for (int i = 1; i < set.count; ++i) {
    const double dc = constraint_deviation(set.codes[i], plus[i], base[i]) / step;
    priced += result.payoff_partials[i] * dc;
  }
  return priced;
}

struct Context {
  const OptimizerWorkspace* ws = nullptr;
  const OptimizerResult* result = nullptr;
  ConstraintSet set;
  // Payoff cost of a unit of partial-weighted constraint change: 1 / kappa for the payload payoff
  // (the eq. 9-22 partials are kappa times the multipliers, docs/theory/exchange-ratios.md), 1 else.
  double price = 1.0;
  ExchangeRatioScratch* scratch = nullptr;
  ExchangeRatios* out = nullptr;
  // The final case re-prepared and flown unperturbed: every one-sided difference starts here.
  double base[kMaxConstraints] = {};
};

// Eq. 8-17 to first order: the change of the re-optimized payoff per unit change of the parameter,
// d payoff - price * sum_i partials_i d c_i, both from the final trajectory flown at +1 unit against
// the base run. One-sided: the unit steps are small against every characteristic (1 lb, 1%, 1 ft^2),
// so the curvature term is far inside the 5% the ratios are checked to, at half the runs of central
// differences (docs/theory/exchange-ratios.md gives both).
Status stage_ratio(Context* c, int code, ExchangeParameter parameter, double* ratio) {
  double plus[kMaxConstraints] = {};
  Status status = perturb_stage_parameter(c->ws->mission, code, parameter, kStepUnits, &c->scratch->mission);
  if (ok(status)) {
    status = fly_and_evaluate(*c->ws, c->set, nullptr, first_affected_slot(*c->ws, code, parameter),
                              c->scratch, &c->scratch->trajectory, plus);
  }
  ++c->out->forward_runs;
  if (!ok(status)) return status;
  const double direct = (plus[0] - c->base[0]) / kStepUnits;  // 0 for the payload payoff
  *ratio = direct - c->price * priced_constraint_change(c->set, *c->result, plus, c->base, kStepUnits);
  return Status::kOk;
}

}  // namespace

Status perturb_stage_parameter(const Mission& base, int stage_code, ExchangeParameter parameter, double units,
                               Mission* out) {
  if (out == &base) return Status::kOutputAliasesInput;
  if (!is_powered_stage(stage_code) || !in_sequence(base, stage_code)) return Status::kUnknownStageCode;
  *out = base;
  const StageData& in = base.vehicle.stages[stage_index(stage_code)];
  StageData& stage = out->vehicle.stages[stage_index(stage_code)];
  switch (parameter) {
    case ExchangeParameter::kBurnRate: {
      // Thrust x f at stage time t / f: the same total impulse and consumed weight in 1/f the time.
      const double f = 1.0 + 0.01 * units;
      if (!(f > 0.0)) return Status::kExchangePercentChangeTooNegative;
      Status status = rescale_table(in.vacuum_thrust_lbf, 1.0 / f, f, &stage.vacuum_thrust_lbf);
      if (ok(status)) {
        status = rescale_table(in.consumable_weight_lb, 1.0 / f, 1.0, &stage.consumable_weight_lb);
      }
      if (!ok(status)) return status;
      stage.duration_s = in.duration_s / f;
      // The zero-alpha window lies in stage 1 (data block 22): it follows the stage's time.
      if (stage_code == 1 && base.options.zero_alpha_window()) {
        out->control.zero_alpha_start_s = base.control.zero_alpha_start_s / f;
        out->control.zero_alpha_end_s = base.control.zero_alpha_end_s / f;
      }
      return Status::kOk;
    }
    case ExchangeParameter::kPropellantWeight: {
      // The consumable table scaled so its initial entry grows by `units`; the thrust by the same
      // factor, which keeps the specific impulse (thrust / mass flow) and the burn time.
      if (in.consumable_weight_lb.empty() || !(in.consumable_weight_lb.y(0) > 0.0)) {
        return Status::kExchangeStageWithoutPropellant;
      }
      const double k = (in.consumable_weight_lb.y(0) + units) / in.consumable_weight_lb.y(0);
      if (!(k > 0.0)) return Status::kExchangePropellantChangeTooNegative;
      const Status status = scale_values(k, &stage.consumable_weight_lb);
      return ok(status) ? scale_values(k, &stage.vacuum_thrust_lbf) : status;
    }
    case ExchangeParameter::kSpecificImpulse: {
      // More thrust for the same mass flow (Sec. 8: "an increase in thrust while maintaining the
      // nominal mass flow rate").
      const double f = 1.0 + 0.01 * units;
      if (!(f > 0.0)) return Status::kExchangePercentChangeTooNegative;
      return scale_values(f, &stage.vacuum_thrust_lbf);
    }
    case ExchangeParameter::kDrag: {
      // C_D S grows by `units` ft^2 at every Mach number: units / S added to every C_D entry.
      if (in.drag_coefficient.empty()) return Status::kOk;  // no drag in this stage
      if (!(in.reference_area_ft2 > 0.0)) return Status::kReferenceAreaMissing;
      const double added = units / in.reference_area_ft2;
      for (int i = 0; i < stage.drag_coefficient.size(); ++i) {
        stage.drag_coefficient.set_y(i, stage.drag_coefficient.y(i) + added);
      }
      return stage.drag_coefficient.finalize();
    }
    case ExchangeParameter::kJettisonWeight:
      stage.jettison_weight_lb = in.jettison_weight_lb + units;
      return Status::kOk;
  }
  return Status::kUnknownExchangeParameter;
}

Status compute_exchange_ratios(const OptimizerWorkspace& final_ws, const OptimizerResult& result,
                               ExchangeRatioScratch* scratch, ExchangeRatios* out) {
  *out = ExchangeRatios();
  const Mission& mission = final_ws.mission;
  if (!ok(final_ws.nominal.status) || final_ws.nominal.point_count <= 0) {
    return Status::kFinalTrajectoryMissing;
  }
  if (final_ws.program.point_count != final_ws.nominal.point_count) {
    return Status::kControlProgramSizeMismatch;
  }
  Context c;
  c.ws = &final_ws;
  c.result = &result;
  c.scratch = scratch;
  c.out = out;
  Status status = make_constraint_set(mission, result, &c.set);
  if (!ok(status)) return status;
  scratch->mission = mission;
  status = fly_and_evaluate(final_ws, c.set, nullptr, 0, scratch, &scratch->base, c.base);
  ++out->forward_runs;
  if (!ok(status)) return status;

  // Payload payoff: kappa = sum_i partials_i d c_i / d payload, the payload's own price in the
  // partials (1 at a true optimum). The payload changes as the optimizer changes it, without
  // re-deriving the Sec. 14 tables, exactly like the column of lambda_m the partials were built from.
  // Its base is the final case flown with the optimizer's own prepared case (the Sec. 14 tables of
  // the initial payload), not the re-prepared one of the stage parameters: the two differ by about
  // 0.07 ft/s at burnout on the reference, as much as a 1 lb payload change does.
  if (c.set.payload_payoff) {
    double base[kMaxConstraints] = {};
    double plus[kMaxConstraints] = {};
    for (int side = 0; side < 2; ++side) {
      scratch->mission = mission;
      if (side == 1) scratch->mission.vehicle.payload_lb += kStepUnits;
      status = fly_and_evaluate(final_ws, c.set, &final_ws.prepared, 0, scratch, &scratch->trajectory,
                                side == 0 ? base : plus);
      ++out->forward_runs;
      if (!ok(status)) return status;
    }
    out->payload_stationarity = priced_constraint_change(c.set, result, plus, base, kStepUnits);
    if (!(out->payload_stationarity > 0.0)) return Status::kSteeringMatrixSingular;
    c.price = 1.0 / out->payload_stationarity;
  }

  const StageSequence& sequence = mission.vehicle.sequence;
  for (int k = 0; k < sequence.count; ++k) {
    const int code = sequence.codes[k];
    if (!is_powered_stage(code) || out->stage_count >= kMaxPoweredStages) continue;
    const int s = out->stage_count++;
    out->stage_codes[s] = code;
    const StageData& stage = mission.vehicle.stages[stage_index(code)];
    status = stage_ratio(&c, code, ExchangeParameter::kBurnRate, &out->burn_rate[s]);
    if (ok(status)) {
      status = stage_ratio(&c, code, ExchangeParameter::kPropellantWeight, &out->propellant_weight[s]);
    }
    if (ok(status)) {
      status = stage_ratio(&c, code, ExchangeParameter::kSpecificImpulse, &out->specific_impulse[s]);
    }
    if (ok(status) && !stage.drag_coefficient.empty() && stage.reference_area_ft2 > 0.0) {
      status = stage_ratio(&c, code, ExchangeParameter::kDrag, &out->drag[s]);
    }
    if (ok(status)) {
      status = stage_ratio(&c, code, ExchangeParameter::kJettisonWeight, &out->jettison_weight[s]);
    }
    if (!ok(status)) return status;
  }
  return Status::kOk;
}

}  // namespace tolip
