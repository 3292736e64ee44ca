// How much `tolip optimize` lists (docs/cli.md "--listing-level"), and the forward runs kept for
// the longer listings (Sec. 22 "OUTPUT FORMAT": "the tabulated history of the trajectory variables
// for each forward iteration"; data block 9's initial and intermediate trajectories).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "tolip/mission/mission.hpp"
#include "tolip/optimizer/linearization.hpp"
#include "tolip/optimizer/steepest_descent.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip_ground/deck_extras.hpp"

namespace tolip::ground {

// kFinal: the iteration history, the final trajectory (two line groups) and the summary, as
// always. kFull adds the third line group of Sec. 22's columns on every trajectory listed, the
// Sec. 14 ideal-velocity and modified-thrust page, the linearized and 6D trajectories and the
// linearized program at the start of each linearization run. kRuns adds, to kFull, the initial
// nominal and every forward run at data block 9's initial and intermediate frequencies.
enum class ListingLevel : int { kFinal, kFull, kRuns };

const char* listing_level_name(ListingLevel level);  // "final", "full", "runs"
bool parse_listing_level(const std::string& text, ListingLevel* level);

// The level when the command line gives none: kRuns when data block 9 gives an initial or an
// intermediate frequency other than 1 (the deck asks for those trajectories to be listed, thinned),
// else kFinal.
ListingLevel deck_listing_level(const OutputFrequency& output);

// One forward run as the optimizer flew it: its record, the case it flew, its trajectory and the
// nominal it was flown about (none for the initial nominal).
struct ListedRun {
  IterationRecord record;
  std::unique_ptr<Mission> mission;
  std::unique_ptr<Trajectory> flown;
  std::unique_ptr<Trajectory> nominal;  // null: the initial nominal
};

// An observer that passes every run on to `inner` (the progress line; may be null) and keeps what
// the level lists: with kRuns every run, with kFull only the final guidance run's nominal (the
// final trajectory's DTHETA reference).
class RunCapture final : public OptimizerObserver {
 public:
  RunCapture(OptimizerObserver* inner, ListingLevel level) : inner_(inner), level_(level) {}
  void on_forward_run(const IterationRecord& record, const OptimizerResult& result) override;
  void on_forward_trajectory(const IterationRecord& record, const Mission& flown_mission,
                             const Trajectory& flown, const Trajectory* nominal) override;

  const std::vector<ListedRun>& runs() const { return runs_; }
  // The nominal the final guidance run was flown about, and that run's trajectory (null: none).
  const Trajectory* final_run_nominal() const { return final_nominal_.get(); }
  const Trajectory* final_run() const { return final_run_.get(); }

 private:
  OptimizerObserver* inner_;
  ListingLevel level_;
  std::vector<ListedRun> runs_;
  std::unique_ptr<Trajectory> final_nominal_;
  std::unique_ptr<Trajectory> final_run_;
};

// Keeps the program of every linearization run (Sec. 22's printout at the start of each run).
class LinearizationPrograms final : public LinearizationObserver {
 public:
  void on_linearization_run(int run, const LinearProgram& program, bool body_dynamics) override {
    static_cast<void>(run);
    programs.push_back(program);
    body_dynamics_runs.push_back(body_dynamics);
  }
  std::vector<LinearProgram> programs;
  std::vector<bool> body_dynamics_runs;
};

}  // namespace tolip::ground
