// The heritage card deck as data (manual Sec. 22, docs/deck-format.md "The card deck"): the block
// table (format, size, stage coding, group, the words' meanings) and the words of one case as
// punched, with the card and columns each word came from.
//
// The card reader (card_reader.cpp) fills a CardCase from 80-column card images; the TOML side
// (card_toml.cpp) turns a CardCase into a TOML deck, which the TOML reader then checks and converts
// to the core's units, so both deck formats share every check and every unit conversion. The
// writer (card_writer.cpp) goes the other way, from a TOML deck to words and card images.
#pragma once

#include <compare>
#include <map>
#include <string>
#include <vector>

#include "tolip_ground/deck.hpp"

namespace tolip::ground::card_detail {

inline constexpr int kCardColumns = 80;
inline constexpr double kTableEnd = 1.0e10;  // the manual's table terminator (any x >= 1.0E10)
inline constexpr int kTableWords = 42;       // blank + 20 pairs + 1.0E10 (42E12.8)

// Where a word (or a header) was punched. card 0: not from a card (a default, or a TOML deck).
struct Origin {
  int card = 0;
  int first_column = 0;
  int last_column = 0;
  bool known() const { return card > 0; }
};

struct Word {
  bool given = false;   // punched (a blank field inside a header range is given, as 0 / blanks)
  double number = 0.0;  // numeric words (I and E formats)
  std::string text;     // A formats: the characters as punched, blank padded
  Origin origin;
};

enum class Format { kText, kDigit, kInteger, kReal, kStation };

enum class Shape {
  kWords,     // independent words; a header may change any range
  kComplete,  // data block 18: the whole block is input again to change it (words after the range cleared)
  kPairs,     // data blocks 30, 38: time, value, time, value ... complete per stage (no blank, no 1.0E10)
  kTable,     // blank, x, y, x, y, ..., 1.0E10 (blocks 31, 32, 34-37, 40, 42-44, 53, 54)
};

enum Group : unsigned {
  kOptimizationGroup = 1u,  // data blocks 1-40: the case (successive cases give only changes)
  kDispersionGroup = 2u,    // IP(21): blocks 46-55 (and 30, 35, 38), after the first blank card
  kHardoverGroup = 4u,      // IP(22): blocks 44, 45 (and 33, 37)
  kImpactGroup = 8u,        // IP(23): blocks 42, 43 (and 33, 23)
  kRadarGroup = 16u,        // IP(24): block 41
};

struct BlockSpec {
  int number = 0;
  const char* title = "";  // upper case, for messages, header comments and the IP(17) echo
  Format format = Format::kReal;
  int size = 0;  // words (of one stage code); block 39 coasts: 2
  Shape shape = Shape::kWords;
  unsigned groups = 0;      // Group bits where the block may appear
  unsigned stages = 0;      // bit c set: stage code c allowed; 0: no stage code (header field 4 blank)
  const char* x_name = "";  // tables: the abscissa and ordinate, for the echo
  const char* y_name = "";
  bool extension = false;  // not a block of the manual (this project's words: blocks 15 and 23)
};

// The block of that number, or nullptr (blocks 7, 24, 25 are not defined; numbers outside 1-55).
const BlockSpec* find_block(int number);
// Every defined block in increasing number.
const std::vector<BlockSpec>& all_blocks();
// Words of the block for that stage code (block 39: 3 for powered stages, 2 for coasts).
int block_size(const BlockSpec& spec, int stage);
// Card layout of a format: fields per card and columns per field.
int fields_per_card(Format format);
int field_width(Format format);
// What a word means ("CT1(2) MU, FT3/S2"); empty when the manual does not use the word.
std::string word_description(int block, int stage, int word);
// Stage codes allowed, as text ("1-5", "1, 2, 6").
std::string stage_list(unsigned stages);
// Names of the groups in `groups` ("the dispersion data (IP(21))").
std::string group_name(unsigned group);

struct BlockData {
  std::vector<Word> words;  // words[i] is word i + 1
  Origin header;            // the last header card that filled it
  bool any_given() const {
    for (const Word& word : words) {
      if (word.given) return true;
    }
    return false;
  }
  const Word* at(int word) const {
    return word >= 1 && word <= static_cast<int>(words.size()) ? &words[static_cast<std::size_t>(word - 1)]
                                                               : nullptr;
  }
};

struct BlockKey {
  int block = 0;
  int stage = 0;  // 0 when not stage-coded
  auto operator<=>(const BlockKey&) const = default;
};
using BlockSet = std::map<BlockKey, BlockData>;

inline const BlockData* find_data(const BlockSet& set, int block, int stage = 0) {
  const auto it = set.find(BlockKey{block, stage});
  return it == set.end() ? nullptr : &it->second;
}
inline const Word* find_word(const BlockSet& set, int block, int stage, int word) {
  const BlockData* data = find_data(set, block, stage);
  if (data == nullptr) return nullptr;
  const Word* found = data->at(word);
  return found != nullptr && found->given ? found : nullptr;
}

// One dispersed trajectory: the block 46 header (code in field 4), its title and its data blocks.
struct Dispersion {
  int code = 0;
  Origin header;
  BlockData title;  // block 46: 2 words of 6 characters
  BlockSet blocks;  // 30, 38, 55, 47-54, 35 of this trajectory
};

// One case: the optimization data as they stand after this case's cards (successive cases start
// from the previous case's words), and the optional groups read for this case only.
struct CardCase {
  int number = 0;      // 1-based
  int first_card = 0;  // first card of the case (TOML decks: 0)
  BlockSet optimization;
  bool dispersion_group = false;  // the groups read after the blank card (selected by IP(21)-IP(24))
  bool hardover_group = false;
  bool impact_group = false;
  bool radar_group = false;
  std::vector<Dispersion> dispersions;
  BlockSet hardover;  // 44, 45, 33, 37: laid over the optimization data for this case
  BlockSet impact;    // 42, 43, 23, 33
  std::vector<BlockData>
      radar;  // one per station card: id (text), latitude, longitude, altitude, name (text)
};

// Thrown inside the card code, caught at the public entry points.
struct CardFailure {
  DeckError error;
};

// The value of a word for arithmetic (0 when not given).
inline double value_of(const Word* word) { return word != nullptr && word->given ? word->number : 0.0; }

// ---- number fields ------------------------------------------------------------------------------
// A FORTRAN E12.8 field (blank: 0). A number needs a decimal point (E12.8 would scale a number
// without one by 1e-8); returns false with the reason in *problem.
bool parse_real_field(const std::string& field, double* value, std::string* problem);
// An I field: right-justified digits, optional sign (blank: 0).
bool parse_integer_field(const std::string& field, int* value, std::string* problem);
// The text of a number in at most `width` columns, always with a decimal point; the exact value
// when it fits, else the most significant digits that fit. *exact tells which.
std::string format_real_field(double value, int width, bool* exact);

}  // namespace tolip::ground::card_detail
