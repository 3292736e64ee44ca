// `tolip radar`: load a deck, fly each case as `simulate` does and report the radar tracking of
// its trajectory from the data block 41 stations (Sec. 18; listing, JSON, CSV).
#include <ostream>
#include <string>

#include "case_output.hpp"
#include "deck_analysis.hpp"
#include "tolip/core/status.hpp"
#include "tolip_ground/commands.hpp"
#include "tolip_ground/deck.hpp"
#include "tolip_ground/radar_report.hpp"
#include "tolip_ground/radar_run.hpp"

namespace tolip::ground {

int run_radar_command(const RadarCommandOptions& options, std::ostream& out, std::ostream& err) {
  Deck deck;
  if (!load_deck_or_report(options.deck_path, &deck, err)) return kExitBadInput;
  const std::size_t cases = deck.cases.size();
  // Every case needs its stations (with IP(24) = 1 the deck reader already demands them).
  for (const DeckCase& deck_case : deck.cases) {
    if (deck_case.extras.radar_stations.empty()) {
      err << "tolip: " << case_message_prefix(deck_case.number, cases) << options.deck_path
          << ": data block 41, radar_station: the case has no radar stations; 'tolip radar' needs at least "
             "one [[radar_station]] (data block 41)\n";
      return kExitBadInput;
    }
  }
  if (!csv_files_spare_the_deck({options.csv_path}, options.deck_path, cases, err)) return kExitBadInput;

  const auto run_case = [&](std::size_t, const DeckCase& deck_case, CaseOutputs* outputs) {
    const Mission& mission = *deck_case.mission;
    SimulatedCase run;
    simulate_case(mission, deck_case.extras.listing, options.deck_path, &run);
    // A failed flight is tracked over the points it flew (they show where it stopped).
    RadarStep radar;
    if (run.trajectory->point_count > 0) {
      run_radar_step(mission.constants, deck_case.extras.radar_stations, *run.trajectory, "simulated",
                     &radar);
    } else {
      skip_radar_step(deck_case.extras.radar_stations, run.report.status, &radar);
    }
    if (!outputs->write_csv(deck_case.number, [&radar](std::ostream& csv) { write_radar_csv(csv, radar); })) {
      return false;
    }
    if (outputs->json()) {
      outputs->add_document(
          radar_document(deck_case.extras.listing, options.deck_path, run.report.status, radar));
    } else {
      write_radar_listing(outputs->listing(), &deck_case.extras.listing, radar);
    }
    if (!ok(run.report.status)) {
      outputs->add_failure(deck_case.number, "trajectory: ", run.report.status);
    } else if (!ok(radar.status)) {
      outputs->add_failure(deck_case.number, "radar: ", radar.status);
    }
    return true;
  };
  return run_analysis_cases(deck, options.deck_path, options.csv_path, options.json, run_case, out, err);
}

}  // namespace tolip::ground
