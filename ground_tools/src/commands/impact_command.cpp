// `tolip impact`: load a deck, fly each case as `simulate` does, compute its nominal impact locus
// (manual Sec. 17) and report it (listing, CSV, JSON).
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
#include "tolip_ground/impact_report.hpp"
#include "tolip_ground/impact_run.hpp"
#include "tolip_ground/report.hpp"
#include "tolip_ground/unused_inputs.hpp"

namespace tolip::ground {

int run_impact_command(const ImpactCommandOptions& options, std::ostream& out, std::ostream& err) {
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
  // Every case's data blocks 42-43 first: bad impact data stops the command with nothing written.
  // The command computes the locus whatever IP(23) says; it needs the data.
  std::vector<std::unique_ptr<ImpactLocusData>> data(cases);
  for (std::size_t k = 0; k < cases; ++k) {
    const DeckCase& deck_case = deck.cases[k];
    const std::string prefix = case_message_prefix(deck_case.number, cases);
    if (!deck_case.extras.impact.present) {
      err << "tolip: " << prefix << options.deck_path
          << ": data block 42 (impact): 'tolip impact' needs the failure-mode and casing drag tables "
             "[impact.failure_drag.N] and [impact.casing_drag.N] (data blocks 42-43)\n";
      return kExitBadInput;
    }
    data[k] = std::make_unique<ImpactLocusData>();
    ImpactMappingFault fault;
    if (!fill_impact_data(*deck_case.mission, deck_case.extras, data[k].get(), &fault)) {
      err << "tolip: " << prefix << impact_fault_text(options.deck_path, fault) << '\n';
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
    SimulatedCase run;
    simulate_case(*deck_case.mission, deck_case.extras.listing, options.deck_path, &run);
    ImpactStep step;
    run_impact_about(*deck_case.mission, *run.prepared, *run.trajectory, "deck program", std::move(data[k]),
                     &step);
    if (step.outcome != StepOutcome::kRun) step.status = run.report.status;

    if (!options.csv_path.empty() &&
        !write_csv_or_report(case_file_path(options.csv_path, deck_case.number, cases), err,
                             [&step](std::ostream& csv) { write_impact_csv(csv, step); })) {
      return kExitFailure;
    }
    if (options.json) {
      nlohmann::ordered_json document = trajectory_json(run.report);
      add_impact_member(&document, step);
      documents.push_back(std::move(document));
    } else {
      write_impact_listing(listing, &deck_case.extras.listing, step);
    }
    if (!ok(run.report.status) || !ok(step.status)) {
      const Status status = ok(run.report.status) ? step.status : run.report.status;
      failures.push_back("tolip: " + prefix + (ok(run.report.status) ? "impact locus: " : "") +
                         status_name(status) + ": " + status_message(status) + "\n");
    }
  }
  write_case_outputs(out, err, options.json, documents, listing.str(), failures);
  return failures.empty() ? kExitOk : kExitFailure;
}

}  // namespace tolip::ground
