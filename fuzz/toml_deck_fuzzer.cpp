// libFuzzer target: the TOML deck reader (ground_tools/src/deck/toml_deck.cpp) on arbitrary text.
// Verifies: REQ-DCK-005
// Property: parse_toml_deck never crashes, never throws and never leaks; on failure it names what
// is wrong (a non-empty message); on success the mission it returns validates. docs/verification/fuzzing.md.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>

#include "tolip/mission/mission.hpp"
#include "tolip_ground/deck.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  auto mission = std::make_unique<tolip::Mission>();
  tolip::ground::DeckError error;
  if (tolip::ground::parse_toml_deck(text, "fuzz.toml", mission.get(), &error)) {
    tolip::MissionFault fault;
    if (tolip::validate_mission(*mission, &fault) != tolip::Status::kOk) std::abort();
  } else if (error.message.empty()) {
    std::abort();
  }
  return 0;
}
