// Speed of the dispersion analysis (manual Sec. 15; issue 11: the full 38-code analysis under
// 10 ms): run_dispersions() about the linearized 6D program of the bundled example, every code of
// its data blocks 46-55 and the three-sigma groups (39 forward trajectories with the nominal).
// Run: build/bench/dispersion_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <memory>

#include "bench_support.hpp"
#include "tolip/dispersion/dispersion.hpp"
#include "tolip_ground/dispersion_run.hpp"
#include "tolip_ground/optimization_run.hpp"

namespace {

struct Prepared : tolip::bench::OptimizedExample {
  std::unique_ptr<tolip::DispersionData> data = std::make_unique<tolip::DispersionData>();
  tolip::DispersionNominal nominal;
};

const Prepared& prepared() {
  static Prepared* p = [] {
    auto* made = new Prepared;
    tolip::bench::load_and_optimize_example(made);
    const tolip::ground::DeckCase& c = made->example();
    tolip::ground::DispersionMappingFault fault;
    if (!tolip::ground::fill_dispersion_data(c.extras.dispersions, made->data.get(), &fault) ||
        made->run.linearization.result == nullptr) {
      tolip::bench::stop_setup("the example did not prepare");
    }
    made->nominal.mission = &made->run.linearization.workspace->mission;
    made->nominal.program = &made->run.linearization.workspace->program;
    made->nominal.body_dynamics = made->run.linearization.result->body_dynamics;
    return made;
  }();
  return *p;
}

void BM_Full38CodeDispersionAnalysis(benchmark::State& state) {
  const Prepared& p = prepared();
  auto ws = std::make_unique<tolip::DispersionWorkspace>();
  auto result = std::make_unique<tolip::DispersionResult>();
  for (auto _ : state) {
    const tolip::Status status = tolip::run_dispersions(p.nominal, *p.data, ws.get(), result.get());
    benchmark::DoNotOptimize(status);
  }
  state.counters["trajectories_per_s"] = benchmark::Counter(static_cast<double>(result->count + 1),
                                                            benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Full38CodeDispersionAnalysis)->Unit(benchmark::kMillisecond);

}  // namespace
