// `tolip impact`: load a deck, fly each case as `simulate` does, compute its nominal impact locus
// (manual Sec. 17) and report it (listing, CSV, JSON).
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "case_output.hpp"
#include "deck_analysis.hpp"
#include "tolip/core/status.hpp"
#include "tolip_ground/card_deck.hpp"
#include "tolip_ground/commands.hpp"
#include "tolip_ground/impact_report.hpp"
#include "tolip_ground/impact_run.hpp"
#include "tolip_ground/report.hpp"

namespace tolip::ground {

int run_impact_command(const ImpactCommandOptions& options, std::ostream& out, std::ostream& err) {
  Deck deck;
  if (!load_deck_or_report(options.deck_path, &deck, err)) return kExitBadInput;
  const std::size_t cases = deck.cases.size();
  if (!csv_files_spare_the_deck({options.csv_path}, options.deck_path, cases, err)) return kExitBadInput;
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

  const auto run_case = [&](std::size_t k, const DeckCase& deck_case, CaseOutputs* outputs) {
    SimulatedCase run;
    simulate_case(*deck_case.mission, deck_case.extras.listing, options.deck_path, &run);
    ImpactStep step;
    run_impact_about(*deck_case.mission, *run.prepared, *run.trajectory, "deck program", std::move(data[k]),
                     &step);
    if (step.outcome != StepOutcome::kRun) step.status = run.report.status;

    if (!outputs->write_csv(deck_case.number, [&step](std::ostream& csv) { write_impact_csv(csv, step); })) {
      return false;
    }
    if (outputs->json()) {
      nlohmann::ordered_json document = trajectory_json(run.report);
      add_impact_member(&document, step);
      outputs->add_document(std::move(document));
    } else {
      write_impact_listing(outputs->listing(), &deck_case.extras.listing, step);
    }
    if (!ok(run.report.status)) {
      outputs->add_failure(deck_case.number, "", run.report.status);
    } else if (!ok(step.status)) {
      outputs->add_failure(deck_case.number, "impact locus: ", step.status);
    }
    return true;
  };
  return run_analysis_cases(deck, options.deck_path, options.csv_path, options.json, run_case, out, err);
}

}  // namespace tolip::ground
