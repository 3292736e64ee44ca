// Forward trajectory: lift-off, then each stage of the sequence with RKAD (Sec. 4, 19, 22).
#include "tolip/trajectory/trajectory.hpp"

#include <cmath>

#include "tolip/atmosphere/atmosphere.hpp"
#include "tolip/dynamics/equations_of_motion.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/frames/frames.hpp"
#include "tolip/integrator/rkad.hpp"
#include "tolip/trajectory/liftoff.hpp"

namespace tolip {
namespace {

constexpr double kHalfPi = 0.5 * kPi;
// Lowest altitude accepted before the run is declared an impact (the pad itself is at ~0 ft).
constexpr double kImpactAltitudeFt = -1000.0;

// A linear pitch segment whose start value is decided in flight: the attitude flown at the end of
// the zero-alpha window (IP(11)), or the alpha = 0 attitude at stage-2 ignition (IP(12)). It runs
// to the next node of the data block 40 table, where the table takes over again.
struct LatchedSegment {
  bool active = false;
  double start_s = 0.0;
  double start_theta_rad = 0.0;
  double end_s = 0.0;
  double end_theta_rad = 0.0;
};

// Controls held over one integration step.
struct StepControls {
  bool heading_hold = false;
  bool alpha_zero = false;
};

// The stage being flown.
struct StageContext {
  int code = 0;
  double start_s = 0.0;  // time from launch at stage time 0
  const StageData* data = nullptr;
  const ModifiedThrustTable* thrust = nullptr;  // null in coasts
  // Jettison weights of this and later stages, payload and later stages' consumables: the vehicle
  // weight is this plus the stage's own consumable weight remaining.
  double weight_above_consumable_lb = 0.0;
};

// Everything the equations of motion saw at one evaluation.
struct Evaluation {
  StateVector derivative = StateVector::Zero();
  double altitude_ft = 0.0;
  double weight_lb = 0.0;
  double vacuum_thrust_lbf = 0.0;
  double net_thrust_lbf = 0.0;
  double dynamic_pressure_lbf_ft2 = 0.0;
  double density_slug_ft3 = 0.0;
  double mach = 0.0;
  Vector3 thrust_axis_local = Vector3(0.0, 1.0, 0.0);
  double theta_rad = 0.0;
  double chi_rad = 0.0;
  double drag_lbf = 0.0;
  double lift_lbf = 0.0;
};

double powered_consumable_at_ignition(const Vehicle& vehicle, int code) {
  return is_powered_stage(code) ? vehicle.stages[stage_index(code)].consumable_weight_lb(0.0) : 0.0;
}

class Flight {
 public:
  Flight(const Mission& mission, const PreparedCase& prepared, Trajectory* trajectory)
      : mission_(mission), prepared_(prepared), trajectory_(trajectory) {}

  Status run();

 private:
  Status fly_stage(const StageTimeline& line, StateVector* state);
  void latch_segments(const StageContext& stage, double t, const StateVector& state);
  StepControls controls_at(double t) const;
  double commanded_theta(const StageContext& stage, double t, const StepControls& controls,
                         const Matrix3& platform_to_local, double* chi_rad) const;
  void evaluate(const StageContext& stage, double t, const StateVector& state,
                const StepControls& controls, Evaluation* out) const;
  Status record(const StageContext& stage, double t, const StateVector& state,
                const StepControls& controls, const Evaluation& eval);
  Status record_pad_point();

  const Mission& mission_;
  const PreparedCase& prepared_;
  Trajectory* trajectory_;
  LatchedSegment latched_;
  bool window_end_latched_ = false;
};

StepControls Flight::controls_at(double t) const {
  // Step-start times are sums of fixed steps; half of TIMEP (CT1(10)) absorbs their round-off.
  const double eps = 0.5 * mission_.constants.time_epsilon_s;
  StepControls controls;
  controls.heading_hold = t + eps < mission_.launch.heading_hold_until_s;
  controls.alpha_zero = mission_.options.zero_alpha_window() &&
                        t + eps >= mission_.control.zero_alpha_start_s &&
                        t + eps < mission_.control.zero_alpha_end_s;
  return controls;
}

void Flight::latch_segments(const StageContext& stage, double t, const StateVector& state) {
  const double eps = 0.5 * mission_.constants.time_epsilon_s;
  const bool window_ends = mission_.options.zero_alpha_window() && !window_end_latched_ &&
                           t + eps >= mission_.control.zero_alpha_end_s;
  const bool stage2_ignites = mission_.options.alpha_zero_at_stage2_ignition() && stage.code == 2 &&
                              std::fabs(t - stage.start_s) < eps;
  if (!window_ends && !stage2_ignites) return;
  if (window_ends) window_end_latched_ = true;

  const Matrix3 platform_to_local = inertial_to_local(state) * prepared_.platform_to_inertial;
  const PitchTable& table = mission_.pitch_program_rad;
  latched_.active = false;
  for (int i = 0; i < table.size(); ++i) {
    if (table.x(i) > t + eps) {
      latched_.active = true;
      latched_.start_s = t;
      latched_.start_theta_rad = theta_for_zero_alpha_rad(platform_to_local, 0.0);
      latched_.end_s = table.x(i);
      latched_.end_theta_rad = table.y(i);
      return;
    }
  }
}

double Flight::commanded_theta(const StageContext& stage, double t, const StepControls& controls,
                               const Matrix3& platform_to_local, double* chi_rad) const {
  *chi_rad = 0.0;
  const MiscellaneousData& misc = mission_.misc;
  const int spin = mission_.options.spin_stages_4_5();
  // Spun stages hold the attitudes of data block 17 (IP(9)); so do the coasts that follow them.
  if ((stage.code == 4 || stage.code == 9) && spin == 1) {
    *chi_rad = misc.stage4_chi_rad;
    return misc.stage4_theta_rad;
  }
  if ((stage.code == 5 || stage.code == 10) && (spin == 1 || spin == 2)) {
    const bool coupled = spin == 1;
    *chi_rad = coupled ? misc.stage4_chi_rad : misc.stage5_chi_rad;
    return coupled ? misc.stage4_theta_rad : misc.stage5_theta_rad;
  }
  if (t < mission_.launch.liftoff_duration_s) return kHalfPi;
  if (controls.alpha_zero) return theta_for_zero_alpha_rad(platform_to_local, 0.0);
  if (latched_.active && t >= latched_.start_s && t < latched_.end_s) {
    const double fraction = (t - latched_.start_s) / (latched_.end_s - latched_.start_s);
    return latched_.start_theta_rad + fraction * (latched_.end_theta_rad - latched_.start_theta_rad);
  }
  return mission_.pitch_program_rad(t);
}

void Flight::evaluate(const StageContext& stage, double t, const StateVector& state,
                      const StepControls& controls, Evaluation* out) const {
  const Constants& constants = mission_.constants;
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
    if (ok(evaluate_atmosphere(mission_.atmosphere, constants, out->altitude_ft, surface_radius, &air))) {
      pressure = air.pressure_lbf_ft2;
      density = air.density_slug_ft3;
      speed_of_sound = air.speed_of_sound_ft_s;
    }
  }

  out->weight_lb = stage.weight_above_consumable_lb +
                   (is_powered_stage(stage.code) ? data.consumable_weight_lb(stage_time) : 0.0);
  out->vacuum_thrust_lbf = (stage.thrust != nullptr) ? (*stage.thrust)(stage_time) : 0.0;
  out->net_thrust_lbf =
      (stage.thrust != nullptr) ? out->vacuum_thrust_lbf - pressure * data.nozzle_exit_area_ft2 : 0.0;

  const Matrix3 platform_to_local = inertial_to_local(trig) * prepared_.platform_to_inertial;
  out->theta_rad = commanded_theta(stage, t, controls, platform_to_local, &out->chi_rad);
  out->thrust_axis_local = platform_to_local * thrust_axis_platform(out->theta_rad, out->chi_rad);

  out->density_slug_ft3 = density;
  out->dynamic_pressure_lbf_ft2 = 0.5 * density * v * v;
  out->mach = (speed_of_sound > 0.0) ? v / speed_of_sound : 0.0;
  out->drag_lbf = 0.0;
  out->lift_lbf = 0.0;
  if (density > 0.0) {
    const double q_s = out->dynamic_pressure_lbf_ft2 * data.reference_area_ft2;
    if (!data.drag_coefficient.empty()) out->drag_lbf = q_s * data.drag_coefficient(out->mach);
    if (data.uses_lift_table && !mission_.vehicle.lift_curve_slope_per_rad.empty()) {
      // Alpha (an atan2) is needed on the integration path only where there is lift.
      out->lift_lbf = q_s * mission_.vehicle.lift_curve_slope_per_rad(out->mach) *
                      angle_of_attack_rad(out->thrust_axis_local);
    }
  }

  AppliedForces forces;
  forces.mass_slug = out->weight_lb / constants.g0_ft_s2;
  forces.thrust_local_lbf = out->net_thrust_lbf * out->thrust_axis_local;
  forces.drag_lbf = out->drag_lbf;
  forces.lift_lbf = out->lift_lbf;
  forces.heading_hold = controls.heading_hold;
  out->derivative = state_derivative(constants, state, trig, forces);
}

Status Flight::record(const StageContext& stage, double t, const StateVector& state,
                      const StepControls& controls, const Evaluation& eval) {
  if (trajectory_->point_count >= kMaxTrajectoryPoints) return Status::kTrajectoryStorageFull;
  const Constants& constants = mission_.constants;
  TrajectoryPoint& p = trajectory_->points[trajectory_->point_count];
  p.time_s = t;
  p.stage_code = stage.code;
  p.stage_time_s = t - stage.start_s;
  p.state = state;
  p.altitude_ft = eval.altitude_ft;
  p.earth_longitude_rad =
      std::remainder(state[kStateTau] - constants.earth_rotation_rate_rad_s * t, 2.0 * kPi);
  p.geodetic_latitude_rad = geodetic_from_geocentric_rad(state[kStateLambda]);
  p.weight_lb = eval.weight_lb;
  p.vacuum_thrust_lbf = eval.vacuum_thrust_lbf;
  p.net_thrust_lbf = eval.net_thrust_lbf;
  p.dynamic_pressure_lbf_ft2 = eval.dynamic_pressure_lbf_ft2;
  p.mach = eval.mach;
  p.alpha_rad = angle_of_attack_rad(eval.thrust_axis_local);
  p.theta_rad = eval.theta_rad;
  p.chi_rad = eval.chi_rad;
  p.drag_lbf = eval.drag_lbf;
  p.lift_lbf = eval.lift_lbf;
  p.heating_rate_btu_ft2_s =
      (mission_.misc.nose_radius_ft > 0.0)
          ? stagnation_heating_rate(mission_.misc.nose_radius_ft, eval.density_slug_ft3,
                                    mission_.atmosphere.base_density_slug_ft3[0], state[kStateV])
          : 0.0;
  p.downrange_rad = downrange_angle_rad(mission_.launch.geocentric_latitude_rad,
                                        mission_.launch.longitude_rad, state[kStateLambda],
                                        p.earth_longitude_rad);
  p.inertial = inertial_velocity(constants, state);
  p.heading_hold = controls.heading_hold;
  p.alpha_zero = controls.alpha_zero;
  // The heating integral by the trapezoidal rule over the stored points.
  if (trajectory_->point_count > 0) {
    const TrajectoryPoint& previous = trajectory_->points[trajectory_->point_count - 1];
    trajectory_->heat_integral_btu_ft2 +=
        0.5 * (previous.heating_rate_btu_ft2_s + p.heating_rate_btu_ft2_s) * (t - previous.time_s);
  }
  ++trajectory_->point_count;
  return Status::kOk;
}

Status Flight::record_pad_point() {
  // At the pad V = 0 and the equations of motion are singular; the point is filled directly.
  const StateVector& pad = prepared_.pad_state;
  StageContext stage1;
  stage1.code = 1;
  stage1.data = &mission_.vehicle.stages[stage_index(1)];
  stage1.thrust = &prepared_.modified_thrust_lbf[stage_index(1)];
  LiftoffResult liftoff;
  const Status status = closed_form_liftoff(mission_, prepared_, &liftoff);
  if (!ok(status)) return status;
  Evaluation eval;
  eval.altitude_ft = mission_.launch.altitude_ft;
  eval.weight_lb = vehicle_weight_lb(mission_.vehicle, 1, 0.0);
  eval.vacuum_thrust_lbf = (*stage1.thrust)(0.0);
  eval.net_thrust_lbf = eval.vacuum_thrust_lbf - liftoff.pad_pressure_lbf_ft2 * stage1.data->nozzle_exit_area_ft2;
  eval.theta_rad = kHalfPi;
  StepControls controls = controls_at(0.0);
  return record(stage1, 0.0, pad, controls, eval);
}

Status Flight::fly_stage(const StageTimeline& line, StateVector* state) {
  StageContext stage;
  stage.code = line.code;
  stage.start_s = line.start_s;
  stage.data = &mission_.vehicle.stages[stage_index(line.code)];
  stage.thrust = is_powered_stage(line.code) ? &prepared_.modified_thrust_lbf[stage_index(line.code)]
                                             : nullptr;
  stage.weight_above_consumable_lb =
      vehicle_weight_lb(mission_.vehicle, line.code, 0.0) -
      (powered_consumable_at_ignition(mission_.vehicle, line.code));
  const bool powered = stage.thrust != nullptr;

  StageEvent& event = trajectory_->stages[trajectory_->stage_count];
  event.code = line.code;
  event.first_point = trajectory_->point_count;

  DerivativeHistory<StateVector> history;
  Evaluation eval;
  for (int i = 0; i < line.steps; ++i) {
    const double t = line.start_s + line.first_step_stage_time_s + i * line.step_s;
    latch_segments(stage, t, *state);
    const StepControls controls = controls_at(t);
    evaluate(stage, t, *state, controls, &eval);
    if (!eval.derivative.allFinite()) return Status::kNonFiniteState;  // nothing NaN is stored
    Status status = record(stage, t, *state, controls, eval);
    if (!ok(status)) return status;
    if (eval.altitude_ft < kImpactAltitudeFt) return Status::kAltitudeBelowSurface;

    const auto derivative = [&](double time, const StateVector& x) {
      Evaluation e;
      evaluate(stage, time, x, controls, &e);
      return e.derivative;
    };
    if (powered || i < kRkadStartSteps) {
      *state = runge_kutta4_step(derivative, t, *state, eval.derivative, line.step_s);
    } else {
      *state = adams_bashforth4_step(*state, eval.derivative, history.back(0), history.back(1),
                                     history.back(2), line.step_s);
    }
    history.push(eval.derivative);

    if (!state->allFinite()) return Status::kNonFiniteState;
  }

  // The stage's end point, with its burnout values (the next stage records the same state again
  // with its own weight and thrust).
  const double t_end = line.start_s + line.duration_s;
  latch_segments(stage, t_end, *state);
  const StepControls controls = controls_at(t_end);
  evaluate(stage, t_end, *state, controls, &eval);
  if (!eval.derivative.allFinite()) return Status::kNonFiniteState;
  const Status status = record(stage, t_end, *state, controls, eval);
  if (!ok(status)) return status;
  if (eval.altitude_ft < kImpactAltitudeFt) return Status::kAltitudeBelowSurface;
  event.last_point = trajectory_->point_count - 1;
  event.burnout_weight_lb = eval.weight_lb;
  ++trajectory_->stage_count;
  return Status::kOk;
}

Status Flight::run() {
  trajectory_->point_count = 0;
  trajectory_->stage_count = 0;
  trajectory_->heat_integral_btu_ft2 = 0.0;
  if (!prepared_.prepared) return Status::kNotPrepared;

  Status status = record_pad_point();
  if (!ok(status)) return status;
  LiftoffResult liftoff;
  status = closed_form_liftoff(mission_, prepared_, &liftoff);
  if (!ok(status)) return status;
  StateVector state = liftoff.state_at_end;

  for (int k = 0; k < prepared_.stage_count; ++k) {
    status = fly_stage(prepared_.timeline[k], &state);
    if (!ok(status)) {
      // Keep the stage that failed as an event over the points it did fly.
      StageEvent& event = trajectory_->stages[trajectory_->stage_count];
      if (trajectory_->point_count > event.first_point) {
        event.last_point = trajectory_->point_count - 1;
        event.burnout_weight_lb = trajectory_->points[event.last_point].weight_lb;
        event.weight_after_jettison_lb = event.burnout_weight_lb;
        ++trajectory_->stage_count;
      }
      return status;
    }
  }
  // Weight after each jettison: the next stage's first weight (the last stage keeps its own).
  for (int k = 0; k < trajectory_->stage_count; ++k) {
    StageEvent& event = trajectory_->stages[k];
    event.weight_after_jettison_lb =
        (k + 1 < trajectory_->stage_count)
            ? trajectory_->points[trajectory_->stages[k + 1].first_point].weight_lb
            : event.burnout_weight_lb - mission_.vehicle.stages[stage_index(event.code)].jettison_weight_lb;
  }
  return Status::kOk;
}

}  // namespace

Status fly_trajectory(const Mission& mission, const PreparedCase& prepared, Trajectory* trajectory) {
  Flight flight(mission, prepared, trajectory);
  trajectory->status = flight.run();
  return trajectory->status;
}

bool is_output_point(const Mission& mission, const Trajectory& trajectory, int index,
                     TrajectoryKind kind) {
  for (int k = 0; k < trajectory.stage_count; ++k) {
    const StageEvent& event = trajectory.stages[k];
    if (index < event.first_point || index > event.last_point) continue;
    if (index == event.first_point || index == event.last_point) return true;
    const int slot = stage_index(event.code);
    int every = 1;
    switch (kind) {
      case TrajectoryKind::kInitial: every = mission.output.initial[slot]; break;
      case TrajectoryKind::kIntermediate: every = mission.output.intermediate[slot]; break;
      case TrajectoryKind::kFinal: every = mission.output.final_trajectory[slot]; break;
    }
    return every <= 1 || (index - event.first_point) % every == 0;
  }
  return index == 0;  // the pad point
}

}  // namespace tolip
