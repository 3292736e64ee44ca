// Everything derived from a validated Mission before integration starts (subroutine REIN and the
// launch geometry): the stage timeline, the Sec. 14 modified thrust tables on the integration
// grid, and the launch frame matrices [B], [B'] frozen at t = 0.
#pragma once

#include "tolip/core/capacity.hpp"
#include "tolip/core/state.hpp"
#include "tolip/core/status.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/math/table.hpp"
#include "tolip/mission/mission.hpp"

namespace tolip {

using ModifiedThrustTable = Table<kMaxModifiedThrustPoints>;

struct StageTimeline {
  int code = 0;          // stage code 1-10
  double start_s = 0.0;  // time from launch at the start of the stage
  double duration_s = 0.0;
  int steps = 0;                         // integration steps (stage 1: after the lift-off interval)
  double step_s = 0.0;                   // fixed step of the stage
  double first_step_stage_time_s = 0.0;  // stage time of the first integration step (TL in stage 1)
};

// Sec. 14 re-tabulation of one powered stage's vacuum thrust.
struct ThrustModification {
  double ideal_velocity_input_ft_s = 0.0;  // A: exact integral of g0 T / W over the input table
  double ideal_velocity_grid_ft_s = 0.0;   // B: the same over the interpolated grid table
  double scale = 1.0;                      // A / B, applied to every grid entry
  double new_initial_thrust_lbf = 0.0;     // T(0) that keeps the impulse of the first interval
};

struct PreparedCase {
  bool prepared = false;
  int stage_count = 0;
  StageTimeline timeline[kMaxStages];                          // in flight order
  ModifiedThrustTable modified_thrust_lbf[kMaxPoweredStages];  // by powered stage code - 1
  ThrustModification thrust_modification[kMaxPoweredStages];
  double pad_radius_ft = 0.0;      // r0 = R_OBL(lambda0) + altitude
  double delta_lambda_rad = 0.0;   // at the pad
  Matrix3 geocentric_to_inertial;  // [B]  at t = 0
  Matrix3 platform_to_geocentric;  // [B'] at t = 0
  Matrix3 platform_to_inertial;    // [B][B']
  StateVector pad_state;           // X at t = 0
  OblateFigure oblate_figure;      // of the mission's constants, for every model evaluation
};

// Builds the timeline (durations and steps of data block 16, coasts included), the modified thrust
// tables and the launch matrices. The Mission must have passed validate_mission().
Status prepare_case(const Mission& mission, PreparedCase* prepared);

// Rebuilds only the stage timeline (after a coast duration changed during an optimization); the
// Sec. 14 thrust tables and the launch geometry are kept, as TOLIP re-tabulates once per case.
Status rebuild_timeline(const Mission& mission, PreparedCase* prepared);

// Recomputes only the launch geometry (pad state, [B], [B']) after the launch azimuth changed.
void prepare_launch_geometry(const Mission& mission, PreparedCase* prepared);

}  // namespace tolip
