// Inputs the deck readers accept that this version does not act on (the rule of the core: an
// input acts, is rejected, or warns by name; never dropped). Each is a warning naming its data
// block and word, printed on stderr by the commands that fly a case (simulate, optimize, export);
// `convert` carries them over unchanged. docs/deck-format.md "Inputs read but not acted on".
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "tolip/mission/mission.hpp"
#include "tolip_ground/card_deck.hpp"
#include "tolip_ground/deck_extras.hpp"

namespace tolip::ground {

struct InputWarning {
  int data_block = 0;
  std::string word;     // the manual's name of the word: "IP(21)", "DA2(8)", "DA6D(12-15)"
  std::string field;    // the TOML key path
  std::string message;  // what it asks for and why it has no effect
};

// The warnings of one case, in data block order; empty when every input given acts.
std::vector<InputWarning> unused_inputs(const Mission& mission, const DeckExtras& extras);

// "tolip: warning: DECK[: case N]: data block B, WORD (FIELD): MESSAGE", one line each.
void print_input_warnings(std::ostream& err, const std::string& deck_path, int case_number, int case_count,
                          const std::vector<InputWarning>& warnings);

// The warnings of every case of a loaded deck, in case order.
void print_deck_input_warnings(std::ostream& err, const std::string& deck_path, const Deck& deck);

}  // namespace tolip::ground
