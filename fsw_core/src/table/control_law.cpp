// Attitude control law delta = K_theta (theta_c - theta) - K_q theta_dot with deflection limits.
#include "tolip/table/control_law.hpp"

#include <cmath>

namespace tolip {

Status attitude_control_deflection(const GuidanceCommand& command, double theta_measured_rad,
                                   double theta_dot_measured_rad_s, ControlDeflection* out) {
  ControlDeflection result;
  if (!std::isfinite(theta_measured_rad) || !std::isfinite(theta_dot_measured_rad_s) ||
      !std::isfinite(command.theta_rad) || !std::isfinite(command.k_theta) || !std::isfinite(command.k_q_s) ||
      !std::isfinite(command.max_deflection_rad)) {
    *out = result;
    return Status::kValueNotFinite;
  }
  const double limit = std::fabs(command.max_deflection_rad);
  result.unlimited_rad =
      command.k_theta * (command.theta_rad - theta_measured_rad) - command.k_q_s * theta_dot_measured_rad_s;
  result.deflection_rad = result.unlimited_rad;
  if (result.deflection_rad > limit) {
    result.deflection_rad = limit;
    result.saturated = true;
  } else if (result.deflection_rad < -limit) {
    result.deflection_rad = -limit;
    result.saturated = true;
  }
  *out = result;
  return Status::kOk;
}

}  // namespace tolip
