// From a TOML deck to words, and from words to card images (card_internal.hpp).
//
// card_case_from_toml() is the inverse of card_case_to_toml(): every TOML key goes back to the
// word it came from, in the card's units (block 19/29 angles back to radians). The TOML deck must
// have passed the TOML reader (parse_toml_deck), so every value has its expected type.
// write_card_images() punches the words: header cards (4I3, the block title as a comment from
// column 13), data cards (12A6, 24I1, 24 I3 fields, 6 E12.8 fields per card), a blank card after
// each case and each optional group, and the 999 card.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "card_internal.hpp"
#include "deck_common.hpp"
#include "toml_reader.hpp"

namespace tolip::ground::card_detail {
namespace {

std::string str(int value) { return std::to_string(value); }

// ---- TOML -> words ------------------------------------------------------------------------------

double number_of(const toml::node* node) {
  if (node == nullptr) return 0.0;
  if (const auto* integer = node->as_integer()) return static_cast<double>(integer->get());
  if (const auto* floating = node->as_floating_point()) return floating->get();
  if (const auto* boolean = node->as_boolean()) return boolean->get() ? 1.0 : 0.0;
  return 0.0;
}

std::vector<double> numbers_of(const toml::node* node) {
  std::vector<double> values;
  if (node == nullptr) return values;
  if (const toml::array* array = node->as_array()) {
    for (std::size_t i = 0; i < array->size(); ++i) values.push_back(number_of(array->get(i)));
  } else {
    values.push_back(number_of(node));
  }
  return values;
}

const toml::table* table_of(const toml::node* node) { return node != nullptr ? node->as_table() : nullptr; }

// A table by dotted path ("hardover.parameters").
const toml::table* find_table(const toml::table& root, const std::string& path) {
  const toml::table* table = &root;
  std::size_t start = 0;
  while (table != nullptr && start <= path.size()) {
    const std::size_t dot = path.find('.', start);
    const std::string part = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    table = table_of(table->get(part));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return table;
}

class FromToml {
 public:
  explicit FromToml(const toml::table& root) : root_(root) {}

  CardCase build() {
    result_.number = 1;
    case_words();
    options();
    scalars();
    vehicle();
    stages();
    constraints();
    adjustable();
    linearization();
    output_frequency();
    table(&result_.optimization, 40, 0, find_table(root_, "pitch_program"), "time_s", "theta_deg");
    body_dynamics();
    radar();
    impact();
    hardover();
    dispersions();
    const auto ip = [this](int n) { return value_of(find_word(result_.optimization, 4, 0, n)) == 1.0; };
    result_.dispersion_group = ip(21);
    result_.hardover_group = ip(22);
    result_.impact_group = ip(23);
    result_.radar_group = ip(24);
    return std::move(result_);
  }

 private:
  static Word& slot(BlockSet* set, int block, int stage, int word) {
    BlockData& data = (*set)[BlockKey{block, stage}];
    const BlockSpec* spec = find_block(block);
    const std::size_t size = static_cast<std::size_t>(spec != nullptr ? block_size(*spec, stage) : word);
    if (data.words.size() < size) data.words.resize(size);
    if (data.words.size() < static_cast<std::size_t>(word)) data.words.resize(static_cast<std::size_t>(word));
    return data.words[static_cast<std::size_t>(word - 1)];
  }
  static void set(BlockSet* set, int block, int stage, int word, double value) {
    Word& target = slot(set, block, stage, word);
    target.given = true;
    target.number = value;
  }
  static void set_text(BlockSet* set, int block, int stage, int first_word, int words,
                       const std::string& text) {
    for (int w = 0; w < words; ++w) {
      Word& target = slot(set, block, stage, first_word + w);
      target.given = true;
      target.text = text.size() > static_cast<std::size_t>(6 * w)
                        ? text.substr(static_cast<std::size_t>(6 * w), 6)
                        : "";
      target.text.resize(6, ' ');
    }
  }
  static std::string text_of(const toml::table* table, const char* key) {
    if (table == nullptr) return "";
    const toml::node* node = table->get(key);
    if (node == nullptr || node->as_string() == nullptr) return "";
    return node->as_string()->get();
  }

  // A table block: kTable (blank, x, y, ..., 1.0E10) or kPairs (x, y, ...).
  static void table(BlockSet* target, int block, int stage, const toml::table* source, const char* x_key,
                    const char* y_key) {
    if (source == nullptr) return;
    const std::vector<double> x = numbers_of(source->get(x_key));
    const std::vector<double> y = numbers_of(source->get(y_key));
    const BlockSpec* spec = find_block(block);
    const bool pairs = spec != nullptr && spec->shape == Shape::kPairs;
    int word = 1;
    if (!pairs) set(target, block, stage, word++, 0.0);
    for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
      set(target, block, stage, word++, x[i]);
      set(target, block, stage, word++, y[i]);
    }
    if (!pairs) set(target, block, stage, word, kTableEnd);
  }

  BlockSet* opt() { return &result_.optimization; }

  void case_words() {
    const toml::table* section = find_table(root_, "case");
    set_text(opt(), 1, 0, 1, 12, text_of(section, "title"));
    if (section != nullptr && section->get("heading") != nullptr)
      set_text(opt(), 2, 0, 1, 12, text_of(section, "heading"));
    if (section != nullptr && section->get("date") != nullptr)
      set_text(opt(), 3, 0, 1, 2, text_of(section, "date"));
  }

  // Every described field of one TOML table (field_description.hpp) into its words; stage
  // fields with their stage code.
  void fields(BlockSet* target, const toml::table* section, const std::string& section_path, int code = 0) {
    if (section == nullptr) return;
    for (const deck_detail::FieldDescription& field : deck_detail::field_descriptions()) {
      if ((field.stage_coding == deck_detail::StageCoding::kNone) != (code == 0)) continue;
      if (!deck_detail::applies_to_stage(field, code) || deck_detail::section_of(field, code) != section_path)
        continue;
      const std::vector<double> values = numbers_of(section->get(field.key));
      for (std::size_t i = 0; i < values.size() && i < static_cast<std::size_t>(field.count); ++i) {
        const int index = static_cast<int>(i);
        set(target, field.block, deck_detail::card_stage(field, code),
            deck_detail::card_word(field, code, index), values[i]);
      }
    }
  }

  void options() {
    const toml::table* section = find_table(root_, "options");
    if (section == nullptr) return;
    for (int ip = 1; ip <= 24; ++ip)
      set(opt(), 4, 0, ip, 0.0);  // block 4 is punched whole: unused IP words 0
    fields(opt(), section, "options");
  }

  void scalars() {
    for (const char* name :
         {"constants", "atmosphere", "launch", "control_constraints", "misc", "convergence"}) {
      fields(opt(), find_table(root_, name), name);
    }
  }

  void vehicle() {
    const toml::table* section = find_table(root_, "vehicle");
    if (section == nullptr) return;
    std::vector<double> codes = numbers_of(section->get("sequence"));
    if (!codes.empty() && codes.back() == 0.0) codes.pop_back();
    for (std::size_t i = 0; i < codes.size(); ++i) set(opt(), 5, 0, static_cast<int>(i) + 1, codes[i]);
    if (codes.size() < 11) set(opt(), 5, 0, static_cast<int>(codes.size()) + 1, 0.0);
    const double payload = number_of(section->get("payload_lb"));
    if (payload != 0.0) set(opt(), 15, 0, 1, payload);
    if (const toml::table* lift = table_of(section->get("lift_curve_slope"))) {
      table(opt(), 32, 0, lift, "mach", "cl_alpha_per_rad");
      if (lift->get("used_in_stages") != nullptr) {
        bool one = false;
        bool six = false;
        for (double code : numbers_of(lift->get("used_in_stages"))) {
          one = one || code == 1.0;
          six = six || code == 6.0;
        }
        set(opt(), 15, 0, 3, one && six ? 16.0 : one ? 1.0 : six ? 6.0 : 0.0);
      }
    }
  }

  void stages() {
    const toml::table* section = find_table(root_, "stage");
    if (section == nullptr) return;
    for (int code = 1; code <= kMaxStages; ++code) {
      const toml::table* stage = table_of(section->get(str(code)));
      if (stage == nullptr) continue;
      fields(opt(), stage, "stage." + str(code), code);
      table(opt(), 30, code, table_of(stage->get("thrust")), "time_s", "vacuum_thrust_lbf");
      table(opt(), 38, code, table_of(stage->get("consumable_weight")), "time_s", "remaining_lb");
      table(opt(), 31, code, table_of(stage->get("drag")), "mach", "cd");
    }
  }

  void constraints() {
    const toml::node* node = root_.get("constraint");
    const toml::array* entries = node != nullptr ? node->as_array() : nullptr;
    if (entries == nullptr || entries->empty()) return;
    std::vector<const toml::table*> tables;
    for (std::size_t i = 0; i < entries->size(); ++i) tables.push_back(table_of(entries->get(i)));
    const auto code_of = [](const toml::table* entry) {
      return entry != nullptr ? static_cast<int>(number_of(entry->get("code"))) : 0;
    };
    const bool heating = tables.size() > 1 && code_of(tables.back()) == 14;
    set(opt(), 8, 0, 1, static_cast<double>(tables.size()) - (heating ? 1.0 : 0.0));
    for (std::size_t i = 0; i < tables.size(); ++i) {
      const int e = static_cast<int>(i);
      const int code = code_of(tables[i]);
      set(opt(), 8, 0, e + 2, code);
      deck_detail::ConstraintUnit unit{};
      if (tables[i] == nullptr || !deck_detail::constraint_unit(code, &unit)) continue;
      const bool angle = std::string(unit.suffix) == "deg";
      auto value = [&](int block, int word, const std::string& key) {
        if (const toml::node* found = tables[i]->get(key + "_" + unit.suffix)) {
          const double deck = number_of(found);
          set(opt(), block, 0, word, angle ? deck * kDegToRad : deck);
        }
      };
      value(19, e + 1, "desired");
      if (e >= 1) {
        value(29, e, "deadband_optimization");
        value(29, e + 13, "deadband_linearization");
      }
    }
  }

  void adjustable() {
    const toml::node* node = root_.get("adjustable_parameter");
    const toml::array* entries = node != nullptr ? node->as_array() : nullptr;
    if (entries == nullptr) return;
    set(opt(), 6, 0, 1, static_cast<double>(entries->size()));
    for (std::size_t i = 0; i < entries->size(); ++i) {
      const toml::table* entry = table_of(entries->get(i));
      if (entry == nullptr) continue;
      const double code = number_of(entry->get("code"));
      set(opt(), 6, 0, static_cast<int>(i) + 2, code);
      // Data block 27 by code number (Sec. 22): DA12(k) weights code k. A code the TOML reader
      // would reject has no word of its own; the read-back of the cards reports it.
      const toml::node* weight = entry->get("weight");
      if (weight != nullptr && code >= 1.0 && code <= kMaxAdjustableParameters && code == std::floor(code)) {
        set(opt(), 27, 0, static_cast<int>(code), number_of(weight));
      }
    }
  }

  void linearization() {
    const toml::table* section = find_table(root_, "linearization");
    if (section == nullptr) return;
    const std::vector<double> times = numbers_of(section->get("coded_times"));
    if (times.empty()) return;
    set(opt(), 18, 0, 1, static_cast<double>(times.size()) - 1.0);
    for (std::size_t i = 0; i < times.size(); ++i) set(opt(), 18, 0, static_cast<int>(i) + 2, times[i]);
    const std::vector<double> weights = numbers_of(section->get("segment_weights"));
    for (std::size_t i = 0; i < weights.size(); ++i) set(opt(), 26, 0, static_cast<int>(i) + 1, weights[i]);
  }

  void output_frequency() {
    const toml::table* section = find_table(root_, "output_frequency");
    if (section == nullptr) return;
    const char* const keys[3] = {"initial", "intermediate", "final"};
    for (int k = 0; k < 3; ++k) {
      const std::vector<double> values = numbers_of(section->get(keys[k]));
      for (int stage = 1; stage <= kMaxStages; ++stage) {
        double value = 1.0;
        if (values.size() == 1) value = values[0];
        if (values.size() == static_cast<std::size_t>(kMaxStages))
          value = values[static_cast<std::size_t>(stage - 1)];
        set(opt(), 9, 0, 4 * (stage - 1) + 1 + k, value);
        set(opt(), 9, 0, 4 * stage, stage);
      }
    }
  }

  void body_dynamics() {
    const toml::table* section = find_table(root_, "body_dynamics");
    if (section == nullptr) return;
    fields(opt(), section, "body_dynamics");
    if (find_data(result_.optimization, 33) == nullptr)
      result_.optimization[BlockKey{33, 0}].words.resize(20);
    table(opt(), 34, 0, table_of(section->get("fin_normal_force")), "mach", "cn_delta_per_rad_per_fin");
    table(opt(), 35, 0, table_of(section->get("pitching_moment")), "mach", "cm_alpha_per_rad");
    table(opt(), 36, 0, table_of(section->get("fin_pitching_moment")), "mach", "cm_delta_per_rad_per_fin");
    if (const toml::table* cg = table_of(section->get("cg"))) {
      for (int stage = 1; stage <= 4; ++stage) {
        table(opt(), 37, stage, table_of(cg->get(str(stage))), "stage_time_s", "station_in");
      }
    }
  }

  void radar() {
    const toml::node* node = root_.get("radar_station");
    const toml::array* entries = node != nullptr ? node->as_array() : nullptr;
    if (entries == nullptr) return;
    for (std::size_t i = 0; i < entries->size(); ++i) {
      const toml::table* entry = table_of(entries->get(i));
      if (entry == nullptr) continue;
      BlockData station;
      station.words.resize(5);
      for (Word& word : station.words) word.given = true;
      station.words[0].text = text_of(entry, "id");
      station.words[1].number = number_of(entry->get("geodetic_latitude_deg"));
      station.words[2].number = number_of(entry->get("longitude_deg"));
      station.words[3].number = number_of(entry->get("altitude_ft"));
      station.words[4].text = text_of(entry, "name");
      result_.radar.push_back(std::move(station));
    }
  }

  void impact() {
    const toml::table* section = find_table(root_, "impact");
    if (section == nullptr) return;
    const struct {
      const char* group;
      int block;
      int area_word;
    } groups[] = {{"failure_drag", 42, 1}, {"casing_drag", 43, 2}};
    for (const auto& group : groups) {
      const toml::table* tables = table_of(section->get(group.group));
      if (tables == nullptr) continue;
      for (int stage = 1; stage <= 3; ++stage) {
        const toml::table* entry = table_of(tables->get(str(stage)));
        if (entry == nullptr) continue;
        table(&result_.impact, group.block, stage, entry, "mach", "cd");
        if (const toml::node* area = entry->get("reference_area_ft2")) {
          set(&result_.impact, 23, stage, group.area_word, number_of(area));
        }
        if (const toml::node* weight = entry->get("casing_weight_lb"))
          set(&result_.impact, 23, stage, 3, number_of(weight));
      }
    }
  }

  void hardover() {
    const toml::table* section = find_table(root_, "hardover");
    if (section == nullptr) return;
    if (const toml::table* inertia = table_of(section->get("pitch_inertia"))) {
      for (int stage = 1; stage <= 3; ++stage) {
        table(&result_.hardover, 44, stage, table_of(inertia->get(str(stage))), "stage_time_s",
              "iyy_slug_ft2");
      }
    }
    table(&result_.hardover, 44, 4, table_of(section->get("pitch_damping")), "mach", "cmq_per_rad");
    fields(&result_.hardover, table_of(section->get("parameters")), "hardover.parameters");
  }

  void dispersions() {
    const toml::node* node = root_.get("dispersion");
    const toml::array* entries = node != nullptr ? node->as_array() : nullptr;
    if (entries == nullptr) return;
    for (std::size_t i = 0; i < entries->size(); ++i) {
      const toml::table* entry = table_of(entries->get(i));
      if (entry == nullptr) continue;
      Dispersion d;
      d.code = static_cast<int>(number_of(entry->get("code")));
      BlockSet title;
      set_text(&title, 46, 0, 1, 2, text_of(entry, "title"));
      d.title = title[BlockKey{46, 0}];
      BlockSet* set_ptr = &d.blocks;
      const int code = d.code;
      const deck_detail::DispersionCodes* codes = deck_detail::find_dispersion(code);
      if (codes != nullptr) {
        int stage = codes->stage_of(code);
        if (stage < 0) {  // the tip-off: stage 4 unless the deck says 5
          stage = entry->get("stage") != nullptr ? static_cast<int>(number_of(entry->get("stage"))) : 4;
        }
        for (const deck_detail::DispersionItem& item : codes->items) {
          const int item_stage = deck_detail::dispersion_stage(code, item.block) == 0 ? 0 : stage;
          if (item.word == 0) {
            table(set_ptr, item.block, item_stage, table_of(entry->get(item.key)), item.x_key, item.y_key);
            continue;
          }
          const std::vector<double> values = numbers_of(entry->get(item.key));
          for (std::size_t w = 0; w < values.size() && w < static_cast<std::size_t>(item.count); ++w) {
            set(set_ptr, item.block, item_stage, item.word + static_cast<int>(w), values[w]);
          }
        }
      }
      result_.dispersions.push_back(std::move(d));
    }
  }

  const toml::table& root_;
  CardCase result_;
};

// ---- words -> card images -----------------------------------------------------------------------

class Punch {
 public:
  explicit Punch(int* rounded) : rounded_(rounded) {}

  std::string take() { return std::move(out_); }

  void card(std::string text) {
    if (text.size() > static_cast<std::size_t>(kCardColumns)) text.resize(kCardColumns);
    while (!text.empty() && text.back() == ' ') text.pop_back();
    out_ += text;
    out_ += '\n';
  }
  void blank_card() { out_ += '\n'; }

  [[noreturn]] static void fail(int block, int stage, int word, const std::string& message) {
    CardFailure failure;
    failure.error.card_deck = true;
    failure.error.data_block = block;
    failure.error.stage_code = stage;
    failure.error.word = word;
    failure.error.message = message;
    throw failure;
  }

  std::string header(int block, int first, int last, int stage, const std::string& note) {
    // Room for three ints of any value (11 characters each): the check below keeps them to 3
    // columns, but GCC's -Wformat-truncation at -O2 (RelWithDebInfo) does not follow it.
    char buffer[36];
    for (int value : {block, first, last, stage}) {
      if (value < -99 || value > 999)
        fail(block, stage, 0, "a header field does not fit its 3 columns: " + str(value));
    }
    std::snprintf(buffer, sizeof buffer, "%3d%3d%3d", block, first, last);
    std::string text(buffer);
    if (stage != 0) {
      std::snprintf(buffer, sizeof buffer, "%3d", stage);
      text += buffer;
    } else {
      text += "   ";
    }
    if (!note.empty()) text += "  " + note;
    return text;
  }

  std::string field(const BlockSpec& spec, int stage, int word_number, const Word& word, bool blank_zero) {
    const int width = field_width(spec.format);
    switch (spec.format) {
      case Format::kText: {
        std::string text = word.text;
        text.resize(static_cast<std::size_t>(width), ' ');
        return text;
      }
      case Format::kDigit:
      case Format::kInteger: {
        const double value = word.number;
        const int low = spec.format == Format::kDigit ? 0 : -99;
        const int high = spec.format == Format::kDigit ? 9 : 999;
        if (value != std::floor(value) || value < low || value > high) {
          fail(spec.number, stage, word_number,
               "value " + deck_detail::format_number(value) + " does not fit its " +
                   (spec.format == Format::kDigit ? std::string("I1 field (0-9)")
                                                  : std::string("I3 field (-99 to 999)")));
        }
        char buffer[8];
        std::snprintf(buffer, sizeof buffer, "%*d", width, static_cast<int>(value));
        return buffer;
      }
      case Format::kReal: {
        if (blank_zero && word.number == 0.0) return std::string(12, ' ');
        bool exact = true;
        std::string text = format_real_field(word.number, width, &exact);
        if (!exact && rounded_ != nullptr) ++*rounded_;
        return std::string(static_cast<std::size_t>(width) - text.size(), ' ') + text;
      }
      case Format::kStation: break;
    }
    return std::string(static_cast<std::size_t>(width), ' ');
  }

  // Punches words first..last of a block (all given) after a header card.
  void words(const BlockSpec& spec, int stage, const BlockData& data, int first, int last, int header_stage) {
    const int size = block_size(spec, spec.number == 46 ? 0 : stage);
    if (last > size) {
      fail(spec.number, stage, last,
           "data block " + str(spec.number) +
               (stage > 0 ? " (stage code " + str(stage) + ")" : std::string()) + " needs " + str(last) +
               " words but holds " + str(size) +
               (spec.shape == Shape::kTable ? " (at most " + str((size - 2) / 2) + " table points)"
                                            : std::string()));
    }
    std::string note = spec.title;
    if (spec.number == 46) note = std::string("DISPERSION ") + deck_detail::dispersion_name(header_stage);
    else if (spec.stages != 0) note += " STAGE " + str(stage);
    card(header(spec.number, first, last, header_stage, note));
    const int per_card = fields_per_card(spec.format);
    std::string line;
    int in_line = 0;
    for (int w = first; w <= last; ++w) {
      const Word& word = data.words[static_cast<std::size_t>(w - 1)];
      line += field(spec, stage, w, word, spec.shape == Shape::kTable && w == 1);
      if (++in_line == per_card) {
        card(line);
        line.clear();
        in_line = 0;
      }
    }
    if (in_line > 0) card(line);
  }

  // Every run of given words of a block.
  void block(const BlockSpec& spec, int stage, const BlockData& data) {
    const int count = static_cast<int>(data.words.size());
    const bool whole = spec.shape != Shape::kWords;
    int w = 1;
    while (w <= count) {
      if (!data.words[static_cast<std::size_t>(w - 1)].given) {
        ++w;
        continue;
      }
      int end = w;
      while (end < count && data.words[static_cast<std::size_t>(end)].given) ++end;
      if (whole && w != 1) {
        fail(spec.number, stage, w, "data block " + str(spec.number) + " must be punched from word 1");
      }
      words(spec, stage, data, w, end, stage);
      if (whole) return;
      w = end + 1;
    }
  }

  // The words of `data` that differ from `before` (successive cases: only the changes).
  void changes(const BlockSpec& spec, int stage, const BlockData& data, const BlockData* before) {
    auto same = [](const Word& a, const Word& b) {
      return a.given == b.given && (!a.given || (a.number == b.number && a.text == b.text));
    };
    if (before == nullptr) {
      block(spec, stage, data);
      return;
    }
    bool differ = data.words.size() != before->words.size();
    for (std::size_t i = 0; !differ && i < data.words.size(); ++i)
      differ = !same(data.words[i], before->words[i]);
    if (!differ) return;
    if (spec.shape != Shape::kWords) {
      block(spec, stage, data);
      return;
    }
    const int count = static_cast<int>(data.words.size());
    int w = 1;
    while (w <= count) {
      const std::size_t i = static_cast<std::size_t>(w - 1);
      const bool changed =
          data.words[i].given && (i >= before->words.size() || !same(data.words[i], before->words[i]));
      if (!changed) {
        ++w;
        continue;
      }
      int end = w;
      while (end < count) {
        const std::size_t j = static_cast<std::size_t>(end);
        if (!data.words[j].given || (j < before->words.size() && same(data.words[j], before->words[j])))
          break;
        ++end;
      }
      words(spec, stage, data, w, end, stage);
      w = end + 1;
    }
  }

  void station(const BlockData& data) {
    std::string text = data.words[0].text;
    text.resize(12, ' ');
    const BlockSpec& spec = *find_block(10);  // E12.8 words
    for (int w = 2; w <= 4; ++w)
      text += field(spec, 0, w, data.words[static_cast<std::size_t>(w - 1)], false);
    text += ' ';  // column 49 blank, the description in columns 50-80
    text += data.words[4].text.substr(0, 31);
    card(text);
  }

 private:
  int* rounded_;
  std::string out_;
};

// The words of block 33 in [first, last] only (the hardover and impact groups repeat some).
BlockData only_words(const BlockData& data, int first, int last) {
  BlockData part = data;
  for (std::size_t i = 0; i < part.words.size(); ++i) {
    const int w = static_cast<int>(i) + 1;
    if (w < first || w > last) part.words[i].given = false;
  }
  return part;
}

// A hardover or impact group: its own blocks, then the words of block 33 (and, hardover, the
// block 37 tables) it needs, as the optimization data give them with the group's own words laid over.
void group(Punch* punch, const CardCase& card_case, const BlockSet& set, int first_33, int last_33, bool cg) {
  for (const auto& [key, data] : set) {
    if (key.block == 33 || key.block == 37) continue;
    if (const BlockSpec* spec = find_block(key.block)) punch->block(*spec, key.stage, data);
  }
  BlockData body;
  if (const BlockData* base = find_data(card_case.optimization, 33))
    body = only_words(*base, first_33, last_33);
  if (const BlockData* own = find_data(set, 33)) {
    if (body.words.size() < own->words.size()) body.words.resize(own->words.size());
    for (std::size_t i = 0; i < own->words.size(); ++i) {
      if (own->words[i].given) body.words[i] = own->words[i];
    }
  }
  punch->block(*find_block(33), 0, body);
  for (int stage = 1; stage <= 4; ++stage) {
    const BlockData* own = find_data(set, 37, stage);
    const BlockData* base = cg ? find_data(card_case.optimization, 37, stage) : nullptr;
    if (own != nullptr) punch->block(*find_block(37), stage, *own);
    else if (base != nullptr) punch->block(*find_block(37), stage, *base);
  }
}

}  // namespace

CardCase card_case_from_toml(const toml::table& root) {
  FromToml builder(root);
  return builder.build();
}

std::string write_card_images(const std::vector<CardCase>& cases, int* rounded) {
  Punch punch(rounded);
  const CardCase* previous = nullptr;
  for (const CardCase& card_case : cases) {
    for (const auto& [key, data] : card_case.optimization) {
      const BlockSpec* spec = find_block(key.block);
      if (spec == nullptr) continue;
      const BlockData* before =
          previous != nullptr ? find_data(previous->optimization, key.block, key.stage) : nullptr;
      punch.changes(*spec, key.stage, data, before);
    }
    punch.blank_card();
    if (card_case.dispersion_group) {
      for (const Dispersion& d : card_case.dispersions) {
        BlockData title = d.title;
        title.words.resize(2);
        for (Word& word : title.words) word.given = true;
        punch.words(*find_block(46), 0, title, 1, 2, d.code);
        for (const auto& [key, data] : d.blocks) {
          if (const BlockSpec* spec = find_block(key.block)) punch.block(*spec, key.stage, data);
        }
      }
      punch.blank_card();
    }
    if (card_case.hardover_group) {
      group(&punch, card_case, card_case.hardover, 7, 16, true);
      punch.blank_card();
    }
    if (card_case.impact_group) {
      group(&punch, card_case, card_case.impact, 17, 19, false);
      punch.blank_card();
    }
    if (card_case.radar_group) {
      const std::size_t count = card_case.radar.size();
      for (std::size_t start = 0; start < count; start += static_cast<std::size_t>(kMaxRadarStations)) {
        const std::size_t end = std::min(count, start + static_cast<std::size_t>(kMaxRadarStations));
        punch.card(punch.header(41, 1, 5, static_cast<int>(end - start), "RADAR STATION LOCATIONS"));
        for (std::size_t i = start; i < end; ++i) punch.station(card_case.radar[i]);
      }
      punch.blank_card();
    }
    previous = &card_case;
  }
  punch.card("999");
  return punch.take();
}

}  // namespace tolip::ground::card_detail
