// The constraint list of a run (data block 8, manual Sec. 5, 9, 13, 22): which constraints are
// active, which are inequalities, their deadbands, their values on a flown trajectory, the
// corrections the steering asks for, whether a run meets them, and the terminal partials that
// start the backward run. The optimizer (steepest descent), the linearization, the exchange
// ratios and the optimization report use this one description; none re-derives it
// (issue 18 item 1, docs/architecture.md).
#pragma once

#include "tolip/core/status.hpp"
#include "tolip/mission/mission.hpp"
#include "tolip/optimizer/backward_run.hpp"
#include "tolip/optimizer/constraint_parameters.hpp"
#include "tolip/trajectory/trajectory.hpp"

namespace tolip {

struct ConstraintSet {
  int count = 0;
  ConstraintCode codes[kMaxConstraints];
  double desired[kMaxConstraints] = {};
  // Per constraint, in its own units (the steering scales by it; a correction within it is met).
  // The payoff, when it is entry 0, has 1 and is never judged.
  double deadband[kMaxConstraints] = {};
  bool inequality[kMaxConstraints] = {};  // achieved <= desired: only an excess is an error
  // Entry 0 is the payoff and the payoff is the payload: its value is the case's payload, not a
  // quantity of the trajectory (the final weight is the inert weight plus it).
  bool payload_payoff = false;
  // Addendum H from an elliptic start (docs/theory/optimizer.md "Earth escape from an elliptic
  // start"): while set, the hyperbolic excess velocity (100) is valued by its energy stand-in
  // (hyperbolic_excess_stand_in_ft_s) and the asymptote's right ascension and declination (101,
  // 102) have no value (NaN: never met) and zero partials. The optimizer sets it from its nominal
  // (needs_hyperbolic_stand_in); every other user leaves it false.
  bool hyperbolic_stand_in = false;
};

// The energy stand-in for code 100: (2E + v_d^2) / (2 v_d), v_d the desired excess velocity. It
// equals v_d exactly where v_H = sqrt(2E) does, with the same slope there (1 / (2 v_d) per unit of
// 2E), exceeds v_H by (v_H - v_d)^2 / (2 v_d) where both exist, and exists at every energy, so a
// steering from an elliptic nominal asks the energy for the right change. NaN unless v_d > 0.
double hyperbolic_excess_stand_in_ft_s(double twice_energy_ft2_s2, double desired_ft_s);

// Whether a nominal is to be steered with the stand-in: the set lists a code 100..102 and the final
// point's 2E is below (v_d / 2)^2 (a quarter of the asked energy; 0 without code 100): not yet
// hyperbolic, or too close to parabolic for the asymptote's first-order theory (d v_H / d 2E =
// 1 / (2 v_H) grows without bound).
bool needs_hyperbolic_stand_in(const ConstraintSet& set, const Mission& mission,
                               const Trajectory& trajectory);

// The inequality rule: total heating (IP(2), Sec. 13) and the q-bar x alpha excess (issue 15)
// always, dynamic pressure under IP(13) = 1.
bool is_inequality_constraint(const ConstraintCode& code, const Options& options);

// Appends one constraint (its inequality by the rule above); kTooManyConstraints when full,
// kDeadbandNotPositive when the deadband is not positive.
Status append_constraint(const ConstraintCode& code, double desired, double deadband, const Options& options,
                         ConstraintSet* set);

// The inequality rule on a correction d psi = desired - achieved: for an inequality (an upper
// limit) a deficit (achieved below desired, d psi > 0) is no error, 0; an excess and every
// equality's correction count as they are. The one place this rule is written.
double counted_correction(bool inequality, double correction);

// desired - achieved of entry i (longitudes wrapped into [-pi, pi)), by the inequality rule.
double constraint_correction(const ConstraintSet& set, int i, double achieved);

// The same judgement for one constraint outside a set (the report's deck constraints).
bool constraint_met(const ConstraintCode& code, bool inequality, double achieved, double desired,
                    double deadband);

// Every entry from `first` on (1 when entry 0 is the payoff) has its correction inside its deadband
// (an entry without a value, NaN, is not).
bool within_deadbands(const ConstraintSet& set, int first, const double achieved[kMaxConstraints]);

// Values of every entry on a flown trajectory (stage-point codes at their stage's end); the
// payload payoff is the payload. kConstraintPointNotInTrajectory when a stage point is not in the
// trajectory.
Status evaluate_constraints(const ConstraintSet& set, const Mission& mission, const Trajectory& trajectory,
                            double achieved[kMaxConstraints]);

// Where each entry applies and its partial derivatives there: the backward run's initial
// conditions (Sec. 5 ICS; total heating is integrated along the run instead).
Status constraint_terminals(const ConstraintSet& set, const Mission& mission, const Trajectory& trajectory,
                            ConstraintTerminal terminals[kMaxConstraints]);

}  // namespace tolip
