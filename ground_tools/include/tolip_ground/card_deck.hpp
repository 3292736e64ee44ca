// The heritage card deck (manual Sec. 22) and decks of either format.
//
// A card deck is a file of 80-column card images: header cards (4I3: data block, first word, last
// word, stage code) each followed by its data cards, a blank card ending each case, the optional
// groups (dispersion, hardover, impact, radar) that the case's options select, each ended by a
// blank card, and a card with 999 in columns 1-3. Successive cases give only the words of data
// blocks 1-40 that change. docs/deck-format.md ("The card deck") describes every block.
//
// A card case is turned into the TOML deck it stands for and read by the TOML reader, so both
// formats share every check, every unit conversion and validate_mission(). Errors name the file,
// the card, the columns, the case, the data block, the stage code and the word. Nothing throws
// out of these functions, whatever the input.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "tolip_ground/deck.hpp"
#include "tolip_ground/deck_extras.hpp"

namespace tolip::ground {

namespace card_detail {
struct CardCase;
}

enum class DeckFormat { kToml, kCards };

// Recognises a deck by its content: a card deck when the first non-blank line starts with a header
// card (columns 1-12 blank or digits and signs, a digit in columns 1-3, e.g. "  1  1 12") or the
// 999 card; a TOML deck otherwise.
DeckFormat detect_deck_format(std::string_view text);
const char* deck_format_name(DeckFormat format);  // "TOML deck", "card deck"

// One case of a deck.
struct DeckCase {
  int number = 1;                    // 1-based
  int first_card = 0;                // card decks: the case's first card (0 for TOML decks)
  std::unique_ptr<Mission> mission;  // validated (validate_mission)
  DeckExtras extras;
  // The case word by word as data blocks (card decks: as punched, with card and columns; TOML
  // decks: as the TOML gives them). For the IP(17) echo and conversions; null when unavailable.
  std::shared_ptr<const card_detail::CardCase> words;
};

struct Deck {
  std::string path;
  DeckFormat format = DeckFormat::kToml;
  std::vector<DeckCase> cases;  // at least one when loading succeeded
};

// Card decks only.
bool parse_card_deck(const std::string& text, const std::string& path, Deck* deck, DeckError* error);
bool load_card_deck(const std::string& path, Deck* deck, DeckError* error);

// Either format, recognised by content (a TOML deck is one case).
bool parse_deck(const std::string& text, const std::string& path, Deck* deck, DeckError* error);
bool load_deck(const std::string& path, Deck* deck, DeckError* error);

// For commands that take one case: loads either format; a card deck with several cases is an error.
bool load_single_case_deck(const std::string& path, Mission* mission, DeckExtras* extras, DeckError* error);

// Conversions (tolip convert). `case_number` picks the case of a card deck for TOML, which holds
// one case (0: the deck must have exactly one). The card form writes every case (later cases as the
// changes of their optimization data); *rounded counts the numbers that do not fit their 12
// columns exactly (TOML values with more digits than a card field holds). Each result is read back
// before it is returned.
bool deck_to_toml(const Deck& deck, int case_number, std::string* toml, DeckError* error);
bool deck_to_cards(const Deck& deck, std::string* cards, int* rounded, DeckError* error);

}  // namespace tolip::ground
