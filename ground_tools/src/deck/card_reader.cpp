// Reading 80-column card images into cases (manual Sec. 22 "DATA INPUT FORMAT").
//
// The deck is a sequence of cases, each: header cards (4I3: data block, first word, last word,
// stage code) each followed by the data cards its word range needs, a blank card; then, for every
// optional computation the case's options select (IP(21) dispersion, IP(22) hardover, IP(23)
// impact, IP(24) radar, in that order), that group's cards and a blank card. A card with 999 in
// columns 1-3 ends the deck. Successive cases change the optimization data word by word; the
// optional groups are read afresh for every case. Every fault throws CardFailure with the card,
// the columns, the case, the data block, the stage code and the word.
#include <string>
#include <string_view>
#include <vector>

#include "card_internal.hpp"
#include "card_model.hpp"
#include "deck_common.hpp"
#include "field_description.hpp"

namespace tolip::ground::card_detail {
namespace {

struct Header {
  int card = 0;
  int block = 0;
  int first = 0;
  int last = 0;
  int stage = 0;  // stage code; block 41: number of station cards; block 46: dispersion code
};

const char* const kHeaderFields[4] = {"data block number", "first word", "last word", "stage code"};

class CardReader {
 public:
  CardReader(const std::string& text, std::string path) : path_(std::move(path)) {
    std::size_t start = 0;
    while (!text.empty() && start <= text.size()) {
      std::size_t end = text.find('\n', start);
      if (end == std::string::npos) end = text.size();
      std::string_view line(text.data() + start, end - start);
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      lines_.push_back(line);
      if (end == text.size()) break;
      start = end + 1;
    }
    // A final newline does not start another card.
    if (!lines_.empty() && lines_.back().empty() && !text.empty() && text.back() == '\n') lines_.pop_back();
  }

  std::vector<CardCase> read();

 private:
  [[noreturn]] void fail(int card, int first_column, int last_column, int block, int stage, int word,
                         const std::string& message) const {
    CardFailure failure;
    failure.error.file = path_;
    failure.error.card_deck = true;
    failure.error.line = card;
    failure.error.first_column = first_column;
    failure.error.last_column = last_column;
    failure.error.case_number = case_number_;
    failure.error.data_block = block;
    failure.error.stage_code = stage;
    failure.error.word = word;
    failure.error.message = message;
    throw failure;
  }

  bool at_end() const { return next_ >= lines_.size(); }
  int next_number() const { return static_cast<int>(next_) + 1; }

  // The card at index, checked (at most 80 printable ASCII columns) and padded with blanks to 80.
  std::string card(std::size_t index) const {
    const std::string_view line = lines_[index];
    const int number = static_cast<int>(index) + 1;
    for (std::size_t i = 0; i < line.size(); ++i) {
      const unsigned char c = static_cast<unsigned char>(line[i]);
      const int column = static_cast<int>(i) + 1;
      if (c == '\t') {
        fail(number, column, column, 0, 0, 0,
             "tab character: a card has fixed columns; expected blanks (spaces) to reach the field");
      }
      if (c < 0x20 || c > 0x7E) {
        char hex[8];
        std::snprintf(hex, sizeof hex, "0x%02X", c);
        fail(number, column, column, 0, 0, 0,
             std::string("character ") + hex + " is not a card character: expected printable ASCII");
      }
    }
    if (line.size() > static_cast<std::size_t>(kCardColumns)) {
      fail(number, kCardColumns + 1, static_cast<int>(line.size()), 0, 0, 0,
           "card has " + std::to_string(line.size()) + " columns: a card has at most 80");
    }
    std::string padded(line);
    padded.resize(kCardColumns, ' ');
    return padded;
  }

  static bool is_blank(const std::string& card) { return card.find_first_not_of(' ') == std::string::npos; }
  static bool is_999(const std::string& card) { return card.compare(0, 3, "999") == 0; }

  std::string previous_header_hint() const {
    if (last_.card == 0) return "";
    std::string hint = " (the header on card " + std::to_string(last_.card) + ", data block " +
                       std::to_string(last_.block) + ", took ";
    if (last_.data_cards == 0) return hint + "no data cards: is a data card missing?)";
    hint += std::to_string(last_.data_cards) + " data card" + (last_.data_cards == 1 ? "" : "s") + ", ";
    if (last_.data_cards == 1)
      return hint + "card " + std::to_string(last_.first_data) + ": is a data card missing or extra?)";
    return hint + "cards " + std::to_string(last_.first_data) + "-" +
           std::to_string(last_.first_data + last_.data_cards - 1) + ": is a data card missing or extra?)";
  }

  Header parse_header(const std::string& text, int number) const {
    Header header;
    header.card = number;
    int* fields[4] = {&header.block, &header.first, &header.last, &header.stage};
    for (int k = 0; k < 4; ++k) {
      std::string problem;
      if (!parse_integer_field(text.substr(static_cast<std::size_t>(3 * k), 3), fields[k], &problem)) {
        fail(number, 3 * k + 1, 3 * k + 3, k == 0 ? 0 : header.block, 0, 0,
             std::string("header card (format 4I3: data block, first word, last word, stage code), ") +
                 kHeaderFields[k] + ": " + problem + previous_header_hint());
      }
    }
    return header;
  }

  // Checks a header against the block table and the group being read; returns the block.
  const BlockSpec& check_header(Header* header, unsigned group) const {
    const int number = header->card;
    if (header->block == 0) {
      fail(number, 1, 3, 0, 0, 0,
           "expected a header card with the data block number in columns 1-3 (or a blank card ending the "
           "data, or "
           "the 999 card); columns 1-3 are blank" +
               previous_header_hint());
    }
    const BlockSpec* spec = find_block(header->block);
    if (spec == nullptr) {
      const bool undefined = header->block == 7 || header->block == 24 || header->block == 25;
      fail(number, 1, 3, header->block, 0, 0,
           undefined ? "data block " + std::to_string(header->block) +
                           " is not defined in the manual (blocks 7, 24 and 25 are not used): expected 1-55"
                     : "unknown data block " + std::to_string(header->block) +
                           ": expected 1-55 (the manual's data blocks)" + previous_header_hint());
    }
    if ((spec->groups & group) == 0) {
      fail(
          number, 1, 3, header->block, 0, 0,
          "data block " + std::to_string(header->block) + " (" + spec->title + ") belongs to " +
              group_name(spec->groups) + ", not to " + group_name(group) +
              (group == kOptimizationGroup ? std::string("; the optional groups follow the blank card ending "
                                                         "the optimization data, when their option is set")
                                           : std::string("; each group ends with a blank card")));
    }
    const int block = header->block;
    if (block == 41) {
      if (header->stage < 1 || header->stage > kMaxRadarStations) {
        fail(number, 10, 12, block, header->stage, 0,
             "data block 41 header: columns 10-12 give the number of station cards that follow, expected "
             "1-20, got " +
                 std::to_string(header->stage));
      }
      return *spec;  // fields 2 and 3 are not used: one card per station
    }
    if (block == 46) {
      if (deck_detail::dispersion_name(header->stage) == nullptr) {
        fail(number, 10, 12, block, header->stage, 0,
             "data block 46 header: columns 10-12 give the dispersion trajectory code, expected 1-38 or 40, "
             "got " +
                 std::to_string(header->stage));
      }
      if (header->first == 0 && header->last == 0) {
        header->first = 1;
        header->last = 2;
      }
    } else if (spec->stages == 0) {
      if (header->stage != 0) {
        fail(number, 10, 12, block, header->stage, 0,
             "data block " + std::to_string(block) +
                 " takes no stage code: columns 10-12 must be blank, got " + std::to_string(header->stage));
      }
    } else if (header->stage < 1 || header->stage > 10 || (spec->stages & (1u << header->stage)) == 0) {
      fail(number, 10, 12, block, header->stage, 0,
           "data block " + std::to_string(block) + " (" + spec->title +
               ") needs a stage code in columns 10-12: expected " + stage_list(spec->stages) + ", got " +
               (header->stage == 0 ? std::string("blank") : std::to_string(header->stage)));
    }
    const int size = block_size(*spec, block == 46 ? 0 : header->stage);
    const std::string size_text =
        "data block " + std::to_string(block) +
        (spec->stages != 0 ? " (stage code " + std::to_string(header->stage) + ")" : std::string()) +
        " has " + std::to_string(size) + " word" + (size == 1 ? "" : "s");
    if (header->first < 1) {
      fail(number, 4, 6, block, header->stage, 0,
           "header card: the first word to fill (columns 4-6) must be 1 or more, got " +
               std::to_string(header->first) + "; " + size_text);
    }
    if (header->last < header->first) {
      fail(number, 7, 9, block, header->stage, 0,
           "header card: the last word to fill (columns 7-9) is " + std::to_string(header->last) +
               ", before the first word " + std::to_string(header->first) +
               "; expected first <= last <= " + std::to_string(size));
    }
    if (header->first > size || header->last > size) {
      fail(number, header->first > size ? 4 : 7, header->first > size ? 6 : 9, block, header->stage,
           header->first > size ? header->first : header->last,
           "header range beyond the block: words " + std::to_string(header->first) + "-" +
               std::to_string(header->last) + " asked but " + size_text);
    }
    if ((spec->shape == Shape::kComplete || spec->shape == Shape::kPairs) && header->first != 1) {
      fail(number, 4, 6, block, header->stage, header->first,
           "data block " + std::to_string(block) + " is input complete (the manual: the entire " +
               (spec->shape == Shape::kPairs ? std::string("table for the given stage")
                                             : std::string("list")) +
               " must be re-input to change it): the first word must be 1, got " +
               std::to_string(header->first));
    }
    return *spec;
  }

  bool looks_like_header(const std::string& text) const {
    int fields[4] = {0, 0, 0, 0};
    for (int k = 0; k < 4; ++k) {
      std::string problem;
      if (!parse_integer_field(text.substr(static_cast<std::size_t>(3 * k), 3), &fields[k], &problem))
        return false;
    }
    const BlockSpec* spec = find_block(fields[0]);
    return spec != nullptr && fields[1] >= 1 && fields[2] >= fields[1] && fields[2] <= spec->size;
  }

  // Reads the data cards of a header into `data`.
  void read_words(const Header& header, const BlockSpec& spec, BlockData* data) {
    const int size = block_size(spec, spec.number == 46 ? 0 : header.stage);
    if (static_cast<int>(data->words.size()) < size) data->words.resize(static_cast<std::size_t>(size));
    if (spec.shape == Shape::kComplete || spec.shape == Shape::kPairs) {
      for (Word& word : data->words) word = Word{};
    }
    const int count = header.last - header.first + 1;
    const int per_card = fields_per_card(spec.format);
    const int width = field_width(spec.format);
    const int cards = (count + per_card - 1) / per_card;
    last_ = LastHeader{header.card, header.block, 0, 0};
    for (int c = 0; c < cards; ++c) {
      const std::string range = "words " + std::to_string(header.first) + "-" + std::to_string(header.last);
      if (at_end()) {
        fail(static_cast<int>(lines_.size()), 0, 0, header.block, header.stage, 0,
             "the deck ends inside data block " + std::to_string(header.block) + ": the header on card " +
                 std::to_string(header.card) + " asks for " + range + ", " + std::to_string(cards) +
                 " data card" + (cards == 1 ? "" : "s") + "; found " + std::to_string(c));
      }
      const int number = next_number();
      const std::string text = card(next_);
      ++next_;
      if (c == 0) last_.first_data = number;
      last_.data_cards = c + 1;
      const std::string where = " (data card " + std::to_string(c + 1) + " of " + std::to_string(cards) +
                                " for the header on card " + std::to_string(header.card) + ", " + range + ")";
      const std::string header_hint =
          looks_like_header(text) ? "; card " + std::to_string(number) +
                                        " looks like a header card: is the data block short of data cards?"
                                  : "";
      for (int f = 0; f < per_card; ++f) {
        const int word_number = header.first + c * per_card + f;
        if (word_number > header.last) break;
        Word& word = data->words[static_cast<std::size_t>(word_number - 1)];
        word = Word{};
        word.given = true;
        const int first_column = f * width + 1;
        word.origin = Origin{number, first_column, first_column + width - 1};
        const std::string field =
            text.substr(static_cast<std::size_t>(f * width), static_cast<std::size_t>(width));
        std::string problem;
        switch (spec.format) {
          case Format::kText: word.text = field; break;
          case Format::kDigit:
          case Format::kInteger: {
            int value = 0;
            if (!parse_integer_field(field, &value, &problem)) {
              fail(number, first_column, first_column + width - 1, header.block, header.stage, word_number,
                   problem + where + header_hint);
            }
            word.number = value;
            break;
          }
          case Format::kReal: {
            double value = 0.0;
            if (!parse_real_field(field, &value, &problem)) {
              fail(number, first_column, first_column + width - 1, header.block, header.stage, word_number,
                   problem + where + header_hint);
            }
            word.number = value;
            break;
          }
          case Format::kStation: break;  // read_station
        }
      }
    }
    data->header = Origin{header.card, 1, 12};
  }

  // One station card of data block 41: 2A6 identification, 3E12.8 latitude, longitude, altitude;
  // columns 49-80 an optional description (an extension; FORTRAN does not read them).
  BlockData read_station(const Header& header, int index) {
    if (at_end()) {
      fail(static_cast<int>(lines_.size()), 0, 0, 41, header.stage, 0,
           "the deck ends inside data block 41: the header on card " + std::to_string(header.card) +
               " announces " + std::to_string(header.stage) + " station cards; found " +
               std::to_string(index));
    }
    const int number = next_number();
    const std::string text = card(next_);
    ++next_;
    BlockData station;
    station.words.resize(5);
    station.header = Origin{header.card, 1, 12};
    static const int kColumns[5][2] = {{1, 12}, {13, 24}, {25, 36}, {37, 48}, {49, 80}};
    for (int w = 0; w < 5; ++w) {
      Word& word = station.words[static_cast<std::size_t>(w)];
      word.given = true;
      word.origin = Origin{number, kColumns[w][0], kColumns[w][1]};
      const std::string field = text.substr(static_cast<std::size_t>(kColumns[w][0] - 1),
                                            static_cast<std::size_t>(kColumns[w][1] - kColumns[w][0] + 1));
      if (w == 0 || w == 4) {
        word.text = field;
        continue;
      }
      std::string problem;
      if (!parse_real_field(field, &word.number, &problem)) {
        fail(number, kColumns[w][0], kColumns[w][1], 41, header.stage, w + 1,
             problem + " (station card " + std::to_string(index + 1) + " of " + std::to_string(header.stage) +
                 ": 2A6 identification, then latitude, longitude, altitude in E12.8)");
      }
    }
    last_ = LastHeader{header.card, 41, number - index, index + 1};
    return station;
  }

  void read_optimization_block(const Header& header, const BlockSpec& spec, BlockSet* state) {
    BlockData& data = (*state)[BlockKey{header.block, spec.stages != 0 ? header.stage : 0}];
    read_words(header, spec, &data);
  }

  void read_group(unsigned group, int option, CardCase* result);

  std::string path_;
  std::vector<std::string_view> lines_;
  std::size_t next_ = 0;
  int case_number_ = 0;
  struct LastHeader {
    int card = 0;
    int block = 0;
    int first_data = 0;
    int data_cards = 0;
  } last_;
};

void CardReader::read_group(unsigned group, int option, CardCase* result) {
  const std::string name = group_name(group);
  Dispersion* current = nullptr;
  while (true) {
    if (at_end()) {
      fail(static_cast<int>(lines_.size()), 0, 0, 0, 0, 0,
           "the deck ends inside " + name + " of case " + std::to_string(case_number_) + ": IP(" +
               std::to_string(option) +
               ") = 1 selects it; expected its data blocks, a blank card, then the 999 card");
    }
    const int number = next_number();
    const std::string text = card(next_);
    if (is_blank(text)) {
      ++next_;
      last_ = LastHeader{};
      return;
    }
    if (is_999(text)) {
      fail(number, 1, 3, 0, 0, 0,
           "999 card where " + name + " of case " + std::to_string(case_number_) + " was expected: IP(" +
               std::to_string(option) +
               ") = 1 selects it; expected its data blocks and a blank card (or IP(" +
               std::to_string(option) + ") = 0)");
    }
    Header header = parse_header(text, number);
    ++next_;
    const BlockSpec& spec = check_header(&header, group);
    if (group == kRadarGroup) {
      for (int i = 0; i < header.stage; ++i) result->radar.push_back(read_station(header, i));
      continue;
    }
    if (group == kDispersionGroup) {
      if (header.block == 46) {
        result->dispersions.emplace_back();
        current = &result->dispersions.back();
        current->code = header.stage;
        current->header = Origin{header.card, 10, 12};
        read_words(header, spec, &current->title);
        continue;
      }
      if (current == nullptr) {
        fail(number, 1, 3, header.block, header.stage, 0,
             "data block " + std::to_string(header.block) +
                 " before the first data block 46: each dispersed trajectory starts with a block 46 header "
                 "(its code "
                 "in columns 10-12) and its title card, followed by its data");
      }
      const int stage = deck_detail::dispersion_stage(current->code, header.block);  // -1: stage 4 or 5
      if (!deck_detail::dispersion_takes(current->code, header.block)) {
        fail(number, 1, 3, header.block, header.stage, 0,
             "data block " + std::to_string(header.block) + " is not data of dispersion code " +
                 std::to_string(current->code) + " (" + deck_detail::dispersion_name(current->code) +
                 ", block 46 on card " + std::to_string(current->header.card) + "): expected " +
                 deck_detail::dispersion_blocks(current->code));
      }
      if (stage > 0 && header.stage != stage) {
        fail(number, 10, 12, header.block, header.stage, 0,
             "dispersion code " + std::to_string(current->code) + " (" +
                 deck_detail::dispersion_name(current->code) + ") applies to stage " + std::to_string(stage) +
                 ": expected stage code " + std::to_string(stage) + " in columns 10-12, got " +
                 std::to_string(header.stage));
      }
      BlockData& data = current->blocks[BlockKey{header.block, spec.stages != 0 ? header.stage : 0}];
      read_words(header, spec, &data);
      continue;
    }
    BlockSet* set = group == kHardoverGroup ? &result->hardover : &result->impact;
    BlockData& data = (*set)[BlockKey{header.block, spec.stages != 0 ? header.stage : 0}];
    read_words(header, spec, &data);
  }
}

std::vector<CardCase> CardReader::read() {
  std::vector<CardCase> cases;
  BlockSet state;
  while (true) {
    if (at_end()) {
      if (cases.empty()) {
        fail(0, 0, 0, 0, 0, 0,
             "empty card deck: expected header cards (4I3: data block, first word, last word, stage code) "
             "with their "
             "data cards, a blank card ending the case, and a card with 999 in columns 1-3");
      }
      case_number_ = 0;
      fail(static_cast<int>(lines_.size()), 0, 0, 0, 0, 0,
           "the deck ends without the 999 card: expected a card with 999 in columns 1-3 after the blank card "
           "ending "
           "the last case (case " +
               std::to_string(cases.size()) + ")");
    }
    const int number = next_number();
    const std::string text = card(next_);
    if (is_999(text)) {
      if (cases.empty())
        fail(number, 1, 3, 0, 0, 0,
             "the 999 card ends the deck before any case: expected the data of case 1 first");
      break;
    }
    if (is_blank(text)) {
      fail(number, 0, 0, 0, 0, 0,
           "blank card where case " + std::to_string(cases.size() + 1) +
               " should start: a case starts with a header card, and one blank card ends it (two blank cards "
               "in a row?)");
    }
    CardCase result;
    result.number = ++case_number_;
    result.first_card = number;
    last_ = LastHeader{};
    while (true) {
      if (at_end()) {
        fail(static_cast<int>(lines_.size()), 0, 0, 0, 0, 0,
             "the deck ends inside case " + std::to_string(case_number_) +
                 ": expected a blank card ending its data, then the 999 card" + previous_header_hint());
      }
      const int card_number = next_number();
      const std::string card_text = card(next_);
      if (is_blank(card_text)) {
        ++next_;
        break;
      }
      if (is_999(card_text)) {
        fail(card_number, 1, 3, 0, 0, 0,
             "999 card inside case " + std::to_string(case_number_) +
                 ": the case's data must be ended by a blank card before the 999 card" +
                 previous_header_hint());
      }
      Header header = parse_header(card_text, card_number);
      ++next_;
      const BlockSpec& spec = check_header(&header, kOptimizationGroup);
      read_optimization_block(header, spec, &state);
    }
    result.optimization = state;
    auto option = [&state](int n) { return value_of(find_word(state, 4, 0, n)) == 1.0; };
    last_ = LastHeader{};
    if (option(21)) {
      result.dispersion_group = true;
      read_group(kDispersionGroup, 21, &result);
    }
    if (option(22)) {
      result.hardover_group = true;
      read_group(kHardoverGroup, 22, &result);
    }
    if (option(23)) {
      result.impact_group = true;
      read_group(kImpactGroup, 23, &result);
    }
    if (option(24)) {
      result.radar_group = true;
      read_group(kRadarGroup, 24, &result);
    }
    cases.push_back(std::move(result));
  }
  return cases;
}

}  // namespace

std::vector<CardCase> read_card_cases(const std::string& text, const std::string& path) {
  CardReader reader(text, path);
  return reader.read();
}

}  // namespace tolip::ground::card_detail
