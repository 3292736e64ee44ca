// tolip_embed_mission DECK OUT.cpp [FUNCTION]: writes C++ source that rebuilds the deck's Mission
// without files (tolip_ground/mission_source.hpp), atomically. Used by the flight image build
// (flight_image/CMakeLists.txt). Exit codes as `tolip`: 0 success, 1 write failure, 2 bad input.
#include <iostream>
#include <memory>
#include <string>

#include "tolip_ground/atomic_file.hpp"
#include "tolip_ground/commands.hpp"
#include "tolip_ground/deck.hpp"
#include "tolip_ground/deck_extras.hpp"
#include "tolip_ground/mission_source.hpp"

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::cerr << "usage: tolip_embed_mission DECK OUT.cpp [FUNCTION]\n";
    return tolip::ground::kExitBadInput;
  }
  const std::string deck = argv[1];
  const std::string out = argv[2];
  const std::string function = argc == 4 ? argv[3] : "build_embedded_mission";
  auto mission = tolip::ground::make_mission();
  tolip::ground::DeckExtras extras;
  tolip::ground::DeckError error;
  if (!tolip::ground::load_toml_deck(deck, mission.get(), &extras, &error)) {
    std::cerr << "tolip_embed_mission: " << error.to_string() << '\n';
    return tolip::ground::kExitBadInput;
  }
  std::string write_error;
  if (!tolip::ground::write_file_atomically(
          out, tolip::ground::mission_cpp_source(*mission, extras.listing, function, deck), &write_error)) {
    std::cerr << "tolip_embed_mission: " << write_error << '\n';
    return tolip::ground::kExitFailure;
  }
  return tolip::ground::kExitOk;
}
