// Access to the independent reference data in ../shared/reference (never written by this project).
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
