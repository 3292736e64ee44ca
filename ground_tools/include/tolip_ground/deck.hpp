// Reading a case deck into a core Mission.
//
// The modern deck is TOML (docs/deck-format.md): one table per data block, named fields with the
// unit in the name, degrees and nautical miles at this edge converted to the core's radians and
// feet. Every error names the file, the line (when the TOML parser knows it), the data block and
// the field, and says what was expected. A failed load leaves *mission untouched.
#pragma once

#include <memory>
#include <string>

#include "tolip/mission/mission.hpp"

namespace tolip::ground {

struct DeckError {
  std::string file;
  int line = 0;         // 0 when unknown; for a card deck the card number (1-based line)
  int data_block = 0;   // manual data block number, 0 when not tied to one
  std::string field;    // TOML key path, e.g. "stage.2.thrust.time_s[5]"
  std::string message;  // what is wrong and what was expected
  // Card decks (card_deck.hpp) only: where on the card and in the data block.
  bool card_deck = false;  // true: to_string() uses the card form below
  int first_column = 0;    // columns of the field on card `line` (0 when not tied to a field)
  int last_column = 0;
  int case_number = 0;  // 1-based case of the deck (0 when not tied to a case)
  int stage_code = 0;   // header field 4 (stage code; dispersion code for block 46)
  int word = 0;         // word of the data block (1-based), 0 when not tied to one
  // TOML: "file:line: data block N, field F: message"
  // cards: "file: card L, columns A-B: case C, data block N, stage code S, word W: message"
  std::string to_string() const;
};

// Loads and validates (validate_mission) a TOML deck. Returns false and fills *error on any fault.
bool load_toml_deck(const std::string& path, Mission* mission, DeckError* error);

// The same from text already in memory (path is used in messages only).
bool parse_toml_deck(const std::string& text, const std::string& path, Mission* mission, DeckError* error);

// Mission is large (fixed-capacity tables); ground tools keep it on the heap.
inline std::unique_ptr<Mission> make_mission() { return std::make_unique<Mission>(); }

}  // namespace tolip::ground
