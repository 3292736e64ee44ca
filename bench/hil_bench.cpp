// Speed of the hardware-in-the-loop bench (docs/hil.md, issue 13: a full ascent at 50 Hz at least
// 200 times faster than real time): the reference deck's exported table flown by the flight
// application against the hal_sim plant, lift-off to the final burnout, in process. The counter
// "realtime_factor" is the simulated flight time over the wall time of one run.
//
// BM_HilQemuLockStep50Hz: the same flight with the flight application as the Cortex-M7 image under
// QEMU (processor in the loop, docs/hil.md), in lock-step over its UART0 with the plant here: the
// first 60 s of the nominal ascent (3,000 cycles). The emulator's start and exit are outside the
// timed part (manual time: the flight alone); "cycles_per_s" and "realtime_factor" are of the
// flight. The image is $TOLIP_PIL_IMAGE, else build-cortex-m7/flight_image/tolip_flight_pil.elf of
// this source tree (the cortex-m7 preset's build); without it or without qemu-system-arm on the
// PATH the benchmark is skipped with a message.
// Run: build/bench/hil_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "support/repository_paths.hpp"
#include "tolip/table/table_image.hpp"
#include "tolip_ground/card_deck.hpp"
#include "tolip_ground/guidance_table.hpp"
#include "tolip_ground/hardover_run.hpp"
#include "tolip_ground/optimization_run.hpp"
#include "tolip_hal_sim/bench.hpp"
#include "tolip_hal_sim/qemu_target.hpp"

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
    const std::string deck =
        std::string(tolip::repository_paths::examples_dir()) + "/scout/reference_optimum.toml";
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

// The bench's inputs for the prepared job: its linearized mission, the hardover data and the
// exported table image (the in-process flight computer unless the caller sets another).
tolip::sim::BenchInputs bench_inputs(const Prepared& p) {
  tolip::sim::BenchInputs inputs;
  inputs.mission = &p.run.linearization.workspace->mission;
  inputs.prepared = &p.run.linearization.workspace->prepared;
  inputs.hardover = p.hardover.get();
  inputs.table = p.image;
  inputs.table_size = sizeof p.image;
  return inputs;
}

void BM_HilNominalAscent50Hz(benchmark::State& state) {
  const Prepared& p = prepared();
  const tolip::sim::BenchInputs inputs = bench_inputs(p);
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

// The processor-in-the-loop image, or "" when it is not built.
std::string pil_image() {
  const char* named = std::getenv("TOLIP_PIL_IMAGE");
  const std::string image = named != nullptr && *named != '\0'
                                ? std::string(named)
                                : std::string(tolip::repository_paths::pil_image());
  return ::access(image.c_str(), R_OK) == 0 ? image : std::string();
}

bool qemu_on_path() {
  const char* path = std::getenv("PATH");
  std::string dirs = path != nullptr ? path : "";
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = dirs.find(':', start) == std::string::npos ? dirs.size() : dirs.find(':', start);
    const std::string candidate = dirs.substr(start, end - start) + "/qemu-system-arm";
    if (end > start && ::access(candidate.c_str(), X_OK) == 0) return true;
    start = end + 1;
  }
  return false;
}

void BM_HilQemuLockStep50Hz(benchmark::State& state) {
  const std::string image = pil_image();
  if (image.empty()) {
    state.SkipWithError(("skipped: no PIL image (" + std::string(tolip::repository_paths::pil_image()) +
                         "; build the cortex-m7 preset or set TOLIP_PIL_IMAGE)")
                            .c_str());
    return;
  }
  if (!qemu_on_path()) {
    state.SkipWithError("skipped: qemu-system-arm is not on the PATH");
    return;
  }
  const Prepared& p = prepared();
  tolip::sim::BenchConfig config;
  config.duration_s = static_cast<double>(state.range(0));
  auto result = std::make_unique<tolip::sim::BenchResult>();
  double wall_s = 0.0;
  double flown_s = 0.0;
  double cycles = 0.0;
  for (auto _ : state) {
    tolip::sim::QemuTarget qemu;
    tolip::sim::QemuOptions options;
    options.image = image;
    std::string error;
    if (!qemu.start(options, &error)) {
      state.SkipWithError(("QEMU did not start: " + error).c_str());
      break;
    }
    tolip::sim::BenchInputs inputs = bench_inputs(p);
    inputs.flight = &qemu;
    const auto start = std::chrono::steady_clock::now();
    const tolip::Status status = tolip::sim::run_bench(inputs, config, result.get());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.SetIterationTime(seconds);
    if (!tolip::ok(status) || !qemu.stop(&error)) {
      state.SkipWithError(("the lock-step flight failed: " + qemu.error() + error).c_str());
      break;
    }
    wall_s += seconds;
    flown_s += static_cast<double>(result->telemetry.size()) / config.cycle_hz;
    cycles += static_cast<double>(result->telemetry.size());
  }
  if (state.error_occurred() || wall_s <= 0.0) return;
  state.counters["flight_s"] = flown_s / static_cast<double>(state.iterations());
  state.counters["cycles"] = cycles / static_cast<double>(state.iterations());
  state.counters["cycles_per_s"] = cycles / wall_s;
  state.counters["realtime_factor"] = flown_s / wall_s;
}
BENCHMARK(BM_HilQemuLockStep50Hz)->Arg(60)->Iterations(1)->Unit(benchmark::kSecond)->UseManualTime();

}  // namespace
