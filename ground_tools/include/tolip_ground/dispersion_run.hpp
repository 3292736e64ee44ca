// The dispersion analysis of a case (manual Sec. 15, IP(21) = 1; docs/theory/dispersions.md): the
// deck's data blocks 46-55 mapped into the core's DispersionData, the final nominal chosen from the
// optimization job (the linearized program when IP(7) = 1, else the optimum), and the core's
// run_dispersions() on heap-held workspaces. Reports: dispersion_report.hpp.
#pragma once

#include <memory>
#include <string>

#include "tolip/dispersion/dispersion.hpp"
#include "tolip_ground/deck_extras.hpp"
#include "tolip_ground/optimization_run.hpp"

namespace tolip::ground {

// Where fill_dispersion_data() found deck data the core cannot hold.
struct DispersionMappingFault {
  int data_block = 0;
  int code = 0;       // dispersion code of the block 46 card
  std::string field;  // deck key path, e.g. "dispersion[3].thrust"
  std::string message;
};

// Deck data blocks 46-55 -> core (stations inches -> ft; angles are already rad). False with *fault
// when a table is longer than the core's capacity (blocks 30/38: 120 points, 35: 20, 53-54: 32), or
// when a source breaks a rule of validate_dispersion_data, its block and key named: among them the
// stacked stage 4/5 tables of codes 7-8 with block 55 that do not split by its durations
// (find_stacked_stage4_5_split: block 55 for durations that do not match, else 30 or 38). Every
// command rejects such a deck before it optimizes or flies anything.
bool fill_dispersion_data(const std::vector<DispersionCase>& deck, DispersionData* data,
                          DispersionMappingFault* fault);

struct DispersionStep {
  StepOutcome outcome = StepOutcome::kNotRequested;
  Status status = Status::kNotPrepared;  // run_dispersions' (the nominal's), or why skipped
  std::string nominal_kind;              // "linearized program" or "optimum"
  std::unique_ptr<DispersionData> data;
  std::unique_ptr<DispersionWorkspace> workspace;
  std::unique_ptr<DispersionResult> result;
};

// The final nominal of the job (the linearized program under IP(7) = 1, else the optimum): false
// with *why when the optimization did not converge or the linearization did not finish.
bool final_dispersion_nominal(const Mission& mission, const OptimizationRun& run, DispersionNominal* nominal,
                              std::string* kind, Status* why);

// Runs the analysis about the job's final nominal when the case asks for it (IP(21) = 1). Skipped
// (with the failing step's status) when the optimization did not converge, or, under IP(7) = 1,
// when the linearization did not finish. `data` must already be filled (fill_dispersion_data).
void run_dispersion_step(const Mission& mission, const OptimizationRun& run,
                         std::unique_ptr<DispersionData> data, DispersionStep* step);

}  // namespace tolip::ground
