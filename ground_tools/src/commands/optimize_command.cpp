// `tolip optimize`: load a deck, run the closed-loop steepest-descent optimization
// (optimize_trajectory) of each case in order, report the iteration history and the final
// trajectory (listing, CSV, JSON).
#include <algorithm>
#include <memory>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "case_output.hpp"
#include "deck_analysis.hpp"
#include "tolip/core/status.hpp"
#include "tolip/optimizer/exchange_ratios.hpp"
#include "tolip/optimizer/steepest_descent.hpp"
#include "tolip/orbit/orbit_elements.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip_ground/atomic_file.hpp"
#include "tolip_ground/autopilot_run.hpp"
#include "tolip_ground/card_deck.hpp"
#include "tolip_ground/commands.hpp"
#include "tolip_ground/deck.hpp"
#include "tolip_ground/dispersion_report.hpp"
#include "tolip_ground/dispersion_run.hpp"
#include "tolip_ground/hardover_report.hpp"
#include "tolip_ground/hardover_run.hpp"
#include "tolip_ground/impact_report.hpp"
#include "tolip_ground/impact_run.hpp"
#include "tolip_ground/input_echo.hpp"
#include "tolip_ground/optimization_report.hpp"
#include "tolip_ground/optimization_run.hpp"
#include "tolip_ground/progress.hpp"
#include "tolip_ground/radar_report.hpp"
#include "tolip_ground/radar_run.hpp"
#include "tolip_ground/report.hpp"
#include "tolip_ground/run_listing.hpp"
#include "tolip_ground/unused_inputs.hpp"

namespace tolip::ground {
namespace {

// Statuses with which optimize_trajectory rejects the case before flying anything: the deck asks
// for an optimization the optimizer does not do (bad input, not a run-time failure).
bool rejects_problem(Status status) {
  return status == Status::kPayoffNotSupported || status == Status::kAdjustableParameterNotSupported ||
         status == Status::kUnknownConstraintCode;
}

// Where one case's work goes. The listing or JSON document is collected, not printed, so that
// stdout stays empty when a later case stops the command (a CSV failure, a rejected case).
struct CaseOutput {
  std::string csv_path;              // empty: no CSV
  std::string dispersions_csv_path;  // empty: no dispersion CSV
  std::string impact_csv_path;       // empty: no impact-locus CSV
  std::string radar_csv_path;        // empty: no radar CSV
  std::string hardover_csv_path;     // empty: no hardover CSV
  bool json = false;
  std::string prefix;  // before the case's diagnostics ("case N: " in a several-case deck)
  std::ostream* listing = nullptr;
  nlohmann::ordered_json document;
  Status failure = Status::kOk;  // the status to report once stdout is written (kOk: none)
  const char* failed_step = "";  // which computation of the job it belongs to
  bool stop = false;             // the command stops here, with nothing on stdout
  // `--listing-level` (run_listing.hpp); not given: the deck's data block 9 decides.
  bool listing_level_given = false;
  ListingLevel listing_level = ListingLevel::kFinal;
};

// One case: the optimization and its report. Returns the case's exit code.
int optimize_case(const Deck& deck, const DeckCase& deck_case, OptimizerObserver* observer,
                  ProgressLine& progress, CaseOutput* output, std::ostream& err) {
  const Mission* const mission = deck_case.mission.get();

  // Data blocks 46-55 into the core's fixed storage first: a table too long for it is bad input,
  // reported before anything runs (IP(21) = 1, Sec. 15).
  std::unique_ptr<DispersionData> dispersion_data;
  if (mission->options.dispersions()) {
    dispersion_data = std::make_unique<DispersionData>();
    DispersionMappingFault fault;
    if (!fill_dispersion_data(deck_case.extras.dispersions, dispersion_data.get(), &fault)) {
      err << "tolip: " << output->prefix << deck.path << ": data block " << fault.data_block
          << ", dispersion code " << fault.code << ", " << fault.field << ": " << fault.message << '\n';
      output->stop = true;
      return kExitBadInput;
    }
  }

  // Data blocks 42-43 and DA6D(17-19) likewise (IP(23) = 1, Sec. 17).
  std::unique_ptr<ImpactLocusData> impact_data;
  if (mission->options.impact()) {
    impact_data = std::make_unique<ImpactLocusData>();
    ImpactMappingFault fault;
    if (!fill_impact_data(*mission, deck_case.extras, impact_data.get(), &fault)) {
      err << "tolip: " << output->prefix << impact_fault_text(deck.path, fault) << '\n';
      output->stop = true;
      return kExitBadInput;
    }
  }

  // Data blocks 44-45 likewise (IP(22) = 1, Sec. 16): mapped and checked before anything runs.
  std::unique_ptr<tolip::HardoverData> hardover_data;
  if (mission->options.hardover() &&
      !prepare_hardover_data(deck.path, output->prefix, deck_case, &hardover_data, err)) {
    output->stop = true;
    return kExitBadInput;
  }

  // Designed autopilot gains (issue 16, autopilot_run.hpp): the request checked before anything runs.
  const bool autopilot_designed = deck_case.extras.autopilot.designed != 0;
  AutopilotPlan autopilot_plan;
  std::string autopilot_error;
  if (autopilot_designed &&
      !plan_autopilot_design(*mission, deck_case.extras, &autopilot_plan, &autopilot_error)) {
    err << "tolip: " << output->prefix << deck.path << ": " << autopilot_error << '\n';
    output->stop = true;
    return kExitBadInput;
  }

  // The optimization, then the linearization and exchange ratios the deck asks for
  // (tolip_ground/optimization_run.hpp); the workspaces are large and live on the heap.
  OptimizationRun run;
  std::unique_ptr<SixDAutopilotGains> six_d_gains;
  if (autopilot_designed && mission->options.linearization() && mission->options.body_dynamics_6d() == 1) {
    six_d_gains = std::make_unique<SixDAutopilotGains>(autopilot_plan);
    run.six_d_gains = six_d_gains.get();
  }
  // What the listing keeps of the runs (the JSON document needs none of it).
  const ListingLevel level = output->json ? ListingLevel::kFinal
                             : output->listing_level_given
                                 ? output->listing_level
                                 : deck_listing_level(deck_case.extras.listing.output);
  RunCapture capture(observer, level);
  LinearizationPrograms linearization_programs;
  if (level != ListingLevel::kFinal) run.linearization_observer = &linearization_programs;
  run_optimization(*mission, level != ListingLevel::kFinal ? &capture : observer, &run);
  progress.clear();  // before anything else goes to stderr
  if (six_d_gains != nullptr && six_d_gains->failed()) {
    err << "tolip: " << output->prefix << deck.path << ": " << six_d_gains->fault_text() << '\n';
    output->stop = true;
    return kExitBadInput;
  }
  OptimizerWorkspace* const workspace = run.workspace.get();
  const OptimizerResult* const result = run.result.get();
  const Status optimizer_status = run.optimizer_status;
  if (!ok(optimizer_status) && result->forward_runs == 0 && rejects_problem(optimizer_status)) {
    err << status_line(optimizer_status, output->prefix);
    output->stop = true;
    return kExitBadInput;
  }

  // The final (best) trajectory: the nominal flown with the optimized case. When no forward run
  // was made (prepare_case failed) there is none.
  Trajectory& trajectory = workspace->nominal;
  OptimizationReport report;
  report.initial_mission = mission;
  report.result = result;
  report.final_trajectory.mission = &workspace->mission;
  report.final_trajectory.listing = &deck_case.extras.listing;
  report.final_trajectory.trajectory = &trajectory;
  report.final_trajectory.deck_path = deck.path;
  report.listing_level = level;
  if (level != ListingLevel::kFinal) {
    report.runs = &capture;
    report.linearization_programs = linearization_programs.programs;
    report.linearization_programs_6d = linearization_programs.body_dynamics_runs;
  }

  Status trajectory_status = Status::kOk;
  if (result->forward_runs == 0) {
    trajectory.status = optimizer_status;
    trajectory.point_count = 0;
    trajectory.stage_count = 0;
    trajectory_status = optimizer_status;
  } else {
    trajectory_status = trajectory.status;
    if (ok(trajectory_status) && stored_point_count(trajectory) == 0)
      trajectory_status = Status::kTrajectoryEmpty;
  }
  if (ok(trajectory_status)) {
    trajectory_status = compute_orbit_elements(workspace->mission.constants, trajectory.final_point().state,
                                               workspace->mission.launch.launch_space_age_date_days,
                                               &report.final_trajectory.orbit);
    report.final_trajectory.has_orbit = ok(trajectory_status);
  }
  report.final_trajectory.status = trajectory_status;
  report.status = ok(optimizer_status) ? trajectory_status : optimizer_status;

  // Performance exchange ratios (IP(3) = 1, manual Sec. 8; docs/theory/exchange-ratios.md).
  report.exchange_ratios_requested = run.exchange_ratios.outcome != StepOutcome::kNotRequested;
  report.exchange_ratio_status = run.exchange_ratios.status;
  if (run.exchange_ratios.outcome == StepOutcome::kRun && ok(run.exchange_ratios.status)) {
    report.exchange_ratios = run.exchange_ratios.ratios.get();
  }
  // The linearized pitch program (IP(7) = 1, manual Sec. 6, 10; docs/theory/linearization.md).
  report.linearization_requested = run.linearization.outcome != StepOutcome::kNotRequested;
  report.linearization_status = run.linearization.status;
  report.optimum_payoff = result->payoff;
  // Body dynamics (IP(6) = 1: inside the linearization; 2: the initial nominal flown both ways).
  report.body_dynamics_option = mission->options.body_dynamics_6d();
  report.initial_nominal_6d_status = run.initial_nominal_6d.status;
  if (run.initial_nominal_6d.outcome == StepOutcome::kRun && ok(run.initial_nominal_6d.status)) {
    report.initial_nominal_point_mass = run.initial_nominal_6d.point_mass.get();
    report.initial_nominal_6d = run.initial_nominal_6d.body_dynamics.get();
  }
  if (run.linearization.outcome == StepOutcome::kRun) {
    report.linearization = run.linearization.result.get();
    if (report.linearization->finished && run.linearization.workspace != nullptr) {
      report.linearized_trajectory = &run.linearization.workspace->nominal;
      report.linearized_mission = &run.linearization.workspace->mission;
    }
  }
  // The dispersion analysis about the final nominal (IP(21) = 1, Sec. 15; dispersion_run.hpp).
  DispersionStep dispersions;
  if (mission->options.dispersions()) {
    run_dispersion_step(*mission, run, std::move(dispersion_data), &dispersions);
    report.dispersions = &dispersions;
  }
  // The impact locus about the same final nominal (IP(23) = 1, Sec. 17; impact_run.hpp).
  ImpactStep impact;
  if (mission->options.impact()) {
    run_impact_step(*mission, run, std::move(impact_data), &impact);
    report.impact = &impact;
  }
  // The hardover turns from the final nominal (IP(22) = 1, Sec. 16; hardover_run.hpp).
  HardoverStep hardover;
  if (mission->options.hardover()) {
    FinalNominal nominal;
    std::string kind;
    Status why = Status::kOk;
    if (final_nominal_flight(*mission, run, &nominal, &kind, &why)) {
      run_hardover_step(*nominal.mission, *nominal.prepared, *nominal.trajectory, kind,
                        std::move(hardover_data), &hardover);
    } else {
      skip_hardover_step(why, &hardover);
    }
    report.hardover = &hardover;
  }
  // The autopilot gain schedule along the final nominal (issue 16; autopilot_run.hpp).
  AutopilotStep autopilot;
  if (autopilot_designed) {
    FinalNominal nominal;
    std::string kind;
    Status why = Status::kOk;
    if (final_nominal_flight(*mission, run, &nominal, &kind, &why)) {
      run_autopilot_step(*nominal.mission, autopilot_plan, *nominal.trajectory, kind, &autopilot);
      autopilot.six_d_scheduled = six_d_gains != nullptr && six_d_gains->called();
      if (!ok(autopilot.status)) {
        err << "tolip: " << output->prefix << deck.path << ": " << autopilot_fault_text(autopilot) << '\n';
        output->stop = true;
        return kExitBadInput;
      }
    } else {
      autopilot.outcome = StepOutcome::kSkipped;
      autopilot.status = why;
    }
    report.autopilot = &autopilot;
  }
  // The radar tracking of the final nominal (IP(24) = 1, Sec. 18; radar_run.hpp).
  RadarStep radar;
  if (mission->options.radar()) {
    std::string kind;
    Status why = Status::kOk;
    if (const Trajectory* nominal = final_nominal_trajectory(*mission, run, &kind, &why)) {
      run_radar_step(mission->constants, deck_case.extras.radar_stations, *nominal, kind, &radar);
    } else {
      skip_radar_step(deck_case.extras.radar_stations, why, &radar);
    }
    report.radar = &radar;
  }

  // The one rule of a case's success (optimization_job_verdict, shared with export): a trajectory or
  // orbit failure, else the first computation the deck asks for that did not succeed.
  JobVerdict verdict = optimization_job_verdict(run);
  if (ok(optimizer_status) && !ok(report.status)) verdict = {report.status, "final trajectory"};
  if (ok(verdict.status) && dispersions.outcome == StepOutcome::kRun && !ok(dispersions.status)) {
    verdict = {dispersions.status, "dispersions"};
  }
  if (ok(verdict.status) && impact.outcome == StepOutcome::kRun && !ok(impact.status)) {
    verdict = {impact.status, "impact locus"};
  }
  if (ok(verdict.status) && hardover.outcome == StepOutcome::kRun && !ok(hardover.status)) {
    verdict = {hardover.status, "hardover"};
  }
  if (ok(verdict.status) && radar.outcome == StepOutcome::kRun && !ok(radar.status)) {
    verdict = {radar.status, "radar"};
  }
  report.case_status = verdict.status;
  report.case_failed_step = verdict.failed_step;

  if (!output->csv_path.empty() && !write_csv_or_report(output->csv_path, err, [&report](std::ostream& csv) {
        write_trajectory_csv(csv, report.final_trajectory);
      })) {
    output->stop = true;
    return kExitFailure;
  }
  if (!output->dispersions_csv_path.empty() && mission->options.dispersions() &&
      !write_csv_or_report(output->dispersions_csv_path, err,
                           [&dispersions](std::ostream& csv) { write_dispersion_csv(csv, dispersions); })) {
    output->stop = true;
    return kExitFailure;
  }

  if (!output->impact_csv_path.empty() && mission->options.impact() &&
      !write_csv_or_report(output->impact_csv_path, err,
                           [&impact](std::ostream& csv) { write_impact_csv(csv, impact); })) {
    output->stop = true;
    return kExitFailure;
  }
  if (!output->radar_csv_path.empty() && mission->options.radar() &&
      !write_csv_or_report(output->radar_csv_path, err,
                           [&radar](std::ostream& csv) { write_radar_csv(csv, radar); })) {
    output->stop = true;
    return kExitFailure;
  }
  if (!output->hardover_csv_path.empty() && mission->options.hardover() &&
      !write_csv_or_report(output->hardover_csv_path, err,
                           [&hardover](std::ostream& csv) { write_hardover_csv(csv, hardover); })) {
    output->stop = true;
    return kExitFailure;
  }

  if (output->json) {
    output->document = optimization_json(report);
  } else {
    if (mission->options.print_input()) write_input_echo(*output->listing, deck, deck_case);  // IP(17)
    write_optimization_listing(*output->listing, report);
  }

  if (!ok(report.case_status)) {
    output->failure = report.case_status;
    output->failed_step = verdict.failed_step;
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

int run_optimize_command(const OptimizeCommandOptions& options, std::ostream& out, std::ostream& err) {
  Deck deck;
  if (!load_deck_or_report(options.deck_path, &deck, err)) return kExitBadInput;
  const std::size_t cases = deck.cases.size();
  if (!csv_files_spare_the_deck({options.csv_path, options.dispersions_csv_path, options.impact_csv_path,
                                 options.radar_csv_path, options.hardover_csv_path},
                                options.deck_path, cases, err)) {
    return kExitBadInput;
  }
  // Inputs read but not acted on are named, never dropped (tolip_ground/unused_inputs.hpp).
  print_deck_input_warnings(err, options.deck_path, deck);

  ProgressLine progress(err, progress_enabled(options.progress));
  std::ostringstream listing;
  nlohmann::ordered_json documents = nlohmann::ordered_json::array();
  std::vector<std::string> failures;
  int exit_code = kExitOk;
  for (const DeckCase& deck_case : deck.cases) {
    if (cases > 1)
      progress.set_prefix("case " + std::to_string(deck_case.number) + "/" + std::to_string(cases));
    OptimizerProgress observer(progress, *deck_case.mission);
    CaseOutput output;
    output.csv_path =
        options.csv_path.empty() ? "" : case_file_path(options.csv_path, deck_case.number, cases);
    output.dispersions_csv_path = options.dispersions_csv_path.empty()
                                      ? ""
                                      : case_file_path(options.dispersions_csv_path, deck_case.number, cases);
    output.impact_csv_path = options.impact_csv_path.empty()
                                 ? ""
                                 : case_file_path(options.impact_csv_path, deck_case.number, cases);
    output.radar_csv_path =
        options.radar_csv_path.empty() ? "" : case_file_path(options.radar_csv_path, deck_case.number, cases);
    output.hardover_csv_path = options.hardover_csv_path.empty()
                                   ? ""
                                   : case_file_path(options.hardover_csv_path, deck_case.number, cases);
    output.json = options.json;
    if (!options.listing_level.empty()) {
      output.listing_level_given = parse_listing_level(options.listing_level, &output.listing_level);
    }
    output.prefix = case_message_prefix(deck_case.number, cases);
    output.listing = &listing;
    const int case_exit =
        optimize_case(deck, deck_case, progress.enabled() ? &observer : nullptr, progress, &output, err);
    // A case the optimizer rejects is bad input and a CSV that cannot be written a reason to stop:
    // like a deck error, nothing goes to stdout.
    if (output.stop) return case_exit;
    if (options.json) documents.push_back(std::move(output.document));
    if (!ok(output.failure)) {
      failures.push_back(status_line(output.failure, output.prefix + output.failed_step + ": "));
    }
    exit_code = std::max(exit_code, case_exit);
  }

  // A deck of one case prints one document, as it always has; several cases an array.
  write_case_outputs(out, err, options.json, documents, listing.str(), failures);
  return exit_code;
}

}  // namespace tolip::ground
