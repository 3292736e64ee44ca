// Guidance executor: lift-off hold, linear segments, spun-stage attitudes (guidance_executor.hpp).
#include "tolip/table/guidance_executor.hpp"

#include <cmath>

#include "tolip/core/constants.hpp"

namespace tolip {
namespace {

constexpr double kVerticalRad = 0.5 * kPi;

}  // namespace

void GuidanceExecutor::reset() {
  for (int i = 0; i < kMaxStages; ++i) {
    stage_start_s_[i] = 0.0;
    stage_started_[i] = false;
  }
  current_stage_ = 1;
  stage_started_[0] = true;
}

Status GuidanceExecutor::stage_event(int code, double time_since_liftoff_s) {
  const int order = flight_order_index(code);
  if (order < 0) return Status::kUnknownStageCode;
  if (!std::isfinite(time_since_liftoff_s)) return Status::kValueNotFinite;
  if (code == current_stage_) {
    // A repeated event for the stage in force (e.g. a re-sent ignition signal) changes nothing.
    return time_since_liftoff_s == stage_start_s_[code - 1] ? Status::kOk : Status::kStageEventOutOfOrder;
  }
  if (order < flight_order_index(current_stage_) ||
      time_since_liftoff_s < stage_start_s_[current_stage_ - 1]) {
    return Status::kStageEventOutOfOrder;
  }
  stage_start_s_[code - 1] = time_since_liftoff_s;
  stage_started_[code - 1] = true;
  current_stage_ = code;
  return Status::kOk;
}

Status GuidanceExecutor::step(double t, GuidanceCommand* command) const {
  const GuidanceTable* table = service_.active();
  if (table == nullptr) return Status::kNoActiveTable;
  if (!std::isfinite(t)) return Status::kValueNotFinite;
  const int stage = current_stage_;
  if (t < stage_start_s_[stage - 1]) return Status::kStageEventOutOfOrder;

  GuidanceCommand out;
  out.stage_code = stage;
  // The gains in force: the stage's schedule (version 3) at its stage time, else its constant record.
  const StageGains gains = scheduled_gains(*table, stage, t - stage_start_s_[stage - 1]);
  out.k_theta = gains.k_theta;
  out.k_q_s = gains.k_q_s;
  out.max_deflection_rad = table->max_deflection_rad;

  // Spun stages (IP(9), the one rule of tolip::stage_is_spun) hold the table's attitudes; stages 4
  // and 5 that IP(9) leaves continuous fly the segments like stages 1-3.
  if (stage_is_spun(table->spin_option, stage)) {
    const bool fourth = stage == 4 || stage == 9;
    out.mode = GuidanceMode::kSpunHold;
    out.theta_rad = fourth ? table->stage4_theta_rad : table->stage5_theta_rad;
    out.chi_rad = fourth ? table->stage4_chi_rad : table->stage5_chi_rad;
    *command = out;
    return Status::kOk;
  }

  if (stage == 1 && t < table->liftoff_duration_s) {
    out.mode = GuidanceMode::kLiftoffHold;
    out.theta_rad = kVerticalRad;
    *command = out;
    return Status::kOk;
  }

  // The segment in force: the last one (in flight order) whose start is not after (stage, t).
  // One bounded pass over the fixed capacity.
  const int order_now = flight_order_index(stage);
  const double stage_time = t - stage_start_s_[stage - 1];
  int chosen = -1;
  double elapsed = 0.0;
  for (int i = 0; i < kMaxLinearSegments; ++i) {
    if (i >= table->segment_count) break;
    const GuidanceSegment& segment = table->segments[i];
    const int order = flight_order_index(segment.stage_code);
    if (order > order_now) break;                           // segments are in flight order (validated)
    if (!stage_started_[segment.stage_code - 1]) continue;  // its stage was skipped
    double since_start = 0.0;
    if (order == order_now) {
      if (segment.start_stage_time_s > stage_time) break;
      since_start = stage_time - segment.start_stage_time_s;
    } else {
      since_start = (t - stage_start_s_[segment.stage_code - 1]) - segment.start_stage_time_s;
      // A segment of an earlier stage that starts after that stage ended has not started yet.
      if (since_start < 0.0) break;
    }
    chosen = i;
    elapsed = since_start;
  }

  if (chosen < 0) {
    out.mode = GuidanceMode::kHoldBeforeSegments;
    out.theta_rad = kVerticalRad;
  } else {
    const GuidanceSegment& segment = table->segments[chosen];
    out.mode = GuidanceMode::kSegment;
    out.segment_index = chosen;
    out.theta_rad = segment.theta_start_rad + segment.rate_rad_s * elapsed;
    out.theta_dot_rad_s = segment.rate_rad_s;
  }
  *command = out;
  return Status::kOk;
}

}  // namespace tolip
