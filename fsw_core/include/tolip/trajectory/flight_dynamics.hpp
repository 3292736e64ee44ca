// The right-hand side the integrator sees: one evaluation of the point-mass model (Sec. 4) for a
// stage, a step's attitude command and a state, with everything it computed on the way (weight,
// thrust, atmosphere, aerodynamics, attitude). Forward runs and the optimizer's backward runs call
// the same function, so the adjoint linearizes exactly what was flown.
#pragma once

#include "tolip/body/body_dynamics.hpp"
#include "tolip/core/state.hpp"
#include "tolip/core/status.hpp"
#include "tolip/frames/frames.hpp"
#include "tolip/mission/mission.hpp"
#include "tolip/trajectory/wind.hpp"
#include "tolip/vehicle/prepared_case.hpp"

namespace tolip {

// What a dispersed trajectory (manual Sec. 15; tolip/dispersion/dispersion.hpp) changes in the
// flight besides the Mission's data: attitude offsets per stage (control deadbands, tip-off,
// launch attitude), a wind profile, and the stage-1 thrust misalignment of the body dynamics.
// Absent (null in FlightInputs / StageContext) on every nominal run, which is then unchanged bit
// for bit.
struct FlightPerturbation {
  // Added to the commanded theta / chi of every step of the stage (by stage_index(code)), except
  // during the vertical lift-off and the zero-alpha window, whose attitudes are fixed by the flight.
  double theta_offset_rad[kMaxStages] = {};
  double chi_offset_rad[kMaxStages] = {};
  const WindProfile* wind = nullptr;  // blocks 53-54; null: still air
  // Block 49: stage 1 only, with body dynamics (BodyDynamicsInputs).
  double misalignment_pitch_rad = 0.0;
  double misalignment_yaw_rad = 0.0;
  double thrust_station_ft = 0.0;
  // Codes 1-8 about a data block 40 nominal (set_program_clock_shifts): the table, its zero-alpha
  // window (IP(11)) and its latched segments (IP(11), IP(12)) are read on a program clock, not at
  // the flight time t. A stage's clock starts at the nominal's start of the stage: t less
  // program_clock_shift_s (its start on this flight minus its start on the nominal); stage 1's runs,
  // after the lift-off, at stage1_program_clock_rate program seconds per flight second (the
  // nominal's step over this flight's). The defaults, 0 and 1, are the flight time itself.
  double program_clock_shift_s[kMaxStages] = {};
  double stage1_program_clock_rate = 1.0;
};

// A flight's memo for evaluate_flight: the interval each table look-up found last (the next
// evaluation's stage time and Mach usually fall in the same one: Table's hinted look-up) and the
// sine and cosine of the last pitch attitude of a held or linear command (RK4's two midpoint
// evaluations fly the same theta). Owned by one flight and never shared between threads; it only
// spares work: every evaluation is the one computed without it, bit for bit.
struct EvaluationScratch {
  int thrust_hint = -1;
  int weight_hint = -1;
  int drag_hint = -1;
  int lift_hint = -1;
  int wind_speed_hint = -1;  // a dispersed flight's wind tables (by altitude)
  int wind_azimuth_hint = -1;
  BodyDynamicsHints body_hints;  // the 6D unit moments' tables
  bool has_theta = false;
  double theta_rad = 0.0;
  double sin_theta = 0.0;
  double cos_theta = 0.0;
  // The same for a non-zero yaw attitude (chi of a deadband, tip-off or spun stage: constant over
  // the stage), so thrust_axis_platform(theta, chi) is formed from kept sines and cosines.
  bool has_chi = false;
  double chi_rad = 0.0;
  double sin_chi = 0.0;
  double cos_chi = 0.0;
  // A dispersion flight's (FlightInputs::trig_by_series): theta's sine and cosine by the addition
  // theorem from an anchor the library evaluated, moved when theta is 1/16 rad or more from it;
  // the angles of attack and the body dynamics' small angles by atan2_by_series; the wind's
  // azimuth relative to psi (psi_w - psi) by the addition theorem from an anchor of its own.
  bool trig_by_series = false;
  SineCosineAnchor theta_anchor;
  SineCosineAnchor wind_azimuth_anchor;
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
  const FlightPerturbation* perturbation = nullptr;  // dispersed trajectories only
  EvaluationScratch* scratch = nullptr;              // null: every look-up searched afresh
};

StageContext make_stage_context(const Mission& mission, const PreparedCase& prepared,
                                const StageTimeline& line);

// How the attitude is decided during one integration step.
enum class AttitudeMode : int {
  kHeld,       // constant theta and chi: vertical lift-off, spun stages
  kZeroAlpha,  // theta re-solved at every evaluation so that the in-plane alpha is 0 (IP(11))
  kLinear,     // theta linear in time from theta_start (step start) to theta_end (step end)
};

struct StepCommand {
  AttitudeMode mode = AttitudeMode::kLinear;
  double theta_start_rad = 0.0;
  double theta_end_rad = 0.0;
  double chi_rad = 0.0;
  double step_start_s = 0.0;  // time from launch
  double step_s = 1.0;
  bool heading_hold = false;  // dpsi/dt held at 0
  // The step starts within 5 deg of the vertical and is integrated in the regular coordinates of
  // tolip/dynamics/vertical_flight.hpp, with the psi of its first point as the heading reference
  // (a Runge-Kutta step of a deck without the heading hold). Set by fly_trajectory(); no effect on
  // evaluate_flight.
  bool vertical_flight = false;
  // Body dynamics (6D, Sec. 7, 11): the attitude above is the autopilot's command theta_c (its rate
  // theta_c-dot the step's (theta_end - theta_start) / step_s; 0 when held or zero-alpha); the
  // flown attitude is the steady state of eqs. 7-6/7-7 and the Sec. 11 normal forces replace the
  // point-mass lift. Set by fly_trajectory() in stage 1 and the following coast of a 6D run.
  bool body_dynamics = false;
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
  double theta_rad = 0.0;          // flown
  double chi_rad = 0.0;            // flown
  double theta_command_rad = 0.0;  // commanded (equal to theta_rad without body dynamics)
  double drag_lbf = 0.0;
  // Along +i_z: the point-mass lift; with body dynamics the i_z component of the Sec. 11
  // aerodynamic and control normal forces.
  double lift_lbf = 0.0;
  // With body dynamics (StepCommand::body_dynamics): the steady-state pitch deflection (eq. 7-3)
  // and the status of eq. 7-6 (kBodyDynamicsNotTrimmable when the body had to follow the command).
  double control_deflection_rad = 0.0;
  Status body_status = Status::kOk;
  // Under a wind (FlightPerturbation::wind) where the air is dense and the air-relative velocity
  // is not zero: true, with the local -> air frame of wind.hpp the forces were resolved in.
  bool windy = false;
  Matrix3 local_to_air = Matrix3::Identity();
};

// Evaluates the model at time t (from launch). `weight_offset_lb` is added to the vehicle weight
// (the optimizer's mass perturbation; 0 on ordinary runs).
void evaluate_flight(const Mission& mission, const PreparedCase& prepared, const StageContext& stage,
                     const StepCommand& command, double t, const StateVector& state, double weight_offset_lb,
                     Evaluation* out);
// The same with the state's sines and cosines already computed (trig = StateTrig(state)), for a
// caller that needs them too.
void evaluate_flight(const Mission& mission, const PreparedCase& prepared, const StageContext& stage,
                     const StepCommand& command, double t, const StateVector& state, const StateTrig& trig,
                     double weight_offset_lb, Evaluation* out);

// True where the attitude at the start of a step is the alpha = 0 attitude of the state there,
// whatever the pitch program says: the end of the zero-alpha window (IP(11)), where the next
// segment starts from the attitude flown, and stage-2 ignition under IP(12).
bool attitude_set_in_flight(const Mission& mission, int stage_code, double stage_start_s, double t);

// Pitch attitude that puts the thrust axis along V (alpha = 0) at this state, chi = 0.
double zero_alpha_theta_rad(const PreparedCase& prepared, const StateVector& state);

}  // namespace tolip
