// Radar tracking of a case (manual Sec. 18, IP(24) = 1; docs/theory/radar.md): the deck's data block
// 41 stations mapped into the core's RadarStations, and the core's compute_radar_tracking() on the
// trajectory the command produced (simulate: the deck's program; optimize: the final nominal, the
// linearized program when IP(7) = 1, else the optimum). Reports: radar_report.hpp.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "tolip/radar/radar.hpp"
#include "tolip_ground/deck_extras.hpp"
#include "tolip_ground/optimization_run.hpp"

namespace tolip::ground {

struct RadarStep {
  StepOutcome outcome = StepOutcome::kNotRequested;
  Status status = Status::kNotPrepared;     // compute_radar_tracking's, or why skipped
  std::string trajectory_kind;              // "simulated", "optimum" or "linearized program"
  std::vector<RadarStation> deck_stations;  // the deck's cards (names for the listing)
  std::unique_ptr<tolip::RadarStations> stations;
  std::unique_ptr<RadarResult> result;
};

// Data block 41 of the deck -> the core (identifications cut to 12 characters, as the card's
// 2A6 field holds; the deck reader already limits them).
void fill_radar_stations(const std::vector<RadarStation>& deck, tolip::RadarStations* stations);

// Tracks `trajectory` (the command's final trajectory, `kind` naming it) from the deck's stations.
void run_radar_step(const Constants& constants, const std::vector<RadarStation>& deck,
                    const Trajectory& trajectory, const std::string& kind, RadarStep* step);

// A step the command could not run (no trajectory to track): kSkipped with `why`.
void skip_radar_step(const std::vector<RadarStation>& deck, Status why, RadarStep* step);

// The final nominal of an optimization job, the trajectory the manual's optional computations
// follow (the rule of final_dispersion_nominal): the linearized program's trajectory under
// IP(7) = 1, else the optimum. Null with *why when the optimization did not converge or the
// linearization did not finish.
const Trajectory* final_nominal_trajectory(const Mission& mission, const OptimizationRun& run,
                                           std::string* kind, Status* why);

}  // namespace tolip::ground
