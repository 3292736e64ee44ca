#include "tolip/trajectory/flight_dynamics.hpp"

#include <cmath>

#include "tolip/atmosphere/atmosphere.hpp"
#include "tolip/body/body_dynamics.hpp"
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
  const bool window_end =
      mission.options.zero_alpha_window() && std::fabs(t - mission.control.zero_alpha_end_s) < eps;
  const bool stage2_ignition = mission.options.alpha_zero_at_stage2_ignition() && stage_code == 2 &&
                               std::fabs(t - stage_start_s) < eps;
  return window_end || stage2_ignition;
}

double zero_alpha_theta_rad(const PreparedCase& prepared, const StateVector& state) {
  return theta_for_zero_alpha_rad(inertial_to_local(StateTrig(state)) * prepared.platform_to_inertial, 0.0);
}

void evaluate_flight(const Mission& mission, const PreparedCase& prepared, const StageContext& stage,
                     const StepCommand& command, double t, const StateVector& state, double weight_offset_lb,
                     Evaluation* out) {
  evaluate_flight(mission, prepared, stage, command, t, state, StateTrig(state), weight_offset_lb, out);
}

namespace {

// The steps of evaluate_flight, in the order it takes them.

struct AirAtPoint {
  double pressure_lbf_ft2 = 0.0;
  double density_slug_ft3 = 0.0;
  double speed_of_sound_ft_s = 0.0;
};

// Above HAERO (CT1(7)) every aerodynamic computation is bypassed: no density, no pressure.
AirAtPoint air_at(const Mission& mission, double altitude_ft, double surface_radius_ft) {
  AirAtPoint out;
  if (altitude_ft <= mission.constants.haero_ft) {
    AtmosphereSample air;
    if (ok(evaluate_atmosphere_without_derivatives(mission.atmosphere, mission.constants, altitude_ft,
                                                   surface_radius_ft, &air))) {
      out.pressure_lbf_ft2 = air.pressure_lbf_ft2;
      out.density_slug_ft3 = air.density_slug_ft3;
      out.speed_of_sound_ft_s = air.speed_of_sound_ft_s;
    }
  }
  return out;
}

// Weight (block 38 and the stage's fixed weights) and thrust (block 30; net of p Ae, block 39).
void weight_and_thrust(const StageContext& stage, double stage_time, double pressure_lbf_ft2,
                       double weight_offset_lb, Evaluation* out) {
  const StageData& data = *stage.data;
  EvaluationScratch* scratch = stage.scratch;
  double consumable_lb = 0.0;
  if (is_powered_stage(stage.code)) {
    consumable_lb = (scratch != nullptr) ? data.consumable_weight_lb(stage_time, &scratch->weight_hint)
                                         : data.consumable_weight_lb(stage_time);
  }
  out->weight_lb = stage.weight_above_consumable_lb + weight_offset_lb + consumable_lb;
  out->vacuum_thrust_lbf = (stage.thrust == nullptr) ? 0.0
                           : (scratch != nullptr)    ? (*stage.thrust)(stage_time, &scratch->thrust_hint)
                                                     : (*stage.thrust)(stage_time);
  out->net_thrust_lbf =
      (stage.thrust != nullptr) ? out->vacuum_thrust_lbf - pressure_lbf_ft2 * data.nozzle_exit_area_ft2 : 0.0;
}

// The commanded attitude of the step: held, zero alpha, or linear in time between its ends.
void commanded_attitude(const StepCommand& command, double t, const Matrix3& platform_to_local,
                        Evaluation* out) {
  out->chi_rad = command.chi_rad;
  switch (command.mode) {
    case AttitudeMode::kHeld: out->theta_rad = command.theta_start_rad; break;
    case AttitudeMode::kZeroAlpha:
      out->theta_rad = theta_for_zero_alpha_rad(platform_to_local, command.chi_rad);
      break;
    case AttitudeMode::kLinear: {
      const double fraction = (t - command.step_start_s) / command.step_s;
      out->theta_rad = command.theta_start_rad + fraction * (command.theta_end_rad - command.theta_start_rad);
      break;
    }
  }
  out->theta_command_rad = out->theta_rad;
}

struct AirRelativeFlow {
  bool windy = false;
  double air_speed_ft_s = 0.0;
  Matrix3 local_to_air = Matrix3::Identity();
};

// Sec. 15 winds: the air-relative velocity takes V's place in q-bar, Mach, the angles of attack
// and the direction of the drag (a dispersed trajectory's; still air otherwise).
AirRelativeFlow air_relative_flow(const StageContext& stage, const StateVector& state, const StateTrig& trig,
                                  double altitude_ft, double density_slug_ft3) {
  AirRelativeFlow flow;
  flow.air_speed_ft_s = state[kStateV];
  const FlightPerturbation* perturbation = stage.perturbation;
  if (perturbation != nullptr && perturbation->wind != nullptr && density_slug_ft3 > 0.0) {
    const WindProfile& wind = *perturbation->wind;
    EvaluationScratch* scratch = stage.scratch;
    const double wind_speed = (scratch != nullptr) ? wind.speed_ft_s(altitude_ft, &scratch->wind_speed_hint)
                                                   : wind.speed_ft_s(altitude_ft);
    if (wind_speed != 0.0) {
      const double wind_azimuth = (scratch != nullptr)
                                      ? wind.azimuth_rad(altitude_ft, &scratch->wind_azimuth_hint)
                                      : wind.azimuth_rad(altitude_ft);
      // In a dispersion flight psi_w - psi's sine and cosine by addition from an anchor.
      const Vector3 air =
          (scratch != nullptr && scratch->trig_by_series)
              ? air_relative_velocity_local(state, trig, wind_speed,
                                            scratch->wind_azimuth_anchor.at(wind_azimuth - state[kStatePsi]))
              : air_relative_velocity_local(state, trig, wind_speed, wind_azimuth);
      flow.air_speed_ft_s = air.norm();
      flow.windy = flow.air_speed_ft_s > 0.0;
      if (flow.windy) flow.local_to_air = local_to_air_frame(air, flow.air_speed_ft_s);
    }
  }
  return flow;
}

// Sec. 7, 11 (docs/theory/body-dynamics.md): the flown attitude is the autopilot's steady state
// about the command, with stage 1's data in stage 1 and in the coast after it. Returns the body
// forces (local frame).
Vector3 body_dynamics_attitude(const Mission& mission, const StageContext& stage, const StepCommand& command,
                               double stage_time, double density_slug_ft3, const Matrix3& platform_to_local,
                               const AirRelativeFlow& flow, Evaluation* out) {
  const StageData& data = *stage.data;
  EvaluationScratch* scratch = stage.scratch;
  const FlightPerturbation* perturbation = stage.perturbation;
  const AeroTable& normal_slope = mission.vehicle.lift_curve_slope_per_rad;
  const bool aero = density_slug_ft3 > 0.0 && !normal_slope.empty();
  const double c_n_alpha = !aero                  ? 0.0
                           : (scratch != nullptr) ? normal_slope(out->mach, &scratch->lift_hint)
                                                  : normal_slope(out->mach);
  BodyDynamicsInputs body;
  body.conditions.stage = 1;
  body.conditions.cg_stage_time_s = (stage.code == 1) ? stage_time : mission.vehicle.stages[0].duration_s;
  body.conditions.mach = out->mach;
  body.conditions.dynamic_pressure_lbf_ft2 = out->dynamic_pressure_lbf_ft2;
  body.conditions.vacuum_thrust_lbf = out->vacuum_thrust_lbf;
  body.conditions.normal_force_slope_per_rad = c_n_alpha;
  body.command.theta_rad = out->theta_rad;
  body.command.theta_rate_rad_s = (command.mode == AttitudeMode::kLinear)
                                      ? (command.theta_end_rad - command.theta_start_rad) / command.step_s
                                      : 0.0;
  body.command.chi_rad = command.chi_rad;
  body.command.chi_rate_rad_s = 0.0;
  // F_alpha: the point-mass model's own normal-force slope (block 32 table, the stage's area).
  body.normal_force_lbf_per_rad = (aero && data.uses_lift_table)
                                      ? out->dynamic_pressure_lbf_ft2 * data.reference_area_ft2 * c_n_alpha
                                      : 0.0;
  body.platform_to_local = platform_to_local;
  Matrix3 air_platform_to_local;
  if (flow.windy) {
    air_platform_to_local = flow.local_to_air * platform_to_local;
    body.air_platform_to_local = &air_platform_to_local;
  }
  if (perturbation != nullptr && stage.code == 1) {
    body.misalignment_pitch_rad = perturbation->misalignment_pitch_rad;
    body.misalignment_yaw_rad = perturbation->misalignment_yaw_rad;
    body.thrust_station_ft = perturbation->thrust_station_ft;
    body.net_thrust_lbf = out->net_thrust_lbf;
  }
  if (scratch != nullptr) {
    body.hints = &scratch->body_hints;
    body.small_angles_by_series = scratch->trig_by_series;
  }
  BodyDynamicsResult result;
  out->body_status = evaluate_body_dynamics(mission.body_dynamics, body, &result);
  out->theta_rad = result.attitude.theta_rad;
  out->chi_rad = result.attitude.chi_rad;
  out->control_deflection_rad = result.attitude.pitch_deflection_rad;
  // The thrust axis is the missile axis m_y the body dynamics resolved with the same sines and
  // cosines: thrust_axis_platform(theta, chi) exactly (its chi = 0 form has a plain 0 and cos theta).
  const Vector3& m_y = result.axes.y;
  const Vector3 axis = (out->chi_rad == 0.0) ? Vector3(0.0, m_y.y(), m_y.z()) : m_y;
  out->thrust_axis_local = platform_to_local * axis;
  return result.forces.local_lbf;
}

// thrust_axis_platform(theta, chi) with theta's (and chi's) sine and cosine kept from the last
// evaluation that flew the same angle (RK4's midpoints, held attitudes, a stage's constant chi).
Vector3 thrust_axis_platform_with_kept_sines(EvaluationScratch* scratch, const Evaluation& out) {
  if (!scratch->has_theta || !(scratch->theta_rad == out.theta_rad)) {
    scratch->has_theta = true;
    scratch->theta_rad = out.theta_rad;
    if (scratch->trig_by_series) {
      const SineCosine theta = scratch->theta_anchor.at(out.theta_rad);
      scratch->sin_theta = theta.sin;
      scratch->cos_theta = theta.cos;
    } else {
      scratch->cos_theta = std::cos(out.theta_rad);
      scratch->sin_theta = std::sin(out.theta_rad);
    }
  }
  if (out.chi_rad == 0.0) return Vector3(0.0, scratch->cos_theta, scratch->sin_theta);
  if (!scratch->has_chi || !(scratch->chi_rad == out.chi_rad)) {
    scratch->has_chi = true;
    scratch->chi_rad = out.chi_rad;
    scratch->cos_chi = std::cos(out.chi_rad);
    scratch->sin_chi = std::sin(out.chi_rad);
  }
  const double ct = scratch->cos_theta;
  return Vector3(ct * scratch->sin_chi, ct * scratch->cos_chi, scratch->sin_theta);
}

// Drag (block 31) and the point-mass lift (block 32); under a wind, their local force components
// along the air frame (returned; zero in still air).
Vector3 drag_and_lift(const Mission& mission, const StageContext& stage, const StepCommand& command,
                      double density_slug_ft3, const AirRelativeFlow& flow, Evaluation* out) {
  const StageData& data = *stage.data;
  EvaluationScratch* scratch = stage.scratch;
  out->drag_lbf = 0.0;
  out->lift_lbf = 0.0;
  Vector3 wind_force_local = Vector3::Zero();  // drag and lift along the air frame (winds only)
  if (!(density_slug_ft3 > 0.0)) return wind_force_local;
  const double q_s = out->dynamic_pressure_lbf_ft2 * data.reference_area_ft2;
  if (!data.drag_coefficient.empty()) {
    out->drag_lbf = q_s * ((scratch != nullptr) ? data.drag_coefficient(out->mach, &scratch->drag_hint)
                                                : data.drag_coefficient(out->mach));
  }
  if (!command.body_dynamics && data.uses_lift_table && !mission.vehicle.lift_curve_slope_per_rad.empty()) {
    // Alpha (an atan2) is needed on the integration path only where there is lift.
    // Under a wind against the air (air_angle_of_attack_rad's axis); by series in dispersion flights.
    const Vector3 axis =
        flow.windy ? thrust_axis_air(flow.local_to_air, out->thrust_axis_local) : out->thrust_axis_local;
    const double alpha = angle_of_attack_rad(axis, scratch != nullptr && scratch->trig_by_series);
    const AeroTable& slope = mission.vehicle.lift_curve_slope_per_rad;
    out->lift_lbf =
        q_s * ((scratch != nullptr) ? slope(out->mach, &scratch->lift_hint) : slope(out->mach)) * alpha;
  }
  if (flow.windy) {
    // Drag against the air-relative velocity, lift along a_z: given to the equations as local
    // force components (the manual's F_j increment, then D = 0).
    wind_force_local = -out->drag_lbf * flow.local_to_air.row(1).transpose() +
                       out->lift_lbf * flow.local_to_air.row(2).transpose();
  }
  return wind_force_local;
}

// The forces the equations of motion take, and their derivative.
void derivative_of(const Constants& constants, const StepCommand& command, const StateVector& state,
                   const StateTrig& trig, const Vector3& body_force_local, const Vector3& wind_force_local,
                   bool windy, Evaluation* out) {
  AppliedForces forces;
  forces.mass_slug = out->weight_lb / constants.g0_ft_s2;
  forces.thrust_local_lbf = out->net_thrust_lbf * out->thrust_axis_local;
  forces.drag_lbf = out->drag_lbf;
  forces.lift_lbf = out->lift_lbf;
  if (command.body_dynamics) {
    // The Sec. 11 forces are added to V-dot, gamma-dot and psi-dot through F_iy / m, F_iz / (m V)
    // and F_ix / (m V cos gamma): exactly where the equations take the local thrust components.
    // They replace the point-mass lift (never counted twice); the reported lift is their i_z part.
    forces.thrust_local_lbf += body_force_local;
    forces.lift_lbf = 0.0;
    out->lift_lbf = body_force_local.z();
  }
  if (windy) {
    forces.thrust_local_lbf += wind_force_local;
    forces.drag_lbf = 0.0;
    forces.lift_lbf = 0.0;
  }
  forces.heading_hold = command.heading_hold;
  out->derivative = state_derivative(constants, state, trig, forces);
}

}  // namespace

void evaluate_flight(const Mission& mission, const PreparedCase& prepared, const StageContext& stage,
                     const StepCommand& command, double t, const StateVector& state, const StateTrig& trig,
                     double weight_offset_lb, Evaluation* out) {
  const double stage_time = t - stage.start_s;
  const double surface_radius = oblate_radius_ft(prepared.oblate_figure, trig.sin_lambda, trig.cos_lambda);
  out->altitude_ft = state[kStateR] - surface_radius;
  const AirAtPoint air = air_at(mission, out->altitude_ft, surface_radius);
  weight_and_thrust(stage, stage_time, air.pressure_lbf_ft2, weight_offset_lb, out);

  // A dispersion flight's point-mass thrust axis is turned from the platform into the local frame
  // rotation by rotation (inertial_to_local_times); the other evaluations form [C] = [A][B][B'].
  EvaluationScratch* scratch = stage.scratch;
  const bool axis_by_rotations = scratch != nullptr && scratch->trig_by_series && !command.body_dynamics &&
                                 command.mode != AttitudeMode::kZeroAlpha;
  Matrix3 platform_to_local;
  if (!axis_by_rotations) platform_to_local = inertial_to_local(trig) * prepared.platform_to_inertial;
  commanded_attitude(command, t, platform_to_local, out);

  const AirRelativeFlow flow = air_relative_flow(stage, state, trig, out->altitude_ft, air.density_slug_ft3);
  out->windy = flow.windy;
  if (flow.windy) out->local_to_air = flow.local_to_air;
  out->density_slug_ft3 = air.density_slug_ft3;
  out->dynamic_pressure_lbf_ft2 = 0.5 * air.density_slug_ft3 * flow.air_speed_ft_s * flow.air_speed_ft_s;
  out->mach = (air.speed_of_sound_ft_s > 0.0) ? flow.air_speed_ft_s / air.speed_of_sound_ft_s : 0.0;
  out->control_deflection_rad = 0.0;
  out->body_status = Status::kOk;

  Vector3 body_force_local = Vector3::Zero();
  if (command.body_dynamics) {
    body_force_local = body_dynamics_attitude(mission, stage, command, stage_time, air.density_slug_ft3,
                                              platform_to_local, flow, out);
  } else if (axis_by_rotations) {
    const Vector3 axis_inertial =
        prepared.platform_to_inertial * thrust_axis_platform_with_kept_sines(scratch, *out);
    out->thrust_axis_local = inertial_to_local_times(trig, axis_inertial);
  } else if (scratch != nullptr) {
    out->thrust_axis_local = platform_to_local * thrust_axis_platform_with_kept_sines(scratch, *out);
  } else {
    out->thrust_axis_local = platform_to_local * thrust_axis_platform(out->theta_rad, out->chi_rad);
  }

  const Vector3 wind_force_local = drag_and_lift(mission, stage, command, air.density_slug_ft3, flow, out);
  derivative_of(mission.constants, command, state, trig, body_force_local, wind_force_local, flow.windy, out);
}

}  // namespace tolip
