// Speed of what follows the optimization (issue: each at most 20% of the full optimization time,
// BM_FullReferenceOptimization in optimizer_bench): the pitch-program linearization with all its
// attempts (Sec. 6, 10; the example's IP(6) = 1 adds the 6D re-linearization, and the point-mass
// attempts alone are measured too) and the exchange-ratio pass (Sec. 8, 12), all from the converged
// optimum of the bundled example. BM_FullReferenceOptimization is repeated here so that the ratio comes
// from one program run on one machine state.
// Run: build/bench/post_optimization_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <memory>

#include "support/repository_paths.hpp"
#include "tolip/optimizer/exchange_ratios.hpp"
#include "tolip/optimizer/linearization.hpp"
#include "tolip/optimizer/steepest_descent.hpp"
#include "tolip_ground/deck.hpp"

namespace {

struct Optimum {
  std::unique_ptr<tolip::Mission> mission = tolip::ground::make_mission();
  std::unique_ptr<tolip::OptimizerWorkspace> workspace = std::make_unique<tolip::OptimizerWorkspace>();
  std::unique_ptr<tolip::OptimizerResult> result = std::make_unique<tolip::OptimizerResult>();
};

// The example deck, optimized once.
const Optimum& optimum() {
  static Optimum* o = [] {
    auto* made = new Optimum;
    tolip::ground::DeckError error;
    const std::string path = std::string(tolip::repository_paths::examples_dir()) + "/scout/mission.toml";
    if (!tolip::ground::load_toml_deck(path, made->mission.get(), &error)) {
      std::fprintf(stderr, "%s\n", error.to_string().c_str());
      std::exit(1);
    }
    if (tolip::optimize_trajectory(*made->mission, made->workspace.get(), made->result.get()) !=
        tolip::Status::kOk) {
      std::fprintf(stderr, "the example did not optimize\n");
      std::exit(1);
    }
    return made;
  }();
  return *o;
}

void BM_FullReferenceOptimizationForRatio(benchmark::State& state) {
  const Optimum& o = optimum();
  auto ws = std::make_unique<tolip::OptimizerWorkspace>();
  auto result = std::make_unique<tolip::OptimizerResult>();
  for (auto _ : state) {
    const tolip::Status status = tolip::optimize_trajectory(*o.mission, ws.get(), result.get());
    benchmark::DoNotOptimize(status);
  }
}
BENCHMARK(BM_FullReferenceOptimizationForRatio)->Unit(benchmark::kMillisecond);

void BM_Linearization(benchmark::State& state) {
  const Optimum& o = optimum();
  auto ws = std::make_unique<tolip::LinearizationWorkspace>();
  auto result = std::make_unique<tolip::LinearizationResult>();
  for (auto _ : state) {
    const tolip::Status status = tolip::linearize_pitch_program(*o.workspace, ws.get(), result.get());
    benchmark::DoNotOptimize(status);
  }
  state.counters["forward_runs"] = result->forward_runs;
  state.counters["programs"] = result->programs_computed;
  state.counters["payoff_lb"] = result->payoff;
}
BENCHMARK(BM_Linearization)->Unit(benchmark::kMillisecond);

// The same without the 6D re-linearization (IP(6) = 0): the point-mass attempts alone.
void BM_LinearizationPointMassOnly(benchmark::State& state) {
  static auto point_mass = [] {
    auto ws = std::make_unique<tolip::OptimizerWorkspace>(*optimum().workspace);
    ws->mission.options.ip[6] = 0;
    return ws;
  }();
  auto ws = std::make_unique<tolip::LinearizationWorkspace>();
  auto result = std::make_unique<tolip::LinearizationResult>();
  for (auto _ : state) {
    const tolip::Status status = tolip::linearize_pitch_program(*point_mass, ws.get(), result.get());
    benchmark::DoNotOptimize(status);
  }
  state.counters["forward_runs"] = result->forward_runs;
  state.counters["payoff_lb"] = result->payoff;
}
BENCHMARK(BM_LinearizationPointMassOnly)->Unit(benchmark::kMillisecond);

void BM_ExchangeRatios(benchmark::State& state) {
  const Optimum& o = optimum();
  auto scratch = std::make_unique<tolip::ExchangeRatioScratch>();
  auto ratios = std::make_unique<tolip::ExchangeRatios>();
  for (auto _ : state) {
    const tolip::Status status =
        tolip::compute_exchange_ratios(*o.workspace, *o.result, scratch.get(), ratios.get());
    benchmark::DoNotOptimize(status);
  }
  state.counters["forward_runs"] = ratios->forward_runs;
}
BENCHMARK(BM_ExchangeRatios)->Unit(benchmark::kMillisecond);

}  // namespace
