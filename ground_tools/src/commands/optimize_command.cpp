// `tolip optimize`: load a deck, run the closed-loop steepest-descent optimization
// (optimize_trajectory), report the iteration history and the final trajectory (listing, CSV, JSON).
#include <memory>
#include <ostream>
#include <string>

#include "tolip/core/status.hpp"
#include "tolip/optimizer/exchange_ratios.hpp"
#include "tolip/optimizer/steepest_descent.hpp"
#include "tolip/orbit/orbit_elements.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip_ground/atomic_file.hpp"
#include "tolip_ground/card_deck.hpp"
#include "tolip_ground/commands.hpp"
#include "tolip_ground/deck.hpp"
#include "tolip_ground/input_echo.hpp"
#include "tolip_ground/optimization_report.hpp"
#include "tolip_ground/report.hpp"

namespace tolip::ground {
namespace {

void print_status(std::ostream& err, Status status) {
  err << "tolip: " << status_name(status) << ": " << status_message(status) << '\n';
}

// Statuses with which optimize_trajectory rejects the case before flying anything: the deck asks
// for an optimization the optimizer does not do (bad input, not a run-time failure).
bool rejects_problem(Status status) {
  return status == Status::kPayoffNotSupported || status == Status::kAdjustableParameterNotSupported ||
         status == Status::kUnknownConstraintCode;
}

}  // namespace

int run_optimize_command(const OptimizeCommandOptions& options, std::ostream& out,
                         std::ostream& err) {
  std::unique_ptr<Mission> mission = make_mission();
  DeckError deck_error;
  if (!load_single_case_deck(options.deck_path, mission.get(), nullptr, &deck_error)) {  // TOML or card deck
    err << "tolip: " << deck_error.to_string() << '\n';
    return kExitBadInput;
  }

  // The workspace (several trajectories and a backward run) and the result are large.
  auto workspace = std::make_unique<OptimizerWorkspace>();
  auto result = std::make_unique<OptimizerResult>();
  const Status optimizer_status = optimize_trajectory(*mission, workspace.get(), result.get());
  if (!ok(optimizer_status) && result->forward_runs == 0 && rejects_problem(optimizer_status)) {
    print_status(err, optimizer_status);
    return kExitBadInput;
  }

  // The final (best) trajectory: the nominal flown with the optimized case. When no forward run
  // was made (prepare_case failed) there is none.
  Trajectory& trajectory = workspace->nominal;
  OptimizationReport report;
  report.initial_mission = mission.get();
  report.result = result.get();
  report.final_trajectory.mission = &workspace->mission;
  report.final_trajectory.trajectory = &trajectory;
  report.final_trajectory.deck_path = options.deck_path;

  Status trajectory_status = Status::kOk;
  if (result->forward_runs == 0) {
    trajectory.status = optimizer_status;
    trajectory.point_count = 0;
    trajectory.stage_count = 0;
    trajectory_status = optimizer_status;
  } else {
    trajectory_status = trajectory.status;
    if (ok(trajectory_status) && stored_point_count(trajectory) == 0) trajectory_status = Status::kNotPrepared;
  }
  if (ok(trajectory_status)) {
    trajectory_status = compute_orbit_elements(workspace->mission.constants, trajectory.final_point().state,
                                               workspace->mission.launch.launch_space_age_date_days,
                                               &report.final_trajectory.orbit);
    report.final_trajectory.has_orbit = ok(trajectory_status);
  }
  report.final_trajectory.status = trajectory_status;
  report.status = ok(optimizer_status) ? trajectory_status : optimizer_status;

  // Performance exchange ratios (IP(3) = 1, manual Sec. 8): after a converged optimization, from
  // the final optimized case (docs/theory/exchange-ratios.md).
  std::unique_ptr<ExchangeRatioScratch> exchange_scratch;  // large: a Mission, a case, a trajectory
  auto exchange_ratios = std::make_unique<ExchangeRatios>();
  report.exchange_ratios_requested = mission->options.exchange_ratios();
  if (report.exchange_ratios_requested) {
    if (!ok(report.status) || !result->converged) {
      report.exchange_ratio_status = ok(report.status) ? Status::kOptimizerDidNotConverge : report.status;
    } else {
      exchange_scratch = std::make_unique<ExchangeRatioScratch>();
      report.exchange_ratio_status =
          compute_exchange_ratios(*workspace, *result, exchange_scratch.get(), exchange_ratios.get());
      if (ok(report.exchange_ratio_status)) {
        report.exchange_ratios = exchange_ratios.get();
      } else {
        err << "tolip: exchange ratios not computed: " << status_name(report.exchange_ratio_status) << ": "
            << status_message(report.exchange_ratio_status) << '\n';
      }
    }
  }

  if (!options.csv_path.empty()) {
    std::string write_error;
    const bool written = write_file_atomically(
        options.csv_path,
        [&report](std::ostream& csv) {
          write_trajectory_csv(csv, report.final_trajectory);
          return static_cast<bool>(csv);
        },
        &write_error);
    if (!written) {
      err << "tolip: " << write_error << '\n';
      return kExitFailure;
    }
  }

  if (options.json) {
    out << dump_json(optimization_json(report));
  } else {
    if (mission->options.print_input()) write_input_echo(out, options.deck_path);  // IP(17)
    write_optimization_listing(out, report);
  }
  out.flush();

  if (!ok(report.status) || !result->converged) {
    print_status(err, ok(report.status) ? Status::kOptimizerDidNotConverge : report.status);
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace tolip::ground
