// One case's optimization job: optimize, then linearize and compute exchange ratios as the deck's
// options ask (tolip_ground/optimization_run.hpp).
#include "tolip_ground/optimization_run.hpp"

namespace tolip::ground {

void run_optimization(const Mission& mission, OptimizerObserver* observer, OptimizationRun* run) {
  run->workspace = std::make_unique<OptimizerWorkspace>();
  run->result = std::make_unique<OptimizerResult>();
  run->workspace->observer = observer;
  run->optimizer_status = optimize_trajectory(mission, run->workspace.get(), run->result.get());
  run->workspace->observer = nullptr;  // the observer need not outlive this call
  const bool converged = ok(run->optimizer_status) && run->result->converged;
  const Status why_skipped = ok(run->optimizer_status) ? Status::kOptimizerDidNotConverge : run->optimizer_status;

  // Exchange ratios (IP(3), Sec. 8) from the optimized case, before linearization changes nothing
  // of it: they describe the optimum, not the straight-segment program.
  if (mission.options.exchange_ratios()) {
    ExchangeRatioStep& step = run->exchange_ratios;
    if (!converged) {
      step.outcome = StepOutcome::kSkipped;
      step.status = why_skipped;
    } else {
      step.outcome = StepOutcome::kRun;
      step.scratch = std::make_unique<ExchangeRatioScratch>();
      step.ratios = std::make_unique<ExchangeRatios>();
      step.status = compute_exchange_ratios(*run->workspace, *run->result, step.scratch.get(), step.ratios.get());
    }
  }

  // Pitch-program linearization (IP(7), Sec. 6, 10).
  if (mission.options.linearization()) {
    LinearizationStep& step = run->linearization;
    if (!converged) {
      step.outcome = StepOutcome::kSkipped;
      step.status = why_skipped;
    } else {
      step.outcome = StepOutcome::kRun;
      step.workspace = std::make_unique<LinearizationWorkspace>();
      step.result = std::make_unique<LinearizationResult>();
      step.status = linearize_pitch_program(*run->workspace, step.workspace.get(), step.result.get());
    }
  }
}

}  // namespace tolip::ground
