// A card case as a TOML deck (card_internal.hpp).
//
// Every punched word becomes the TOML value the TOML deck reader knows (docs/deck-format.md "The
// card deck" maps each word); words not punched are left out, so the TOML reader's defaults and
// "required" checks apply. The units are those of the cards except data blocks 19 and 29, whose
// angles are radians on the cards and degrees in TOML. In the located form every value sits on a
// line of its own and the word behind every line and key path is recorded, so the TOML reader's
// messages can be put back on the card and columns.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "card_internal.hpp"
#include "deck_common.hpp"
#include "toml_reader.hpp"

namespace tolip::ground::card_detail {
namespace {

constexpr int kWrap = 96;

std::string toml_number(double value) {
  std::string text = deck_detail::format_number(value);
  if (text.find_first_of(".eEni") == std::string::npos) text += ".0";
  return text;
}

std::string toml_integer(double value) {
  if (std::isfinite(value) && value == std::floor(value) && std::abs(value) < 2147483648.0) {
    return std::to_string(static_cast<long long>(value));
  }
  return toml_number(value);  // the TOML reader says "expected an integer"
}

std::string toml_string(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string trim(const std::string& text) {
  const std::size_t begin = text.find_first_not_of(' ');
  if (begin == std::string::npos) return "";
  const std::size_t end = text.find_last_not_of(' ');
  return text.substr(begin, end - begin + 1);
}

std::string rtrim(const std::string& text) {
  const std::size_t end = text.find_last_not_of(' ');
  return end == std::string::npos ? std::string() : text.substr(0, end + 1);
}

std::string str(int value) { return std::to_string(value); }

struct ParsedTable {
  std::vector<double> x;
  std::vector<double> y;
  std::vector<WordRef> x_refs;
  std::vector<WordRef> y_refs;
};

class Builder {
 public:
  Builder(const CardCase& card_case, const std::string& path, bool located)
      : case_(card_case), path_(path), located_(located) {
    body_ = overlay_body();
  }

  TomlDeck build() {
    check_unused_words();
    if (!located_) {
      comment("TOLIP case deck (TOML; format: docs/deck-format.md), converted from the card deck");
      comment(path_ + ", case " + str(case_.number) + " (first card " + str(case_.first_card) + ").");
      comment("Comments name the data block and word each value was punched in.");
    }
    case_section();
    options_section();
    scalar_section("constants", case_.optimization);
    atmosphere_section();
    vehicle_section();
    stage_sections();
    scalar_section("launch", case_.optimization);
    scalar_section("control_constraints", case_.optimization);
    scalar_section("misc", case_.optimization);
    constraint_sections();
    adjustable_sections();
    linearization_section();
    scalar_section("convergence", case_.optimization);
    output_frequency_section();
    pitch_program_section();
    body_dynamics_sections();
    radar_sections();
    impact_sections();
    hardover_sections();
    dispersion_sections();
    if (!out_.text.empty() && out_.text.back() != '\n') out_.text += '\n';
    return std::move(out_);
  }

 private:
  // ---- output -----------------------------------------------------------------------------------
  void line(const std::string& text, const WordRef& ref) {
    out_.text += text;
    out_.text += '\n';
    out_.lines.push_back(ref);
  }
  void blank() {
    const std::size_t size = out_.text.size();
    if (!located_ && size > 0 && !(size >= 2 && out_.text.compare(size - 2, 2, "\n\n") == 0))
      line("", WordRef{});
  }
  void comment(const std::string& text) {
    if (!located_) line(rtrim("# " + text), WordRef{});
  }
  void remember(const std::string& path, const WordRef& ref) { out_.paths.emplace(path, ref); }

  std::string note(const WordRef& ref) const {
    if (ref.block == 0) return "";
    std::string text = "block " + str(ref.block);
    if (ref.stage > 0) text += (ref.block == 46 ? " code " : " stage ") + str(ref.stage);
    const BlockSpec* spec = find_block(ref.block);
    if (spec != nullptr && spec->format == Format::kText)
      return text + (spec->size == 12 ? ", 12A6" : ", 2A6");
    if (ref.word > 0) {
      text += " word " + str(ref.word);
      const std::string meaning = word_description(ref.block, ref.stage, ref.word);
      if (!meaning.empty()) text += ": " + meaning;
    }
    return text;
  }

  void table_header(const std::string& path, const WordRef& ref, bool array = false,
                    const std::string& extra = "") {
    blank();
    std::string text = (array ? "[[" : "[") + path + (array ? "]]" : "]");
    if (!located_) {
      std::string what = extra.empty() ? note(WordRef{ref.block, ref.stage, 0, {}, {}}) : extra;
      if (!what.empty()) text += "  # " + what;
    }
    line(text, ref);
    remember(path, ref);
  }

  void scalar(const std::string& section, const std::string& key, const std::string& literal,
              const WordRef& ref) {
    std::string text = key + " = " + literal;
    if (!located_) {
      const std::string what = note(ref);
      if (!what.empty()) {
        if (text.size() < 44) text.resize(44, ' ');
        text += " # " + what;
      }
    }
    line(text, ref);
    remember(section.empty() ? key : section + "." + key, ref);
  }

  void array(const std::string& section, const std::string& key, const std::vector<std::string>& literals,
             const std::vector<WordRef>& refs, const WordRef& key_ref) {
    const std::string path = section.empty() ? key : section + "." + key;
    remember(path, key_ref);
    for (std::size_t i = 0; i < literals.size(); ++i)
      remember(path + "[" + str(static_cast<int>(i)) + "]", refs[i]);
    if (located_) {
      line(key + " = [", key_ref);
      for (std::size_t i = 0; i < literals.size(); ++i) line(literals[i] + ",", refs[i]);
      line("]", key_ref);
      return;
    }
    std::string joined;
    for (const std::string& literal : literals) joined += (joined.empty() ? "" : ", ") + literal;
    const std::string one_line = key + " = [" + joined + "]";
    if (static_cast<int>(one_line.size()) <= kWrap) {
      line(one_line, key_ref);
      return;
    }
    line(key + " = [", key_ref);
    std::string current = "  ";
    for (const std::string& literal : literals) {
      const std::string piece = literal + ",";
      if (static_cast<int>(current.size() + piece.size()) + 1 > kWrap && current.size() > 2) {
        line(rtrim(current), key_ref);
        current = "  ";
      }
      current += piece + " ";
    }
    if (current.size() > 2) line(rtrim(current), key_ref);
    line("]", key_ref);
  }

  void numbers(const std::string& section, const std::string& key, const std::vector<double>& values,
               const std::vector<WordRef>& refs, const WordRef& key_ref, bool integers = false) {
    std::vector<std::string> literals;
    literals.reserve(values.size());
    for (double value : values) literals.push_back(integers ? toml_integer(value) : toml_number(value));
    array(section, key, literals, refs, key_ref);
  }

  // ---- words ------------------------------------------------------------------------------------
  [[noreturn]] void fail(const WordRef& ref, const std::string& message) const {
    CardFailure failure;
    failure.error.file = path_;
    failure.error.card_deck = true;
    failure.error.case_number = case_.number;
    failure.error.data_block = ref.block;
    failure.error.stage_code = ref.stage;
    failure.error.word = ref.word;
    const Origin& where = ref.origin.known() ? ref.origin : ref.header;
    failure.error.line = where.card;
    failure.error.first_column = ref.origin.known() ? where.first_column : 0;
    failure.error.last_column = ref.origin.known() ? where.last_column : 0;
    failure.error.message = message;
    throw failure;
  }

  static WordRef ref_in(const BlockSet& set, int block, int stage, int word) {
    WordRef ref{block, stage, word, {}, {}};
    if (const BlockData* data = find_data(set, block, stage)) {
      ref.header = data->header;
      if (const Word* found = data->at(word); found != nullptr && found->given) ref.origin = found->origin;
    }
    return ref;
  }
  static const Word* given(const BlockSet& set, int block, int stage, int word) {
    return find_word(set, block, stage, word);
  }
  static bool block_given(const BlockSet& set, int block, int stage = 0) {
    const BlockData* data = find_data(set, block, stage);
    return data != nullptr && data->any_given();
  }
  const BlockSet& opt() const { return case_.optimization; }

  static std::string text_of(const BlockData* data, int words) {
    std::string text;
    for (int w = 1; w <= words; ++w) {
      const Word* word = data != nullptr ? data->at(w) : nullptr;
      std::string piece = word != nullptr && word->given ? word->text : std::string();
      piece.resize(6, ' ');
      text += piece;
    }
    return rtrim(text);
  }

  // Blocks 33-37 as the optional groups of this case see them: the optimization data with the
  // words the hardover and impact groups punched laid over them.
  BlockSet overlay_body() const {
    BlockSet body;
    for (const auto& [key, data] : case_.optimization) {
      if (key.block >= 33 && key.block <= 37) body[key] = data;
    }
    for (const BlockSet* group : {&case_.hardover, &case_.impact}) {
      for (const auto& [key, data] : *group) {
        if (key.block != 33 && key.block != 37) continue;
        BlockData& target = body[key];
        if (target.words.size() < data.words.size()) target.words.resize(data.words.size());
        for (std::size_t i = 0; i < data.words.size(); ++i) {
          if (!data.words[i].given) continue;
          // A word given twice with different values would be dropped silently: refused instead.
          const Word& before = target.words[i];
          if (before.given && before.origin.known() && before.number != data.words[i].number) {
            fail(ref_in(*group, key.block, key.stage, static_cast<int>(i) + 1),
                 "word " + str(static_cast<int>(i) + 1) + " given again with another value: " +
                     deck_detail::format_number(data.words[i].number) + " here, " +
                     deck_detail::format_number(before.number) + " on card " + str(before.origin.card) +
                     "; the case would fly only one of them: give the word once, or the same value");
          }
          target.words[i] = data.words[i];
        }
        target.header = data.header;
      }
    }
    return body;
  }

  // Words the manual does not use must be blank (or zero).
  void check_unused_words() const {
    auto check = [this](const BlockSet& set) {
      for (const auto& [key, data] : set) {
        const BlockSpec* spec = find_block(key.block);
        if (spec == nullptr || spec->shape != Shape::kWords || spec->format == Format::kText ||
            spec->format == Format::kStation) {
          continue;
        }
        for (std::size_t i = 0; i < data.words.size(); ++i) {
          const Word& word = data.words[i];
          const int number = static_cast<int>(i) + 1;
          if (!word.given || word.number == 0.0) continue;
          if (word_description(key.block, key.stage, number).empty()) {
            fail(ref_in(set, key.block, key.stage, number),
                 std::string(key.block == 4 ? "IP(" + str(number) + ")" : "word " + str(number)) +
                     " is not used by the manual: expected blank or 0, got " +
                     deck_detail::format_number(word.number));
          }
        }
      }
    };
    check(case_.optimization);
    check(case_.hardover);
    check(case_.impact);
    for (const Dispersion& dispersion : case_.dispersions) check(dispersion.blocks);
  }

  ParsedTable parse_table(const BlockSet& set, int block, int stage) const {
    ParsedTable table;
    const BlockData* data = find_data(set, block, stage);
    if (data == nullptr) return table;
    const BlockSpec* spec = find_block(block);
    const int size = static_cast<int>(data->words.size());
    auto at = [&](int w) { return ref_in(set, block, stage, w); };
    if (spec != nullptr && spec->shape == Shape::kPairs) {
      for (int i = 1; i <= size; i += 2) {
        const Word* x = data->at(i);
        if (x == nullptr || !x->given || x->number >= kTableEnd) break;
        const Word* y = data->at(i + 1);
        if (y == nullptr || !y->given) {
          fail(at(i), "word " + str(i) + " (" + spec->x_name +
                          ") has no value after it: the table is pairs of " + spec->x_name + " and " +
                          spec->y_name + ", an even number of words");
        }
        table.x.push_back(x->number);
        table.y.push_back(y->number);
        table.x_refs.push_back(at(i));
        table.y_refs.push_back(at(i + 1));
      }
      return table;
    }
    const std::string shape = "the manual's sequence: blank, x, y, x, y, ..., 1.0E10";
    const Word* first = data->at(1);
    if (first != nullptr && first->given && first->number != 0.0) {
      fail(at(1), "word 1 of the table must be blank (" + shape + "), got " +
                      deck_detail::format_number(first->number) + ": are the pairs shifted by one word?");
    }
    for (int i = 2;; i += 2) {
      if (i > size) {
        fail(
            WordRef{block, stage, 0, {}, data->header},
            "table without its 1.0E10 terminator within the block's " + str(size) + " words (" + shape + ")");
      }
      const Word* x = data->at(i);
      if (!x->given) {
        fail(at(i), "word " + str(i) +
                        " not given: the table needs an abscissa or the 1.0E10 terminator here (" + shape +
                        ")");
      }
      if (x->number >= kTableEnd) break;
      if (i + 1 > size) {
        fail(at(i), "abscissa in the block's last word: no room for its ordinate and the 1.0E10 terminator");
      }
      const Word* y = data->at(i + 1);
      if (!y->given)
        fail(at(i + 1), "word " + str(i + 1) + " not given: the ordinate paired with word " + str(i));
      table.x.push_back(x->number);
      table.y.push_back(y->number);
      table.x_refs.push_back(at(i));
      table.y_refs.push_back(at(i + 1));
    }
    return table;
  }

  // [path] with the x and y arrays of a table block (nothing when the block is not punched; the
  // path is remembered so a missing table is put on its block).
  void table_section(const std::string& path, const BlockSet& set, int block, int stage, const char* x_key,
                     const char* y_key,
                     const std::vector<std::pair<std::string, std::pair<std::string, WordRef>>>& extra = {}) {
    const WordRef block_ref = ref_in(set, block, stage, 0);
    if (!block_given(set, block, stage) && extra.empty()) {
      remember(path, block_ref);
      return;
    }
    const ParsedTable table = parse_table(set, block, stage);
    table_header(path, block_ref);
    for (const auto& [key, literal] : extra) scalar(path, key, literal.first, literal.second);
    if (!block_given(set, block, stage)) return;
    numbers(path, x_key, table.x, table.x_refs, block_ref);
    numbers(path, y_key, table.y, table.y_refs, block_ref);
  }

  // The described fields (field_description.hpp) of a TOML section, not stage-coded.
  static std::vector<const deck_detail::FieldDescription*> fields_of(const std::string& section) {
    std::vector<const deck_detail::FieldDescription*> fields;
    for (const deck_detail::FieldDescription& field : deck_detail::field_descriptions()) {
      if (field.stage_coding == deck_detail::StageCoding::kNone && section == field.section)
        fields.push_back(&field);
    }
    return fields;
  }

  // The words of a TOML section's described fields, when any of them is punched.
  void scalar_section(const std::string& section, const BlockSet& set, bool always = false) {
    bool any = always;
    WordRef section_ref;
    for (const deck_detail::FieldDescription* field : fields_of(section)) {
      for (int i = 0; i < field->count; ++i)
        any = any || given(set, field->block, 0, field->word + i) != nullptr;
      if (section_ref.block == 0 || (!section_ref.header.known() && block_given(set, field->block))) {
        section_ref = ref_in(set, field->block, 0, 0);
      }
    }
    if (!any) {
      remember(section, section_ref);
      for (const deck_detail::FieldDescription* field : fields_of(section)) {
        remember(section + "." + field->key, ref_in(set, field->block, 0, field->word));
      }
      return;
    }
    table_header(section, section_ref, false, section == "launch" ? "blocks 20, 21 (and 15 word 2)" : "");
    scalar_words(section, set);
  }

  // One described field of stage `code` (0: not stage-coded): a scalar, or an array whose words
  // not punched take their default; nothing (the key path remembered) when no word is punched.
  void field_words(const std::string& section, const deck_detail::FieldDescription& field,
                   const BlockSet& set, int code) {
    const int stage = deck_detail::card_stage(field, code);
    const int first = deck_detail::card_word(field, code);
    const WordRef key_ref = ref_in(set, field.block, stage, first);
    if (field.count == 1) {
      if (const Word* word = given(set, field.block, stage, first)) {
        scalar(section, field.key, field.integer ? toml_integer(word->number) : toml_number(word->number),
               key_ref);
      } else {
        remember(section + "." + field.key, key_ref);
      }
      return;
    }
    bool punched = false;
    std::vector<double> values;
    std::vector<WordRef> refs;
    for (int i = 0; i < field.count; ++i) {
      const Word* word = given(set, field.block, stage, first + i);
      punched = punched || word != nullptr;
      values.push_back(word != nullptr ? word->number : deck_detail::default_deck_value(field, code, i));
      refs.push_back(ref_in(set, field.block, stage, first + i));
    }
    if (punched) {
      numbers(section, field.key, values, refs, key_ref, field.integer);
    } else {
      remember(section + "." + field.key, key_ref);
    }
  }

  void scalar_words(const std::string& section, const BlockSet& set) {
    for (const deck_detail::FieldDescription* field : fields_of(section))
      field_words(section, *field, set, 0);
  }

  // ---- data blocks 1-40 -------------------------------------------------------------------------
  void case_section() {
    table_header("case", ref_in(opt(), 1, 0, 0), false, "blocks 1-3");
    scalar("case", "title", toml_string(text_of(find_data(opt(), 1), 12)), ref_in(opt(), 1, 0, 1));
    if (block_given(opt(), 2)) {
      scalar("case", "heading", toml_string(text_of(find_data(opt(), 2), 12)), ref_in(opt(), 2, 0, 1));
    }
    if (block_given(opt(), 3)) {
      scalar("case", "date", toml_string(text_of(find_data(opt(), 3), 2)), ref_in(opt(), 3, 0, 1));
    }
  }

  void options_section() {
    if (!block_given(opt(), 4)) {
      remember("options", ref_in(opt(), 4, 0, 0));
      return;
    }
    table_header("options", ref_in(opt(), 4, 0, 0));
    scalar_words("options", opt());
  }

  void atmosphere_section() {
    bool any = false;
    for (int block = 11; block <= 14; ++block) any = any || block_given(opt(), block);
    if (!any) return;
    table_header("atmosphere", ref_in(opt(), 11, 0, 0), false, "blocks 11-14");
    for (const deck_detail::FieldDescription* field : fields_of("atmosphere")) {
      if (!block_given(opt(), field->block)) continue;
      if (!located_) {
        comment("block " + str(field->block) + " (" + find_block(field->block)->title +
                "); words not punched keep the nominal value");
      }
      field_words("atmosphere", *field, opt(), 0);
    }
  }

  std::vector<int> sequence() const {
    std::vector<int> codes;
    for (int w = 1; w <= 11; ++w) {
      const Word* word = given(opt(), 5, 0, w);
      if (word == nullptr || word->number == 0.0) break;
      codes.push_back(static_cast<int>(word->number));
    }
    return codes;
  }

  void vehicle_section() {
    table_header("vehicle", ref_in(opt(), 5, 0, 0), false, "block 5 and the payload (block 15 word 1)");
    if (block_given(opt(), 5)) {
      const std::vector<int> codes = sequence();
      std::vector<double> values(codes.begin(), codes.end());
      std::vector<WordRef> refs;
      for (std::size_t k = 0; k < codes.size(); ++k)
        refs.push_back(ref_in(opt(), 5, 0, static_cast<int>(k) + 1));
      numbers("vehicle", "sequence", values, refs, ref_in(opt(), 5, 0, 1), true);
    } else {
      remember("vehicle.sequence", ref_in(opt(), 5, 0, 1));
    }
    const Word* payload = given(opt(), 15, 0, 1);
    scalar("vehicle", "payload_lb", toml_number(payload != nullptr ? payload->number : 0.0),
           ref_in(opt(), 15, 0, 1));
    if (block_given(opt(), 32)) {
      table_section("vehicle.lift_curve_slope", opt(), 32, 0, "mach", "cl_alpha_per_rad");
      if (const Word* word = given(opt(), 15, 0, 3)) {
        const WordRef ref = ref_in(opt(), 15, 0, 3);
        std::vector<std::string> stages;
        if (word->number == 1.0) stages = {"1"};
        else if (word->number == 6.0) stages = {"6"};
        else if (word->number == 16.0) stages = {"1", "6"};
        else if (word->number != 0.0) {
          fail(ref,
               "the stages using the lift table (block 15 word 3, an extension) are coded 0 none, 1 stage 1, "
               "6 coast 6, 16 both; got " +
                   deck_detail::format_number(word->number));
        }
        array("vehicle.lift_curve_slope", "used_in_stages", stages, std::vector<WordRef>(stages.size(), ref),
              ref);
      }
    } else {
      remember("vehicle.lift_curve_slope", ref_in(opt(), 32, 0, 0));
    }
  }

  void stage_sections() {
    const std::vector<int> codes = sequence();
    remember("stage", ref_in(opt(), 16, 0, 0));
    for (int code = 1; code <= kMaxStages; ++code) {
      bool in_sequence = false;
      for (int c : codes) in_sequence = in_sequence || c == code;
      const bool powered = code <= kMaxPoweredStages;
      bool any = in_sequence || block_given(opt(), 39, code) || block_given(opt(), 31, code);
      if (powered) any = any || block_given(opt(), 30, code) || block_given(opt(), 38, code);
      for (int w : {2 * code - 1, 2 * code}) {
        if (const Word* word = given(opt(), 16, 0, w)) any = any || word->number != 0.0;
      }
      const std::string path = "stage." + str(code);
      if (!any) {
        remember(path, ref_in(opt(), 16, 0, 2 * code - 1));
        continue;
      }
      table_header(path, ref_in(opt(), 16, 0, 0), false,
                   (powered ? "powered stage " : "coast ") + str(code) + ": blocks 16, 39" +
                       (powered ? ", 30, 38" : "") + (block_given(opt(), 31, code) ? ", 31" : ""));
      for (const deck_detail::FieldDescription& field : deck_detail::field_descriptions()) {
        if (field.stage_coding == deck_detail::StageCoding::kNone ||
            !deck_detail::applies_to_stage(field, code))
          continue;
        field_words(path, field, opt(), code);
      }
      if (powered) {
        table_section(path + ".thrust", opt(), 30, code, "time_s", "vacuum_thrust_lbf");
        table_section(path + ".consumable_weight", opt(), 38, code, "time_s", "remaining_lb");
      }
      table_section(path + ".drag", opt(), 31, code, "mach", "cd");  // any stage (data block 31)
    }
  }

  void constraint_sections() {
    const WordRef count_ref = ref_in(opt(), 8, 0, 1);
    remember("constraint", count_ref);
    if (!block_given(opt(), 8)) return;
    const Word* count_word = given(opt(), 8, 0, 1);
    if (count_word == nullptr)
      fail(count_ref, "IB3(1), the number of constraints (the payoff included), not given");
    const int count = static_cast<int>(count_word->number);
    if (count < 0 || count > kMaxConstraints) {
      fail(count_ref, "IB3(1) = " + str(count) +
                          " constraints: expected 1-13, the payoff included (data block 8 "
                          "holds the count and at most 13 codes)");
    }
    const bool heating = value_of(given(opt(), 4, 0, 2)) == 1.0;
    const int entries = count + (heating && count > 0 ? 1 : 0);
    if (entries + 1 > 14) {
      fail(count_ref, "IP(2) = 1 needs the heating code 14 after the " + str(count) +
                          " constraint codes, in word " + str(count + 2) +
                          ", beyond data block 8's 14 words");
    }
    for (int e = 0; e < entries; ++e) {
      const std::string path = "constraint[" + str(e) + "]";
      const WordRef code_ref = ref_in(opt(), 8, 0, e + 2);
      const Word* code_word = given(opt(), 8, 0, e + 2);
      if (code_word == nullptr) {
        fail(code_ref, "word " + str(e + 2) + " not given: IB3(1) = " + str(count) +
                           (e == count ? " and IP(2) = 1 need the heating code 14 here"
                                       : " needs a constraint code here"));
      }
      blank();
      line(located_ ? "[[constraint]]" : "[[constraint]]  # " + note(code_ref), code_ref);
      remember(path, code_ref);
      const int code = static_cast<int>(code_word->number);
      scalar(path, "code", toml_integer(code_word->number), code_ref);
      deck_detail::ConstraintUnit unit{};
      if (!deck_detail::constraint_unit(code, &unit)) continue;  // the TOML reader names the bad code
      const bool angle = std::string(unit.suffix) == "deg";
      auto value = [&](int block, int word, const std::string& key) {
        const std::string name = key + "_" + unit.suffix;
        const WordRef ref = ref_in(opt(), block, 0, word);
        if (const Word* found = given(opt(), block, 0, word)) {
          scalar(path, name, toml_number(angle ? found->number * kRadToDeg : found->number), ref);
        } else {
          remember(path + "." + name, ref);
        }
      };
      value(19, e + 1, "desired");
      if (e >= 1) {
        value(29, e, "deadband_optimization");
        value(29, e + 13, "deadband_linearization");
      }
    }
  }

  void adjustable_sections() {
    const WordRef count_ref = ref_in(opt(), 6, 0, 1);
    remember("adjustable_parameter", count_ref);
    if (!block_given(opt(), 6)) return;
    const Word* count_word = given(opt(), 6, 0, 1);
    if (count_word == nullptr) fail(count_ref, "IB1(1), the number of adjustable parameters, not given");
    const int count = static_cast<int>(count_word->number);
    if (count < 0 || count > kMaxAdjustableParameters) {
      fail(count_ref,
           "IB1(1) = " + str(count) + " adjustable parameters: expected 0-11 (codes in words 2-12)");
    }
    // Data block 27 is by code number (Sec. 22: DA12(1)-DA12(11) "for adjustable parameters
    // identified by code number as listed for Data Block 6"; the nomenclature's ST2(23)-(25) =
    // DA12(3)-(5) and ST2(30)-(31) = DA12(10)-(11) are the coast codes): word k weights code k, and
    // the words of unselected codes are blank or zero.
    bool selected[kMaxAdjustableParameters + 1] = {};
    for (int i = 0; i < count; ++i) {
      const std::string path = "adjustable_parameter[" + str(i) + "]";
      const WordRef code_ref = ref_in(opt(), 6, 0, i + 2);
      const Word* code_word = given(opt(), 6, 0, i + 2);
      if (code_word == nullptr) {
        fail(code_ref,
             "word " + str(i + 2) + " not given: IB1(1) = " + str(count) + " needs a parameter code here");
      }
      const double code_value = code_word->number;
      if (!(code_value >= 1.0 && code_value <= kMaxAdjustableParameters) ||
          code_value != std::floor(code_value)) {
        fail(code_ref, "IB1(" + str(i + 2) + ") = " + deck_detail::format_number(code_value) +
                           ": an adjustable parameter code is a whole number 1-11 (Sec. 22, data block 6)");
      }
      const int code = static_cast<int>(code_value);
      if (selected[code])
        fail(code_ref, "IB1(" + str(i + 2) + ") = " + str(code) + ": code selected twice in data block 6");
      selected[code] = true;
      blank();
      line(located_ ? "[[adjustable_parameter]]" : "[[adjustable_parameter]]  # " + note(code_ref), code_ref);
      remember(path, code_ref);
      scalar(path, "code", toml_integer(code_value), code_ref);
      const WordRef weight_ref = ref_in(opt(), 27, 0, code);
      if (const Word* weight = given(opt(), 27, 0, code)) {
        scalar(path, "weight", toml_number(weight->number), weight_ref);
      } else {
        remember(path + ".weight", weight_ref);
      }
    }
    for (int code = 1; code <= kMaxAdjustableParameters; ++code) {
      const Word* weight = given(opt(), 27, 0, code);
      if (selected[code] || weight == nullptr || weight->number == 0.0) continue;
      fail(ref_in(opt(), 27, 0, code),
           "DA12(" + str(code) + ") = " + deck_detail::format_number(weight->number) +
               " weights adjustable parameter code " + str(code) +
               ", which data block 6 does not select: block 27 words are by code number (Sec. 22: word k "
               "weights code k; the words of unselected codes are blank or zero). Decks written by tolip "
               "0.1.0's convert "
               "put the weights in block 6's order instead: move each weight to the word of its code");
    }
  }

  void linearization_section() {
    remember("linearization", ref_in(opt(), 18, 0, 1));
    if (!block_given(opt(), 18)) return;
    const WordRef count_ref = ref_in(opt(), 18, 0, 1);
    const Word* count_word = given(opt(), 18, 0, 1);
    const double count_value = value_of(count_word);
    if (count_word == nullptr || count_value != std::floor(count_value) || count_value < 0.0 ||
        count_value > kMaxLinearSegments) {
      fail(count_ref,
           "TLIN(1), the number of linear segments, must be a whole number 1-15; got " +
               (count_word == nullptr ? std::string("nothing") : deck_detail::format_number(count_value)));
    }
    const int segments = static_cast<int>(count_value);
    table_header("linearization", ref_in(opt(), 18, 0, 0), false, "blocks 18 (TLIN) and 26 (ETALIN)");
    scalar("linearization", "segment_count", toml_integer(count_value), count_ref);
    std::vector<double> times;
    std::vector<WordRef> refs;
    for (int w = 2; w <= segments + 2; ++w) {
      const WordRef ref = ref_in(opt(), 18, 0, w);
      const Word* word = given(opt(), 18, 0, w);
      if (word == nullptr) {
        fail(ref, "word " + str(w) + " not given: TLIN(1) = " + str(segments) + " segments need " +
                      str(segments + 1) + " coded times in words 2-" + str(segments + 2));
      }
      times.push_back(word->number);
      refs.push_back(ref);
    }
    numbers("linearization", "coded_times", times, refs, ref_in(opt(), 18, 0, 2));
    if (block_given(opt(), 26)) {
      std::vector<double> weights;
      std::vector<WordRef> weight_refs;
      for (int w = 1; w <= segments; ++w) {
        const Word* word = given(opt(), 26, 0, w);
        weights.push_back(word != nullptr ? word->number : 1.0);
        weight_refs.push_back(ref_in(opt(), 26, 0, w));
      }
      numbers("linearization", "segment_weights", weights, weight_refs, ref_in(opt(), 26, 0, 1));
    }
  }

  void output_frequency_section() {
    remember("output_frequency", ref_in(opt(), 9, 0, 0));
    if (!block_given(opt(), 9)) return;
    static const char* const kKeys[3] = {"initial", "intermediate", "final"};
    std::vector<double> values[3];
    std::vector<WordRef> refs[3];
    for (int k = 0; k < 3; ++k) {
      values[k].assign(kMaxStages, 1.0);
      refs[k].assign(kMaxStages, ref_in(opt(), 9, 0, 0));
    }
    for (int g = 0; g < 10; ++g) {
      const WordRef code_ref = ref_in(opt(), 9, 0, 4 * g + 4);
      const double code = value_of(given(opt(), 9, 0, 4 * g + 4));
      if (code == 0.0) {
        for (int k = 0; k < 3; ++k) {
          if (value_of(given(opt(), 9, 0, 4 * g + 1 + k)) != 0.0) {
            fail(ref_in(opt(), 9, 0, 4 * g + 1 + k),
                 "IB4(" + str(4 * g + 1) + "-" + str(4 * g + 3) + ") give output frequencies but IB4(" +
                     str(4 * g + 4) + "), the stage code they apply to, is blank");
          }
        }
        continue;
      }
      if (code < 1.0 || code > 10.0) {
        fail(code_ref, "IB4(" + str(4 * g + 4) + ") = " + deck_detail::format_number(code) +
                           ": expected the stage code (1-10) the group's three frequencies apply to");
      }
      const int stage = static_cast<int>(code);
      // A stage code in two groups would drop the first group's frequencies silently.
      for (int h = 0; h < g; ++h) {
        if (value_of(given(opt(), 9, 0, 4 * h + 4)) == code) {
          fail(code_ref, "IB4(" + str(4 * g + 4) + ") = " + str(stage) + ": stage code " + str(stage) +
                             " already has its frequencies in IB4(" + str(4 * h + 1) + "-" + str(4 * h + 3) +
                             "); expected each stage code once");
        }
      }
      for (int k = 0; k < 3; ++k) {
        const Word* word = given(opt(), 9, 0, 4 * g + 1 + k);
        if (word == nullptr) continue;
        if (word->number < 1.0) {
          fail(ref_in(opt(), 9, 0, 4 * g + 1 + k),
               "output frequency must be at least 1 (every computed point), got " +
                   deck_detail::format_number(word->number));
        }
        values[k][static_cast<std::size_t>(stage - 1)] = word->number;
        refs[k][static_cast<std::size_t>(stage - 1)] = ref_in(opt(), 9, 0, 4 * g + 1 + k);
      }
    }
    table_header("output_frequency", ref_in(opt(), 9, 0, 0), false, "block 9, by stage code 1-10");
    for (int k = 0; k < 3; ++k)
      numbers("output_frequency", kKeys[k], values[k], refs[k], ref_in(opt(), 9, 0, 0), true);
  }

  void pitch_program_section() { table_section("pitch_program", opt(), 40, 0, "time_s", "theta_deg"); }

  // ---- data blocks 33-37, 41-55 -----------------------------------------------------------------
  void body_dynamics_sections() {
    const BlockSet& body = body_;
    bool any = false;
    for (const auto& [key, data] : body) any = any || data.any_given();
    remember("body_dynamics", ref_in(body, 33, 0, 0));
    if (!any) return;
    table_header("body_dynamics", ref_in(body, 33, 0, 0), false, "blocks 33-37 (6D), DA6D");
    scalar_words("body_dynamics", body);
    table_section("body_dynamics.fin_normal_force", body, 34, 0, "mach", "cn_delta_per_rad_per_fin");
    table_section("body_dynamics.pitching_moment", body, 35, 0, "mach", "cm_alpha_per_rad");
    table_section("body_dynamics.fin_pitching_moment", body, 36, 0, "mach", "cm_delta_per_rad_per_fin");
    for (int stage = 1; stage <= 4; ++stage) {
      table_section("body_dynamics.cg." + str(stage), body, 37, stage, "stage_time_s", "station_in");
    }
  }

  void radar_sections() {
    remember("radar_station", WordRef{41, 0, 0, {}, {}});
    for (std::size_t i = 0; i < case_.radar.size(); ++i) {
      const BlockData& station = case_.radar[i];
      const std::string path = "radar_station[" + str(static_cast<int>(i)) + "]";
      auto at = [&station](int w) {
        WordRef ref{41, 0, w, station.words[static_cast<std::size_t>(w - 1)].origin, station.header};
        return ref;
      };
      blank();
      line(located_ ? "[[radar_station]]" : "[[radar_station]]  # block 41", at(1));
      remember(path, at(1));
      scalar(path, "id", toml_string(trim(station.words[0].text)), at(1));
      const std::string name = trim(station.words[4].text);
      if (!name.empty()) scalar(path, "name", toml_string(name), at(5));
      scalar(path, "geodetic_latitude_deg", toml_number(station.words[1].number), at(2));
      scalar(path, "longitude_deg", toml_number(station.words[2].number), at(3));
      scalar(path, "altitude_ft", toml_number(station.words[3].number), at(4));
    }
  }

  void impact_sections() {
    const BlockSet& set = case_.impact;
    remember("impact", ref_in(set, 42, 1, 0));
    bool any = false;
    for (const auto& [key, data] : set) any = any || (key.block != 33 && data.any_given());
    if (!case_.impact_group || !any) return;
    table_header("impact", ref_in(set, 42, 1, 0), false, "blocks 42, 43 and the extension block 23");
    const struct {
      const char* group;
      int block;
    } groups[] = {{"failure_drag", 42}, {"casing_drag", 43}};
    for (const auto& group : groups) {
      remember(std::string("impact.") + group.group, ref_in(set, group.block, 1, 0));
      for (int stage = 1; stage <= 3; ++stage) {
        std::vector<std::pair<std::string, std::pair<std::string, WordRef>>> extra;
        auto add = [&](int word, const char* key) {
          if (const Word* found = given(set, 23, stage, word)) {
            extra.push_back({key, {toml_number(found->number), ref_in(set, 23, stage, word)}});
          }
        };
        add(group.block == 42 ? 1 : 2, "reference_area_ft2");
        if (group.block == 43) add(3, "casing_weight_lb");
        table_section(std::string("impact.") + group.group + "." + str(stage), set, group.block, stage,
                      "mach", "cd", extra);
      }
    }
  }

  void hardover_sections() {
    const BlockSet& set = case_.hardover;
    remember("hardover", ref_in(set, 44, 1, 0));
    bool any = false;
    for (const auto& [key, data] : set)
      any = any || ((key.block == 44 || key.block == 45) && data.any_given());
    if (!case_.hardover_group || !any) return;
    remember("hardover.pitch_inertia", ref_in(set, 44, 1, 0));
    for (int stage = 1; stage <= 3; ++stage) {
      table_section("hardover.pitch_inertia." + str(stage), set, 44, stage, "stage_time_s", "iyy_slug_ft2");
    }
    table_section("hardover.pitch_damping", set, 44, 4, "mach", "cmq_per_rad");
    if (block_given(set, 45)) {
      table_header("hardover.parameters", ref_in(set, 45, 0, 0));
      scalar_words("hardover.parameters", set);
    } else {
      remember("hardover.parameters", ref_in(set, 45, 0, 0));
    }
  }

  void dispersion_sections() {
    remember("dispersion", WordRef{46, 0, 0, {}, {}});
    for (std::size_t i = 0; i < case_.dispersions.size(); ++i) {
      const Dispersion& d = case_.dispersions[i];
      const std::string path = "dispersion[" + str(static_cast<int>(i)) + "]";
      const WordRef code_ref{46, d.code, 0, d.header, d.header};
      blank();
      line(located_ ? "[[dispersion]]"
                    : "[[dispersion]]  # block 46 code " + str(d.code) + ": " +
                          deck_detail::dispersion_name(d.code),
           code_ref);
      remember(path, code_ref);
      scalar(path, "code", str(d.code), code_ref);
      const std::string title = trim(text_of(&d.title, 2));
      if (!title.empty()) {
        WordRef title_ref{46, d.code, 1, d.title.words.empty() ? Origin{} : d.title.words[0].origin,
                          d.header};
        scalar(path, "title", toml_string(title), title_ref);
      }
      const BlockSet& set = d.blocks;
      auto ref = [&](int block, int stage, int word) {
        WordRef r = ref_in(set, block, stage, word);
        if (!r.header.known()) r.header = d.header;
        return r;
      };
      auto value = [&](int block, int stage, int word, const char* key) {
        if (const Word* found = given(set, block, stage, word)) {
          scalar(path, key, toml_number(found->number), ref(block, stage, word));
        } else {
          remember(path + "." + key, ref(block, stage, word));
        }
      };
      auto sub_table = [&](const char* key, int block, int stage, const char* x_key, const char* y_key) {
        const std::string sub = path + "." + key;
        if (!block_given(set, block, stage)) {
          remember(sub, ref(block, stage, 0));
          return;
        }
        const ParsedTable table = parse_table(set, block, stage);
        const WordRef block_ref = ref(block, stage, 0);
        blank();
        line(located_ ? "[dispersion." + std::string(key) + "]"
                      : "[dispersion." + std::string(key) + "]  # block " + str(block) +
                            (stage > 0 ? " stage " + str(stage) : std::string()),
             block_ref);
        remember(sub, block_ref);
        numbers(sub, x_key, table.x, table.x_refs, block_ref);
        numbers(sub, y_key, table.y, table.y_refs, block_ref);
      };
      const int code = d.code;
      const deck_detail::DispersionCodes* codes = deck_detail::find_dispersion(code);
      if (codes == nullptr) continue;  // the TOML reader names the unknown code
      int stage = codes->stage_of(code);
      if (stage <
          0) {  // the tip-off (51), thrust 7-8 (30) and weight 15-16 (47): stage 4 or 5, as the cards give it
        const int block = codes->items.front().block;
        const bool four = block_given(set, block, 4);
        const bool five = block_given(set, block, 5);
        if (four && five) {
          fail(ref(block, 5, 0), "dispersion code " + str(code) + ": data block " + str(block) +
                                     " given for stage codes 4 and 5; expected one stage");
        }
        stage = five ? 5 : 4;
        // The tip-off always names its stage; the others only stage 5 (4 is their default).
        if ((four && block == 51) || five) scalar(path, "stage", str(stage), ref(block, stage, 0));
      }
      // The words first: after a sub-table header a TOML key would belong to the sub-table.
      for (const deck_detail::DispersionItem& item : codes->items) {
        const int item_stage = deck_detail::dispersion_stage(code, item.block) == 0 ? 0 : stage;
        if (item.word == 0) continue;
        if (item.count == 1) {
          value(item.block, item_stage, item.word, item.key);
        } else if (block_given(set, item.block)) {
          std::vector<double> values;
          std::vector<WordRef> refs;
          for (int w = item.word; w < item.word + item.count; ++w) {
            values.push_back(value_of(given(set, item.block, item_stage, w)));
            refs.push_back(ref(item.block, item_stage, w));
          }
          numbers(path, item.key, values, refs, ref(item.block, item_stage, item.word));
        }
      }
      for (const deck_detail::DispersionItem& item : codes->items) {
        const int item_stage = deck_detail::dispersion_stage(code, item.block) == 0 ? 0 : stage;
        if (item.word == 0) sub_table(item.key, item.block, item_stage, item.x_key, item.y_key);
      }
    }
  }

  const CardCase& case_;
  std::string path_;
  bool located_;
  BlockSet body_;
  TomlDeck out_;
};

}  // namespace

TomlDeck card_case_to_toml(const CardCase& card_case, const std::string& path, bool located) {
  Builder builder(card_case, path, located);
  return builder.build();
}

}  // namespace tolip::ground::card_detail
