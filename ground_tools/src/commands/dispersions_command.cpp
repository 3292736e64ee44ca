// `tolip dispersions`: load a deck, optimize each case as `optimize` does, and run the dispersion
// analysis of manual Sec. 15 (data blocks 46-55) about its final nominal whatever IP(21) says;
// report only that analysis (listing pages, CSV, JSON member `dispersions`).
#include <memory>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "case_output.hpp"
#include "tolip/core/status.hpp"
#include "tolip_ground/atomic_file.hpp"
#include "tolip_ground/card_deck.hpp"
#include "tolip_ground/commands.hpp"
#include "tolip_ground/dispersion_report.hpp"
#include "tolip_ground/dispersion_run.hpp"
#include "tolip_ground/optimization_run.hpp"
#include "tolip_ground/report.hpp"
#include "tolip_ground/unused_inputs.hpp"

namespace tolip::ground {

int run_dispersions_command(const DispersionsCommandOptions& options, std::ostream& out, std::ostream& err) {
  Deck deck;
  DeckError deck_error;
  if (!load_deck(options.deck_path, &deck, &deck_error)) {
    err << "tolip: " << deck_error.to_string() << '\n';
    return kExitBadInput;
  }
  const std::size_t cases = deck.cases.size();
  if (std::string csv_error; !csv_spares_the_deck(options.csv_path, options.deck_path, cases, &csv_error)) {
    err << "tolip: " << csv_error << '\n';
    return kExitBadInput;
  }
  // Every case's data blocks 46-55 first: bad dispersion data stops the command with nothing
  // written, before any optimization runs.
  std::vector<std::unique_ptr<DispersionData>> data(cases);
  for (std::size_t k = 0; k < cases; ++k) {
    const DeckCase& deck_case = deck.cases[k];
    const std::string prefix = case_message_prefix(deck_case.number, cases);
    if (deck_case.extras.dispersions.empty()) {
      err << "tolip: " << prefix << options.deck_path
          << ": data block 46 (dispersion): 'tolip dispersions' needs the dispersion cases [[dispersion]] "
             "(data blocks 46-55)\n";
      return kExitBadInput;
    }
    data[k] = std::make_unique<DispersionData>();
    DispersionMappingFault fault;
    if (!fill_dispersion_data(deck_case.extras.dispersions, data[k].get(), &fault)) {
      err << "tolip: " << prefix << options.deck_path << ": data block " << fault.data_block
          << ", dispersion code " << fault.code << ", " << fault.field << ": " << fault.message << '\n';
      return kExitBadInput;
    }
  }
  print_deck_input_warnings(err, options.deck_path, deck);

  std::ostringstream listing;
  nlohmann::ordered_json documents = nlohmann::ordered_json::array();
  std::vector<std::string> failures;
  for (std::size_t k = 0; k < cases; ++k) {
    const DeckCase& deck_case = deck.cases[k];
    const std::string prefix = case_message_prefix(deck_case.number, cases);
    // The case as the deck gives it, with IP(21) = 1: the analysis the command is asked for.
    const auto mission = std::make_unique<Mission>(*deck_case.mission);
    mission->options.ip[21] = 1;
    OptimizationRun run;
    run_optimization(*mission, nullptr, &run);
    DispersionStep step;
    run_dispersion_step(*mission, run, std::move(data[k]), &step);

    if (step.outcome == StepOutcome::kRun && !options.csv_path.empty() &&
        !write_csv_or_report(case_file_path(options.csv_path, deck_case.number, cases), err,
                             [&step](std::ostream& csv) { write_dispersion_csv(csv, step); })) {
      return kExitFailure;
    }
    if (options.json) {
      nlohmann::ordered_json document;
      document["case"] = deck_case.number;
      document["optimizer_status"] = status_name(run.optimizer_status);
      document["dispersions"] = dispersion_json(step);
      documents.push_back(std::move(document));
    } else {
      write_dispersion_listing(listing, &deck_case.extras.listing, step);
    }
    if (step.outcome != StepOutcome::kRun) {
      failures.push_back("tolip: " + prefix + "no final nominal to disperse about: " +
                         status_name(step.status) + ": " + status_message(step.status) + "\n");
    } else if (!ok(step.status)) {
      failures.push_back("tolip: " + prefix + "dispersions: " + status_name(step.status) + ": " +
                         status_message(step.status) + "\n");
    }
  }
  write_case_outputs(out, err, options.json, documents, listing.str(), failures);
  return failures.empty() ? kExitOk : kExitFailure;
}

}  // namespace tolip::ground
