// Autopilot gain schedules along a trajectory (issue 16, docs/theory/autopilot-design.md): at the
// schedule points of stages 1-3 of a flown nominal, the flight condition (q-bar, Mach, V, vacuum
// thrust, c.g., I_yy and its slope from data block 44, m-dot from block 38, the nozzle station of
// block 45, C_M_q of block 44 in stage 1), the short-period model and the designed gains.
//
// Schedule points (our choice): `points_per_stage` stage times evenly spaced over the controllable
// part of the stage (from its first to its last point where the vehicle moves and has control
// power: vacuum thrust, or q-bar in stage 1; the pad point and an upper stage's burnout point are
// not), each taken at the trajectory point of that stage nearest to it (the points are where the
// trajectory has its flight condition exactly); a point already taken is not taken twice. Stages 2 and 3 fly
// without atmosphere (q-bar = 0, as the Sec. 16 hardover turns of those stages).
#pragma once

#include "tolip/autopilot/autopilot_design.hpp"
#include "tolip/core/capacity.hpp"
#include "tolip/hardover/hardover.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip/vehicle/prepared_case.hpp"

namespace tolip {

struct GainScheduleDesignPoint {
  int stage_code = 0;
  int trajectory_point = 0;
  double time_s = 0.0;        // from launch
  double stage_time_s = 0.0;  // the table record's time
  AutopilotCondition condition;
  AutopilotDesign design;
};

struct GainScheduleDesign {
  int count = 0;
  GainScheduleDesignPoint points[kMaxGainSchedulePoints];
};

// `requests[k]` and `designed[k]` for stage k + 1 (k = 0-2); a stage not designed, or not flown,
// gets no points. On a failure *fault_stage names the stage (1-3) and the status the field
// (design_autopilot_gains()'s statuses; kTooManyGainSchedulePoints when points_per_stage is outside
// 1 .. kMaxGainSchedulePointsPerStage; kHardoverInertiaMissing when a designed stage has no block 44
// I_yy table).
Status design_gain_schedule(const Mission& mission, const Trajectory& trajectory,
                            const HardoverData& hardover,
                            const AutopilotRequest requests[kGainScheduleStages],
                            const bool designed[kGainScheduleStages], int points_per_stage,
                            GainScheduleDesign* schedule, int* fault_stage);

}  // namespace tolip
