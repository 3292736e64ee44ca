// One case's whole optimization job, in the order of the manual's sequence of iterations (Sec. 20,
// 22): the optimization (Sec. 5, 9), then, as the deck's options ask, the pitch-program
// linearization (IP(7), Sec. 6, 10) with its 6D re-linearization (IP(6) = 1, Sec. 7, 10, 11), and
// the performance exchange ratios (IP(3), Sec. 8, 12). `tolip optimize` reports it; `tolip export`
// takes its linearized program for the table image. The core does the work; this module owns the
// (large) workspaces on the heap and decides what runs after what.
#pragma once

#include <memory>

#include "tolip/core/status.hpp"
#include "tolip/mission/mission.hpp"
#include "tolip/optimizer/exchange_ratios.hpp"
#include "tolip/optimizer/linearization.hpp"
#include "tolip/optimizer/steepest_descent.hpp"

namespace tolip::ground {

// What a step of the job did: not asked for by the deck, skipped (an earlier step failed: the
// status says which), or run (the status is the step's own).
enum class StepOutcome : int { kNotRequested, kSkipped, kRun };

struct LinearizationStep {
  StepOutcome outcome = StepOutcome::kNotRequested;
  Status status = Status::kNotPrepared;
  std::unique_ptr<LinearizationWorkspace> workspace;  // workspace->nominal: the linearized trajectory
  std::unique_ptr<LinearizationResult> result;
};

struct ExchangeRatioStep {
  StepOutcome outcome = StepOutcome::kNotRequested;
  Status status = Status::kNotPrepared;
  std::unique_ptr<ExchangeRatioScratch> scratch;
  std::unique_ptr<ExchangeRatios> ratios;
};

// IP(6) = 2, "6D on initial nominal": the deck's own program flown point mass and with body
// dynamics (stage 1 and the coast after it), for the comparison the report prints. (With IP(6) = 1
// the 6D re-linearization is part of the linearization step.)
struct InitialNominalBodyDynamicsStep {
  StepOutcome outcome = StepOutcome::kNotRequested;
  Status status = Status::kNotPrepared;
  std::unique_ptr<Trajectory> point_mass;
  std::unique_ptr<Trajectory> body_dynamics;
};

struct OptimizationRun {
  std::unique_ptr<OptimizerWorkspace> workspace;  // workspace->nominal: the optimized trajectory
  std::unique_ptr<OptimizerResult> result;
  Status optimizer_status = Status::kNotPrepared;
  LinearizationStep linearization;
  ExchangeRatioStep exchange_ratios;
  InitialNominalBodyDynamicsStep initial_nominal_6d;
  // Designed autopilot gains with IP(6) = 1 (issue 16, autopilot_run.hpp): set by the caller before
  // run_optimization; the linearization calls it before its 6D runs. Null: the deck's constants.
  SixDGainDesign* six_d_gains = nullptr;
  // Told of each linearization run's program (`optimize --listing-level full|runs`); null: none.
  LinearizationObserver* linearization_observer = nullptr;
};

// Runs the job for a validated mission. `observer` (may be null) sees every optimizer forward run.
// Exchange ratios and linearization need a converged optimization; otherwise they are kSkipped
// with the optimizer's status.
void run_optimization(const Mission& mission, OptimizerObserver* observer, OptimizationRun* run);

// The one rule of a case's success, for every command that runs the job (optimize, export;
// docs/cli.md "Exit codes"): kOk when every computation the deck asks for succeeded (the
// optimization converged; the exchange ratios, under IP(3), were computed; the linearized program,
// under IP(7), meets every constraint and rate limit); otherwise the status of the first that
// did not, in the job's order, with that computation's name.
struct JobVerdict {
  Status status = Status::kOk;
  const char* failed_step = "";  // "optimization", "exchange ratios" or "linearization"
};
JobVerdict optimization_job_verdict(const OptimizationRun& run);

}  // namespace tolip::ground
