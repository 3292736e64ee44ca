// The q-bar x alpha load limit (not in the manual: a TOLIP extension, issue 15; derivation in
// docs/theory/constraints-and-ics.md "The q-bar x alpha path constraint").
//
// A structures limit |q-bar alpha| <= L over the phases with aerodynamic lift (the stages that use
// the lift table of data block 32, inside the atmosphere) is imposed as an inequality on the
// integral of the squared relative excess over the stored points (trapezoidal, like the heat
// integral of Sec. 13):
//
//   J = integral of max(0, |q alpha| / L - 1)^2 dt   (seconds),   J <= 0 within kQbarAlphaExcessDeadbandS.
//
// The optimizer handles it as Sec. 13 handles the heating constraint: started without it, it is
// appended to the list (code kQbarAlphaConstraintCode) the first time a nominal exceeds the limit
// and kept for the rest of the case. Its adjoint starts at zero and is forced at every point k by
// dJ/dx_k and its pitch-program value by dJ/dtheta_k (qbar_alpha_excess_gradient).
#pragma once

#include "tolip/core/state.hpp"
#include "tolip/core/status.hpp"
#include "tolip/mission/mission.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip/vehicle/prepared_case.hpp"

namespace tolip {

// The optimization deadband of J (s): a 1 % excess held for 1 s. A peak that stays above the limit
// over about 2 s exceeds it by at most about sqrt(1e-4 / 2 s x 15/8) ~ 1 % (parabolic cap).
inline constexpr double kQbarAlphaExcessDeadbandS = 1e-4;

// q-bar alpha at a stored point as flown (lbf rad/ft^2, signed: alpha's sign).
double qbar_alpha_lbf_rad_ft2(const TrajectoryPoint& point);

// True at a point the limit covers: its stage uses the lift table (data block 32) and the point is in
// the atmosphere (q-bar > 0).
bool qbar_alpha_limited(const Mission& mission, const TrajectoryPoint& point);

// The point's weight in the trapezoidal integral over the stored points, s.
double trapezoidal_weight_s(const Trajectory& trajectory, int point);

// J of the flown trajectory (0 when the options set no limit).
double qbar_alpha_excess_s(const Mission& mission, const Trajectory& trajectory);

// The peak |q-bar alpha| of a trajectory and where it is: over every stored point, or over the points
// the limit covers (limited_only). point -1 (value 0) when no point has q-bar alpha != 0.
struct QbarAlphaPeak {
  double value_lbf_rad_ft2 = 0.0;
  double time_s = 0.0;
  int point = -1;
};
QbarAlphaPeak peak_qbar_alpha(const Mission& mission, const Trajectory& trajectory, bool limited_only);

// The partials of q-bar alpha itself at point k (lbf rad/ft^2 per state unit, per rad of the point's
// pitch attitude): central differences of the model evaluation the forward run made there (same
// atmosphere, frames and attitude); zero where the limit does not cover the point or alpha is held
// at zero; kNonFiniteState if they are not finite. The linearization's peak rows
// (docs/theory/linearization.md) start their adjoints from them.
Status qbar_alpha_point_partials(const Mission& mission, const PreparedCase& prepared,
                                 const Trajectory& trajectory, int point, StateVector* ds_dx,
                                 double* ds_dtheta);

// The forcing of J's adjoint at point k: dJ/dx_k ([V, gamma, r, psi, lambda, tau]) and dJ/dtheta_k
// (the point's own pitch attitude), both zero where the point is under the limit. q-bar alpha's
// partials are central differences of the model evaluation the forward run made there (same
// atmosphere, frames and attitude); kNonFiniteState if they are not finite.
Status qbar_alpha_excess_gradient(const Mission& mission, const PreparedCase& prepared,
                                  const Trajectory& trajectory, int point, StateVector* d_state,
                                  double* d_theta);

}  // namespace tolip
