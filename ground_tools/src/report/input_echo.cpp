// IP(17) echo of the input data (input_echo.hpp).
#include "tolip_ground/input_echo.hpp"

#include <cstdio>
#include <string>
#include <vector>

#include "../deck/card_internal.hpp"
#include "../deck/card_model.hpp"
#include "../deck/deck_common.hpp"
#include "../deck/field_description.hpp"
#include "listing_pager.hpp"

namespace tolip::ground {
namespace {

using card_detail::BlockData;
using card_detail::BlockKey;
using card_detail::BlockSet;
using card_detail::BlockSpec;
using card_detail::CardCase;
using card_detail::Format;
using card_detail::Shape;
using card_detail::Word;
using report_detail::Pager;

constexpr int kColumnWidth = 66;  // two words per line, 132 columns

std::string number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%15.8E", value);
  return buffer;
}

std::string fixed(const std::string& text, std::size_t width) {
  std::string out = text.substr(0, width);
  out.resize(width, ' ');
  return out;
}

class Echo {
 public:
  Echo(Pager& pager) : pager_(pager) {}

  void block(const BlockSet& set, int block, int stage, const std::string& prefix = "") {
    const BlockSpec* spec = card_detail::find_block(block);
    const BlockData* data = card_detail::find_data(set, block, stage);
    if (spec == nullptr) return;
    const bool nominal_block = block >= 10 && block <= 14;
    if ((data == nullptr || !data->any_given()) && !nominal_block) return;
    std::string title = prefix + "DATA BLOCK " + std::to_string(block) + "  " + spec->title;
    if (spec->stages != 0 && stage > 0) title += "  STAGE CODE " + std::to_string(stage);
    if (spec->extension) title += "  (EXTENSION, NOT IN THE MANUAL)";
    pager_.reserve(3);
    pager_.emit(title);
    if (spec->format == Format::kText) {
      text(data, spec->size);
    } else if (spec->shape == Shape::kTable || spec->shape == Shape::kPairs) {
      table(*spec, set, block, stage);
    } else {
      words(*spec, data, block, stage, nominal_block);
    }
    pager_.emit("");
  }

  void text(const BlockData* data, int size) {
    std::string line;
    for (int w = 1; w <= size; ++w) {
      const Word* word = data != nullptr ? data->at(w) : nullptr;
      line += fixed(word != nullptr && word->given ? word->text : "", 6);
    }
    pager_.emit(
        "      '" +
        line.substr(0, line.find_last_not_of(' ') == std::string::npos ? 0 : line.find_last_not_of(' ') + 1) +
        "'");
  }

  void words(const BlockSpec& spec, const BlockData* data, int block, int stage, bool nominal_block) {
    std::vector<std::string> cells;
    const int size =
        data != nullptr ? static_cast<int>(data->words.size()) : card_detail::block_size(spec, stage);
    for (int w = 1; w <= size; ++w) {
      const Word* word = data != nullptr ? data->at(w) : nullptr;
      const bool given = word != nullptr && word->given;
      const std::string meaning = card_detail::word_description(block, stage, w);
      double value = given ? word->number : 0.0;
      std::string note;
      if (!given) {
        if (!nominal_block || meaning.empty() || !nominal(block, w, &value)) continue;
        note = " NOM";
      }
      char label[16];
      std::snprintf(label, sizeof label, block == 4 ? "IP(%2d)" : "%3d", w);
      std::string text =
          fixed(std::string("  ") + label, 9) + fixed(meaning.empty() ? "(NOT USED)" : meaning, 38);
      if (spec.format == Format::kReal) {
        text += number(value);
      } else {
        char integer[24];
        std::snprintf(integer, sizeof integer, "%15lld", static_cast<long long>(value));
        text += integer;
      }
      cells.push_back(text + note);
    }
    for (std::size_t i = 0; i < cells.size(); i += 2) {
      std::string line = fixed(cells[i], kColumnWidth);
      if (i + 1 < cells.size()) line += cells[i + 1];
      pager_.emit(line);
    }
  }

  // The value a word of blocks 10-14 has when the deck does not punch it (the field description's).
  static bool nominal(int block, int word, double* value) {
    int index = 0;
    const deck_detail::FieldDescription* field = deck_detail::find_field(block, 0, word, &index);
    if (field == nullptr) return false;
    *value = deck_detail::default_deck_value(*field, 0, index);
    return true;
  }

  void table(const BlockSpec& spec, const BlockSet& set, int block, int stage) {
    const BlockData* data = card_detail::find_data(set, block, stage);
    std::vector<std::pair<double, double>> points;
    const int size = static_cast<int>(data->words.size());
    const bool pairs = spec.shape == Shape::kPairs;
    for (int w = pairs ? 1 : 2; w + 1 <= size; w += 2) {
      const Word* x = data->at(w);
      const Word* y = data->at(w + 1);
      if (x == nullptr || !x->given || x->number >= card_detail::kTableEnd || y == nullptr || !y->given)
        break;
      points.emplace_back(x->number, y->number);
    }
    pager_.emit("      " + std::to_string(points.size()) + " POINTS: " + spec.x_name + " VS " + spec.y_name);
    std::string line;
    for (std::size_t i = 0; i < points.size(); ++i) {
      char cell[64];
      std::snprintf(cell, sizeof cell, "  %3zu%15.8E%15.8E", i + 1, points[i].first, points[i].second);
      line += cell;
      if (i % 3 == 2 || i + 1 == points.size()) {
        pager_.emit("    PT" + line);
        line.clear();
      }
    }
  }

  void set(const BlockSet& blocks, const std::string& prefix = "") {
    for (const auto& [key, data] : blocks) {
      if (key.block >= 10 && key.block <= 14) continue;
      block(blocks, key.block, key.stage, prefix);
    }
  }

 private:
  Pager& pager_;
};

}  // namespace

void write_input_echo(std::ostream& out, const Deck& deck, const DeckCase& deck_case) {
  if (!deck_case.mission) return;
  Pager pager(out, &deck_case.extras.listing);
  pager.new_page("INPUT DATA", false);
  pager.emit(" INPUT DATA OF CASE " + std::to_string(deck_case.number) + " (OPTION IP(17)), " +
             deck_format_name(deck.format));
  pager.emit(" " + deck.path.substr(0, 130));
  pager.emit("");
  if (!deck_case.words) {
    pager.emit(" (the input data word by word are not available for this deck)");
    return;
  }
  const CardCase& words = *deck_case.words;
  Echo echo(pager);
  // Blocks in number order; 10-14 always (with their nominal values).
  bool nominal_done = false;
  for (const auto& [key, data] : words.optimization) {
    if (!nominal_done && key.block > 14) {
      for (int block = 10; block <= 14; ++block) echo.block(words.optimization, block, 0);
      nominal_done = true;
    }
    if (key.block >= 10 && key.block <= 14) continue;
    echo.block(words.optimization, key.block, key.stage);
  }
  if (!nominal_done) {
    for (int block = 10; block <= 14; ++block) echo.block(words.optimization, block, 0);
  }
  if (words.dispersion_group) {
    pager.reserve(3);
    pager.emit(" DISPERSION DATA (IP(21))");
    pager.emit("");
    for (const card_detail::Dispersion& d : words.dispersions) {
      std::string title;
      for (const Word& word : d.title.words) title += fixed(word.text, 6);
      const char* name = deck_detail::dispersion_name(d.code);
      pager.reserve(2);
      pager.emit(" DATA BLOCK 46  DISPERSION CODE " + std::to_string(d.code) + "  " +
                 (name != nullptr ? name : "") + "  TITLE '" +
                 title.substr(0, title.find_last_not_of(' ') + 1) + "'");
      echo.set(d.blocks, "   ");
    }
  }
  if (words.hardover_group) {
    pager.reserve(3);
    pager.emit(" HARDOVER DATA (IP(22))");
    pager.emit("");
    echo.set(words.hardover);
  }
  if (words.impact_group) {
    pager.reserve(3);
    pager.emit(" IMPACT DATA (IP(23))");
    pager.emit("");
    echo.set(words.impact);
  }
  if (words.radar_group || !words.radar.empty()) {
    pager.reserve(3 + static_cast<int>(words.radar.size()));
    pager.emit(" DATA BLOCK 41  RADAR STATION LOCATIONS (IP(24))");
    pager.emit("      STATION       GEOD LAT DEG      LONGITUDE DEG    ALTITUDE FT   DESCRIPTION");
    for (const BlockData& station : words.radar) {
      if (station.words.size() < 5) continue;
      pager.emit("      " + fixed(station.words[0].text, 12) + number(station.words[1].number) +
                 number(station.words[2].number) + number(station.words[3].number) + "   " +
                 station.words[4].text.substr(0, 40));
    }
    pager.emit("");
  }
}

void write_input_echo(std::ostream& out, const std::string& path, int case_number) {
  Deck deck;
  DeckError error;
  if (!load_deck(path, &deck, &error)) return;
  if (case_number < 1 || case_number > static_cast<int>(deck.cases.size())) return;
  write_input_echo(out, deck, deck.cases[static_cast<std::size_t>(case_number - 1)]);
}

}  // namespace tolip::ground
