// An independent inertial (Cartesian) model of the point-mass motion, written in the tests from
// textbook definitions rather than the manual's equations: position and velocity in an inertial
// frame (x through Greenwich at lift-off, z north), the J2 gravity gradient, and the conversions to
// and from the state [V, gamma, r, psi, lambda, tau]. Used to check the equations of motion
// (Sec. 4) and the near-vertical integration.
#pragma once

#include <cmath>

#include "tolip/core/constants.hpp"
#include "tolip/core/state.hpp"

namespace tolip::test {

struct Cartesian {
  Vector3 r;  // inertial position (x through Greenwich at lift-off, z north)
  Vector3 v;  // inertial velocity
};

inline Cartesian to_cartesian(const Constants& k, const StateVector& x) {
  const double g = x[1], p = x[3], l = x[4], t = x[5];
  const Vector3 up(std::cos(l) * std::cos(t), std::cos(l) * std::sin(t), std::sin(l));
  const Vector3 east(-std::sin(t), std::cos(t), 0.0);
  const Vector3 north = up.cross(east);
  const Vector3 v_rel = x[0] * (std::cos(g) * (std::cos(p) * north + std::sin(p) * east) + std::sin(g) * up);
  Cartesian c;
  c.r = x[2] * up;
  c.v = v_rel + Vector3(0.0, 0.0, k.earth_rotation_rate_rad_s).cross(c.r);
  return c;
}

// Angles from the vertical by atan2 of the along and across components, not asin of their ratio
// to the norm: at gamma = 90 deg exactly (the state the vertical lift-off ends in) round-off puts
// v.up / |v| above 1 and asin returns NaN.
inline StateVector from_cartesian(const Constants& k, const Cartesian& c) {
  const double r = c.r.norm();
  const double l = std::atan2(c.r.z(), std::hypot(c.r.x(), c.r.y()));
  const double t = std::atan2(c.r.y(), c.r.x());
  const Vector3 up = c.r / r;
  const Vector3 east(-std::sin(t), std::cos(t), 0.0);
  const Vector3 north = up.cross(east);
  const Vector3 v_rel = c.v - Vector3(0.0, 0.0, k.earth_rotation_rate_rad_s).cross(c.r);
  StateVector x;
  const double v_up = v_rel.dot(up);
  x << v_rel.norm(), std::atan2(v_up, (v_rel - v_up * up).norm()), r,
      std::atan2(v_rel.dot(east), v_rel.dot(north)), l, t;
  return x;
}

// Gradient of U = mu/r [1 - J2/2 (re/r)^2 (3 sin^2(lat) - 1)], the textbook Cartesian J2 form.
inline Vector3 j2_acceleration(const Constants& k, const Vector3& r) {
  const double rn = r.norm();
  const double f = 1.5 * k.j2 * std::pow(k.earth_equatorial_radius_ft / rn, 2);
  const double z2 = std::pow(r.z() / rn, 2);
  const double m = -k.gravitational_parameter_ft3_s2 / std::pow(rn, 3);
  return Vector3(m * r.x() * (1.0 - f * (5.0 * z2 - 1.0)), m * r.y() * (1.0 - f * (5.0 * z2 - 1.0)),
                 m * r.z() * (1.0 - f * (5.0 * z2 - 3.0)));
}

}  // namespace tolip::test
