#include "tolip/dynamics/equations_of_motion.hpp"

#include <cmath>

#include "tolip/earth/earth_model.hpp"

namespace tolip {

StateVector state_derivative(const Constants& constants, const StateVector& state,
                             const AppliedForces& forces) {
  return state_derivative(constants, state, StateTrig(state), forces);
}

StateVector state_derivative(const Constants& constants, const StateVector& state, const StateTrig& trig,
                             const AppliedForces& forces) {
  const double v = state[kStateV];
  const double r = state[kStateR];
  const double sg = trig.sin_gamma, cg = trig.cos_gamma;
  const double sp = trig.sin_psi, cp = trig.cos_psi;
  const double sl = trig.sin_lambda, cl = trig.cos_lambda;
  const double omega = constants.earth_rotation_rate_rad_s;
  const double r_omega2 = r * omega * omega;

  // Gravity in the local frame: inward radial g_r and northward g_N; north = cos(psi) (horizontal
  // along V) - sin(psi) i_x, so its i_y, i_z, i_x parts are cos(psi) cos(gamma), -cos(psi) sin(gamma),
  // -sin(psi).
  const Gravity gravity = j2_gravity(constants, r, sl, cl);
  const double gravity_y = -gravity.radial_ft_s2 * sg + gravity.north_ft_s2 * cp * cg;
  const double gravity_z = -gravity.radial_ft_s2 * cg - gravity.north_ft_s2 * cp * sg;
  const double gravity_x = -gravity.north_ft_s2 * sp;

  const double inv_m = 1.0 / forces.mass_slug;
  const Vector3& thrust = forces.thrust_local_lbf;

  StateVector d;
  // F = dV/dt
  d[kStateV] =
      r_omega2 * (cl * cl * sg - sl * cl * cp * cg) + gravity_y + (thrust.y() - forces.drag_lbf) * inv_m;
  // G = dgamma/dt
  d[kStateGamma] =
      2.0 * omega * cl * sp + (v / r) * cg +
      (gravity_z + r_omega2 * (cl * cl * cg + sl * cl * cp * sg) + (thrust.z() + forces.lift_lbf) * inv_m) /
          v;
  // H = dpsi/dt
  if (forces.heading_hold) {
    d[kStatePsi] = 0.0;
  } else {
    d[kStatePsi] = (v / r) * cg * sp * sl / cl + 2.0 * omega * sl - 2.0 * omega * cl * cp * sg / cg +
                   (r_omega2 * sl * cl * sp + gravity_x + thrust.x() * inv_m) / (v * cg);
  }
  // I, J, K
  d[kStateR] = v * sg;
  d[kStateLambda] = v * cg * cp / r;
  d[kStateTau] = v * cg * sp / (r * cl) + omega;
  return d;
}

}  // namespace tolip
