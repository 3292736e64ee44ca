// Closed-loop steepest descent (manual Sec. 5 control law, Sec. 9 programming, Sec. 22 sequence).
//
// From an initial nominal flown with the data block 40 pitch table, backward/forward guidance runs
// until the constraints are inside their data block 29 deadbands, then backward/forward
// optimization runs asking for payoff improvement (initial size from dP^2, eqs. 5-31..5-34,
// fallback DA13(1)), each judged by the corrected payoff (eqs. 9-18..9-22), halved on failure,
// until the attempt falls under DA13(2) or the forward-run budget DA13(3) is one short; then a
// final backward and forward guidance run. The controls are the per-point pitch program, the
// adjustable parameters of data block 6 (weights Y of data block 27) and, for payload payoff, the
// payload itself (Sec. 9 "Optimization for maximum payload"). See docs/theory/optimizer.md.
#pragma once

#include "tolip/core/capacity.hpp"
#include "tolip/core/status.hpp"
#include "tolip/mission/mission.hpp"
#include "tolip/optimizer/backward_run.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip/vehicle/prepared_case.hpp"

namespace tolip {

inline constexpr int kMaxOptimizerIterations = 80;  // history records kept; later runs are counted

enum class RunKind : int { kInitialNominal, kGuidance, kOptimization, kFinalGuidance };

// One forward run, as the manual prints at the start of each iteration.
struct IterationRecord {
  int forward_run = 0;
  RunKind kind = RunKind::kInitialNominal;
  // The run's own outcome: kOk, or why it stopped (kAltitudeBelowSurface, ...); then the payoff
  // values and constraint corrections below are NaN (the run has none).
  Status run_status = Status::kOk;
  bool successful = false;
  double attempted_payoff_improvement = 0.0;  // delta m_d on optimization runs
  double payoff = 0.0;                        // achieved on this run
  double corrected_payoff = 0.0;              // corrected to zero constraint error (eq. 9-21)
  double payload_lb = 0.0;
  double payload_increment_lb = 0.0;
  // d psi_i = desired - achieved for constraints i = 1..JC-1 (index 0 unused), data block 19 units.
  double constraint_corrections[kMaxConstraints] = {};
  // Partials of payoff with respect to each constraint (eq. 9-22) from the preceding backward run.
  double payoff_partials[kMaxConstraints] = {};
  // Constraint i was left out of this run's steering: it has no first-order effect the controls
  // can produce (its steerability was under kMinimumSteerableDeadbands), so it was held by its
  // deadband instead of driving the step (docs/theory/optimizer.md "Weak directions").
  bool constraint_held[kMaxConstraints] = {};
};

// Why the optimization phase ended (Sec. 22: "either until the attempted payoff improvement is
// smaller than a specified magnitude or until the count of forward trajectories is within one of
// a specified limit").
enum class OptimizationStop : int {
  kNotReached,               // no optimization run was made
  kImprovementBelowMinimum,  // the attempted payoff improvement fell under DA13(2)
  kForwardRunBudget,         // the forward-run count came within one of DA13(3)
};

struct OptimizerResult {
  // kOk only when converged; otherwise the phase that failed (kGuidanceDidNotConverge,
  // kOptimizationNotStarted, kFinalGuidanceFailed) or the core failure that stopped a run.
  Status status = Status::kNotPrepared;
  // Sec. 22's sequence ran to its end: a guidance run met every deadband, at least one optimization
  // run was made, the attempted improvement fell under DA13(2) (the manual's other way out, the
  // forward-run budget, ends the case too but leaves improvement on the table: not converged,
  // kOptimizationBudgetExhausted), and the final guidance run met every deadband. The reported
  // trajectory is then that final guidance run.
  bool converged = false;
  OptimizationStop optimization_stop = OptimizationStop::kNotReached;
  int guidance_runs = 0;      // forward guidance runs before the optimization phase
  int optimization_runs = 0;  // forward optimization runs (successful or not)
  int successful_optimization_runs = 0;
  bool final_guidance_met = false;  // the final forward guidance run met every deadband
  // The first attempted payoff improvement (payoff units): from dP^2 (eqs. 5-31..5-34), or DA13(1)
  // when that computation fails (`initial_improvement_from_da13_1`). 0 when never computed.
  double initial_payoff_improvement = 0.0;
  bool initial_improvement_from_da13_1 = false;
  int forward_runs = 0;
  int backward_runs = 0;
  int constraint_count = 0;
  int codes[kMaxConstraints] = {};
  double desired[kMaxConstraints] = {};
  double achieved[kMaxConstraints] = {};
  double tolerance[kMaxConstraints] = {};  // data block 29 optimization deadbands (0 for payoff)
  bool inequality[kMaxConstraints] = {};   // achieved <= desired + tolerance suffices
  double payoff = 0.0;
  double corrected_payoff = 0.0;
  double payload_lb = 0.0;
  double payoff_partials[kMaxConstraints] = {};
  int adjustable_count = 0;
  int adjustable_codes[kMaxAdjustableParameters] = {};
  // rad for attitudes and azimuth, s for coasts, Space Age Date days for the launch time (code 7).
  double adjustable_values[kMaxAdjustableParameters] = {};
  int iteration_count = 0;
  IterationRecord iterations[kMaxOptimizerIterations];
  int iterations_dropped = 0;  // forward runs after the first kMaxOptimizerIterations, not kept
  // Weak directions of the steering matrix (docs/theory/optimizer.md "Weak directions"): from the
  // last backward run, constraint i held (left out of the steering: no first-order effect) and its
  // steerability, the deadbands the typical control change dP^2 of eq. 5-31 moves it with the
  // other constraints held (0 for the payoff); and over the case, the forward runs on which
  // constraint i was held.
  bool constraint_held[kMaxConstraints] = {};
  double steerability_deadbands[kMaxConstraints] = {};
  int held_runs[kMaxConstraints] = {};
  // Guidance runs on which constraint i was deferred instead (the argument of perigee while another
  // constraint is outside its deadband: docs/theory/optimizer.md "Deferred argument of perigee");
  // those runs are not counted in held_runs.
  bool constraint_deferred[kMaxConstraints] = {};
  int deferred_runs[kMaxConstraints] = {};
  // Forward runs that failed (below the surface, a non-finite state, ...) and were recovered from:
  // the next attempt started again from the last good nominal with a smaller step.
  int crashed_runs = 0;
};

// Told of every forward run as it is recorded (a terminal progress display, a log). Called on the
// optimizer's own thread, between runs; it must not touch the workspace. A plain interface: a
// type-erased callable could allocate, and the core never does.
class OptimizerObserver {
 public:
  virtual void on_forward_run(const IterationRecord& record, const OptimizerResult& result) = 0;
  // The same run's trajectory (as far as it flew: its status says), the case it flew, and the
  // nominal it was flown about (null for the initial nominal), for a listing of every forward run
  // (data block 9's initial and intermediate trajectories). Right after on_forward_run, before the
  // run is accepted or dropped; the references do not outlive the call. Default: nothing.
  virtual void on_forward_trajectory(const IterationRecord& record, const Mission& flown_mission,
                                     const Trajectory& flown, const Trajectory* nominal) {
    static_cast<void>(record);
    static_cast<void>(flown_mission);
    static_cast<void>(flown);
    static_cast<void>(nominal);
  }

 protected:
  ~OptimizerObserver() = default;
};

// Everything the optimizer works on, in the caller's storage (large: keep it static or on the heap).
// After optimize_trajectory, `mission` holds the optimized payload, spun attitudes and coasts,
// `program` the optimized pitch program and `nominal` the final trajectory.
struct OptimizerWorkspace {
  Mission mission;
  PreparedCase prepared;
  ControlProgram program;
  ControlProgram candidate_program;
  Mission candidate_mission;
  PreparedCase candidate_prepared;
  Trajectory nominal;
  Trajectory candidate;
  BackwardRun backward;
  OptimizerObserver* observer = nullptr;  // optional; not owned
};

// Runs the whole optimization of `mission` (which must have passed validate_mission). A failure to
// converge still leaves the best trajectory found in the workspace and returns a named status.
Status optimize_trajectory(const Mission& mission, OptimizerWorkspace* workspace, OptimizerResult* result);

}  // namespace tolip
