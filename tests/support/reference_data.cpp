#include "support/reference_data.hpp"
#include "support/repository_paths.hpp"

#include <fstream>
#include <stdexcept>

namespace tolip::test {
namespace {
nlohmann::json load(const std::string& name) {
  const std::string path = std::string(tolip::repository_paths::reference_dir()) + "/" + name;
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open reference file " + path);
  return nlohmann::json::parse(in);
}
}  // namespace

const nlohmann::json& scout_reference() {
  static const nlohmann::json data = load("scout_reference.json");
  return data;
}

const nlohmann::json& oracle_test_vectors() {
  static const nlohmann::json data = load("oracle_test_vectors.json");
  return data;
}

std::string example_path(const std::string& relative) {
  return std::string(tolip::repository_paths::examples_dir()) + "/" + relative;
}

}  // namespace tolip::test
