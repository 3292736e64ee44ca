// The optimization report shared by the listing and the JSON document of `tolip optimize`: names
// and units of the constraints (data blocks 8, 19, 29) and adjustable parameters (data block 6),
// and the manual-style listing (Sec. 22 "OUTPUT FORMAT", "Output at Start of Each Iteration").
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "listing_pager.hpp"
#include "number_format.hpp"
#include "tolip/atmosphere/atmosphere.hpp"
#include "tolip/core/constants.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/mission/adjustable_parameter.hpp"
#include "tolip/optimizer/constraint_parameters.hpp"
#include "tolip/optimizer/constraint_set.hpp"
#include "tolip/optimizer/qbar_alpha.hpp"
#include "tolip/orbit/orbit_elements.hpp"
#include "tolip/vehicle/prepared_case.hpp"
#include "tolip_ground/autopilot_run.hpp"
#include "tolip_ground/dispersion_report.hpp"
#include "tolip_ground/hardover_report.hpp"
#include "tolip_ground/impact_report.hpp"
#include "tolip_ground/optimization_report.hpp"
#include "tolip_ground/radar_report.hpp"

namespace tolip::ground {
namespace {

using report_detail::fixed_cell;
using report_detail::left_aligned;
using report_detail::Pager;
using report_detail::right_aligned;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct QuantityText {
  const char* name;          // JSON (snake_case)
  const char* heading;       // listing
  const char* unit;          // data block 19 unit (JSON)
  const char* unit_heading;  // listing
  int decimals;              // listing decimals in data block 19 units
};

QuantityText quantity_text(ConstraintQuantity kind) {
  switch (kind) {
    case ConstraintQuantity::kPayload: return {"payload", "PAYLOAD", "lb", "LB", 3};
    case ConstraintQuantity::kInertialVelocity:
      return {"inertial_velocity", "INERTIAL VELOCITY", "ft/s", "FT/SEC", 4};
    case ConstraintQuantity::kInertialFlightPathAngle:
      return {"inertial_flight_path_angle", "INERTIAL PATH ANGLE", "rad", "RAD", 8};
    case ConstraintQuantity::kVelocityOverCircular:
      return {"velocity_minus_circular", "VI MINUS CIRCULAR VEL", "ft/s", "FT/SEC", 4};
    case ConstraintQuantity::kRadius: return {"radius", "RADIUS", "ft", "FT", 3};
    case ConstraintQuantity::kAerodynamicVelocity: return {"velocity", "VELOCITY", "ft/s", "FT/SEC", 4};
    case ConstraintQuantity::kAerodynamicFlightPathAngle:
      return {"flight_path_angle", "PATH ANGLE", "rad", "RAD", 8};
    case ConstraintQuantity::kAltitude: return {"altitude", "ALTITUDE", "ft", "FT", 3};
    case ConstraintQuantity::kDownrange: return {"downrange", "DOWNRANGE", "nmi", "N.MI.", 4};
    case ConstraintQuantity::kTwiceEnergy: return {"twice_energy", "2E", "ft2/s2", "FT2/SEC2", 1};
    case ConstraintQuantity::kInclination: return {"inclination", "INCLINATION", "rad", "RAD", 8};
    case ConstraintQuantity::kPerigeeRadius: return {"perigee_radius", "PERIGEE RADIUS", "ft", "FT", 3};
    case ConstraintQuantity::kNodeLongitude: return {"node_longitude", "NODE LONGITUDE", "rad", "RAD", 8};
    case ConstraintQuantity::kArgumentOfPerigee:
      return {"argument_of_perigee", "ARGUMENT OF PERIGEE", "rad", "RAD", 8};
    case ConstraintQuantity::kTotalHeating:
      return {"total_heating", "TOTAL HEATING", "btu/ft2", "BTU/FT2", 3};
    case ConstraintQuantity::kDynamicPressure:
      return {"dynamic_pressure", "DYNAMIC PRESSURE", "lbf/ft2", "LB/FT2", 4};
    case ConstraintQuantity::kHyperbolicExcessVelocity:
      return {"hyperbolic_excess_velocity", "HYPERBOLIC EXCESS VEL", "ft/s", "FT/SEC", 4};
    case ConstraintQuantity::kAsymptoteRightAscension:
      return {"asymptote_right_ascension", "ASYMPTOTE RA", "rad", "RAD", 8};
    case ConstraintQuantity::kAsymptoteDeclination:
      return {"asymptote_declination", "ASYMPTOTE DECL", "rad", "RAD", 8};
    case ConstraintQuantity::kQbarAlphaExcess:
      return {"qbar_alpha_excess", "QBAR*ALPHA EXCESS", "s", "SEC", 8};
  }
  return {"unknown", "UNKNOWN", "", "", 6};
}

QuantityText code_text(int code, ConstraintCode* decoded) {
  ConstraintCode c;
  if (!ok(decode_constraint_code(code, &c))) {
    if (decoded != nullptr) *decoded = c;
    return {"unknown", "UNKNOWN", "", "", 6};
  }
  if (decoded != nullptr) *decoded = c;
  return quantity_text(c.kind);
}

// Value of constraint `code` on a completed trajectory (as the optimizer evaluates it), or NaN.
double evaluate_on_trajectory(const Mission& mission, const Trajectory& trajectory, int code) {
  ConstraintCode c;
  if (!ok(decode_constraint_code(code, &c))) return kNaN;
  const int count = stored_point_count(trajectory);
  if (!ok(trajectory.status) || count == 0) return kNaN;
  const int index = constraint_point_index(c, trajectory);
  if (index < 0 || index >= count) return kNaN;
  const ConstraintPoint point = constraint_point_at(mission, trajectory, index);
  double value = kNaN;
  if (!ok(constraint_value(mission.constants, mission.launch, c, point, &value))) return kNaN;
  return value;
}

// True when optimize_trajectory reached its summary (it fills the result only then).
// (The heating constraint may have joined its list, so it can be one longer than data block 8's.)
bool result_complete(const OptimizationReport& report) {
  const OptimizerResult& result = *report.result;
  return result.constraint_count > 0 &&
         result.constraint_count >= report.final_trajectory.mission->constraints.count;
}

// `launch_day` is the space-age date (days) of 0h UT of the deck's launch day (code 7).
double adjustable_value(const Mission& mission, int code, double launch_day) {
  const MiscellaneousData& misc = mission.misc;
  AdjustableParameter parameter = AdjustableParameter::kStage4Theta;
  if (!decode_adjustable_parameter(code, &parameter)) return kNaN;
  switch (parameter) {
    case AdjustableParameter::kStage4Theta: return misc.stage4_theta_rad * kRadToDeg;
    case AdjustableParameter::kStage4Chi: return misc.stage4_chi_rad * kRadToDeg;
    case AdjustableParameter::kLaunchAzimuth: return mission.launch.azimuth_rad * kRadToDeg;
    case AdjustableParameter::kLaunchTime:
      return (mission.launch.launch_space_age_date_days - launch_day) * 86400.0;
    case AdjustableParameter::kStage5Theta: return misc.stage5_theta_rad * kRadToDeg;
    case AdjustableParameter::kStage5Chi: return misc.stage5_chi_rad * kRadToDeg;
    default: return mission.vehicle.stages[stage_index(adjusted_coast_stage_code(parameter))].duration_s;
  }
}

struct ParameterText {
  const char* name;
  const char* heading;
  const char* unit;
};

ParameterText parameter_text(int code) {
  AdjustableParameter parameter = AdjustableParameter::kStage4Theta;
  if (!decode_adjustable_parameter(code, &parameter)) return {"unknown", "UNKNOWN", ""};
  switch (parameter) {
    case AdjustableParameter::kStage4Theta: return {"stage4_theta", "STAGE 4 THETA (SPUN)", "deg"};
    case AdjustableParameter::kStage4Chi: return {"stage4_chi", "STAGE 4 CHI (SPUN)", "deg"};
    case AdjustableParameter::kCoastAfterStage3: return {"coast_after_stage_3", "COAST AFTER STAGE 3", "s"};
    case AdjustableParameter::kCoastAfterStage2: return {"coast_after_stage_2", "COAST AFTER STAGE 2", "s"};
    case AdjustableParameter::kCoastAfterStage1: return {"coast_after_stage_1", "COAST AFTER STAGE 1", "s"};
    case AdjustableParameter::kLaunchAzimuth: return {"launch_azimuth", "LAUNCH AZIMUTH", "deg"};
    case AdjustableParameter::kLaunchTime: return {"launch_time", "LAUNCH TIME (UT)", "s"};
    case AdjustableParameter::kStage5Theta: return {"stage5_theta", "STAGE 5 THETA (SPUN)", "deg"};
    case AdjustableParameter::kStage5Chi: return {"stage5_chi", "STAGE 5 CHI (SPUN)", "deg"};
    case AdjustableParameter::kCoastAfterStage4: return {"coast_after_stage_4", "COAST AFTER STAGE 4", "s"};
    case AdjustableParameter::kCoastAfterStage5: return {"coast_after_stage_5", "COAST AFTER STAGE 5", "s"};
  }
  return {"unknown", "UNKNOWN", ""};
}

// ---- listing helpers -------------------------------------------------------------------------

std::string number_cell(double value, int decimals, int width) { return fixed_cell(value, decimals, width); }

// Scientific notation in a right-aligned cell ("-" when not finite).
std::string e_cell(double value, int width) {
  if (!std::isfinite(value)) return right_aligned("-", width);
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6E", value);
  return right_aligned(buffer, width);
}

std::string upper(const char* text) {
  std::string out(text);
  for (char& c : out) {
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  }
  return out;
}

// Sec. 22's two stopping rules of the optimization phase, as the summary prints them.
const char* optimization_stop_text(OptimizationStop stop) {
  switch (stop) {
    case OptimizationStop::kNotReached: return "NOT REACHED";
    case OptimizationStop::kImprovementBelowMinimum: return "ATTEMPT BELOW DA13(2)";
    case OptimizationStop::kForwardRunBudget: return "RUN BUDGET DA13(3)";
  }
  return "UNKNOWN";
}

const char* run_kind_heading(RunKind kind) {
  switch (kind) {
    case RunKind::kInitialNominal: return "INITIAL NOMINAL";
    case RunKind::kGuidance: return "GUIDANCE";
    case RunKind::kOptimization: return "OPTIMIZATION";
    case RunKind::kFinalGuidance: return "FINAL GUIDANCE";
  }
  return "UNKNOWN";
}

// A right-aligned cell without its leading blanks, for numbers inside sentences.
std::string trimmed(const std::string& cell) {
  const std::size_t first = cell.find_first_not_of(' ');
  return first == std::string::npos ? cell : cell.substr(first);
}

std::string constraint_label(const ConstraintCode& decoded, const QuantityText& text) {
  std::string label = text.heading;
  if (decoded.is_stage_point) label += " END STG " + std::to_string(decoded.stage_code);
  return label;
}

// Payoff partial unit: payoff unit per constraint unit.
std::string partial_unit(const std::string& payoff, const std::string& constraint) {
  return payoff + "/" + constraint;
}

void write_problem(Pager& pager, const OptimizationReport& report,
                   const std::vector<ConstraintSummary>& constraints,
                   const std::vector<AdjustableSummary>& adjustable) {
  const Mission& mission = *report.final_trajectory.mission;
  const int ip1 = mission.options.payoff();
  pager.reserve(6 + static_cast<int>(constraints.size()));
  pager.emit(" OPTIMIZATION PROBLEM");
  pager.emit("   PAYOFF: " + upper(payoff_kind_name(ip1)) + " (IP(1) = " + std::to_string(ip1) +
             ", DATA BLOCK 8 CODE " + std::to_string(mission.constraints.codes[0]) + ")");
  pager.emit("   CONSTRAINTS (DATA BLOCKS 8, 19, 29; UNITS OF DATA BLOCK 19)");
  pager.emit(
      "    NO.  CODE  PARAMETER                          DESIRED        DEADBAND  UNIT"
      "              DESIRED      DEADBAND  UNIT");
  for (std::size_t i = 0; i < constraints.size(); ++i) {
    const ConstraintSummary& c = constraints[i];
    ConstraintCode decoded;
    const QuantityText text = code_text(c.code, &decoded);
    std::string line = right_aligned(std::to_string(i + 1), 7) + right_aligned(std::to_string(c.code), 6) +
                       "  " +
                       left_aligned(constraint_label(decoded, text) + (c.inequality ? " (MAX)" : ""), 27);
    line += number_cell(c.desired, text.decimals, 16) + number_cell(c.tolerance, text.decimals, 16);
    line += "  " + left_aligned(text.unit_heading, 9);
    if (c.angle) {
      line +=
          number_cell(c.desired * kRadToDeg, 6, 16) + number_cell(c.tolerance * kRadToDeg, 6, 14) + "  DEG";
    }
    pager.emit(line);
  }
  pager.emit("");
  if (adjustable.empty()) return;
  pager.reserve(3 + static_cast<int>(adjustable.size()));
  pager.emit("   ADJUSTABLE PARAMETERS (DATA BLOCKS 6, 27)");
  pager.emit("    NO.  CODE  PARAMETER                    INITIAL VALUE  UNIT        WEIGHT");
  for (std::size_t p = 0; p < adjustable.size(); ++p) {
    const AdjustableSummary& a = adjustable[p];
    const double weight =
        p < static_cast<std::size_t>(kMaxAdjustableParameters) ? mission.adjustable.weights[p] : kNaN;
    pager.emit(right_aligned(std::to_string(p + 1), 7) + right_aligned(std::to_string(a.code), 6) + "  " +
               left_aligned(parameter_text(a.code).heading, 25) + number_cell(a.initial_value, 6, 18) + "  " +
               left_aligned(upper(a.unit.c_str()), 6) + e_cell(weight, 14));
  }
  pager.emit("");
}

void write_iteration_table(Pager& pager, const OptimizationReport& report) {
  const OptimizerResult& result = *report.result;
  const int ip1 = report.final_trajectory.mission->options.payoff();
  const std::string unit = upper(payoff_unit(ip1));
  const auto headings = [&pager, &unit]() {
    pager.emit(" ITERATION HISTORY (ONE LINE PER FORWARD RUN)");
    pager.emit(
        "    RUN  KIND              SUCCESSFUL  NOMINAL PAYOFF INCR          PAYOFF  CORRECTED PAYOFF"
        "         PAYLOAD  PAYLOAD INCREMENT");
    pager.emit("                                       " + right_aligned(unit, 19) + right_aligned(unit, 16) +
               right_aligned(unit, 18) + right_aligned("LB", 16) + right_aligned("LB", 19));
  };
  pager.reserve(5);
  headings();
  const int count = std::clamp(result.iteration_count, 0, kMaxOptimizerIterations);
  for (int k = 0; k < count; ++k) {
    const IterationRecord& r = result.iterations[k];
    pager.reserve(1);
    std::string line = right_aligned(std::to_string(r.forward_run), 7) + "  " +
                       left_aligned(run_kind_heading(r.kind), 18) +
                       left_aligned(r.successful ? "YES" : "NO", 10);
    line += number_cell(r.attempted_payoff_improvement, 4, 21) + number_cell(r.payoff, 4, 16) +
            number_cell(r.corrected_payoff, 4, 18) + number_cell(r.payload_lb, 4, 16) +
            number_cell(r.payload_increment_lb, 4, 19);
    if (!ok(r.run_status)) line += std::string("  RUN FAILED: ") + status_name(r.run_status);
    std::string held;
    for (int i = 1; i < kMaxConstraints; ++i) {
      if (!r.constraint_held[i]) continue;
      if (!held.empty()) held += ',';
      held += std::to_string(i);
    }
    if (!held.empty()) line += "  HELD: " + held;
    pager.emit(line);
  }
  if (result.iterations_dropped > 0) {
    pager.emit("    ... " + std::to_string(result.iterations_dropped) +
               " LATER FORWARD RUNS NOT RECORDED (THE HISTORY HOLDS " +
               std::to_string(kMaxOptimizerIterations) + ")");
  }
  pager.emit("");
}

void write_iteration_details(Pager& pager, const OptimizationReport& report,
                             const std::vector<ConstraintSummary>& constraints) {
  const OptimizerResult& result = *report.result;
  const int ip1 = report.final_trajectory.mission->options.payoff();
  const std::string payoff = upper(payoff_unit(ip1));
  const int count = std::clamp(result.iteration_count, 0, kMaxOptimizerIterations);
  const int rows = static_cast<int>(constraints.size());
  for (int k = 0; k < count; ++k) {
    const IterationRecord& r = result.iterations[k];
    pager.reserve(9 + rows);
    pager.emit(
        " FORWARD RUN " + std::to_string(r.forward_run) + "   " + run_kind_heading(r.kind) + "   " +
        (r.successful ? "SUCCESSFUL" : "NOT SUCCESSFUL") +
        (ok(r.run_status) ? std::string() : std::string("   RUN FAILED: ") + status_name(r.run_status)));
    pager.emit(
        "   NOMINAL PAYOFF INCREMENT          PAYOFF  CORRECTED PAYOFF         PAYLOAD  PAYLOAD INCREMENT");
    pager.emit("   " + right_aligned(payoff, 24) + right_aligned(payoff, 16) + right_aligned(payoff, 18) +
               right_aligned("LB", 16) + right_aligned("LB", 19));
    pager.emit("   " + number_cell(r.attempted_payoff_improvement, 4, 24) + number_cell(r.payoff, 4, 16) +
               number_cell(r.corrected_payoff, 4, 18) + number_cell(r.payload_lb, 4, 16) +
               number_cell(r.payload_increment_lb, 4, 19));
    if (rows > 0) {
      pager.emit(
          "   CONSTRAINT CORRECTIONS (DESIRED - ACHIEVED) AND PARTIALS OF PAYOFF WITH RESPECT TO EACH "
          "CONSTRAINT"
          " (EQ. 9-22)");
      pager.emit(
          "    NO.  CODE  PARAMETER                       CORRECTION  UNIT           CORRECTION  UNIT"
          "     D PAYOFF/D CONSTRAINT  UNIT");
      for (int i = 0; i < rows; ++i) {
        const ConstraintSummary& c = constraints[static_cast<std::size_t>(i)];
        ConstraintCode decoded;
        const QuantityText text = code_text(c.code, &decoded);
        const double correction = (i + 1 < kMaxConstraints) ? r.constraint_corrections[i + 1] : kNaN;
        const double partial = (i + 1 < kMaxConstraints) ? r.payoff_partials[i + 1] : kNaN;
        std::string line =
            right_aligned(std::to_string(i + 1), 7) + right_aligned(std::to_string(c.code), 6) + "  " +
            left_aligned(constraint_label(decoded, text) + (c.inequality ? " (MAX)" : ""), 27) +
            number_cell(correction, text.decimals, 16) + "  " + left_aligned(text.unit_heading, 9);
        if (c.angle) {
          line += number_cell(correction * kRadToDeg, 6, 16) + "  DEG  ";
        } else {
          line += std::string(23, ' ');
        }
        line += e_cell(partial, 22) + "  " + partial_unit(payoff, text.unit_heading);
        pager.emit(line);
      }
    }
    pager.emit("");
  }
}

// The peak q-bar x alpha lines of a trajectory (issue 15): the lift phases' peak and time, the
// limit and whether it is met, and the peak over every stage.
void write_qbar_alpha_peak(Pager& pager, const std::string& label, const QbarAlphaSummary& q) {
  pager.reserve(2);
  std::string line = "   PEAK QBAR*ALPHA, LIFT PHASES (" + label +
                     ") = " + trimmed(number_cell(q.lift_peak_lb_deg_ft2, 1, 20)) +
                     " LB DEG/FT2 AT T = " + trimmed(number_cell(q.lift_peak_time_s, 2, 12)) + " S";
  if (q.limit_lb_deg_ft2 > 0.0) {
    line += "; LIMIT " + trimmed(number_cell(q.limit_lb_deg_ft2, 1, 20)) +
            (q.met ? " MET (EXCESS INTEGRAL " : " EXCEEDED (EXCESS INTEGRAL ") +
            trimmed(e_cell(q.excess_integral_s, 14)) + " S)";
  }
  pager.emit(line);
  pager.emit("   PEAK QBAR*ALPHA, ALL STAGES (" + label +
             ") = " + trimmed(number_cell(q.peak_lb_deg_ft2, 1, 20)) +
             " LB DEG/FT2 AT T = " + trimmed(number_cell(q.peak_time_s, 2, 12)) + " S");
}

void write_summary(Pager& pager, const OptimizationReport& report,
                   const std::vector<ConstraintSummary>& constraints,
                   const std::vector<AdjustableSummary>& adjustable) {
  const OptimizerResult& result = *report.result;
  const Mission& mission = *report.final_trajectory.mission;
  const int ip1 = mission.options.payoff();
  const std::string payoff_heading = upper(payoff_unit(ip1));
  const PayoffSummary summary = payoff_summary(report);
  const double payoff = summary.value;
  const double corrected = summary.corrected;

  const auto labelled = [](const std::string& label, const std::string& value, const std::string& unit) {
    std::string text = "   " + label;
    text.resize(30, ' ');
    text += "= " + right_aligned(value, 20);
    if (!unit.empty()) text += " " + unit;
    return text;
  };

  pager.reserve(17);
  pager.emit(" OPTIMIZATION SUMMARY");
  pager.emit(labelled("STATUS", status_name(report.status), ""));
  pager.emit(labelled("CONVERGED", result.converged ? "YES" : "NO", ""));
  pager.emit(labelled("OPTIMIZATION ENDED BY", optimization_stop_text(result.optimization_stop), ""));
  pager.emit(labelled("GUIDANCE RUNS", std::to_string(result.guidance_runs), ""));
  pager.emit(labelled(
      result.initial_improvement_from_da13_1 ? "FIRST ATTEMPT (DA13(1))" : "FIRST ATTEMPT (EQ. 5-34)",
      trimmed(number_cell(result.initial_payoff_improvement, 4, 20)), payoff_heading));
  pager.emit(labelled("OPTIMIZATION RUNS",
                      std::to_string(result.optimization_runs) + " (" +
                          std::to_string(result.successful_optimization_runs) + " SUCCESSFUL)",
                      ""));
  pager.emit(labelled("FINAL GUIDANCE RUN", result.final_guidance_met ? "MET EVERY DEADBAND" : "FAILED", ""));
  pager.emit(labelled("FAILED RUNS RECOVERED", std::to_string(result.crashed_runs), ""));
  // Weak directions of the steering matrix (docs/theory/optimizer.md "Weak directions").
  for (int i = 1; i < std::min(result.constraint_count, kMaxConstraints); ++i) {
    if (result.held_runs[i] == 0) continue;
    pager.reserve(1);
    pager.emit("   CONSTRAINT " + std::to_string(i) + " (CODE " + std::to_string(result.codes[i]) +
               ") HAS NO FIRST-ORDER EFFECT: HELD BY DEADBAND ON " + std::to_string(result.held_runs[i]) +
               " OF " + std::to_string(result.forward_runs) + " RUNS");
  }
  for (int i = 1; i < std::min(result.constraint_count, kMaxConstraints); ++i) {
    if (result.deferred_runs[i] == 0) continue;
    pager.reserve(1);
    // Codes 101-102 wait for the trajectory to become hyperbolic (the Addendum H stand-in), code 13
    // for the other constraints (docs/theory/optimizer.md).
    const bool asymptote = result.codes[i] == 101 || result.codes[i] == 102;
    pager.emit("   CONSTRAINT " + std::to_string(i) + " (CODE " + std::to_string(result.codes[i]) +
               (asymptote ? ") DEFERRED UNTIL THE TRAJECTORY WAS HYPERBOLIC ON "
                          : ") DEFERRED UNTIL THE OTHERS MET THEIR DEADBANDS ON ") +
               std::to_string(result.deferred_runs[i]) + " GUIDANCE RUNS");
  }
  pager.emit(labelled("CASE RESULT",
                      ok(report.case_status)
                          ? std::string("kOk")
                          : report.case_failed_step + ": " + status_name(report.case_status),
                      ""));
  pager.emit(labelled("FORWARD RUNS", std::to_string(result.forward_runs), ""));
  pager.emit(labelled("BACKWARD RUNS", std::to_string(result.backward_runs), ""));
  pager.emit(labelled("PAYOFF (" + upper(payoff_kind_name(ip1)) + ")", trimmed(number_cell(payoff, 4, 20)),
                      payoff_heading));
  pager.emit(labelled("CORRECTED PAYOFF", trimmed(number_cell(corrected, 4, 20)), payoff_heading));
  pager.emit(labelled("PAYLOAD", trimmed(number_cell(mission.vehicle.payload_lb, 4, 20)), "LB"));
  if (report.initial_mission != nullptr) {
    pager.emit(labelled(
        "PAYLOAD INCREMENT",
        trimmed(number_cell(mission.vehicle.payload_lb - report.initial_mission->vehicle.payload_lb, 4, 20)),
        "LB"));
  }
  if (report.final_trajectory.trajectory != nullptr && report.final_trajectory.trajectory->point_count > 0) {
    write_qbar_alpha_peak(pager, "OPTIMIZED",
                          qbar_alpha_summary(mission, *report.final_trajectory.trajectory));
  }
  if (report.linearized_trajectory != nullptr && report.linearized_mission != nullptr) {
    write_qbar_alpha_peak(pager, "LINEARIZED",
                          qbar_alpha_summary(*report.linearized_mission, *report.linearized_trajectory));
  }
  pager.emit("");

  report_detail::write_constraint_table(
      pager, constraints,
      "   CONSTRAINTS ON THE FINAL TRAJECTORY (UNITS OF DATA BLOCK 19; ANGLES ALSO IN DEG)");

  if (!constraints.empty()) {
    pager.reserve(3 + static_cast<int>(constraints.size()));
    pager.emit("   PARTIALS OF PAYOFF WITH RESPECT TO EACH CONSTRAINT (EQ. 9-22, LAST BACKWARD RUN)");
    pager.emit("    NO.  CODE  PARAMETER                   D PAYOFF/D CONSTRAINT  UNIT");
    for (std::size_t i = 0; i < constraints.size(); ++i) {
      const ConstraintSummary& c = constraints[i];
      ConstraintCode decoded;
      const QuantityText text = code_text(c.code, &decoded);
      pager.emit(right_aligned(std::to_string(i + 1), 7) + right_aligned(std::to_string(c.code), 6) + "  " +
                 left_aligned(constraint_label(decoded, text) + (c.inequality ? " (MAX)" : ""), 27) +
                 e_cell(c.payoff_partial, 22) + "  " + partial_unit(payoff_heading, text.unit_heading));
    }
    pager.emit("");
  }

  if (!adjustable.empty()) {
    pager.reserve(3 + static_cast<int>(adjustable.size()));
    pager.emit("   ADJUSTABLE PARAMETERS (DATA BLOCK 6), FINAL VALUES");
    pager.emit("    NO.  CODE  PARAMETER                    INITIAL VALUE       FINAL VALUE  UNIT");
    for (std::size_t p = 0; p < adjustable.size(); ++p) {
      const AdjustableSummary& a = adjustable[p];
      pager.emit(right_aligned(std::to_string(p + 1), 7) + right_aligned(std::to_string(a.code), 6) + "  " +
                 left_aligned(parameter_text(a.code).heading, 25) + number_cell(a.initial_value, 6, 18) +
                 number_cell(a.value, 6, 18) + "  " + upper(a.unit.c_str()));
    }
    pager.emit("");
  }
  if (!ok(report.status)) {
    pager.emit(std::string(" OPTIMIZATION ENDED: ") + status_name(report.status) + ": " +
               status_message(report.status));
    pager.emit("");
  }
}

// Sec. 8 and 22 "Performance Exchange Ratios": payoff change per unit change of each stage
// characteristic, assuming a new optimum trajectory (IP(3) = 1).
void write_exchange_ratios(Pager& pager, const OptimizationReport& report) {
  if (!report.exchange_ratios_requested) return;
  const int ip1 = report.final_trajectory.mission->options.payoff();
  const std::string unit = upper(payoff_unit(ip1));
  const ExchangeRatios* r = report.exchange_ratios;
  if (r == nullptr) {
    pager.reserve(3);
    pager.emit(" PERFORMANCE EXCHANGE RATIOS");
    pager.emit(std::string("   NOT COMPUTED: ") + status_name(report.exchange_ratio_status) + ": " +
               status_message(report.exchange_ratio_status));
    pager.emit("");
    return;
  }
  const int count = std::clamp(r->stage_count, 0, kMaxPoweredStages);
  pager.reserve(7 + count);
  pager.emit(
      " PERFORMANCE EXCHANGE RATIOS (SEC. 8: FIRST-ORDER PAYOFF CHANGE OF THE RE-OPTIMIZED TRAJECTORY"
      " PER UNIT CHANGE)");
  pager.emit(
      "    STAGE         BURN RATE   PROPELLANT WEIGHT    SPECIFIC IMPULSE           DRAG AREA"
      "     JETTISON WEIGHT");
  pager.emit("          " + right_aligned(unit + "/PCT", 18) + right_aligned(unit + "/LB", 20) +
             right_aligned(unit + "/PCT", 20) + right_aligned(unit + "/FT2", 20) +
             right_aligned(unit + "/LB", 20));
  for (int s = 0; s < count; ++s) {
    pager.emit(right_aligned(std::to_string(r->stage_codes[s]), 9) + " " + e_cell(r->burn_rate[s], 18) +
               e_cell(r->propellant_weight[s], 20) + e_cell(r->specific_impulse[s], 20) +
               e_cell(r->drag[s], 20) + e_cell(r->jettison_weight[s], 20));
  }
  pager.emit(
      "   BURN RATE AND SPECIFIC IMPULSE PER 1 PCT, WEIGHTS PER LB, DRAG PER FT2 OF C_D S (0: NO DRAG "
      "TABLE)");
  if (ip1 == 0) {
    pager.emit("   PAYOFF PARTIALS' PRICE OF 1 LB OF PAYLOAD (1 AT A TRUE OPTIMUM) = " +
               fixed_cell(r->payload_stationarity, 5, 10));
  }
  pager.emit("");
}

// Sec. 6, 10, 22 "Linearized Pitch Program": theta at each segment start (stage time and time from
// launch) and the segment's rate, then the constraints the linearized trajectory achieved against
// the linearization deadbands (data block 29 words 14-25), and its payoff against the optimum's.
void write_linearized_program(Pager& pager, const OptimizationReport& report) {
  if (!report.linearization_requested) return;
  const LinearizationResult* r = report.linearization;
  if (r == nullptr || !r->finished) {
    pager.reserve(3);
    pager.emit(" LINEARIZED PITCH PROGRAM");
    pager.emit(std::string("   NOT COMPUTED: ") + status_name(report.linearization_status) + ": " +
               status_message(report.linearization_status));
    pager.emit("");
    return;
  }
  const LinearProgram& p = r->program;
  const int count = std::clamp(p.segment_count, 0, kMaxLinearSegments);
  pager.reserve(6 + count);
  pager.emit(" LINEARIZED PITCH PROGRAM (SEC. 6, 10): THETA LINEAR IN TIME FROM EACH SEGMENT START");
  pager.emit("    SEGMENT  STAGE   STAGE TIME  TIME FROM LAUNCH           THETA      PITCH RATE");
  pager.emit("                            SEC               SEC             DEG         DEG/SEC");
  for (int s = 0; s < count; ++s) {
    const bool merged = rate_continues_previous(p, s);
    pager.emit(right_aligned(std::to_string(s + 1), 11) + right_aligned(std::to_string(p.stage_code[s]), 7) +
               number_cell(p.start_stage_time_s[s], 3, 13) + number_cell(p.break_time_s[s], 3, 18) +
               number_cell(p.theta_rad[s] * kRadToDeg, 5, 16) +
               number_cell(p.rate_rad_s[s] * kRadToDeg, 5, 16) + (merged ? "  (SAME RATE: MERGED)" : ""));
  }
  if (count > 0) {
    pager.emit(std::string(11 + 7 + 13, ' ') + number_cell(p.break_time_s[count], 3, 18) +
               number_cell(p.theta_rad[count] * kRadToDeg, 5, 16) + "  (END OF PROGRAM; HELD AFTER)");
  }
  pager.emit("");
  const int constraints = std::clamp(r->constraint_count, 0, kMaxConstraints);
  pager.reserve(4 + constraints);
  pager.emit(
      "   CONSTRAINTS ON THE LINEARIZED TRAJECTORY (LINEARIZATION DEADBANDS, DATA BLOCK 29 WORDS 14-25)");
  pager.emit(
      "          CODE  PARAMETER                          DESIRED        ACHIEVED       TOLERANCE  UNIT      "
      "MET");
  for (int j = 0; j < constraints; ++j) {
    ConstraintCode decoded;
    const QuantityText text = code_text(r->codes[j], &decoded);
    pager.emit(
        right_aligned(std::to_string(r->codes[j]), 14) + "  " +
        left_aligned(constraint_label(decoded, text), 27) + number_cell(r->desired[j], text.decimals, 16) +
        number_cell(r->achieved[j], text.decimals, 16) + number_cell(r->tolerance[j], text.decimals, 16) +
        "  " + left_aligned(text.unit_heading, 9) + (r->met[j] ? "YES" : "NO"));
  }
  const int ip1 = report.final_trajectory.mission->options.payoff();
  const double loss_percent = 100.0 * (report.optimum_payoff - r->payoff) / report.optimum_payoff;
  pager.emit("   PAYOFF (" + upper(payoff_kind_name(ip1)) + ") " + trimmed(number_cell(r->payoff, 4, 20)) +
             " " + upper(payoff_unit(ip1)) + " AGAINST THE OPTIMUM'S " +
             trimmed(number_cell(report.optimum_payoff, 4, 20)) + " (LOSS " +
             trimmed(number_cell(loss_percent, 3, 12)) + " PCT)");
  pager.emit("   RATE LIMITS (DATA BLOCK 22) " + std::string(r->rate_limits_met ? "MET" : "NOT MET") +
             "; CONSTRAINTS " + (r->constraints_met ? "MET" : "NOT MET") + "; " +
             std::to_string(r->forward_runs) + " FORWARD" +
             (r->reference_flights > 0 ? " (+" + std::to_string(r->reference_flights) + " 6D REF.)"
                                       : std::string()) +
             " AND " + std::to_string(r->backward_runs) + " BACKWARD RUNS, " +
             std::to_string(r->programs_computed) + " PROGRAMS, " + std::to_string(p.rate_repair_count) +
             " RATE REPAIRS");
  // Sec. 10's messages for the coast between stages 2 and 3.
  if (r->coast7_below_min_rate)
    pager.emit("   COAST 7 PITCH RATE IS BELOW THE MINIMUM PITCH RATE (DATA BLOCK 22 WORD 4)");
  if (r->coast7_below_min_rate_change) {
    pager.emit(
        "   COAST 7 PITCH RATE CHANGES BY LESS THAN THE MINIMUM CHANGE OF RATE (DATA BLOCK 22 WORD 5)");
  }
  if (r->point_mass_met && r->body_dynamics) {
    // IP(6) = 1 (Sec. 10, 11): what body dynamics did to the accepted point-mass program, and the
    // payoff after the 6D re-linearization.
    pager.reserve(4 + constraints);
    pager.emit(
        "   6D RE-LINEARIZATION (IP(6) = 1, SEC. 10, 11): THE PROGRAM ABOVE WAS LINEARIZED WITH BODY "
        "DYNAMICS IN"
        " STAGE 1 AND COAST 6,");
    pager.emit("   STARTING FROM THE ACCEPTED POINT-MASS PROGRAM, WHOSE CONSTRAINT VALUES WERE:");
    pager.emit(
        "          CODE  PARAMETER                          DESIRED    POINT-MASS PROGRAM: POINT MASS       "
        "6D");
    for (int j = 0; j < constraints; ++j) {
      ConstraintCode decoded;
      const QuantityText text = code_text(r->codes[j], &decoded);
      pager.emit(right_aligned(std::to_string(r->codes[j]), 14) + "  " +
                 left_aligned(constraint_label(decoded, text), 27) +
                 number_cell(r->desired[j], text.decimals, 16) +
                 number_cell(r->point_mass_achieved[j], text.decimals, 26) +
                 number_cell(r->point_mass_program_6d_achieved[j], text.decimals, 16));
    }
    pager.emit("   PAYOFF: POINT MASS " + trimmed(number_cell(r->point_mass_payoff, 4, 20)) + ", 6D " +
               trimmed(number_cell(r->payoff, 4, 20)) + " (DIFFERENCE " +
               trimmed(number_cell(r->payoff - r->point_mass_payoff, 4, 20)) + " " + upper(payoff_unit(ip1)) +
               ")");
  }
  if (!ok(report.linearization_status)) {
    pager.emit(std::string("   LINEARIZATION ENDED: ") + status_name(report.linearization_status) + ": " +
               status_message(report.linearization_status));
  }
  pager.emit("");
}

}  // namespace

QbarAlphaSummary qbar_alpha_summary(const Mission& mission, const Trajectory& trajectory) {
  QbarAlphaSummary q;
  const QbarAlphaPeak lift = peak_qbar_alpha(mission, trajectory, true);
  const QbarAlphaPeak all = peak_qbar_alpha(mission, trajectory, false);
  q.lift_peak_lb_deg_ft2 = lift.value_lbf_rad_ft2 * kRadToDeg;
  q.lift_peak_time_s = lift.time_s;
  q.peak_lb_deg_ft2 = all.value_lbf_rad_ft2 * kRadToDeg;
  q.peak_time_s = all.time_s;
  q.limit_lb_deg_ft2 = mission.options.qbar_alpha_limit_lbf_rad_ft2 * kRadToDeg;
  q.excess_integral_s = qbar_alpha_excess_s(mission, trajectory);
  q.met = !mission.options.qbar_alpha_constraint() || q.excess_integral_s <= kQbarAlphaExcessDeadbandS;
  return q;
}

const char* payoff_kind_name(int ip1) {
  switch (ip1) {
    case 0: return "payload";
    case 1: return "velocity";
    case 2: return "altitude";
    default: return "unknown";
  }
}

const char* payoff_unit(int ip1) {
  switch (ip1) {
    case 0: return "lb";
    case 1: return "ft/s";
    case 2: return "ft";
    default: return "";
  }
}

const char* run_kind_name(RunKind kind) {
  switch (kind) {
    case RunKind::kInitialNominal: return "initial_nominal";
    case RunKind::kGuidance: return "guidance";
    case RunKind::kOptimization: return "optimization";
    case RunKind::kFinalGuidance: return "final_guidance";
  }
  return "unknown";
}

const char* optimization_stop_name(OptimizationStop stop) {
  switch (stop) {
    case OptimizationStop::kNotReached: return "not_reached";
    case OptimizationStop::kImprovementBelowMinimum: return "improvement_below_minimum";
    case OptimizationStop::kForwardRunBudget: return "forward_run_budget";
  }
  return "unknown";
}

namespace {

// Constraint i (>= 1) of the list, named, with the deck's desired value and deadband; `achieved`,
// `error`, `met` and `payoff_partial` are left for the caller.
ConstraintSummary describe_constraint(const Mission& mission, int code, ConstraintCode* decoded_out) {
  ConstraintSummary c;
  c.code = code;
  ConstraintCode decoded;
  const QuantityText text = code_text(c.code, &decoded);
  c.name = text.name;
  c.stage = decoded.is_stage_point ? decoded.stage_code : 0;
  c.unit = text.unit;
  c.angle = c.unit == "rad";
  c.inequality = is_inequality_constraint(decoded, mission.options);
  *decoded_out = decoded;
  return c;
}

void judge(const ConstraintCode& decoded, ConstraintSummary* c) {
  c->error = std::isfinite(c->achieved) ? constraint_deviation(decoded, c->achieved, c->desired) : kNaN;
  c->met = std::isfinite(c->error) &&
           constraint_met(decoded, c->inequality, c->achieved, c->desired, c->tolerance);
}

}  // namespace

void report_detail::write_constraint_table(Pager& pager, const std::vector<ConstraintSummary>& constraints,
                                           const std::string& heading) {
  if (constraints.empty()) return;
  pager.reserve(4 + static_cast<int>(constraints.size()));
  pager.emit(heading);
  pager.emit(
      "    NO.  CODE  PARAMETER                          DESIRED        ACHIEVED           ERROR"
      "       TOLERANCE  UNIT      MET");
  for (std::size_t i = 0; i < constraints.size(); ++i) {
    const ConstraintSummary& c = constraints[i];
    ConstraintCode decoded;
    const QuantityText text = code_text(c.code, &decoded);
    std::string line =
        right_aligned(std::to_string(i + 1), 7) + right_aligned(std::to_string(c.code), 6) + "  " +
        left_aligned(constraint_label(decoded, text) + (c.inequality ? " (MAX)" : ""), 27) +
        number_cell(c.desired, text.decimals, 16) + number_cell(c.achieved, text.decimals, 16) +
        number_cell(c.error, text.decimals, 16) + number_cell(c.tolerance, text.decimals, 16) + "  " +
        left_aligned(text.unit_heading, 9) + (c.met ? "YES" : "NO");
    pager.emit(line);
    if (c.angle) {
      pager.emit(std::string(42, ' ') + number_cell(c.desired * kRadToDeg, 6, 16) +
                 number_cell(c.achieved * kRadToDeg, 6, 16) + number_cell(c.error * kRadToDeg, 6, 16) +
                 number_cell(c.tolerance * kRadToDeg, 6, 16) + "  DEG");
    }
  }
  pager.emit("");
}

std::vector<ConstraintSummary> deck_constraint_summaries(const Mission& mission,
                                                         const Trajectory& trajectory) {
  const int count = std::clamp(mission.constraints.count, 0, kMaxConstraints);
  std::vector<ConstraintSummary> out;
  for (int i = 1; i < count; ++i) {
    ConstraintCode decoded;
    ConstraintSummary c = describe_constraint(mission, mission.constraints.codes[i], &decoded);
    c.desired = mission.constraints.desired[i];
    c.tolerance = mission.constraints.deadband_optimization[i - 1];
    c.achieved = evaluate_on_trajectory(mission, trajectory, c.code);
    c.payoff_partial = kNaN;
    judge(decoded, &c);
    out.push_back(c);
  }
  return out;
}

std::vector<ConstraintSummary> constraint_summaries(const OptimizationReport& report) {
  const Mission& mission = *report.final_trajectory.mission;
  const OptimizerResult& result = *report.result;
  if (!result_complete(report))
    return deck_constraint_summaries(mission, *report.final_trajectory.trajectory);
  const int count = std::clamp(result.constraint_count, 0, kMaxConstraints);
  std::vector<ConstraintSummary> out;
  for (int i = 1; i < count; ++i) {
    ConstraintCode decoded;
    ConstraintSummary c = describe_constraint(mission, result.codes[i], &decoded);
    c.desired = result.desired[i];
    c.achieved = result.achieved[i];
    c.tolerance = result.tolerance[i];
    c.payoff_partial = result.payoff_partials[i];
    judge(decoded, &c);
    out.push_back(c);
  }
  return out;
}

PayoffSummary payoff_summary(const OptimizationReport& report) {
  const Mission& mission = *report.final_trajectory.mission;
  const OptimizerResult& result = *report.result;
  const int ip1 = mission.options.payoff();
  PayoffSummary payoff;
  payoff.code = mission.constraints.codes[0];
  payoff.kind = payoff_kind_name(ip1);
  payoff.unit = payoff_unit(ip1);
  if (result_complete(report)) {
    payoff.value = result.payoff;
    payoff.corrected = result.corrected_payoff;
  } else {
    payoff.value = payoff.code == 0
                       ? mission.vehicle.payload_lb
                       : evaluate_on_trajectory(mission, *report.final_trajectory.trajectory, payoff.code);
    payoff.corrected = kNaN;
  }
  return payoff;
}

std::vector<AdjustableSummary> adjustable_summaries(const OptimizationReport& report) {
  const Mission& mission = *report.final_trajectory.mission;
  const Mission& initial = report.initial_mission != nullptr ? *report.initial_mission : mission;
  std::vector<AdjustableSummary> out;
  const int count = std::clamp(mission.adjustable.count, 0, kMaxAdjustableParameters);
  for (int p = 0; p < count; ++p) {
    AdjustableSummary a;
    a.code = mission.adjustable.codes[p];
    const ParameterText text = parameter_text(a.code);
    a.name = text.name;
    a.unit = text.unit;
    const double launch_day = std::floor(initial.launch.launch_space_age_date_days);
    a.initial_value = adjustable_value(initial, a.code, launch_day);
    a.value = adjustable_value(mission, a.code, launch_day);
    out.push_back(a);
  }
  return out;
}

namespace {

// A trajectory listed beside the final one (`--listing-level full|runs`): its points with all
// columns, its terminal conditions and, when it flew to the end, its orbit elements.
void write_other_trajectory(Pager& pager, const OptimizationReport& report, const Mission& mission,
                            const Trajectory& trajectory, const std::string& section, TrajectoryKind kind,
                            const Trajectory* reference) {
  SimulationReport listed;
  listed.mission = &mission;
  listed.listing = report.final_trajectory.listing;
  listed.trajectory = &trajectory;
  listed.status = trajectory.status;
  if (ok(listed.status) && stored_point_count(trajectory) == 0) listed.status = Status::kTrajectoryEmpty;
  if (ok(listed.status)) {
    listed.has_orbit = ok(compute_orbit_elements(mission.constants, trajectory.final_point().state,
                                                 mission.launch.launch_space_age_date_days, &listed.orbit));
  }
  listed.section = section;
  listed.kind = kind;
  listed.all_columns = true;
  listed.reference = reference;
  report_detail::write_trajectory_pages(pager, listed);
}

// Sec. 14 (REIN): "The ideal velocities and the final modified thrust tables are output whenever
// this calculation is performed": once per case, for the deck's stages, before the first run.
void write_thrust_modification(Pager& pager, const Mission& mission) {
  auto prepared = std::make_unique<PreparedCase>();
  pager.new_page("THRUST MODIFICATION", false);
  pager.emit(" IDEAL VELOCITY AND MODIFIED THRUST TABLES (SEC. 14): THE INPUT THRUST RE-TABULATED AT THE");
  pager.emit(" INTEGRATION TIMES, T(0) SET FOR THE INPUT IMPULSE OF THE FIRST STEP, SCALED BY A/B");
  pager.emit("");
  const Status status = prepare_case(mission, prepared.get());
  if (!ok(status)) {
    pager.emit(std::string("   NOT COMPUTED: ") + status_name(status) + ": " + status_message(status));
    pager.emit("");
    return;
  }
  for (int k = 0; k < prepared->stage_count; ++k) {
    const int code = prepared->timeline[k].code;
    if (!is_powered_stage(code)) continue;
    const ThrustModification& m = prepared->thrust_modification[stage_index(code)];
    const ModifiedThrustTable& table = prepared->modified_thrust_lbf[stage_index(code)];
    pager.reserve(7);
    pager.emit(" STAGE " + std::to_string(code));
    pager.emit("   IDEAL VELOCITY OF THE INPUT TABLE       A =" +
               number_cell(m.ideal_velocity_input_ft_s, 4, 16) + " FT/SEC");
    pager.emit("   IDEAL VELOCITY OF THE INTERPOLATED TABLE B =" +
               number_cell(m.ideal_velocity_grid_ft_s, 4, 16) + " FT/SEC");
    pager.emit("   SCALE A/B                                  =" + number_cell(m.scale, 9, 16));
    pager.emit("   NEW THRUST AT STAGE TIME 0 (BEFORE A/B)    =" +
               number_cell(m.new_initial_thrust_lbf, 2, 16) + " LB");
    pager.emit("   MODIFIED VACUUM THRUST TABLE:" + std::string(4, ' ') +
               "STAGE TIME SEC / VACUUM THRUST LB, " + std::to_string(table.size()) + " POINTS");
    for (int i = 0; i < table.size(); i += 4) {
      pager.reserve(1);
      std::string line = "  ";
      for (int j = i; j < std::min(i + 4, table.size()); ++j) {
        line += number_cell(table.x(j), 3, 11) + number_cell(table.y(j), 2, 14) + "   ";
      }
      pager.emit(line);
    }
    pager.emit("");
  }
}

// Sec. 22's program printout at the start of each linearization run: the program flown, segment
// by segment (theta at the segment start and the rate to the next break).
void write_linearization_programs(Pager& pager, const OptimizationReport& report) {
  if (report.linearization_programs.empty()) return;
  pager.new_page("LINEARIZATION RUNS", false);
  for (std::size_t n = 0; n < report.linearization_programs.size(); ++n) {
    const LinearProgram& p = report.linearization_programs[n];
    const int count = std::clamp(p.segment_count, 0, kMaxLinearSegments);
    pager.reserve(4 + count);
    const bool six_d = n < report.linearization_programs_6d.size() && report.linearization_programs_6d[n];
    pager.emit(" LINEARIZATION RUN " + std::to_string(n + 1) + (six_d ? " (6D)" : " (POINT MASS)") +
               ": PROGRAM FLOWN");
    pager.emit("    SEGMENT  BREAK TIME         THETA    PITCH RATE  FIXED");
    pager.emit("                    SEC           DEG       DEG/SEC");
    for (int s = 0; s <= count; ++s) {
      const double rate = s < count ? (p.theta_rad[s + 1] - p.theta_rad[s]) /
                                          (p.break_time_s[s + 1] - p.break_time_s[s]) * kRadToDeg
                                    : std::numeric_limits<double>::quiet_NaN();
      pager.emit((s < count ? right_aligned(std::to_string(s + 1), 11) : std::string(11, ' ')) +
                 number_cell(p.break_time_s[s], 3, 12) + number_cell(p.theta_rad[s] * kRadToDeg, 5, 14) +
                 (s < count ? number_cell(rate, 5, 14) : std::string(14, ' ')) +
                 (p.fixed[s] ? "  YES" : "   NO"));
    }
    pager.emit("");
  }
}

// The other trajectories of `--listing-level full|runs`: before the final one, the initial
// nominal and every forward run (kRuns); after the summary, the linearized trajectory (a final
// trajectory for data block 9: "Linearizations are treated as final trajectories") and the 6D
// initial nominal of IP(6) = 2.
void write_run_listings(Pager& pager, const OptimizationReport& report) {
  if (report.runs == nullptr) return;
  for (const ListedRun& run : report.runs->runs()) {
    const bool initial = run.record.kind == RunKind::kInitialNominal;
    const std::string section = initial ? std::string("INITIAL NOMINAL TRAJECTORY")
                                        : "FORWARD RUN " + std::to_string(run.record.forward_run) + " (" +
                                              run_kind_heading(run.record.kind) + ")";
    write_other_trajectory(pager, report, *run.mission, *run.flown, section,
                           initial ? TrajectoryKind::kInitial : TrajectoryKind::kIntermediate,
                           run.nominal.get());
  }
}

void write_after_summary(Pager& pager, const OptimizationReport& report) {
  write_linearization_programs(pager, report);
  if (report.linearized_trajectory != nullptr && report.linearized_mission != nullptr) {
    const bool six_d = report.linearization != nullptr && report.linearization->body_dynamics;
    write_other_trajectory(pager, report, *report.linearized_mission, *report.linearized_trajectory,
                           six_d ? "LINEARIZED TRAJECTORY (6D)" : "LINEARIZED TRAJECTORY",
                           TrajectoryKind::kFinal, report.final_trajectory.trajectory);
  }
  if (report.initial_nominal_6d != nullptr && report.initial_mission != nullptr) {
    write_other_trajectory(pager, report, *report.initial_mission, *report.initial_nominal_6d,
                           "INITIAL NOMINAL WITH BODY DYNAMICS (6D)", TrajectoryKind::kInitial,
                           report.initial_nominal_point_mass);
  }
}

// The final trajectory's DTHETA reference: the nominal the final guidance run was flown about,
// when that run is the reported trajectory.
const Trajectory* final_reference(const OptimizationReport& report) {
  if (report.runs == nullptr || report.runs->final_run() == nullptr) return nullptr;
  const Trajectory& run = *report.runs->final_run();
  const Trajectory& final_trajectory = *report.final_trajectory.trajectory;
  if (run.point_count != final_trajectory.point_count || stored_point_count(run) == 0) return nullptr;
  if (run.final_point().state != final_trajectory.final_point().state) return nullptr;
  return report.runs->final_run_nominal();
}

}  // namespace

void write_optimization_listing(std::ostream& out, const OptimizationReport& report) {
  const std::vector<ConstraintSummary> constraints = constraint_summaries(report);
  const std::vector<AdjustableSummary> adjustable = adjustable_summaries(report);
  const bool full = report.listing_level != ListingLevel::kFinal;
  Pager pager(out, report.final_trajectory.listing);
  if (full && report.initial_mission != nullptr) write_thrust_modification(pager, *report.initial_mission);
  pager.new_page("OPTIMIZATION HISTORY", false);
  write_problem(pager, report, constraints, adjustable);
  write_iteration_table(pager, report);
  write_iteration_details(pager, report, constraints);
  if (report.listing_level == ListingLevel::kRuns) write_run_listings(pager, report);
  if (full) {
    SimulationReport final_trajectory = report.final_trajectory;
    final_trajectory.all_columns = true;
    final_trajectory.reference = final_reference(report);
    report_detail::write_trajectory_pages(pager, final_trajectory);
  } else {
    report_detail::write_trajectory_pages(pager, report.final_trajectory);
  }
  pager.new_page("OPTIMIZATION SUMMARY", false);
  write_summary(pager, report, constraints, adjustable);
  write_exchange_ratios(pager, report);
  write_linearized_program(pager, report);
  if (full) write_after_summary(pager, report);
  if (report.dispersions != nullptr) report_detail::write_dispersion_pages(pager, *report.dispersions);
  if (report.impact != nullptr) report_detail::write_impact_pages(pager, *report.impact);
  if (report.hardover != nullptr) report_detail::write_hardover_pages(pager, *report.hardover);
  if (report.radar != nullptr) report_detail::write_radar_pages(pager, *report.radar);
  if (report.autopilot != nullptr) report_detail::write_autopilot_pages(pager, *report.autopilot);
}

}  // namespace tolip::ground
