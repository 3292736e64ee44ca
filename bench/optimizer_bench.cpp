// Speed of the optimizer (issue: the full reference optimization, to the final guidance run, at
// most 50 ms single thread), and of its parts: one backward run (adjoint of 4 constraints) and one
// forward run with a per-point pitch program.
// Run: build/bench/optimizer_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <memory>

#include "support/repository_paths.hpp"
#include "tolip/optimizer/steepest_descent.hpp"
#include "tolip_ground/deck.hpp"

namespace {

// `name` is a deck path under examples/: "scout/mission.toml", "scout/reference_optimum.toml",
// "strapon/mission.toml", "scout/mission_qalpha.toml", "escape/mission.toml".
tolip::Mission& load(const char* name) {
  static std::unique_ptr<tolip::Mission> missions[5];
  const std::string deck(name);
  const int slot = deck == "scout/mission.toml"             ? 0
                   : deck == "scout/reference_optimum.toml" ? 1
                   : deck == "strapon/mission.toml"         ? 2
                   : deck == "escape/mission.toml"          ? 4
                                                            : 3;
  if (!missions[slot]) {
    missions[slot] = tolip::ground::make_mission();
    tolip::ground::DeckError error;
    const std::string path = std::string(tolip::repository_paths::examples_dir()) + "/" + name;
    if (!tolip::ground::load_toml_deck(path, missions[slot].get(), &error)) {
      std::fprintf(stderr, "%s\n", error.to_string().c_str());
      std::exit(1);
    }
  }
  return *missions[slot];
}

tolip::OptimizerWorkspace& workspace() {
  static auto ws = std::make_unique<tolip::OptimizerWorkspace>();
  return *ws;
}

// The whole optimization of `mission`, with its run counts and payload as counters.
void optimize_repeatedly(benchmark::State& state, const tolip::Mission& mission) {
  auto result = std::make_unique<tolip::OptimizerResult>();
  for (auto _ : state) {
    const tolip::Status status = tolip::optimize_trajectory(mission, &workspace(), result.get());
    benchmark::DoNotOptimize(status);
  }
  state.counters["forward_runs"] = result->forward_runs;
  state.counters["backward_runs"] = result->backward_runs;
  state.counters["payload_lb"] = result->payload_lb;
}

void BM_FullReferenceOptimization(benchmark::State& state) {
  optimize_repeatedly(state, load("scout/mission.toml"));
}
BENCHMARK(BM_FullReferenceOptimization)->Unit(benchmark::kMillisecond);

// The reference mission with the 3,500 lb deg/ft^2 q-bar x alpha limit (issue 15,
// examples/scout/mission_qalpha.toml): the limit joins at the first feasible nominal, guidance
// removes its excess, the optimization runs along it (30 forward, 26 backward runs).
void BM_FullQAlphaOptimization(benchmark::State& state) {
  optimize_repeatedly(state, load("scout/mission_qalpha.toml"));
}
BENCHMARK(BM_FullQAlphaOptimization)->Unit(benchmark::kMillisecond);

// The second example (examples/strapon): boosters and core back to back, an elliptic target by
// orbit elements, a spherical Earth, the launch azimuth adjusted (two extra forward runs per
// backward run), from its crude four-line program: about 70 forward runs.
void BM_FullStrapOnOptimization(benchmark::State& state) {
  optimize_repeatedly(state, load("strapon/mission.toml"));
}
BENCHMARK(BM_FullStrapOnOptimization)->Unit(benchmark::kMillisecond);

// The Earth-escape example (examples/escape, Addendum H, issue 15): five stages, maximum payload
// to a hyperbolic excess velocity and asymptote direction from a crude elliptic start (the energy
// stand-in, then the true constraints), the launch time, two coasts and the spun stage-5 attitudes
// adjusted.
void BM_FullEscapeOptimization(benchmark::State& state) {
  optimize_repeatedly(state, load("escape/mission.toml"));
}
BENCHMARK(BM_FullEscapeOptimization)->Unit(benchmark::kMillisecond);

// The same case as a heritage deck flies it: no heading hold, so the first steps after the lift-off
// are near-vertical steps in regular coordinates (forward and backward; issue 10).
void BM_FullReferenceOptimizationWithoutHeadingHold(benchmark::State& state) {
  static tolip::Mission mission = load("scout/mission.toml");
  mission.launch.heading_hold_until_s = 0.0;
  optimize_repeatedly(state, mission);
}
BENCHMARK(BM_FullReferenceOptimizationWithoutHeadingHold)->Unit(benchmark::kMillisecond);

// One backward run over the reference optimum with the mission's 4 constraints (payload, altitude,
// gamma_I, V_I - V_circ), terminals given as unit partials.
void BM_BackwardRun(benchmark::State& state) {
  const tolip::Mission& mission = load("scout/reference_optimum.toml");
  tolip::OptimizerWorkspace& ws = workspace();
  if (!tolip::ok(tolip::prepare_case(mission, &ws.prepared)) ||
      !tolip::ok(tolip::fly_trajectory(mission, ws.prepared, &ws.nominal))) {
    std::exit(1);
  }
  tolip::ConstraintTerminal terminals[4];
  for (int j = 0; j < 4; ++j) {
    terminals[j].point = ws.nominal.point_count - 1;
    terminals[j].partials.setZero();
    terminals[j].partials[j == 0 ? 6 : j] = 1.0;
  }
  for (auto _ : state) {
    const tolip::Status status =
        tolip::run_backward(mission, ws.prepared, ws.nominal, 4, terminals, &ws.backward);
    benchmark::DoNotOptimize(status);
  }
}
BENCHMARK(BM_BackwardRun)->Unit(benchmark::kMicrosecond);

void BM_ForwardRunWithProgram(benchmark::State& state) {
  const tolip::Mission& mission = load("scout/reference_optimum.toml");
  tolip::OptimizerWorkspace& ws = workspace();
  if (!tolip::ok(tolip::prepare_case(mission, &ws.prepared)) ||
      !tolip::ok(tolip::fly_trajectory(mission, ws.prepared, &ws.nominal))) {
    std::exit(1);
  }
  ws.program.point_count = ws.nominal.point_count;
  for (int k = 0; k < ws.nominal.point_count; ++k) ws.program.theta_rad[k] = ws.nominal.points[k].theta_rad;
  for (auto _ : state) {
    const tolip::Status status = tolip::fly_trajectory(mission, ws.prepared, ws.program, &ws.candidate);
    benchmark::DoNotOptimize(status);
  }
}
BENCHMARK(BM_ForwardRunWithProgram)->Unit(benchmark::kMicrosecond);

}  // namespace
