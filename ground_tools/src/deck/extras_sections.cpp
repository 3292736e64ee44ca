// The deck sections of the optional computations (data blocks 33-37, 41-55) -> DeckExtras.
//
// Shape is checked here (numbers, table monotonicity, counts, the data each option needs); the
// values are kept for the modules that will use them (docs/deck-format.md).
#include <cmath>
#include <string>
#include <vector>

#include "deck_common.hpp"
#include "tolip_ground/deck_table.hpp"
#include "toml_reader.hpp"

namespace tolip::ground::deck_detail {
namespace {

std::string str(int value) { return std::to_string(value); }

// A table sub-section read completely (two arrays, nothing else).
DeckTable read_table(Section& parent, std::string_view key, int block, std::string_view x_key,
                     std::string_view y_key, const std::string& x_what, const std::string& y_what,
                     double y_scale, const std::string& what, bool restarts_at_zero = false) {
  Section section = parent.table(key, block, what);
  const ReadTable read = section.xy(x_key, y_key, block, x_what, y_what, 1, restarts_at_zero);
  section.finish();
  return to_deck_table(read, y_scale);
}

std::optional<DeckTable> read_optional_table(Section& parent, std::string_view key, int block,
                                             std::string_view x_key, std::string_view y_key,
                                             const std::string& x_what, const std::string& y_what,
                                             double y_scale) {
  std::optional<Section> section = parent.optional_table(key, block);
  if (!section) return std::nullopt;
  const ReadTable read = section->xy(x_key, y_key, block, x_what, y_what);
  section->finish();
  return to_deck_table(read, y_scale);
}

// ---- data blocks 33-37 --------------------------------------------------------------------------
// A table the deck gave, into the core's fixed-capacity table (y scaled to core units).
template <int N>
void fill_core_table(Section& section, const DeckTable& deck, double y_scale, int block,
                     const std::string& field, const std::string& what, Table<N>* table) {
  std::string message;
  if (!copy_deck_table(deck, y_scale, what, table, &message)) section.fail(block, field, message);
}

void read_body_dynamics(Section& root, Mission* mission, const FieldTarget& target) {
  const Options& options = mission->options;
  std::optional<Section> section = root.optional_table("body_dynamics", 33);
  const bool six_d = options.body_dynamics_6d() >= 1 || options.dispersions();
  const bool hardover = options.hardover();
  const bool impact = options.impact();
  if (!section) {
    if (six_d || hardover || impact) {
      root.fail(33, "body_dynamics",
                std::string("missing [body_dynamics] (data blocks 33-37): required by ") +
                    (six_d      ? "options.body_dynamics_6d / options.dispersions (IP(6), IP(21))"
                     : hardover ? "options.hardover (IP(22): block 33 words 7, 10, 11, 16 and block 37)"
                                : "options.impact (IP(23): block 33 words 17-19)"));
    }
    return;
  }
  BodyDynamicsBlocks& body = mission->body_dynamics;
  body = BodyDynamicsBlocks{};
  body.present = true;
  target.extras->body_dynamics.present = true;
  const bool all = six_d;
  read_fields(*section, "body_dynamics", target, *mission);
  // S of Sec. 11: DA6D has no word for the area blocks 34-36 are referred to; stage 1's SG1(2).
  body.reference_area_ft2 = mission->vehicle.stages[stage_index(1)].reference_area_ft2;
  auto table = [&](std::string_view key, int block, std::string_view y_key, const std::string& y_what,
                   bool required, const std::string& what, AeroTable* out) {
    DeckTable read;
    if (required) {
      read = read_table(*section, key, block, "mach", y_key, "Mach number", y_what, 1.0,
                        "data block " + str(block) + ": mach and " + std::string(y_key) + " arrays");
    } else if (auto optional =
                   read_optional_table(*section, key, block, "mach", y_key, "Mach number", y_what, 1.0)) {
      read = *optional;
    }
    fill_core_table(*section, read, 1.0, block, "body_dynamics." + std::string(key), what, out);
  };
  table("fin_normal_force", 34, "cn_delta_per_rad_per_fin", "C_N per radian per fin", all,
        "the C_N_delta table (data block 34)", &body.fin_normal_force_per_rad);
  table("pitching_moment", 35, "cm_alpha_per_rad", "C_M per radian of alpha about X_FS", all,
        "the C_M_alpha table (data block 35)", &body.pitching_moment_per_rad);
  table("fin_pitching_moment", 36, "cm_delta_per_rad_per_fin", "C_M per radian per fin about X_FS", all,
        "the C_M_delta table (data block 36)", &body.fin_pitching_moment_per_rad);

  std::optional<Section> cg = section->optional_table("cg", 37);
  if (cg) {
    for (auto&& [key, value] : cg->table()) {
      const std::string name(key.str());
      if (name != "1" && name != "2" && name != "3" && name != "4") {
        cg->fail_at(name, 37,
                    "unknown stage '" + name +
                        "': data block 37 has c.g. tables for stages 1-4 ([body_dynamics.cg.N])");
      }
    }
    for (int stage = 1; stage <= kCgTableStages; ++stage) {
      if (auto read = read_optional_table(*cg, str(stage), 37, "stage_time_s", "station_in",
                                          "stage time in s", "c.g. body station in inches", 1.0)) {
        // The deck's inches become the core's ft here, at the edge.
        fill_core_table(*section, *read, kFeetPerInch, 37, "body_dynamics.cg." + str(stage),
                        "the stage " + str(stage) + " c.g. history (data block 37)",
                        &body.cg_station_ft[stage - 1]);
      }
    }
    cg->finish();
  }
  // Block 37: stage 1 for 6D; stages 1-3 for dispersions ("data for stages 2 and 3 in data blocks
  // 33 and 37") and hardover turns ("#37 all of data").
  const int needed = (options.dispersions() || hardover) ? 3 : (options.body_dynamics_6d() >= 1 ? 1 : 0);
  for (int stage = 1; stage <= needed; ++stage) {
    if (body.cg_station_ft[stage - 1].size() == 0) {
      section->fail(37, section->key_path("cg." + str(stage)),
                    "missing [body_dynamics.cg." + str(stage) + "]: data block 37 c.g. history of stage " +
                        str(stage) + " (stage_time_s, station_in) is required by the selected options");
    }
  }
  section->finish();
}

// ---- data block 41 ------------------------------------------------------------------------------
void read_radar(Section& root, const Options& options, std::vector<RadarStation>* stations) {
  std::vector<Section> entries = root.array_of_tables("radar_station", 41);
  if (options.radar() && entries.empty()) {
    root.fail(41, "radar_station",
              "options.radar (IP(24)) is set: at least one [[radar_station]] (data block 41) is required");
  }
  if (static_cast<int>(entries.size()) > kMaxRadarStations) {
    entries[kMaxRadarStations].fail(
        41, entries[kMaxRadarStations].path(),
        "too many radar stations (" + str(static_cast<int>(entries.size())) + "): at most 20");
  }
  for (Section& entry : entries) {
    RadarStation station;
    const std::optional<std::string> id = entry.optional_text("id", 41, "station identification, 2A6", 12);
    if (!id || id->empty()) entry.missing("id", 41, "the station identification (up to 12 characters)");
    station.id = *id;
    station.name =
        entry.optional_text("name", 41, "station description (not a manual word)", 200).value_or("");
    station.geodetic_latitude_rad =
        entry.number("geodetic_latitude_deg", 41, "geodetic latitude, deg") * kDegToRad;
    station.longitude_rad = entry.number("longitude_deg", 41, "longitude, deg east") * kDegToRad;
    station.altitude_ft = entry.number("altitude_ft", 41, "station altitude, ft");
    if (std::abs(station.geodetic_latitude_rad) > 0.5 * kPi) {
      entry.fail_at("geodetic_latitude_deg", 41, "latitude must be within -90..90 deg");
    }
    entry.finish();
    stations->push_back(station);
  }
}

// ---- data blocks 42-43 --------------------------------------------------------------------------
void read_impact_group(Section& impact, std::string_view key, int block, bool casing, const Mission& mission,
                       bool required, std::array<ImpactDragTable, 3>* tables) {
  std::optional<Section> group = impact.optional_table(key, block);
  if (group) {
    for (auto&& [name_key, value] : group->table()) {
      const std::string name(name_key.str());
      if (name != "1" && name != "2" && name != "3") {
        group->fail_at(name, block,
                       "unknown stage '" + name + "': data block " + str(block) +
                           " has drag tables for stages 1-3 only");
      }
    }
  }
  for (int stage = 1; stage <= 3; ++stage) {
    ImpactDragTable& table = (*tables)[static_cast<std::size_t>(stage - 1)];
    const StageData& data = mission.vehicle.stages[stage_index(stage)];
    std::optional<Section> section = group ? group->optional_table(str(stage), block) : std::nullopt;
    if (!section) {
      if (required && data.in_sequence) {
        impact.fail(block, impact.key_path(std::string(key) + "." + str(stage)),
                    "missing [" + impact.key_path(std::string(key) + "." + str(stage)) +
                        "]: options.impact (IP(23)) needs the data block " + str(block) +
                        " drag table of every stage 1-3 in the sequence");
      }
      continue;
    }
    const ReadTable read = section->xy("mach", "cd", block, "Mach number", "drag coefficient", 2);
    if (read.x.front() != 0.0) {
      section->fail_at("mach", block,
                       "impact drag tables must start at Mach 0 (manual, data blocks 42-43), got " +
                           format_number(read.x.front()));
    }
    table.present = true;
    table.cd_vs_mach = to_deck_table(read);
    table.reference_area_ft2 =
        section->number_or("reference_area_ft2", block,
                           "reference area of the table, ft^2 (extension; default the stage's block 39 area)",
                           data.reference_area_ft2);
    if (!(table.reference_area_ft2 > 0.0))
      section->fail_at("reference_area_ft2", block, "reference area must be positive");
    if (casing) {
      table.casing_weight_lb = section->number_or(
          "casing_weight_lb", block,
          "weight of the expended casing, lb (extension; default the stage's jettison weight)",
          data.jettison_weight_lb);
      if (table.casing_weight_lb < 0.0)
        section->fail_at("casing_weight_lb", block, "casing weight must not be negative");
    }
    section->finish();
  }
  if (group) group->finish();
}

void read_impact(Section& root, const Mission& mission, ImpactData* impact) {
  std::optional<Section> section = root.optional_table("impact", 42);
  const bool required = mission.options.impact();
  if (!section) {
    if (required) {
      root.fail(42, "impact",
                "options.impact (IP(23)) is set: [impact] with failure_drag and casing_drag tables "
                "(data blocks 42-43) is required");
    }
    return;
  }
  impact->present = true;
  read_impact_group(*section, "failure_drag", 42, false, mission, required, &impact->failure_mode);
  read_impact_group(*section, "casing_drag", 43, true, mission, required, &impact->expended_casing);
  section->finish();
}

// ---- data blocks 44-45 --------------------------------------------------------------------------
void read_hardover(Section& root, const Mission& mission, const FieldTarget& target) {
  HardoverData* hardover = &target.extras->hardover;
  std::optional<Section> section = root.optional_table("hardover", 44);
  if (!section) {
    if (mission.options.hardover()) {
      root.fail(44, "hardover",
                "options.hardover (IP(22)) is set: [hardover] (data blocks 44-45) is required");
    }
    return;
  }
  hardover->present = true;
  std::optional<Section> inertia = section->optional_table("pitch_inertia", 44);
  if (!inertia)
    section->missing("pitch_inertia", 44,
                     "[hardover.pitch_inertia.N] I_yy tables of stages 1-3 (data block 44)");
  for (auto&& [key, value] : inertia->table()) {
    const std::string name(key.str());
    if (name != "1" && name != "2" && name != "3") {
      inertia->fail_at(name, 44,
                       "unknown stage '" + name + "': data block 44 has I_yy tables for stages 1-3");
    }
  }
  for (int stage = 1; stage <= 3; ++stage) {
    if (!mission.vehicle.stages[stage_index(stage)].in_sequence) {
      if (auto read = read_optional_table(*inertia, str(stage), 44, "stage_time_s", "iyy_slug_ft2",
                                          "stage time in s", "pitch moment of inertia in slug ft^2", 1.0)) {
        hardover->pitch_inertia_slug_ft2[static_cast<std::size_t>(stage - 1)] = *read;
      }
      continue;
    }
    hardover->pitch_inertia_slug_ft2[static_cast<std::size_t>(stage - 1)] =
        read_table(*inertia, str(stage), 44, "stage_time_s", "iyy_slug_ft2", "stage time in s",
                   "pitch moment of inertia in slug ft^2", 1.0,
                   "data block 44 IYY" + str(stage) + ": stage_time_s and iyy_slug_ft2 arrays");
  }
  inertia->finish();
  hardover->stage1_pitch_damping_per_rad =
      read_table(*section, "pitch_damping", 44, "mach", "cmq_per_rad", "Mach number", "CMQ per radian", 1.0,
                 "data block 44 (stage code 4): stage 1 pitch damping, mach and cmq_per_rad arrays");

  Section p = section->table("parameters", 45, "data block 45: the 26 hardover words");
  read_fields(p, "hardover.parameters", target, mission);
  if (hardover->stage1_min_step_s > hardover->stage1_max_step_s) {
    p.fail_at("stage1_min_step_s", 45, "minimum step (word 5) exceeds the maximum step (word 4)");
  }
  if (hardover->upper_min_step_s > hardover->upper_max_step_s) {
    p.fail_at("upper_min_step_s", 45, "minimum step (word 25) exceeds the maximum step (word 24)");
  }
  p.finish();
  section->finish();
}

// ---- data blocks 46-55 --------------------------------------------------------------------------
// Codes 7-8 and 15-16: `stage` = 4 (default) or 5, stage 5 of a five-stage vehicle (the card's
// stage code; no squeeze).
int read_stage_4_or_5(Section& entry, int code, int block) {
  const int stage =
      entry.optional_integer("stage", block, "stage the code disperses, 4 or 5 (five stages)").value_or(4);
  if (stage != 4 && stage != 5) {
    entry.fail_at("stage", block,
                  "dispersion code " + str(code) + " applies to stage 4, or 5 on a five-stage vehicle");
  }
  return stage;
}

void read_dispersion(Section& entry, int code, DispersionCase* out) {
  const std::string label = "code " + str(code) + " (" + dispersion_name(code) + ")";
  const DispersionCodes& codes = *find_dispersion(code);  // the code was checked by the caller
  const int card_stage = codes.stage_of(code);
  // The TOML keys of the code's data (dispersion_codes()); every block asked for is one of its items.
  const auto item = [&codes](int block, int word = 1) -> const DispersionItem& {
    for (const DispersionItem& candidate : codes.items) {
      if (candidate.block == block && (candidate.word == 0 || candidate.word == word)) return candidate;
    }
    return codes.items.front();
  };
  switch (codes.kind) {
    case DispersionKind::kThrust: {
      out->stage = card_stage;
      if (card_stage < 0) out->stage = read_stage_4_or_5(entry, code, 30);
      // Block 55 first: with it the tables are the stacked stage 4/5 tables of page 22-30, whose
      // stage-5 entries may restart at stage time 0 (the core splits and checks them).
      if (dispersion_takes(code, 55)) {
        if (auto durations = entry.optional_numbers(item(55).key, 55, "stage 4 and 5 durations, s", 2)) {
          out->has_stage_durations = true;
          out->stage4_5_durations_s = {(*durations)[0], (*durations)[1]};
        }
      }
      const bool stacked = out->has_stage_durations;
      const std::string stage =
          stacked ? "stages 4 and 5 (stacked, data block 55)" : "stage " + str(out->stage);
      out->vacuum_thrust_lbf = read_table(
          entry, item(30).key, 30, item(30).x_key, item(30).y_key, "stage time in s", "vacuum thrust in lbf",
          1.0, "data block 30 replacement thrust table of " + stage + " for " + label, stacked);
      out->consumable_weight_lb =
          read_table(entry, item(38).key, 38, item(38).x_key, item(38).y_key, "stage time in s",
                     "consumable weight remaining in lb", 1.0,
                     "data block 38 replacement weight table of " + stage + " for " + label, stacked);
      break;
    }
    case DispersionKind::kWeightIncrement:
      out->stage = card_stage;
      if (card_stage < 0) out->stage = read_stage_4_or_5(entry, code, 47);
      out->weight_increment_lb = entry.number(item(47).key, 47, "jettison weight increment (signed), lb");
      break;
    case DispersionKind::kDrag:
      out->drag_variation_fraction =
          entry.number(item(48).key, 48, "drag variation as a signed fraction (0.xxxx)");
      if (std::abs(out->drag_variation_fraction) >= 1.0) {
        entry.fail_at(item(48).key, 48, "expected a fraction 0.xxxx (|value| < 1)");
      }
      break;
    case DispersionKind::kPitchingMoment:
      out->stage = 1;  // block 35 is stage 1's (no stage code on the card)
      out->pitching_moment_per_rad = read_table(entry, item(35).key, 35, item(35).x_key, item(35).y_key,
                                                "Mach number", "C_M per radian of alpha about X_FS", 1.0,
                                                "the complete data block 35 table for " + label);
      break;
    case DispersionKind::kMisalignment:
      out->stage = card_stage;
      out->misalignment_rad =
          entry.number(item(49).key, 49, "thrust misalignment angle (signed), deg") * kDegToRad;
      out->thrust_station_in = entry.number(item(49, 2).key, 49, "thrust application station, in");
      break;
    case DispersionKind::kDeadband:
      out->stage = card_stage;
      out->deadband_rad =
          entry.number(item(50).key, 50, "control system deadband angle (signed), deg") * kDegToRad;
      break;
    case DispersionKind::kTipoff:
      out->stage = entry.optional_integer("stage", 51, "spun stage of the tip-off, 4 or 5").value_or(4);
      if (out->stage != 4 && out->stage != 5) entry.fail_at("stage", 51, "tip-off applies to stage 4 or 5");
      out->tipoff_rad =
          entry.number(item(51).key, 51, "effective attitude change from tip-off (signed), deg") * kDegToRad;
      break;
    case DispersionKind::kLaunchAzimuth:
      out->stage = 1;  // a launch condition: stage 1 flies it
      out->launch_change_rad =
          entry.number(item(52).key, 52, "launch azimuth change (signed), deg") * kDegToRad;
      break;
    case DispersionKind::kLaunchAttitude:
      out->stage = 1;
      out->launch_change_rad =
          entry.number(item(52).key, 52, "launch attitude change (signed), deg") * kDegToRad;
      break;
    case DispersionKind::kWinds:
      out->wind_speed_ft_s =
          read_table(entry, item(53).key, 53, item(53).x_key, item(53).y_key, "altitude in ft",
                     "wind speed in ft/s", 1.0, "data block 53 WINDVL table for " + label);
      out->wind_azimuth_rad = read_table(entry, item(54).key, 54, item(54).x_key, item(54).y_key,
                                         "altitude in ft", "azimuth of the wind vector in deg from north",
                                         kDegToRad, "data block 54 WINDAZ table for " + label);
      break;
    case DispersionKind::kSummary: break;
  }
}

void read_dispersions(Section& root, const Options& options, std::vector<DispersionCase>* dispersions) {
  std::vector<Section> entries = root.array_of_tables("dispersion", 46);
  if (options.dispersions() && entries.empty()) {
    root.fail(46, "dispersion",
              "options.dispersions (IP(21)) is set: at least one [[dispersion]] (data block 46) is required");
  }
  int previous = 0;
  for (Section& entry : entries) {
    DispersionCase dispersion;
    dispersion.code = entry.integer("code", 46, "dispersion trajectory code 1-38 or 40");
    if (dispersion_name(dispersion.code) == nullptr) {
      entry.fail_at("code", 46,
                    "unknown dispersion code " + str(dispersion.code) +
                        ": expected 1-38 (the manual's dispersion table) or 40 (three-sigma summary)");
    }
    if (dispersion.code <= previous) {
      entry.fail_at("code", 46,
                    "dispersion codes must be given in increasing order: " + str(dispersion.code) +
                        " follows " + str(previous));
    }
    previous = dispersion.code;
    dispersion.title = entry.optional_text("title", 46, "data block 46 title, 2A6", 12).value_or("");
    read_dispersion(entry, dispersion.code, &dispersion);
    entry.finish();
    dispersions->push_back(std::move(dispersion));
  }
}

}  // namespace

void read_extras_sections(Section& root, Mission* mission_data, DeckExtras* extras) {
  FieldTarget target;
  target.mission = mission_data;  // blocks 33-37, in core units
  target.extras = extras;         // block 33's words the core does not hold, block 45
  read_body_dynamics(root, mission_data, target);
  const Mission& mission = *mission_data;
  read_radar(root, mission.options, &extras->radar_stations);
  read_impact(root, mission, &extras->impact);
  read_hardover(root, mission, target);
  read_dispersions(root, mission.options, &extras->dispersions);
}

}  // namespace tolip::ground::deck_detail
