// Autopilot gain schedules along a trajectory (gain_schedule_design.hpp).
#include "tolip/autopilot/gain_schedule_design.hpp"

#include <cmath>

#include "tolip/core/stage_codes.hpp"

namespace tolip {
namespace {

constexpr double kMinimumSpeed_ft_s = 1.0;  // the pad point does not move: no model there

// A point the design can use: the vehicle moves and has control power there (thrust for the jet
// vanes, or, in stage 1, dynamic pressure for the fins). The burnout point of an upper stage has
// neither.
bool controllable(const TrajectoryPoint& p, int code) {
  if (!(p.state[kStateV] >= kMinimumSpeed_ft_s)) return false;
  return p.vacuum_thrust_lbf > 0.0 || (code == 1 && p.dynamic_pressure_lbf_ft2 > 0.0);
}

}  // namespace

Status design_gain_schedule(const Mission& mission, const Trajectory& trajectory,
                            const HardoverData& hardover,
                            const AutopilotRequest requests[kGainScheduleStages],
                            const bool designed[kGainScheduleStages], int points_per_stage,
                            GainScheduleDesign* schedule, int* fault_stage) {
  schedule->count = 0;
  if (fault_stage != nullptr) *fault_stage = 0;
  if (points_per_stage < 1 || points_per_stage > kMaxGainSchedulePointsPerStage) {
    return Status::kTooManyGainSchedulePoints;
  }
  const BodyDynamicsBlocks& body = mission.body_dynamics;
  for (int e = 0; e < trajectory.stage_count; ++e) {
    const StageEvent& event = trajectory.stages[e];
    const int code = event.code;
    if (code < 1 || code > kGainScheduleStages || !designed[code - 1]) continue;
    auto fail = [&](Status status) {
      if (fault_stage != nullptr) *fault_stage = code;
      return status;
    };
    const HardoverStage& data = hardover.stages[code - 1];
    if (data.pitch_inertia_slug_ft2.empty() || !data.pitch_inertia_slug_ft2.finalized()) {
      return fail(Status::kHardoverInertiaMissing);
    }
    int first_index = -1;
    int last_index = -1;
    for (int i = event.first_point; i <= event.last_point; ++i) {
      if (!controllable(trajectory.points[i], code)) continue;
      if (first_index < 0) first_index = i;
      last_index = i;
    }
    if (first_index < 0) continue;  // never controllable: nothing to design
    const TrajectoryPoint& first = trajectory.points[first_index];
    const TrajectoryPoint& last = trajectory.points[last_index];
    const double duration = last.stage_time_s - first.stage_time_s;
    int previous = -1;
    for (int j = 0; j < points_per_stage; ++j) {
      const double target =
          first.stage_time_s + (points_per_stage == 1 ? 0.0 : duration * j / (points_per_stage - 1));
      int best = -1;
      double best_distance = 0.0;
      for (int i = first_index; i <= last_index; ++i) {
        const TrajectoryPoint& p = trajectory.points[i];
        if (!controllable(p, code)) continue;
        const double distance = std::fabs(p.stage_time_s - target);
        if (best < 0 || distance < best_distance) {
          best = i;
          best_distance = distance;
        }
      }
      if (best < 0 || best <= previous) continue;  // none moving, or taken already
      // The end point of a stage shares its time with the next stage's start: keep strictly
      // increasing stage times.
      if (previous >= 0 &&
          !(trajectory.points[best].stage_time_s > trajectory.points[previous].stage_time_s)) {
        continue;
      }
      previous = best;
      const TrajectoryPoint& p = trajectory.points[best];
      GainScheduleDesignPoint out;
      out.stage_code = code;
      out.trajectory_point = best;
      out.time_s = p.time_s;
      out.stage_time_s = p.stage_time_s;
      AutopilotCondition& c = out.condition;
      const bool stage1 = code == 1;
      c.moments.stage = code;
      c.moments.cg_stage_time_s = p.stage_time_s;
      c.moments.mach = p.mach;
      c.moments.dynamic_pressure_lbf_ft2 = stage1 ? p.dynamic_pressure_lbf_ft2 : 0.0;
      c.moments.vacuum_thrust_lbf = p.vacuum_thrust_lbf;
      const StageData& stage_data = mission.vehicle.stages[stage_index(code)];
      const bool lift = stage1 && p.dynamic_pressure_lbf_ft2 > 0.0 && stage_data.uses_lift_table &&
                        !mission.vehicle.lift_curve_slope_per_rad.empty();
      c.moments.normal_force_slope_per_rad = lift ? mission.vehicle.lift_curve_slope_per_rad(p.mach) : 0.0;
      c.speed_ft_s = p.state[kStateV];
      double inertia_rate = 0.0;
      c.pitch_inertia_slug_ft2 = data.pitch_inertia_slug_ft2.value_and_slope(p.stage_time_s, &inertia_rate);
      c.inertia_rate_slug_ft2_s = inertia_rate;
      double consumable_slope_lb_s = 0.0;
      if (!stage_data.consumable_weight_lb.empty()) {
        (void)stage_data.consumable_weight_lb.value_and_slope(p.stage_time_s, &consumable_slope_lb_s);
      }
      c.mass_rate_slug_s = consumable_slope_lb_s / mission.constants.g0_ft_s2;
      c.thrust_station_ft = data.thrust_station_ft;
      c.pitch_damping_per_rad =
          (stage1 && !hardover.pitch_damping_per_rad.empty()) ? hardover.pitch_damping_per_rad(p.mach) : 0.0;
      const ShortPeriodModel model = short_period_model(body, c);
      const Status status = design_autopilot_gains(model, requests[code - 1], &out.design);
      if (!ok(status)) return fail(status);
      if (schedule->count >= kMaxGainSchedulePoints) return fail(Status::kTooManyGainSchedulePoints);
      schedule->points[schedule->count++] = out;
    }
  }
  return Status::kOk;
}

}  // namespace tolip
