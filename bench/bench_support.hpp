// The set-up shared by the benches that measure an analysis about the bundled example's optimum
// (dispersion_bench, impact_bench, monte_carlo_bench, range_safety_bench): the deck loaded and
// optimized once, outside the timed loops. A set-up that fails stops the program: it would
// measure nothing.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

#include "support/repository_paths.hpp"
#include "tolip_ground/card_deck.hpp"
#include "tolip_ground/optimization_run.hpp"

namespace tolip::bench {

// Prints `message` and stops the bench program.
[[noreturn]] inline void stop_setup(const std::string& message) {
  std::fprintf(stderr, "%s\n", message.c_str());
  std::exit(1);
}

// The bundled example deck (examples/scout/mission.toml) and its first case optimized as
// `tolip optimize` does; a bench's own prepared inputs derive from it.
struct OptimizedExample {
  ground::Deck deck;
  ground::OptimizationRun run;

  const ground::DeckCase& example() const { return deck.cases.front(); }
};

// Loads the deck into `made` and optimizes its first case.
inline void load_and_optimize_example(OptimizedExample* made) {
  ground::DeckError error;
  if (!ground::load_deck(std::string(tolip::repository_paths::examples_dir()) + "/scout/mission.toml",
                         &made->deck, &error)) {
    stop_setup(error.to_string());
  }
  ground::run_optimization(*made->example().mission, nullptr, &made->run);
}

}  // namespace tolip::bench
