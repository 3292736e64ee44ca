// The standalone analysis commands' shared driver (deck_analysis.hpp).
#include "deck_analysis.hpp"

#include "tolip_ground/commands.hpp"
#include "tolip_ground/unused_inputs.hpp"

namespace tolip::ground {

bool load_deck_or_report(const std::string& path, Deck* deck, std::ostream& err) {
  DeckError deck_error;
  if (load_deck(path, deck, &deck_error)) return true;
  err << "tolip: " << deck_error.to_string() << '\n';
  return false;
}

bool csv_files_spare_the_deck(std::initializer_list<std::string> csv_paths, const std::string& deck_path,
                              std::size_t cases, std::ostream& err) {
  for (const std::string& csv : csv_paths) {
    if (std::string csv_error; !csv_spares_the_deck(csv, deck_path, cases, &csv_error)) {
      err << "tolip: " << csv_error << '\n';
      return false;
    }
  }
  return true;
}

std::string status_line(Status status, const std::string& prefix) {
  return "tolip: " + prefix + status_name(status) + ": " + status_message(status) + "\n";
}

int CaseOutputs::finish(std::ostream& out) {
  write_case_outputs(out, err_, json_, documents_, listing_.str(), failures_);
  return failures_.empty() ? kExitOk : kExitFailure;
}

int run_analysis_cases(const Deck& deck, const std::string& deck_path, const std::string& csv_path, bool json,
                       const RunAnalysisCase& run_case, std::ostream& out, std::ostream& err) {
  // Inputs read but not acted on are named, never dropped (tolip_ground/unused_inputs.hpp).
  print_deck_input_warnings(err, deck_path, deck);
  CaseOutputs outputs(deck.cases.size(), csv_path, json, err);
  for (std::size_t k = 0; k < deck.cases.size(); ++k) {
    if (!run_case(k, deck.cases[k], &outputs)) return kExitFailure;
  }
  return outputs.finish(out);
}

}  // namespace tolip::ground
