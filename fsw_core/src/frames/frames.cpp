#include "tolip/frames/frames.hpp"

#include <cmath>

#include "tolip/core/constants.hpp"

namespace tolip {

Matrix3 frame_rotation_x(double angle_rad) {
  const double c = std::cos(angle_rad);
  const double s = std::sin(angle_rad);
  Matrix3 m;
  m << 1.0, 0.0, 0.0, 0.0, c, s, 0.0, -s, c;
  return m;
}

Matrix3 frame_rotation_y(double angle_rad) {
  const double c = std::cos(angle_rad);
  const double s = std::sin(angle_rad);
  Matrix3 m;
  m << c, 0.0, -s, 0.0, 1.0, 0.0, s, 0.0, c;
  return m;
}

Matrix3 frame_rotation_z(double angle_rad) {
  const double c = std::cos(angle_rad);
  const double s = std::sin(angle_rad);
  Matrix3 m;
  m << c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0;
  return m;
}

StateTrig::StateTrig(const StateVector& state)
    : sin_gamma(std::sin(state[kStateGamma])), sin_psi(std::sin(state[kStatePsi])),
      sin_lambda(std::sin(state[kStateLambda])), sin_tau(std::sin(state[kStateTau])),
      cos_gamma(std::cos(state[kStateGamma])), cos_psi(std::cos(state[kStatePsi])),
      cos_lambda(std::cos(state[kStateLambda])), cos_tau(std::cos(state[kStateTau])) {}

namespace {

// sin(a0 + d) and cos(a0 + d) from s0 = sin a0, c0 = cos a0 for |d| < kStateTrigAdditionLimitRad:
// sin d = d (1 - d^2/6 (1 - d^2/20 (1 - d^2/42 (1 - d^2/72)))) and 1 - cos d = d^2/2 (1 - d^2/12
// (1 - d^2/30 (1 - d^2/56 (1 - d^2/90)))), the Taylor series in nested (Horner) form, with the small
// corrections added last so that the result keeps the accuracy of s0 and c0 (d = 0 gives s0 and
// c0). One formula for one angle (T = double) and for the state's four at once (T = Eigen::Array4d,
// two at a time): the same IEEE operations on each angle, so the values do not depend on which.
template <typename T>
void add_small_angle(const T& s0, const T& c0, const T& d, T* s, T* c) {
  constexpr double k6 = 1.0 / 6.0, k20 = 1.0 / 20.0, k42 = 1.0 / 42.0, k72 = 1.0 / 72.0;
  constexpr double k12 = 1.0 / 12.0, k30 = 1.0 / 30.0, k56 = 1.0 / 56.0, k90 = 1.0 / 90.0;
  const T d2 = d * d;
  const T sin_d = d * (1.0 - d2 * k6 * (1.0 - d2 * k20 * (1.0 - d2 * k42 * (1.0 - d2 * k72))));
  const T one_minus_cos_d =
      0.5 * d2 * (1.0 - d2 * k12 * (1.0 - d2 * k30 * (1.0 - d2 * k56 * (1.0 - d2 * k90))));
  *s = s0 + (c0 * sin_d - s0 * one_minus_cos_d);
  *c = c0 - (s0 * sin_d + c0 * one_minus_cos_d);
}

// The four angles' steps from a base state, as one Eigen array.
using AngleSteps = Eigen::Array4d;
AngleSteps angle_steps(const StateVector& base, const StateVector& state) {
  return AngleSteps(state[kStateGamma] - base[kStateGamma], state[kStatePsi] - base[kStatePsi],
                    state[kStateLambda] - base[kStateLambda], state[kStateTau] - base[kStateTau]);
}

bool within_limit(const AngleSteps& d) {
  return (d.abs() < kStateTrigAdditionLimitRad).all();  // false for a NaN or infinite angle too
}

// StateTrig from `b` by the addition theorem, every step d within the limit (the callers check it).
StateTrig added_state_trig(const StateTrig& b, const AngleSteps& d) {
  const AngleSteps s0(b.sin_gamma, b.sin_psi, b.sin_lambda, b.sin_tau);
  const AngleSteps c0(b.cos_gamma, b.cos_psi, b.cos_lambda, b.cos_tau);
  AngleSteps s;
  AngleSteps c;
  add_small_angle(s0, c0, d, &s, &c);
  StateTrig t = b;
  t.sin_gamma = s[0];
  t.sin_psi = s[1];
  t.sin_lambda = s[2];
  t.sin_tau = s[3];
  t.cos_gamma = c[0];
  t.cos_psi = c[1];
  t.cos_lambda = c[2];
  t.cos_tau = c[3];
  return t;
}

}  // namespace

SineCosine sine_cosine_by_addition(double s0, double c0, double a0, double a) {
  const double d = a - a0;
  if (!(std::fabs(d) < kStateTrigAdditionLimitRad)) {  // a large step, or a NaN / infinite angle
    return {std::sin(a), std::cos(a)};
  }
  SineCosine out;
  add_small_angle(s0, c0, d, &out.sin, &out.cos);
  return out;
}

SineCosine SineCosineAnchor::at(double angle_rad) {
  if (anchored_ && std::fabs(angle_rad - anchor_rad_) < kStateTrigAdditionLimitRad) {
    return sine_cosine_by_addition(anchor_.sin, anchor_.cos, anchor_rad_, angle_rad);
  }
  anchored_ = true;
  anchor_rad_ = angle_rad;
  anchor_ = {std::sin(angle_rad), std::cos(angle_rad)};
  return anchor_;
}

double atan2_by_series(double y, double x) {
  // Also NaN and infinities, and y = +-0 (whose sign the sum below would lose).
  if (!in_atan2_series_domain(y, x) || y == 0.0) return std::atan2(y, x);
  constexpr double k3 = 1.0 / 3.0, k5 = 1.0 / 5.0, k7 = 1.0 / 7.0, k9 = 1.0 / 9.0, k11 = 1.0 / 11.0,
                   k13 = 1.0 / 13.0;
  const double z = y / x;
  const double z2 = z * z;
  // atan z = z - z^3/3 + z^5/5 - ... + z^13/13; the small correction added last.
  return z + z * z2 * (-k3 + z2 * (k5 + z2 * (-k7 + z2 * (k9 + z2 * (-k11 + z2 * k13)))));
}

double Atan2Anchor::at(double y, double x) {
  if (anchored_) {
    const double along = x * anchor_.cos + y * anchor_.sin;
    const double across = y * anchor_.cos - x * anchor_.sin;
    if (in_atan2_series_domain(across, along)) return anchor_rad_ + atan2_by_series(across, along);
  }
  anchored_ = true;
  anchor_rad_ = std::atan2(y, x);
  anchor_ = {std::sin(anchor_rad_), std::cos(anchor_rad_)};
  return anchor_rad_;
}

StateTrig StateTrigAnchor::at(const StateVector& state) {
  if (anchored_) {
    const AngleSteps d = angle_steps(anchor_, state);
    if (within_limit(d)) return added_state_trig(anchor_trig_, d);
  }
  anchored_ = true;
  anchor_ = state;
  anchor_trig_ = StateTrig(state);
  return anchor_trig_;
}

Matrix3 inertial_to_local(const StateTrig& t) {
  // M = Rz(90 - psi) Ry(90 - lambda) Rz(tau); [A] = Rx(gamma) M.
  const double m00 = t.sin_psi * t.sin_lambda * t.cos_tau - t.cos_psi * t.sin_tau;
  const double m01 = t.sin_psi * t.sin_lambda * t.sin_tau + t.cos_psi * t.cos_tau;
  const double m02 = -t.sin_psi * t.cos_lambda;
  const double m10 = -t.cos_psi * t.sin_lambda * t.cos_tau - t.sin_psi * t.sin_tau;
  const double m11 = -t.cos_psi * t.sin_lambda * t.sin_tau + t.sin_psi * t.cos_tau;
  const double m12 = t.cos_psi * t.cos_lambda;
  const double m20 = t.cos_lambda * t.cos_tau;
  const double m21 = t.cos_lambda * t.sin_tau;
  const double m22 = t.sin_lambda;
  const double cg = t.cos_gamma, sg = t.sin_gamma;
  Matrix3 a;
  a << m00, m01, m02, cg * m10 + sg * m20, cg * m11 + sg * m21, cg * m12 + sg * m22, -sg * m10 + cg * m20,
      -sg * m11 + cg * m21, -sg * m12 + cg * m22;
  return a;
}

Vector3 inertial_to_local_times(const StateTrig& t, const Vector3& v) {
  // Each frame rotation by angle a turns the two components it acts on by (c, s) = (cos a, sin a);
  // 90 - lambda and 90 - psi swap their sines and cosines.
  const double x1 = t.cos_tau * v.x() + t.sin_tau * v.y();  // Rz(tau)
  const double y1 = -t.sin_tau * v.x() + t.cos_tau * v.y();
  const double x2 = t.sin_lambda * x1 - t.cos_lambda * v.z();  // Ry(90 - lambda)
  const double z2 = t.cos_lambda * x1 + t.sin_lambda * v.z();
  const double x3 = t.sin_psi * x2 + t.cos_psi * y1;  // Rz(90 - psi)
  const double y3 = -t.cos_psi * x2 + t.sin_psi * y1;
  return Vector3(x3, t.cos_gamma * y3 + t.sin_gamma * z2,  // Rx(gamma)
                 -t.sin_gamma * y3 + t.cos_gamma * z2);
}

// The definition as a product of frame rotations; kept as the readable form and tested against
// the multiplied-out one.
Matrix3 inertial_to_local(const StateVector& state) {
  const double half_pi = 0.5 * kPi;
  return frame_rotation_x(state[kStateGamma]) * frame_rotation_z(half_pi - state[kStatePsi]) *
         frame_rotation_y(half_pi - state[kStateLambda]) * frame_rotation_z(state[kStateTau]);
}

Matrix3 geocentric_to_inertial(double azimuth_rad, double geocentric_latitude_rad, double longitude_rad) {
  const double sp = std::sin(azimuth_rad), cp = std::cos(azimuth_rad);
  const double sl = std::sin(geocentric_latitude_rad), cl = std::cos(geocentric_latitude_rad);
  const double st = std::sin(longitude_rad), ct = std::cos(longitude_rad);
  Matrix3 b;
  b << sp * sl * ct - cp * st, -sp * st - cp * sl * ct, cl * ct, cp * ct + sp * sl * st,
      sp * ct - cp * sl * st, cl * st, -sp * cl, cp * cl, sl;
  return b;
}

Matrix3 platform_to_geocentric(double azimuth_rad, double delta_lambda_rad) {
  const double sp = std::sin(azimuth_rad), cp = std::cos(azimuth_rad);
  const double sd = std::sin(delta_lambda_rad), cd = std::cos(delta_lambda_rad);
  Matrix3 b;
  b << sp * sp * cd + cp * cp, sp * cp * (1.0 - cd), -sp * sd, sp * cp * (1.0 - cd), sp * sp + cp * cp * cd,
      cp * sd, sp * sd, -cp * sd, cd;
  return b;
}

Vector3 thrust_axis_platform(double theta_rad, double chi_rad) {
  const double ct = std::cos(theta_rad);
  // Yaw is zero on most trajectories; skip its sine and cosine then.
  if (chi_rad == 0.0) return Vector3(0.0, ct, std::sin(theta_rad));
  return Vector3(ct * std::sin(chi_rad), ct * std::cos(chi_rad), std::sin(theta_rad));
}

double angle_of_attack_rad(const Vector3& thrust_axis_local) {
  return std::atan2(thrust_axis_local.z(), thrust_axis_local.y());
}

double angle_of_attack_rad(const Vector3& thrust_axis_local, bool by_series) {
  return small_angle_atan2(thrust_axis_local.z(), thrust_axis_local.y(), by_series);
}

double theta_for_zero_alpha_rad(const Matrix3& platform_to_local, double chi_rad) {
  const Matrix3& c = platform_to_local;
  // u_Lz = cos(theta) a + sin(theta) b = 0 with a = C31 sin chi + C32 cos chi, b = C33.
  const double a = c(2, 0) * std::sin(chi_rad) + c(2, 1) * std::cos(chi_rad);
  const double b = c(2, 2);
  double theta = std::atan2(-a, b);
  // Of the two roots theta and theta + pi, keep the one whose thrust points forward along V.
  const double forward = c(1, 0) * std::cos(theta) * std::sin(chi_rad) +
                         c(1, 1) * std::cos(theta) * std::cos(chi_rad) + c(1, 2) * std::sin(theta);
  if (forward < 0.0) theta = (theta > 0.0) ? theta - kPi : theta + kPi;
  return theta;
}

Matrix3 earth_fixed_to_topocentric(double geodetic_latitude_rad, double longitude_rad) {
  const double sl = std::sin(geodetic_latitude_rad), cl = std::cos(geodetic_latitude_rad);
  const double su = std::sin(longitude_rad), cu = std::cos(longitude_rad);
  Matrix3 a;
  a << -cu * sl, -su * sl, cl,  //
      -su, cu, 0.0,             //
      -cl * cu, -cl * su, -sl;
  return a;
}

}  // namespace tolip
