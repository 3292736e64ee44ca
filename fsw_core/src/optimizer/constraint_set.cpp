#include "tolip/optimizer/constraint_set.hpp"

#include <cmath>
#include <limits>

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
    if (!(std::fabs(constraint_correction(set, i, achieved[i])) <= set.deadband[i])) return false;
  }
  return true;
}

namespace {

bool is_asymptote(ConstraintQuantity kind) {
  return kind == ConstraintQuantity::kHyperbolicExcessVelocity ||
         kind == ConstraintQuantity::kAsymptoteRightAscension ||
         kind == ConstraintQuantity::kAsymptoteDeclination;
}

// Code 9, twice the energy (2E): the Addendum H stand-in's quantity.
Status twice_energy_code(ConstraintCode* energy) { return decode_constraint_code(9, energy); }

}  // namespace

double hyperbolic_excess_stand_in_ft_s(double twice_energy_ft2_s2, double desired_ft_s) {
  if (!(desired_ft_s > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  return (twice_energy_ft2_s2 + desired_ft_s * desired_ft_s) / (2.0 * desired_ft_s);
}

bool needs_hyperbolic_stand_in(const ConstraintSet& set, const Mission& mission,
                               const Trajectory& trajectory) {
  bool listed = false;
  double desired_ft_s = 0.0;
  for (int i = 0; i < set.count; ++i) {
    if (!is_asymptote(set.codes[i].kind)) continue;
    listed = true;
    if (set.codes[i].kind == ConstraintQuantity::kHyperbolicExcessVelocity) desired_ft_s = set.desired[i];
  }
  if (!listed || trajectory.point_count < 1) return false;
  const ConstraintPoint point = constraint_point_at(mission, trajectory, trajectory.point_count - 1);
  double twice_energy = 0.0;
  ConstraintCode energy;
  // Without a 2E (a non-finite state) there is nothing to continue from; the evaluation fails.
  if (!ok(twice_energy_code(&energy)) ||
      !ok(constraint_value(mission.constants, mission.launch, energy, point, &twice_energy))) {
    return false;
  }
  return twice_energy <= 0.0 || twice_energy < 0.25 * desired_ft_s * desired_ft_s;
}

Status evaluate_constraints(const ConstraintSet& set, const Mission& mission, const Trajectory& trajectory,
                            double achieved[kMaxConstraints]) {
  for (int i = 0; i < set.count; ++i) {
    const int index = constraint_point_index(set.codes[i], trajectory);
    if (index < 0) return Status::kConstraintPointNotInTrajectory;
    const ConstraintPoint point = constraint_point_at(mission, trajectory, index);
    if (set.hyperbolic_stand_in && is_asymptote(set.codes[i].kind)) {
      achieved[i] = std::numeric_limits<double>::quiet_NaN();
      if (set.codes[i].kind != ConstraintQuantity::kHyperbolicExcessVelocity) continue;
      double twice_energy = 0.0;
      ConstraintCode energy;
      Status status = twice_energy_code(&energy);
      if (ok(status)) {
        status = constraint_value(mission.constants, mission.launch, energy, point, &twice_energy);
      }
      if (!ok(status)) return status;
      achieved[i] = hyperbolic_excess_stand_in_ft_s(twice_energy, set.desired[i]);
      continue;
    }
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
    if (set.hyperbolic_stand_in && is_asymptote(set.codes[i].kind)) {
      terminals[i].partials.setZero();
      const bool stand_in =
          set.codes[i].kind == ConstraintQuantity::kHyperbolicExcessVelocity && set.desired[i] > 0.0;
      if (!stand_in) continue;  // deferred: no adjoint
      ConstraintCode energy;
      AdjointVector energy_partials;
      Status status = twice_energy_code(&energy);
      if (ok(status)) {
        status = constraint_partials(mission.constants, mission.launch, energy, point, &energy_partials);
      }
      if (!ok(status)) return status;
      terminals[i].partials = energy_partials / (2.0 * set.desired[i]);
      continue;
    }
    const Status status =
        constraint_partials(mission.constants, mission.launch, set.codes[i], point, &terminals[i].partials);
    if (!ok(status)) return status;
  }
  return Status::kOk;
}

}  // namespace tolip
