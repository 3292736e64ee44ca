// Dispersion analysis (manual Sec. 15, Sec. 22 blocks 46-55; docs/theory/dispersions.md).
#include "tolip/dispersion/dispersion.hpp"

#include <cmath>

#include "tolip/frames/frames.hpp"

namespace tolip {
namespace {

using Kind = DispersionKind;
using Plane = DispersionPlane;

// The DISPERSION TRAJECTORY CODES table of Sec. 22.
struct CodeRow {
  int code;
  Kind kind;
  Plane plane;
  int stage;
  bool high;
  const char* name;
};

constexpr CodeRow kCodeTable[] = {
    {1, Kind::kVacuumThrust, Plane::kHighLow, 1, true, "vacuum thrust high, stage 1"},
    {2, Kind::kVacuumThrust, Plane::kHighLow, 1, false, "vacuum thrust low, stage 1"},
    {3, Kind::kVacuumThrust, Plane::kHighLow, 2, true, "vacuum thrust high, stage 2"},
    {4, Kind::kVacuumThrust, Plane::kHighLow, 2, false, "vacuum thrust low, stage 2"},
    {5, Kind::kVacuumThrust, Plane::kHighLow, 3, true, "vacuum thrust high, stage 3"},
    {6, Kind::kVacuumThrust, Plane::kHighLow, 3, false, "vacuum thrust low, stage 3"},
    {7, Kind::kVacuumThrust, Plane::kHighLow, 4, true, "vacuum thrust high, stage 4"},
    {8, Kind::kVacuumThrust, Plane::kHighLow, 4, false, "vacuum thrust low, stage 4"},
    {9, Kind::kWeightIncrement, Plane::kHighLow, 1, true, "weight increment high, stage 1"},
    {10, Kind::kWeightIncrement, Plane::kHighLow, 1, false, "weight increment low, stage 1"},
    {11, Kind::kWeightIncrement, Plane::kHighLow, 2, true, "weight increment high, stage 2"},
    {12, Kind::kWeightIncrement, Plane::kHighLow, 2, false, "weight increment low, stage 2"},
    {13, Kind::kWeightIncrement, Plane::kHighLow, 3, true, "weight increment high, stage 3"},
    {14, Kind::kWeightIncrement, Plane::kHighLow, 3, false, "weight increment low, stage 3"},
    {15, Kind::kWeightIncrement, Plane::kHighLow, 4, true, "weight increment high, stage 4"},
    {16, Kind::kWeightIncrement, Plane::kHighLow, 4, false, "weight increment low, stage 4"},
    {17, Kind::kDrag, Plane::kHighLow, 0, true, "drag variation high, stages 1, 6, 2"},
    {18, Kind::kDrag, Plane::kHighLow, 0, false, "drag variation low, stages 1, 6, 2"},
    {19, Kind::kPitchingMoment, Plane::kHighLow, 1, true, "C_M_alpha variation forward, stage 1"},
    {20, Kind::kPitchingMoment, Plane::kHighLow, 1, false, "C_M_alpha variation aft, stage 1"},
    {21, Kind::kThrustMisalignment, Plane::kHighLow, 1, true, "thrust misalignment high, stage 1"},
    {22, Kind::kThrustMisalignment, Plane::kHighLow, 1, false, "thrust misalignment low, stage 1"},
    {23, Kind::kThrustMisalignment, Plane::kYaw, 1, false, "thrust misalignment yaw, stage 1"},
    {24, Kind::kControlDeadband, Plane::kHighLow, 2, true, "control system deadband high, stage 2"},
    {25, Kind::kControlDeadband, Plane::kHighLow, 2, false, "control system deadband low, stage 2"},
    {26, Kind::kControlDeadband, Plane::kYaw, 2, false, "control system deadband yaw, stage 2"},
    {27, Kind::kControlDeadband, Plane::kHighLow, 3, true, "control system deadband high, stage 3"},
    {28, Kind::kControlDeadband, Plane::kHighLow, 3, false, "control system deadband low, stage 3"},
    {29, Kind::kControlDeadband, Plane::kYaw, 3, false, "control system deadband yaw, stage 3"},
    {30, Kind::kTipoff, Plane::kHighLow, 4, true, "4th and/or 5th stage tip-off high"},
    {31, Kind::kTipoff, Plane::kHighLow, 4, false, "4th and/or 5th stage tip-off low"},
    {32, Kind::kTipoff, Plane::kYaw, 4, false, "4th and/or 5th stage tip-off yaw"},
    {33, Kind::kLaunchAzimuth, Plane::kYaw, 1, false, "launch azimuth, yaw"},
    {34, Kind::kLaunchAttitude, Plane::kHighLow, 1, true, "launch attitude high"},
    {35, Kind::kLaunchAttitude, Plane::kHighLow, 1, false, "launch attitude low"},
    {36, Kind::kWind, Plane::kHighLow, 0, true, "winds high"},
    {37, Kind::kWind, Plane::kHighLow, 0, false, "winds low"},
    {38, Kind::kWind, Plane::kYaw, 0, false, "winds yaw"},
    {40, Kind::kNominal, Plane::kNone, 0, false, "nominal trajectory, three-sigma variations"},
};

bool in_sequence(const Mission& mission, int code) {
  const StageSequence& sequence = mission.vehicle.sequence;
  for (int k = 0; k < sequence.count; ++k) {
    if (sequence.codes[k] == code) return true;
  }
  return false;
}

// Stage time of the i-th point of a stage's points (the step starts, then the end point).
double point_stage_time_s(const StageTimeline& line, int i) {
  return (i < line.steps) ? line.first_step_stage_time_s + i * line.step_s : line.duration_s;
}

bool same_grid(const StageTimeline& a, const StageTimeline& b) {
  return a.steps == b.steps && a.step_s == b.step_s && a.duration_s == b.duration_s &&
         a.first_step_stage_time_s == b.first_step_stage_time_s;
}

void copy_title(const char* from, char* to) {
  int i = 0;
  for (; i < 12 && from[i] != '\0'; ++i) to[i] = from[i];
  to[i] = '\0';
}

void accumulate(const DispersedTrajectory& t, int columns, ThreeSigmaGroup* group) {
  if (group->member_count >= kMaxDispersionSources) return;
  group->members[group->member_count++] = t.code;
  for (int j = 0; j < columns; ++j) {
    for (int i = 0; i < kStagingVariables; ++i) {
      group->sum[j][i] += t.dispersions[j][i];
      group->rss[j][i] += t.dispersions[j][i] * t.dispersions[j][i];  // squares until finish()
    }
  }
}

void finish(int columns, ThreeSigmaGroup* group) {
  for (int j = 0; j < columns; ++j) {
    for (int i = 0; i < kStagingVariables; ++i) group->rss[j][i] = std::sqrt(group->rss[j][i]);
  }
}

// The rules of one stage's replacement tables, as data blocks 30 and 38 (validate_mission):
// entries [first, last] of the thrust and weight tables at stage time x - offset_s, from stage
// time 0 and ending after it, on the same times, the thrust not negative, the consumable weight
// not increasing and not negative. A per-stage source is the whole table at offset 0; a stacked
// one (codes 7-8 with block 55) has two such parts.
Status check_replacement_part(const ThrustTable& thrust, const WeightTable& weight, int first, int last,
                              double offset_s) {
  if (thrust.x(first) - offset_s != 0.0 || !(thrust.x(last) - offset_s > 0.0)) {
    return Status::kDispersionThrustTableTimesInvalid;
  }
  for (int i = first; i <= last; ++i) {
    if (thrust.x(i) != weight.x(i)) return Status::kThrustWeightTimesDiffer;
    if (i > first && !(thrust.x(i) > thrust.x(i - 1))) return Status::kTableNotMonotonic;
    if (thrust.y(i) < 0.0) return Status::kDispersionThrustNegative;
    if (weight.y(i) < 0.0) return Status::kNegativeWeight;
    if (i > first && weight.y(i) > weight.y(i - 1)) return Status::kConsumableWeightIncreases;
  }
  return Status::kOk;
}

// Block 55 against the table times (Sec. 22: "These must be the same as final entries in data
// blocks 30 and 38"): the same number, up to the round-off of t_last - d5 in the continuing layout.
constexpr double kStackedTimeTolerance = 1e-9;  // relative to the larger time, at least 1 s

bool same_time_s(double a, double b) {
  return std::fabs(a - b) <= kStackedTimeTolerance * std::fmax(1.0, std::fmax(std::fabs(a), std::fabs(b)));
}

// One part of a split stacked source into a stage's tables, in its own stage time.
Status copy_part(const DispersionSource& source, int first, int last, double offset_s, StageData* out) {
  out->vacuum_thrust_lbf.clear();
  out->consumable_weight_lb.clear();
  for (int i = first; i <= last; ++i) {
    const double t = source.vacuum_thrust_lbf.x(i) - offset_s;
    Status status = out->vacuum_thrust_lbf.append(t, source.vacuum_thrust_lbf.y(i));
    if (ok(status)) status = out->consumable_weight_lb.append(t, source.consumable_weight_lb.y(i));
    if (!ok(status)) return status;
  }
  Status status = out->vacuum_thrust_lbf.finalize();
  if (ok(status)) status = out->consumable_weight_lb.finalize();
  if (!ok(status)) return status;
  out->duration_s = out->vacuum_thrust_lbf.last_x();
  return Status::kOk;
}

}  // namespace

Status find_stacked_stage4_5_split(const DispersionSource& source, StackedStage45Split* split) {
  *split = StackedStage45Split{};
  const ThrustTable& thrust = source.vacuum_thrust_lbf;
  const WeightTable& weight = source.consumable_weight_lb;
  const double d4 = source.stage4_5_durations_s[0];
  const double d5 = source.stage4_5_durations_s[1];
  if (!(d4 > 0.0) || !(d5 > 0.0) || !std::isfinite(d4) || !std::isfinite(d5)) {
    return Status::kDispersionStageDurationsMismatch;
  }
  if (thrust.empty() || weight.empty()) return Status::kTableEmpty;
  const int n = thrust.size();
  if (weight.size() != n) return Status::kThrustWeightTimesDiffer;
  for (int i = 0; i < n; ++i) {
    if (thrust.x(i) != weight.x(i)) return Status::kThrustWeightTimesDiffer;
  }
  // Stage 4: the first run of increasing times, up to its entry at d4.
  int stage4_last = 0;
  while (stage4_last + 1 < n && thrust.x(stage4_last + 1) > thrust.x(stage4_last) &&
         (thrust.x(stage4_last + 1) <= d4 || same_time_s(thrust.x(stage4_last + 1), d4))) {
    ++stage4_last;
  }
  if (!same_time_s(thrust.x(stage4_last), d4)) return Status::kDispersionStageDurationsMismatch;
  // Stage 5: the last run when the times restart (at stage time 0), else the entries of the last
  // d5 seconds of the one continuing run.
  int restart = -1;
  for (int i = stage4_last + 1; i < n; ++i) {
    if (!(thrust.x(i) > thrust.x(i - 1))) restart = i;
  }
  const double end_s = thrust.x(n - 1);
  int stage5_first = -1;
  double offset_s = 0.0;
  if (restart >= 0) {
    if (thrust.x(restart) != 0.0) return Status::kDispersionStackedTablesNotSplittable;
    if (!same_time_s(end_s, d5)) return Status::kDispersionStageDurationsMismatch;
    stage5_first = restart;
  } else {
    const double ignition_s = end_s - d5;  // stage 4 duration + the coast as input
    if (!(ignition_s > thrust.x(stage4_last)) || same_time_s(ignition_s, thrust.x(stage4_last))) {
      return Status::kDispersionStackedTablesNotSplittable;  // no coast between the stages
    }
    for (int i = stage4_last + 1; i + 1 < n && stage5_first < 0; ++i) {
      if (same_time_s(thrust.x(i), ignition_s)) stage5_first = i;
    }
    if (stage5_first < 0) return Status::kDispersionStageDurationsMismatch;
    offset_s = thrust.x(stage5_first);
  }
  // The coast between them: zero thrust ("one segment of thrust equal to zero over the coast").
  for (int i = stage4_last + 1; i < stage5_first; ++i) {
    if (thrust.y(i) != 0.0) return Status::kDispersionStackedTablesNotSplittable;
    if (weight.y(i) < 0.0) return Status::kNegativeWeight;
  }
  Status status = check_replacement_part(thrust, weight, 0, stage4_last, 0.0);
  if (ok(status)) status = check_replacement_part(thrust, weight, stage5_first, n - 1, offset_s);
  if (!ok(status)) return status;
  split->stage4_last = stage4_last;
  split->stage5_first = stage5_first;
  split->stage5_offset_s = offset_s;
  return Status::kOk;
}

Status unstack_stage4_5_tables(const DispersionSource& source, StageData* stage4, StageData* stage5) {
  StackedStage45Split split;
  Status status = find_stacked_stage4_5_split(source, &split);
  if (ok(status)) status = copy_part(source, 0, split.stage4_last, 0.0, stage4);
  if (ok(status)) {
    status = copy_part(source, split.stage5_first, source.vacuum_thrust_lbf.size() - 1, split.stage5_offset_s,
                       stage5);
  }
  return status;
}

// The nominal per-point program carried onto a dispersed timeline: a stage whose grid is the
// nominal's keeps its values; one whose burn time changed (codes 1-8) flies the nominal program
// as a function of stage time (the guidance programmer's clock starts at each ignition), linear
// between the nominal points and continued at the last step's rate past the nominal burnout.
void map_control_program(const PreparedCase& nominal, const ControlProgram& program,
                         const PreparedCase& dispersed, ControlProgram* out) {
  out->point_count = program.point_count;
  out->theta_rad[0] = program.theta_rad[0];
  int first = 1;
  for (int slot = 0; slot < dispersed.stage_count; ++slot) {
    const StageTimeline& from = nominal.timeline[slot];
    const StageTimeline& to = dispersed.timeline[slot];
    const int n = to.steps + 1;
    if (same_grid(from, to)) {
      for (int i = 0; i < n; ++i) out->theta_rad[first + i] = program.theta_rad[first + i];
    } else {
      // The nominal interval [j, j + 1] holding tau (the last one past the end); tau increases
      // with i, so the search goes on from the last point's interval.
      int j = 0;
      for (int i = 0; i < n; ++i) {
        const double tau = point_stage_time_s(to, i);
        while (j + 2 < n && point_stage_time_s(from, j + 1) <= tau) ++j;
        const double t0 = point_stage_time_s(from, j);
        const double t1 = point_stage_time_s(from, j + 1);
        const double y0 = program.theta_rad[first + j];
        const double y1 = program.theta_rad[first + j + 1];
        out->theta_rad[first + i] = (t1 > t0) ? y0 + (y1 - y0) * (tau - t0) / (t1 - t0) : y0;
      }
    }
    first += n;
  }
}

void set_program_clock_shifts(const PreparedCase& nominal, const PreparedCase& dispersed,
                              FlightPerturbation* perturbation) {
  for (int slot = 0; slot < dispersed.stage_count && slot < nominal.stage_count; ++slot) {
    const StageTimeline& line = dispersed.timeline[slot];
    perturbation->program_clock_shift_s[stage_index(line.code)] =
        line.start_s - nominal.timeline[slot].start_s;
    // Stage 1's clock runs with its step grid, so that the zero-alpha window (a stage-1 rule, decided
    // on the step that starts in it: Sec. 22 IP(11)) opens and closes on the nominal's integration
    // points; the later stages' clocks run in stage time, as map_control_program.
    if (line.code == 1) perturbation->stage1_program_clock_rate = nominal.timeline[slot].step_s / line.step_s;
  }
}

bool dispersion_code_info(int code, DispersionCodeInfo* info) {
  for (const CodeRow& row : kCodeTable) {
    if (row.code != code) continue;
    info->code = row.code;
    info->kind = row.kind;
    info->plane = row.plane;
    info->stage = row.stage;
    info->high = row.high;
    info->name = row.name;
    return true;
  }
  return false;
}

int dispersion_source_stage(const DispersionSource& source) {
  DispersionCodeInfo info;
  if (!dispersion_code_info(source.code, &info)) return 0;
  if (info.kind == Kind::kTipoff) return source.stage;
  // Five stages without the squeeze: the stage-4 codes of thrust (7-8) and weight (15-16) name
  // stage 5 when the card's stage code says 5.
  if (info.stage == 4 && source.stage == 5 &&
      (info.kind == Kind::kVacuumThrust || info.kind == Kind::kWeightIncrement)) {
    return 5;
  }
  return info.stage;
}

Status validate_dispersion_data(const DispersionData& data, int* fault_code) {
  *fault_code = 0;
  if (data.count < 0 || data.count > kMaxDispersionSources) return Status::kDispersionCodeInvalid;
  int previous = 0;
  for (int k = 0; k < data.count; ++k) {
    const DispersionSource& s = data.sources[k];
    *fault_code = s.code;
    DispersionCodeInfo info;
    if (!dispersion_code_info(s.code, &info) || s.code <= previous) return Status::kDispersionCodeInvalid;
    previous = s.code;
    switch (info.kind) {
      case Kind::kVacuumThrust: {
        if (s.stage != 0 && s.stage != info.stage && !(info.stage == 4 && s.stage == 5)) {
          return Status::kDispersionStageCodeMismatch;
        }
        if (s.stacked_stage4_5_tables) {
          // Page 22-30: both stages "into the stage 4 tables" (stage code 4), split by block 55.
          if (s.stage == 5) return Status::kDispersionStageCodeMismatch;
          StackedStage45Split split;
          const Status status = find_stacked_stage4_5_split(s, &split);
          if (!ok(status)) return status;
          break;
        }
        if (s.vacuum_thrust_lbf.empty() || s.consumable_weight_lb.empty()) return Status::kTableEmpty;
        if (!s.vacuum_thrust_lbf.finalized() || !s.consumable_weight_lb.finalized()) {
          return Status::kTableNotMonotonic;
        }
        if (s.vacuum_thrust_lbf.size() != s.consumable_weight_lb.size()) {
          return Status::kThrustWeightTimesDiffer;
        }
        const Status status = check_replacement_part(s.vacuum_thrust_lbf, s.consumable_weight_lb, 0,
                                                     s.vacuum_thrust_lbf.size() - 1, 0.0);
        if (!ok(status)) return status;
        break;
      }
      case Kind::kPitchingMoment:
        if (s.pitching_moment_per_rad.empty()) return Status::kTableEmpty;
        if (!s.pitching_moment_per_rad.finalized()) return Status::kTableNotMonotonic;
        break;
      case Kind::kWind:
        if (s.wind.speed_ft_s.empty() || s.wind.azimuth_rad.empty()) return Status::kTableEmpty;
        if (!s.wind.speed_ft_s.finalized() || !s.wind.azimuth_rad.finalized()) {
          return Status::kTableNotMonotonic;
        }
        break;
      case Kind::kDrag:
        if (!(std::fabs(s.drag_variation_fraction) < 1.0)) return Status::kDispersionDragVariationOutOfRange;
        break;
      case Kind::kTipoff:
        if (s.stage != 4 && s.stage != 5) return Status::kDispersionStageNotSpun;
        break;
      case Kind::kWeightIncrement:
        // Stage 5 only through the stage-4 codes (15-16); otherwise the code's own stage.
        if (s.stage != 0 && s.stage != info.stage && !(info.stage == 4 && s.stage == 5)) {
          return Status::kDispersionStageCodeMismatch;
        }
        break;
      default: break;
    }
    const double scalars[] = {s.weight_increment_lb, s.drag_variation_fraction,
                              s.misalignment_rad,    s.thrust_station_ft,
                              s.deadband_rad,        s.tipoff_rad,
                              s.launch_change_rad};
    for (double value : scalars) {
      if (!std::isfinite(value)) return Status::kValueNotFinite;
    }
  }
  *fault_code = 0;
  return Status::kOk;
}

Status build_dispersed_case(const DispersionNominal& nominal, const PreparedCase& nominal_prepared,
                            const DispersionSource& source, DispersionWorkspace* ws) {
  DispersionCodeInfo info;
  if (!dispersion_code_info(source.code, &info) || info.kind == Kind::kNominal) {
    return Status::kDispersionCodeInvalid;
  }
  ws->mission = *nominal.mission;
  ws->monte_carlo_edits = DispersionWorkspace::MonteCarloEdits{};  // any member may change below
  ws->perturbation = FlightPerturbation{};
  Mission& m = ws->mission;
  FlightPerturbation& p = ws->perturbation;
  const int stage = dispersion_source_stage(source);
  if (stage != 0 && !in_sequence(m, stage)) return Status::kDispersionStageNotInSequence;

  switch (info.kind) {
    case Kind::kVacuumThrust: {
      // Blocks 30 and 38 replace the stage's tables; its burn time is the new table's last time.
      // prepare_case() below re-tabulates it (Sec. 14) at the dispersed burn time.
      if (source.stacked_stage4_5_tables) {
        // Page 22-30: stages 4 and 5 stacked in the stage-4 tables, both replaced; the coast 9
        // between them keeps its optimized length ("the program automatically changes this to
        // the optimized value").
        if (!in_sequence(m, 5)) return Status::kDispersionStackedTablesNeedStage5;
        const Status status = unstack_stage4_5_tables(source, &m.vehicle.stages[stage_index(4)],
                                                      &m.vehicle.stages[stage_index(5)]);
        if (!ok(status)) return status;
        break;
      }
      StageData& data = m.vehicle.stages[stage_index(stage)];
      data.vacuum_thrust_lbf = source.vacuum_thrust_lbf;
      data.consumable_weight_lb = source.consumable_weight_lb;
      data.duration_s = source.vacuum_thrust_lbf.last_x();
      // The tables' own rules (validate_dispersion_data); the rest of the case validated as the nominal.
      if (stage == 1 && !(data.duration_s > m.launch.liftoff_duration_s)) {
        return Status::kLiftoffLongerThanStage1;
      }
      break;
    }
    case Kind::kWeightIncrement:
      m.vehicle.stages[stage_index(stage)].jettison_weight_lb += source.weight_increment_lb;
      break;
    case Kind::kDrag:
      // "Percentage drag variation to be used for all stages": every drag table (stages 1, 6, 2).
      for (StageData& data : m.vehicle.stages) {
        AeroTable& cd = data.drag_coefficient;
        for (int i = 0; i < cd.size(); ++i) cd.set_y(i, cd.y(i) * (1.0 + source.drag_variation_fraction));
        if (!cd.empty()) {
          const Status status = cd.finalize();
          if (!ok(status)) return status;
        }
      }
      break;
    case Kind::kPitchingMoment: {
      if (!nominal.body_dynamics) return Status::kDispersionNeedsBodyDynamics;
      m.body_dynamics.pitching_moment_per_rad = source.pitching_moment_per_rad;
      break;
    }
    case Kind::kThrustMisalignment:
      if (!nominal.body_dynamics) return Status::kDispersionNeedsBodyDynamics;
      (info.plane == Plane::kYaw ? p.misalignment_yaw_rad : p.misalignment_pitch_rad) =
          source.misalignment_rad;
      p.thrust_station_ft = source.thrust_station_ft;
      break;
    case Kind::kControlDeadband:
      (info.plane == Plane::kYaw ? p.chi_offset_rad : p.theta_offset_rad)[stage_index(stage)] =
          source.deadband_rad;
      break;
    case Kind::kTipoff: {
      if (!m.options.stage_is_spun(stage)) return Status::kDispersionStageNotSpun;
      // The spin axis moves at separation and stays: the stage, its coast, and stage 5 when it
      // spins on stage 4's attitudes (IP(9) = 1).
      double* offsets = (info.plane == Plane::kYaw) ? p.chi_offset_rad : p.theta_offset_rad;
      offsets[stage_index(stage)] = source.tipoff_rad;
      offsets[stage_index(stage + 5)] = source.tipoff_rad;
      if (stage == 4 && m.options.spin_stages_4_5() == 1) {
        offsets[stage_index(5)] = source.tipoff_rad;
        offsets[stage_index(10)] = source.tipoff_rad;
      }
      break;
    }
    case Kind::kLaunchAzimuth:
      // The platform is aligned on the changed azimuth: the whole program turns with it.
      m.launch.azimuth_rad += source.launch_change_rad;
      break;
    case Kind::kLaunchAttitude:
      // A pitch reference error: every commanded attitude after the lift-off is off by the change.
      for (double& offset : p.theta_offset_rad) offset = source.launch_change_rad;
      break;
    case Kind::kWind: p.wind = &source.wind; break;
    case Kind::kNominal: return Status::kDispersionCodeInvalid;
  }

  // Only thrust and weight (Sec. 14's ideal velocities) and the launch azimuth (the launch matrices)
  // enter prepare_case; every other code's prepared case is the nominal's, exactly what
  // prepare_case would rebuild.
  const bool prepares = info.kind == Kind::kVacuumThrust || info.kind == Kind::kWeightIncrement ||
                        info.kind == Kind::kLaunchAzimuth;
  if (prepares) {
    const Status prepared = prepare_case(m, &ws->prepared);
    if (!ok(prepared)) return prepared;
  } else {
    ws->prepared = nominal_prepared;
  }
  ws->program_mapped = false;
  if (nominal.program != nullptr && info.kind == Kind::kVacuumThrust) {
    if (trajectory_point_count(ws->prepared) != nominal.program->point_count) {
      return Status::kControlProgramSizeMismatch;
    }
    map_control_program(nominal_prepared, *nominal.program, ws->prepared, &ws->program);
    ws->program_mapped = true;
  } else if (info.kind == Kind::kVacuumThrust) {
    set_program_clock_shifts(nominal_prepared, ws->prepared, &p);
  }
  return Status::kOk;
}

FlightInputs dispersion_flight_inputs(const DispersionNominal& nominal) {
  FlightInputs inputs;
  inputs.program = nominal.program;
  inputs.body_dynamics = nominal.body_dynamics;
  inputs.trig_by_series = true;
  return inputs;
}

Status fly_dispersed_case(const DispersionNominal& nominal, DispersionWorkspace* ws,
                          DispersedTrajectory* out) {
  FlightInputs inputs = dispersion_flight_inputs(nominal);
  if (ws->program_mapped) inputs.program = &ws->program;
  inputs.perturbation = &ws->perturbation;
  // Only what the record reads (lean points, the air-relative alpha kept from the flight).
  inputs.lean_points = true;
  inputs.air_alpha_rad = ws->air_alpha_rad;
  const Status status = fly_trajectory(ws->mission, ws->prepared, inputs, &ws->dispersed);
  if (!ok(status)) return status;
  return record_dispersed_trajectory(ws->mission, ws->prepared, ws->nominal, ws->dispersed,
                                     ws->perturbation.wind, ws->air_alpha_rad, out);
}

Status record_dispersed_trajectory(const Mission& mission, const PreparedCase& prepared,
                                   const Trajectory& reference, const Trajectory& flown,
                                   const WindProfile* wind, DispersedTrajectory* out) {
  return record_dispersed_trajectory(mission, prepared, reference, flown, wind, nullptr, out);
}

Status record_dispersed_trajectory(const Mission& mission, const PreparedCase& prepared,
                                   const Trajectory& reference, const Trajectory& flown,
                                   const WindProfile* wind, const double* air_alpha_rad,
                                   DispersedTrajectory* out) {
  if (!ok(flown.status) || flown.point_count <= 0) {
    return ok(flown.status) ? Status::kTrajectoryEmpty : flown.status;
  }
  // Columns: the ignition of each powered stage after the first in the reference, then the final point.
  int columns = 0;
  int reference_points[kMaxStagingPoints] = {};
  int flown_points[kMaxStagingPoints] = {};
  for (int k = 0; k < reference.stage_count && columns + 1 < kMaxStagingPoints; ++k) {
    const int code = reference.stages[k].code;
    if (!is_powered_stage(code) || code == 1) continue;
    int flown_point = -1;
    for (int f = 0; f < flown.stage_count; ++f) {
      if (flown.stages[f].code == code) flown_point = flown.stages[f].first_point;
    }
    if (flown_point < 0) return Status::kDispersionStageNotInSequence;
    reference_points[columns] = reference.stages[k].first_point;
    flown_points[columns] = flown_point;
    ++columns;
  }
  reference_points[columns] = reference.point_count - 1;
  flown_points[columns] = flown.point_count - 1;
  ++columns;

  for (int j = 0; j < columns; ++j) {
    const TrajectoryPoint& n = reference.points[reference_points[j]];
    const TrajectoryPoint& d = flown.points[flown_points[j]];
    double* v = out->values[j];
    v[static_cast<int>(StagingVariable::kAltitude)] = d.altitude_ft;
    v[static_cast<int>(StagingVariable::kVelocity)] = d.state[kStateV];
    v[static_cast<int>(StagingVariable::kFlightPathAngle)] = d.state[kStateGamma];
    // The point's downrange_rad recomputed as the flight does (so lean points, which leave it 0,
    // give the same figure bit for bit).
    const double launch_latitude = mission.launch.geocentric_latitude_rad;
    const double latitude = d.state[kStateLambda];
    v[static_cast<int>(StagingVariable::kDownrange)] =
        downrange_angle_rad(std::sin(launch_latitude), std::cos(launch_latitude), std::sin(latitude),
                            std::cos(latitude), d.earth_longitude_rad - mission.launch.longitude_rad) *
        kNauticalMilesPerRadian;
    // Sec. 4: crossrange from the plane of motion at the nominal staging point (0 on the nominal).
    v[static_cast<int>(StagingVariable::kCrossrange)] =
        crossrange_angle_rad(n.state[kStateLambda], n.earth_longitude_rad, n.state[kStatePsi],
                             d.state[kStateLambda],
                             d.earth_longitude_rad) *
            kNauticalMilesPerRadian +
        0.0;  // the nominal's own crossrange is -0: print it as 0
  }

  OrbitElements elements;
  const Status orbit = compute_orbit_elements(mission.constants, flown.final_point().state,
                                              mission.launch.launch_space_age_date_days, &elements);
  if (!ok(orbit)) return orbit;
  out->orbit[0] = elements.twice_energy_ft2_s2;
  out->orbit[1] = elements.angular_momentum_ft2_s;
  out->orbit[2] = elements.perigee_radius_ft;
  out->orbit[3] = elements.inclination_rad;
  out->orbit[4] = elements.argument_of_perigee_rad;
  out->orbit[5] = elements.node_longitude_rad;

  // Max |q-bar alpha|; under a wind the angle is against the air mass, as flown (wind.hpp).
  out->max_qbar_alpha_lbf_rad_ft2 = 0.0;
  out->max_qbar_alpha_time_s = 0.0;
  for (int k = 0; k < flown.point_count; ++k) {
    const TrajectoryPoint& point = flown.points[k];
    double alpha = point.alpha_rad;
    if (air_alpha_rad != nullptr) {
      alpha = air_alpha_rad[k];
    } else if (wind != nullptr && point.dynamic_pressure_lbf_ft2 > 0.0) {
      const double speed = wind->speed_ft_s(point.altitude_ft);
      if (speed != 0.0) {
        const StateTrig trig(point.state);
        const Vector3 air =
            air_relative_velocity_local(point.state, trig, speed, wind->azimuth_rad(point.altitude_ft));
        if (air.norm() > 0.0) {
          const Matrix3 platform_to_local = inertial_to_local(trig) * prepared.platform_to_inertial;
          alpha = air_angle_of_attack_rad(
              local_to_air_frame(air),
              platform_to_local * thrust_axis_platform(point.theta_rad, point.chi_rad));
        }
      }
    }
    const double qbar_alpha = std::fabs(point.dynamic_pressure_lbf_ft2 * alpha);
    if (qbar_alpha > out->max_qbar_alpha_lbf_rad_ft2) {
      out->max_qbar_alpha_lbf_rad_ft2 = qbar_alpha;
      out->max_qbar_alpha_time_s = point.time_s;
    }
  }
  return Status::kOk;
}

bool is_high_dispersion(const DispersedTrajectory& t, int final_column) {
  const double altitude = t.dispersions[final_column][static_cast<int>(StagingVariable::kAltitude)];
  if (altitude != 0.0) return altitude > 0.0;
  return t.dispersions[final_column][static_cast<int>(StagingVariable::kVelocity)] > 0.0;
}

void compute_three_sigma(DispersionResult* result) {
  ThreeSigmaSummary& s = result->three_sigma;
  s.yaw = ThreeSigmaGroup{};
  s.high = ThreeSigmaGroup{};
  s.low = ThreeSigmaGroup{};
  s.high_with_winds = ThreeSigmaGroup{};
  s.low_with_winds = ThreeSigmaGroup{};
  const int columns = result->staging_count;
  const int final_column = columns - 1;
  // The yaw trajectories first, then high/low without winds; the high/low winds join last.
  for (int pass = 0; pass < 2; ++pass) {
    for (int k = 0; k < result->count; ++k) {
      const DispersedTrajectory& t = result->trajectories[k];
      DispersionCodeInfo info;
      if (!ok(t.status) || !dispersion_code_info(t.code, &info)) continue;
      const bool wind = info.kind == Kind::kWind;
      if (info.plane == Plane::kYaw) {
        if (pass == 0) accumulate(t, columns, &s.yaw);
        continue;
      }
      if (info.plane != Plane::kHighLow) continue;
      const bool high = is_high_dispersion(t, final_column);
      if (pass == 0 && !wind) {
        accumulate(t, columns, high ? &s.high : &s.low);
        accumulate(t, columns, high ? &s.high_with_winds : &s.low_with_winds);
      } else if (pass == 1 && wind) {
        accumulate(t, columns, high ? &s.high_with_winds : &s.low_with_winds);
      }
    }
  }
  finish(columns, &s.yaw);
  finish(columns, &s.high);
  finish(columns, &s.low);
  finish(columns, &s.high_with_winds);
  finish(columns, &s.low_with_winds);
  s.computed = true;
}

Status run_dispersions(const DispersionNominal& nominal, const DispersionData& data, DispersionWorkspace* ws,
                       DispersionResult* result) {
  result->count = 0;
  result->fault_code = 0;
  result->staging_count = 0;
  result->three_sigma = ThreeSigmaSummary{};
  result->nominal = DispersedTrajectory{};
  result->nominal.code = kNominalDispersionCode;
  if (nominal.mission == nullptr) return result->status = Status::kDispersionNominalNotPrepared;
  int fault_code = 0;
  Status status = validate_dispersion_data(data, &fault_code);
  result->fault_code = fault_code;
  if (!ok(status)) return result->status = status;

  // GIANT plane 40: the nominal, prepared and flown by the same rules as every dispersed case.
  status = prepare_case(*nominal.mission, &ws->nominal_prepared);
  if (!ok(status)) return result->status = status;
  status =
      fly_trajectory(*nominal.mission, ws->nominal_prepared, dispersion_flight_inputs(nominal), &ws->nominal);
  if (ok(status)) {
    status = record_dispersed_trajectory(*nominal.mission, ws->nominal_prepared, ws->nominal, ws->nominal,
                                         nullptr, &result->nominal);
  }
  result->nominal.status = status;
  copy_title("NOMINAL TRAJ", result->nominal.title);
  if (!ok(status)) return result->status = status;
  int columns = 0;
  for (int k = 0; k < ws->nominal.stage_count && columns + 1 < kMaxStagingPoints; ++k) {
    const int code = ws->nominal.stages[k].code;
    if (is_powered_stage(code) && code != 1) result->staging_stage_code[columns++] = code;
  }
  result->staging_stage_code[columns++] = 0;
  result->staging_count = columns;

  bool three_sigma = false;
  for (int k = 0; k < data.count; ++k) {
    const DispersionSource& source = data.sources[k];
    if (source.code == kNominalDispersionCode) {
      three_sigma = true;
      continue;
    }
    DispersedTrajectory& out = result->trajectories[result->count++];
    out = DispersedTrajectory{};
    out.code = source.code;
    copy_title(source.title, out.title);
    Status code_status = build_dispersed_case(nominal, ws->nominal_prepared, source, ws);
    if (ok(code_status)) code_status = fly_dispersed_case(nominal, ws, &out);
    out.status = code_status;
    if (!ok(code_status)) continue;
    for (int j = 0; j < columns; ++j) {
      for (int i = 0; i < kStagingVariables; ++i) {
        out.dispersions[j][i] = out.values[j][i] - result->nominal.values[j][i];
      }
    }
    for (int i = 0; i < kOrbitDispersionElements; ++i) {
      const double d = out.orbit[i] - result->nominal.orbit[i];
      out.orbit_dispersions[i] = (i >= 3) ? wrap_angle_rad(d) : d;
    }
  }
  if (three_sigma) compute_three_sigma(result);
  return result->status = Status::kOk;
}

}  // namespace tolip
