// One description of every word-per-value field of the deck (docs/deck-format.md "One field
// description"): where it is punched (data block, word, stage coding), its TOML table and key, what
// it means on the card and in a message, its unit conversion, whether the TOML reader demands it,
// its default, its allowed range, and where the value lives (the core's Mission, the ground-side
// DeckExtras or the listing options). The TOML reader (mission_sections.cpp, extras_sections.cpp),
// the card reader's TOML form (card_toml.cpp), the card writer (card_writer.cpp), the word meanings
// of the IP(17) echo and of `tolip convert` (card_blocks.cpp) and the C++ source emitter
// (mission_source.cpp) all walk this one table, so a new field is added once.
//
// What is not word-per-value stays with its own reader and writer: texts (blocks 1-3, 41, 46),
// counted lists (5, 6, 8, 18, 19, 26, 27, 29), output frequency groups (9), tables (30-32, 34-38,
// 40, 42-44, 53, 54) and the dispersion data (47-55, one description of its own: dispersion_codes()).
#pragma once

#include <string>
#include <vector>

#include "tolip/mission/mission.hpp"
#include "tolip_ground/deck_extras.hpp"

namespace tolip::ground::deck_detail {

// What a field's value lives in. The TOML reader fills all three; the C++ source emitter reads the
// Mission only.
struct FieldTarget {
  Mission* mission = nullptr;
  DeckExtras* extras = nullptr;
};

// The storage of one value: exactly one of the pointers is set.
struct FieldSlot {
  double* real = nullptr;
  int* integer = nullptr;
};

// How the deck's unit becomes the core's (the inverse is applied by the card and TOML writers).
enum class Conversion {
  kNone,
  kDegToRad,        // deck degrees (or deg/s) -> rad (rad/s)
  kPerDegToPerRad,  // deck "per degree" -> "per radian"
  kInchToFt,        // deck body stations in inches -> ft
};
double to_core(Conversion conversion, double deck_value);
double to_deck(Conversion conversion, double core_value);

// Where a field sits on the cards.
enum class StageCoding {
  kNone,          // one word of the block (header field 4 blank)
  kStageCode,     // one word per stage code: header field 4 is the stage code (block 39)
  kWordPerStage,  // words word + 2 (code - 1): two words per stage code in one block (block 16)
};

enum class Presence {
  kOptional,            // absent: the default (or the target's own value when the field has none)
  kRequired,            // the TOML reader demands the key
  kRequiredWhen,        // required when required_when(mission) holds; otherwise optional
  kRequiredForPowered,  // stage fields: required for powered stages 1-5, optional for coasts
};

enum class Range {
  kAny,         // any finite number (integer fields: any integer)
  kPositive,    // > 0
  kAtLeastOne,  // >= 1 (integers: counts, every n-th step; arrays: every element)
  kFlag,        // a 0/1 option: true/false or 0/1 in TOML
  kChoice,      // an integer low..high
};

// Stages a stage-coded field exists for.
enum class StageSet { kAll, kPowered };

struct FieldDescription {
  int block = 0;  // manual data block on the cards
  int word = 0;   // first word (kWordPerStage: of stage code 1)
  int count = 1;  // > 1: words word..word+count-1 are one TOML array
  StageCoding stage_coding = StageCoding::kNone;
  StageSet stages = StageSet::kAll;
  const char* section = "";    // TOML table; "stage.{n}" for stage-coded fields
  const char* key = "";        // TOML key, the unit in its name
  const char* card_text = "";  // the word's meaning on the card (IP(17) echo, convert comments)
  // The quantity and its unit in the TOML reader's messages. {w}: the word, {n}: the stage code,
  // {kind}: "powered stage n" or "coast n".
  const char* what = "";
  int message_block = 0;  // data block the TOML reader names (0: `block`)
  Conversion conversion = Conversion::kNone;
  bool integer = false;  // the TOML reader wants an integer
  Presence presence = Presence::kOptional;
  bool (*required_when)(const Mission&) = nullptr;
  bool has_default = false;  // absent: default_value (deck units); otherwise the target keeps its value
  double default_value = 0.0;
  Range range = Range::kAny;
  int low = 0;  // kChoice
  int high = 0;
  // C++ member path in the Mission for the source emitter ("constants.haero_ft";
  // "vehicle.stages[{i}].duration_s"); "" when the value does not live in the Mission.
  const char* core_name = "";
  // The storage of element `index` (0..count-1) of the field for stage `stage` (0 when not stage-coded).
  FieldSlot (*slot)(const FieldTarget& target, int stage, int index) = nullptr;
};

// Every field, in card order within each TOML section.
const std::vector<FieldDescription>& field_descriptions();

// The field punched at (block, stage, word) and the element of it that word is; nullptr when no
// field of the description is punched there.
const FieldDescription* find_field(int block, int stage, int word, int* index = nullptr, int* code = nullptr);
// The field with this TOML section ("stage.{n}" for stage fields) and key; nullptr when none.
const FieldDescription* find_field(const std::string& section, const std::string& key);

// Whether a stage-coded field exists for stage `code` (always true when not stage-coded).
bool applies_to_stage(const FieldDescription& field, int code);
// Card location of element `index` for stage `code`: the word, and the header's stage code.
int card_word(const FieldDescription& field, int code, int index = 0);
int card_stage(const FieldDescription& field, int code);
// The section with {n} replaced by the stage code.
std::string section_of(const FieldDescription& field, int code);
// `card_text`, `what` and `core_name` with their placeholders filled.
std::string card_text_of(const FieldDescription& field, int code, int index = 0);
std::string what_of(const FieldDescription& field, int code, int index = 0);
std::string core_name_of(const FieldDescription& field, int code, int index = 0);
int message_block(const FieldDescription& field);

// The value of element `index` (core units) in the target, and storing one (integers truncated).
double field_value(const FieldDescription& field, const FieldTarget& target, int stage, int index);
void set_field_value(const FieldDescription& field, const FieldTarget& target, int stage, int index,
                     double value);
// The same for a read-only Mission (the source emitter and the echo's nominal values).
double field_value(const FieldDescription& field, const Mission& mission, int stage, int index);

// The value element `index` takes when the deck does not give it, in deck units: the default, or
// the value of a default-constructed Mission / DeckExtras (the core's nominal constants).
double default_deck_value(const FieldDescription& field, int stage, int index);

// The stage codes a field is walked for: {0} when not stage-coded, else the codes of its StageSet.
std::vector<int> stage_codes(const FieldDescription& field);

// ---- the dispersion codes of data block 46 (Sec. 15, Sec. 22 data blocks 46-55) -----------------

// One datum a dispersion code takes: a word of a block, or a whole table block.
struct DispersionItem {
  int block = 0;
  int word = 0;          // 0: a table block (x_key, y_key)
  int count = 1;         // words: > 1 is a TOML array of words word..word+count-1
  const char* key = "";  // TOML key in [[dispersion]] (a sub-table for table blocks)
  const char* x_key = "";
  const char* y_key = "";
};

// What a dispersed trajectory changes (Sec. 15 table of dispersion codes).
enum class DispersionKind {
  kThrust,           // 1-8: replacement thrust and weight tables (and, 7-8, the stage 4-5 durations)
  kWeightIncrement,  // 9-16
  kDrag,             // 17-18
  kPitchingMoment,   // 19-20: a complete block 35
  kMisalignment,     // 21-23
  kDeadband,         // 24-29
  kTipoff,           // 30-32
  kLaunchAzimuth,    // 33
  kLaunchAttitude,   // 34-35
  kWinds,            // 36-38
  kSummary,          // 40: the three-sigma summary, no data
};

// A run of dispersion codes with the same data.
struct DispersionCodes {
  int first = 0;
  int last = 0;
  DispersionKind kind = DispersionKind::kSummary;
  const char* name = "";    // the kind of dispersed trajectory
  const char* blocks = "";  // what the cards must give, for messages
  std::vector<DispersionItem> items;
  // The stage code the code's data blocks carry: 0 none; -1 4 or 5 (the tip-off); otherwise fixed.
  int (*stage_of)(int code) = nullptr;
};

const std::vector<DispersionCodes>& dispersion_codes();
// The codes' entry of a dispersion code, nullptr for an unknown code.
const DispersionCodes* find_dispersion(int code);
// The stage code `code`'s data of `block` carries (0 none, -1 stage 4 or 5).
int dispersion_stage(int code, int block);
// Whether dispersion code `code` takes data block `block`.
bool dispersion_takes(int code, int block);
// What the cards of dispersion code `code` must give ("data block 47 (stage code 2)").
std::string dispersion_blocks(int code);

}  // namespace tolip::ground::deck_detail
