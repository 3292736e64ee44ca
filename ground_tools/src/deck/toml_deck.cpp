// load_toml_deck() / parse_toml_deck(): the modern TOML case deck (docs/deck-format.md).
//
// The deck is parsed into a temporary Mission (and DeckExtras), checked section by section with
// located messages, then validated by the core (validate_mission); only a deck that passes every
// check is copied to the caller's objects. Nothing throws out of these functions.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <memory>
#include <new>
#include <sstream>
#include <string>

#include "card_internal.hpp"
#include "deck_common.hpp"
#include "tolip_ground/deck.hpp"
#include "tolip_ground/deck_extras.hpp"
#include "toml_reader.hpp"

namespace tolip::ground {

std::string DeckError::to_string() const {
  std::string out = file.empty() ? std::string("<deck>") : file;
  if (card_deck) {
    std::string where;
    if (line > 0) {
      where += "card " + std::to_string(line);
      if (first_column > 0) {
        where += first_column == last_column || last_column <= 0
                     ? ", column " + std::to_string(first_column)
                     : ", columns " + std::to_string(first_column) + "-" + std::to_string(last_column);
      }
    }
    std::string what;
    auto add = [&what](const std::string& part) { what += (what.empty() ? "" : ", ") + part; };
    if (case_number > 0) add("case " + std::to_string(case_number));
    if (data_block > 0) add("data block " + std::to_string(data_block));
    if (data_block > 0 && stage_code > 0) {
      add((data_block == 46   ? "dispersion code "
           : data_block == 41 ? "station count "
                              : "stage code ") +
          std::to_string(stage_code));
    }
    if (word > 0) add("word " + std::to_string(word));
    out += ": ";
    if (!where.empty()) out += where + ": ";
    if (!what.empty()) out += what + ": ";
    return out + message;
  }
  if (line > 0) {
    out += ':';
    out += std::to_string(line);
  }
  out += ": ";
  if (data_block > 0) {
    out += "data block ";
    out += std::to_string(data_block);
    out += ", ";
  }
  if (!field.empty()) {
    out += "field ";
    out += field;
    out += ": ";
  }
  out += message;
  return out;
}

namespace {

using deck_detail::AcceptedKey;
using deck_detail::DeckFailure;
using deck_detail::format_number;
using deck_detail::Reader;
using deck_detail::Section;

// Every top-level table of the deck (docs/deck-format.md).
constexpr const char* kTopLevelKeys[] = {"case",
                                         "options",
                                         "constants",
                                         "atmosphere",
                                         "vehicle",
                                         "stage",
                                         "launch",
                                         "control_constraints",
                                         "misc",
                                         "constraint",
                                         "adjustable_parameter",
                                         "linearization",
                                         "convergence",
                                         "output_frequency",
                                         "pitch_program",
                                         "body_dynamics",
                                         "radar_station",
                                         "impact",
                                         "hardover",
                                         "dispersion"};

void check_top_level(const toml::table& root, Reader& reader) {
  for (auto&& [key, value] : root) {
    bool known = false;
    for (const char* name : kTopLevelKeys) known = known || key.str() == name;
    if (known) continue;
    std::string expected;
    for (const char* name : kTopLevelKeys) expected += (expected.empty() ? "" : ", ") + std::string(name);
    int line = static_cast<int>(key.source().begin.line);
    if (line == 0) line = deck_detail::line_of_node(value);
    reader.fail(
        line, 0, std::string(key.str()),
        "unknown key '" + std::string(key.str()) + "' at the top level; expected one of: " + expected);
  }
}

// "x_rad" -> "x_deg", "x_rad_s" -> "x_deg_s": the deck spells angles in degrees.
std::string deck_key(const std::string& core_field) {
  std::string key = core_field;
  const std::size_t at = key.rfind("_rad");
  if (at != std::string::npos &&
      (at + 4 == key.size() || key.compare(at + 4, std::string::npos, "_s") == 0)) {
    key.replace(at, 4, "_deg");
  }
  return key;
}

std::string element(const std::string& path, int index) {
  return index >= 0 ? path + "[" + std::to_string(index) + "]" : path;
}

// The deck key of a constraint entry's word: code (block 8), desired (19) or a deadband (29), with
// the unit suffix of its code.
std::string constraint_key(const MissionFault& fault, const Mission& mission) {
  const std::string field = fault.field != nullptr ? fault.field : "";
  if (fault.index < 0) return "constraint";
  const std::string entry = "constraint[" + std::to_string(fault.index) + "]";
  if (fault.data_block == 8) return entry + ".code";
  deck_detail::ConstraintUnit unit{};
  const int code = fault.index <= kMaxConstraints ? mission.constraints.codes[fault.index] : -1;
  if (!deck_detail::constraint_unit(code, &unit)) return entry;
  if (fault.data_block == 19) return entry + ".desired_" + unit.suffix;
  return entry + "." + field + "_" + unit.suffix;
}

// The deck key path of a core fault (mission.hpp field names -> docs/deck-format.md keys), with the
// element the fault names.
std::string fault_path(const MissionFault& fault, const Mission& mission) {
  const std::string field = fault.field != nullptr ? fault.field : "";
  const std::string stage = "stage." + std::to_string(fault.stage_code);
  const bool staged = fault.stage_code > 0;
  const int index = fault.index;
  // A described field (field_description.hpp): its core member name leads to its deck key.
  for (const deck_detail::FieldDescription& described : deck_detail::field_descriptions()) {
    const std::string core_name = described.core_name;
    const std::size_t dot = core_name.rfind('.');
    if (deck_detail::message_block(described) != fault.data_block || dot == std::string::npos) continue;
    std::string member = core_name.substr(dot + 1);
    if (const std::size_t bracket = member.find('['); bracket != std::string::npos) member.resize(bracket);
    const bool ip_word = fault.data_block == 4 && described.word == index;
    // An IP(n) fault names its word: every option's core member is `ip`, so the member alone
    // would name IP(1), the payoff.
    if (fault.data_block == 4 && field == "ip" ? !ip_word : member != field && !ip_word) continue;
    const int code = described.stage_coding == deck_detail::StageCoding::kNone ? 0 : fault.stage_code;
    if (code != 0 && !deck_detail::applies_to_stage(described, code)) continue;
    if (described.stage_coding != deck_detail::StageCoding::kNone && code == 0) continue;
    const std::string path = deck_detail::section_of(described, code) + "." + described.key;
    return described.count > 1 ? element(path, index) : path;
  }
  switch (fault.data_block) {
    case 4: return "options";  // an IP(n) without a key (the described ones are found above)
    case 5: return field == "sequence" ? element("vehicle.sequence", index) : "vehicle.sequence";
    case 6:
      return index >= 0 ? "adjustable_parameter[" + std::to_string(index) + "].code" : "adjustable_parameter";
    case 27:
      return index >= 0 ? "adjustable_parameter[" + std::to_string(index) + "].weight"
                        : "adjustable_parameter";
    case 8:
    case 19:
    case 29: return constraint_key(fault, mission);
    case 10: return field == "constants" ? "constants" : "constants." + field;
    case 11:
    case 12:
    case 13:
    case 14: return element("atmosphere." + field, index);
    case 16: return staged ? stage + "." + field : "stage";
    case 17: return field == "misc" ? "misc" : "misc." + deck_key(field);
    case 18:
      if (field == "segment_count") return "linearization.segment_count";
      return element("linearization.coded_times", index);
    case 20:
    case 21:
      if (field == "launch_space_age_date_days") return "launch.space_age_date_days";
      return "launch." + deck_key(field);
    case 22: return field == "control" ? "control_constraints" : "control_constraints." + deck_key(field);
    case 26: return element("linearization.segment_weights", index);
    case 28: return field == "convergence" ? "convergence" : "convergence." + field;
    case 30:
      if (!staged) return "stage";
      if (field == "vacuum_thrust_time_s") return element(stage + ".thrust.time_s", index);
      if (index >= 0) return element(stage + ".thrust.vacuum_thrust_lbf", index);
      return stage + ".thrust";
    case 31:
      if (field == "drag_mach") return element(stage + ".drag.mach", index);
      if (index >= 0) return element(stage + ".drag.cd", index);
      return stage + ".drag";
    case 32:
      if (field == "lift_mach") return element("vehicle.lift_curve_slope.mach", index);
      if (index >= 0) return element("vehicle.lift_curve_slope.cl_alpha_per_rad", index);
      return "vehicle.lift_curve_slope";
    case 38:
      if (!staged) return "stage";
      if (field == "consumable_weight_time_s") return element(stage + ".consumable_weight.time_s", index);
      if (index >= 0) return element(stage + ".consumable_weight.remaining_lb", index);
      return stage + ".consumable_weight";
    case 39:
      if (field == "payload_lb") return "vehicle.payload_lb";
      if (field == "stage_data" || !staged) return staged ? stage : "stage";
      return stage + "." + field;
    case 40:
      if (field == "pitch_program_time_s") return element("pitch_program.time_s", index);
      if (index >= 0) return element("pitch_program.theta_deg", index);
      return "pitch_program";
    case 33:
      // The described DA6D words are found above; the area S is stage 1's block 39 area.
      if (field == "body_dynamics") return "body_dynamics";
      if (field == "reference_area_ft2") return "stage.1.reference_area_ft2";
      return "body_dynamics." + field;
    case 34: return "body_dynamics.fin_normal_force";
    case 35: return "body_dynamics.pitching_moment";
    case 36: return "body_dynamics.fin_pitching_moment";
    case 37: return "body_dynamics.cg." + std::to_string(fault.stage_code);
    default: return field;
  }
}

// A number in the deck's unit: the core's value converted (to_deck), printed with 12 significant
// digits when converted so a degree read as radians prints as the degrees given.
std::string deck_number(double core_value, double to_deck) {
  if (!std::isfinite(core_value)) return format_number(core_value);
  char buffer[64];
  if (to_deck != 1.0) {
    std::snprintf(buffer, sizeof buffer, "%.12g", core_value * to_deck);
    return buffer;
  }
  // Plain digits where 15 significant digits hold the value exactly (100000, not 1e+05).
  std::snprintf(buffer, sizeof buffer, "%.15g", core_value);
  return std::strtod(buffer, nullptr) == core_value ? std::string(buffer) : format_number(core_value);
}

// A data block 18 fault carries the boundary's time from ignition (s); the deck writes the
// boundary as its coded time 100 n + t (deck_common.hpp), and so does the message.
MissionFault in_deck_encoding(const MissionFault& fault, const Mission& mission) {
  if (fault.data_block != 18 || fault.field == nullptr || std::strcmp(fault.field, "boundaries") != 0) {
    return fault;
  }
  MissionFault coded = fault;
  const SegmentBoundary boundary = fault.index >= 0 && fault.index <= kMaxLinearSegments
                                       ? mission.linearization.boundaries[fault.index]
                                       : SegmentBoundary{fault.stage_code, fault.value};
  coded.value = deck_detail::coded_time(boundary);
  coded.unit = "";
  coded.range = ValueRange{};
  return coded;
}

// The value and allowed range a core fault carries, in the units of the deck key that holds it:
// "key = value unit; expected range unit" (or what the core says it expected).
std::string value_detail(const MissionFault& core_fault, const Mission& mission, const std::string& path) {
  if (!core_fault.has_value) return "";
  const MissionFault fault = in_deck_encoding(core_fault, mission);
  std::string unit = fault.unit != nullptr ? fault.unit : "";
  double to_deck = 1.0;
  const auto ends_with = [&path](const std::string& tail) {
    std::string key = path;
    if (const std::size_t bracket = key.find('['); bracket != std::string::npos && key.back() == ']') {
      key.resize(key.rfind('['));
    }
    return key.size() >= tail.size() && key.compare(key.size() - tail.size(), tail.size(), tail) == 0;
  };
  if (fault.data_block == 19 || fault.data_block == 29) {
    deck_detail::ConstraintUnit constraint{};
    const int code =
        fault.index >= 0 && fault.index <= kMaxConstraints ? mission.constraints.codes[fault.index] : -1;
    if (deck_detail::constraint_unit(code, &constraint)) {
      to_deck = 1.0 / constraint.to_core;
      unit = constraint.suffix;  // ft_s -> ft/s, lb_ft2 -> lb/ft2
      std::replace(unit.begin(), unit.end(), '_', '/');
    }
  } else if (unit == "rad" && ends_with("_deg")) {
    to_deck = kRadToDeg;
    unit = "deg";
  } else if (unit == "rad/s" && ends_with("_deg_s")) {
    to_deck = kRadToDeg;
    unit = "deg/s";
  } else if (unit == "ft" && ends_with("_in")) {
    to_deck = 12.0;
    unit = "in";
  } else if (fault.data_block == 33 && fault.field != nullptr &&
             std::strcmp(fault.field, "position_gain") == 0) {
    unit = "deg/deg";
  }
  const std::string with_unit = unit.empty() || unit == "points" ? "" : " " + unit;
  std::string key = path;
  if (const std::size_t dot = key.rfind('.'); dot != std::string::npos) {
    key = key.substr(dot + 1);
  } else if (fault.field != nullptr && *fault.field != '\0' && key.find('[') == std::string::npos) {
    key = fault.field;  // a whole table ([[constraint]]): the core's word, e.g. its count
  }
  std::string out =
      key + " = " + deck_number(fault.value, to_deck) + (unit == "points" ? " points" : with_unit);
  const ValueRange& range = fault.range;
  std::string expected;
  if (range.has_low && range.has_high && range.low == range.high && range.low_inclusive &&
      range.high_inclusive) {
    expected = deck_number(range.low, to_deck) + with_unit;
  } else if (range.has_low && range.has_high) {
    expected = deck_number(range.low, to_deck) + (range.low_inclusive ? " <= " : " < ") + key +
               (range.high_inclusive ? " <= " : " < ") + deck_number(range.high, to_deck) + with_unit;
  } else if (range.has_low) {
    expected = std::string(range.low_inclusive ? ">= " : "> ") + deck_number(range.low, to_deck) + with_unit;
  } else if (range.has_high) {
    expected =
        std::string(range.high_inclusive ? "<= " : "< ") + deck_number(range.high, to_deck) + with_unit;
  }
  const std::string phrase = fault.expected != nullptr ? fault.expected : "";
  if (!expected.empty() && !phrase.empty()) return out + "; expected " + expected + " (" + phrase + ")";
  if (!expected.empty()) return out + "; expected " + expected;
  if (!phrase.empty()) return out + "; expected " + phrase;
  return out;
}

int total_points(const Mission& mission, bool thrust) {
  int total = 0;
  for (const StageData& stage : mission.vehicle.stages) {
    total += thrust ? stage.vacuum_thrust_lbf.size() : stage.consumable_weight_lb.size();
  }
  return total;
}

// Values behind a core fault, so the message says what was found and what was expected.
std::string fault_detail(Status status, const MissionFault& fault, const Mission& mission) {
  const int code = fault.stage_code;
  const bool staged = code >= 1 && code <= kMaxStages;
  const StageData* stage = staged ? &mission.vehicle.stages[stage_index(code)] : nullptr;
  const std::string eps = format_number(mission.constants.time_epsilon_s);
  switch (status) {
    case Status::kStageDurationMismatch:
      if (stage == nullptr) break;
      return "stage " + std::to_string(code) + " duration_s = " + format_number(stage->duration_s) +
             " s but its thrust table ends at " + format_number(stage->vacuum_thrust_lbf.last_x()) +
             " s; expected them equal within CT1(10) = " + eps + " s";
    case Status::kThrustWeightTimesDiffer:
      if (stage == nullptr) break;
      return "stage " + std::to_string(code) + " thrust table ends at " +
             format_number(stage->vacuum_thrust_lbf.last_x()) + " s, consumable weight table at " +
             format_number(stage->consumable_weight_lb.last_x()) +
             " s; expected the same end time within CT1(10) = " + eps + " s";
    case Status::kNegativeWeight:
      if (std::strcmp(fault.field, "payload_lb") == 0) {
        return "payload_lb = " + format_number(mission.vehicle.payload_lb) + "; expected >= 0";
      }
      if (stage != nullptr && fault.data_block == 39) {
        return "stage " + std::to_string(code) +
               " jettison_weight_lb = " + format_number(stage->jettison_weight_lb) + "; expected >= 0";
      }
      break;
    case Status::kLiftoffLongerThanStage1:
      return "liftoff_duration_s = " + format_number(mission.launch.liftoff_duration_s) +
             " s but stage 1 lasts " + format_number(mission.vehicle.stages[0].duration_s) +
             " s; expected 0 <= lift-off < stage 1 duration";
    case Status::kInitialConditionsInvalid:
      return "velocity_ft_s = " + format_number(mission.launch.velocity_ft_s) +
             ", flight_path_angle_deg = " + format_number(mission.launch.flight_path_angle_rad * kRadToDeg) +
             "; the manual requires velocity 0 and flight-path angle 90 deg";
    case Status::kTooManyThrustPointsInAllStages:
      return std::to_string(total_points(mission, true)) + " thrust points over all stages; at most " +
             std::to_string(kMaxThrustPoints);
    case Status::kTooManyWeightPointsInAllStages:
      return std::to_string(total_points(mission, false)) + " weight points over all stages; at most " +
             std::to_string(kMaxWeightPoints);
    case Status::kTooFewStage1Steps:
      return "stage 1 has " + std::to_string(mission.vehicle.stages[0].integration_steps) +
             " integration steps; at least " + std::to_string(kMinStage1Steps);
    case Status::kTooManyCoastSteps:
      if (stage == nullptr) break;
      return "coast " + std::to_string(code) + " has " + std::to_string(stage->integration_steps) +
             " integration steps; at most " + std::to_string(kMaxCoastSteps) + " per coast";
    case Status::kTooManyPoweredSteps:
    case Status::kTooManyPoweredStepsWithFollowingCoast: {
      int steps = 0;
      for (int c = 1; c <= (status == Status::kTooManyPoweredSteps ? 5 : 6); ++c) {
        if (mission.vehicle.stages[stage_index(c)].in_sequence)
          steps += mission.vehicle.stages[stage_index(c)].integration_steps;
      }
      return std::to_string(steps) + " integration steps; at most " +
             std::to_string(status == Status::kTooManyPoweredSteps ? kMaxPoweredSteps
                                                                   : kMaxPoweredStepsWithFollowingCoast);
    }
    case Status::kControlStationAtCenterOfGravity: {
      const CgTable& cg = mission.body_dynamics.cg_station_ft[0];
      double lowest = cg.empty() ? 0.0 : cg.y(0);
      double highest = lowest;
      for (int i = 1; i < cg.size(); ++i) {
        lowest = std::min(lowest, cg.y(i));
        highest = std::max(highest, cg.y(i));
      }
      // The core holds ft; back to the deck's inches, rounded to 1e-6 in so 478/12*12 reads 478.
      const auto inches = [](double ft) { return format_number(std::round(ft * 12.0 * 1e6) / 1e6); };
      return "control_station_in[0] = " + inches(mission.body_dynamics.control_station_ft[0]) +
             " in lies within the stage 1 c.g. stations " + inches(lowest) + "-" + inches(highest) +
             " in (data block 37); expected it outside";
    }
    case Status::kNonPositiveDuration:
      if (stage == nullptr) break;
      return "duration_s = " + format_number(stage->duration_s) + "; expected > 0";
    case Status::kZeroLengthCoast:
      return "duration_s = 0; expected > 0, or coast " + std::to_string(fault.stage_code) +
             " left out of vehicle.sequence (data block 5), so that stage " +
             std::to_string(fault.stage_code - 4) + " ignites at the burnout of stage " +
             std::to_string(fault.stage_code - 5);
    case Status::kNonPositiveStepCount:
      if (stage == nullptr) break;
      return "integration_steps = " + std::to_string(stage->integration_steps) + "; expected >= 1";
    default: break;
  }
  return value_detail(fault, mission, fault_path(fault, mission));
}

DeckError fault_error(Status status, const MissionFault& fault, const Mission& mission,
                      const Reader& reader) {
  DeckError error;
  error.file = reader.file();
  error.data_block = fault.data_block;
  error.field = fault_path(fault, mission);
  error.line = reader.line_of(error.field);
  error.message = std::string(status_name(status)) + ": " + status_message(status);
  const std::string detail = fault_detail(status, fault, mission);
  if (!detail.empty()) error.message += "; " + detail;
  return error;
}

bool parse_deck(const std::string& text, const std::string& path, Mission* mission, DeckExtras* extras,
                DeckError* error, std::vector<AcceptedKey>* accepted = nullptr) {
  DeckError failure;
  failure.file = path;
  try {
    toml::table root;
    try {
      root = toml::parse(text, path);
    } catch (const toml::parse_error& parse_error) {
      failure.line = static_cast<int>(parse_error.source().begin.line);
      failure.message = "TOML syntax error: " + std::string(parse_error.description()) + " (column " +
                        std::to_string(parse_error.source().begin.column) + ")";
      if (error != nullptr) *error = failure;
      return false;
    }
    Reader reader(path);
    reader.record_accepted_keys(accepted);
    check_top_level(root, reader);
    auto parsed = std::make_unique<Mission>();
    auto parsed_extras = std::make_unique<DeckExtras>();
    Section top(&reader, &root, "", 0);
    deck_detail::read_mission_sections(top, parsed.get(), parsed_extras.get());
    deck_detail::read_extras_sections(top, parsed.get(), parsed_extras.get());
    top.finish();

    MissionFault fault;
    const Status status = validate_mission(*parsed, &fault);
    if (!ok(status)) {
      if (error != nullptr) *error = fault_error(status, fault, *parsed, reader);
      return false;
    }
    if (mission != nullptr) *mission = *parsed;
    if (extras != nullptr) *extras = std::move(*parsed_extras);
    return true;
  } catch (const DeckFailure& deck_failure) {
    failure = deck_failure.error;
  } catch (const std::bad_alloc&) {
    failure.message = "out of memory while reading the deck";
  } catch (const std::exception& exception) {
    failure.message = std::string("internal error while reading the deck: ") + exception.what();
  } catch (...) {
    failure.message = "internal error while reading the deck";
  }
  if (error != nullptr) *error = failure;
  return false;
}

}  // namespace

bool parse_toml_deck(const std::string& text, const std::string& path, Mission* mission, DeckExtras* extras,
                     DeckError* error) {
  try {
    return parse_deck(text, path, mission, extras, error);
  } catch (...) {  // only reachable if reporting an error itself runs out of memory
    return false;
  }
}

bool parse_toml_deck(const std::string& text, const std::string& path, Mission* mission, DeckError* error) {
  return parse_toml_deck(text, path, mission, nullptr, error);
}

bool deck_detail::accepted_toml_keys(const std::string& text, const std::string& path,
                                     std::vector<AcceptedKey>* keys, DeckError* error) {
  try {
    keys->clear();
    return parse_deck(text, path, nullptr, nullptr, error, keys);
  } catch (...) {
    return false;
  }
}

bool load_toml_deck(const std::string& path, Mission* mission, DeckExtras* extras, DeckError* error) {
  try {
    std::string text;
    if (!deck_detail::read_deck_file(path, &text, error)) return false;
    return parse_deck(text, path, mission, extras, error);
  } catch (...) {
    try {
      if (error != nullptr) {
        *error = DeckError{};
        error->file = path;
        error->message = "internal error while reading the deck file";
      }
    } catch (...) {  // out of memory while reporting: nothing more can be said
    }
    return false;
  }
}

bool load_toml_deck(const std::string& path, Mission* mission, DeckError* error) {
  return load_toml_deck(path, mission, nullptr, error);
}

}  // namespace tolip::ground
