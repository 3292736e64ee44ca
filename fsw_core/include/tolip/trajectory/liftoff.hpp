// Closed-form vertical lift-off for DA5(1) seconds (data block 20).
//
// The manual names a "closed-form lift-off" and gives nothing more. The model (docs/theory/
// liftoff.md): the vehicle rises along the geocentric vertical, fixed to the rotating Earth's
// meridian (gamma = 90 deg, psi = launch azimuth, latitude constant, tau = tau0 + omega t); its
// vertical acceleration
//   a(t) = (T(t) - p0 Ae) C23 / m(t) + r0 omega^2 cos^2(lambda) - g (1 + J2/2 (re/r0)^2 (3 - 9 sin^2 lambda))
// (the F equation at gamma = 90 deg without drag) is taken linear between its values at 0 and TL,
// which integrates exactly: V_L = TL (a0 + a1) / 2, h_L = TL^2 (a0 / 3 + a1 / 6). Drag is neglected
// (q < 40 lb/ft^2 in three seconds). T is the Sec. 14 table, whose first interval is [0, TL].
#pragma once

#include "tolip/core/state.hpp"
#include "tolip/core/status.hpp"
#include "tolip/mission/mission.hpp"
#include "tolip/vehicle/prepared_case.hpp"

namespace tolip {

struct LiftoffResult {
  double acceleration_at_0_ft_s2 = 0.0;
  double acceleration_at_end_ft_s2 = 0.0;
  double velocity_ft_s = 0.0;  // V_L
  double height_ft = 0.0;      // h_L, rise above the pad radius
  double c23 = 0.0;            // thrust-axis component along V at the pad
  double pad_pressure_lbf_ft2 = 0.0;
  StateVector state_at_end = StateVector::Zero();  // state at TL
  // Sensitivity of V_L and h_L to the vehicle weight (a payload change), for the backward runs.
  double dvelocity_dweight_ft_s_per_lb = 0.0;
  double dheight_dweight_ft_per_lb = 0.0;
};

Status closed_form_liftoff(const Mission& mission, const PreparedCase& prepared, LiftoffResult* out);

}  // namespace tolip
