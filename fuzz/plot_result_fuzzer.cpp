// libFuzzer target: the result reader of `tolip plot` (ground_tools/src/commands/plot_command.cpp
// and src/plot/): a simulate/optimize JSON result, read as the command reads it.
// Verifies: REQ-GND-002, REQ-DCK-005
// Property: the only ways out are the command's own: a JSON parse error or a PlotDataError naming
// the field (exit 2), or figures. Any other exception (a JSON type error, an out-of-range access)
// escapes, and libFuzzer reports it as a crash, as `tolip plot` would have ended with one.
// docs/verification/fuzzing.md.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tolip_ground/plot.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  nlohmann::json result;
  try {
    result = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception&) {  // as the command: parse_error, out_of_range
    return 0;
  }
  std::vector<const nlohmann::json*> documents;
  if (result.is_array()) {
    for (const nlohmann::json& document : result) documents.push_back(&document);
    if (documents.empty()) return 0;
  } else {
    documents.push_back(&result);
  }
  try {
    const tolip::ground::DocumentFigures figures = tolip::ground::figures_for_cases(documents);
    (void)figures;
  } catch (const tolip::ground::PlotDataError&) {
    return 0;
  }
  return 0;
}
