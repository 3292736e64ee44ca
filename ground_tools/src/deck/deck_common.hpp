// Deck vocabulary shared by the TOML reader and the card-deck reader/writer (ground_tools/src/deck/):
// the units of the constraint codes (data blocks 8, 19, 29) and the names of the dispersion codes
// (data block 46, from dispersion_codes() in field_description.hpp), and the card encoding of data
// block 18's times. One table or rule each, so both deck formats agree.
#pragma once

#include <string>

#include "tolip_ground/deck.hpp"

namespace tolip::ground::deck_detail {

// Unit of a constraint code's desired value and deadbands: the TOML key suffix and the factor from
// the deck's human unit to the core's pure unit (block 19/29 hold radians for angles).
struct ConstraintUnit {
  const char* suffix;  // key suffix in the deck
  double to_core;      // deck value * to_core = DA4 pure units
  const char* name;
};

// The unit of a constraint code (0-14, X5-X9 for stage points, 100-102); false for an unknown code.
bool constraint_unit(int code, ConstraintUnit* unit);

// Data block 18's encoding of a segment boundary, TLIN = 100 n + t (n the powered stage, t s from
// its ignition): n = floor(TLIN / 100), t = TLIN - 100 n. The deck readers decode at this edge;
// the core holds SegmentBoundary. coded_time() is the inverse, for messages.
SegmentBoundary decode_coded_time(double coded);
double coded_time(const SegmentBoundary& boundary);

// The kind of dispersed trajectory of a data block 46 code (1-38, 40); nullptr for an unknown code.
const char* dispersion_name(int code);

// Reads a whole deck file, at most kMaxDeckFileBytes (read_file_capped); false with *error
// (file = path, message "cannot open the deck file: ...", "is a directory, not a deck file",
// "more than ... bytes: ...") on failure.
bool read_deck_file(const std::string& path, std::string* text, DeckError* error);

}  // namespace tolip::ground::deck_detail
