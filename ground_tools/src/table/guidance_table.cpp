// Ground side of the guidance table image: contents from a case (linearized program or data
// block 40), the C header, the inspect listing (guidance_table.hpp).
#include "tolip_ground/guidance_table.hpp"

#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <iterator>
#include <sstream>

#include "tolip/core/constants.hpp"
#include "tolip_ground/capped_read.hpp"
#include "tolip_ground/version.hpp"

namespace tolip::ground {

double table_max_deflection_rad(const DeckExtras& extras) {
  return (extras.hardover.present && extras.hardover.stage1_fin_vane_deflection_rad > 0.0)
             ? extras.hardover.stage1_fin_vane_deflection_rad
             : kDefaultMaxDeflectionRad;
}
namespace {

// The stage of the timeline that holds time `t` from launch: [start, start + duration), the later
// stage at a boundary; nullptr past the end of the last stage.
const StageTimeline* stage_at(const PreparedCase& prepared, double t) {
  for (int i = prepared.stage_count - 1; i >= 0; --i) {
    const StageTimeline& line = prepared.timeline[i];
    if (t >= line.start_s) return (t < line.start_s + line.duration_s) ? &line : nullptr;
  }
  return nullptr;
}

std::string degrees(double rad, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, rad * kRadToDeg);
  return buffer;
}

std::string fixed(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

std::string utc_stamp(std::int64_t unix_s) {
  const std::time_t t = static_cast<std::time_t>(unix_s);
  std::tm tm{};
  if (gmtime_r(&t, &tm) == nullptr) return "?";
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buffer;
}

void copy_text(const std::string& text, char* out, std::size_t capacity) {
  std::size_t i = 0;
  for (; i < text.size() && i < capacity; ++i) out[i] = text[i];
  for (; i <= capacity; ++i) out[i] = '\0';
}

}  // namespace

std::string default_mission_id(const DeckListingOptions& listing) {
  std::string id;
  bool blank = false;
  for (std::size_t i = 0; i < listing.title.size() && listing.title[i] != '\0'; ++i) {
    char c = listing.title[i];
    if (c == ' ' || c == '\t') {
      blank = !id.empty();
      continue;
    }
    if (c < 0x20 || c > 0x7E) c = '?';
    if (blank) id += ' ';
    blank = false;
    id += c;
  }
  if (id.size() > kTableMissionIdBytes) id.resize(kTableMissionIdBytes);
  while (!id.empty() && id.back() == ' ') id.pop_back();
  return id.empty() ? std::string("TOLIP CASE") : id;
}

bool build_guidance_table(const Mission& mission, const DeckExtras& extras, const PreparedCase& prepared,
                          const LinearProgram* linearized, const TableBuildOptions& options,
                          GuidanceTable* table, std::string* error) {
  auto fail = [error](const std::string& message) {
    if (error != nullptr) *error = message;
    return false;
  };
  if (!prepared.prepared) return fail("the case was not prepared (prepare_case) before building the table");

  GuidanceTable t;
  // Header.
  const std::string id = options.mission_id.empty() ? default_mission_id(extras.listing) : options.mission_id;
  if (id.empty() || id.size() > kTableMissionIdBytes) {
    return fail("the mission identifier must have 1 to 32 characters, got " + std::to_string(id.size()));
  }
  for (char c : id) {
    if (c < 0x20 || c > 0x7E) return fail("the mission identifier must be printable ASCII");
  }
  copy_text(id, t.mission_id, kTableMissionIdBytes);
  copy_text(version_string(), t.generator_version, kTableGeneratorVersionBytes);
  t.created_unix_s = options.created_unix_s;

  // Data block 20: the vertical lift-off.
  t.liftoff_duration_s = mission.launch.liftoff_duration_s;

  // Data block 22: pitch-rate limits.
  if (!(mission.control.max_pitch_rate_rad_s > 0.0)) {
    return fail(
        "data block 22, field control_constraints.max_pitch_rate_deg_s (DA7(3)): the table image needs a "
        "positive maximum pitch rate");
  }
  t.max_pitch_rate_rad_s = mission.control.max_pitch_rate_rad_s;
  t.min_pitch_rate_rad_s = mission.control.min_pitch_rate_rad_s;
  t.min_pitch_rate_change_rad_s = mission.control.min_pitch_rate_change_rad_s;

  // Data block 45 word 11 (stage 1 fin and vane deflection), else the documented default.
  t.max_deflection_rad = table_max_deflection_rad(extras);

  // Data block 17 and IP(9): spun stages hold their attitudes (IP(9) = 1 spins stage 5 on stage 4's);
  // stages 4 and 5 that IP(9) leaves continuous fly segments, and their attitude words are zero.
  const Options& o = mission.options;
  const int spin = o.spin_stages_4_5();
  t.spin_option = spin;
  const SpunAttitude spun4 = spun_stage_attitude(o, mission.misc, 4);
  const SpunAttitude spun5 = spun_stage_attitude(o, mission.misc, 5);
  t.stage4_theta_rad = o.stage_is_spun(4) ? spun4.theta_rad : 0.0;
  t.stage4_chi_rad = o.stage_is_spun(4) ? spun4.chi_rad : 0.0;
  t.stage5_theta_rad = o.stage_is_spun(5) ? spun5.theta_rad : 0.0;
  t.stage5_chi_rad = o.stage_is_spun(5) ? spun5.chi_rad : 0.0;

  // Data block 33: autopilot gains of stages 1-3; the coasts 6-8 keep the gains of the stage
  // before them; spun stages and the coasts after them have none. Data block 33 has no gains for
  // stages 4 and 5 (the manual's vehicle spins them): a continuous stage 4 or 5, and the coast
  // after it, takes stage 3's, the last stage the deck gives (our choice, docs/table-format.md).
  if (!mission.body_dynamics.present) {
    return fail(
        "data block 33 ([body_dynamics], DA6D(1-6)) is required: it gives the autopilot gains K_theta "
        "and K_q of stages 1-3 that the table image carries");
  }
  for (int k = 0; k < 3; ++k) {
    const StageGains gains{mission.body_dynamics.position_gain[k], mission.body_dynamics.rate_gain_s[k]};
    t.gains[stage_index(k + 1)] = gains;
    t.gains[stage_index(k + 6)] = gains;
  }
  for (int code : {4, 5}) {
    if (o.stage_is_spun(code)) continue;
    t.gains[stage_index(code)] = t.gains[stage_index(3)];
    t.gains[stage_index(code + 5)] = t.gains[stage_index(3)];
  }

  std::vector<GuidanceSegment> segments;
  auto add_segment = [&](double t_from_launch, double theta, double rate) {
    const StageTimeline* line = stage_at(prepared, t_from_launch);
    if (line == nullptr || !is_segment_stage(spin, line->code)) return;
    segments.push_back(GuidanceSegment{line->code, t_from_launch - line->start_s, theta, rate});
  };
  const std::string source = linearized != nullptr ? "the linearized pitch program" : "data block 40";
  if (linearized != nullptr) {
    // The linearized program (Sec. 6, 10): its segments, then its last value held.
    const LinearProgram& p = *linearized;
    if (p.segment_count < 1 || p.segment_count > kMaxLinearSegments) {
      return fail("the linearized pitch program has " + std::to_string(p.segment_count) + " segments (1 to " +
                  std::to_string(kMaxLinearSegments) + " expected)");
    }
    for (int s = 0; s < p.segment_count; ++s) add_segment(p.break_time_s[s], p.theta_rad[s], p.rate_rad_s[s]);
    add_segment(p.break_time_s[p.segment_count], p.theta_rad[p.segment_count], 0.0);
  } else {
    // Data block 40: the segments (without linearization).
    const PitchTable& pitch = mission.pitch_program_rad;
    if (pitch.size() == 0) return fail("data block 40 (pitch_program) is empty: no segment can be built");
    const double liftoff = mission.launch.liftoff_duration_s;
    if (pitch.x(0) > liftoff) add_segment(liftoff, pitch.y(0), 0.0);
    for (int i = 0; i + 1 < pitch.size(); ++i) {
      if (pitch.x(i + 1) <= liftoff) continue;  // inside the vertical lift-off
      const double rate = (pitch.y(i + 1) - pitch.y(i)) / (pitch.x(i + 1) - pitch.x(i));
      add_segment(pitch.x(i), pitch.y(i), rate);
    }
    add_segment(pitch.last_x(), pitch.last_y(), 0.0);  // the table holds its last value
  }

  if (segments.size() > static_cast<std::size_t>(kMaxLinearSegments)) {
    return fail(source + " gives " + std::to_string(segments.size()) +
                " segments in the stages that fly the pitch program; the table image holds at most " +
                std::to_string(kMaxLinearSegments) + " (kTooManyLinearSegments)");
  }
  const double rate_limit = t.max_pitch_rate_rad_s * (1.0 + kTableRateLimitRelativeTolerance);
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (std::fabs(segments[i].rate_rad_s) > rate_limit) {
      return fail(
          source + ": segment " + std::to_string(i) + " (stage " + std::to_string(segments[i].stage_code) +
          ", from stage time " + fixed(segments[i].start_stage_time_s, 3) + " s) pitches at " +
          degrees(segments[i].rate_rad_s, 6) + " deg/s, beyond the data block 22 maximum pitch rate " +
          degrees(t.max_pitch_rate_rad_s, 6) + " deg/s (kSegmentRateExceedsLimit)");
    }
  }
  t.segment_count = static_cast<int>(segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) t.segments[i] = segments[i];

  const Status valid = validate_guidance_table(t);
  if (!ok(valid)) {
    return fail(std::string("the table contents are invalid: ") + status_name(valid) + ": " +
                status_message(valid));
  }
  *table = t;
  return true;
}

std::string table_image_c_header(const std::uint8_t* image, std::size_t size, const std::string& symbol,
                                 const std::string& origin) {
  std::string guard = "TOLIP_TABLE_IMAGE_";
  for (char c : symbol) guard += static_cast<char>((c >= 'a' && c <= 'z') ? c - 'a' + 'A' : c);
  guard += "_H";
  char line[128];
  std::ostringstream out;
  out << "/* GENERATED by tolip " << version_string() << " (tolip export --c-header): do not edit.\n"
      << " * Guidance table image, format version " << kTableFormatVersion << " (docs/table-format.md), "
      << size << " bytes.\n"
      << " * Source: " << origin << "\n"
      << " * Include this header in exactly ONE translation unit: it defines the array, placed in\n"
      << " * the linker section " << kTableLinkerSection
      << " (the flight image maps it at a fixed address). */\n"
      << "#ifndef " << guard << "\n#define " << guard << "\n\n#include <stdint.h>\n\n";
  std::snprintf(line, sizeof line, "#define %s_SIZE %zuu\n", guard.c_str(), size);
  out << line;
  if (size >= kTableImageSize) {
    std::snprintf(line, sizeof line, "#define %s_CRC32 0x%08Xu\n", guard.c_str(),
                  static_cast<unsigned>(stored_table_crc(image)));
    out << line;
  }
  out << "\n#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n"
      << "extern const uint8_t " << symbol << "[" << size << "];\n"
      << "__attribute__((section(\"" << kTableLinkerSection << "\"), aligned(8), used))\n"
      << "const uint8_t " << symbol << "[" << size << "] = {\n";
  for (std::size_t i = 0; i < size; ++i) {
    if (i % 12 == 0) out << "   ";
    std::snprintf(line, sizeof line, " 0x%02X,", static_cast<unsigned>(image[i]));
    out << line;
    if (i % 12 == 11 || i + 1 == size) out << '\n';
  }
  out << "};\n\n#ifdef __cplusplus\n}  /* extern \"C\" */\n#endif\n\n#endif  /* " << guard << " */\n";
  return out.str();
}

void write_table_listing(std::ostream& out, const GuidanceTable& t, std::uint32_t crc) {
  char line[256];
  out << "guidance table image: valid\n";
  std::snprintf(line, sizeof line, "  format version       %u\n", static_cast<unsigned>(t.format_version));
  out << line;
  std::snprintf(line, sizeof line, "  image size           %zu bytes\n", kTableImageSize);
  out << line;
  std::snprintf(line, sizeof line, "  CRC-32               0x%08X\n", static_cast<unsigned>(crc));
  out << line;
  out << "  mission id           " << t.mission_id << "\n";
  out << "  created              " << utc_stamp(t.created_unix_s) << " (" << t.created_unix_s << " s)\n";
  out << "  generator            tolip " << t.generator_version << "\n";
  out << "  lift-off duration    " << fixed(t.liftoff_duration_s, 6) << " s (theta held at 90 deg)\n";
  out << "  pitch-rate limits    max " << degrees(t.max_pitch_rate_rad_s, 6) << " deg/s, min "
      << degrees(t.min_pitch_rate_rad_s, 6) << " deg/s, min change "
      << degrees(t.min_pitch_rate_change_rad_s, 6) << " deg/s\n";
  out << "  max deflection       " << degrees(t.max_deflection_rad, 6) << " deg\n";
  const auto control = [&t](int code) { return stage_is_spun(t.spin_option, code) ? "spun" : "segments"; };
  out << "  stages 4, 5 (IP(9))  " << t.spin_option << ": stage 4 and coast 9 " << control(4)
      << ", stage 5 and coast 10 " << control(5) << "\n";
  out << "  spun stage 4         theta " << degrees(t.stage4_theta_rad, 9) << " deg, chi "
      << degrees(t.stage4_chi_rad, 9) << " deg\n";
  out << "  spun stage 5         theta " << degrees(t.stage5_theta_rad, 9) << " deg, chi "
      << degrees(t.stage5_chi_rad, 9) << " deg\n";
  out << "  autopilot gains (stage code: K_theta deg/deg, K_q s)\n";
  for (int code = 1; code <= kMaxStages; ++code) {
    std::snprintf(line, sizeof line, "    stage %2d  K_theta %10.6f  K_q %10.6f\n", code,
                  t.gains[code - 1].k_theta, t.gains[code - 1].k_q_s);
    out << line;
  }
  std::snprintf(line, sizeof line, "  segments             %d of %d\n", t.segment_count, kMaxLinearSegments);
  out << line;
  out << "     #  stage  start (stage s)   theta start (deg)   rate (deg/s)\n";
  for (int i = 0; i < t.segment_count; ++i) {
    const GuidanceSegment& s = t.segments[i];
    std::snprintf(line, sizeof line, "    %2d  %5d  %15.6f  %18.9f  %13.9f\n", i, s.stage_code,
                  s.start_stage_time_s, s.theta_start_rad * kRadToDeg, s.rate_rad_s * kRadToDeg);
    out << line;
  }
  std::snprintf(line, sizeof line, "  gain schedule        %d of %d\n", t.schedule_count,
                kMaxGainSchedulePoints);
  out << line;
  if (t.schedule_count > 0) out << "     #  stage  time (stage s)   K_theta      K_q (s)\n";
  for (int i = 0; i < t.schedule_count; ++i) {
    const GainSchedulePoint& p = t.schedule[i];
    std::snprintf(line, sizeof line, "    %2d  %5d  %14.6f  %10.6f  %10.6f\n", i, p.stage_code,
                  p.stage_time_s, p.k_theta, p.k_q_s);
    out << line;
  }
}

nlohmann::ordered_json table_json(const GuidanceTable& t, std::uint32_t crc, std::size_t image_size) {
  using json = nlohmann::ordered_json;
  char crc_text[16];
  std::snprintf(crc_text, sizeof crc_text, "0x%08X", static_cast<unsigned>(crc));
  json gains = json::array();
  for (int code = 1; code <= kMaxStages; ++code) {
    gains.push_back(json{{"stage", code},
                         {"k_theta_deg_per_deg", t.gains[code - 1].k_theta},
                         {"k_q_s", t.gains[code - 1].k_q_s}});
  }
  json segments = json::array();
  for (int i = 0; i < t.segment_count; ++i) {
    const GuidanceSegment& s = t.segments[i];
    segments.push_back(json{{"stage", s.stage_code},
                            {"start_stage_time_s", s.start_stage_time_s},
                            {"theta_start_deg", s.theta_start_rad * kRadToDeg},
                            {"rate_deg_s", s.rate_rad_s * kRadToDeg}});
  }
  json schedule = json::array();
  for (int i = 0; i < t.schedule_count; ++i) {
    const GainSchedulePoint& p = t.schedule[i];
    schedule.push_back(json{{"stage", p.stage_code},
                            {"stage_time_s", p.stage_time_s},
                            {"k_theta", p.k_theta},
                            {"k_q_s", p.k_q_s}});
  }
  return json{
      {"valid", true},
      {"format_version", t.format_version},
      {"image_size_bytes", image_size},
      {"crc32", crc_text},
      {"mission_id", t.mission_id},
      {"created_unix_s", t.created_unix_s},
      {"generator_version", t.generator_version},
      {"liftoff_duration_s", t.liftoff_duration_s},
      {"max_pitch_rate_deg_s", t.max_pitch_rate_rad_s * kRadToDeg},
      {"min_pitch_rate_deg_s", t.min_pitch_rate_rad_s * kRadToDeg},
      {"min_pitch_rate_change_deg_s", t.min_pitch_rate_change_rad_s * kRadToDeg},
      {"max_deflection_deg", t.max_deflection_rad * kRadToDeg},
      {"spin_option_ip9", t.spin_option},
      {"stage4_theta_deg", t.stage4_theta_rad * kRadToDeg},
      {"stage4_chi_deg", t.stage4_chi_rad * kRadToDeg},
      {"stage5_theta_deg", t.stage5_theta_rad * kRadToDeg},
      {"stage5_chi_deg", t.stage5_chi_rad * kRadToDeg},
      {"gains", std::move(gains)},
      {"segments", std::move(segments)},
      {"gain_schedule", std::move(schedule)},
  };
}

bool read_table_image_file(const std::string& path, std::vector<std::uint8_t>* bytes, std::string* error) {
  std::string contents;
  std::string reason;
  if (!read_file_capped(path, kTableImageSize, "guidance table image", &contents, &reason)) {
    if (error != nullptr) *error = path + ": " + reason;
    return false;
  }
  bytes->assign(contents.begin(), contents.end());
  return true;
}

}  // namespace tolip::ground
