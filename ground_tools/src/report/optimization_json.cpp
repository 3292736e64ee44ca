// The JSON document of `tolip optimize --json`: the `simulate --json` document of the final
// trajectory, with the optimizer's status and results inserted before `trajectory` (schema:
// docs/cli.md).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "number_format.hpp"
#include "tolip/core/constants.hpp"
#include "tolip/core/state.hpp"
#include "tolip_ground/autopilot_run.hpp"
#include "tolip_ground/dispersion_report.hpp"
#include "tolip_ground/hardover_report.hpp"
#include "tolip_ground/impact_report.hpp"
#include "tolip_ground/optimization_report.hpp"
#include "tolip_ground/radar_report.hpp"

namespace tolip::ground {
namespace {

using json = nlohmann::ordered_json;
using report_detail::json_number;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

json payoff_json(const PayoffSummary& payoff) {
  return json{
      {"kind", payoff.kind},
      {"code", payoff.code},
      {"unit", payoff.unit},
      {"value", json_number(payoff.value)},
      {"corrected_value", json_number(payoff.corrected)},
  };
}

json adjustable_json(const std::vector<AdjustableSummary>& adjustable) {
  json array = json::array();
  for (const AdjustableSummary& a : adjustable) {
    array.push_back(json{
        {"code", a.code},
        {"name", a.name},
        {"value", json_number(a.value)},
        {"initial_value", json_number(a.initial_value)},
        {"unit", a.unit},
    });
  }
  return array;
}

json iterations_json(const OptimizationReport& report, int rows) {
  const OptimizerResult& result = *report.result;
  json array = json::array();
  const int count = std::clamp(result.iteration_count, 0, kMaxOptimizerIterations);
  for (int k = 0; k < count; ++k) {
    const IterationRecord& r = result.iterations[k];
    json corrections = json::array();
    json partials = json::array();
    json held = json::array();
    for (int i = 1; i <= rows && i < kMaxConstraints; ++i) {
      corrections.push_back(json_number(r.constraint_corrections[i]));
      partials.push_back(json_number(r.payoff_partials[i]));
      held.push_back(r.constraint_held[i]);
    }
    array.push_back(json{
        {"forward_run", r.forward_run},
        {"kind", run_kind_name(r.kind)},
        {"run_status", status_name(r.run_status)},
        {"successful", r.successful},
        {"attempted_payoff_improvement", json_number(r.attempted_payoff_improvement)},
        {"payoff", json_number(r.payoff)},
        {"corrected_payoff", json_number(r.corrected_payoff)},
        {"payload_lb", json_number(r.payload_lb)},
        {"payload_increment_lb", json_number(r.payload_increment_lb)},
        {"constraint_corrections", std::move(corrections)},
        {"payoff_partials", std::move(partials)},
        {"constraints_held", std::move(held)},
    });
  }
  return array;
}

// Weak directions of the steering matrix (docs/theory/optimizer.md "Weak directions"): one object per
// entry of `constraints`.
json held_constraints_json(const OptimizerResult& result, int rows) {
  json array = json::array();
  for (int i = 1; i <= rows && i < kMaxConstraints; ++i) {
    json entry = json{{"code", result.codes[i]},
                      {"held_runs", result.held_runs[i]},
                      {"held_at_end", result.constraint_held[i]},
                      {"steerability_deadbands", json_number(result.steerability_deadbands[i])}};
    if (result.held_runs[i] > 0) {
      entry["message"] = "constraint " + std::to_string(i) + " (code " + std::to_string(result.codes[i]) +
                         ") has no first-order effect: held by deadband";
    }
    // Deferred (argument of perigee while the orbit's shape is corrected): member only when > 0.
    if (result.deferred_runs[i] > 0) entry["deferred_runs"] = result.deferred_runs[i];
    array.push_back(std::move(entry));
  }
  return array;
}

json theta_history_json(const Trajectory& trajectory) {
  json array = json::array();
  const int count = stored_point_count(trajectory);
  for (int k = 0; k < count; ++k) {
    const TrajectoryPoint& p = trajectory.points[k];
    array.push_back(json::array({json_number(p.time_s), json_number(p.theta_rad * kRadToDeg)}));
  }
  return array;
}

// One object per powered stage (units in docs/cli.md); null when asked for but not computed.
json exchange_ratios_json(const OptimizationReport& report) {
  if (report.exchange_ratios == nullptr) return json(nullptr);
  const ExchangeRatios& r = *report.exchange_ratios;
  json array = json::array();
  const int count = std::clamp(r.stage_count, 0, kMaxPoweredStages);
  for (int s = 0; s < count; ++s) {
    array.push_back(json{
        {"stage", r.stage_codes[s]},
        {"burn_rate", json_number(r.burn_rate[s])},
        {"propellant_weight", json_number(r.propellant_weight[s])},
        {"specific_impulse", json_number(r.specific_impulse[s])},
        {"drag", json_number(r.drag[s])},
        {"jettison_weight", json_number(r.jettison_weight[s])},
    });
  }
  return array;
}

// The peak q-bar x alpha of a trajectory (docs/cli.md "qbar_alpha").
json qbar_alpha_json(const Mission& mission, const Trajectory& trajectory) {
  const QbarAlphaSummary q = qbar_alpha_summary(mission, trajectory);
  return json{
      {"lift_peak_lb_deg_ft2", json_number(q.lift_peak_lb_deg_ft2)},
      {"lift_peak_time_s", json_number(q.lift_peak_time_s)},
      {"peak_lb_deg_ft2", json_number(q.peak_lb_deg_ft2)},
      {"peak_time_s", json_number(q.peak_time_s)},
      {"limit_lb_deg_ft2", q.limit_lb_deg_ft2 > 0.0 ? json_number(q.limit_lb_deg_ft2) : json(nullptr)},
      {"excess_integral_s", json_number(q.excess_integral_s)},
      {"met", q.met},
  };
}

// The linearized program (docs/cli.md): null when asked for but not run; otherwise the best program
// found, with the status that says whether it meets the constraints and the rate limits.
json linearized_json(const OptimizationReport& report) {
  if (report.linearization == nullptr || !report.linearization->finished) {
    return json{{"status", status_name(report.linearization_status)},
                {"status_message", status_message(report.linearization_status)},
                {"segments", json::array()}};
  }
  const LinearizationResult& r = *report.linearization;
  const LinearProgram& p = r.program;
  json segments = json::array();
  const int count = std::clamp(p.segment_count, 0, kMaxLinearSegments);
  for (int s = 0; s < count; ++s) {
    const bool merged = rate_continues_previous(p, s);
    segments.push_back(json{
        {"stage", p.stage_code[s]},
        {"start_stage_time_s", json_number(p.start_stage_time_s[s])},
        {"start_time_s", json_number(p.break_time_s[s])},
        {"theta_deg", json_number(p.theta_rad[s] * kRadToDeg)},
        {"rate_deg_s", json_number(p.rate_rad_s[s] * kRadToDeg)},
        {"rate_continues_previous", merged},
    });
  }
  json constraints = json::array();
  for (int j = 0; j < std::clamp(r.constraint_count, 0, kMaxConstraints); ++j) {
    constraints.push_back(json{
        {"code", r.codes[j]},
        {"desired", json_number(r.desired[j])},
        {"achieved", json_number(r.achieved[j])},
        {"tolerance", json_number(r.tolerance[j])},
        {"met", r.met[j]},
    });
  }
  return json{
      {"status", status_name(report.linearization_status)},
      {"status_message", status_message(report.linearization_status)},
      {"segments", std::move(segments)},
      {"end_time_s", json_number(count > 0 ? p.break_time_s[count] : kNaN)},
      {"end_theta_deg", json_number(count > 0 ? p.theta_rad[count] * kRadToDeg : kNaN)},
      {"constraints_met", r.constraints_met},
      {"rate_limits_met", r.rate_limits_met},
      {"payoff", json_number(r.payoff)},
      {"optimum_payoff", json_number(report.optimum_payoff)},
      {"forward_runs", r.forward_runs},
      {"backward_runs", r.backward_runs},
      {"programs_computed", r.programs_computed},
      {"rate_repairs", p.rate_repair_count},
      {"coast7_below_min_rate", r.coast7_below_min_rate},
      {"coast7_below_min_rate_change", r.coast7_below_min_rate_change},
      {"constraints", std::move(constraints)},
      {"qbar_alpha", report.linearized_trajectory != nullptr && report.linearized_mission != nullptr
                         ? qbar_alpha_json(*report.linearized_mission, *report.linearized_trajectory)
                         : json(nullptr)},
      {"trajectory", report.linearized_trajectory != nullptr
                         ? trajectory_points_json(*report.linearized_trajectory)
                         : json(nullptr)},
  };
}

// The end of a trajectory in the quantities a 6D comparison needs.
json terminal_json(const Trajectory& t) {
  const TrajectoryPoint& p = t.final_point();
  return json{
      {"time_s", json_number(p.time_s)},
      {"altitude_ft", json_number(p.altitude_ft)},
      {"velocity_ft_s", json_number(p.state(kStateV))},
      {"flight_path_angle_deg", json_number(p.state(kStateGamma) * kRadToDeg)},
      {"inertial_velocity_ft_s", json_number(p.inertial.velocity_ft_s)},
      {"inertial_flight_path_angle_deg", json_number(p.inertial.flight_path_angle_rad * kRadToDeg)},
  };
}

// Body dynamics (IP(6); docs/cli.md): the 6D re-linearization (1) or the initial nominal flown
// point mass and 6D (2).
json body_dynamics_json(const OptimizationReport& report) {
  json out{{"option", report.body_dynamics_option}};
  if (report.body_dynamics_option == 2) {
    out["mode"] = "initial_nominal";
    out["status"] = status_name(report.initial_nominal_6d_status);
    if (report.initial_nominal_point_mass != nullptr && report.initial_nominal_6d != nullptr &&
        ok(report.initial_nominal_6d_status)) {
      const json pm = terminal_json(*report.initial_nominal_point_mass);
      const json six = terminal_json(*report.initial_nominal_6d);
      json difference = json::object();
      for (auto it = six.begin(); it != six.end(); ++it) {
        difference[it.key()] = (it.value().is_number() && pm[it.key()].is_number())
                                   ? json(it.value().get<double>() - pm[it.key()].get<double>())
                                   : json(nullptr);
      }
      out["point_mass"] = pm;
      out["body_dynamics"] = six;
      out["difference"] = difference;
    }
    return out;
  }
  out["mode"] = "relinearization";
  const LinearizationResult* r = report.linearization;
  if (r == nullptr) {
    out["status"] = status_name(report.linearization_status);
    return out;
  }
  out["status"] = status_name(report.linearization_status);
  out["point_mass_met"] = r->point_mass_met;
  out["relinearized"] = r->body_dynamics;
  if (!r->point_mass_met || !r->finished) return out;
  out["point_mass_payoff"] = json_number(r->point_mass_payoff);
  out["body_dynamics_payoff"] = json_number(r->payoff);
  out["payoff_difference"] = json_number(r->payoff - r->point_mass_payoff);
  json flown = json::array();
  for (int j = 0; j < std::clamp(r->constraint_count, 0, kMaxConstraints); ++j) {
    flown.push_back(json{{"code", r->codes[j]},
                         {"desired", json_number(r->desired[j])},
                         {"point_mass", json_number(r->point_mass_achieved[j])},
                         {"body_dynamics", json_number(r->point_mass_program_6d_achieved[j])}});
  }
  out["point_mass_program_flown_6d"] = std::move(flown);
  return out;
}

}  // namespace

json optimization_json(const OptimizationReport& report) {
  const Mission& mission = *report.final_trajectory.mission;
  const OptimizerResult& result = *report.result;
  const std::vector<ConstraintSummary> constraints = constraint_summaries(report);
  const std::vector<AdjustableSummary> adjustable = adjustable_summaries(report);

  json partials = json::array();
  for (const ConstraintSummary& c : constraints) partials.push_back(json_number(c.payoff_partial));

  json additions = json::object();
  additions["converged"] = result.converged;
  additions["optimization_stop"] = optimization_stop_name(result.optimization_stop);
  additions["guidance_runs"] = result.guidance_runs;
  additions["optimization_runs"] = result.optimization_runs;
  additions["successful_optimization_runs"] = result.successful_optimization_runs;
  additions["final_guidance_met"] = result.final_guidance_met;
  additions["initial_payoff_improvement"] = json_number(result.initial_payoff_improvement);
  additions["initial_improvement_from_da13_1"] = result.initial_improvement_from_da13_1;
  additions["case_status"] = status_name(report.case_status);
  additions["case_failed_step"] = report.case_failed_step;
  additions["forward_runs"] = result.forward_runs;
  additions["backward_runs"] = result.backward_runs;
  additions["payoff"] = payoff_json(payoff_summary(report));
  additions["payload_lb"] = json_number(mission.vehicle.payload_lb);
  additions["initial_payload_lb"] =
      json_number(report.initial_mission != nullptr ? report.initial_mission->vehicle.payload_lb : kNaN);
  additions["constraints"] = constraints_json(constraints);
  additions["payoff_partials"] = std::move(partials);
  additions["adjustable"] = adjustable_json(adjustable);
  additions["theta_history"] = theta_history_json(*report.final_trajectory.trajectory);
  additions["iterations"] = iterations_json(report, static_cast<int>(constraints.size()));
  additions["iterations_dropped"] = result.iterations_dropped;
  additions["failed_runs_recovered"] = result.crashed_runs;
  additions["held_constraints"] = held_constraints_json(result, static_cast<int>(constraints.size()));
  if (report.final_trajectory.trajectory != nullptr && report.final_trajectory.trajectory->point_count > 0) {
    additions["qbar_alpha"] = qbar_alpha_json(mission, *report.final_trajectory.trajectory);
  }
  if (report.exchange_ratios_requested) additions["exchange_ratios"] = exchange_ratios_json(report);
  if (report.linearization_requested) additions["linearized"] = linearized_json(report);
  if (report.body_dynamics_option == 1 || report.body_dynamics_option == 2) {
    additions["body_dynamics"] = body_dynamics_json(report);
  }
  if (report.dispersions != nullptr) additions["dispersions"] = dispersion_json(*report.dispersions);
  if (report.impact != nullptr) additions["impact"] = impact_json(*report.impact);
  if (report.hardover != nullptr) additions["hardover"] = hardover_json(*report.hardover);
  if (report.radar != nullptr) additions["radar"] = radar_json(*report.radar);
  if (report.autopilot != nullptr) additions["autopilot"] = autopilot_json(*report.autopilot);

  // The simulate document of the final trajectory, with the run's status and the additions placed
  // before the (long) point array.
  const json base = trajectory_json(report.final_trajectory);
  json document = json::object();
  for (auto it = base.begin(); it != base.end(); ++it) {
    if (it.key() == "trajectory") {
      for (auto add = additions.begin(); add != additions.end(); ++add) document[add.key()] = add.value();
    }
    if (it.key() == "status") {
      document["status"] = status_name(report.status);
    } else if (it.key() == "status_message") {
      document["status_message"] = status_message(report.status);
    } else {
      document[it.key()] = it.value();
    }
  }
  return document;
}

}  // namespace tolip::ground
