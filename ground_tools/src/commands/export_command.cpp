// `tolip export`: a case deck to a guidance table image (and optionally a C header), written
// atomically (docs/table-format.md, docs/cli.md).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <ostream>
#include <string>
#include <utility>

#include "tolip/table/table_image.hpp"
#include "tolip/vehicle/prepared_case.hpp"
#include "tolip_ground/atomic_file.hpp"
#include "tolip_ground/autopilot_run.hpp"
#include "tolip_ground/card_deck.hpp"
#include "tolip_ground/commands.hpp"
#include "tolip_ground/deck_extras.hpp"
#include "tolip_ground/guidance_table.hpp"
#include "tolip_ground/optimization_run.hpp"
#include "tolip_ground/table_commands.hpp"
#include "tolip_ground/unused_inputs.hpp"

namespace tolip::ground {
namespace {

bool is_c_identifier(const std::string& name) {
  if (name.empty()) return false;
  for (std::size_t i = 0; i < name.size(); ++i) {
    const char c = name[i];
    const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
    const bool digit = c >= '0' && c <= '9';
    if (!letter && !(digit && i > 0)) return false;
  }
  return true;
}

// The creation stamp: the option, else SOURCE_DATE_EPOCH (reproducible builds), else now.
bool creation_stamp(const ExportCommandOptions& options, std::int64_t* stamp, std::string* error) {
  if (options.created_unix_s.has_value()) {
    *stamp = *options.created_unix_s;
  } else if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH"); epoch != nullptr && *epoch != '\0') {
    char* end = nullptr;
    const long long value = std::strtoll(epoch, &end, 10);
    if (end == epoch || *end != '\0') {
      *error = "SOURCE_DATE_EPOCH is not an integer: '" + std::string(epoch) + "'";
      return false;
    }
    *stamp = value;
  } else {
    *stamp = static_cast<std::int64_t>(std::time(nullptr));
  }
  if (*stamp < 0 || *stamp > kTableMaxCreatedUnixS) {
    *error = "the creation stamp " + std::to_string(*stamp) + " s is outside [0, " +
             std::to_string(kTableMaxCreatedUnixS) + "] (docs/table-format.md)";
    return false;
  }
  return true;
}

}  // namespace

int run_export_command(const ExportCommandOptions& options, std::ostream& out, std::ostream& err) {
  if (!is_c_identifier(options.symbol)) {
    err << "tolip: --symbol '" << options.symbol << "' is not a C identifier\n";
    return kExitBadInput;
  }
  // Two outputs naming one file would leave only the second; an output naming the deck would
  // destroy it. Refused before anything runs.
  const bool header_wanted = !options.c_header_path.empty();
  if (header_wanted && names_same_file(options.out_path, options.c_header_path)) {
    err << "tolip: --out '" << options.out_path << "' and --c-header '" << options.c_header_path
        << "' name the same file: the header would replace the image; name two different files\n";
    return kExitBadInput;
  }
  for (const auto& [option, path] : {std::pair<const char*, const std::string*>{"--out", &options.out_path},
                                     {"--c-header", &options.c_header_path}}) {
    if (!path->empty() && names_same_file(*path, options.deck_path)) {
      err << "tolip: " << option << " '" << *path << "' is the input deck '" << options.deck_path
          << "': writing it would destroy the deck; name another file\n";
      return kExitBadInput;
    }
  }

  std::int64_t stamp = 0;
  std::string stamp_error;
  if (!creation_stamp(options, &stamp, &stamp_error)) {
    err << "tolip: " << stamp_error << '\n';
    return kExitBadInput;
  }

  std::unique_ptr<Mission> mission = make_mission();
  auto extras = std::make_unique<DeckExtras>();
  DeckError deck_error;
  if (!load_single_case_deck(options.deck_path, mission.get(), extras.get(),
                             &deck_error)) {  // TOML or card deck
    err << "tolip: " << deck_error.to_string() << '\n';
    return kExitBadInput;
  }
  print_input_warnings(err, options.deck_path, 1, 1, unused_inputs(*mission, *extras));
  auto prepared = std::make_unique<PreparedCase>();
  const Status prepare = prepare_case(*mission, prepared.get());
  if (!ok(prepare)) {
    err << "tolip: " << status_name(prepare) << ": " << status_message(prepare) << '\n';
    return kExitFailure;
  }

  // The pitch program: the linearized optimum when the deck asks for linearization (IP(7) = 1),
  // which needs the optimization first; else data block 40 (docs/table-format.md). A program that
  // misses a constraint or a rate limit is not exported.
  // Designed autopilot gains (issue 16): the request is checked before anything runs.
  const bool designed = extras->autopilot.designed != 0;
  AutopilotPlan plan;
  std::string plan_error;
  if (designed && !plan_autopilot_design(*mission, *extras, &plan, &plan_error)) {
    err << "tolip: " << options.deck_path << ": " << plan_error << '\n';
    return kExitBadInput;
  }
  std::unique_ptr<SixDAutopilotGains> six_d_gains;
  OptimizationRun run;
  if (designed && mission->options.linearization() && mission->options.body_dynamics_6d() == 1) {
    six_d_gains = std::make_unique<SixDAutopilotGains>(plan);
    run.six_d_gains = six_d_gains.get();
  }
  const Mission* table_mission = mission.get();
  const PreparedCase* table_case = prepared.get();
  const LinearProgram* linearized = nullptr;
  if (mission->options.linearization()) {
    run_optimization(*mission, nullptr, &run);
    if (six_d_gains != nullptr && six_d_gains->failed()) {
      err << "tolip: " << options.deck_path << ": no table exported: " << six_d_gains->fault_text() << '\n';
      return kExitBadInput;
    }
    // The same rule as `optimize` (optimization_job_status): a case that optimize would not pass is
    // not exported.
    const JobVerdict verdict = optimization_job_verdict(run);
    if (!ok(verdict.status)) {
      err << "tolip: " << options.deck_path
          << ": no table exported: the deck asks for the linearized pitch program "
          << "(IP(7) = 1) and its " << verdict.failed_step
          << " did not succeed: " << status_name(verdict.status) << ": " << status_message(verdict.status)
          << '\n';
      return kExitFailure;
    }
    table_mission = &run.linearization.workspace->mission;
    table_case = &run.linearization.workspace->prepared;
    linearized = &run.linearization.result->program;
  }

  // The gain schedule along the final nominal: the linearized trajectory, else the deck's program.
  AutopilotStep autopilot;
  if (designed) {
    std::unique_ptr<Trajectory> simulated;
    const Trajectory* nominal = nullptr;
    if (linearized != nullptr) {
      nominal = &run.linearization.workspace->nominal;
    } else {
      simulated = std::make_unique<Trajectory>();
      const Status flown = fly_trajectory(*mission, *prepared, simulated.get());
      if (!ok(flown)) {
        err << "tolip: " << status_name(flown) << ": " << status_message(flown) << '\n';
        return kExitFailure;
      }
      nominal = simulated.get();
    }
    run_autopilot_step(*table_mission, plan, *nominal,
                       linearized != nullptr ? "linearized program" : "simulated", &autopilot);
    if (!ok(autopilot.status)) {
      err << "tolip: " << options.deck_path << ": no table exported: " << autopilot_fault_text(autopilot)
          << '\n';
      return kExitBadInput;
    }
  }

  TableBuildOptions build;
  build.mission_id = options.mission_id;
  build.created_unix_s = stamp;
  auto table = std::make_unique<GuidanceTable>();
  std::string build_error;
  if (!build_guidance_table(*table_mission, *extras, *table_case, linearized, build, table.get(),
                            &build_error)) {
    err << "tolip: " << options.deck_path << ": " << build_error << '\n';
    return kExitBadInput;
  }
  if (designed) apply_gain_schedule(*autopilot.schedule, table.get());
  std::uint8_t image[kTableImageSize];
  const Status encoded = encode_table_image(*table, image, sizeof image);
  if (!ok(encoded)) {
    err << "tolip: " << status_name(encoded) << ": " << status_message(encoded) << '\n';
    return kExitFailure;
  }
  // Read back through the flight-side decoder before anything is written.
  auto check = std::make_unique<GuidanceTable>();
  const Status decoded = decode_table_image(image, sizeof image, check.get());
  if (!ok(decoded)) {
    err << "tolip: the encoded image does not decode: " << status_name(decoded) << ": "
        << status_message(decoded) << '\n';
    return kExitFailure;
  }

  // Render everything first, then write each file atomically (temporary file, then rename).
  const std::string header =
      options.c_header_path.empty()
          ? std::string()
          : table_image_c_header(image, sizeof image, options.symbol, options.deck_path);
  std::string write_error;
  if (!write_file_atomically(options.out_path,
                             std::string_view(reinterpret_cast<const char*>(image), sizeof image),
                             &write_error)) {
    err << "tolip: " << write_error << '\n';
    return kExitFailure;
  }
  if (!options.c_header_path.empty() && !write_file_atomically(options.c_header_path, header, &write_error)) {
    err << "tolip: " << write_error << '\n';
    return kExitFailure;
  }

  char crc[16];
  std::snprintf(crc, sizeof crc, "0x%08X", static_cast<unsigned>(stored_table_crc(image)));
  out << "wrote " << options.out_path << " (" << sizeof image << " bytes, CRC-32 " << crc << ", "
      << table->segment_count << " segments from "
      << (linearized != nullptr ? "the linearized program" : "data block 40")
      << (designed ? ", " + std::to_string(table->schedule_count) + " designed gain schedule points"
                   : std::string())
      << ", mission id '" << table->mission_id << "')\n";
  if (!options.c_header_path.empty()) {
    out << "wrote " << options.c_header_path << " (C array " << options.symbol << " in section "
        << kTableLinkerSection << ")\n";
  }
  return kExitOk;
}

}  // namespace tolip::ground
