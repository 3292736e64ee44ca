// libFuzzer target: the heritage card-deck reader (ground_tools/src/deck/card_deck.cpp) on
// arbitrary text, through parse_card_deck as `tolip` reads a deck recognised as cards.
// Verifies: REQ-DCK-005
// Property: never a crash, an escaping exception or a leak; a rejection names what is wrong (a
// non-empty message); an accepted deck holds at least one case, each with a validated mission.
// docs/verification/fuzzing.md.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "tolip/mission/mission.hpp"
#include "tolip_ground/card_deck.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  tolip::ground::Deck deck;
  tolip::ground::DeckError error;
  if (tolip::ground::parse_card_deck(text, "fuzz.dat", &deck, &error)) {
    if (deck.cases.empty()) std::abort();
    for (const tolip::ground::DeckCase& c : deck.cases) {
      tolip::MissionFault fault;
      if (!c.mission || tolip::validate_mission(*c.mission, &fault) != tolip::Status::kOk) std::abort();
    }
  } else if (error.message.empty()) {
    std::abort();
  }
  return 0;
}
