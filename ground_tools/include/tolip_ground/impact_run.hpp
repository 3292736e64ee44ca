// The nominal impact locus of a case (manual Sec. 17, IP(23) = 1; docs/theory/impact.md): the deck's
// data blocks 42-43 and DA6D(17-19) mapped into the core's ImpactLocusData, the nominal chosen
// (optimize: the final nominal of the job, by the dispersion analysis' own rule,
// final_dispersion_nominal: the linearized program when IP(7) = 1, else the optimum; simulate and
// `tolip impact`: the deck's program as simulate flies it), and the core's compute_impact_locus()
// on heap-held workspaces. Reports: impact_report.hpp.
#pragma once

#include <memory>
#include <string>

#include "tolip/impact/impact.hpp"
#include "tolip_ground/deck_extras.hpp"
#include "tolip_ground/optimization_run.hpp"

namespace tolip::ground {

// Where fill_impact_data() found deck data the core cannot take.
struct ImpactMappingFault {
  int data_block = 0;
  std::string word;   // the manual's word: "CD2F", "DA6D(19)", ...
  std::string field;  // deck key path: "impact.failure_drag.2", "body_dynamics.impact_every_nth_step[2]"
  std::string message;
};

// Deck data blocks 42-43 and DA6D(17-19) -> core, checked against the case (validate_impact_data:
// every stage 1-3 in the sequence has both tables, n between 1 and the stage's steps). False with
// *fault otherwise: bad input, to be reported before anything runs.
bool fill_impact_data(const Mission& mission, const DeckExtras& extras, ImpactLocusData* data,
                      ImpactMappingFault* fault);

// Data block 43 alone -> core for the casings of `stages` (stage k when stages[k - 1]; the Monte
// Carlo's casing impacts): each stage asked for in the sequence, with its casing table, area and
// weight valid (validate_casing_data); blocks 42 and DA6D(17-19) are not needed. False with
// *fault otherwise, `needed_by` naming the asker in the message ("--impacts").
bool fill_casing_impact_data(const Mission& mission, const DeckExtras& extras,
                             const bool (&stages)[kImpactStages], const std::string& needed_by,
                             ImpactLocusData* data, ImpactMappingFault* fault);

// "DECK: data block 33, DA6D(19) (body_dynamics.impact_every_nth_step[2]): message"
std::string impact_fault_text(const std::string& deck_path, const ImpactMappingFault& fault);

struct ImpactStep {
  StepOutcome outcome = StepOutcome::kNotRequested;
  Status status = Status::kNotPrepared;  // compute_impact_locus's, or why skipped
  std::string nominal_kind;              // "linearized program", "optimum" or "deck program"
  const Mission* mission = nullptr;      // the nominal's case (launch site, azimuth)
  std::unique_ptr<ImpactLocusData> data;
  std::unique_ptr<PreparedCase> prepared;  // the nominal's, when this step flew it
  std::unique_ptr<Trajectory> nominal;     // the nominal flown again (optimize)
  std::unique_ptr<ImpactWorkspace> workspace;
  std::unique_ptr<ImpactLocus> locus;
};

// The locus about a flown nominal (simulate, `tolip impact`): `prepared` and `trajectory` must
// outlive the step's use.
void run_impact_about(const Mission& mission, const PreparedCase& prepared, const Trajectory& trajectory,
                      const std::string& nominal_kind, std::unique_ptr<ImpactLocusData> data,
                      ImpactStep* step);

// The locus about the job's final nominal when the case asks for it (IP(23) = 1): flown again from
// final_dispersion_nominal()'s choice exactly as the dispersion analysis flies its nominal.
// Skipped (with the failing step's status) when the optimization did not converge or, under
// IP(7) = 1, the linearization did not finish.
void run_impact_step(const Mission& mission, const OptimizationRun& run,
                     std::unique_ptr<ImpactLocusData> data, ImpactStep* step);

}  // namespace tolip::ground
