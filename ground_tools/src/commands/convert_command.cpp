// `tolip convert DECK --to OUT`: a card deck to a TOML deck and back (docs/cli.md).
#include <ostream>
#include <string>

#include "tolip_ground/atomic_file.hpp"
#include "tolip_ground/card_deck.hpp"
#include "tolip_ground/commands.hpp"

namespace tolip::ground {
namespace {

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

int run_convert_command(const ConvertCommandOptions& options, std::ostream& out, std::ostream& err) {
  DeckFormat target = DeckFormat::kToml;
  if (options.format == "toml") {
    target = DeckFormat::kToml;
  } else if (options.format == "cards") {
    target = DeckFormat::kCards;
  } else if (!options.format.empty()) {
    err << "tolip: --format must be 'toml' or 'cards', got '" << options.format << "'\n";
    return kExitBadInput;
  } else if (ends_with(options.out_path, ".toml")) {
    target = DeckFormat::kToml;
  } else if (ends_with(options.out_path, ".dat") || ends_with(options.out_path, ".cards") ||
             ends_with(options.out_path, ".crd")) {
    target = DeckFormat::kCards;
  } else {
    err << "tolip: cannot tell the output format from '" << options.out_path
        << "': name it *.toml (TOML deck) or *.dat (card deck), or give --format toml|cards\n";
    return kExitBadInput;
  }

  // Converting a deck onto itself would replace it (its comments, its header) by the conversion.
  if (names_same_file(options.out_path, options.deck_path)) {
    err << "tolip: --to '" << options.out_path << "' is the input deck '" << options.deck_path
        << "': converting a deck onto itself would replace it; name another file\n";
    return kExitBadInput;
  }

  Deck deck;
  DeckError error;
  if (!load_deck(options.deck_path, &deck, &error)) {
    err << "tolip: " << error.to_string() << '\n';
    return kExitBadInput;
  }
  std::string text;
  int rounded = 0;
  if (target == DeckFormat::kToml) {
    if (!deck_to_toml(deck, options.case_number, &text, &error)) {
      err << "tolip: " << error.to_string() << '\n';
      return kExitBadInput;
    }
  } else {
    if (options.case_number != 0) {
      err << "tolip: --case applies to conversions to TOML (a card deck holds every case)\n";
      return kExitBadInput;
    }
    if (!deck_to_cards(deck, &text, &rounded, &error)) {
      err << "tolip: " << error.to_string() << '\n';
      return kExitBadInput;
    }
  }
  std::string write_error;
  if (!write_file_atomically(options.out_path, text, &write_error)) {
    err << "tolip: " << write_error << '\n';
    return kExitFailure;
  }
  const std::size_t cases = target == DeckFormat::kToml ? 1 : deck.cases.size();
  out << "wrote " << options.out_path << ": " << deck_format_name(target) << " of " << cases << " case"
      << (cases == 1 ? "" : "s") << " from the " << deck_format_name(deck.format) << " " << options.deck_path;
  if (target == DeckFormat::kToml && deck.cases.size() > 1) {
    out << " (case " << (options.case_number == 0 ? 1 : options.case_number) << " of " << deck.cases.size()
        << ")";
  }
  if (rounded > 0) {
    out << "; " << rounded << " value" << (rounded == 1 ? " was" : "s were")
        << " rounded to the 12 columns of an E12.8 field";
  }
  out << '\n';
  return kExitOk;
}

}  // namespace tolip::ground
