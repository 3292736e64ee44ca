// One case's optimization job: optimize, then linearize and compute exchange ratios as the deck's
// options ask (tolip_ground/optimization_run.hpp).
#include "tolip_ground/optimization_run.hpp"

namespace tolip::ground {

namespace {

Status fly_initial_nominal(const Mission& mission, bool body_dynamics, Trajectory* trajectory) {
  auto prepared = std::make_unique<PreparedCase>();
  const Status status = prepare_case(mission, prepared.get());
  if (!ok(status)) return status;
  FlightInputs inputs;
  inputs.body_dynamics = body_dynamics;
  return fly_trajectory(mission, *prepared, inputs, trajectory);
}

}  // namespace

void run_optimization(const Mission& mission, OptimizerObserver* observer, OptimizationRun* run) {
  // IP(6) = 2: the initial nominal with and without body dynamics (Sec. 7, 11, 22).
  if (mission.options.body_dynamics_6d() == 2) {
    InitialNominalBodyDynamicsStep& step = run->initial_nominal_6d;
    step.outcome = StepOutcome::kRun;
    step.point_mass = std::make_unique<Trajectory>();
    step.body_dynamics = std::make_unique<Trajectory>();
    step.status = fly_initial_nominal(mission, false, step.point_mass.get());
    if (ok(step.status)) step.status = fly_initial_nominal(mission, true, step.body_dynamics.get());
  }

  run->workspace = std::make_unique<OptimizerWorkspace>();
  run->result = std::make_unique<OptimizerResult>();
  run->workspace->observer = observer;
  run->optimizer_status = optimize_trajectory(mission, run->workspace.get(), run->result.get());
  run->workspace->observer = nullptr;  // the observer need not outlive this call
  // The optimizer's status is kOk exactly when it converged; otherwise it names the failed phase.
  const bool converged = ok(run->optimizer_status) && run->result->converged;
  const Status why_skipped = converged ? Status::kOk : run->optimizer_status;

  // Exchange ratios (IP(3), Sec. 8) of the optimized case: they describe the optimum, not the
  // straight-segment program.
  if (mission.options.exchange_ratios()) {
    ExchangeRatioStep& step = run->exchange_ratios;
    if (!converged) {
      step.outcome = StepOutcome::kSkipped;
      step.status = why_skipped;
    } else {
      step.outcome = StepOutcome::kRun;
      step.scratch = std::make_unique<ExchangeRatioScratch>();
      step.ratios = std::make_unique<ExchangeRatios>();
      step.status =
          compute_exchange_ratios(*run->workspace, *run->result, step.scratch.get(), step.ratios.get());
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
      step.status = linearize_pitch_program(*run->workspace, step.workspace.get(), step.result.get(),
                                            run->six_d_gains, run->linearization_observer);
    }
  }
}

JobVerdict optimization_job_verdict(const OptimizationRun& run) {
  if (!ok(run.optimizer_status)) return {run.optimizer_status, "optimization"};
  if (run.exchange_ratios.outcome != StepOutcome::kNotRequested && !ok(run.exchange_ratios.status)) {
    return {run.exchange_ratios.status, "exchange ratios"};
  }
  if (run.linearization.outcome != StepOutcome::kNotRequested && !ok(run.linearization.status)) {
    return {run.linearization.status, "linearization"};
  }
  return {};
}

}  // namespace tolip::ground
