// `tolip simulate`: load a deck (TOML or card deck), fly the forward trajectory of each case,
// report it (listing, CSV, JSON).
#include <memory>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "case_output.hpp"
#include "deck_analysis.hpp"
#include "tolip/core/status.hpp"
#include "tolip/orbit/orbit_elements.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip/vehicle/prepared_case.hpp"
#include "tolip_ground/atomic_file.hpp"
#include "tolip_ground/card_deck.hpp"
#include "tolip_ground/commands.hpp"
#include "tolip_ground/deck.hpp"
#include "tolip_ground/hardover_report.hpp"
#include "tolip_ground/hardover_run.hpp"
#include "tolip_ground/impact_report.hpp"
#include "tolip_ground/impact_run.hpp"
#include "tolip_ground/input_echo.hpp"
#include "tolip_ground/radar_report.hpp"
#include "tolip_ground/radar_run.hpp"
#include "tolip_ground/report.hpp"
#include "tolip_ground/unused_inputs.hpp"

namespace tolip::ground {

void simulate_case(const Mission& mission, const DeckListingOptions& listing, const std::string& deck_path,
                   SimulatedCase* run) {
  // PreparedCase and Trajectory are large fixed-capacity structures: kept on the heap.
  SimulationReport& report = run->report;
  Trajectory* trajectory = run->trajectory.get();
  report.mission = &mission;
  report.listing = &listing;
  report.trajectory = trajectory;
  report.deck_path = deck_path;

  Status status = prepare_case(mission, run->prepared.get());
  if (ok(status)) {
    // IP(6) = 2, "6D on initial nominal" (Sec. 22): the case's own program flown with body
    // dynamics in stage 1 and the coast after it (Sec. 7, 11).
    FlightInputs inputs;
    inputs.body_dynamics = mission.options.body_dynamics_6d() == 2;
    status = fly_trajectory(mission, *run->prepared, inputs, trajectory);
    if (ok(status) && !ok(trajectory->status)) status = trajectory->status;
    if (ok(status) && stored_point_count(*trajectory) == 0) status = Status::kTrajectoryEmpty;
  } else {
    trajectory->status = status;
    trajectory->point_count = 0;
    trajectory->stage_count = 0;
  }
  if (ok(status)) {
    const TrajectoryPoint& final_point = trajectory->final_point();
    status = compute_orbit_elements(mission.constants, final_point.state,
                                    mission.launch.launch_space_age_date_days, &report.orbit);
    report.has_orbit = ok(status);
  }
  report.status = status;
  // The deck's constraints, achieved against desired: what the engineer tunes the program for.
  report.constraints = deck_constraint_summaries(mission, *trajectory);
}

int run_simulate_command(const SimulateCommandOptions& options, std::ostream& out, std::ostream& err) {
  Deck deck;
  if (!load_deck_or_report(options.deck_path, &deck, err)) return kExitBadInput;
  const std::size_t cases = deck.cases.size();
  if (!csv_files_spare_the_deck({options.csv_path, options.radar_csv_path, options.hardover_csv_path},
                                options.deck_path, cases, err)) {
    return kExitBadInput;
  }
  // Inputs read but not acted on are named, never dropped (tolip_ground/unused_inputs.hpp).
  print_deck_input_warnings(err, options.deck_path, deck);
  // IP(21): the dispersions are taken about the final nominal, which only `optimize` produces.
  for (const DeckCase& deck_case : deck.cases) {
    if (!deck_case.mission->options.dispersions()) continue;
    print_input_warnings(err, options.deck_path, deck_case.number, static_cast<int>(deck.cases.size()),
                         {InputWarning{4, "IP(21)", "options.dispersions",
                                       "the dispersions (Sec. 15) are computed about the final nominal by "
                                       "`tolip optimize`; simulate flies the deck's program only"}});
  }

  // IP(23): data blocks 42-43 into the core's storage for every case before anything runs, so that
  // bad impact data stops the command with nothing written (Sec. 17; impact_run.hpp).
  std::vector<std::unique_ptr<ImpactLocusData>> impact_data(deck.cases.size());
  for (std::size_t k = 0; k < deck.cases.size(); ++k) {
    const DeckCase& deck_case = deck.cases[k];
    if (!deck_case.mission->options.impact()) continue;
    impact_data[k] = std::make_unique<ImpactLocusData>();
    ImpactMappingFault fault;
    if (!fill_impact_data(*deck_case.mission, deck_case.extras, impact_data[k].get(), &fault)) {
      err << "tolip: " << case_message_prefix(deck_case.number, cases)
          << impact_fault_text(options.deck_path, fault) << '\n';
      return kExitBadInput;
    }
  }

  // IP(22): data blocks 44-45 mapped and checked before anything flies (bad input, exit 2).
  std::vector<std::unique_ptr<tolip::HardoverData>> hardover_data(cases);
  for (std::size_t c = 0; c < cases; ++c) {
    const DeckCase& deck_case = deck.cases[c];
    if (deck_case.mission->options.hardover() &&
        !prepare_hardover_data(options.deck_path, case_message_prefix(deck_case.number, cases), deck_case,
                               &hardover_data[c], err)) {
      return kExitBadInput;
    }
  }

  // Everything goes to stdout at the end, so a CSV failure leaves stdout empty.
  std::ostringstream listing;
  nlohmann::ordered_json documents = nlohmann::ordered_json::array();
  std::vector<std::string> failures;
  for (std::size_t c = 0; c < cases; ++c) {
    const DeckCase& deck_case = deck.cases[c];
    SimulatedCase run;
    simulate_case(*deck_case.mission, deck_case.extras.listing, options.deck_path, &run);
    // The impact locus about the trajectory flown (IP(23) = 1, Sec. 17; impact_run.hpp).
    ImpactStep impact;
    if (impact_data[c] != nullptr) {
      run_impact_about(*deck_case.mission, *run.prepared, *run.trajectory, "deck program",
                       std::move(impact_data[c]), &impact);
      run.report.impact = &impact;
    }
    // IP(24) = 1: the radar tracking of the trajectory flown (Sec. 18; radar_run.hpp).
    RadarStep radar;
    if (deck_case.mission->options.radar()) {
      if (ok(run.report.status)) {
        run_radar_step(deck_case.mission->constants, deck_case.extras.radar_stations, *run.trajectory,
                       "simulated", &radar);
      } else {
        skip_radar_step(deck_case.extras.radar_stations, run.report.status, &radar);
      }
      run.report.radar = &radar;
    }
    // IP(22) = 1: the hardover turns from the trajectory flown (Sec. 16; hardover_run.hpp).
    HardoverStep hardover;
    if (deck_case.mission->options.hardover()) {
      if (ok(run.report.status)) {
        run_hardover_step(*deck_case.mission, *run.prepared, *run.trajectory, "simulated",
                          std::move(hardover_data[c]), &hardover);
      } else {
        skip_hardover_step(run.report.status, &hardover);
      }
      run.report.hardover = &hardover;
    }

    // Every point flown goes to the CSV, also after a failure (it shows where the run stopped).
    if (!options.csv_path.empty() &&
        !write_csv_or_report(
            case_file_path(options.csv_path, deck_case.number, cases), err,
            [&report = run.report](std::ostream& csv) { write_trajectory_csv(csv, report); })) {
      return kExitFailure;
    }
    // IP(24) / IP(22): the radar look angles and the hardover turns, each atomically.
    if (!options.radar_csv_path.empty() && deck_case.mission->options.radar() &&
        !write_csv_or_report(case_file_path(options.radar_csv_path, deck_case.number, cases), err,
                             [&radar](std::ostream& csv) { write_radar_csv(csv, radar); })) {
      return kExitFailure;
    }
    if (!options.hardover_csv_path.empty() && deck_case.mission->options.hardover() &&
        !write_csv_or_report(case_file_path(options.hardover_csv_path, deck_case.number, cases), err,
                             [&hardover](std::ostream& csv) { write_hardover_csv(csv, hardover); })) {
      return kExitFailure;
    }

    if (options.json) {
      nlohmann::ordered_json document = trajectory_json(run.report);
      if (run.report.impact != nullptr) add_impact_member(&document, impact);
      documents.push_back(std::move(document));
    } else {
      if (deck_case.mission->options.print_input()) write_input_echo(listing, deck, deck_case);
      write_trajectory_listing(listing, run.report);
    }
    if (!ok(run.report.status)) {
      failures.push_back(status_line(run.report.status, case_message_prefix(deck_case.number, cases)));
    } else if (impact.outcome == StepOutcome::kRun && !ok(impact.status)) {
      failures.push_back(
          status_line(impact.status, case_message_prefix(deck_case.number, cases) + "impact locus: "));
    } else if (hardover.outcome == StepOutcome::kRun && !ok(hardover.status)) {
      failures.push_back(
          status_line(hardover.status, case_message_prefix(deck_case.number, cases) + "hardover: "));
    } else if (radar.outcome == StepOutcome::kRun && !ok(radar.status)) {
      failures.push_back(status_line(radar.status, case_message_prefix(deck_case.number, cases) + "radar: "));
    }
  }

  write_case_outputs(out, err, options.json, documents, listing.str(), failures);
  return failures.empty() ? kExitOk : kExitFailure;
}

}  // namespace tolip::ground
