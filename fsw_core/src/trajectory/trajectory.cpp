// Forward trajectory: lift-off, then each stage of the sequence with RKAD (Sec. 4, 19, 22).
#include "tolip/trajectory/trajectory.hpp"

#include <cmath>

#include "tolip/dynamics/vertical_flight.hpp"
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

class Flight {
 public:
  Flight(const Mission& mission, const PreparedCase& prepared, const FlightInputs& inputs,
         Trajectory* trajectory)
      : mission_(mission), prepared_(prepared),
        program_(inputs.feedback != nullptr ? inputs.live_program : inputs.program), inputs_(inputs),
        trajectory_(trajectory), sin_launch_latitude_(std::sin(mission.launch.geocentric_latitude_rad)),
        cos_launch_latitude_(std::cos(mission.launch.geocentric_latitude_rad)) {}

  Status run();

 private:
  Status fly_stage(int slot, StateVector* state);
  // The steps of fly_stage: one integration step from point `i` of the stage, the stage's end point.
  struct StageFlight {
    StageContext stage;
    const StageTimeline* line = nullptr;
    int slot = 0;
    bool body_dynamics = false;
    int substeps = 1;                  // DA6D(12-15) in a 6D forward trajectory, else 1
    double last_theta_step_rad = 0.0;  // theta_end - theta_start of the last step flown
    DerivativeHistory<StateVector> history;
    Evaluation eval;
    // The evaluations inside a step, of which only the derivative is read (evaluate_flight() sets
    // it every time): one kept for the stage, since building an Evaluation costs ~2 % of a flight.
    Evaluation step_eval;
    StateTrigAnchor trig_anchor;  // with FlightInputs::trig_by_series: the stage's anchor
  };
  Status fly_step(StageFlight* flight, int i, StateVector* state);
  // StateTrig(state), or with trig_by_series from the stage's anchor.
  StateTrig state_trig(StageFlight* flight, const StateVector& state) const;
  // The angle of the thrust axis (local or air frame): with trig_by_series by series, as flown.
  double alpha_rad(const Vector3& thrust_axis) const {
    return angle_of_attack_rad(thrust_axis, inputs_.trig_by_series);
  }
  void integrate_step(StageFlight* flight, const StepCommand& command, bool adams, double t,
                      StateVector* state) const;
  Status record_stage_end(StageFlight* flight, StageEvent* event, StateVector* state);
  void set_weights_after_jettison(int ended);
  void latch_segments(const StageContext& stage, double t, const StateVector& state);
  StepCommand command_at(const StageContext& stage, int point, double t, double step_s,
                         const StateVector& state);
  void perturb_command(const StageContext& stage, double t, StepCommand* command) const;
  double program_clock_shift_s(const StageContext& stage) const;
  double program_time_s(const StageContext& stage, double t) const;
  double program_theta(int point, double t) const;
  Status record(const StageContext& stage, double t, const StateVector& state, const StateTrig& trig,
                const StepCommand& command, const Evaluation& eval);
  Status record_pad_point();
  Status resume(StateVector* state);

  const Mission& mission_;
  const PreparedCase& prepared_;
  const ControlProgram* program_;  // null: data block 40 table
  const FlightInputs& inputs_;
  Trajectory* trajectory_;
  LatchedSegment latched_;
  bool window_end_latched_ = false;
  // The launch point's, for every point's downrange.
  double sin_launch_latitude_;
  double cos_launch_latitude_;
};

// FlightPerturbation::program_clock_shift_s of the stage: 0 but on a changed burn time (codes 1-8
// about a data block 40 nominal).
double Flight::program_clock_shift_s(const StageContext& stage) const {
  return (inputs_.perturbation != nullptr)
             ? inputs_.perturbation->program_clock_shift_s[stage_index(stage.code)]
             : 0.0;
}

// Flight time t on the program's clock: t less the stage's shift; in stage 1, after the lift-off,
// at stage1_program_clock_rate program seconds per flight second.
double Flight::program_time_s(const StageContext& stage, double t) const {
  const double shift_s = program_clock_shift_s(stage);
  const double rate =
      (inputs_.perturbation != nullptr) ? inputs_.perturbation->stage1_program_clock_rate : 1.0;
  const double liftoff_s = mission_.launch.liftoff_duration_s;
  if (stage.code != 1 || rate == 1.0 || !(t > liftoff_s)) return t - shift_s;
  return liftoff_s + (t - liftoff_s) * rate;  // stage 1 starts at 0 on every flight
}

// `t` on the program's clock (program_time_s).
void Flight::latch_segments(const StageContext& stage, double t, const StateVector& state) {
  const double eps = 0.5 * mission_.constants.time_epsilon_s;
  const bool window_ends = mission_.options.zero_alpha_window() && !window_end_latched_ &&
                           t + eps >= mission_.control.zero_alpha_end_s;
  const bool stage2_ignites = mission_.options.alpha_zero_at_stage2_ignition() && stage.code == 2 &&
                              std::fabs(t - (stage.start_s - program_clock_shift_s(stage))) < eps;
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

// Theta of the pitch program at a point: the per-point control, or the data block 40 table with the
// latched segment.
double Flight::program_theta(int point, double t) const {
  if (program_ != nullptr) return program_->theta_rad[point];
  if (latched_.active && t >= latched_.start_s && t < latched_.end_s) {
    const double fraction = (t - latched_.start_s) / (latched_.end_s - latched_.start_s);
    return latched_.start_theta_rad + fraction * (latched_.end_theta_rad - latched_.start_theta_rad);
  }
  return mission_.pitch_program_rad(t);
}

// The attitude command of the step that starts at `point` (time t, state x), in order of
// precedence: spun stages, lift-off, the zero-alpha window, alpha = 0 at stage-2 ignition, and
// the pitch program. The program, its window and its latched segments are read on the program's
// clock (program_time_s); the lift-off and the heading hold on the flight's.
StepCommand Flight::command_at(const StageContext& stage, int point, double t, double step_s,
                               const StateVector& state) {
  // Step-start times are sums of fixed steps; half of TIMEP (CT1(10)) absorbs their round-off.
  const double eps = 0.5 * mission_.constants.time_epsilon_s;
  const double shift_s = program_clock_shift_s(stage);
  const double tp = program_time_s(stage, t);
  latch_segments(stage, tp, state);
  StepCommand command;
  command.step_start_s = t;
  command.step_s = step_s;
  command.heading_hold = t + eps < mission_.launch.heading_hold_until_s;

  // Spun stages hold the attitudes of data block 17 (IP(9), IP(10): spun_stage_attitude); so do the
  // coasts that follow them.
  if (mission_.options.stage_is_spun(stage.code)) {
    const SpunAttitude held = spun_stage_attitude(mission_.options, mission_.misc, stage.code);
    command.mode = AttitudeMode::kHeld;
    command.theta_start_rad = command.theta_end_rad = held.theta_rad;
    command.chi_rad = held.chi_rad;
    return command;
  }
  if (t + eps < mission_.launch.liftoff_duration_s) {
    command.mode = AttitudeMode::kHeld;
    command.theta_start_rad = command.theta_end_rad = kHalfPi;
    return command;
  }
  if (mission_.options.zero_alpha_window() && tp + eps >= mission_.control.zero_alpha_start_s &&
      tp + eps < mission_.control.zero_alpha_end_s) {
    command.mode = AttitudeMode::kZeroAlpha;
    return command;
  }
  command.mode = AttitudeMode::kLinear;
  command.theta_start_rad = attitude_set_in_flight(mission_, stage.code, stage.start_s - shift_s, tp)
                                ? zero_alpha_theta_rad(prepared_, state)
                                : program_theta(point, tp);
  command.theta_end_rad = program_theta(point + 1, program_time_s(stage, t + step_s));
  return command;
}

// A dispersed trajectory's attitude offsets (FlightPerturbation) on the step's command: not during
// the vertical lift-off nor the zero-alpha window, whose attitudes the flight itself fixes.
void Flight::perturb_command(const StageContext& stage, double t, StepCommand* command) const {
  const FlightPerturbation* perturbation = inputs_.perturbation;
  if (perturbation == nullptr || command->mode == AttitudeMode::kZeroAlpha) return;
  if (t + 0.5 * mission_.constants.time_epsilon_s < mission_.launch.liftoff_duration_s) return;
  const int slot = stage_index(stage.code);
  command->theta_start_rad += perturbation->theta_offset_rad[slot];
  command->theta_end_rad += perturbation->theta_offset_rad[slot];
  command->chi_rad += perturbation->chi_offset_rad[slot];
}

// `trig` is the point's evaluation's StateTrig (StateTrig(state) unless trig_by_series).
Status Flight::record(const StageContext& stage, double t, const StateVector& state, const StateTrig& trig,
                      const StepCommand& command, const Evaluation& eval) {
  if (trajectory_->point_count >= kMaxTrajectoryPoints) return Status::kTrajectoryStorageFull;
  const Constants& constants = mission_.constants;
  TrajectoryPoint& p = trajectory_->points[trajectory_->point_count];
  p.time_s = t;
  p.stage_code = stage.code;
  p.theta_command_rad = static_cast<float>(eval.theta_command_rad);
  p.stage_time_s = t - stage.start_s;
  p.state = state;
  p.altitude_ft = eval.altitude_ft;
  p.earth_longitude_rad = wrap_angle_rad(state[kStateTau] - constants.earth_rotation_rate_rad_s * t);
  p.weight_lb = eval.weight_lb;
  p.vacuum_thrust_lbf = eval.vacuum_thrust_lbf;
  p.net_thrust_lbf = eval.net_thrust_lbf;
  p.dynamic_pressure_lbf_ft2 = eval.dynamic_pressure_lbf_ft2;
  p.mach = eval.mach;
  // A lean point whose air-relative alpha is kept needs no still-air alpha (FlightInputs::lean_points).
  const bool air_alpha_only = inputs_.lean_points && inputs_.air_alpha_rad != nullptr && eval.windy;
  p.alpha_rad = air_alpha_only ? 0.0 : alpha_rad(eval.thrust_axis_local);
  p.theta_rad = eval.theta_rad;
  p.chi_rad = eval.chi_rad;
  p.drag_lbf = eval.drag_lbf;
  p.lift_lbf = eval.lift_lbf;
  p.heading_hold = command.heading_hold;
  p.alpha_zero = command.mode == AttitudeMode::kZeroAlpha;
  p.body_dynamics = command.body_dynamics;
  p.control_deflection_rad = static_cast<float>(eval.control_deflection_rad);
  if (inputs_.air_alpha_rad != nullptr) {
    inputs_.air_alpha_rad[trajectory_->point_count] =
        eval.windy ? alpha_rad(thrust_axis_air(eval.local_to_air, eval.thrust_axis_local)) : p.alpha_rad;
  }
  if (inputs_.lean_points) {
    p.geodetic_latitude_rad = 0.0;
    p.heating_rate_btu_ft2_s = 0.0;
    p.downrange_rad = 0.0;
    p.inertial = InertialVelocity{};
    ++trajectory_->point_count;
    return Status::kOk;
  }
  p.geodetic_latitude_rad = geodetic_from_geocentric_rad(constants, state[kStateLambda]);
  p.heating_rate_btu_ft2_s =
      (mission_.misc.nose_radius_ft > 0.0)
          ? stagnation_heating_rate(mission_.misc.nose_radius_ft, eval.density_slug_ft3,
                                    mission_.atmosphere.base_density_slug_ft3[0], state[kStateV])
          : 0.0;
  // A point's downrange and inertial velocity are of its state alone: with trig_by_series (which
  // lean points skip) from the library's sines of the state, as record_dispersed_trajectory()
  // recomputes the downrange.
  const StateTrig point_trig = inputs_.trig_by_series ? StateTrig(state) : trig;
  p.downrange_rad =
      downrange_angle_rad(sin_launch_latitude_, cos_launch_latitude_, point_trig.sin_lambda,
                          point_trig.cos_lambda, p.earth_longitude_rad - mission_.launch.longitude_rad);
  p.inertial = inertial_velocity(constants, state, point_trig.sin_gamma, point_trig.cos_gamma,
                                 point_trig.sin_psi, point_trig.cos_psi, point_trig.cos_lambda);
  // The heating integral by the trapezoidal rule over the stored points.
  if (trajectory_->point_count > 0) {
    const TrajectoryPoint& previous = trajectory_->points[trajectory_->point_count - 1];
    trajectory_->heat_integral_btu_ft2 +=
        0.5 * (previous.heating_rate_btu_ft2_s + p.heating_rate_btu_ft2_s) * (t - previous.time_s);
  }
  ++trajectory_->point_count;
  return Status::kOk;
}

// FlightInputs::resume_from: the flight before timeline slot resume_stage_slot, copied; *state is
// the state at that stage's start (its first point records it).
Status Flight::resume(StateVector* state) {
  const Trajectory& from = *inputs_.resume_from;
  const int slot = inputs_.resume_stage_slot;
  if (inputs_.feedback != nullptr || inputs_.injection_point >= 0 || inputs_.air_alpha_rad != nullptr) {
    return Status::kResumeInputsIncompatible;
  }
  if (!ok(from.status) || slot <= 0 || slot >= prepared_.stage_count || slot >= from.stage_count ||
      from.stages[slot].code != prepared_.timeline[slot].code) {
    return Status::kResumeStageSlotInvalid;
  }
  const int first_point = from.stages[slot].first_point;
  if (first_point <= 0 || first_point >= from.point_count) return Status::kResumeStageNotRecorded;
  for (int k = 0; k < first_point; ++k) {
    trajectory_->points[k] = from.points[k];
    // The heating integral accumulated exactly as record() does, point after point.
    if (k > 0) {
      const TrajectoryPoint& a = from.points[k - 1];
      const TrajectoryPoint& b = from.points[k];
      trajectory_->heat_integral_btu_ft2 +=
          0.5 * (a.heating_rate_btu_ft2_s + b.heating_rate_btu_ft2_s) * (b.time_s - a.time_s);
    }
  }
  trajectory_->point_count = first_point;
  int steps = 0;
  while (steps < from.step_count && from.steps[steps].point < first_point) {
    trajectory_->steps[steps] = from.steps[steps];
    ++steps;
  }
  trajectory_->step_count = steps;
  for (int k = 0; k < slot; ++k) trajectory_->stages[k] = from.stages[k];
  trajectory_->stage_count = slot;
  *state = from.points[first_point].state;
  return Status::kOk;
}

Status Flight::record_pad_point() {
  // At the pad V = 0 and the equations of motion are singular; the point is filled directly.
  const StateVector& pad = prepared_.pad_state;
  const StageContext stage1 = make_stage_context(mission_, prepared_, prepared_.timeline[0]);
  LiftoffResult liftoff;
  const Status status = closed_form_liftoff(mission_, prepared_, &liftoff);
  if (!ok(status)) return status;
  Evaluation eval;
  eval.altitude_ft = mission_.launch.altitude_ft;
  eval.weight_lb = vehicle_weight_lb(mission_.vehicle, 1, 0.0);
  eval.vacuum_thrust_lbf = (*stage1.thrust)(0.0);
  eval.net_thrust_lbf =
      eval.vacuum_thrust_lbf - liftoff.pad_pressure_lbf_ft2 * stage1.data->nozzle_exit_area_ft2;
  eval.theta_rad = kHalfPi;
  eval.theta_command_rad = kHalfPi;
  StepCommand command;
  command.mode = AttitudeMode::kHeld;
  command.theta_start_rad = command.theta_end_rad = kHalfPi;
  command.heading_hold = mission_.launch.heading_hold_until_s > 0.0;
  return record(stage1, 0.0, pad, StateTrig(pad), command, eval);
}

Status Flight::fly_stage(int slot, StateVector* state) {
  StageFlight flight;
  const StageTimeline& line = prepared_.timeline[slot];
  flight.line = &line;
  flight.slot = slot;
  flight.stage = make_stage_context(mission_, prepared_, line);
  flight.stage.perturbation = inputs_.perturbation;
  EvaluationScratch scratch;
  scratch.trig_by_series = inputs_.trig_by_series;
  flight.stage.scratch = &scratch;
  // Body dynamics act in stage 1 and the coast after it only (Sec. 11).
  flight.body_dynamics = inputs_.body_dynamics && (line.code == 1 || line.code == 6);
  flight.substeps = integration_substeps(mission_.body_dynamics, line.code, inputs_.body_dynamics);

  StageEvent& event = trajectory_->stages[trajectory_->stage_count];
  event.code = line.code;
  event.first_point = trajectory_->point_count;
  event.completed = false;
  for (int i = 0; i < line.steps; ++i) {
    const Status status = fly_step(&flight, i, state);
    if (!ok(status)) return status;
  }
  return record_stage_end(&flight, &event, state);
}

// Records point `i` of the stage (its command and evaluation) and integrates the step from it.
Status Flight::fly_step(StageFlight* flight, int i, StateVector* state) {
  const StageTimeline& line = *flight->line;
  const StageContext& stage = flight->stage;
  Evaluation& eval = flight->eval;
  const double t = line.start_s + line.first_step_stage_time_s + i * line.step_s;
  const int point = trajectory_->point_count;
  if (point == inputs_.injection_point) *state += inputs_.injection;
  if (inputs_.feedback != nullptr) inputs_.feedback->at_point(point, *state, inputs_.live_program);
  StepCommand command = command_at(stage, point, t, line.step_s, *state);
  perturb_command(stage, t, &command);
  command.body_dynamics = flight->body_dynamics;
  const StateTrig trig = state_trig(flight, *state);
  evaluate_flight(mission_, prepared_, stage, command, t, *state, trig, 0.0, &eval);
  if (!eval.derivative.allFinite()) return Status::kNonFiniteState;  // nothing NaN is stored
  const Status status = record(stage, t, *state, trig, command, eval);
  if (!ok(status)) return status;
  if (eval.altitude_ft < kImpactAltitudeFt) return Status::kAltitudeBelowSurface;
  if (!ok(eval.body_status)) return eval.body_status;
  flight->last_theta_step_rad =
      (command.mode == AttitudeMode::kLinear) ? command.theta_end_rad - command.theta_start_rad : 0.0;

  StepRecord& step = trajectory_->steps[trajectory_->step_count++];
  step.point = point;
  step.stage_slot = flight->slot;
  // Substeps (DA6D(12-15)) are RK4 throughout: Adams-Bashforth would need a history at the substep.
  step.adams = stage.thrust == nullptr && i >= kRkadStartSteps && flight->substeps == 1;
  // Near the vertical a deck without the heading hold (the manual's decks) integrates the step in
  // regular coordinates; with the hold the steps are the reference oracle's, bit for bit.
  command.vertical_flight =
      !step.adams && !(mission_.launch.heading_hold_until_s > 0.0) && starts_near_vertical(*state);
  step.command = command;
  integrate_step(flight, command, step.adams, t, state);
  flight->history.push(eval.derivative);
  if (!state->allFinite()) return Status::kNonFiniteState;
  return Status::kOk;
}

StateTrig Flight::state_trig(StageFlight* flight, const StateVector& state) const {
  return inputs_.trig_by_series ? flight->trig_anchor.at(state) : StateTrig(state);
}

// RK4 (in vertical-flight coordinates near the vertical) or, in coasts after the start steps,
// Adams-Bashforth from the derivative history. A 6D forward trajectory with DA6D(12-15) = m > 1
// takes m RK4 substeps of step / m (the step's command, its linear theta_c over the whole step,
// serves every substep; the vertical-flight choice and heading reference are the step's).
void Flight::integrate_step(StageFlight* stage_flight, const StepCommand& command, bool adams, double t,
                            StateVector* state) const {
  const StageFlight& flight = *stage_flight;
  const StageTimeline& line = *flight.line;
  const StateVector& start_derivative = flight.eval.derivative;
  const double heading_reference_rad = (*state)[kStatePsi];
  const auto derivative = [&](double time, const StateVector& x) {
    Evaluation& e = stage_flight->step_eval;
    evaluate_flight(mission_, prepared_, flight.stage, command, time, x, state_trig(stage_flight, x), 0.0,
                    &e);
    return e.derivative;
  };
  const auto vertical = [&](double time, const StateVector& y) {
    const StateVector x = from_vertical_coordinates(y, heading_reference_rad);
    return vertical_derivative(x, derivative(time, x));
  };
  if (flight.substeps > 1) {
    const double h = line.step_s / flight.substeps;
    StateVector f0 = start_derivative;
    for (int j = 0; j < flight.substeps; ++j) {
      const double tj = t + j * h;
      if (j > 0) f0 = derivative(tj, *state);
      if (command.vertical_flight) {
        const StateVector y1 = runge_kutta4_step(vertical, tj, to_vertical_coordinates(*state),
                                                 vertical_derivative(*state, f0), h);
        *state = from_vertical_coordinates(y1, heading_reference_rad);
      } else {
        *state = runge_kutta4_step(derivative, tj, *state, f0, h);
      }
    }
  } else if (command.vertical_flight) {
    const StateVector y1 = runge_kutta4_step(vertical, t, to_vertical_coordinates(*state),
                                             vertical_derivative(*state, start_derivative), line.step_s);
    *state = from_vertical_coordinates(y1, heading_reference_rad);
  } else if (!adams) {
    *state = runge_kutta4_step(derivative, t, *state, start_derivative, line.step_s);
  } else {
    *state = adams_bashforth4_step(*state, start_derivative, flight.history.back(0), flight.history.back(1),
                                   flight.history.back(2), line.step_s);
  }
}

// The stage's end point, with its burnout values (the next stage records the same state again
// with its own weight and thrust). Its attitude is the one a step starting there would fly.
Status Flight::record_stage_end(StageFlight* flight, StageEvent* event, StateVector* state) {
  const StageTimeline& line = *flight->line;
  const StageContext& stage = flight->stage;
  Evaluation& eval = flight->eval;
  const double t_end = line.start_s + line.duration_s;
  // With body dynamics the end point keeps the rate of the last step flown, so its steady-state
  // attitude is the one the last step ended with.
  StepCommand command = command_at(stage, trajectory_->point_count, t_end, line.step_s, *state);
  perturb_command(stage, t_end, &command);
  if (command.mode == AttitudeMode::kLinear) {
    command.theta_end_rad = flight->body_dynamics ? command.theta_start_rad + flight->last_theta_step_rad
                                                  : command.theta_start_rad;
  }
  command.body_dynamics = flight->body_dynamics;
  const StateTrig trig = state_trig(flight, *state);
  evaluate_flight(mission_, prepared_, stage, command, t_end, *state, trig, 0.0, &eval);
  if (!eval.derivative.allFinite()) return Status::kNonFiniteState;
  const Status status = record(stage, t_end, *state, trig, command, eval);
  if (!ok(status)) return status;
  if (eval.altitude_ft < kImpactAltitudeFt) return Status::kAltitudeBelowSurface;
  if (!ok(eval.body_status)) return eval.body_status;
  event->last_point = trajectory_->point_count - 1;
  event->burnout_weight_lb = eval.weight_lb;
  event->completed = true;
  ++trajectory_->stage_count;
  return Status::kOk;
}

Status Flight::run() {
  trajectory_->point_count = 0;
  trajectory_->step_count = 0;
  trajectory_->stage_count = 0;
  trajectory_->heat_integral_btu_ft2 = 0.0;
  if (!prepared_.prepared) return Status::kNotPrepared;
  if (inputs_.feedback != nullptr && inputs_.live_program == nullptr) {
    return Status::kFeedbackWithoutLiveProgram;
  }
  if (program_ != nullptr && program_->point_count != trajectory_point_count(prepared_)) {
    return Status::kControlProgramSizeMismatch;
  }
  if (inputs_.body_dynamics) {
    MissionFault fault;
    const Status body = validate_body_dynamics(mission_, &fault);
    if (!ok(body)) return body;
  }

  StateVector state;
  int first_slot = 0;
  Status status = Status::kOk;
  if (inputs_.resume_from != nullptr) {
    status = resume(&state);
    if (!ok(status)) return status;
    first_slot = inputs_.resume_stage_slot;
  } else {
    status = record_pad_point();
    if (!ok(status)) return status;
    LiftoffResult liftoff;
    status = closed_form_liftoff(mission_, prepared_, &liftoff);
    if (!ok(status)) return status;
    state = liftoff.state_at_end;
  }

  for (int k = first_slot; k < prepared_.stage_count; ++k) {
    status = fly_stage(k, &state);
    if (!ok(status)) {
      // The stages that ended before the failure jettisoned as on a successful run.
      set_weights_after_jettison(trajectory_->stage_count);
      // Keep the stage that failed as an event over the points it did fly: it never ended, so it
      // jettisoned nothing (its "burnout" weight is the weight at the last point flown).
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
  set_weights_after_jettison(trajectory_->stage_count);
  return Status::kOk;
}

// Weight after the jettison of each of the first `ended` stage events: the next stage's first
// weight (the last stage of the flight keeps its burnout weight less its jettison weight).
void Flight::set_weights_after_jettison(int ended) {
  for (int k = 0; k < ended; ++k) {
    StageEvent& event = trajectory_->stages[k];
    event.weight_after_jettison_lb =
        (k + 1 < trajectory_->stage_count)
            ? trajectory_->points[trajectory_->stages[k + 1].first_point].weight_lb
            : event.burnout_weight_lb - mission_.vehicle.stages[stage_index(event.code)].jettison_weight_lb;
  }
}

}  // namespace

Status fly_trajectory(const Mission& mission, const PreparedCase& prepared, const FlightInputs& inputs,
                      Trajectory* trajectory) {
  Flight flight(mission, prepared, inputs, trajectory);
  trajectory->status = flight.run();
  return trajectory->status;
}

Status fly_trajectory(const Mission& mission, const PreparedCase& prepared, Trajectory* trajectory) {
  return fly_trajectory(mission, prepared, FlightInputs{}, trajectory);
}

Status fly_trajectory(const Mission& mission, const PreparedCase& prepared, const ControlProgram& program,
                      Trajectory* trajectory) {
  FlightInputs inputs;
  inputs.program = &program;
  return fly_trajectory(mission, prepared, inputs, trajectory);
}

int trajectory_point_count(const PreparedCase& prepared) {
  int count = 1;
  for (int k = 0; k < prepared.stage_count; ++k) count += prepared.timeline[k].steps + 1;
  return count;
}

}  // namespace tolip
