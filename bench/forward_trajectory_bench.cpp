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

}  // namespace
