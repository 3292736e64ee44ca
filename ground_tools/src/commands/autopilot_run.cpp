// Autopilot gains designed along the trajectory (tolip_ground/autopilot_run.hpp).
#include "tolip_ground/autopilot_run.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "../report/listing_pager.hpp"
#include "tolip/core/constants.hpp"
#include "tolip/core/stage_codes.hpp"
#include "tolip_ground/guidance_table.hpp"
#include "tolip_ground/hardover_run.hpp"

namespace tolip::ground {
namespace {

using json = nlohmann::ordered_json;

json number(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

std::string indexed(const char* key, int stage) {
  return std::string("body_dynamics.") + key + "[" + std::to_string(stage - 1) + "]";
}

const char* status_word(Status status) {
  switch (status) {
    case Status::kAutopilotDampingNotPositive: return "autopilot_damping_ratio";
    case Status::kAutopilotFrequencyNotPositive:
    case Status::kAutopilotFrequencyBeyondDeflection:
    case Status::kAutopilotGainOutOfRange: return "autopilot_natural_frequency_rad_s";
    case Status::kAutopilotRequestInvalid: return "autopilot_attitude_error_deg";
    case Status::kTooManyGainSchedulePoints: return "autopilot_points_per_stage";
    default: return "";
  }
}

int data_block_of(Status status) {
  return (status == Status::kHardoverInertiaMissing || status == Status::kAutopilotModelInvalid) ? 44 : 33;
}

}  // namespace

std::string autopilot_fault_key(Status status, int stage) {
  const char* word = status_word(status);
  if (*word == '\0') return "hardover.pitch_inertia." + std::to_string(stage);
  if (status == Status::kAutopilotRequestInvalid || status == Status::kTooManyGainSchedulePoints)
    return std::string("body_dynamics.") + word;
  return indexed(word, stage);
}

bool plan_autopilot_design(const Mission& mission, const DeckExtras& extras, AutopilotPlan* plan,
                           std::string* message) {
  const AutopilotDesignData& d = extras.autopilot;
  auto fail = [&](const std::string& key, int stage, const std::string& what) {
    *message =
        "data block 33, " + key + (stage > 0 ? " (stage " + std::to_string(stage) + ")" : "") + ": " + what;
    return false;
  };
  if (d.points_per_stage < 1 || d.points_per_stage > kMaxGainSchedulePointsPerStage) {
    return fail("body_dynamics.autopilot_points_per_stage", 0,
                "gain schedule of " + std::to_string(d.points_per_stage) +
                    " points per stage: the table image holds " +
                    std::to_string(kMaxGainSchedulePointsPerStage) + " per stage 1-3 (" +
                    std::to_string(kMaxGainSchedulePoints) + " records); expected 1-" +
                    std::to_string(kMaxGainSchedulePointsPerStage));
  }
  if (!(d.attitude_error_rad > 0.0)) {
    return fail("body_dynamics.autopilot_attitude_error_deg", 0,
                "the design attitude error must be positive, got " +
                    std::to_string(d.attitude_error_rad * kRadToDeg) + " deg");
  }
  if (!(d.actuator_time_constant_s >= 0.0)) {
    return fail("body_dynamics.autopilot_actuator_time_constant_s", 0,
                "the actuator time constant must not be negative, got " +
                    std::to_string(d.actuator_time_constant_s) + " s");
  }
  plan->points_per_stage = d.points_per_stage;
  const double limit = table_max_deflection_rad(extras);
  for (int k = 0; k < kGainScheduleStages; ++k) {
    const int stage = k + 1;
    plan->designed[k] = mission.vehicle.stages[stage_index(stage)].in_sequence;
    if (!plan->designed[k]) continue;
    if (!(d.damping_ratio[k] > 0.0)) {
      return fail(indexed("autopilot_damping_ratio", stage), stage,
                  "the damping ratio must be positive, got " + std::to_string(d.damping_ratio[k]));
    }
    if (!(d.natural_frequency_rad_s[k] > 0.0)) {
      return fail(indexed("autopilot_natural_frequency_rad_s", stage), stage,
                  "the natural frequency must be positive, got " +
                      std::to_string(d.natural_frequency_rad_s[k]) + " rad/s");
    }
    AutopilotRequest& r = plan->requests[k];
    r.natural_frequency_rad_s = d.natural_frequency_rad_s[k];
    r.damping_ratio = d.damping_ratio[k];
    r.attitude_error_rad = d.attitude_error_rad;
    r.max_deflection_rad = limit;
    r.actuator_time_constant_s = d.actuator_time_constant_s;
  }
  if (!extras.hardover.present) {
    *message =
        "data block 44, hardover.pitch_inertia: designed autopilot gains "
        "(body_dynamics.autopilot_designed_gains = 1) "
        "need the pitch inertia of data block 44 ([hardover], the I_yy tables)";
    return false;
  }
  plan->hardover = std::make_unique<tolip::HardoverData>();
  HardoverMappingFault mapping;
  if (!fill_hardover_data(extras.hardover, plan->hardover.get(), &mapping)) {
    *message =
        "data block " + std::to_string(mapping.data_block) + ", " + mapping.field + ": " + mapping.message;
    return false;
  }
  for (int k = 0; k < kGainScheduleStages; ++k) {
    const HardoverTable& iyy = plan->hardover->stages[k].pitch_inertia_slug_ft2;
    if (plan->designed[k] && (iyy.empty() || !iyy.finalized())) {
      *message = "data block 44, hardover.pitch_inertia." + std::to_string(k + 1) + " (stage " +
                 std::to_string(k + 1) + "): designed autopilot gains need the stage's pitch inertia I_yy";
      return false;
    }
  }
  return true;
}

void run_autopilot_step(const Mission& mission, const AutopilotPlan& plan, const Trajectory& trajectory,
                        const std::string& kind, AutopilotStep* step) {
  step->outcome = StepOutcome::kRun;
  step->trajectory_kind = kind;
  step->schedule = std::make_unique<GainScheduleDesign>();
  step->status = design_gain_schedule(mission, trajectory, *plan.hardover, plan.requests, plan.designed,
                                      plan.points_per_stage, step->schedule.get(), &step->fault_stage);
}

std::string autopilot_fault_text(const AutopilotStep& step) {
  const int stage = step.fault_stage;
  std::string text = "data block " + std::to_string(data_block_of(step.status)) + ", " +
                     autopilot_fault_key(step.status, stage) + " (stage " + std::to_string(stage) +
                     ", along the " + step.trajectory_kind + " trajectory): " + status_name(step.status) +
                     ": " + status_message(step.status);
  return text;
}

std::string SixDAutopilotGains::fault_text() const {
  AutopilotStep failed;
  failed.outcome = StepOutcome::kRun;
  failed.status = status_;
  failed.fault_stage = fault_stage_;
  failed.trajectory_kind = "point-mass linearized program";
  return autopilot_fault_text(failed);
}

Status SixDAutopilotGains::before_body_dynamics(const Trajectory& point_mass_nominal, Mission* mission) {
  called_ = true;
  auto schedule = std::make_unique<GainScheduleDesign>();
  status_ = design_gain_schedule(*mission, point_mass_nominal, *plan_.hardover, plan_.requests,
                                 plan_.designed, plan_.points_per_stage, schedule.get(), &fault_stage_);
  if (!ok(status_)) return status_;
  set_stage1_schedule(*schedule, &mission->body_dynamics);
  return Status::kOk;
}

void set_stage1_schedule(const GainScheduleDesign& schedule, BodyDynamicsBlocks* body) {
  int n = 0;
  for (int i = 0; i < schedule.count && n < kMaxGainSchedulePointsPerStage; ++i) {
    const GainScheduleDesignPoint& p = schedule.points[i];
    if (p.stage_code != 1) continue;
    body->stage1_schedule_time_s[n] = p.stage_time_s;
    body->stage1_schedule_k_theta[n] = p.design.k_theta;
    body->stage1_schedule_k_q_s[n] = p.design.k_q_s;
    ++n;
  }
  body->stage1_schedule_count = n;
}

void apply_gain_schedule(const GainScheduleDesign& schedule, GuidanceTable* table) {
  table->schedule_count = 0;
  for (int i = 0; i < schedule.count && i < kMaxGainSchedulePoints; ++i) {
    const GainScheduleDesignPoint& p = schedule.points[i];
    table->schedule[table->schedule_count++] =
        GainSchedulePoint{p.stage_code, p.stage_time_s, p.design.k_theta, p.design.k_q_s};
    const bool last_of_stage = i + 1 == schedule.count || schedule.points[i + 1].stage_code != p.stage_code;
    // The coast after the stage (codes 6-8) holds the stage's last gains.
    if (last_of_stage && p.stage_code >= 1 && p.stage_code <= 3) {
      table->gains[stage_index(p.stage_code + 5)] = StageGains{p.design.k_theta, p.design.k_q_s};
    }
  }
}

json autopilot_json(const AutopilotStep& step) {
  json a = json::object();
  const bool computed = step.outcome == StepOutcome::kRun && ok(step.status);
  a["computed"] = computed;
  a["status"] = status_name(step.status);
  a["status_message"] = status_message(step.status);
  a["trajectory"] = step.trajectory_kind;
  a["six_d_scheduled"] = step.six_d_scheduled;
  if (step.outcome == StepOutcome::kRun && !ok(step.status)) {
    a["fault"] = {{"stage", step.fault_stage}, {"key", autopilot_fault_key(step.status, step.fault_stage)}};
  }
  json points = json::array();
  if (computed) {
    for (int i = 0; i < step.schedule->count; ++i) {
      const GainScheduleDesignPoint& p = step.schedule->points[i];
      const AutopilotDesign& d = p.design;
      auto roots = [](const RootPair& r) {
        json out = json::array();
        for (int k = 0; k < 2; ++k) out.push_back(json{{"re", number(r.re[k])}, {"im", number(r.im[k])}});
        return out;
      };
      json point = json::object();
      point["stage"] = p.stage_code;
      point["time_s"] = number(p.time_s);
      point["stage_time_s"] = number(p.stage_time_s);
      point["mach"] = number(p.condition.moments.mach);
      point["dynamic_pressure_lbf_ft2"] = number(p.condition.moments.dynamic_pressure_lbf_ft2);
      point["pitch_inertia_slug_ft2"] = number(d.model.pitch_inertia_slug_ft2);
      point["m_alpha_lbf_ft_per_rad"] = number(d.model.m_alpha_lbf_ft_per_rad);
      point["m_delta_lbf_ft_per_rad"] = number(d.model.m_delta_lbf_ft_per_rad);
      point["m_q_lbf_ft_s_per_rad"] =
          number(d.model.m_q_aero_lbf_ft_s_per_rad + d.model.m_q_jet_lbf_ft_s_per_rad);
      point["open_loop_poles"] = roots(d.open_loop);
      point["k_theta"] = number(d.k_theta);
      point["k_q_s"] = number(d.k_q_s);
      point["closed_loop_poles"] = roots(d.closed_loop);
      point["upper_gain_margin"] = number(d.margins.upper_gain_margin);  // factor; null: infinite
      point["upper_gain_margin_db"] = number(20.0 * std::log10(d.margins.upper_gain_margin));
      point["lower_gain_margin"] = number(d.margins.lower_gain_margin);
      point["lower_gain_margin_db"] = d.margins.lower_gain_margin > 0.0
                                          ? number(20.0 * std::log10(d.margins.lower_gain_margin))
                                          : json(nullptr);
      point["phase_margin_deg"] = number(d.margins.phase_margin_rad * kRadToDeg);
      point["crossover_rad_s"] = number(d.margins.crossover_rad_s);
      point["step_deflection_deg"] = number(d.step_deflection_rad * kRadToDeg);
      points.push_back(std::move(point));
    }
  }
  a["points"] = std::move(points);
  return a;
}

namespace report_detail {

void write_autopilot_pages(Pager& pager, const AutopilotStep& step) {
  if (step.outcome == StepOutcome::kNotRequested) return;
  pager.new_page("AUTOPILOT GAIN SCHEDULE", false);
  if (!(step.outcome == StepOutcome::kRun && ok(step.status))) {
    pager.emit(" AUTOPILOT GAINS NOT DESIGNED: " + std::string(status_name(step.status)) + ": " +
               status_message(step.status) +
               (step.outcome == StepOutcome::kRun ? " (" + autopilot_fault_text(step) + ")" : ""));
    return;
  }
  pager.emit(" AUTOPILOT GAINS DESIGNED ALONG THE " +
             std::string(step.trajectory_kind == "linearized program" ? "LINEARIZED PROGRAM"
                         : step.trajectory_kind == "optimum"          ? "OPTIMUM"
                                                                      : "SIMULATED") +
             " TRAJECTORY (ISSUE 16, SEC. 7 EQS. 7-1 TO 7-3, SEC. 16 MOMENTS)");
  if (step.six_d_scheduled) pager.emit(" THE 6D RE-LINEARIZATION FLEW THE DESIGNED STAGE-1 SCHEDULE");
  pager.emit("");
  pager.emit(
      " STG     TIME    STAGE T     M ALPHA     M DELTA   OPEN-LOOP POLES     K THETA     K Q    CLOSED-LOOP "
      "POLES"
      "      GM+    GM-     PM");
  pager.emit(
      "          SEC        SEC  FT-LB/RAD   FT-LB/RAD   1/S                 DEG/DEG       S   1/S           "
      "     "
      "       DB     DB    DEG");
  char line[240];
  for (int i = 0; i < step.schedule->count; ++i) {
    const GainScheduleDesignPoint& p = step.schedule->points[i];
    const AutopilotDesign& d = p.design;
    auto pair = [](const RootPair& r, char* out, std::size_t size) {
      if (r.im[0] != 0.0) {
        std::snprintf(out, size, "%8.4f+-%7.4fj", r.re[0], std::fabs(r.im[0]));
      } else {
        std::snprintf(out, size, "%8.4f,%8.4f ", r.re[0], r.re[1]);
      }
    };
    char open[40], closed[40];
    pair(d.open_loop, open, sizeof open);
    pair(d.closed_loop, closed, sizeof closed);
    const double gm_up = d.margins.upper_gain_margin;
    const double gm_low = d.margins.lower_gain_margin;
    char up[16], low[16];
    if (std::isfinite(gm_up)) std::snprintf(up, sizeof up, "%6.1f", 20.0 * std::log10(gm_up));
    else std::snprintf(up, sizeof up, "%6s", "INF");
    if (gm_low > 0.0) std::snprintf(low, sizeof low, "%6.1f", 20.0 * std::log10(gm_low));
    else std::snprintf(low, sizeof low, "%6s", "-");
    std::snprintf(line, sizeof line,
                  " %3d %8.2f %10.2f %11.4E %11.4E  %-18s %8.4f %7.4f  %-18s %6s %6s %6.1f", p.stage_code,
                  p.time_s, p.stage_time_s, d.model.m_alpha_lbf_ft_per_rad, d.model.m_delta_lbf_ft_per_rad,
                  open, d.k_theta, d.k_q_s, closed, up, low, d.margins.phase_margin_rad * kRadToDeg);
    pager.emit(line);
  }
}

}  // namespace report_detail

}  // namespace tolip::ground
