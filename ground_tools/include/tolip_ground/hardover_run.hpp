// Hardover turns of a case (manual Sec. 16, IP(22) = 1; docs/theory/hardover.md): the deck's data
// blocks 44-45 mapped into the core's HardoverData, and the core's compute_hardover_turns() from
// the trajectory the command produced (simulate: the deck's program; optimize: the final nominal).
// Reports: hardover_report.hpp.
#pragma once

#include <memory>
#include <ostream>
#include <string>

#include "tolip/hardover/hardover.hpp"
#include "tolip_ground/deck_extras.hpp"
#include "tolip_ground/optimization_run.hpp"

namespace tolip::ground {

// Where fill_hardover_data() found deck data the core cannot hold.
struct HardoverMappingFault {
  int data_block = 0;
  std::string field;  // deck key path, e.g. "hardover.pitch_inertia.2"
  std::string message;
};

// Blocks 44-45 of the deck -> the core (inches -> ft; angles are already rad). False with *fault
// when a table is longer than the core holds (10 points, the 22E12.8 card).
bool fill_hardover_data(const HardoverData& deck, tolip::HardoverData* data, HardoverMappingFault* fault);

struct HardoverStep {
  StepOutcome outcome = StepOutcome::kNotRequested;
  Status status = Status::kNotPrepared;  // compute_hardover_turns', or why skipped
  HardoverFault fault;                   // where validation failed
  std::string trajectory_kind;           // "simulated", "optimum" or "linearized program"
  std::unique_ptr<tolip::HardoverData> data;
  std::unique_ptr<HardoverResult> result;
};

// Runs the turns from `trajectory` (flown with `prepared`).
void run_hardover_step(const Mission& mission, const PreparedCase& prepared, const Trajectory& trajectory,
                       const std::string& kind, std::unique_ptr<tolip::HardoverData> data,
                       HardoverStep* step);

void skip_hardover_step(Status why, HardoverStep* step);

struct DeckCase;  // tolip_ground/card_deck.hpp

// The case's blocks 44-45 mapped (fill_hardover_data) and checked (validate_hardover_data) before
// anything is flown: false, with "tolip: <prefix><deck>: data block N, ...: ..." on err, when the
// deck has no [hardover] or a datum is bad (the commands exit 2, nothing written).
bool prepare_hardover_data(const std::string& deck_path, const std::string& prefix, const DeckCase& deck_case,
                           std::unique_ptr<tolip::HardoverData>* data, std::ostream& err);

// The final nominal of an optimization job with the case and preparation it was flown with (the
// rule of final_nominal_trajectory, radar_run.hpp). False with *why when there is none.
struct FinalNominal {
  const Mission* mission = nullptr;
  const PreparedCase* prepared = nullptr;
  const Trajectory* trajectory = nullptr;
};
bool final_nominal_flight(const Mission& mission, const OptimizationRun& run, FinalNominal* nominal,
                          std::string* kind, Status* why);

}  // namespace tolip::ground
