// The subcommands of the `tolip` program and the program itself (docs/cli.md).
//
// Every command writes its normal output to `out` and its diagnostics to `err` as
// "tolip: <message>", and returns the process exit code.
#pragma once

#include <cstdint>
#include <ostream>
#include <string>

#include "tolip_ground/progress.hpp"

namespace tolip::ground {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;   // run-time or core failure (trajectory, orbit, file write)
inline constexpr int kExitBadInput = 2;  // bad command line or deck

// The altitudes `tolip atmosphere` accepts, ft: from -5 km (where the 1962 standard atmosphere
// starts) to 1,000,000 ft (about 305 km; trajectories bypass the atmosphere above CT1(7) =
// 250,000 ft, and far above the last Sec. 19 base the extended layer describes nothing).
inline constexpr double kAtmosphereLowestAltitude_ft = -16404.0;
inline constexpr double kAtmosphereHighestAltitude_ft = 1000000.0;

// `tolip atmosphere --altitude-ft H [--json]`
struct AtmosphereCommandOptions {
  double altitude_ft = 0.0;  // geometric altitude
  bool json = false;
};
int run_atmosphere_command(const AtmosphereCommandOptions& options, std::ostream& out, std::ostream& err);

// `tolip simulate DECK [--csv FILE] [--json]`
struct SimulateCommandOptions {
  std::string deck_path;
  std::string csv_path;  // empty: no CSV
  bool json = false;
  // IP(24) = 1 / IP(22) = 1: the radar look angles / hardover turns as CSV (radar_report.hpp,
  // hardover_report.hpp; FILE.caseN per case of several); empty: none.
  std::string radar_csv_path;
  std::string hardover_csv_path;
};
int run_simulate_command(const SimulateCommandOptions& options, std::ostream& out, std::ostream& err);

// `tolip optimize DECK [--csv FILE] [--json] [--progress|--no-progress]`: every case of the deck in
// order. A deck of one case prints one JSON document, a deck of several a JSON array of one per case.
struct OptimizeCommandOptions {
  std::string deck_path;
  std::string csv_path;  // empty: no CSV (of the final trajectory; FILE.caseN per case of several)
  // IP(21) = 1: the dispersion analysis as CSV (dispersion_report.hpp); empty: none.
  std::string dispersions_csv_path;
  // IP(23) = 1: the impact locus as CSV (impact_report.hpp); empty: none.
  std::string impact_csv_path;
  bool json = false;
  // IP(24) = 1 / IP(22) = 1: the radar look angles / hardover turns as CSV; empty: none.
  std::string radar_csv_path;
  std::string hardover_csv_path;
  ProgressMode progress = ProgressMode::kAuto;  // the forward-run status line on stderr
  // `--listing-level final|full|runs` (tolip_ground/run_listing.hpp); empty: the deck's data
  // block 9 decides (runs when it gives an initial or intermediate frequency other than 1).
  std::string listing_level;
};
int run_optimize_command(const OptimizeCommandOptions& options, std::ostream& out, std::ostream& err);

// `tolip dispersions DECK [--csv FILE] [--json]`: optimize each case as `optimize` does and run the
// dispersion analysis (manual Sec. 15, data blocks 46-55) about its final nominal whatever IP(21)
// says; reports only that analysis (dispersion_run.hpp, docs/cli.md).
struct DispersionsCommandOptions {
  std::string deck_path;
  std::string csv_path;  // empty: no CSV (FILE.caseN per case of several)
  bool json = false;
};
int run_dispersions_command(const DispersionsCommandOptions& options, std::ostream& out, std::ostream& err);

// `tolip impact DECK [--csv FILE] [--json]`: the nominal impact locus (manual Sec. 17, data blocks
// 42-43) of each case about the trajectory `simulate` flies (impact_run.hpp, docs/cli.md).
struct ImpactCommandOptions {
  std::string deck_path;
  std::string csv_path;  // empty: no CSV (FILE.caseN per case of several)
  bool json = false;
};
int run_impact_command(const ImpactCommandOptions& options, std::ostream& out, std::ostream& err);

// `tolip radar DECK [--csv FILE] [--json]`: the radar tracking (Sec. 18) of each case's trajectory,
// flown as `simulate` flies it, from the deck's data block 41 stations (docs/cli.md).
struct RadarCommandOptions {
  std::string deck_path;
  std::string csv_path;  // empty: no CSV (FILE.caseN per case of several)
  bool json = false;
};
int run_radar_command(const RadarCommandOptions& options, std::ostream& out, std::ostream& err);

// `tolip hardover DECK [--csv FILE] [--json]`: the failure-mode hardover turns (Sec. 16) from each
// case's trajectory, flown as `simulate` flies it, with the deck's data blocks 44-45 (docs/cli.md).
struct HardoverCommandOptions {
  std::string deck_path;
  std::string csv_path;  // empty: no CSV (FILE.caseN per case of several)
  bool json = false;
};
int run_hardover_command(const HardoverCommandOptions& options, std::ostream& out, std::ostream& err);

// `tolip hil DECK --table FILE [--scenario NAME] [--seed S] [--rate-hz HZ] [--telemetry FILE]
// [--mission-id TEXT] [--json]`: the hardware-in-the-loop bench (docs/hil.md, docs/cli.md).
struct HilCommandOptions {
  std::string deck_path;
  std::string table_path;
  std::string scenario = "nominal";
  std::uint64_t seed = 1;
  double rate_hz = 50.0;
  std::string telemetry_path;  // empty: no CSV
  std::string mission_id;      // the identifier the table was exported with; empty: the case title's
  bool json = false;
  std::string target = "host";  // host: in process; qemu: the Cortex-M7 image under QEMU
  std::string image_path;       // --target qemu: the image; empty: the cortex-m7 preset's build
  double duration_s = 0.0;      // > 0: fly only this long
};
int run_hil_command(const HilCommandOptions& options, std::ostream& out, std::ostream& err);

// `tolip convert DECK --to OUT [--format toml|cards] [--case N]`: a card deck to TOML and back.
struct ConvertCommandOptions {
  std::string deck_path;
  std::string out_path;
  std::string format;   // "toml", "cards" or empty (from the extension of out_path)
  int case_number = 0;  // card deck -> TOML: the case (0: the deck must hold one)
};
int run_convert_command(const ConvertCommandOptions& options, std::ostream& out, std::ostream& err);

// `tolip plot RESULT.json --out DIR`: PNG and SVG figures of a simulate/optimize JSON result,
// drawn by gnuplot (plot.hpp, docs/cli.md).
struct PlotCommandOptions {
  std::string result_path;
  std::string out_dir;
  std::string gnuplot;  // the gnuplot program; empty: $TOLIP_GNUPLOT, else "gnuplot" on PATH
};
int run_plot_command(const PlotCommandOptions& options, std::ostream& out, std::ostream& err);

// The whole program: parses the command line (CLI11), runs the subcommand, maps parse errors to
// kExitBadInput. `tolip --help` and `--version` print to `out` and return kExitOk.
int run_tolip(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace tolip::ground
