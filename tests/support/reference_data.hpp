// Access to the independent reference data in tests/reference (PROVENANCE.md there: where it came
// from; this project reads it and never writes it).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace tolip::test {

// scout_reference.json and oracle_test_vectors.json, parsed once per process.
const nlohmann::json& scout_reference();
const nlohmann::json& oracle_test_vectors();

// Path of a file under examples/.
std::string example_path(const std::string& relative);

}  // namespace tolip::test
