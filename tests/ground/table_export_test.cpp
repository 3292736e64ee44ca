// `tolip export` / `tolip inspect` and the ground-to-flight round trip of the guidance table image:
// export the reference deck, load the file with the flight-side loader, execute it along the
// reference trajectory (docs/table-format.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "support/repository_paths.hpp"
#include "tolip/table/guidance_executor.hpp"
#include "tolip/table/table_image.hpp"
#include "tolip/table/table_service.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip_ground/atomic_file.hpp"
#include "tolip_ground/deck_extras.hpp"
#include "tolip_ground/guidance_table.hpp"
#include "tolip_ground/optimization_run.hpp"
#include "tolip_ground/table_commands.hpp"

namespace tolip::test {
namespace {

using Image = std::vector<std::uint8_t>;

Image read_image(const std::filesystem::path& path) {
  const std::string text = read_text_file(path);
  return Image(text.begin(), text.end());
}

void write_image(const std::filesystem::path& path, const Image& image) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(image.data()), static_cast<std::streamsize>(image.size()));
}

// The reference case loaded in-process: mission, extras, prepared case, flown trajectory, and the
// segment lists build_guidance_table() makes of it (same stamp as the exports below): from data
// block 40 (`table`), and from the linearized program of the optimization the deck asks for
// (IP(7) = 1; `linearized_table`, what `tolip export` writes for this deck).
struct ReferenceCase {
  std::unique_ptr<Mission> mission = std::make_unique<Mission>();
  std::unique_ptr<ground::DeckExtras> extras = std::make_unique<ground::DeckExtras>();
  std::unique_ptr<PreparedCase> prepared = std::make_unique<PreparedCase>();
  std::unique_ptr<Trajectory> trajectory = std::make_unique<Trajectory>();
  GuidanceTable table;
  ground::OptimizationRun run;
  GuidanceTable linearized_table;
  const Trajectory& linearized_trajectory() const { return run.linearization.workspace->nominal; }
  const PreparedCase& linearized_case() const { return run.linearization.workspace->prepared; }
};

const ReferenceCase& reference_case() {
  static const ReferenceCase* loaded = [] {
    auto* c = new ReferenceCase;
    ground::DeckError error;
    EXPECT_TRUE(ground::load_toml_deck(reference_deck(), c->mission.get(), c->extras.get(), &error))
        << error.to_string();
    EXPECT_EQ(prepare_case(*c->mission, c->prepared.get()), Status::kOk);
    EXPECT_EQ(fly_trajectory(*c->mission, *c->prepared, c->trajectory.get()), Status::kOk);
    ground::TableBuildOptions options;
    options.created_unix_s = 0;
    std::string build_error;
    EXPECT_TRUE(ground::build_guidance_table(*c->mission, *c->extras, *c->prepared, nullptr, options,
                                             &c->table, &build_error))
        << build_error;
    ground::run_optimization(*c->mission, nullptr, &c->run);
    EXPECT_EQ(c->run.linearization.status, Status::kOk);
    if (c->run.linearization.outcome == ground::StepOutcome::kRun) {
      EXPECT_TRUE(ground::build_guidance_table(c->run.linearization.workspace->mission, *c->extras,
                                               c->linearized_case(), &c->run.linearization.result->program,
                                               options, &c->linearized_table, &build_error))
          << build_error;
    }
    return c;
  }();
  return *loaded;
}

// Exports the reference deck to `scratch/name` through the program; returns the image bytes.
Image export_reference(const ScratchDirectory& scratch, const std::string& name) {
  const std::filesystem::path path = scratch / name;
  const CommandResult result =
      run_tolip_executable({"export", reference_deck(), "--out", path.string(), "--created-unix-s", "0"});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  return read_image(path);
}

// The reference deck without the linearization option (IP(7) = 0, and so IP(6) = 0): export
// takes data block 40.
std::string without_linearization(std::string deck) {
  for (const auto& [from, to] :
       {std::pair<std::string, std::string>{"linearization = true", "linearization = false"},
        {"body_dynamics_6d = 1", "body_dynamics_6d = 0"}}) {
    const std::size_t at = deck.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) deck.replace(at, from.size(), to);
  }
  return deck;
}

// The segment list's theta at (t, stage), evaluated independently of the executor: stage starts
// from the prepared case's timeline, the segment in force the last one (flight order, then start
// time) that has started.
double segment_list_theta_rad(const GuidanceTable& table, const PreparedCase& prepared, int stage, double t) {
  if (stage == 4 || stage == 9) return table.stage4_theta_rad;
  if (stage == 5 || stage == 10) return table.stage5_theta_rad;
  if (stage == 1 && t < table.liftoff_duration_s) return 0.5 * kPi;
  auto start_of = [&prepared](int code) {
    for (int i = 0; i < prepared.stage_count; ++i) {
      if (prepared.timeline[i].code == code) return prepared.timeline[i].start_s;
    }
    ADD_FAILURE() << "stage " << code << " not in the timeline";
    return 0.0;
  };
  double theta = 0.5 * kPi;
  for (int i = 0; i < table.segment_count; ++i) {
    const GuidanceSegment& s = table.segments[i];
    if (flight_order_index(s.stage_code) > flight_order_index(stage)) break;
    const double since = (t - start_of(s.stage_code)) - s.start_stage_time_s;
    if (since < 0.0) break;
    theta = s.theta_start_rad + s.rate_rad_s * since;
  }
  return theta;
}

// Drives a GuidanceExecutor along the trajectory's integration points: a stage event whenever the
// stage changes (at the stage's start time), one step per point. Returns theta_c per point.
std::vector<double> executed_theta(const GuidanceTableService& service, const Trajectory& trajectory) {
  GuidanceExecutor executor(service);
  std::vector<double> theta;
  for (int i = 0; i < trajectory.point_count; ++i) {
    const TrajectoryPoint& p = trajectory.points[i];
    if (p.stage_code != executor.stage_in_force()) {
      EXPECT_EQ(executor.stage_event(p.stage_code, p.time_s - p.stage_time_s), Status::kOk) << i;
    }
    GuidanceCommand command;
    EXPECT_EQ(executor.step(p.time_s, &command), Status::kOk) << "point " << i;
    theta.push_back(command.theta_rad);
  }
  return theta;
}

TEST(TableExport, RoundTripReproducesTheSegmentListThetaAtEveryIntegrationPoint) {
  const ReferenceCase& c = reference_case();
  ScratchDirectory scratch("table_round_trip");
  const Image image = export_reference(scratch, "table.bin");
  ASSERT_EQ(image.size(), kTableImageSize);

  // The file holds exactly the linearized segment list built in-process.
  GuidanceTable decoded;
  ASSERT_EQ(decode_table_image(image.data(), image.size(), &decoded), Status::kOk);
  ASSERT_EQ(decoded.segment_count, c.linearized_table.segment_count);
  for (int i = 0; i < decoded.segment_count; ++i) {
    EXPECT_EQ(decoded.segments[i].stage_code, c.linearized_table.segments[i].stage_code);
    EXPECT_EQ(decoded.segments[i].start_stage_time_s, c.linearized_table.segments[i].start_stage_time_s);
    EXPECT_EQ(decoded.segments[i].theta_start_rad, c.linearized_table.segments[i].theta_start_rad);
    EXPECT_EQ(decoded.segments[i].rate_rad_s, c.linearized_table.segments[i].rate_rad_s);
  }
  EXPECT_EQ(decoded.stage4_theta_rad,
            c.run.workspace->mission.misc.stage4_theta_rad);  // the optimized attitude

  static GuidanceTableService service;
  ASSERT_EQ(service.load(image.data(), image.size()), Status::kOk);
  const Trajectory& trajectory = c.linearized_trajectory();
  const std::vector<double> theta = executed_theta(service, trajectory);
  ASSERT_EQ(static_cast<int>(theta.size()), trajectory.point_count);
  ASSERT_GT(trajectory.point_count, 190);
  double worst_deg = 0.0;
  for (int i = 0; i < trajectory.point_count; ++i) {
    const TrajectoryPoint& p = trajectory.points[i];
    const double expected = segment_list_theta_rad(decoded, c.linearized_case(), p.stage_code, p.time_s);
    const double error_deg = std::fabs(theta[i] - expected) * kRadToDeg;
    worst_deg = std::max(worst_deg, error_deg);
    EXPECT_LE(error_deg, 1e-12) << "point " << i << " t " << p.time_s << " stage " << p.stage_code;
  }
  char worst[32];
  std::snprintf(worst, sizeof worst, "%.3e", worst_deg);
  RecordProperty("worst_theta_error_deg", worst);
}

// Sec. 6, 10 to the flight side: the exported image, loaded and executed by the flight code along
// the linearized trajectory, commands exactly the attitude that trajectory was commanded at every
// point after lift-off (segments, the hold through coast 8, the optimized spun stage-4 attitude).
// With the reference deck's IP(6) = 1 the trajectory is the 6D one: in stage 1 and coast 6 the
// body flies the autopilot's steady state about this command (Sec. 7), elsewhere the command.
TEST(TableExport, Sec10_ExecutedTableFliesTheLinearizedTrajectoryAttitude) {
  const ReferenceCase& c = reference_case();
  ScratchDirectory scratch("table_linearized");
  const Image image = export_reference(scratch, "table.bin");
  static GuidanceTableService service;
  ASSERT_EQ(service.load(image.data(), image.size()), Status::kOk);
  const Trajectory& trajectory = c.linearized_trajectory();
  const std::vector<double> theta = executed_theta(service, trajectory);
  ASSERT_EQ(static_cast<int>(theta.size()), trajectory.point_count);
  int compared = 0;
  double worst_deg = 0.0;
  for (int i = 0; i < trajectory.point_count; ++i) {
    const TrajectoryPoint& p = trajectory.points[i];
    if (p.time_s < c.mission->launch.liftoff_duration_s) continue;
    // The program commands stages 1-3 and coasts 6-8; the spun stages fly their attitude.
    const double commanded = is_segment_stage(c.mission->options.spin_stages_4_5(), p.stage_code)
                                 ? c.run.linearization.workspace->program.theta_rad[i]
                                 : p.theta_rad;
    if (!p.body_dynamics) EXPECT_EQ(commanded, p.theta_rad) << "point " << i;  // flown = commanded
    const double error_deg = std::fabs(theta[i] - commanded) * kRadToDeg;
    worst_deg = std::max(worst_deg, error_deg);
    EXPECT_LE(error_deg, 1e-9) << "point " << i << " t " << p.time_s << " stage " << p.stage_code;
    ++compared;
  }
  EXPECT_GT(compared, 180);
  char worst[32];
  std::snprintf(worst, sizeof worst, "%.3e", worst_deg);
  RecordProperty("worst_theta_error_deg", worst);
}

TEST(TableExport, InterimSegmentsReproduceTheBlock40ProgramAndTheFlownAttitude) {
  const ReferenceCase& c = reference_case();
  static GuidanceTableService service;
  Image image(kTableImageSize);
  ASSERT_EQ(encode_table_image(c.table, image.data(), image.size()), Status::kOk);
  ASSERT_EQ(service.load(image.data(), image.size()), Status::kOk);
  const Trajectory& trajectory = *c.trajectory;
  const std::vector<double> theta = executed_theta(service, trajectory);

  // Where the trajectory flew in-flight rules instead of the table (zero-alpha window, IP(11);
  // latched segments from the window end and from stage-2 ignition, IP(12), to the next node).
  const Mission& m = *c.mission;
  auto next_node_after = [&m](double t) {
    for (int i = 0; i < m.pitch_program_rad.size(); ++i) {
      if (m.pitch_program_rad.x(i) > t + 0.5 * m.constants.time_epsilon_s) return m.pitch_program_rad.x(i);
    }
    return t;
  };
  double stage2_start = 0.0;
  for (int i = 0; i < c.prepared->stage_count; ++i) {
    if (c.prepared->timeline[i].code == 2) stage2_start = c.prepared->timeline[i].start_s;
  }
  const double rules_from = m.control.zero_alpha_start_s;
  const double rules_until =
      std::max(next_node_after(m.control.zero_alpha_end_s), next_node_after(stage2_start));

  int compared_with_table = 0;
  int compared_with_flight = 0;
  for (int i = 0; i < trajectory.point_count; ++i) {
    const TrajectoryPoint& p = trajectory.points[i];
    if (is_segment_stage(m.options.spin_stages_4_5(), p.stage_code) &&
        p.time_s >= m.launch.liftoff_duration_s) {
      EXPECT_NEAR(theta[i] * kRadToDeg, m.pitch_program_rad(p.time_s) * kRadToDeg, 1e-12) << "t " << p.time_s;
      ++compared_with_table;
    }
    const bool in_flight_rules = p.time_s >= rules_from - 1e-9 && p.time_s < rules_until - 1e-9;
    if (!in_flight_rules) {
      EXPECT_NEAR(theta[i] * kRadToDeg, p.theta_rad * kRadToDeg, 1e-12)
          << "t " << p.time_s << " stage " << p.stage_code;
      ++compared_with_flight;
    }
  }
  EXPECT_GT(compared_with_table, 120);
  EXPECT_GT(compared_with_flight, 150);
}

TEST(TableExport, ReferenceDeckGivesTheDocumentedInterimContents) {
  const ReferenceCase& c = reference_case();
  const GuidanceTable& t = c.table;
  EXPECT_EQ(t.segment_count, 10);
  EXPECT_EQ(t.liftoff_duration_s, 3.0);
  EXPECT_DOUBLE_EQ(t.max_pitch_rate_rad_s * kRadToDeg, 5.0);
  EXPECT_DOUBLE_EQ(t.max_deflection_rad * kRadToDeg, 10.0);  // block 45 word 11
  EXPECT_EQ(t.stage4_theta_rad, c.mission->misc.stage4_theta_rad);
  EXPECT_EQ(t.stage5_theta_rad, c.mission->misc.stage4_theta_rad);  // IP(9) = 1: theta_5 = theta_4
  EXPECT_EQ(t.gains[0].k_theta, c.mission->body_dynamics.position_gain[0]);
  EXPECT_EQ(t.gains[1].k_q_s, c.mission->body_dynamics.rate_gain_s[1]);
  EXPECT_EQ(t.gains[5].k_theta, t.gains[0].k_theta);  // coast 6 keeps stage 1's gains
  EXPECT_EQ(t.gains[3].k_theta, 0.0);                 // spun stage 4: no autopilot
  EXPECT_EQ(t.segments[0].stage_code, 1);
  EXPECT_EQ(t.segments[0].start_stage_time_s, 3.0);  // the lift-off interval is excluded
  EXPECT_EQ(t.segments[3].stage_code, 6);
  EXPECT_EQ(t.segments[9].stage_code, 8);  // hold of the last node through coast 8
  EXPECT_EQ(t.segments[9].rate_rad_s, 0.0);
  EXPECT_STREQ(t.mission_id, "SCOUT-CLASS 4-STAGE, WALLOPS ISL");
}

TEST(ExportCli, RepeatedExportsWithTheSameStampAreByteIdentical) {
  ScratchDirectory scratch("table_repeat");
  const Image first = export_reference(scratch, "a.bin");
  const Image second = export_reference(scratch, "b.bin");
  ASSERT_EQ(first.size(), kTableImageSize);
  EXPECT_EQ(first, second);
}

TEST(ExportCli, CHeaderHoldsTheImageBytesInTheTableSection) {
  ScratchDirectory scratch("table_header");
  const std::filesystem::path bin = scratch / "t.bin";
  const std::filesystem::path header = scratch / "pitch_table.h";
  const CommandResult result =
      run_tolip_executable({"export", reference_deck(), "--out", bin.string(), "--c-header", header.string(),
                            "--symbol", "flight_table", "--created-unix-s", "0"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(contains(result.out, "pitch_table.h"));
  const std::string text = read_text_file(header);
  EXPECT_TRUE(contains(text, "__attribute__((section(\".tolip_table\")"));
  EXPECT_TRUE(contains(text, "const uint8_t flight_table[1580] = {"));
  EXPECT_TRUE(contains(text, "extern const uint8_t flight_table[1580];"));
  // The array's bytes, in order, are the .bin file.
  Image parsed;
  std::size_t at = text.find("= {");
  ASSERT_NE(at, std::string::npos);
  while ((at = text.find("0x", at)) != std::string::npos && at < text.find("};")) {
    parsed.push_back(static_cast<std::uint8_t>(std::stoul(text.substr(at + 2, 2), nullptr, 16)));
    at += 4;
  }
  EXPECT_EQ(parsed, read_image(bin));
}

TEST(ExportCli, MissionIdAndCreationStampAreStored) {
  ScratchDirectory scratch("table_stamp");
  const std::filesystem::path bin = scratch / "t.bin";
  const CommandResult result =
      run_tolip_executable({"export", reference_deck(), "--out", bin.string(), "--mission-id", "SCOUT S-142",
                            "--created-unix-s", "-86400"});
  EXPECT_EQ(result.exit_code, 2);  // before 1970
  EXPECT_TRUE(contains(result.err, "creation stamp")) << result.err;
  EXPECT_FALSE(std::filesystem::exists(bin));
  const CommandResult stamped =
      run_tolip_executable({"export", reference_deck(), "--out", bin.string(), "--mission-id", "SCOUT S-142",
                            "--created-unix-s", "1000000000"});
  ASSERT_EQ(stamped.exit_code, 0) << stamped.err;
  const Image image = read_image(bin);
  GuidanceTable table;
  ASSERT_EQ(decode_table_image(image.data(), image.size(), &table), Status::kOk);
  EXPECT_STREQ(table.mission_id, "SCOUT S-142");
  EXPECT_EQ(table.created_unix_s, 1000000000);
  const CommandResult inspected = run_tolip_executable({"inspect", bin.string()});
  EXPECT_TRUE(contains(inspected.out, "2001-09-09T01:46:40Z")) << inspected.out;
  const CommandResult too_long = run_tolip_executable(
      {"export", reference_deck(), "--out", bin.string(), "--mission-id", std::string(33, 'X')});
  EXPECT_EQ(too_long.exit_code, 2);
  EXPECT_TRUE(contains(too_long.err, "mission identifier")) << too_long.err;
}

TEST(ExportCli, SourceDateEpochSetsTheDefaultStamp) {
  ScratchDirectory scratch("table_epoch");
  const std::filesystem::path bin = scratch / "t.bin";
  ::setenv("SOURCE_DATE_EPOCH", "123456789", 1);
  ground::ExportCommandOptions options;
  options.deck_path = reference_deck();
  options.out_path = bin.string();
  std::ostringstream out;
  std::ostringstream err;
  const int code = ground::run_export_command(options, out, err);
  ::unsetenv("SOURCE_DATE_EPOCH");
  ASSERT_EQ(code, 0) << err.str();
  const Image image = read_image(bin);
  GuidanceTable table;
  ASSERT_EQ(decode_table_image(image.data(), image.size(), &table), Status::kOk);
  EXPECT_EQ(table.created_unix_s, 123456789);
}

// Atomic export: a failure at any step of the write leaves an existing destination exactly as it
// was (or no file at all) and no temporary file behind.
ground::AtomicWriteStep g_failing_step = ground::AtomicWriteStep::kOpen;
bool fail_selected_step(ground::AtomicWriteStep step) { return step == g_failing_step; }

TEST(ExportCli, FailedWriteLeavesNoPartialFileAndKeepsTheOldOne) {
  for (ground::AtomicWriteStep step :
       {ground::AtomicWriteStep::kOpen, ground::AtomicWriteStep::kWrite, ground::AtomicWriteStep::kSync,
        ground::AtomicWriteStep::kClose, ground::AtomicWriteStep::kRename}) {
    ScratchDirectory scratch("table_atomic_" + std::to_string(static_cast<int>(step)));
    const std::filesystem::path existing = scratch / "table.bin";
    const std::filesystem::path fresh = scratch / "fresh.bin";
    { std::ofstream(existing, std::ios::binary) << "previous flight table"; }
    for (const std::filesystem::path& target : {existing, fresh}) {
      ground::ExportCommandOptions options;
      options.deck_path = reference_deck();
      options.out_path = target.string();
      options.created_unix_s = 0;
      std::ostringstream out;
      std::ostringstream err;
      g_failing_step = step;
      ground::set_atomic_write_fault_hook(&fail_selected_step);
      const int code = ground::run_export_command(options, out, err);
      ground::set_atomic_write_fault_hook(nullptr);
      EXPECT_EQ(code, 1) << static_cast<int>(step);
      EXPECT_TRUE(contains(err.str(), "tolip: ")) << err.str();
    }
    EXPECT_EQ(read_text_file(existing), "previous flight table") << static_cast<int>(step);
    EXPECT_FALSE(std::filesystem::exists(fresh)) << static_cast<int>(step);
    for (const std::string& name : scratch.entries()) {
      EXPECT_EQ(name.find(".tmp."), std::string::npos) << name;
    }
  }
}

TEST(ExportCli, RateBeyondTheDeckLimitIsRejectedAndWritesNothing) {
  ScratchDirectory scratch("table_rate");
  std::string deck = read_text_file(reference_deck());
  const std::string from = "max_pitch_rate_deg_s = 5.0";
  const std::size_t at = deck.find(from);
  ASSERT_NE(at, std::string::npos);
  deck.replace(at, from.size(), "max_pitch_rate_deg_s = 1.0");
  deck = without_linearization(deck);
  const std::filesystem::path deck_path = scratch / "slow.toml";
  std::ofstream(deck_path) << deck;
  const std::filesystem::path bin = scratch / "t.bin";
  const CommandResult result = run_tolip_executable({"export", deck_path.string(), "--out", bin.string()});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_TRUE(contains(result.err, "data block 40")) << result.err;
  EXPECT_TRUE(contains(result.err, "kSegmentRateExceedsLimit")) << result.err;
  EXPECT_TRUE(result.out.empty());
  EXPECT_FALSE(std::filesystem::exists(bin));
}

TEST(ExportCli, MissingDeckExitsTwoAndWritesNothing) {
  ScratchDirectory scratch("table_nodeck");
  const std::filesystem::path bin = scratch / "t.bin";
  const CommandResult result =
      run_tolip_executable({"export", (scratch / "no_such_deck.toml").string(), "--out", bin.string()});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_TRUE(contains(result.err, "no_such_deck.toml")) << result.err;
  EXPECT_FALSE(std::filesystem::exists(bin));
  const CommandResult no_out = run_tolip_executable({"export", reference_deck()});
  EXPECT_EQ(no_out.exit_code, 2);
}

TEST(InspectCli, PrintsAValidImageInEngineeringUnits) {
  ScratchDirectory scratch("table_inspect");
  // From data block 40 (IP(7) = 0), so that the printed stage-4 attitude is the deck's.
  const std::filesystem::path deck_path = scratch / "block40.toml";
  std::ofstream(deck_path) << without_linearization(read_text_file(reference_deck()));
  const CommandResult exported = run_tolip_executable(
      {"export", deck_path.string(), "--out", (scratch / "t.bin").string(), "--created-unix-s", "0"});
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  EXPECT_TRUE(contains(exported.out, "from data block 40")) << exported.out;
  const Image image = read_image(scratch / "t.bin");
  const CommandResult result = run_tolip_executable({"inspect", (scratch / "t.bin").string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(result.err.empty()) << result.err;
  for (const char* part :
       {"guidance table image: valid", "format version       3", "1580 bytes",
        "SCOUT-CLASS 4-STAGE, WALLOPS ISL", "1970-01-01T00:00:00Z", "lift-off duration    3.000000 s",
        "max 5.000000 deg/s", "max deflection       10.000000 deg", "theta -22.259653370 deg",
        "segments             10 of 15", "K_theta   1.200000  K_q   0.350000"}) {
    EXPECT_TRUE(contains(result.out, part)) << part << "\n" << result.out;
  }
  char crc[16];
  std::snprintf(crc, sizeof crc, "0x%08X", static_cast<unsigned>(stored_table_crc(image.data())));
  EXPECT_TRUE(contains(result.out, crc));
}

// `inspect --json` holds the decoded image, the same numbers as the in-process table.
TEST(InspectCli, JsonHoldsEveryFieldOfTheImage) {
  const ReferenceCase& c = reference_case();
  ScratchDirectory scratch("table_inspect_json");
  const Image image = export_reference(scratch, "t.bin");
  const CommandResult result = run_tolip_executable({"inspect", (scratch / "t.bin").string(), "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json document = nlohmann::json::parse(result.out);
  const GuidanceTable& t = c.linearized_table;
  EXPECT_TRUE(document["valid"].get<bool>());
  EXPECT_EQ(document["image_size_bytes"].get<std::size_t>(), kTableImageSize);
  char crc[16];
  std::snprintf(crc, sizeof crc, "0x%08X", static_cast<unsigned>(stored_table_crc(image.data())));
  EXPECT_EQ(document["crc32"], crc);
  EXPECT_EQ(document["mission_id"], t.mission_id);
  EXPECT_EQ(document["created_unix_s"].get<std::int64_t>(), 0);
  EXPECT_DOUBLE_EQ(document["stage4_theta_deg"].get<double>(), t.stage4_theta_rad * kRadToDeg);
  EXPECT_DOUBLE_EQ(document["max_pitch_rate_deg_s"].get<double>(), 5.0);
  ASSERT_EQ(document["gains"].size(), 10u);
  EXPECT_DOUBLE_EQ(document["gains"][0]["k_theta_deg_per_deg"].get<double>(), t.gains[0].k_theta);
  ASSERT_EQ(document["segments"].size(), static_cast<std::size_t>(t.segment_count));
  for (int i = 0; i < t.segment_count; ++i) {
    const nlohmann::json& s = document["segments"][static_cast<std::size_t>(i)];
    EXPECT_EQ(s["stage"].get<int>(), t.segments[i].stage_code);
    EXPECT_DOUBLE_EQ(s["start_stage_time_s"].get<double>(), t.segments[i].start_stage_time_s);
    EXPECT_DOUBLE_EQ(s["rate_deg_s"].get<double>(), t.segments[i].rate_rad_s * kRadToDeg);
  }
}

TEST(InspectCli, NamesTheFaultOfABadImageAndExitsNonZero) {
  ScratchDirectory scratch("table_bad");
  const Image good = export_reference(scratch, "good.bin");
  ASSERT_EQ(good.size(), kTableImageSize);
  struct Case {
    const char* name;
    Image image;
    const char* status;
  };
  std::vector<Case> cases;
  cases.push_back({"truncated", Image(good.begin(), good.end() - 100), "kTableImageTruncated"});
  Image crc = good;
  crc[kOffsetSegments + 9] ^= 0x01;
  cases.push_back({"crc", crc, "kTableImageCrcMismatch"});
  Image magic = good;
  magic[1] = 'X';
  reseal_table_image(magic.data());
  cases.push_back({"magic", magic, "kTableImageBadMagic"});
  Image version = good;
  put_u16_le(version.data() + kOffsetFormatVersion, 9);
  reseal_table_image(version.data());
  cases.push_back({"version", version, "kTableImageUnsupportedVersion"});
  Image nan = good;
  put_f64_le(nan.data() + kOffsetSegments + kSegmentOffsetTheta, std::numeric_limits<double>::quiet_NaN());
  reseal_table_image(nan.data());
  cases.push_back({"nan", nan, "kValueNotFinite"});
  Image count = good;
  put_u16_le(count.data() + kOffsetSegmentCount, 16);
  reseal_table_image(count.data());
  cases.push_back({"count", count, "kTooManyLinearSegments"});
  // A value out of its range is named by its field (issue 18), not by a generic out-of-range.
  Image theta = good;
  put_f64_le(theta.data() + kOffsetSegments + kSegmentOffsetTheta, 7.0);
  reseal_table_image(theta.data());
  cases.push_back({"theta", theta, "kSegmentAttitudeOutOfRange"});
  Image liftoff = good;
  put_f64_le(liftoff.data() + kOffsetLiftoffDuration, -3.0);
  reseal_table_image(liftoff.data());
  cases.push_back({"liftoff", liftoff, "kTableLiftoffDurationOutOfRange"});
  for (const Case& c : cases) {
    const std::filesystem::path path = scratch / (std::string(c.name) + ".bin");
    write_image(path, c.image);
    const CommandResult result = run_tolip_executable({"inspect", path.string()});
    EXPECT_EQ(result.exit_code, 2) << c.name;
    EXPECT_TRUE(result.out.empty()) << c.name << ": " << result.out;
    EXPECT_TRUE(contains(result.err, c.status)) << c.name << ": " << result.err;
    EXPECT_TRUE(contains(result.err, path.string())) << c.name << ": " << result.err;
  }
}

TEST(InspectCli, MissingFileIsReportedAndExitsNonZero) {
  const CommandResult result = run_tolip_executable({"inspect", "/nonexistent/table.bin"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(
      result.err,
      "tolip: /nonexistent/table.bin: cannot open the guidance table image: No such file or directory\n");
}

// The macros the help and the docs name are the ones the generated C header defines.
TEST(ExportCli, HelpAndDocsNameTheMacrosTheHeaderDefines) {
  ScratchDirectory scratch("hostile_header_macros");
  const std::string symbol = "flight_table";
  const std::string header = (scratch / "table.h").string();
  const CommandResult exported =
      run_tolip_executable({"export", reference_deck(), "--out", (scratch / "t.bin").string(), "--c-header",
                            header, "--symbol", symbol, "--created-unix-s", "0"});
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  const std::string text = read_text_file(header);

  // Every macro name the help gives, with its placeholders filled in, is #defined.
  const CommandResult help = run_tolip_executable({"export", "--help"});
  ASSERT_EQ(help.exit_code, 0);
  const std::regex macro(R"([A-Za-z_<>]+_(SIZE|CRC32)\b)");
  std::vector<std::string> named;
  for (std::sregex_iterator it(help.out.begin(), help.out.end(), macro), end; it != end; ++it) {
    std::string name = it->str();
    name = std::regex_replace(name, std::regex("<SYMBOL>"), "FLIGHT_TABLE");
    name = std::regex_replace(name, std::regex("NAME"), symbol);
    named.push_back(name);
  }
  ASSERT_EQ(named.size(), 2u) << help.out;
  for (const std::string& name : named) {
    EXPECT_TRUE(contains(text, "#define " + name + " ")) << name << " is not defined by the header:\n"
                                                         << text;
  }

  // The docs spell the default symbol's macros; exported with it, the header defines them.
  const std::string default_header = (scratch / "default.h").string();
  ASSERT_EQ(run_tolip_executable({"export", reference_deck(), "--out", (scratch / "d.bin").string(),
                                  "--c-header", default_header, "--created-unix-s", "0"})
                .exit_code,
            0);
  const std::string default_text = read_text_file(default_header);
  for (const char* doc : {"docs/cli.md", "docs/table-format.md"}) {
    const std::string page = read_text_file(std::string(tolip::repository_paths::source_dir()) + "/" + doc);
    const std::regex spelled(R"(TOLIP_TABLE_IMAGE_TOLIP_PITCH_TABLE_H_(SIZE|CRC32))");
    int found = 0;
    for (std::sregex_iterator it(page.begin(), page.end(), spelled), end; it != end; ++it, ++found) {
      EXPECT_TRUE(contains(default_text, "#define " + it->str() + " ")) << doc << ": " << it->str();
    }
    EXPECT_GE(found, 2) << doc << " does not spell the macros";
  }
}

}  // namespace
}  // namespace tolip::test
