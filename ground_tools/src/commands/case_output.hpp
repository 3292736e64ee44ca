// What the commands that run every case of a deck (simulate, optimize) share: the per-case name
// of an output file and the prefix of a case's diagnostics. Internal to ground_tools/src/commands.
#pragma once

#include <cstddef>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include <memory>

#include <nlohmann/json.hpp>

#include "tolip/trajectory/trajectory.hpp"
#include "tolip/vehicle/prepared_case.hpp"
#include "tolip_ground/atomic_file.hpp"
#include "tolip_ground/report.hpp"

namespace tolip::ground {

// One case flown as `simulate` flies it (the deck's program; IP(6) = 2 with body dynamics in
// stage 1): the report and the structures it points to. Shared by simulate and the commands that
// analyse the deck's trajectory (impact, radar, hardover).
struct SimulatedCase {
  std::unique_ptr<PreparedCase> prepared = std::make_unique<PreparedCase>();
  std::unique_ptr<Trajectory> trajectory = std::make_unique<Trajectory>();
  SimulationReport report;
};
void simulate_case(const Mission& mission, const DeckListingOptions& listing, const std::string& deck_path,
                   SimulatedCase* run);

// FILE for a deck of one case; for several, FILE with ".caseN" before the extension
// ("points.csv" -> "points.case2.csv", "points" -> "points.case2").
std::string case_file_path(const std::string& path, int case_number, std::size_t cases);

// True when no --csv file of the deck's cases (case_file_path) is the deck itself
// (names_same_file); else false with *error naming both.
bool csv_spares_the_deck(const std::string& csv_path, const std::string& deck_path, std::size_t cases,
                         std::string* error);

// "case N: " before a case's diagnostics when the deck has several cases, "" otherwise (a
// one-case deck keeps the messages it always had).
std::string case_message_prefix(int case_number, std::size_t cases);

// Writes what the cases produced, once every case has run: stdout gets one JSON document for a
// deck of one case, an array for several (`json`), else the collected listing; then stderr gets
// each case's failure line, in case order.
// `documents` is the JSON array of the cases' documents.
void write_case_outputs(std::ostream& out, std::ostream& err, bool json,
                        const nlohmann::ordered_json& documents, const std::string& listing,
                        const std::vector<std::string>& failures);

// Writes one CSV output (write(csv) fills it) atomically (nothing half-written); on failure the reason goes
// to err.
template <typename Write>
bool write_csv_or_report(const std::string& path, std::ostream& err, Write write) {
  std::string write_error;
  const bool written = write_file_atomically(
      path,
      [&write](std::ostream& csv) {
        write(csv);
        return static_cast<bool>(csv);
      },
      &write_error);
  if (!written) err << "tolip: " << write_error << '\n';
  return written;
}

}  // namespace tolip::ground
