// Frames and thrust resolution of manual Sec. 4: platform P -> geocentric G [B'] -> inertial I [B]
// -> local L [A], and [C] = [A][B][B'].
//
// The printed [A] is garbled by the scan. It is built here from the rotation sequence the manual
// lists ("rotate about k_z by -tau, about k_y by 90 - lambda, about k_x by 90 - psi, about k_y by
// -gamma"), which as passive (frame) rotations is [A] = Rx(gamma) Rz(90 - psi) Ry(90 - lambda) Rz(tau).
// tests/core/frames_test.cpp proves it orthonormal, equal to the oracle's [A], and consistent with
// the partial derivatives of [A] listed in Sec. 5. [B] and [B'] are as printed, evaluated once at
// t = 0 with the launch latitude, azimuth and longitude.
#pragma once

#include <cmath>

#include "tolip/core/constants.hpp"
#include "tolip/core/state.hpp"

namespace tolip {

// Passive rotations: the matrix that re-expresses a vector in a frame turned by `angle_rad`.
Matrix3 frame_rotation_x(double angle_rad);
Matrix3 frame_rotation_y(double angle_rad);
Matrix3 frame_rotation_z(double angle_rad);

// Sines and cosines of the state's angles, computed once per derivative evaluation and shared by
// [A], the equations of motion, gravity and the oblate radius.
struct StateTrig {
  // The sines, then the cosines, each in the state's order: the addition-theorem form (StateTrigAnchor)
  // reads and writes them four at a time.
  double sin_gamma, sin_psi, sin_lambda, sin_tau;
  double cos_gamma, cos_psi, cos_lambda, cos_tau;
  explicit StateTrig(const StateVector& state);
};

// The largest angle step the addition-theorem form takes: there the truncated series (d^9 for the
// sine, d^10 for 1 - cos) err by below 1e-19 relative.
inline constexpr double kStateTrigAdditionLimitRad = 1.0 / 16.0;

struct SineCosine {
  double sin, cos;
};

// sin(a) and cos(a) from s0 = sin(a0), c0 = cos(a0) by the addition theorem, sin(a0 + d) = sin a0 +
// (cos a0 sin d - sin a0 (1 - cos d)) with d = a - a0 and sin d, 1 - cos d from their Taylor series
// (StateTrigAnchor forms each of the state's angles so); the library's when
// |a - a0| >= kStateTrigAdditionLimitRad or a is not finite.
SineCosine sine_cosine_by_addition(double s0, double c0, double a0, double a);

// One angle's sine and cosine along a flight by the addition theorem from an anchor the library
// evaluated, as StateTrigAnchor below does for the state's four: moved to the angle itself when it
// is kStateTrigAdditionLimitRad or more from the anchor (or not finite).
class SineCosineAnchor {
 public:
  SineCosine at(double angle_rad);

 private:
  bool anchored_ = false;
  double anchor_rad_ = 0.0;
  SineCosine anchor_ = {0.0, 1.0};
};

// The angle's remainder about a turn, in [-pi, pi]: std::remainder(angle, 2 pi), which is the angle
// itself (bit for bit) when |angle| <= pi, its nearest quotient being 0; that case skips the library.
inline double wrap_angle_rad(double angle) {
  return (std::fabs(angle) <= kPi) ? angle : std::remainder(angle, 2.0 * kPi);
}

// atan2(y, x) of a small angle, x > 0 and |y| < x / 16 (3.6 deg), by the Taylor series of atan(y / x)
// to (y / x)^13 (truncation below 1e-18 relative); the library's atan2 otherwise (and for NaN and
// y = +-0).
double atan2_by_series(double y, double x);
// That series' domain, x > 0 and |y| < x / 16 (false for NaN): the one place the limit is written.
inline bool in_atan2_series_domain(double y, double x) { return x > 0.0 && std::fabs(y) * 16.0 < x; }
// atan2 of an angle that is small in flight: atan2_by_series when `by_series` (a dispersion flight's,
// FlightInputs::trig_by_series), the library's otherwise. The one place that choice is made.
inline double small_angle_atan2(double y, double x, bool by_series) {
  return by_series ? atan2_by_series(y, x) : std::atan2(y, x);
}

// atan2(y, x) of an angle that moves little along a flight, from an anchor angle a0 the library
// evaluated: a0 + atan2_by_series(y cos a0 - x sin a0, x cos a0 + y sin a0), the direction (x, y)
// turned back by a0. The anchor moves to atan2(y, x) itself, by the library, when that difference
// is outside atan2_by_series' domain (3.6 deg, or not finite). A dispersion flight's body dynamics
// take the velocity's elevation gamma_w this way (docs/theory/trajectory.md).
class Atan2Anchor {
 public:
  double at(double y, double x);

 private:
  bool anchored_ = false;
  double anchor_rad_ = 0.0;
  SineCosine anchor_ = {0.0, 1.0};
};

// The state's sines and cosines along a flight by the addition theorem from an anchor, a state
// whose StateTrig the library evaluated. Every value is one addition from the anchor's, so no error
// accumulates (each is within 2 ulps of the library's); the anchor moves to the state itself,
// evaluated by the library, whenever one of its angles is kStateTrigAdditionLimitRad or more from
// the anchor's, or is not finite. A dispersion flight keeps one per stage
// (FlightInputs::trig_by_series; docs/theory/trajectory.md).
class StateTrigAnchor {
 public:
  StateTrig at(const StateVector& state);

 private:
  bool anchored_ = false;
  StateVector anchor_ = StateVector::Zero();
  StateTrig anchor_trig_ = StateTrig(StateVector::Zero());
};

// [A]: inertial -> local at the state's gamma, psi, lambda and inertial longitude tau.
Matrix3 inertial_to_local(const StateVector& state);
// The same, multiplied out: row 1 = Rz(90 - psi) Ry(90 - lambda) Rz(tau) row 1, rows 2-3 turned by gamma.
Matrix3 inertial_to_local(const StateTrig& trig);
// [A] v without forming [A]: v turned by Rz(tau), Ry(90 - lambda), Rz(90 - psi) and Rx(gamma) in
// turn (24 operations against [A]'s 39 and its product's 15). Equal to inertial_to_local(trig) * v
// to round-off, not bit for bit: a dispersion flight's thrust axis (docs/theory/trajectory.md).
Vector3 inertial_to_local_times(const StateTrig& trig, const Vector3& v);

// [B]: geocentric launch frame -> inertial, at launch azimuth psi0, latitude lambda0, longitude tau0.
Matrix3 geocentric_to_inertial(double azimuth_rad, double geocentric_latitude_rad, double longitude_rad);

// [B']: platform -> geocentric launch frame, turning the geodetic vertical into the geocentric one.
Matrix3 platform_to_geocentric(double azimuth_rad, double delta_lambda_rad);

// Unit thrust axis in the platform frame: (cos theta sin chi, cos theta cos chi, sin theta).
Vector3 thrust_axis_platform(double theta_rad, double chi_rad);

// In-plane angle of attack: the angle from i_y (along V) to the thrust axis in the i_y-i_z plane.
double angle_of_attack_rad(const Vector3& thrust_axis_local);
// The same angle by small_angle_atan2 (by series in a dispersion flight).
double angle_of_attack_rad(const Vector3& thrust_axis_local, bool by_series);

// Pitch attitude theta that puts the thrust axis along V in the vertical plane (alpha = 0) for yaw
// chi, given [C]: solves C31 cos(theta) sin(chi) + C32 cos(theta) cos(chi) + C33 sin(theta) = 0 on
// the branch with a forward (positive i_y) thrust component.
double theta_for_zero_alpha_rad(const Matrix3& platform_to_local, double chi_rad);

// A(lambda_d, u) of Sec. 18: Earth-fixed rectangular -> topocentric geodetic at a site of geodetic
// latitude lambda_d and longitude u (east). Rows: local geodetic north, east, and the normal to the
// spheroid positive towards the geocentre (down). As printed; it is Ry(-(90 deg + lambda_d)) Rz(u).
Matrix3 earth_fixed_to_topocentric(double geodetic_latitude_rad, double longitude_rad);

}  // namespace tolip
