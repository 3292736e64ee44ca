// The deck sections that fill the core's Mission (data blocks 1-40; docs/deck-format.md).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "deck_common.hpp"
#include "toml_reader.hpp"

namespace tolip::ground::deck_detail {
namespace {

std::string str(int value) { return std::to_string(value); }

// At most `capacity` characters, ending at the first NUL (the 12A6 / 2A6 fields of blocks 1-3).
std::string text_within(const std::string& text, std::size_t capacity) {
  return text.substr(0, std::min(capacity, text.find('\0')));
}

template <int N>
void fill_table(Section& section, std::string_view x_key, const ReadTable& read, double y_scale,
                int data_block, const std::string& capacity_note, Table<N>* table) {
  table->clear();
  if (static_cast<int>(read.x.size()) > N) {
    section.fail_at(x_key, data_block,
                    "table has " + str(static_cast<int>(read.x.size())) + " points; at most " + str(N) +
                        " allowed (" + capacity_note + ")");
  }
  for (std::size_t i = 0; i < read.x.size(); ++i) {
    const Status status = table->append(read.x[i], read.y[i] * y_scale);
    if (!ok(status)) {
      section.fail_at(x_key, data_block, std::string(status_name(status)) + ": " + status_message(status));
    }
  }
  const Status status = table->finalize();
  if (!ok(status)) {
    section.fail_at(x_key, data_block, std::string(status_name(status)) + ": " + status_message(status));
  }
}

// ---- data blocks 1-3 ----------------------------------------------------------------------------
// The listing's texts: ground side (DeckListingOptions), never in the core's Mission.
void read_case(Section& root, DeckListingOptions* listing) {
  Section section = root.table("case", 1, "data blocks 1-3: title, case heading and date");
  const std::optional<std::string> title =
      section.optional_text("title", 1, "data block 1 main heading, 12A6", 72);
  if (!title) section.missing("title", 1, "the main heading (data block 1, up to 72 characters)");
  listing->title = text_within(*title, 72);
  listing->case_heading = text_within(
      section.optional_text("heading", 2, "data block 2 case heading, 12A6", 72).value_or(""), 72);
  listing->date =
      text_within(section.optional_text("date", 3, "data block 3 date, 2A6", 12).value_or(""), 12);
  section.finish();
}

// ---- data block 4 -------------------------------------------------------------------------------
void read_options(Section& root, const FieldTarget& target) {
  std::optional<Section> section = root.optional_table("options", 4);
  if (!section) return;
  read_fields(*section, "options", target, *target.mission);
  section->finish();
  const Options& options = target.mission->options;
  if (options.ip[6] == 1 && options.ip[7] != 1) {
    section->fail_at(
        "body_dynamics_6d", 4,
        "IP(6) = 1 (6D after successful linearization) requires linearization = true (IP(7) = 1)");
  }
}

// A table of scalar fields (field_description.hpp), optional in the deck.
void read_field_section(Section& root, const char* name, int data_block, const FieldTarget& target) {
  std::optional<Section> section = root.optional_table(name, data_block);
  if (!section) return;
  read_fields(*section, name, target, *target.mission);
  section->finish();
}

// ---- data blocks 5, 32 and the payload ---------------------------------------------------------
void read_vehicle(Section& root, Vehicle* vehicle) {
  Section section = root.table("vehicle", 5, "data block 5 (stage sequence) and the payload");
  std::vector<int> codes = section.integers("sequence", 5, "stage codes in flight order");
  if (!codes.empty() && codes.back() == 0) codes.pop_back();  // the card's terminating 0
  if (codes.empty()) {
    section.fail_at(
        "sequence", 5,
        "empty stage sequence: expected at least stage 1 (the order 1 6 2 7 3 8 4 9 5 10, coasts optional)");
  }
  if (static_cast<int>(codes.size()) > kMaxStages) {
    section.fail_at("sequence", 5,
                    "too many stages (" + str(static_cast<int>(codes.size())) +
                        "): at most 10 codes, in the order 1 6 2 7 3 8 4 9 5 10");
  }
  Reader& reader = section.reader();
  for (std::size_t k = 0; k < codes.size(); ++k) {
    const int code = codes[k];
    const int line = section.element_line("sequence", k);
    const std::string field = section.key_path("sequence") + "[" + str(static_cast<int>(k)) + "]";
    if (code == 0) {
      reader.fail(line, 5, field, "0 ends the sequence and may appear only last");
    }
    if (!is_powered_stage(code) && !is_coast_stage(code)) {
      reader.fail(line, 5, field,
                  "unknown stage code " + str(code) +
                      ": expected 1-5 (powered stages) or 6-10 (the coasts after stages 1-5)");
    }
    const int previous = (k == 0) ? 0 : codes[k - 1];
    if (!may_follow_in_sequence(previous, code)) {
      std::string expected = "1";
      if (is_powered_stage(previous)) {
        expected = previous < kMaxPoweredStages ? str(previous + 1) + " or its coast " + str(previous + 5)
                                                : "its coast " + str(previous + 5);
      } else if (previous != 0) {
        expected = str(previous - 4);
      }
      reader.fail(line, 5, field,
                  "stage code " + str(code) + " cannot be at position " + str(static_cast<int>(k) + 1) +
                      ": the sequence keeps the order 1 6 2 7 3 8 4 9 5 10 starting with 1, each coast "
                      "n+5 directly after its stage n, coasts optional (expected " +
                      expected + " here)");
    }
    vehicle->sequence.codes[k] = code;
  }
  vehicle->sequence.count = static_cast<int>(codes.size());
  for (int k = 0; k < vehicle->sequence.count; ++k) {
    vehicle->stages[stage_index(vehicle->sequence.codes[k])].in_sequence = true;
  }

  vehicle->payload_lb = section.number(
      "payload_lb", 39, "payload weight in lb, carried in the jettison weight of the last powered stage");

  if (std::optional<Section> lift = section.optional_table("lift_curve_slope", 32)) {
    const ReadTable read = lift->xy("mach", "cl_alpha_per_rad", 32, "Mach number", "C_L per radian of alpha");
    fill_table(*lift, "mach", read, 1.0, 32, "data block 32, 42E12.8: 20 pairs",
               &vehicle->lift_curve_slope_per_rad);
    std::vector<int> used = {1, 6};
    if (lift->has("used_in_stages")) {
      used = lift->integers("used_in_stages", 32, "stage codes using the lift table (1 and/or 6)");
    }
    for (std::size_t i = 0; i < used.size(); ++i) {
      if (used[i] != 1 && used[i] != 6) {
        section.reader().fail(lift->element_line("used_in_stages", i), 32,
                              lift->key_path("used_in_stages") + "[" + str(static_cast<int>(i)) + "]",
                              "stage " + str(used[i]) +
                                  " cannot use the lift table: data block 32 is used in stages 1 and 6 only");
      }
      vehicle->stages[stage_index(used[i])].uses_lift_table = true;
    }
    lift->finish();
  }
  section.finish();
}

// ---- data blocks 16, 30, 31, 38, 39 -------------------------------------------------------------
// The description of a stage field (data blocks 16, 39).
const FieldDescription& stage_field(const char* key) {
  const FieldDescription* field = find_field("stage.1", key);
  return *field;  // every key asked for here is described (field_description.cpp)
}

void read_stage(Section& section, int code, const FieldTarget& target, StageData* stage) {
  const bool powered = is_powered_stage(code);
  const std::string kind = powered ? "powered stage " + str(code) : "coast " + str(code);
  const Mission& options = *target.mission;
  if (std::optional<std::string> name =
          section.optional_text("name", 16, "description of the stage (not a manual word)", 200)) {
    if (target.extras != nullptr)
      target.extras->listing.stage_names[static_cast<std::size_t>(stage_index(code))] = *name;
  }
  read_field(section, stage_field("integration_steps"), target, options, code);
  read_field(section, stage_field("jettison_weight_lb"), target, options, code);
  if (powered) {
    read_field(section, stage_field("nozzle_exit_area_ft2"), target, options, code);
  } else if (section.has("nozzle_exit_area_ft2")) {
    section.fail_at(
        "nozzle_exit_area_ft2", 39,
        "a coast has no nozzle: data block 39 gives coasts only the jettison weight and the reference area");
  }
  read_field(section, stage_field("reference_area_ft2"), target, options, code);

  if (powered) {
    Section thrust =
        section.table("thrust", 30, "data block 30: time_s and vacuum_thrust_lbf arrays of " + kind);
    const ReadTable thrust_read =
        thrust.xy("time_s", "vacuum_thrust_lbf", 30, "stage time in s", "vacuum thrust in lbf", 2);
    fill_table(thrust, "time_s", thrust_read, 1.0, 30,
               "data block 30: 120 thrust points for all stages together", &stage->vacuum_thrust_lbf);
    thrust.finish();

    Section weight =
        section.table("consumable_weight", 38, "data block 38: time_s and remaining_lb arrays of " + kind);
    const ReadTable weight_read =
        weight.xy("time_s", "remaining_lb", 38, "stage time in s", "consumable weight remaining in lb", 2);
    fill_table(weight, "time_s", weight_read, 1.0, 38,
               "data block 38: 120 weight points for all stages together", &stage->consumable_weight_lb);
    weight.finish();

    // A powered stage burns to the end of its thrust table unless the deck says otherwise.
    const FieldDescription& duration = stage_field("duration_s");
    stage->duration_s = section.number_or(duration.key, duration.block, what_of(duration, code),
                                          stage->vacuum_thrust_lbf.last_x());
  } else {
    for (const char* key : {"thrust", "consumable_weight"}) {
      if (section.has(key)) {
        section.fail_at(key, std::string(key) == "thrust" ? 30 : 38,
                        "a coast has no thrust or consumable-weight table (data blocks 30 and 38 are for "
                        "powered stages 1-5)");
      }
    }
    const FieldDescription& duration = stage_field("duration_s");  // a coast has no table to end it
    stage->duration_s = section.number(duration.key, duration.block, what_of(duration, code));
  }

  // Data block 31: the manual stores drag tables for stages 1, 6 and 2 only (TD1, TD6, TD2, a
  // storage limit of 1966); any powered or coast stage may have one here (issue 17), so a vehicle
  // whose upper stages still fly in the atmosphere has their drag.
  if (std::optional<Section> drag = section.optional_table("drag", 31)) {
    const ReadTable read = drag->xy("mach", "cd", 31, "Mach number", "drag coefficient at alpha = 0");
    fill_table(*drag, "mach", read, 1.0, 31, "data block 31: 20 pairs", &stage->drag_coefficient);
    drag->finish();
  }
  section.finish();
}

void read_stages(Section& root, const FieldTarget& target) {
  Vehicle* vehicle = &target.mission->vehicle;
  Section stages = root.table(
      "stage", 16,
      "one [stage.N] table for every stage code N of the sequence (data blocks 16, 30, 31, 38, 39)");
  for (auto&& [key, value] : stages.table()) {
    const std::string name(key.str());
    bool known = false;
    for (int code = 1; code <= kMaxStages; ++code) known = known || name == str(code);
    if (!known) {
      int line = static_cast<int>(key.source().begin.line);
      if (line == 0) line = line_of_node(value);
      stages.reader().fail(
          line, 16, stages.key_path(name),
          "unknown stage code '" + name +
              "': expected [stage.N] with N = 1-5 (powered stages) or 6-10 (the coasts after stages 1-5)");
    }
  }
  for (int code = 1; code <= kMaxStages; ++code) {
    StageData* stage = &vehicle->stages[stage_index(code)];
    std::optional<Section> section = stages.optional_table(str(code), 16);
    if (section) {
      read_stage(*section, code, target, stage);
    } else if (stage->in_sequence) {
      stages.fail(16, stages.key_path(str(code)),
                  "stage " + str(code) + " is in the sequence (data block 5) but [stage." + str(code) +
                      "] is missing: expected its duration and integration steps (data block 16)" +
                      (is_powered_stage(code)
                           ? ", jettison weight (39), thrust (30) and consumable weight (38) tables"
                           : ""));
    }
  }
  stages.finish();
}

// ---- data blocks 20, 21 -------------------------------------------------------------------------
bool read_launch(Section& root, const FieldTarget& target) {
  Section section =
      root.table("launch", 20, "data blocks 20-21: lift-off time, launch date and initial conditions");
  read_fields(section, "launch", target, *target.mission);
  const bool has_date = section.has("space_age_date_days");
  section.finish();
  return has_date;
}

// ---- data block 22 ------------------------------------------------------------------------------
void read_control(Section& root, const FieldTarget& target) {
  if (target.mission->options.zero_alpha_window() && !root.has("control_constraints")) {
    root.fail(22, "control_constraints",
              "option zero_alpha_window (IP(11)) needs [control_constraints] with zero_alpha_start_s and "
              "zero_alpha_end_s (data block 22)");
  }
  read_field_section(root, "control_constraints", 22, target);
}

// ---- data blocks 8, 19, 29 ----------------------------------------------------------------------
// Returns true when a constraint needs the launch date (inertial longitude reference).
bool read_constraints(Section& root, const Options& options, const Vehicle& vehicle, ConstraintList* list) {
  std::string sequence;
  for (int k = 0; k < vehicle.sequence.count; ++k) {
    if (k > 0) sequence += ' ';
    sequence += str(vehicle.sequence.codes[k]);
  }
  std::vector<Section> entries = root.array_of_tables("constraint", 8);
  if (entries.empty()) {
    root.fail(
        8, "constraint",
        "missing [[constraint]] entries: data block 8 needs at least the payoff (code 0 payload, 1 or 5 "
        "velocity, 7 altitude) as the first entry");
  }
  std::vector<int> codes;
  for (Section& entry : entries) codes.push_back(entry.integer("code", 8, "data block 8 constraint code"));
  const bool heating_listed = codes.size() > 1 && codes.back() == 14;
  const int count = static_cast<int>(codes.size()) - (heating_listed ? 1 : 0);
  if (count > kMaxConstraints) {
    entries[kMaxConstraints].fail_at("code", 8,
                                     "too many constraints (" + str(count) +
                                         "): data block 8 takes at most 13 "
                                         "including the payoff (IB3(2..14)), plus the heating code 14 last");
  }
  bool needs_date = false;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    Section& entry = entries[i];
    const int code = codes[i];
    ConstraintUnit unit{};
    const bool stage_point = code >= 15 && code <= 99;
    if (!constraint_unit(code, &unit) ||
        (stage_point && !vehicle.stages[stage_index(code / 10)].in_sequence)) {
      const std::string why = stage_point && constraint_unit(code, &unit)
                                  ? " (stage " + str(code / 10) + " is not in the sequence " + sequence + ")"
                                  : "";
      entry.fail_at("code", 8,
                    "unknown constraint code " + str(code) + why +
                        ": expected 0-13 (terminal), 14 (heating, last), X5-X9 (at the end of stage X of "
                        "the sequence " +
                        sequence + ") or 100-102");
    }
    if (code == 14 && i + 1 != entries.size()) {
      entry.fail_at("code", 8, "the heating constraint (code 14) must be the last entry");
    }
    if (code == 0 && i != 0)
      entry.fail_at("code", 8, "payload (code 0) can only be the payoff, the first entry");
    for (std::size_t j = 0; j < i; ++j) {
      if (codes[j] == code) entry.fail_at("code", 8, "constraint code " + str(code) + " is listed twice");
    }
    const std::string desired_key = std::string("desired_") + unit.suffix;
    const std::string optimization_key = std::string("deadband_optimization_") + unit.suffix;
    const std::string linearization_key = std::string("deadband_linearization_") + unit.suffix;
    list->codes[i] = code;
    if (i == 0) {
      const int payoff = options.payoff();
      const bool consistent = (payoff == 0 && code == 0) || (payoff == 1 && (code == 1 || code == 5)) ||
                              (payoff == 2 && code == 7);
      if (!consistent) {
        entry.fail_at("code", 8,
                      "the first entry is the payoff and must match options.payoff (IP(1) = " + str(payoff) +
                          "): expected code " +
                          (payoff == 0   ? std::string("0 (payload)")
                           : payoff == 1 ? std::string("1 or 5 (velocity)")
                                         : std::string("7 (altitude)")) +
                          ", got " + str(code));
      }
      list->desired[0] =
          entry.number_or(desired_key, 19,
                          "DA4(1), the payoff entry (a placeholder) in " + std::string(unit.suffix), 0.0) *
          unit.to_core;
      for (const std::string& key : {optimization_key, linearization_key}) {
        if (entry.has(key)) {
          entry.fail_at(key, 29,
                        "the payoff has no deadband: data block 29 lists the constraints after the payoff");
        }
      }
    } else {
      const std::string name = std::string(unit.name) + " (code " + str(code) + ")";
      list->desired[i] =
          entry.number(desired_key, 19, "DA4 desired " + name + " in " + unit.suffix) * unit.to_core;
      list->deadband_optimization[i - 1] =
          entry.number(optimization_key, 29,
                       "DA14 allowed deviation of " + name + " during optimization, " + unit.suffix) *
          unit.to_core;
      const std::string lin_what =
          "DA14(13+n) allowed deviation of " + name + " during linearization, " + unit.suffix;
      list->deadband_linearization[i - 1] =
          (options.linearization() ? entry.number(linearization_key, 29, lin_what)
                                   : entry.number_or(linearization_key, 29, lin_what, 0.0)) *
          unit.to_core;
    }
    entry.finish();
    if (code == 12 || code == 101) needs_date = true;
  }
  list->count = count;
  if (options.heating_constraint() && !heating_listed) {
    root.fail(8, "constraint",
              "options.heating_constraint (IP(2)) is set: the heating constraint code 14 must be the last "
              "[[constraint]]");
  }
  if (heating_listed && !options.heating_constraint()) {
    entries.back().fail_at(
        "code", 8, "the heating constraint (code 14) needs options.heating_constraint = true (IP(2))");
  }
  return needs_date;
}

// ---- data blocks 6, 27 --------------------------------------------------------------------------
void read_adjustable(Section& root, AdjustableParameters* adjustable) {
  std::vector<Section> entries = root.array_of_tables("adjustable_parameter", 6);
  if (static_cast<int>(entries.size()) > kMaxAdjustableParameters) {
    entries[kMaxAdjustableParameters].fail_at(
        "code", 6,
        "too many adjustable parameters (" + str(static_cast<int>(entries.size())) + "): at most 11");
  }
  for (std::size_t i = 0; i < entries.size(); ++i) {
    Section& entry = entries[i];
    const int code = entry.integer("code", 6, "data block 6 adjustable parameter code 1-11");
    if (code < 1 || code > 11) {
      entry.fail_at("code", 6,
                    "unknown adjustable parameter code " + str(code) +
                        ": expected 1-11 (1/2 stage-4 theta/chi, 3/4/5 coasts after stages 3/2/1, 6 launch "
                        "azimuth, 7 launch time, 8/9 stage-5 theta/chi, 10/11 coasts after stages 4/5)");
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (adjustable->codes[j] == code)
        entry.fail_at("code", 6, "adjustable parameter code " + str(code) + " is listed twice");
    }
    const double weight = entry.number("weight", 27, "data block 27 DA12 weighting constant");
    if (!(weight > 0.0))
      entry.fail_at("weight", 27, "weighting constant must be positive, got " + format_number(weight));
    adjustable->codes[i] = code;
    adjustable->weights[i] = weight;
    entry.finish();
  }
  adjustable->count = static_cast<int>(entries.size());
}

// ---- data blocks 18, 26 -------------------------------------------------------------------------
void read_linearization(Section& root, const Mission& mission, LinearizationData* linearization) {
  std::optional<Section> section = root.optional_table("linearization", 18);
  if (!section) {
    if (mission.options.linearization()) {
      root.fail(18, "linearization",
                "options.linearization (IP(7)) is set: [linearization] with coded_times (data block 18) is "
                "required");
    }
    return;
  }
  const std::vector<double> times = section->numbers(
      "coded_times", 18, "TLIN times coded 100 n + t (n powered stage, t s from its ignition)");
  if (times.size() < 2) {
    section->fail_at("coded_times", 18, "expected at least 2 coded times (the start and end of one segment)");
  }
  if (static_cast<int>(times.size()) > kMaxLinearSegments + 1) {
    section->fail_at("coded_times", 18,
                     "too many coded times (" + str(static_cast<int>(times.size())) +
                         "): at most 16 (15 segments, data block 18)");
  }
  Reader& reader = section->reader();
  for (std::size_t i = 0; i < times.size(); ++i) {
    const std::string field = section->key_path("coded_times") + "[" + str(static_cast<int>(i)) + "]";
    const int line = section->element_line("coded_times", i);
    const SegmentBoundary boundary = decode_coded_time(times[i]);
    const int code = boundary.stage;
    const double t = boundary.time_from_ignition_s;
    if (code < 1 || code > kMaxPoweredStages || !mission.vehicle.stages[stage_index(code)].in_sequence) {
      reader.fail(line, 18, field,
                  "coded time " + format_number(times[i]) +
                      " does not name a powered stage of the sequence: expected 100 n + t with n = 1-5");
    }
    // A stage duration that is not positive is the stage's fault (data block 16, validate_mission).
    const double duration = mission.vehicle.stages[stage_index(code)].duration_s;
    if (duration > 0.0 && t > duration + mission.constants.time_epsilon_s) {
      reader.fail(line, 18, field,
                  "coded time " + format_number(times[i]) + " is " + format_number(t) + " s into stage " +
                      str(code) + ", after its burnout at " + format_number(duration) + " s");
    }
    if (i > 0 && !(times[i] > times[i - 1])) {
      reader.fail(line, 18, field,
                  "coded times must increase: " + format_number(times[i]) + " follows " +
                      format_number(times[i - 1]));
    }
    linearization->boundaries[i] = boundary;
  }
  const int segments = static_cast<int>(times.size()) - 1;
  if (const std::optional<int> count =
          section->optional_integer("segment_count", 18, "TLIN(1) number of linear segments")) {
    if (*count != segments) {
      section->fail_at("segment_count", 18,
                       "TLIN(1) = " + str(*count) + " but " + str(static_cast<int>(times.size())) +
                           " coded times make " + str(segments) +
                           " segments (one coast segment between consecutive powered stages)");
    }
  }
  linearization->segment_count = segments;
  for (int i = 0; i < kMaxLinearSegments; ++i) linearization->segment_weights[i] = i < segments ? 1.0 : 0.0;
  if (const auto weights =
          section->optional_numbers("segment_weights", 26, "ETALIN weighting constant per segment")) {
    if (static_cast<int>(weights->size()) != segments) {
      section->fail_at("segment_weights", 26,
                       "expected one weight per segment (" + str(segments) + "), got " +
                           str(static_cast<int>(weights->size())));
    }
    for (int i = 0; i < segments; ++i) {
      const double weight = (*weights)[static_cast<std::size_t>(i)];
      if (!(weight > 0.0)) {
        reader.fail(section->element_line("segment_weights", static_cast<std::size_t>(i)), 26,
                    section->key_path("segment_weights") + "[" + str(i) + "]",
                    "segment weight must be positive, got " + format_number(weight));
      }
      linearization->segment_weights[i] = weight;
    }
  }
  section->finish();
}

// ---- data block 9 -------------------------------------------------------------------------------
void read_output_frequency(Section& root, OutputFrequency* output) {  // ground side: listing thinning
  std::optional<Section> section = root.optional_table("output_frequency", 9);
  if (!section) return;
  struct Entry {
    const char* key;
    int* values;
    const char* what;
  };
  const Entry entries[] = {
      {"initial", output->initial.data(), "IB4 output every n-th point on the initial trajectory"},
      {"intermediate", output->intermediate.data(),
       "IB4 output every n-th point on intermediate trajectories"},
      {"final", output->final_trajectory.data(), "IB4 output every n-th point on the final trajectory"},
  };
  for (const Entry& entry : entries) {
    const toml::node* node = section->node(entry.key);
    if (node == nullptr) continue;
    std::vector<int> values;
    if (node->is_integer()) {
      values.assign(kMaxStages, section->integer(entry.key, 9, entry.what));
    } else {
      values = section->integers(entry.key, 9, std::string(entry.what) + ", per stage code 1-10");
      if (static_cast<int>(values.size()) != kMaxStages) {
        section->fail_at(entry.key, 9,
                         "expected one integer for all stages or an array of 10 (stage codes 1-10), got " +
                             str(static_cast<int>(values.size())) + " values");
      }
    }
    for (int i = 0; i < kMaxStages; ++i) {
      if (values[static_cast<std::size_t>(i)] < 1) {
        section->fail_at(entry.key, 9,
                         "output frequency must be at least 1 (every computed point), got " +
                             str(values[static_cast<std::size_t>(i)]));
      }
      entry.values[i] = values[static_cast<std::size_t>(i)];
    }
  }
  section->finish();
}

// ---- data block 40 ------------------------------------------------------------------------------
void read_pitch_program(Section& root, PitchTable* pitch) {
  Section section =
      root.table("pitch_program", 40, "data block 40: time_s (from launch) and theta_deg arrays");
  const ReadTable read =
      section.xy("time_s", "theta_deg", 40, "time from launch in s", "pitch attitude theta in deg");
  fill_table(section, "time_s", read, kDegToRad, 40, "data block 40, 32E12.8: 15 pairs", pitch);
  section.finish();
}

}  // namespace

void read_mission_sections(Section& root, Mission* mission, DeckExtras* extras) {
  FieldTarget target;
  target.mission = mission;
  target.extras = extras;
  read_case(root, &extras->listing);
  read_options(root, target);
  read_field_section(root, "constants", 10, target);
  read_field_section(root, "atmosphere", 11, target);
  read_vehicle(root, &mission->vehicle);
  read_stages(root, target);
  const bool has_date = read_launch(root, target);
  read_control(root, target);
  read_field_section(root, "misc", 17, target);
  const bool needs_date = read_constraints(root, mission->options, mission->vehicle, &mission->constraints);
  if (needs_date && !has_date) {
    root.fail(20, "launch.space_age_date_days",
              "a constraint uses an inertial longitude reference (code 12 or 101): the launch date DA5(2) "
              "space_age_date_days is required (data block 20)");
  }
  read_adjustable(root, &mission->adjustable);
  read_linearization(root, *mission, &mission->linearization);
  read_field_section(root, "convergence", 28, target);
  read_output_frequency(root, &extras->listing.output);
  read_pitch_program(root, &mission->pitch_program_rad);
}

}  // namespace tolip::ground::deck_detail
