// `tolip radar`: load a deck, fly each case as `simulate` does and report the radar tracking of
// its trajectory from the data block 41 stations (Sec. 18; listing, JSON, CSV).
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "case_output.hpp"
#include "tolip/core/status.hpp"
#include "tolip_ground/atomic_file.hpp"
#include "tolip_ground/commands.hpp"
#include "tolip_ground/deck.hpp"
#include "tolip_ground/radar_report.hpp"
#include "tolip_ground/radar_run.hpp"
#include "tolip_ground/unused_inputs.hpp"

namespace tolip::ground {

int run_radar_command(const RadarCommandOptions& options, std::ostream& out, std::ostream& err) {
  Deck deck;
  DeckError deck_error;
  if (!load_deck(options.deck_path, &deck, &deck_error)) {
    err << "tolip: " << deck_error.to_string() << '\n';
    return kExitBadInput;
  }
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
  if (std::string csv_error; !csv_spares_the_deck(options.csv_path, options.deck_path, cases, &csv_error)) {
    err << "tolip: " << csv_error << '\n';
    return kExitBadInput;
  }
  print_deck_input_warnings(err, options.deck_path, deck);

  std::ostringstream listing;
  nlohmann::ordered_json documents = nlohmann::ordered_json::array();
  std::vector<std::string> failures;
  for (const DeckCase& deck_case : deck.cases) {
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
    if (!options.csv_path.empty() &&
        !write_csv_or_report(case_file_path(options.csv_path, deck_case.number, cases), err,
                             [&radar](std::ostream& csv) { write_radar_csv(csv, radar); })) {
      return kExitFailure;
    }
    if (options.json) {
      nlohmann::ordered_json document =
          radar_document(deck_case.extras.listing, options.deck_path, run.report.status, radar);
      documents.push_back(std::move(document));
    } else {
      write_radar_listing(listing, &deck_case.extras.listing, radar);
    }
    const std::string prefix = case_message_prefix(deck_case.number, cases);
    if (!ok(run.report.status) || !ok(radar.status)) {
      const Status status = ok(run.report.status) ? radar.status : run.report.status;
      failures.push_back("tolip: " + prefix + (ok(run.report.status) ? "radar: " : "trajectory: ") +
                         status_name(status) + ": " + status_message(status) + "\n");
    }
  }
  write_case_outputs(out, err, options.json, documents, listing.str(), failures);
  return failures.empty() ? kExitOk : kExitFailure;
}

}  // namespace tolip::ground
