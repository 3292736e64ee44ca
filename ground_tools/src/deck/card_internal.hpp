// Private interfaces between the card-deck files (card_reader.cpp, card_toml.cpp, card_writer.cpp,
// card_deck.cpp) and the IP(17) echo.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "card_model.hpp"

namespace tolip::ground::card_detail {

// Reads every case of a card deck (throws CardFailure).
std::vector<CardCase> read_card_cases(const std::string& text, const std::string& path);

// A word of the card deck behind a TOML value: data block, stage code, word, and where it was
// punched (origin) or at least the header card of its block.
struct WordRef {
  int block = 0;
  int stage = 0;
  int word = 0;
  Origin origin;
  Origin header;
};

// A card case as a TOML deck. `lines[i]` is the word behind line i + 1 of `text`; `paths` maps the
// key paths the TOML reader names in its messages (every key written, and the keys a word would
// have given when it was not punched) to their words.
struct TomlDeck {
  std::string text;
  std::vector<WordRef> lines;
  std::map<std::string, WordRef> paths;
};

// Turns a card case into a TOML deck (docs/deck-format.md), throwing CardFailure for what only
// the card form can get wrong (unused words, counts, table terminators). `located` writes one
// value per line (for messages); otherwise the TOML is laid out for people (tolip convert).
TomlDeck card_case_to_toml(const CardCase& card_case, const std::string& path, bool located);

// The words of a (checked) TOML deck. Throws CardFailure when a value has no card form.
CardCase card_case_from_toml(const toml::table& root);

// Writes cases as card images: the first case complete, later cases as the changes of the
// optimization data (and their optional groups complete), each ended by a blank card, then 999.
// `rounded` counts the numbers that do not fit exactly in their 12 columns. Throws CardFailure
// when a value cannot be punched (an integer too wide, a table longer than its block).
std::string write_card_images(const std::vector<CardCase>& cases, int* rounded);

}  // namespace tolip::ground::card_detail
