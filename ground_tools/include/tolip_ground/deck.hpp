// Reading a case deck into a core Mission.
//
// The modern deck is TOML (docs/deck-format.md): one table per data block, named fields with the
// unit in the name, degrees and nautical miles at this edge converted to the core's radians and
// feet. Every error names the file, the line (when the TOML parser knows it), the data block and
// the field, and says what was expected. A failed load leaves *mission untouched.
#pragma once

#include <memory>
#include <string>

#include "tolip/mission/mission.hpp"

namespace tolip::ground {

struct DeckError {
  std::string file;
  int line = 0;            // 0 when unknown
  int data_block = 0;      // manual data block number, 0 when not tied to one
  std::string field;       // TOML key path, e.g. "stage.2.thrust.time_s[5]"
  std::string message;     // what is wrong and what was expected
  std::string to_string() const;  // "file:line: data block N, field F: message"
};

// Loads and validates (validate_mission) a TOML deck. Returns false and fills *error on any fault.
bool load_toml_deck(const std::string& path, Mission* mission, DeckError* error);

// The same from text already in memory (path is used in messages only).
bool parse_toml_deck(const std::string& text, const std::string& path, Mission* mission,
                     DeckError* error);

// Mission is large (fixed-capacity tables); ground tools keep it on the heap.
inline std::unique_ptr<Mission> make_mission() { return std::make_unique<Mission>(); }

}  // namespace tolip::ground
