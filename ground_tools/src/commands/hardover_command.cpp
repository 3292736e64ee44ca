// `tolip hardover`: load a deck, fly each case as `simulate` does and report the failure-mode
// hardover turns from its trajectory (Sec. 16; listing, JSON, CSV).
#include <memory>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "case_output.hpp"
#include "tolip/core/status.hpp"
#include "tolip_ground/atomic_file.hpp"
#include "tolip_ground/commands.hpp"
#include "tolip_ground/deck.hpp"
#include "tolip_ground/hardover_report.hpp"
#include "tolip_ground/hardover_run.hpp"
#include "tolip_ground/unused_inputs.hpp"

namespace tolip::ground {

int run_hardover_command(const HardoverCommandOptions& options, std::ostream& out, std::ostream& err) {
  Deck deck;
  DeckError deck_error;
  if (!load_deck(options.deck_path, &deck, &deck_error)) {
    err << "tolip: " << deck_error.to_string() << '\n';
    return kExitBadInput;
  }
  const std::size_t cases = deck.cases.size();
  std::vector<std::unique_ptr<tolip::HardoverData>> data(cases);
  for (std::size_t c = 0; c < cases; ++c) {
    const DeckCase& deck_case = deck.cases[c];
    if (!prepare_hardover_data(options.deck_path, case_message_prefix(deck_case.number, cases), deck_case,
                               &data[c], err)) {
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
  for (std::size_t c = 0; c < cases; ++c) {
    const DeckCase& deck_case = deck.cases[c];
    const Mission& mission = *deck_case.mission;
    SimulatedCase run;
    simulate_case(mission, deck_case.extras.listing, options.deck_path, &run);
    HardoverStep step;
    if (ok(run.report.status)) {
      run_hardover_step(mission, *run.prepared, *run.trajectory, "simulated", std::move(data[c]), &step);
    } else {
      skip_hardover_step(run.report.status, &step);
    }
    if (!options.csv_path.empty() &&
        !write_csv_or_report(case_file_path(options.csv_path, deck_case.number, cases), err,
                             [&step](std::ostream& csv) { write_hardover_csv(csv, step); })) {
      return kExitFailure;
    }
    if (options.json) {
      documents.push_back(
          hardover_document(deck_case.extras.listing, options.deck_path, run.report.status, step));
    } else {
      write_hardover_listing(listing, &deck_case.extras.listing, step);
    }
    if (!ok(step.status)) {
      const std::string prefix = case_message_prefix(deck_case.number, cases);
      failures.push_back("tolip: " + prefix + (ok(run.report.status) ? "hardover: " : "trajectory: ") +
                         status_name(step.status) + ": " + status_message(step.status) + "\n");
    }
  }
  write_case_outputs(out, err, options.json, documents, listing.str(), failures);
  return failures.empty() ? kExitOk : kExitFailure;
}

}  // namespace tolip::ground
