#include "tolip/optimizer/constraint_set.hpp"

#include <cmath>

namespace tolip {

bool is_inequality_constraint(const ConstraintCode& code, const Options& options) {
  return code.kind == ConstraintQuantity::kTotalHeating ||
         code.kind == ConstraintQuantity::kQbarAlphaExcess ||
         (code.kind == ConstraintQuantity::kDynamicPressure && options.qbar_constraint_type() == 1);
}

Status append_constraint(const ConstraintCode& code, double desired, double deadband, const Options& options,
                         ConstraintSet* set) {
  if (set->count >= kMaxConstraints) return Status::kTooManyConstraints;
  if (!(deadband > 0.0)) return Status::kDeadbandNotPositive;
  const int i = set->count++;
  set->codes[i] = code;
  set->desired[i] = desired;
  set->deadband[i] = deadband;
  set->inequality[i] = is_inequality_constraint(code, options);
  return Status::kOk;
}

double counted_correction(bool inequality, double correction) {
  return (inequality && correction > 0.0) ? 0.0 : correction;
}

double constraint_correction(const ConstraintSet& set, int i, double achieved) {
  return counted_correction(set.inequality[i], -constraint_deviation(set.codes[i], achieved, set.desired[i]));
}

bool constraint_met(const ConstraintCode& code, bool inequality, double achieved, double desired,
                    double deadband) {
  return std::fabs(counted_correction(inequality, -constraint_deviation(code, achieved, desired))) <=
         deadband;
}

bool within_deadbands(const ConstraintSet& set, int first, const double achieved[kMaxConstraints]) {
  for (int i = first; i < set.count; ++i) {
    if (std::fabs(constraint_correction(set, i, achieved[i])) > set.deadband[i]) return false;
  }
  return true;
}

Status evaluate_constraints(const ConstraintSet& set, const Mission& mission, const Trajectory& trajectory,
                            double achieved[kMaxConstraints]) {
  for (int i = 0; i < set.count; ++i) {
    const int index = constraint_point_index(set.codes[i], trajectory);
    if (index < 0) return Status::kConstraintPointNotInTrajectory;
    const ConstraintPoint point = constraint_point_at(mission, trajectory, index);
    const Status status =
        constraint_value(mission.constants, mission.launch, set.codes[i], point, &achieved[i]);
    if (!ok(status)) return status;
  }
  if (set.payload_payoff) achieved[0] = mission.vehicle.payload_lb;
  return Status::kOk;
}

Status constraint_terminals(const ConstraintSet& set, const Mission& mission, const Trajectory& trajectory,
                            ConstraintTerminal terminals[kMaxConstraints]) {
  for (int i = 0; i < set.count; ++i) {
    terminals[i].point = constraint_point_index(set.codes[i], trajectory);
    if (terminals[i].point < 0) return Status::kConstraintPointNotInTrajectory;
    terminals[i].heat_integral = set.codes[i].kind == ConstraintQuantity::kTotalHeating;
    terminals[i].qbar_alpha_integral = set.codes[i].kind == ConstraintQuantity::kQbarAlphaExcess;
    const ConstraintPoint point = constraint_point_at(mission, trajectory, terminals[i].point);
    const Status status =
        constraint_partials(mission.constants, mission.launch, set.codes[i], point, &terminals[i].partials);
    if (!ok(status)) return status;
  }
  return Status::kOk;
}

}  // namespace tolip
