#include "tolip/trajectory/liftoff.hpp"

#include <cmath>

#include "tolip/atmosphere/atmosphere.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/frames/frames.hpp"

namespace tolip {

Status closed_form_liftoff(const Mission& mission, const PreparedCase& prepared, LiftoffResult* out) {
  if (!prepared.prepared) return Status::kNotPrepared;
  const Constants& constants = mission.constants;
  const StageData& stage1 = mission.vehicle.stages[stage_index(1)];
  const ModifiedThrustTable& thrust = prepared.modified_thrust_lbf[stage_index(1)];
  const double tl = mission.launch.liftoff_duration_s;
  const StateVector& pad = prepared.pad_state;
  const double latitude = pad[kStateLambda];
  const double r0 = pad[kStateR];

  AtmosphereSample air;
  const Status status = evaluate_atmosphere(mission.atmosphere, constants, mission.launch.altitude_ft,
                                            oblate_radius_ft(constants, latitude), &air);
  if (!ok(status)) return status;

  // Thrust-axis component along the vertical velocity at the pad (theta = 90 deg, chi = 0).
  const Matrix3 platform_to_local = inertial_to_local(pad) * prepared.platform_to_inertial;
  const double c23 = platform_to_local(1, 2);

  const Gravity gravity = j2_gravity(constants, r0, latitude);
  const double cos_lat = std::cos(latitude);
  const double omega = constants.earth_rotation_rate_rad_s;
  const double centrifugal = r0 * omega * omega * cos_lat * cos_lat;
  const auto acceleration = [&](double t) {
    const double mass = vehicle_weight_lb(mission.vehicle, 1, t) / constants.g0_ft_s2;
    const double net_thrust = thrust(t) - air.pressure_lbf_ft2 * stage1.nozzle_exit_area_ft2;
    return net_thrust * c23 / mass + centrifugal - gravity.radial_ft_s2;
  };
  const double a0 = acceleration(0.0);
  const double a1 = acceleration(tl);
  // da/dW = -(T - p0 Ae) C23 g0 / W^2 at both ends.
  const auto dacceleration_dweight = [&](double t) {
    const double weight = vehicle_weight_lb(mission.vehicle, 1, t);
    const double net_thrust = thrust(t) - air.pressure_lbf_ft2 * stage1.nozzle_exit_area_ft2;
    return -net_thrust * c23 * constants.g0_ft_s2 / (weight * weight);
  };
  const double da0 = dacceleration_dweight(0.0);
  const double da1 = dacceleration_dweight(tl);
  if (!std::isfinite(a0) || !std::isfinite(a1)) return Status::kNonFiniteState;

  out->acceleration_at_0_ft_s2 = a0;
  out->acceleration_at_end_ft_s2 = a1;
  out->velocity_ft_s = tl * (a0 + a1) / 2.0;
  out->height_ft = tl * tl * (a0 / 3.0 + a1 / 6.0);
  out->dvelocity_dweight_ft_s_per_lb = tl * (da0 + da1) / 2.0;
  out->dheight_dweight_ft_per_lb = tl * tl * (da0 / 3.0 + da1 / 6.0);
  out->c23 = c23;
  out->pad_pressure_lbf_ft2 = air.pressure_lbf_ft2;
  out->state_at_end = pad;
  out->state_at_end[kStateV] = out->velocity_ft_s;
  out->state_at_end[kStateR] = r0 + out->height_ft;
  out->state_at_end[kStateTau] = pad[kStateTau] + omega * tl;
  return Status::kOk;
}

}  // namespace tolip
