// Helpers shared by the deck tests (tests/ground/deck_*_test.cpp).
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "support/reference_data.hpp"
#include "support/text_match.hpp"
#include "tolip_ground/deck.hpp"
#include "tolip_ground/deck_extras.hpp"

namespace tolip::test {

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(static_cast<bool>(in)) << "cannot open " << path;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

inline std::string scout_mission_text() { return read_text(example_path("scout/mission.toml")); }
inline std::string scout_optimum_text() { return read_text(example_path("scout/reference_optimum.toml")); }

// Replaces the first occurrence of `from` (which must occur) by `to`.
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "test edit target not found: " << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// Removes the text from `begin` (inclusive) up to `end` (exclusive); both must occur.
inline std::string removed(std::string text, const std::string& begin, const std::string& end) {
  const std::size_t from = text.find(begin);
  EXPECT_NE(from, std::string::npos) << "test edit target not found: " << begin;
  if (from == std::string::npos) return text;
  const std::size_t to = text.find(end, from + begin.size());
  EXPECT_NE(to, std::string::npos) << "test edit target not found: " << end;
  if (to == std::string::npos) return text;
  text.erase(from, to - from);
  return text;
}

// 1-based line of the first occurrence of `needle` in `text` (0 when absent).
inline int line_of(const std::string& text, const std::string& needle) {
  const std::size_t at = text.find(needle);
  if (at == std::string::npos) return 0;
  int line = 1;
  for (std::size_t i = 0; i < at; ++i) line += text[i] == '\n' ? 1 : 0;
  return line;
}

// Parses text that must be rejected; returns the error.
inline ground::DeckError rejected(const std::string& text, const std::string& name = "edited.toml") {
  auto mission = ground::make_mission();
  ground::DeckError error;
  const bool loaded = ground::parse_toml_deck(text, name, mission.get(), &error);
  EXPECT_FALSE(loaded) << "deck was accepted but should have been rejected";
  return error;
}

}  // namespace tolip::test
