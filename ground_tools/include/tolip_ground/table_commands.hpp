// `tolip export` and `tolip inspect`: the guidance table image (docs/table-format.md, docs/cli.md).
// Same conventions as commands.hpp: normal output to `out`, diagnostics to `err` as
// "tolip: <message>", the process exit code returned.
#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>

namespace tolip::ground {

// `tolip export DECK --out FILE [--c-header FILE] [--symbol NAME] [--mission-id TEXT]
//  [--created-unix-s N]`
struct ExportCommandOptions {
  std::string deck_path;
  std::string out_path;                        // the binary image (required)
  std::string c_header_path;                   // empty: no C header
  std::string symbol = "tolip_pitch_table";    // C array name in the header
  std::string mission_id;                      // empty: from the case title (data block 1)
  std::optional<std::int64_t> created_unix_s;  // empty: SOURCE_DATE_EPOCH, else the current time
};
int run_export_command(const ExportCommandOptions& options, std::ostream& out, std::ostream& err);

// `tolip inspect IMAGE`
struct InspectCommandOptions {
  std::string image_path;
  bool json = false;  // the image's contents as one JSON document (docs/cli.md)
};
int run_inspect_command(const InspectCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace tolip::ground
