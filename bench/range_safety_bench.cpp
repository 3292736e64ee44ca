// Speed of the range-safety analyses of issue 12 (each under 5 ms on this machine): the radar
// tracking of every station of the bundled example (manual Sec. 18: six stations of data block
// 41 at every point of the final nominal, launch through stage-4 burnout) and every hardover turn
// the data blocks name (Sec. 16: blocks 44-45 of the example, from the final nominal).
// Run: build/bench/range_safety_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <memory>

#include "bench_support.hpp"
#include "tolip/hardover/hardover.hpp"
#include "tolip/radar/radar.hpp"
#include "tolip_ground/hardover_run.hpp"
#include "tolip_ground/optimization_run.hpp"
#include "tolip_ground/radar_run.hpp"

namespace {

struct Prepared : tolip::bench::OptimizedExample {
  const tolip::Trajectory* nominal = nullptr;
  std::unique_ptr<tolip::RadarStations> stations = std::make_unique<tolip::RadarStations>();
  tolip::ground::FinalNominal flight;
  std::unique_ptr<tolip::HardoverData> hardover = std::make_unique<tolip::HardoverData>();
};

// The bundled example optimized once (its final nominal: the linearized 6D program).
const Prepared& prepared() {
  static Prepared* p = [] {
    auto* made = new Prepared;
    tolip::bench::load_and_optimize_example(made);
    const tolip::ground::DeckCase& c = made->example();
    std::string kind;
    tolip::Status why = tolip::Status::kOk;
    made->nominal = tolip::ground::final_nominal_trajectory(*c.mission, made->run, &kind, &why);
    if (made->nominal == nullptr) {
      tolip::bench::stop_setup(std::string("the example did not converge: ") + tolip::status_name(why));
    }
    tolip::ground::fill_radar_stations(c.extras.radar_stations, made->stations.get());
    tolip::ground::HardoverMappingFault fault;
    if (!tolip::ground::final_nominal_flight(*c.mission, made->run, &made->flight, &kind, &why) ||
        !tolip::ground::fill_hardover_data(c.extras.hardover, made->hardover.get(), &fault)) {
      tolip::bench::stop_setup("the example's hardover data did not prepare");
    }
    return made;
  }();
  return *p;
}

void BM_RadarAllStationsOfTheReferenceMission(benchmark::State& state) {
  const Prepared& p = prepared();
  const tolip::Mission& mission = *p.deck.cases.front().mission;
  auto result = std::make_unique<tolip::RadarResult>();
  for (auto _ : state) {
    const tolip::Status status =
        tolip::compute_radar_tracking(mission.constants, *p.stations, *p.nominal, result.get());
    benchmark::DoNotOptimize(status);
  }
  state.counters["stations"] = result->station_count;
  state.counters["points"] = result->point_count;
}
BENCHMARK(BM_RadarAllStationsOfTheReferenceMission)->Unit(benchmark::kMillisecond);

void BM_HardoverAllTurnsOfTheReferenceMission(benchmark::State& state) {
  const Prepared& p = prepared();
  auto result = std::make_unique<tolip::HardoverResult>();
  tolip::HardoverFault fault;
  for (auto _ : state) {
    const tolip::Status status = tolip::compute_hardover_turns(
        *p.flight.mission, *p.flight.prepared, *p.flight.trajectory, *p.hardover, result.get(), &fault);
    benchmark::DoNotOptimize(status);
  }
  state.counters["turns"] = result->turn_count;
}
BENCHMARK(BM_HardoverAllTurnsOfTheReferenceMission)->Unit(benchmark::kMillisecond);

}  // namespace
