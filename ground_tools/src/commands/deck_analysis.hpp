// The shape the standalone analysis commands share (`tolip dispersions`, `impact`, `radar`,
// `hardover`), written once: load the deck, check it before anything runs, run every case in order
// into a listing or a JSON document (and, with --csv, a CSV file per case), then print all of it
// and each failed case's line. Each command keeps what is its own: the checks of its data blocks
// (and where they stand beside the --csv check), how a case is run and reported, its messages.
// The loading and --csv checks serve `simulate` and `optimize` too. Internal to
// ground_tools/src/commands.
#pragma once

#include <cstddef>
#include <functional>
#include <initializer_list>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "case_output.hpp"
#include "tolip/core/status.hpp"
#include "tolip_ground/card_deck.hpp"

namespace tolip::ground {

// Loads the deck at `path` (TOML or cards, every case checked); false after "tolip: <error>" on err
// (the command then exits 2 with nothing written).
bool load_deck_or_report(const std::string& path, Deck* deck, std::ostream& err);

// True when none of the output files (empty: not asked for) of any case is the deck itself
// (csv_spares_the_deck); else false after "tolip: <error>" on err for the first that is.
bool csv_files_spare_the_deck(std::initializer_list<std::string> csv_paths, const std::string& deck_path,
                              std::size_t cases, std::ostream& err);

// "tolip: <prefix><STATUS NAME>: <status message>\n": how a command reports a failed status.
std::string status_line(Status status, const std::string& prefix = "");

// What the cases of an analysis produce, collected until every case has run (stdout stays empty
// when a CSV write stops the command): the listing or the JSON documents, and the failure lines.
class CaseOutputs {
 public:
  CaseOutputs(std::size_t cases, const std::string& csv_path, bool json, std::ostream& err)
      : cases_(cases), csv_path_(csv_path), json_(json), err_(err) {}

  // --json: each case gives a document, else it writes to listing().
  bool json() const { return json_; }
  void add_document(nlohmann::ordered_json document) { documents_.push_back(std::move(document)); }
  std::ostream& listing() { return listing_; }

  // With --csv, writes the case's file (case_file_path) atomically with write(csv); false after
  // the reason on err (the command then stops with exit code 1). True without --csv.
  template <typename Write>
  bool write_csv(int case_number, Write write) {
    return csv_path_.empty() ||
           write_csv_or_report(case_file_path(csv_path_, case_number, cases_), err_, write);
  }

  // The case failed: "tolip: [case N: ]<context><STATUS>: <message>" goes to stderr after the
  // output, and the command exits 1.
  void add_failure(int case_number, const std::string& context, Status status) {
    failures_.push_back(status_line(status, case_message_prefix(case_number, cases_) + context));
  }

  // Prints what the cases produced (write_case_outputs); the command's exit code: 0 when no case
  // failed, else 1.
  int finish(std::ostream& out);

 private:
  std::size_t cases_;
  const std::string& csv_path_;
  bool json_;
  std::ostream& err_;
  std::ostringstream listing_;
  nlohmann::ordered_json documents_ = nlohmann::ordered_json::array();
  std::vector<std::string> failures_;
};

// One case of an analysis: runs deck.cases[index] and reports it into *outputs; false when the
// command must stop (a CSV not written).
using RunAnalysisCase =
    std::function<bool(std::size_t index, const DeckCase& deck_case, CaseOutputs* outputs)>;

// Names the deck's inputs read but not acted on (print_deck_input_warnings), runs every case in
// order and prints the outputs. The exit code: 0 every case ran, 1 a case failed (everything is
// still printed) or a CSV was not written (nothing printed).
int run_analysis_cases(const Deck& deck, const std::string& deck_path, const std::string& csv_path, bool json,
                       const RunAnalysisCase& run_case, std::ostream& out, std::ostream& err);

}  // namespace tolip::ground
