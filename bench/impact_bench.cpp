// Speed of the nominal impact locus (manual Sec. 17; issue 12: the whole locus of the reference
// mission under 5 ms): compute_impact_locus() about the final nominal of the bundled example
// (the linearized 6D program, as `tolip optimize` takes it), every n-th point of stages 1-3 of its
// DA6D(17-19) and the three casings.
// Run: build/bench/impact_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <memory>

#include "bench_support.hpp"
#include "tolip/impact/impact.hpp"
#include "tolip_ground/impact_run.hpp"
#include "tolip_ground/optimization_run.hpp"

namespace {

struct Prepared : tolip::bench::OptimizedExample {
  tolip::ground::ImpactStep step;
};

const Prepared& prepared() {
  static Prepared* p = [] {
    auto* made = new Prepared;
    tolip::bench::load_and_optimize_example(made);
    const tolip::ground::DeckCase& c = made->example();
    auto data = std::make_unique<tolip::ImpactLocusData>();
    tolip::ground::ImpactMappingFault fault;
    if (!tolip::ground::fill_impact_data(*c.mission, c.extras, data.get(), &fault)) {
      tolip::bench::stop_setup(fault.message);
    }
    tolip::ground::run_impact_step(*c.mission, made->run, std::move(data), &made->step);
    if (made->step.outcome != tolip::ground::StepOutcome::kRun || !tolip::ok(made->step.status)) {
      tolip::bench::stop_setup("the example's impact locus did not run");
    }
    std::fprintf(stderr, "impact locus about the %s: %d cases\n", made->step.nominal_kind.c_str(),
                 made->step.locus->count);
    return made;
  }();
  return *p;
}

void BM_ReferenceImpactLocus(benchmark::State& state) {
  const Prepared& p = prepared();
  auto ws = std::make_unique<tolip::ImpactWorkspace>();
  auto locus = std::make_unique<tolip::ImpactLocus>();
  for (auto _ : state) {
    const tolip::Status status = tolip::compute_impact_locus(
        *p.step.mission, *p.step.prepared, *p.step.nominal, *p.step.data, ws.get(), locus.get());
    benchmark::DoNotOptimize(status);
  }
  state.counters["cases"] = static_cast<double>(locus->count);
}
BENCHMARK(BM_ReferenceImpactLocus)->Unit(benchmark::kMillisecond);

}  // namespace
