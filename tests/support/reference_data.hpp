// Access to the independent reference data in tests/reference (PROVENANCE.md there: where it came
// from; this project reads it and never writes it).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "tolip/core/state.hpp"

namespace tolip::test {

// scout_reference.json and oracle_test_vectors.json, parsed once per process.
const nlohmann::json& scout_reference();
const nlohmann::json& oracle_test_vectors();

// Path of a file under examples/.
std::string example_path(const std::string& relative);

// The bundled Scout case decks (examples/scout/): any file, the crude-program mission and the
// reference optimum.
inline std::string scout_example(const std::string& name) { return example_path("scout/" + name); }
inline std::string mission_deck() { return scout_example("mission.toml"); }
inline std::string reference_deck() { return scout_example("reference_optimum.toml"); }

// A state vector X = [V, gamma, r, psi, lambda, tau] from a JSON array of six numbers.
inline StateVector state_from_json(const nlohmann::json& j) {
  StateVector x;
  for (int i = 0; i < 6; ++i) x(i) = j.at(static_cast<std::size_t>(i)).get<double>();
  return x;
}

}  // namespace tolip::test
