// Option IP(17): the output of all the input data of a case, identified by data block number and a
// few descriptive words per word (manual Sec. 22, "Output of Input Data").
#pragma once

#include <ostream>
#include <string>

#include "tolip_ground/card_deck.hpp"

namespace tolip::ground {

// Writes the input data of one case as listing pages (titles from data blocks 1-3, CT1(8) lines per
// page, section "INPUT DATA"): every data block the case gives, word by word with its meaning and
// value (blocks 10-14 complete, nominal values marked), tables as points, then the optional groups
// read for the case. `deck` names the deck and its format. A case without words (not available)
// gets one line saying so.
void write_input_echo(std::ostream& out, const Deck& deck, const DeckCase& deck_case);

// The same for case `case_number` (1-based) of the deck at `path` (either format), for commands
// that loaded the case by other means. Writes nothing when the deck does not load.
void write_input_echo(std::ostream& out, const std::string& path, int case_number = 1);

}  // namespace tolip::ground
