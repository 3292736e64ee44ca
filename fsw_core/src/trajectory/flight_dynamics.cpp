#include "tolip/trajectory/flight_dynamics.hpp"

#include <cmath>

#include "tolip/atmosphere/atmosphere.hpp"
#include "tolip/dynamics/equations_of_motion.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/frames/frames.hpp"

namespace tolip {

StageContext make_stage_context(const Mission& mission, const PreparedCase& prepared,
                                 const StageTimeline& line) {
  StageContext stage;
  stage.code = line.code;
  stage.start_s = line.start_s;
  stage.data = &mission.vehicle.stages[stage_index(line.code)];
  const bool powered = is_powered_stage(line.code);
  stage.thrust = powered ? &prepared.modified_thrust_lbf[stage_index(line.code)] : nullptr;
  const double own_consumable = powered ? stage.data->consumable_weight_lb(0.0) : 0.0;
  stage.weight_above_consumable_lb = vehicle_weight_lb(mission.vehicle, line.code, 0.0) - own_consumable;
  return stage;
}

bool attitude_set_in_flight(const Mission& mission, int stage_code, double stage_start_s, double t) {
  // Step-start times are sums of fixed steps; half of TIMEP (CT1(10)) absorbs their round-off.
  const double eps = 0.5 * mission.constants.time_epsilon_s;
  const bool window_end = mission.options.zero_alpha_window() &&
                          std::fabs(t - mission.control.zero_alpha_end_s) < eps;
  const bool stage2_ignition = mission.options.alpha_zero_at_stage2_ignition() && stage_code == 2 &&
                               std::fabs(t - stage_start_s) < eps;
  return window_end || stage2_ignition;
}

double zero_alpha_theta_rad(const PreparedCase& prepared, const StateVector& state) {
  return theta_for_zero_alpha_rad(inertial_to_local(StateTrig(state)) * prepared.platform_to_inertial, 0.0);
}

void evaluate_flight(const Mission& mission, const PreparedCase& prepared, const StageContext& stage,
                     const StepCommand& command, double t, const StateVector& state,
                     double weight_offset_lb, Evaluation* out) {
  const Constants& constants = mission.constants;
  const StageData& data = *stage.data;
  const double stage_time = t - stage.start_s;
  const double v = state[kStateV];
  const StateTrig trig(state);
  const double surface_radius = oblate_radius_ft(constants, trig.sin_lambda, trig.cos_lambda);
  out->altitude_ft = state[kStateR] - surface_radius;

  // Above HAERO (CT1(7)) every aerodynamic computation is bypassed: no density, no pressure.
  double pressure = 0.0;
  double density = 0.0;
  double speed_of_sound = 0.0;
  if (out->altitude_ft <= constants.haero_ft) {
    AtmosphereSample air;
    if (ok(evaluate_atmosphere(mission.atmosphere, constants, out->altitude_ft, surface_radius, &air))) {
      pressure = air.pressure_lbf_ft2;
      density = air.density_slug_ft3;
      speed_of_sound = air.speed_of_sound_ft_s;
    }
  }

  out->weight_lb = stage.weight_above_consumable_lb + weight_offset_lb +
                   (is_powered_stage(stage.code) ? data.consumable_weight_lb(stage_time) : 0.0);
  out->vacuum_thrust_lbf = (stage.thrust != nullptr) ? (*stage.thrust)(stage_time) : 0.0;
  out->net_thrust_lbf =
      (stage.thrust != nullptr) ? out->vacuum_thrust_lbf - pressure * data.nozzle_exit_area_ft2 : 0.0;

  const Matrix3 platform_to_local = inertial_to_local(trig) * prepared.platform_to_inertial;
  out->chi_rad = command.chi_rad;
  switch (command.mode) {
    case AttitudeMode::kHeld:
      out->theta_rad = command.theta_start_rad;
      break;
    case AttitudeMode::kZeroAlpha:
      out->theta_rad = theta_for_zero_alpha_rad(platform_to_local, command.chi_rad);
      break;
    case AttitudeMode::kLinear: {
      const double fraction = (t - command.step_start_s) / command.step_s;
      out->theta_rad = command.theta_start_rad + fraction * (command.theta_end_rad - command.theta_start_rad);
      break;
    }
  }
  out->thrust_axis_local = platform_to_local * thrust_axis_platform(out->theta_rad, out->chi_rad);

  out->density_slug_ft3 = density;
  out->dynamic_pressure_lbf_ft2 = 0.5 * density * v * v;
  out->mach = (speed_of_sound > 0.0) ? v / speed_of_sound : 0.0;
  out->drag_lbf = 0.0;
  out->lift_lbf = 0.0;
  if (density > 0.0) {
    const double q_s = out->dynamic_pressure_lbf_ft2 * data.reference_area_ft2;
    if (!data.drag_coefficient.empty()) out->drag_lbf = q_s * data.drag_coefficient(out->mach);
    if (data.uses_lift_table && !mission.vehicle.lift_curve_slope_per_rad.empty()) {
      // Alpha (an atan2) is needed on the integration path only where there is lift.
      out->lift_lbf = q_s * mission.vehicle.lift_curve_slope_per_rad(out->mach) *
                      angle_of_attack_rad(out->thrust_axis_local);
    }
  }

  AppliedForces forces;
  forces.mass_slug = out->weight_lb / constants.g0_ft_s2;
  forces.thrust_local_lbf = out->net_thrust_lbf * out->thrust_axis_local;
  forces.drag_lbf = out->drag_lbf;
  forces.lift_lbf = out->lift_lbf;
  forces.heading_hold = command.heading_hold;
  out->derivative = state_derivative(constants, state, trig, forces);
}

}  // namespace tolip
