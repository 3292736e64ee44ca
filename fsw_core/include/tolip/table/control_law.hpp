// The attitude control law of the bench (manual Sec. 7, eq. 7-3):
//
//   delta = K_theta (theta_c - theta) - K_q theta_dot,   limited to +/- max_deflection
//
// with theta_c, K_theta, K_q and the limit from the guidance command in force, theta and
// theta_dot the measured pitch attitude (rad) and body pitch rate (rad/s).
#pragma once

#include "tolip/core/status.hpp"
#include "tolip/table/guidance_executor.hpp"

namespace tolip {

struct ControlDeflection {
  double deflection_rad = 0.0;  // commanded deflection after limiting
  double unlimited_rad = 0.0;   // before limiting
  bool saturated = false;       // the limit was applied
};

// Computes the deflection. A non-finite input gives kValueNotFinite and a neutral (zero)
// deflection, never a NaN command.
Status attitude_control_deflection(const GuidanceCommand& command, double theta_measured_rad,
                                   double theta_dot_measured_rad_s, ControlDeflection* out);

}  // namespace tolip
