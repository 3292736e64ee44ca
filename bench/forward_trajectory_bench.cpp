// Speed of one forward trajectory of the reference mission (issue: at most 150 us on the 2-core
// development machine, median). Run: build/bench/forward_trajectory_bench --benchmark_repetitions=10
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <memory>

#include "support/repository_paths.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip_ground/deck.hpp"

namespace {

struct Case {
  std::unique_ptr<tolip::Mission> mission = tolip::ground::make_mission();
  std::unique_ptr<tolip::PreparedCase> prepared = std::make_unique<tolip::PreparedCase>();
  std::unique_ptr<tolip::Trajectory> trajectory = std::make_unique<tolip::Trajectory>();
};

Case& reference_case() {
  static Case c = [] {
    Case loaded;
    tolip::ground::DeckError error;
    const std::string path =
        std::string(tolip::repository_paths::examples_dir()) + "/scout/reference_optimum.toml";
    if (!tolip::ground::load_toml_deck(path, loaded.mission.get(), &error)) {
      std::fprintf(stderr, "%s\n", error.to_string().c_str());
      std::exit(1);
    }
    if (tolip::prepare_case(*loaded.mission, loaded.prepared.get()) != tolip::Status::kOk) std::exit(1);
    return loaded;
  }();
  return c;
}

// Lift-off and every stage to stage-4 burnout, storing all points (the thrust tables already
// re-tabulated, as on every iteration of an optimization).
void BM_ForwardTrajectory(benchmark::State& state) {
  Case& c = reference_case();
  for (auto _ : state) {
    const tolip::Status status = tolip::fly_trajectory(*c.mission, *c.prepared, c.trajectory.get());
    benchmark::DoNotOptimize(status);
    benchmark::DoNotOptimize(c.trajectory->final_point().state);
  }
  state.counters["points"] = c.trajectory->point_count;
}
BENCHMARK(BM_ForwardTrajectory)->Unit(benchmark::kMicrosecond);

// The per-case preparation: Sec. 14 thrust re-tabulation and launch geometry.
void BM_PrepareCase(benchmark::State& state) {
  Case& c = reference_case();
  for (auto _ : state) {
    const tolip::Status status = tolip::prepare_case(*c.mission, c.prepared.get());
    benchmark::DoNotOptimize(status);
  }
}
BENCHMARK(BM_PrepareCase)->Unit(benchmark::kMicrosecond);

// How much of an evaluation's time is latency: K independent Euler chains through evaluate_flight
// (the reference case in stage 1 at about 40 s, in the atmosphere), interleaved evaluation by
// evaluation. Each chain's next state needs its last derivative, as inside an RK4 step, so with
// K = 1 any wait on the evaluation's dependent chain (square roots, divisions, pow) is lost; with
// K = 2 the second chain's work can fill it. The time per evaluation at K = 2 against K = 1 bounds
// what interleaving samples could gain (docs/performance.md, "Seventh pass": about 5 %).
void BM_EvaluationChains(benchmark::State& state) {
  Case& c = reference_case();
  if (!ok(tolip::fly_trajectory(*c.mission, *c.prepared, c.trajectory.get()))) std::exit(1);
  int start = 0;
  while (start + 1 < c.trajectory->point_count && c.trajectory->points[start].time_s < 40.0) ++start;
  const tolip::TrajectoryPoint& point = c.trajectory->points[start];
  const tolip::StageContext stage =
      tolip::make_stage_context(*c.mission, *c.prepared, c.prepared->timeline[0]);
  tolip::StepCommand command;
  command.mode = tolip::AttitudeMode::kHeld;
  command.theta_start_rad = point.theta_command_rad;
  constexpr int kMaxChains = 4;
  constexpr int kEvaluations = 200;
  constexpr double kStepS = 1e-3;
  const int chains = static_cast<int>(state.range(0));
  tolip::Evaluation eval[kMaxChains];
  for (auto _ : state) {
    tolip::StateVector x[kMaxChains];
    for (int k = 0; k < chains; ++k) {  // chains a few feet apart: the same work, different numbers
      x[k] = point.state;
      x[k][tolip::kStateR] += 3.0 * k;
    }
    double t = point.time_s;
    for (int n = 0; n < kEvaluations; ++n) {
      for (int k = 0; k < chains; ++k) {
        tolip::evaluate_flight(*c.mission, *c.prepared, stage, command, t, x[k], 0.0, &eval[k]);
        x[k] += kStepS * eval[k].derivative;
      }
      t += kStepS;
    }
    for (int k = 0; k < chains; ++k) benchmark::DoNotOptimize(x[k]);
  }
  state.SetItemsProcessed(state.iterations() * chains * kEvaluations);
  state.counters["altitude_ft"] = eval[0].altitude_ft;
}
BENCHMARK(BM_EvaluationChains)->Arg(1)->Arg(2)->Arg(4)->Unit(benchmark::kMicrosecond);

}  // namespace
