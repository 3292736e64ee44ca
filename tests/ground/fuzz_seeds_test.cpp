// The compact seeds of the deck readers' fuzz targets (fuzz/corpus/toml_deck/compact_*.toml,
// fuzz/corpus/card_deck/compact_*.dat; docs/verification/fuzzing.md) are what
// scripts/make_fuzz_seeds.py derives from the examples: the same decks with every table cut to its
// first, middle and last row. A seed is only worth its executions if the fuzz target's success
// path runs on it (the deck read whole, then validate_mission) and if it holds every key of the
// deck it stands for: this checks both, against the examples themselves.
// Verifies: REQ-DCK-005
#include <gtest/gtest.h>

#include <cstdlib>
#include <set>
#include <string>

#include <toml++/toml.h>

#include "deck_test_support.hpp"
#include "support/repository_paths.hpp"
#include "tolip/mission/mission.hpp"
#include "tolip_ground/card_deck.hpp"

namespace tolip::test {
namespace {

const std::string kCorpus = std::string(tolip::repository_paths::source_dir()) + "/fuzz/corpus";

// Every key path of a TOML document, array-of-tables entries by index ("dispersion.3.code"); the
// elements of value arrays are not paths (the tables are thinned, their keys are not).
void key_paths(const toml::table& table, const std::string& prefix, std::set<std::string>* out) {
  for (const auto& [key, node] : table) {
    const std::string path = prefix + std::string(key.str());
    out->insert(path);
    if (const toml::table* sub = node.as_table()) {
      key_paths(*sub, path + ".", out);
    } else if (const toml::array* array = node.as_array(); array != nullptr && array->is_array_of_tables()) {
      for (std::size_t i = 0; i < array->size(); ++i) {
        key_paths(*array->get(i)->as_table(), path + "." + std::to_string(i) + ".", out);
      }
    }
  }
}

std::set<std::string> key_paths_of(const std::string& toml_text) {
  std::set<std::string> paths;
  key_paths(toml::parse(toml_text), "", &paths);
  return paths;
}

// The key paths of every case of a card deck, "case N." before each: the TOML deck each case
// stands for (the card reader's own conversion).
std::set<std::string> card_deck_key_paths(const std::string& text, const std::string& name) {
  ground::Deck deck;
  ground::DeckError error;
  EXPECT_TRUE(ground::parse_card_deck(text, name, &deck, &error)) << error.to_string();
  std::set<std::string> paths;
  for (int c = 1; c <= static_cast<int>(deck.cases.size()); ++c) {
    std::string toml_text;
    EXPECT_TRUE(ground::deck_to_toml(deck, c, &toml_text, &error)) << error.to_string();
    for (const std::string& path : key_paths_of(toml_text))
      paths.insert("case " + std::to_string(c) + "." + path);
  }
  return paths;
}

// The fuzz target's success path (fuzz/toml_deck_fuzzer.cpp): parsed, then validated.
void expect_toml_seed_parses_and_validates(const std::string& text, const std::string& name) {
  auto mission = ground::make_mission();
  ground::DeckError error;
  ASSERT_TRUE(ground::parse_toml_deck(text, name, mission.get(), &error)) << error.to_string();
  MissionFault fault;
  EXPECT_EQ(validate_mission(*mission, &fault), Status::kOk)
      << name << ": " << fault.data_block << " " << fault.field;
}

// fuzz/card_deck_fuzzer.cpp's success path: parsed, at least one case, each validated.
void expect_card_seed_parses_and_validates(const std::string& text, const std::string& name) {
  ground::Deck deck;
  ground::DeckError error;
  ASSERT_TRUE(ground::parse_card_deck(text, name, &deck, &error)) << error.to_string();
  ASSERT_FALSE(deck.cases.empty());
  for (const ground::DeckCase& c : deck.cases) {
    MissionFault fault;
    ASSERT_TRUE(c.mission != nullptr);
    EXPECT_EQ(validate_mission(*c.mission, &fault), Status::kOk)
        << name << ": " << fault.data_block << " " << fault.field;
  }
}

struct Seed {
  const char* seed;     // under fuzz/corpus
  const char* example;  // under examples
};

constexpr Seed kTomlSeeds[] = {
    {"toml_deck/compact_scout_mission.toml", "scout/mission.toml"},
    {"toml_deck/compact_strapon_mission.toml", "strapon/mission.toml"},
    {"toml_deck/compact_escape_mission.toml", "escape/mission.toml"},
};
constexpr Seed kCardSeeds[] = {
    {"card_deck/compact_scout_mission.dat", "scout/mission.dat"},
    {"card_deck/compact_scout_cases.dat", "scout/cases.dat"},
};

TEST(FuzzSeeds, CompactDeckSeedsParseAndValidateAndMatchTheirGenerator) {
  for (const Seed& s : kTomlSeeds) {
    SCOPED_TRACE(s.seed);
    const std::string seed = read_text(kCorpus + "/" + s.seed);
    const std::string example = read_text(example_path(s.example));
    EXPECT_LT(seed.size() * 5, example.size() * 3);  // compact: less than 60 % of the example
    expect_toml_seed_parses_and_validates(seed, s.seed);
    EXPECT_EQ(key_paths_of(seed), key_paths_of(example)) << "a key of " << s.example << " is missing";
  }
  for (const Seed& s : kCardSeeds) {
    SCOPED_TRACE(s.seed);
    const std::string seed = read_text(kCorpus + "/" + s.seed);
    const std::string example = read_text(example_path(s.example));
    EXPECT_LT(seed.size() * 5, example.size() * 3);
    expect_card_seed_parses_and_validates(seed, s.seed);
    EXPECT_EQ(card_deck_key_paths(seed, s.seed), card_deck_key_paths(example, s.example))
        << "a data block of " << s.example << " is missing";
  }

  // The checked-in seeds are the generator's output, byte for byte (no hand edits, none stale).
  if (std::system("python3 -c 'import tomllib' > /dev/null 2>&1") != 0) {
    GTEST_SKIP() << "python3 with tomllib (3.11) not available";
  }
  const std::string out = std::string(tolip::repository_paths::binary_dir()) + "/generated_fuzz_seeds";
  const std::string command = "python3 '" + std::string(tolip::repository_paths::source_dir()) +
                              "/scripts/make_fuzz_seeds.py' --out '" + out + "' > /dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  for (const Seed& s : kTomlSeeds) {
    EXPECT_EQ(read_text(out + "/" + s.seed), read_text(kCorpus + "/" + s.seed))
        << s.seed << " differs from scripts/make_fuzz_seeds.py output";
  }
  for (const Seed& s : kCardSeeds) {
    EXPECT_EQ(read_text(out + "/" + s.seed), read_text(kCorpus + "/" + s.seed))
        << s.seed << " differs from scripts/make_fuzz_seeds.py output";
  }
}

}  // namespace
}  // namespace tolip::test
