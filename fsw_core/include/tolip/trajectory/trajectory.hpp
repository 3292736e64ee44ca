// Forward trajectory (manual Sec. 4, 19, 22): closed-form vertical lift-off, then every stage of
// the sequence with the RKAD integrator (RK4 in powered stages, RK4 start then Adams-Bashforth 4
// in coasts), a commanded pitch program (data block 40), the zero-alpha window (IP(11)), alpha = 0
// at stage-2 ignition (IP(12)) and spun-stage attitudes (data block 17). Every integration point
// is stored in the caller's fixed storage.
#pragma once

#include "tolip/core/capacity.hpp"
#include "tolip/core/state.hpp"
#include "tolip/core/status.hpp"
#include "tolip/mission/mission.hpp"
#include "tolip/orbit/orbit_elements.hpp"
#include "tolip/trajectory/flight_dynamics.hpp"
#include "tolip/vehicle/prepared_case.hpp"

namespace tolip {

// One integration point: the state and what the equations of motion saw there.
struct TrajectoryPoint {
  double time_s = 0.0;  // from launch (TIMCT), coasts included
  int stage_code = 0;
  // The commanded pitch attitude (the pitch program's theta_c). Equal to theta_rad but for body
  // dynamics, where theta_rad is the flown steady state (Sec. 7). Single precision (1e-7 rad is far
  // below any listing's resolution) so it fits the padding after stage_code: the point stays
  // 240 bytes.
  float theta_command_rad = 0.0f;
  double stage_time_s = 0.0;
  StateVector state = StateVector::Zero();
  double altitude_ft = 0.0;          // above the oblate surface
  double earth_longitude_rad = 0.0;  // tau - omega t
  double geodetic_latitude_rad = 0.0;
  double weight_lb = 0.0;
  double vacuum_thrust_lbf = 0.0;  // modified (Sec. 14) table
  double net_thrust_lbf = 0.0;     // Tv - p Ae
  double dynamic_pressure_lbf_ft2 = 0.0;
  double mach = 0.0;
  double alpha_rad = 0.0;  // in-plane angle between thrust axis and V (of the flown attitude)
  double theta_rad = 0.0;  // pitch attitude flown, in the platform frame
  double chi_rad = 0.0;    // yaw attitude flown, in the platform frame
  double drag_lbf = 0.0;
  double lift_lbf = 0.0;                // along +i_z; body dynamics: i_z part of the Sec. 11 normal forces
  double heating_rate_btu_ft2_s = 0.0;  // Sec. 13 (0 when no nose radius)
  double downrange_rad = 0.0;           // central angle from the launch point
  InertialVelocity inertial;
  bool heading_hold = false;   // dpsi/dt held at 0 on the step starting here
  bool alpha_zero = false;     // theta set for alpha = 0 on the step starting here
  bool body_dynamics = false;  // 6D (Sec. 7, 11) on the step starting here
  // Body dynamics: the steady-state pitch deflection delta of eq. 7-3 (0 otherwise). Single
  // precision in the padding after the flags.
  float control_deflection_rad = 0.0f;
};

struct StageEvent {
  int code = 0;
  int first_point = 0;             // index of the stage's first point
  int last_point = 0;              // index of the stage's last point (before jettison)
  double burnout_weight_lb = 0.0;  // at the end of the stage, before jettison
  double weight_after_jettison_lb = 0.0;
  // The stage flew to its end (and jettisoned). false for the stage a failed run stopped in: its
  // last point is the last point flown, it jettisoned nothing.
  bool completed = false;
};

// One integration step as flown, so a backward run can re-evaluate exactly the same model.
struct StepRecord {
  int point = 0;       // index of the step's start point; the step ends at point + 1
  int stage_slot = 0;  // index into PreparedCase::timeline
  bool adams = false;  // Adams-Bashforth step (RK4 otherwise)
  StepCommand command;
};

// The pitch program as values at the trajectory's points (the optimizer's control): within a step
// theta is linear between the values at the step's two points. Points whose attitude is decided
// otherwise (lift-off, zero-alpha window, alpha = 0 at stage-2 ignition, spun stages) ignore it.
struct ControlProgram {
  int point_count = 0;
  double theta_rad[kMaxTrajectoryPoints] = {};
};

struct Trajectory {
  Status status = Status::kNotPrepared;
  int point_count = 0;
  TrajectoryPoint points[kMaxTrajectoryPoints];
  int step_count = 0;
  StepRecord steps[kMaxTrajectoryPoints];
  int stage_count = 0;
  StageEvent stages[kMaxStages];       // flight order
  double heat_integral_btu_ft2 = 0.0;  // time integral of the heating rate
  const TrajectoryPoint& final_point() const { return points[point_count - 1]; }
};

// Flies the case. On success trajectory->status is kOk and the final point is the end of the last
// stage. On a failure (non-finite state, impact, ...) the points up to the failure are kept and
// the status names the cause; no NaN is stored.
// What a forward run flies besides the Mission: an optional per-point pitch program, and an
// optional state change injected at one point (how a perturbation of the state at a given time is
// propagated; used by the optimizer's tests of its sensitivities).
// A pitch program that reacts to the flight: consulted at the start of every integration step with
// the state there, it may rewrite the program's values from that point on (the optimizer's
// closed-loop steering, Sec. 5 and 9). Implementations must not allocate.
class PitchFeedback {
 public:
  virtual void at_point(int point, const StateVector& state, ControlProgram* program) = 0;

 protected:
  ~PitchFeedback() = default;
};

struct FlightInputs {
  const ControlProgram* program = nullptr;  // null: data block 40 table (ignored with feedback)
  int injection_point = -1;                 // point whose state receives `injection` (-1: none)
  StateVector injection = StateVector::Zero();
  // With feedback, `live_program` is flown and rewritten in flight (without it: kFeedbackWithoutLiveProgram).
  PitchFeedback* feedback = nullptr;
  ControlProgram* live_program = nullptr;
  // Body dynamics (6D, manual Sec. 7, 11; docs/theory/body-dynamics.md): in stage 1 and the coast
  // after it the vehicle flies the autopilot's steady-state attitude about the pitch program above
  // (block 40 table, `program` or the live program) and the Sec. 11 normal forces act; every other
  // stage follows the command as without it. Needs data blocks 33-37 (validate_body_dynamics()),
  // else the run fails with that status before flying. Off: the point-mass run, bit for bit.
  bool body_dynamics = false;
  // Resume at the start of timeline slot `resume_stage_slot` (> 0): the points, steps and stage
  // events before it are copied from `resume_from`, a completed flight of a case that flies exactly
  // like this one up to there (same mission and prepared case before that stage: a change of that
  // stage's thrust, burn rate or drag, say), and the integration restarts from its state there.
  // Every stage restarts its integrator, so the result is the full flight's, bit for bit; it skips
  // the work before the stage (the exchange ratios' runs). Not with feedback or an injection
  // (kResumeInputsIncompatible); a slot that is not a later stage of both flights is
  // kResumeStageSlotInvalid, one without a recorded start point kResumeStageNotRecorded.
  const Trajectory* resume_from = nullptr;
  int resume_stage_slot = 0;
  // A dispersed trajectory's changes to the flight (Sec. 15; flight_dynamics.hpp). Null: none.
  const FlightPerturbation* perturbation = nullptr;
  // Lean points (a Monte Carlo sample's flight): every point leaves geodetic_latitude_rad,
  // heating_rate_btu_ft2_s, downrange_rad and inertial at 0 (and heat_integral_btu_ft2 at 0), and
  // with air_alpha_rad below a windy point its alpha_rad too (the air-relative alpha is kept
  // there): what record_dispersed_trajectory() does not read. The flight and every other member are
  // the full run's, bit for bit.
  bool lean_points = false;
  // The model evaluations' trigonometry by series (frames.hpp): the state's and theta's sines and
  // cosines by the addition theorem from a per-stage anchor (StateTrigAnchor), the small angles of
  // attack, sideslip and velocity azimuth by the series of atan (atan2_by_series); each within 2
  // ulps of the library's, at a fraction of the cost. The dispersion analyses' flights set it
  // (dispersion_flight_inputs), where the per-sample cost counts. Off, every evaluation calls the
  // library, as the optimizer's runs do: their hard cases are sensitive to the last bit
  // (docs/theory/trajectory.md). A point's downrange and inertial velocity are the library's
  // functions of its state either way; what the evaluation there gives (alpha, q-bar) is the flight's.
  bool trig_by_series = false;
  // Optional output, kMaxTrajectoryPoints values of the caller's: at every point the angle of
  // attack against the air mass where the evaluation there was windy (Evaluation::windy), else
  // the point's alpha_rad; what record_dispersed_trajectory() would recompute from the point. Not
  // with resume_from (kResumeInputsIncompatible).
  double* air_alpha_rad = nullptr;
};

Status fly_trajectory(const Mission& mission, const PreparedCase& prepared, const FlightInputs& inputs,
                      Trajectory* trajectory);

// The pitch program is data block 40's table (theta at each point from the table, with the
// in-flight latched segments described in docs/theory/trajectory.md).
Status fly_trajectory(const Mission& mission, const PreparedCase& prepared, Trajectory* trajectory);

// The same flown with an explicit per-point pitch program (its point_count must equal the number
// of points the case produces, which depends only on the step counts).
Status fly_trajectory(const Mission& mission, const PreparedCase& prepared, const ControlProgram& program,
                      Trajectory* trajectory);

// Number of points a flight of the prepared case stores (pad point, every step start, every stage
// end point): the size a ControlProgram must have.
int trajectory_point_count(const PreparedCase& prepared);

}  // namespace tolip
