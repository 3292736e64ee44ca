// Thread scaling of the Monte Carlo dispersions (issue 11 "Speed": at least 1.8x on 2 cores):
// run_monte_carlo() of 200 samples of the bundled example about its linearized 6D program (every
// scalar source of data blocks 46-55 drawn per sample), on 1 and 2 threads. The ratio of the two
// wall-clock times is the scaling; samples_per_s is the rate (docs/performance.md).
// Run: build/bench/monte_carlo_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <memory>

#include "bench_support.hpp"
#include "tolip/dispersion/monte_carlo.hpp"
#include "tolip_ground/dispersion_run.hpp"
#include "tolip_ground/impact_run.hpp"
#include "tolip_ground/monte_carlo_run.hpp"
#include "tolip_ground/optimization_run.hpp"

namespace {

constexpr int kSamples = 200;

struct Prepared : tolip::bench::OptimizedExample {
  std::unique_ptr<tolip::DispersionData> data = std::make_unique<tolip::DispersionData>();
  tolip::DispersionNominal nominal;
  std::unique_ptr<tolip::ImpactLocusData> impact = std::make_unique<tolip::ImpactLocusData>();
  tolip::MonteCarloImpactRequest impacts;  // the casings of stages 1-3 (data block 43)
};

const Prepared& prepared() {
  static Prepared* p = [] {
    auto* made = new Prepared;
    tolip::bench::load_and_optimize_example(made);
    const tolip::ground::DeckCase& c = made->example();
    tolip::ground::DispersionMappingFault fault;
    std::string kind;
    tolip::Status why = tolip::Status::kOk;
    if (!tolip::ground::fill_dispersion_data(c.extras.dispersions, made->data.get(), &fault) ||
        !tolip::ground::final_dispersion_nominal(*c.mission, made->run, &made->nominal, &kind, &why)) {
      tolip::bench::stop_setup("the example did not prepare");
    }
    const bool stages[tolip::kImpactStages] = {true, true, true};
    tolip::ground::ImpactMappingFault impact_fault;
    if (!tolip::ground::fill_casing_impact_data(*c.mission, c.extras, stages, "the bench", made->impact.get(),
                                                &impact_fault)) {
      tolip::bench::stop_setup(impact_fault.message);
    }
    made->impacts.data = made->impact.get();
    for (int k = 0; k < tolip::kImpactStages; ++k) made->impacts.stages[k] = true;
    return made;
  }();
  return *p;
}

void BM_MonteCarloSamples(benchmark::State& state) {
  const Prepared& p = prepared();
  const int threads = static_cast<int>(state.range(0));
  tolip::ground::MonteCarloSamples samples;
  for (auto _ : state) {
    const tolip::Status status =
        tolip::ground::run_monte_carlo(p.nominal, *p.data, 1, kSamples, threads, &samples);
    benchmark::DoNotOptimize(status);
  }
  state.counters["samples_per_s"] =
      benchmark::Counter(static_cast<double>(kSamples), benchmark::Counter::kIsIterationInvariantRate);
}
// Wall-clock time: the threads' work is what is measured, not the calling thread's CPU time.
BENCHMARK(BM_MonteCarloSamples)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// One sample on the calling thread, CPU time: the per-core rate of issue 11's "10,000 dispersed
// trajectories per second per core" (samples 0, 1, 2, ... in turn, each built, prepared, flown and
// recorded as run_monte_carlo() does).
void BM_MonteCarloOneSample(benchmark::State& state) {
  const Prepared& p = prepared();
  auto ws = std::make_unique<tolip::DispersionWorkspace>();
  if (!tolip::ok(tolip::prepare_monte_carlo(p.nominal, *p.data, ws.get()))) std::exit(1);
  tolip::DispersedTrajectory nominal_values;
  if (!tolip::ok(tolip::record_dispersed_trajectory(*p.nominal.mission, ws->nominal_prepared, ws->nominal,
                                                    ws->nominal, nullptr, &nominal_values))) {
    std::exit(1);
  }
  tolip::DispersedTrajectory out;
  std::uint64_t sample = 0;
  for (auto _ : state) {
    const tolip::Status status = tolip::fly_monte_carlo_sample(p.nominal, *p.data, 1, sample++ % kSamples,
                                                               nominal_values, ws.get(), &out);
    benchmark::DoNotOptimize(status);
  }
  state.counters["samples_per_s"] = benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_MonteCarloOneSample)->Unit(benchmark::kMicrosecond);
// The same, samples 0-19 exactly once: a fixed piece of work for instruction counts, which do not
// depend on the machine's load (docs/performance.md):
//   valgrind --tool=callgrind --toggle-collect='tolip::fly_monte_carlo_sample*' \
//     build/bench/monte_carlo_bench --benchmark_filter=BM_MonteCarloOneSample/iterations:20
BENCHMARK(BM_MonteCarloOneSample)->Unit(benchmark::kMicrosecond)->Iterations(20);

// The same sample with its expended casings of stages 1-3 flown to impact (--impacts, by default
// under IP(23) = 1: fly_monte_carlo_casings after fly_monte_carlo_sample, as run_monte_carlo does):
// the difference to BM_MonteCarloOneSample is the casings' cost (docs/performance.md).
void BM_MonteCarloOneSampleWithImpacts(benchmark::State& state) {
  const Prepared& p = prepared();
  auto ws = std::make_unique<tolip::DispersionWorkspace>();
  auto impact_ws = std::make_unique<tolip::ImpactWorkspace>();
  if (!tolip::ok(tolip::prepare_monte_carlo(p.nominal, *p.data, ws.get()))) std::exit(1);
  tolip::DispersedTrajectory nominal_values;
  if (!tolip::ok(tolip::record_dispersed_trajectory(*p.nominal.mission, ws->nominal_prepared, ws->nominal,
                                                    ws->nominal, nullptr, &nominal_values))) {
    std::exit(1);
  }
  tolip::DispersedTrajectory out;
  tolip::MonteCarloImpacts impacts;
  std::uint64_t sample = 0;
  long steps = 0;
  for (auto _ : state) {
    tolip::Status status = tolip::fly_monte_carlo_sample(p.nominal, *p.data, 1, sample++ % kSamples,
                                                         nominal_values, ws.get(), &out);
    if (tolip::ok(status)) {
      status = tolip::fly_monte_carlo_casings(p.nominal, p.impacts, ws->mission, ws->prepared, ws->dispersed,
                                              impact_ws.get(), &impacts);
      for (int k = 0; k < impacts.count; ++k) steps += impacts.casings[k].steps;
    }
    benchmark::DoNotOptimize(status);
  }
  state.counters["samples_per_s"] = benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["casing_steps"] = static_cast<double>(steps) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_MonteCarloOneSampleWithImpacts)->Unit(benchmark::kMicrosecond);

// 200 samples on 1 and 2 threads with the casings (run_monte_carlo with the impact request).
void BM_MonteCarloSamplesWithImpacts(benchmark::State& state) {
  const Prepared& p = prepared();
  const int threads = static_cast<int>(state.range(0));
  tolip::ground::MonteCarloSamples samples;
  for (auto _ : state) {
    const tolip::Status status =
        tolip::ground::run_monte_carlo(p.nominal, *p.data, 1, kSamples, threads, &samples, {}, p.impacts);
    benchmark::DoNotOptimize(status);
  }
  state.counters["samples_per_s"] =
      benchmark::Counter(static_cast<double>(kSamples), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_MonteCarloSamplesWithImpacts)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The parts of one sample: building its case (the copy of the mission and prepared case, the draws,
// prepare_case when a weight or the azimuth changes), then the flight alone.
void BM_MonteCarloSampleCase(benchmark::State& state) {
  const Prepared& p = prepared();
  auto ws = std::make_unique<tolip::DispersionWorkspace>();
  if (!tolip::ok(tolip::prepare_monte_carlo(p.nominal, *p.data, ws.get()))) std::exit(1);
  std::uint64_t sample = 0;
  for (auto _ : state) {
    const tolip::Status status = tolip::build_monte_carlo_case(p.nominal, ws->nominal_prepared, *p.data, 1,
                                                               sample++ % kSamples, ws.get());
    benchmark::DoNotOptimize(status);
  }
}
BENCHMARK(BM_MonteCarloSampleCase)->Unit(benchmark::kMicrosecond);

void BM_MonteCarloSampleFlight(benchmark::State& state) {
  const Prepared& p = prepared();
  auto ws = std::make_unique<tolip::DispersionWorkspace>();
  if (!tolip::ok(tolip::prepare_monte_carlo(p.nominal, *p.data, ws.get()))) std::exit(1);
  if (!tolip::ok(tolip::build_monte_carlo_case(p.nominal, ws->nominal_prepared, *p.data, 1, 0, ws.get())))
    std::exit(1);
  tolip::FlightInputs inputs;
  inputs.program = p.nominal.program;
  inputs.body_dynamics = p.nominal.body_dynamics;
  inputs.perturbation = &ws->perturbation;
  for (auto _ : state) {
    const tolip::Status status = tolip::fly_trajectory(ws->mission, ws->prepared, inputs, &ws->dispersed);
    benchmark::DoNotOptimize(status);
  }
  state.counters["points"] = ws->dispersed.point_count;
}
BENCHMARK(BM_MonteCarloSampleFlight)->Unit(benchmark::kMicrosecond);

}  // namespace
