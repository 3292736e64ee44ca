// The guidance executor: called once per minor cycle with the time since lift-off, it returns the
// commanded pitch attitude theta, its rate, the yaw attitude chi and the autopilot gains and
// deflection limit in force, from the active table of a GuidanceTableService.
//
//   * From lift-off (t = 0) until the image's lift-off duration: theta = 90 deg (vertical rise).
//   * Stages 1-3, coasts 6-8, and stages 4, 5 and coasts 9, 10 when the table's IP(9) does not spin
//     them: the linear segment in force, theta = theta_start + rate (t - segment start), the
//     segment start being its stage's start time (from the stage event) plus its start in stage
//     time. A segment stays in force across stage boundaries until the next one starts. Before the
//     first segment starts, theta is held at 90 deg.
//   * A spun stage 4 and coast 9 (IP(9) = 1): the spun stage-4 attitude; a spun stage 5 and coast 10
//     (IP(9) = 1, 2): the spun stage-5 one.
//
// The stage in force comes from stage events (stage_event(code, t)): stage 1 starts at lift-off.
// The executor is deterministic (+, -, * only on the command path) and its worst-case path is
// bounded: one pass over at most kMaxLinearSegments records, no other loop.
#pragma once

#include <cstdint>

#include "tolip/core/capacity.hpp"
#include "tolip/core/status.hpp"
#include "tolip/table/table_image.hpp"
#include "tolip/table/table_service.hpp"

namespace tolip {

enum class GuidanceMode : std::uint8_t {
  kLiftoffHold,         // theta = 90 deg during the vertical lift-off
  kHoldBeforeSegments,  // after lift-off, before the first segment starts: theta = 90 deg
  kSegment,             // a linear segment
  kSpunHold,            // spun stage 4/5 (and coasts 9/10, IP(9)): attitude of the table
};

struct GuidanceCommand {
  GuidanceMode mode = GuidanceMode::kLiftoffHold;
  int stage_code = 1;            // stage in force
  int segment_index = -1;        // segment in force (kSegment), else -1
  double theta_rad = 0.0;        // commanded pitch attitude theta_c
  double theta_dot_rad_s = 0.0;  // commanded pitch rate (the segment's rate; 0 when holding)
  double chi_rad = 0.0;          // commanded yaw attitude
  double k_theta = 0.0;          // position gain in force, rad/rad
  double k_q_s = 0.0;            // rate gain in force, s
  double max_deflection_rad = 0.0;
};

class GuidanceExecutor {
 public:
  explicit GuidanceExecutor(const GuidanceTableService& service) : service_(service) { reset(); }

  // Lift-off: stage 1 in force since t = 0, no other stage started.
  void reset();

  // Stage `code` (1-10) started at `time_since_liftoff_s`. Stages follow the flight order
  // 1 6 2 7 3 8 4 9 5 10 (stages may be skipped, never revisited) and never start before the
  // stage in force. On failure nothing changes.
  Status stage_event(int code, double time_since_liftoff_s);

  // The command at `time_since_liftoff_s` (>= the start of the stage in force). On failure
  // (kNoActiveTable, kValueNotFinite, kStageEventOutOfOrder) *command is not modified.
  Status step(double time_since_liftoff_s, GuidanceCommand* command) const;

  int stage_in_force() const { return current_stage_; }
  double stage_start_s(int code) const { return stage_start_s_[code - 1]; }

 private:
  const GuidanceTableService& service_;
  double stage_start_s_[kMaxStages] = {};
  bool stage_started_[kMaxStages] = {};
  int current_stage_ = 1;
};

}  // namespace tolip
