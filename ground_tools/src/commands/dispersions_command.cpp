// `tolip dispersions`: load a deck, optimize each case as `optimize` does, and run the dispersion
// analysis of manual Sec. 15 (data blocks 46-55) about its final nominal whatever IP(21) says;
// report only that analysis (listing pages, CSV, JSON member `dispersions`).
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "case_output.hpp"
#include "deck_analysis.hpp"
#include "tolip/core/status.hpp"
#include "tolip_ground/card_deck.hpp"
#include "tolip_ground/commands.hpp"
#include "tolip_ground/dispersion_report.hpp"
#include "tolip_ground/dispersion_run.hpp"
#include "tolip_ground/optimization_run.hpp"
#include "tolip_ground/report.hpp"

namespace tolip::ground {

int run_dispersions_command(const DispersionsCommandOptions& options, std::ostream& out, std::ostream& err) {
  Deck deck;
  if (!load_deck_or_report(options.deck_path, &deck, err)) return kExitBadInput;
  const std::size_t cases = deck.cases.size();
  if (!csv_files_spare_the_deck({options.csv_path}, options.deck_path, cases, err)) return kExitBadInput;
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

  const auto run_case = [&](std::size_t k, const DeckCase& deck_case, CaseOutputs* outputs) {
    // The case as the deck gives it, with IP(21) = 1: the analysis the command is asked for.
    const auto mission = std::make_unique<Mission>(*deck_case.mission);
    mission->options.ip[21] = 1;
    OptimizationRun run;
    run_optimization(*mission, nullptr, &run);
    DispersionStep step;
    run_dispersion_step(*mission, run, std::move(data[k]), &step);

    if (step.outcome == StepOutcome::kRun &&
        !outputs->write_csv(deck_case.number,
                            [&step](std::ostream& csv) { write_dispersion_csv(csv, step); })) {
      return false;
    }
    if (outputs->json()) {
      nlohmann::ordered_json document;
      document["case"] = deck_case.number;
      document["optimizer_status"] = status_name(run.optimizer_status);
      document["dispersions"] = dispersion_json(step);
      outputs->add_document(std::move(document));
    } else {
      write_dispersion_listing(outputs->listing(), &deck_case.extras.listing, step);
    }
    if (step.outcome != StepOutcome::kRun) {
      outputs->add_failure(deck_case.number, "no final nominal to disperse about: ", step.status);
    } else if (!ok(step.status)) {
      outputs->add_failure(deck_case.number, "dispersions: ", step.status);
    }
    return true;
  };
  return run_analysis_cases(deck, options.deck_path, options.csv_path, options.json, run_case, out, err);
}

}  // namespace tolip::ground
