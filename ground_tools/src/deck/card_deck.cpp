// Card decks and decks of either format (card_deck.hpp): reading, recognising, converting.
//
// A card case is read into words (card_reader.cpp), turned into the TOML deck it stands for with
// one value per line (card_toml.cpp) and read by the TOML reader (parse_toml_deck), which applies
// every check, the unit conversions and validate_mission(). A fault the TOML reader finds is put
// back on the card: the line of the TOML value, or the key path it names, leads to the word.
#include "tolip_ground/card_deck.hpp"

#include <exception>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "card_internal.hpp"
#include "deck_common.hpp"

namespace tolip::ground {
namespace {

using card_detail::CardCase;
using card_detail::CardFailure;
using card_detail::TomlDeck;
using card_detail::WordRef;

DeckError internal_error(const std::string& path, const std::string& what) {
  DeckError error;
  error.file = path;
  error.message = what;
  return error;
}

// The word behind a TOML reader message about a located card TOML deck.
DeckError on_the_card(const DeckError& toml_error, const TomlDeck& deck, const CardCase& card_case,
                      const std::string& path) {
  DeckError error;
  error.file = path;
  error.card_deck = true;
  error.case_number = card_case.number;
  error.data_block = toml_error.data_block;
  error.field = toml_error.field;
  error.message = toml_error.message;
  const WordRef* ref = nullptr;
  if (const auto it = deck.paths.find(toml_error.field); it != deck.paths.end()) ref = &it->second;
  const bool line_known = toml_error.line >= 1 && toml_error.line <= static_cast<int>(deck.lines.size());
  if ((ref == nullptr || (!ref->origin.known() && ref->block == 0)) && line_known) {
    const WordRef& by_line = deck.lines[static_cast<std::size_t>(toml_error.line - 1)];
    if (by_line.block != 0 || by_line.origin.known()) ref = &by_line;
  }
  if (ref == nullptr) {
    std::string probe = toml_error.field;
    while (ref == nullptr && !probe.empty()) {
      const std::size_t cut = probe.find_last_of(".[");
      if (cut == std::string::npos) break;
      probe.resize(cut);
      if (const auto it = deck.paths.find(probe); it != deck.paths.end()) ref = &it->second;
    }
  }
  if (ref == nullptr) return error;
  if (ref->block > 0) {
    error.data_block = ref->block;
    error.stage_code = ref->stage;
    error.word = ref->word;
  }
  if (ref->origin.known()) {
    error.line = ref->origin.card;
    error.first_column = ref->origin.first_column;
    error.last_column = ref->origin.last_column;
  } else if (ref->header.known()) {
    error.line = ref->header.card;
    if (ref->word > 0) error.message = "word " + std::to_string(ref->word) + " not punched: " + error.message;
  } else if (ref->word > 0) {
    error.message = "not punched: " + error.message;
  }
  return error;
}

bool fill_case(const CardCase& card_case, const std::string& path, DeckCase* out, DeckError* error) {
  const TomlDeck located = card_detail::card_case_to_toml(card_case, path, true);
  out->number = card_case.number;
  out->first_card = card_case.first_card;
  out->mission = make_mission();
  DeckError toml_error;
  if (!parse_toml_deck(located.text, path, out->mission.get(), &out->extras, &toml_error)) {
    if (error != nullptr) *error = on_the_card(toml_error, located, card_case, path);
    return false;
  }
  out->words = std::make_shared<const CardCase>(card_case);
  return true;
}

template <typename Body>
bool guarded(const std::string& path, DeckError* error, Body body) {
  try {
    return body();
  } catch (const CardFailure& failure) {
    if (error != nullptr) {
      *error = failure.error;
      if (error->file.empty()) error->file = path;
    }
  } catch (const std::bad_alloc&) {
    if (error != nullptr) *error = internal_error(path, "out of memory while reading the deck");
  } catch (const std::exception& exception) {
    if (error != nullptr)
      *error =
          internal_error(path, std::string("internal error while reading the deck: ") + exception.what());
  } catch (...) {
    if (error != nullptr) *error = internal_error(path, "internal error while reading the deck");
  }
  return false;
}

bool parse_toml_case(const std::string& text, const std::string& path, Deck* deck, DeckError* error) {
  DeckCase single;
  single.mission = make_mission();
  if (!parse_toml_deck(text, path, single.mission.get(), &single.extras, error)) return false;
  try {
    const toml::table root = toml::parse(text, path);
    single.words = std::make_shared<const CardCase>(card_detail::card_case_from_toml(root));
  } catch (...) {
    single.words.reset();  // the echo and the conversions then say they cannot
  }
  deck->cases.clear();
  deck->cases.push_back(std::move(single));
  return true;
}

bool is_card_header_line(std::string_view line) {
  if (line.size() >= 3 && line.substr(0, 3) == "999") return true;
  const std::size_t width = line.size() < 12 ? line.size() : 12;
  bool digit_in_block = false;
  for (std::size_t i = 0; i < width; ++i) {
    const char c = line[i];
    const bool digit = c >= '0' && c <= '9';
    if (!digit && c != ' ' && c != '-' && c != '+') return false;
    if (digit && i < 3) digit_in_block = true;
  }
  return digit_in_block;
}

}  // namespace

DeckFormat detect_deck_format(std::string_view text) {
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.find_first_not_of(" \t") != std::string_view::npos) {
      return is_card_header_line(line) ? DeckFormat::kCards : DeckFormat::kToml;
    }
    start = end + 1;
  }
  return DeckFormat::kToml;
}

const char* deck_format_name(DeckFormat format) {
  return format == DeckFormat::kCards ? "card deck" : "TOML deck";
}

bool parse_card_deck(const std::string& text, const std::string& path, Deck* deck, DeckError* error) {
  return guarded(path, error, [&]() {
    const std::vector<CardCase> cases = card_detail::read_card_cases(text, path);
    std::vector<DeckCase> loaded;
    loaded.reserve(cases.size());
    for (const CardCase& card_case : cases) {
      DeckCase one;
      if (!fill_case(card_case, path, &one, error)) return false;
      loaded.push_back(std::move(one));
    }
    if (deck != nullptr) {
      deck->path = path;
      deck->format = DeckFormat::kCards;
      deck->cases = std::move(loaded);
    }
    return true;
  });
}

bool load_card_deck(const std::string& path, Deck* deck, DeckError* error) {
  return guarded(path, error, [&]() {
    std::string text;
    if (!deck_detail::read_deck_file(path, &text, error)) return false;
    return parse_card_deck(text, path, deck, error);
  });
}

bool parse_deck(const std::string& text, const std::string& path, Deck* deck, DeckError* error) {
  return guarded(path, error, [&]() {
    if (detect_deck_format(text) == DeckFormat::kCards) return parse_card_deck(text, path, deck, error);
    Deck parsed;
    if (!parse_toml_case(text, path, &parsed, error)) return false;
    parsed.path = path;
    parsed.format = DeckFormat::kToml;
    if (deck != nullptr) *deck = std::move(parsed);
    return true;
  });
}

bool load_deck(const std::string& path, Deck* deck, DeckError* error) {
  return guarded(path, error, [&]() {
    std::string text;
    if (!deck_detail::read_deck_file(path, &text, error)) return false;
    return parse_deck(text, path, deck, error);
  });
}

bool load_single_case_deck(const std::string& path, Mission* mission, DeckExtras* extras, DeckError* error) {
  return guarded(path, error, [&]() {
    Deck deck;
    if (!load_deck(path, &deck, error)) return false;
    if (deck.cases.size() != 1) {
      if (error != nullptr) {
        *error = internal_error(path, "the card deck has " + std::to_string(deck.cases.size()) +
                                          " cases; this command takes a deck of one case");
        error->card_deck = true;
      }
      return false;
    }
    if (mission != nullptr) *mission = *deck.cases[0].mission;
    if (extras != nullptr) *extras = std::move(deck.cases[0].extras);
    return true;
  });
}

bool deck_to_toml(const Deck& deck, int case_number, std::string* toml, DeckError* error) {
  return guarded(deck.path, error, [&]() {
    if (deck.cases.empty()) {
      if (error != nullptr) *error = internal_error(deck.path, "the deck has no case");
      return false;
    }
    if (case_number == 0 && deck.cases.size() > 1) {
      if (error != nullptr) {
        *error = internal_error(deck.path, "the card deck has " + std::to_string(deck.cases.size()) +
                                               " cases and a TOML deck holds one: choose one with --case N");
      }
      return false;
    }
    const int index = case_number == 0 ? 1 : case_number;
    if (index < 1 || index > static_cast<int>(deck.cases.size())) {
      if (error != nullptr) {
        *error = internal_error(deck.path, "no case " + std::to_string(index) + ": the deck has " +
                                               std::to_string(deck.cases.size()));
      }
      return false;
    }
    const DeckCase& chosen = deck.cases[static_cast<std::size_t>(index - 1)];
    if (!chosen.words) {
      if (error != nullptr)
        *error = internal_error(deck.path, "the deck's words are not available for conversion");
      return false;
    }
    const TomlDeck pretty = card_detail::card_case_to_toml(*chosen.words, deck.path, false);
    auto check = make_mission();
    DeckError check_error;
    if (!parse_toml_deck(pretty.text, deck.path + " (converted to TOML)", check.get(), nullptr,
                         &check_error)) {
      if (error != nullptr) {
        *error = internal_error(deck.path, "internal error: the converted TOML deck does not read back: " +
                                               check_error.to_string());
      }
      return false;
    }
    *toml = pretty.text;
    return true;
  });
}

bool deck_to_cards(const Deck& deck, std::string* cards, int* rounded, DeckError* error) {
  return guarded(deck.path, error, [&]() {
    std::vector<CardCase> cases;
    for (const DeckCase& one : deck.cases) {
      if (!one.words) {
        if (error != nullptr)
          *error = internal_error(deck.path, "the deck's words are not available for conversion");
        return false;
      }
      cases.push_back(*one.words);
    }
    int count = 0;
    std::string text;
    try {
      text = card_detail::write_card_images(cases, &count);
    } catch (const CardFailure& failure) {
      if (error != nullptr) {
        *error = failure.error;
        error->file = deck.path;
        error->message = "cannot punch the deck as cards: " + error->message;
      }
      return false;
    }
    Deck check;
    DeckError check_error;
    if (!parse_card_deck(text, deck.path + " (converted to cards)", &check, &check_error)) {
      if (error != nullptr) {
        *error = internal_error(deck.path, "the card deck written from it does not read back (" +
                                               std::to_string(count) +
                                               " values rounded to 12 columns): " + check_error.to_string());
      }
      return false;
    }
    *cards = std::move(text);
    if (rounded != nullptr) *rounded = count;
    return true;
  });
}

}  // namespace tolip::ground
