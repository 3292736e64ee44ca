// `tolip hardover`: load a deck, fly each case as `simulate` does and report the failure-mode
// hardover turns from its trajectory (Sec. 16; listing, JSON, CSV).
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "case_output.hpp"
#include "deck_analysis.hpp"
#include "tolip/core/status.hpp"
#include "tolip_ground/commands.hpp"
#include "tolip_ground/deck.hpp"
#include "tolip_ground/hardover_report.hpp"
#include "tolip_ground/hardover_run.hpp"

namespace tolip::ground {

int run_hardover_command(const HardoverCommandOptions& options, std::ostream& out, std::ostream& err) {
  Deck deck;
  if (!load_deck_or_report(options.deck_path, &deck, err)) return kExitBadInput;
  const std::size_t cases = deck.cases.size();
  std::vector<std::unique_ptr<tolip::HardoverData>> data(cases);
  for (std::size_t c = 0; c < cases; ++c) {
    const DeckCase& deck_case = deck.cases[c];
    if (!prepare_hardover_data(options.deck_path, case_message_prefix(deck_case.number, cases), deck_case,
                               &data[c], err)) {
      return kExitBadInput;
    }
  }
  if (!csv_files_spare_the_deck({options.csv_path}, options.deck_path, cases, err)) return kExitBadInput;

  const auto run_case = [&](std::size_t c, const DeckCase& deck_case, CaseOutputs* outputs) {
    const Mission& mission = *deck_case.mission;
    SimulatedCase run;
    simulate_case(mission, deck_case.extras.listing, options.deck_path, &run);
    HardoverStep step;
    if (ok(run.report.status)) {
      run_hardover_step(mission, *run.prepared, *run.trajectory, "simulated", std::move(data[c]), &step);
    } else {
      skip_hardover_step(run.report.status, &step);
    }
    if (!outputs->write_csv(deck_case.number,
                            [&step](std::ostream& csv) { write_hardover_csv(csv, step); })) {
      return false;
    }
    if (outputs->json()) {
      outputs->add_document(
          hardover_document(deck_case.extras.listing, options.deck_path, run.report.status, step));
    } else {
      write_hardover_listing(outputs->listing(), &deck_case.extras.listing, step);
    }
    if (!ok(step.status)) {
      outputs->add_failure(deck_case.number,
                           ok(run.report.status) ? "hardover: " : "trajectory: ", step.status);
    }
    return true;
  };
  return run_analysis_cases(deck, options.deck_path, options.csv_path, options.json, run_case, out, err);
}

}  // namespace tolip::ground
