// Constraint parameters of data block 8 and the initial conditions of their adjoint variables
// (manual Sec. 5 "INITIAL CONDITIONS FOR INTEGRATION OF THE ADJOINT EQUATIONS", subroutine ICS,
// and Addendum H5.5). See docs/theory/constraints-and-ics.md for every formula and the
// misprints found in the printed partial derivatives.
//
// Units: angles in radians, lengths in ft, velocities in ft/s, downrange in nautical miles
// (60 n.mi. per degree of arc, data block 19), dynamic pressure in lbf/ft^2, heating in Btu/ft^2,
// the payoff payload as a weight in lb.
#pragma once

#include <Eigen/Core>

#include "tolip/core/constants.hpp"
#include "tolip/core/state.hpp"
#include "tolip/core/status.hpp"
#include "tolip/mission/mission.hpp"
#include "tolip/trajectory/trajectory.hpp"

namespace tolip {

// The quantity a block-8 code constrains. Stage-point codes 10 X + 5 .. 10 X + 8 name the same
// quantities as the terminal codes 5 .. 8; 10 X + 9 is the dynamic pressure (not 2E).
enum class ConstraintQuantity : int {
  kPayload,                     // 0 (payoff only)
  kInertialVelocity,            // 1  V_I
  kInertialFlightPathAngle,     // 2  gamma_I
  kVelocityOverCircular,        // 3  V_I - sqrt(mu / r)
  kRadius,                      // 4  r
  kAerodynamicVelocity,         // 5, X5  V
  kAerodynamicFlightPathAngle,  // 6, X6  gamma
  kAltitude,                    // 7, X7  h = r - R_OBL(lambda)
  kDownrange,                   // 8, X8  n.mi. from the launch point
  kTwiceEnergy,                 // 9  2E = V_I^2 - 2 mu / r
  kInclination,                 // 10 i
  kPerigeeRadius,               // 11 r_p
  kNodeLongitude,               // 12 Omega_e (inertial, from the vernal equinox)
  kArgumentOfPerigee,           // 13 beta_p
  kTotalHeating,                // 14 integral of the heating rate (Sec. 13)
  kDynamicPressure,             // X9 q = rho V^2 / 2
  kHyperbolicExcessVelocity,    // 100 v_H = sqrt(2E)
  kAsymptoteRightAscension,     // 101 alpha_eH
  kAsymptoteDeclination,        // 102 delta_eH
  // 200: not a data block 8 code (TOLIP extension, issue 15): the q-bar x alpha excess integral of
  // tolip/optimizer/qbar_alpha.hpp, which joins the list when the limit in the options is exceeded.
  kQbarAlphaExcess,
};

// The code the q-bar x alpha constraint carries in the optimizer's list and its reports.
inline constexpr int kQbarAlphaConstraintCode = 200;

struct ConstraintCode {
  int code = 0;                 // as written in data block 8
  bool is_stage_point = false;  // 10 X + 5 .. 10 X + 9
  int stage_code = 0;           // X = 1..9 (the stage at whose END it applies); 0 if terminal
  int quantity = 0;             // the manual's number: the code if terminal, its last digit if stage point
  ConstraintQuantity kind = ConstraintQuantity::kPayload;
};

// Decodes a block-8 code. Fails with kUnknownConstraintCode for anything but 0..14,
// 10 X + 5 .. 10 X + 9 (X = 1..9), 100..102 and kQbarAlphaConstraintCode (the optimizer's own; data
// block 8 never lists it); *out is untouched on failure.
Status decode_constraint_code(int code, ConstraintCode* out);

// What a constraint value or its partial derivatives need at the point where it applies (the
// end of stage X, or the final point). The caller fills the atmosphere fields from the
// atmosphere model at the point's altitude (they are used only by the dynamic pressure), and
// the heating integral (used only by code 14).
struct ConstraintPoint {
  StateVector state = StateVector::Zero();  // [V, gamma, r, psi, lambda, tau], tau inertial
  double time_from_launch_s = 0.0;          // Earth-fixed longitude = tau - omega t
  // Vehicle weight at the point, W = g0 m. The payoff "payload" (code 0) is reported as this
  // final weight: the payload differs from it by inert weights that no control changes.
  double weight_lb = 0.0;
  double density_slug_ft3 = 0.0;       // rho at the point
  double ddensity_dh = 0.0;            // d rho / dh, slug/ft^3 per ft (for q-bar partials)
  double total_heating_btu_ft2 = 0.0;  // integral of Qdot dt up to the point (code 14)
  double qbar_alpha_excess_s = 0.0;    // the q-bar x alpha excess integral of the trajectory (code 200)
};

// Index of the mass in the 7-component adjoint vector [V, gamma, r, psi, lambda, tau, m].
// The constraint point of a trajectory's point `index`: its state, time, weight, the heat integral
// of the whole trajectory, and the density with its GEOMETRIC altitude derivative (Sec. 19 gives
// d rho / dH*; dH*/dh = (R / (R + h))^2). No atmosphere above HAERO.
ConstraintPoint constraint_point_at(const Mission& mission, const Trajectory& trajectory, int index);

// Index of the point where a constraint applies: the final point for terminal constraints, the end
// point of stage X for stage-point codes; -1 when that stage was not flown.
int constraint_point_index(const ConstraintCode& code, const Trajectory& trajectory);

inline constexpr int kAdjointMass = 6;
using AdjointVector = Eigen::Matrix<double, 7, 1>;

// Value of the constraint parameter at the point, in the units of data block 19.
// Fails with kNonFiniteState (non-finite state or point data), kZeroVelocity (V_I ~ 0 or r <= 0
// where orbit quantities are needed), kConstraintNotHyperbolic (codes 100..102 with 2E <= 0),
// kUnknownConstraintCode (a ConstraintCode not produced by decode_constraint_code).
// The angles 12, 13, 101 are in [0, 2 pi), like the orbit elements module.
Status constraint_value(const Constants& constants, const LaunchConditions& launch,
                        const ConstraintCode& code, const ConstraintPoint& point, double* value);

// d(value)/d(state) at the point: the adjoint initial conditions (ICS). Components
// [V, gamma, r, psi, lambda, tau, m] with m the vehicle MASS in slug: only the payload has a
// mass component, g0 (the weight in lb of one slug); every other constraint has 0 there.
// Total heating (14) is an integral constraint: its adjoint starts at zero and is driven by
// stagnation_heating_rate_partials() in the adjoint equations (Sec. 13), so its partials are 0.
// Fails like constraint_value, and with kConstraintSingular where the derivative does not exist:
// inclination, node or asymptote constraints on an equatorial orbit (sin i < 1e-12),
// perigee radius or argument of perigee on a circular orbit (e < 1e-10), any gamma_I/psi_I
// dependent constraint with vertical inertial velocity, downrange at 0 or 180 deg of arc,
// declination at +-90 deg.
Status constraint_partials(const Constants& constants, const LaunchConditions& launch,
                           const ConstraintCode& code, const ConstraintPoint& point, AdjointVector* partials);

// Constraint error value - desired, in the units of data block 19. For the angles that are
// reported in [0, 2 pi) (node longitude 12, argument of perigee 13, asymptote right ascension
// 101) the difference is wrapped into [-pi, pi), so that a value of 359.9 deg against a desired
// 0.1 deg is an error of -0.2 deg, not 359.8 deg.
double constraint_deviation(const ConstraintCode& code, double value, double desired);

// d(constraint)/d(launch time of day), rad/s: nonzero only for the node longitude (12) and the
// asymptote right ascension (101), which depend on the right ascension of Greenwich at lift-off.
// Every other constraint is Earth-referenced and does not move when the launch is delayed.
double constraint_partial_wrt_launch_time(const ConstraintCode& code);

// d Omega_e / d(launch time), rad/s: the rate of the Herget right ascension of Greenwich
// (360 + 0.98564743) deg per day. The manual prints 4.1068643e-3 deg/s, a misprint for
// 4.1780746e-3 deg/s (= 7.2921159e-5 rad/s, the Earth's sidereal rate).
double node_longitude_partial_wrt_launch_time_rad_per_s();

// Partial derivatives of the inertial variables (INER) with respect to the state
// [V, gamma, r, psi, lambda, tau]: rows V_I, gamma_I, psi_I. Fails with kNonFiniteState or
// kZeroVelocity (V_I ~ 0), and kConstraintSingular when the inertial velocity is vertical
// (gamma_I and psi_I have no derivative there).
using InertialJacobian = Eigen::Matrix<double, 3, 6>;
Status inertial_variable_partials(const Constants& constants, const StateVector& state,
                                  InertialJacobian* jacobian);

// d R_OBL / d lambda (ft/rad) of the oblate Earth radius (earth_model.hpp), so that the altitude
// h = r - R_OBL(lambda) has dh/dlambda = -d R_OBL / d lambda.
double oblate_radius_latitude_derivative_ft_per_rad(const Constants& constants,
                                                    double geocentric_latitude_rad);

// Sec. 13 forcing of the heating constraint's adjoint equations: partials of the stagnation
// heating rate Qdot (Btu/ft^2/s) with respect to [V, gamma, r, psi, lambda, tau] at a point:
// dQ/dV = 3.25 Q / V, dQ/dr = Q / (2 rho) drho/dh, dQ/dlambda = -dQ/dr dR_OBL/dlambda.
// Fails with kValueNotFinite, kNoseRadiusNotPositive, kSeaLevelDensityNotPositive or
// kHeatingStateNegative (negative density or velocity). Zero density (above the atmosphere) gives zero.
Status stagnation_heating_rate_partials(const Constants& constants, double nose_radius_ft,
                                        double sea_level_density_slug_ft3, const ConstraintPoint& point,
                                        Eigen::Matrix<double, 6, 1>* partials);

// Stopping-condition correction (manual eqs. 5-12..5-18): the initial conditions of the adjoint
// of Z when the trajectory ends where S(x) reaches a given value, not at a fixed time:
// dZ/dx - (Zdot / Sdot) dS/dx. TOLIP trajectories end at fixed times (S = t, dS/dx = 0), where
// this is the identity. Sdot must not be zero (the stopping condition must be crossed).
AdjointVector apply_stopping_condition_correction(const AdjointVector& dz_dx, double z_dot,
                                                  const AdjointVector& ds_dx, double s_dot);

}  // namespace tolip
