// The one field description of the deck (ground_tools/src/deck/field_description.hpp) drives every
// reader and writer: walking it, each field given a distinctive value in the Scout deck must come
// back with that value through the TOML reader, through the card writer and the card reader
// (TOML -> cards -> TOML -> reader), in the TOML that `tolip convert` writes from the cards, and in
// the C++ source of the flight image. A reader or writer that skips a described field, or a field
// whose block/word or key disagrees between the two formats, fails here and names the field.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>
#include <string>

#include <toml++/toml.h>

#include "../../ground_tools/src/deck/field_description.hpp"
#include "deck_test_support.hpp"
#include "tolip_ground/card_deck.hpp"
#include "tolip_ground/mission_source.hpp"

namespace tolip::test {
namespace {

using ground::deck_detail::FieldDescription;
using ground::deck_detail::FieldTarget;

// The value of a described element in a loaded case, core units.
double loaded_value(const FieldDescription& field, const ground::DeckCase& deck_case, int code, int index) {
  FieldTarget target;
  target.mission = deck_case.mission.get();
  target.extras = const_cast<ground::DeckExtras*>(&deck_case.extras);  // read only
  return ground::deck_detail::field_value(field, target, code, index);
}

// A nearby value with at most 6 significant digits, so that it fits an E12.8 card field exactly:
// 1e-4 larger (the stage 1 duration and the end of the zero-alpha window stay within CT1(10) of
// the end of the thrust table), 0.5 for a zero, half a unit more for a value that must be at least 1,
// integers one more, 0/1 flags swapped, choices the next allowed one.
double distinctive(const FieldDescription& field, double current) {
  using ground::deck_detail::Range;
  if (field.range == Range::kFlag) return current == 0.0 ? 1.0 : 0.0;
  if (field.range == Range::kChoice) return current + 1.0 <= field.high ? current + 1.0 : current - 1.0;
  if (field.integer) return current + 1.0;
  if (current == 0.0) return 0.5;
  if (field.range == Range::kAtLeastOne) return current + 1.0;  // whole: DA6D(12-15) are substep counts
  char text[32];
  std::snprintf(text, sizeof text, "%.5e", current * 1.0001);
  return std::strtod(text, nullptr);
}

toml::table* section_table(toml::table& root, const std::string& path) {
  toml::table* table = &root;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = path.find('.', start);
    const std::string part = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (table->get(part) == nullptr) table->insert(part, toml::table{});
    table = table->get(part)->as_table();
    if (dot == std::string::npos) return table;
    start = dot + 1;
  }
}

// Sets element `index` of the field (stage `code`) to `value` (deck units) in a TOML deck.
void set_in(toml::table& root, const FieldDescription& field, int code, int index, double value) {
  toml::table* section = section_table(root, ground::deck_detail::section_of(field, code));
  if (field.count == 1) {
    if (field.integer) section->insert_or_assign(field.key, static_cast<int64_t>(value));
    else section->insert_or_assign(field.key, value);
    return;
  }
  toml::array values;
  for (int i = 0; i < field.count; ++i) {
    const toml::node* given = section->get(field.key);
    const double element = i == index ? value
                           : given != nullptr
                               ? given->as_array()->get(static_cast<std::size_t>(i))->value<double>().value()
                               : ground::deck_detail::default_deck_value(field, code, i);
    if (field.integer) values.push_back(static_cast<int64_t>(element));
    else values.push_back(element);
  }
  section->insert_or_assign(field.key, values);
}

// The value of the key behind a field in a TOML text (deck units); NaN when absent.
double toml_value(const std::string& text, const FieldDescription& field, int code, int index) {
  const toml::table root = toml::parse(text);
  const toml::node_view<const toml::node> at =
      root.at_path(ground::deck_detail::section_of(field, code))[field.key];
  const toml::node_view<const toml::node> element =
      field.count == 1 ? at : at[static_cast<std::size_t>(index)];
  return element.value<double>().value_or(std::nan(""));
}

std::string hex(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%a", value);
  return buffer;
}

struct Probe {
  const FieldDescription* field;
  int code;
  int index;
  std::string name;
};

std::vector<Probe> probes(const ground::DeckCase& base) {
  std::vector<Probe> out;
  for (const FieldDescription& field : ground::deck_detail::field_descriptions()) {
    for (int code : ground::deck_detail::stage_codes(field)) {
      // Stage fields: every stage of the Scout sequence (the others have no [stage.N]).
      if (code != 0 && !base.mission->vehicle.stages[stage_index(code)].in_sequence) continue;
      const int index = field.count - 1;  // arrays: the last element (a base altitude 0 must stay 0)
      out.push_back({&field, code, index,
                     ground::deck_detail::section_of(field, code) + "." + field.key +
                         (field.count > 1 ? "[" + std::to_string(index) + "]" : "")});
    }
  }
  return out;
}

struct Edit {
  Probe probe;
  double value;  // deck units
};

// The Scout deck with the edits, through every reader and writer; each edited value must come back.
void expect_every_path_keeps(const std::vector<Edit>& edits) {
  toml::table root = toml::parse(scout_mission_text());
  for (const Edit& edit : edits)
    set_in(root, *edit.probe.field, edit.probe.code, edit.probe.index, edit.value);
  std::ostringstream text;
  text << root;
  ground::Deck toml_deck;
  ground::DeckError error;
  ASSERT_TRUE(ground::parse_deck(text.str(), "edited.toml", &toml_deck, &error)) << error.to_string();
  std::string cards;
  int rounded = 0;
  ASSERT_TRUE(ground::deck_to_cards(toml_deck, &cards, &rounded, &error)) << error.to_string();
  ground::Deck card_deck;
  ASSERT_TRUE(ground::parse_deck(cards, "edited.dat", &card_deck, &error)) << error.to_string();
  ASSERT_EQ(card_deck.format, ground::DeckFormat::kCards);
  std::string converted;
  ASSERT_TRUE(ground::deck_to_toml(card_deck, 0, &converted, &error)) << error.to_string();
  const std::string source = ground::mission_cpp_source(
      *toml_deck.cases[0].mission, toml_deck.cases[0].extras.listing, "build_case", "test");
  for (const Edit& edit : edits) {
    const FieldDescription& field = *edit.probe.field;
    const int code = edit.probe.code;
    const int index = edit.probe.index;
    SCOPED_TRACE(edit.probe.name + " (data block " + std::to_string(field.block) + " word " +
                 std::to_string(ground::deck_detail::card_word(field, code, index)) + ")");
    const double core = ground::deck_detail::to_core(field.conversion, edit.value);
    EXPECT_EQ(loaded_value(field, toml_deck.cases[0], code, index), core) << "TOML reader";
    EXPECT_EQ(loaded_value(field, card_deck.cases[0], code, index), core) << "card writer, then card reader";
    EXPECT_EQ(toml_value(converted, field, code, index), edit.value) << "tolip convert of the cards";
    if (*field.core_name != '\0') {  // the fields the core's Mission holds
      const std::string name = ground::deck_detail::core_name_of(field, code, index);
      const std::string literal = field.integer ? std::to_string(static_cast<long long>(core)) : hex(core);
      EXPECT_NE(source.find("  m." + name + " = " + literal + ";\n"), std::string::npos)
          << "C++ source: m." << name;
    }
  }
}

TEST(Sec22DeckFields, EveryDescribedFieldIsReadByBothReadersWrittenByTheWriterAndEmitted) {
  ground::Deck base;
  ground::DeckError error;
  ASSERT_TRUE(ground::parse_deck(scout_mission_text(), "scout.toml", &base, &error)) << error.to_string();
  // The Scout deck takes no other value for these; they keep the deck's own value: the payoff is
  // the payload of its first constraint, heating needs a heating constraint it does not list,
  // IP(6) = 1 needs IP(7) = 1, stage 5's chi option needs a stage 5; and the launch is vertical
  // from rest (validate_mission admits the nominal value only, so these two cannot be told from a
  // dropped key; the mission validation tests reject any other value). IP(9) = 2, 3 need the deck's
  // spun-attitude adjustable codes replaced and stage-4 segments added (and 3 a stage 5): the
  // upper-stage deck tests carry IP(9) = 2 through the TOML and the card reader instead.
  const std::set<std::string> fixed = {"options.payoff", "options.heating_constraint",
                                       "options.linearization", "options.stage5_chi",
                                       "options.spin_stages_4_5"};
  const std::set<std::string> nominal_only = {"launch.velocity_ft_s", "launch.flight_path_angle_deg"};
  // Two decks: every other field at once, and the options at once (an option switching a group
  // off drops that group's cards, so the groups' own fields are checked in the first deck).
  std::vector<Edit> fields;
  std::vector<Edit> options;
  int walked = 0;
  for (const Probe& probe : probes(base.cases[0])) {
    const FieldDescription& field = *probe.field;
    const double current = ground::deck_detail::to_deck(
        field.conversion, loaded_value(field, base.cases[0], probe.code, probe.index));
    double value = distinctive(field, current);
    if (fixed.count(probe.name) == 1 || nominal_only.count(probe.name) == 1) value = current;
    (field.block == 4 ? options : fields).push_back({probe, value});
    ++walked;
  }
  EXPECT_GE(walked, 100);  // blocks 4, 10-14, 16, 17, 20-22, 28, 33, 39, 45 and the heading hold
  expect_every_path_keeps(fields);
  expect_every_path_keeps(options);
}

// One card word, one field; one TOML key, one field: find_field() leads back to the entry.
TEST(Sec22DeckFields, EveryCardWordIsDescribedAtMostOnce) {
  std::set<std::string> words;
  std::set<std::string> keys;
  for (const FieldDescription& field : ground::deck_detail::field_descriptions()) {
    for (int code : ground::deck_detail::stage_codes(field)) {
      for (int i = 0; i < field.count; ++i) {
        const std::string word = std::to_string(field.block) + "/" +
                                 std::to_string(ground::deck_detail::card_stage(field, code)) + "/" +
                                 std::to_string(ground::deck_detail::card_word(field, code, i));
        EXPECT_TRUE(words.insert(word).second) << "card word " << word << " described twice";
        int index = -1;
        EXPECT_EQ(ground::deck_detail::find_field(field.block, ground::deck_detail::card_stage(field, code),
                                                  ground::deck_detail::card_word(field, code, i), &index),
                  &field);
        EXPECT_EQ(index, i);
      }
      const std::string key = ground::deck_detail::section_of(field, code) + "." + field.key;
      EXPECT_TRUE(keys.insert(key).second) << "TOML key " << key << " described twice";
    }
  }
}

TEST(Sec15DispersionCodes, EveryCodeMapsToItsDataOnce) {
  // Sec. 15's table: codes 1-38 and 40, in runs, none twice; 39 and 41 are no codes.
  int previous_last = 0;
  for (const auto& codes : ground::deck_detail::dispersion_codes()) {
    EXPECT_GT(codes.first, previous_last);
    EXPECT_LE(codes.first, codes.last);
    previous_last = codes.last;
  }
  for (int code = 1; code <= 38; ++code)
    EXPECT_NE(ground::deck_detail::find_dispersion(code), nullptr) << code;
  EXPECT_EQ(ground::deck_detail::find_dispersion(39), nullptr);
  EXPECT_NE(ground::deck_detail::find_dispersion(40), nullptr);
  EXPECT_EQ(ground::deck_detail::find_dispersion(41), nullptr);
  // The stage each code's data carry (Sec. 22 data blocks 30, 38, 47, 49-51).
  EXPECT_EQ(ground::deck_detail::dispersion_stage(3, 30), 2);
  EXPECT_EQ(ground::deck_detail::dispersion_stage(8, 38), -1);  // stage 4, or 5 of a five-stage vehicle
  EXPECT_EQ(ground::deck_detail::dispersion_stage(16, 47), -1);
  EXPECT_EQ(ground::deck_detail::dispersion_stage(8, 55), 0);
  EXPECT_EQ(ground::deck_detail::dispersion_stage(12, 47), 2);
  EXPECT_EQ(ground::deck_detail::dispersion_stage(22, 49), 1);
  EXPECT_EQ(ground::deck_detail::dispersion_stage(27, 50), 3);
  EXPECT_EQ(ground::deck_detail::dispersion_stage(31, 51), -1);
  EXPECT_TRUE(ground::deck_detail::dispersion_takes(7, 55));
  EXPECT_FALSE(ground::deck_detail::dispersion_takes(6, 55));
  EXPECT_EQ(ground::deck_detail::dispersion_blocks(13), "data block 47 (stage code 3)");
}

}  // namespace
}  // namespace tolip::test
