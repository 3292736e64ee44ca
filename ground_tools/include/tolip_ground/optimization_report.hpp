// Reports of an optimization (`tolip optimize`): the manual-style listing (Sec. 22 "OUTPUT FORMAT",
// "Output at Start of Each Iteration", then the final trajectory exactly as `simulate` lists it and
// a summary) and the JSON document (the `simulate --json` schema plus the optimizer's results).
// docs/cli.md describes both. Non-finite values are never printed as "nan": JSON gets null, the
// listing "-".
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tolip/core/status.hpp"
#include "tolip/mission/mission.hpp"
#include "tolip/optimizer/exchange_ratios.hpp"
#include "tolip/optimizer/linearization.hpp"
#include "tolip/optimizer/steepest_descent.hpp"
#include "tolip_ground/report.hpp"
#include "tolip_ground/run_listing.hpp"

namespace tolip::ground {
struct DispersionStep;
struct ImpactStep;
struct AutopilotStep;
}  // namespace tolip::ground

namespace tolip::ground {

// What `optimize` computed.
struct OptimizationReport {
  // The final trajectory: mission = the optimized case (OptimizerWorkspace::mission: optimized
  // payload, spun attitudes, coasts), trajectory = OptimizerWorkspace::nominal. Its status is that
  // of the trajectory and orbit elements alone (kOk when both exist), so the listing reports a
  // trajectory failure but not a failure to converge.
  SimulationReport final_trajectory;
  const Mission* initial_mission = nullptr;  // the deck as loaded (initial parameter values)
  const OptimizerResult* result = nullptr;   // required
  // The run's status: the optimizer's (kOk when converged; kGuidanceDidNotConverge,
  // kOptimizationNotStarted, kFinalGuidanceFailed, or the core failure that stopped it), or, when
  // that is kOk, the final trajectory's or orbit's failure.
  Status status = Status::kNotPrepared;
  // The case's result by the one rule of optimization_job_verdict (the exit code): kOk when every
  // computation the deck asks for succeeded, else the first failure and the computation's name.
  Status case_status = Status::kNotPrepared;
  std::string case_failed_step;
  // Performance exchange ratios (IP(3) = 1; manual Sec. 8, 12; compute_exchange_ratios), computed
  // after a converged optimization. `exchange_ratios` is null unless they were computed; when the
  // deck asks for them and they were not, `exchange_ratio_status` says why (the optimizer's status
  // when it did not converge, else the failure of the computation).
  bool exchange_ratios_requested = false;
  const ExchangeRatios* exchange_ratios = nullptr;
  Status exchange_ratio_status = Status::kNotPrepared;
  // The linearized pitch program (IP(7) = 1; manual Sec. 6, 10; linearize_pitch_program), after a
  // converged optimization. `linearization` is null unless it ran (then it holds the best program
  // found even when `linearization_status` says it did not converge); when the deck asks for it
  // and it did not run, `linearization_status` says why.
  bool linearization_requested = false;
  const LinearizationResult* linearization = nullptr;
  Status linearization_status = Status::kNotPrepared;
  // The optimum's payoff the linearized payoff is compared with (payoff units).
  double optimum_payoff = 0.0;
  // The linearized trajectory and the case it flew (LinearizationWorkspace::nominal, ::mission):
  // null unless the linearization ran and finished (its peak q-bar x alpha is reported).
  const Trajectory* linearized_trajectory = nullptr;
  const Mission* linearized_mission = nullptr;
  // Body dynamics (IP(6), Sec. 7, 10, 11). With 1, the 6D re-linearization's figures are in
  // `linearization`; with 2, the deck's own program flown point mass and 6D (null unless flown;
  // `initial_nominal_6d_status` says why not).
  int body_dynamics_option = 0;
  const Trajectory* initial_nominal_point_mass = nullptr;
  const Trajectory* initial_nominal_6d = nullptr;
  Status initial_nominal_6d_status = Status::kNotPrepared;
  // The dispersion analysis (IP(21) = 1, Sec. 15; dispersion_report.hpp): null unless asked for.
  const DispersionStep* dispersions = nullptr;
  // The impact locus (IP(23) = 1, Sec. 17; impact_report.hpp): null unless asked for.
  const ImpactStep* impact = nullptr;
  // The radar tracking of the final nominal (IP(24) = 1, Sec. 18; radar_run.hpp): null unless asked for.
  const RadarStep* radar = nullptr;
  // The hardover turns from the final nominal (IP(22) = 1, Sec. 16; hardover_run.hpp): null unless asked for.
  const HardoverStep* hardover = nullptr;
  // The designed autopilot gain schedule (issue 16; autopilot_run.hpp): null unless asked for.
  const AutopilotStep* autopilot = nullptr;
  // `--listing-level` (run_listing.hpp): the pages the listing adds to the default ones, and the
  // forward runs kept for them (null: none kept). The JSON document does not depend on either.
  ListingLevel listing_level = ListingLevel::kFinal;
  const RunCapture* runs = nullptr;
  // kFull and kRuns: the linearized program at the start of each linearization run (Sec. 22
  // "program printout"), in order, with the runs' kind (true: 6D). Empty: none kept.
  std::vector<LinearProgram> linearization_programs;
  std::vector<bool> linearization_programs_6d;
};

// One adjustable parameter of data block 6: degrees for attitudes and the launch azimuth,
// seconds for coast durations and for the launch time (code 7: seconds after 0h UT of the deck's
// launch day, data block 20 word 2).
struct AdjustableSummary {
  int code = 0;
  std::string name;            // "stage4_theta", "coast_after_stage_3", ...
  std::string unit;            // "deg" or "s"
  double initial_value = 0.0;  // from the deck
  double value = 0.0;          // final (optimized)
};

// The payoff (data block 8 entry 1) on the final trajectory: the payload (lb) itself for code 0,
// else the velocity or altitude at the final point.
struct PayoffSummary {
  int code = 0;            // data block 8 code of the payoff: 0, 1, 5 or 7
  const char* kind = "";   // payoff_kind_name(IP(1))
  const char* unit = "";   // payoff_unit(IP(1))
  double value = 0.0;      // achieved; NaN when it could not be evaluated
  double corrected = 0.0;  // corrected to zero constraint error (eq. 9-21); NaN unless the optimizer finished
};

// The peak |q-bar x alpha| of a trajectory (issue 15; docs/theory/constraints-and-ics.md "The q-bar x
// alpha path constraint"): over the phases with aerodynamic lift (the points the load limit covers:
// stages using the lift table of data block 32, in the atmosphere) and over every point, each with
// its time (lb deg/ft^2 as the deck gives the limit), the deck's limit (0: none) and the excess
// integral J of constraint code 200 (s). `met` is the optimizer's criterion: no limit, or J within
// its deadband kQbarAlphaExcessDeadbandS (the peak itself may then exceed the limit by about 1 %).
struct QbarAlphaSummary {
  double lift_peak_lb_deg_ft2 = 0.0;
  double lift_peak_time_s = 0.0;
  double peak_lb_deg_ft2 = 0.0;
  double peak_time_s = 0.0;
  double limit_lb_deg_ft2 = 0.0;
  double excess_integral_s = 0.0;
  bool met = true;
};
QbarAlphaSummary qbar_alpha_summary(const Mission& mission, const Trajectory& trajectory);

// "payload", "velocity" or "altitude" from IP(1) (0, 1, 2); "unknown" otherwise.
const char* payoff_kind_name(int ip1);
// "lb", "ft/s", "ft" for IP(1) = 0, 1, 2.
const char* payoff_unit(int ip1);
// "initial_nominal", "guidance", "optimization", "final_guidance".
const char* run_kind_name(RunKind kind);
// JSON spelling of how the optimization phase ended (docs/cli.md "optimization_stop").
const char* optimization_stop_name(OptimizationStop stop);

// The constraints after the payoff: the optimizer's list when it finished (data block 8 entries
// 2 .. IB3(1), then the heating constraint 14 if it became active), with its achieved values and
// partials; otherwise data block 8's list evaluated on the final trajectory (partials NaN).
std::vector<ConstraintSummary> constraint_summaries(const OptimizationReport& report);
std::vector<AdjustableSummary> adjustable_summaries(const OptimizationReport& report);
PayoffSummary payoff_summary(const OptimizationReport& report);

// Listing: iteration history pages, the final trajectory pages of write_trajectory_listing (page
// numbers continue), then the optimization summary.
void write_optimization_listing(std::ostream& out, const OptimizationReport& report);

// The JSON document of `tolip optimize --json` (schema in docs/cli.md).
nlohmann::ordered_json optimization_json(const OptimizationReport& report);

}  // namespace tolip::ground
