// Failure-mode hardover turns (manual Sec. 16, data blocks 44-45, IP(22) = 1): from points of the
// nominal trajectory, the turn of the velocity vector a control failure makes in up to ten
// seconds. Stage 1: full deflection of the fins and jet vanes with an additive thrust
// misalignment, the aerodynamic restoring moment, pitch damping and jet damping. Stages 2 and 3:
// control-jet modes 1 (thrust misalignment only), 2 (a single control jet) and 3 (one pitch and
// one yaw jet, 45 deg roll), jet damping, no atmosphere. Euler integration within the attitude-step
// and time-step limits of data block 45; a turn stops after ten seconds, one second after q-bar x
// alpha reaches (q-bar alpha)max, when the vehicle tumbles (|alpha| reaches 90 deg), at the end of
// its stage or after the deck's maximum number of steps. docs/theory/hardover.md gives the
// equations and the choices. The vehicle's thrust, weight and atmosphere come from the trajectory
// module's evaluate_flight (the nominal's own model), the moments of stage 1 from the body module's
// unit_moments (data blocks 33-37).
#pragma once

#include "tolip/core/capacity.hpp"
#include "tolip/core/status.hpp"
#include "tolip/math/table.hpp"
#include "tolip/mission/mission.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip/vehicle/prepared_case.hpp"

namespace tolip {

// Block 44 tables (22E12.8: blank, ten pairs, the 1.0E10 terminator).
using HardoverTable = Table<kMaxHardoverTablePoints>;

// The data block 45 words and block 44 table of one stage (1-3).
struct HardoverStage {
  int every_nth_step = 0;                // words 1, 21, 22: a turn from every n-th integration point
  double max_attitude_step_rad = 0.0;    // words 3, 23: (delta theta)max per integration step
  double max_step_s = 0.0;               // words 4, 24: (DT)max
  double min_step_s = 0.0;               // words 5, 25: (DT)min
  int max_steps_per_turn = 0;            // words 6, 26
  double thrust_misalignment_rad = 0.0;  // words 7-9: alpha_T
  double thrust_station_ft = 0.0;        // words 10, 16, 17: X_TA (body station, aft positive)
  double single_jet_force_lbf = 0.0;     // words 12-13: mode 2 (B) control-jet force, stages 2-3
  double pitch_yaw_jet_force_lbf = 0.0;  // words 14-15: mode 3 (C) force, stages 2-3
  double control_jet_station_ft = 0.0;   // words 18-19: X_TAC, stages 2-3
  HardoverTable pitch_inertia_slug_ft2;  // block 44 IYYk: stage time s -> I_yy about the c.g.
};

struct HardoverData {
  HardoverStage stages[3];
  HardoverTable pitch_damping_per_rad;      // block 44, stage code 4: Mach -> CMQ (stage 1)
  double max_qbar_alpha_lbf_rad_ft2 = 0.0;  // word 2 (the deck gives lb deg/ft^2)
  double fin_vane_deflection_rad = 0.0;     // word 11: delta of stage 1
  double output_interval_s = 0.0;           // word 20
};

// The over-turning moment of a turn.
enum class HardoverMode : int {
  kFinsAndVanes = 0,        // stage 1: full deflection plus additive thrust misalignment
  kThrustMisalignment = 1,  // stages 2-3, mode 1
  kSingleJet = 2,           // mode 2
  kPitchAndYawJets = 3,     // mode 3
};

// +1: the failure turns the nose up (positive deflection and misalignment, Sec. 16's sign
// convention); -1: down.
enum class HardoverDirection : int { kNoseDown = -1, kNoseUp = 1 };

enum class HardoverStop : int {
  kTimeLimit,       // ten seconds
  kQbarAlphaLimit,  // one second after |q-bar alpha| reached (q-bar alpha)max
  kTumbling,        // |alpha| reached 90 deg
  kEndOfStage,      // the stage burnt out
  kStepLimit,       // the deck's maximum number of integration steps per turn
};
const char* hardover_stop_name(HardoverStop stop);

// One output line of a turn (every output interval, and the last point).
struct HardoverSample {
  double time_s = 0.0;                  // from the start of the turn
  double change_in_gamma_rad = 0.0;     // gamma - gamma_0
  double qbar_alpha_lbf_rad_ft2 = 0.0;  // q-bar alpha (0 in stages 2-3)
  double attitude_change_rad = 0.0;     // eta - eta_0
  double attitude_rate_rad_s = 0.0;     // eta-dot
};

struct HardoverTurn {
  int stage = 0;
  HardoverMode mode = HardoverMode::kFinsAndVanes;
  int nominal_point = 0;        // index into the trajectory
  double failure_time_s = 0.0;  // from launch
  HardoverStop stop = HardoverStop::kTimeLimit;
  int steps = 0;
  int sample_count = 0;
  HardoverSample samples[kMaxHardoverSamples];
  const HardoverSample& last() const { return samples[sample_count - 1]; }
};

struct HardoverResult {
  int turn_count = 0;
  HardoverTurn turns[kMaxHardoverTurns];
};

// Where validate_hardover_data() found a fault.
struct HardoverFault {
  int data_block = 0;  // 44 or 45
  int word = 0;        // block 45 word (0 for a table)
  int stage = 0;       // 1-3, 4 for the CMQ table, 0 when not staged
};

// The rigid-body pitch (or yaw) loads of Sec. 16 at one evaluation, shared by the hardover turns
// and the HIL bench's plant (hal_sim): the moment about the c.g. (1. control deflection delta
// M_delta, 2. thrust misalignment T alpha_T (X_TA - X_CG), 3. angle of attack alpha M_alpha,
// 4. pitch damping CMQ, stage 1; 5. jet damping, every stage; 6. control jets F (X_TAC - X_CG),
// stages 2-3), the normal force FORCEN, the lift, I_yy. Stage 1 has the atmosphere; the upper
// stages do not (Sec. 16). `ev` is evaluate_flight's evaluation of the stage flown.
struct RigidBodyInputs {
  int body_stage = 1;                // 1-3: the block 33-37 / 44-45 data of the stack flying
  double body_stage_time_s = 0.0;    // time in that stage's tables (I_yy, c.g.)
  const StageData* flown = nullptr;  // the stage flown: consumption rate, reference area, lift
  double flown_stage_time_s = 0.0;   // its stage time
  double alpha_rad = 0.0;            // angle of attack in the plane of the moment
  double rate_rad_s = 0.0;           // attitude rate in that plane
  double speed_ft_s = 0.0;           // V (pitch damping)
  double deflection_rad = 0.0;       // stage 1 fins and jet vanes
  double misalignment_rad = 0.0;     // thrust misalignment alpha_T
  double jet_force_lbf = 0.0;        // stages 2-3: control-jet force (signed)
};
struct RigidBodyMoment {
  double moment_lbf_ft = 0.0;
  double normal_force_lbf = 0.0;          // FORCEN
  double lift_lbf = 0.0;                  // stage 1: q S C_L_alpha alpha
  double dynamic_pressure_lbf_ft2 = 0.0;  // the q used (0 in stages 2-3)
  double inertia_slug_ft2 = 0.0;
  double cg_station_ft = 0.0;
};
RigidBodyMoment rigid_body_moment(const Mission& mission, const HardoverData& data, const Evaluation& ev,
                                  const RigidBodyInputs& inputs);

// Checks what the turns of every stage 1-3 in the sequence need (block 45 step limits and counts,
// the output interval against kMaxHardoverSamples, the I_yy tables positive, the CMQ table, the
// body-dynamics data of blocks 33-37 for stage 1 and the c.g. histories of stages 1-3).
Status validate_hardover_data(const Mission& mission, const HardoverData& data, HardoverFault* fault);

// One turn from trajectory point `point` (which must lie inside a powered stage 1-3 and move).
Status compute_hardover_turn(const Mission& mission, const PreparedCase& prepared,
                             const Trajectory& trajectory, const HardoverData& data, int point,
                             HardoverMode mode, HardoverDirection direction, HardoverTurn* turn);

// Every turn the data blocks name (nose up): stage 1 from every n-th point (the moving points,
// before burnout), stages 2 and 3 in modes 1-3 from every n-th point; in flight order. Validates
// first (kHardover... statuses, *fault).
Status compute_hardover_turns(const Mission& mission, const PreparedCase& prepared,
                              const Trajectory& trajectory, const HardoverData& data, HardoverResult* result,
                              HardoverFault* fault);

}  // namespace tolip
