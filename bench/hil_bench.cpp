// Speed of the hardware-in-the-loop bench (docs/hil.md, issue 13: a full ascent at 50 Hz at least
// 200 times faster than real time): the reference deck's exported table flown by the flight
// application against the hal_sim plant, lift-off to the final burnout, in process. The counter
// "realtime_factor" is the simulated flight time over the wall time of one run.
// Run: build/bench/hil_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "tolip/table/table_image.hpp"
#include "tolip_ground/card_deck.hpp"
#include "tolip_ground/guidance_table.hpp"
#include "tolip_ground/hardover_run.hpp"
#include "tolip_ground/optimization_run.hpp"
#include "tolip_hal_sim/bench.hpp"

namespace {

struct Prepared {
  tolip::ground::Deck deck;
  tolip::ground::OptimizationRun run;
  std::unique_ptr<tolip::HardoverData> hardover;
  std::uint8_t image[tolip::kTableImageSize] = {};
};

// The reference deck's optimization job and the table export builds of it.
const Prepared& prepared() {
  static Prepared* p = [] {
    auto* made = new Prepared;
    tolip::ground::DeckError error;
    const std::string deck = std::string(TOLIP_EXAMPLES_DIR) + "/scout/reference_optimum.toml";
    if (!tolip::ground::load_deck(deck, &made->deck, &error)) {
      std::fprintf(stderr, "%s\n", error.to_string().c_str());
      std::exit(1);
    }
    const tolip::ground::DeckCase& c = made->deck.cases.front();
    std::ostringstream err;
    if (!tolip::ground::prepare_hardover_data(deck, "", c, &made->hardover, err)) {
      std::fprintf(stderr, "%s", err.str().c_str());
      std::exit(1);
    }
    tolip::ground::run_optimization(*c.mission, nullptr, &made->run);
    tolip::GuidanceTable table;
    std::string build_error;
    if (!tolip::ground::build_guidance_table(
            made->run.linearization.workspace->mission, c.extras, made->run.linearization.workspace->prepared,
            &made->run.linearization.result->program, {}, &table, &build_error) ||
        !tolip::ok(tolip::encode_table_image(table, made->image, sizeof made->image))) {
      std::fprintf(stderr, "no table: %s\n", build_error.c_str());
      std::exit(1);
    }
    return made;
  }();
  return *p;
}

void BM_HilNominalAscent50Hz(benchmark::State& state) {
  const Prepared& p = prepared();
  tolip::sim::BenchInputs inputs;
  inputs.mission = &p.run.linearization.workspace->mission;
  inputs.prepared = &p.run.linearization.workspace->prepared;
  inputs.hardover = p.hardover.get();
  inputs.table = p.image;
  inputs.table_size = sizeof p.image;
  tolip::sim::BenchConfig config;
  auto result = std::make_unique<tolip::sim::BenchResult>();
  double flown_s = 0.0;
  for (auto _ : state) {
    const tolip::Status status = tolip::sim::run_bench(inputs, config, result.get());
    if (!tolip::ok(status) || !result->completed) {
      state.SkipWithError("the bench run did not complete");
      return;
    }
    flown_s = result->end_time_s;
    benchmark::DoNotOptimize(result->burnout_state);
  }
  state.counters["flight_s"] = flown_s;
  state.counters["cycles"] = static_cast<double>(result->flight.cycles);
  state.counters["realtime_factor"] =
      benchmark::Counter(flown_s * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_HilNominalAscent50Hz)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
