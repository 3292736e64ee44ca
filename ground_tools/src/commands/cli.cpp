// The `tolip` command line (CLI11): subcommands, help text, exit codes (docs/cli.md).
#include <CLI/CLI.hpp>
#include <cstdint>
#include <ostream>
#include <string>

#include "cli_options.hpp"
#include "tolip_ground/commands.hpp"
#include "tolip_ground/monte_carlo_command.hpp"
#include "tolip_ground/table_commands.hpp"
#include "tolip_ground/version.hpp"

namespace tolip::ground {
namespace {

// What parse_command_line() returns when a command is to run (exit codes are 0 to 2).
constexpr int kRunCommand = -1;

constexpr const char* kDescription =
    "TOLIP - Trajectory Optimization and Linearized Pitch (NASA CR-66515, 1966),\n"
    "a modern re-implementation for Scout-class launch vehicles.";

constexpr const char* kFooter =
    "A DECK is a TOML deck or a heritage card deck (80-column cards, manual\n"
    "Sec. 22), recognised by its content; docs/deck-format.md.\n"
    "Getting started (docs/user-guide.md walks through it):\n"
    "  tolip simulate examples/scout/mission.toml\n"
    "  tolip optimize examples/scout/mission.toml --json > result.json\n"
    "  tolip plot result.json --out plots\n"
    "  tolip convert examples/scout/mission.toml --to mission.dat\n"
    "  tolip export examples/scout/mission.toml --out table.bin\n"
    "  tolip inspect table.bin\n"
    "  tolip montecarlo examples/scout/mission.toml --samples 1000 --seed 1\n"
    "Exit codes: 0 success; 1 run-time or core failure (trajectory, orbit elements,\n"
    "file write, optimization not converged, gnuplot); 2 bad input (command line,\n"
    "deck or result file). Errors go to stderr as 'tolip: <message>'.\n"
    "Run 'tolip <command> --help' for a command's options and examples.\n"
    "Full reference: docs/cli.md.";

// "atmosphere, simulate, ..." in the order of the help.
std::string command_names(const CLI::App& app) {
  std::string names;
  for (const CLI::App* command : app.get_subcommands({})) {
    names += (names.empty() ? "" : ", ") + command->get_name();
  }
  return names;
}

// The first word of the command line that is not an option, when no command was parsed and that
// word names none; "" otherwise. The program's own options (--help, --version) take no value, so
// that word is where the command belongs.
std::string unknown_command_word(const CLI::App& app, int argc, const char* const* argv) {
  for (const CLI::App* command : app.get_subcommands({})) {
    if (command->parsed()) return {};
  }
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word == "--") return i + 1 < argc ? argv[i + 1] : "";
    if (word.empty() || word[0] == '-') continue;
    for (const CLI::App* command : app.get_subcommands({})) {
      if (command->check_name(word)) return {};
    }
    return word;
  }
  return {};
}

// Rejects an empty (or all-blank) option value, which CLI11 would otherwise read as 0 or as "not
// given": `--altitude-ft ""`, `--mission-id ""`.
CLI::Validator not_blank(const std::string& expected) {
  return CLI::Validator(
      [expected](std::string& value) -> std::string {
        if (value.find_first_not_of(" \t") != std::string::npos) return std::string();
        return "an empty value: expected " + expected;
      },
      "");
}

// tolip atmosphere: the 1962 ARDC atmosphere at one altitude.
CLI::App* add_atmosphere_command(CLI::App& app, AtmosphereCommandOptions* options) {
  CLI::App* atmosphere = add_command(app, "atmosphere",
                                     "Evaluate the 1962 ARDC standard atmosphere of manual\n"
                                     "Sec. 19 at one geometric altitude: density (slug/ft^3),\n"
                                     "pressure (lbf/ft^2), speed of sound (ft/s) and molecular-\n"
                                     "scale temperature (deg R). The geopotential altitude uses\n"
                                     "the equatorial radius CT1(3) = 20,925,696 ft.",
                                     "Examples:\n"
                                     "  tolip atmosphere --altitude-ft 0\n"
                                     "  tolip atmosphere --altitude-ft=-500 --json\n"
                                     "Exit codes: 0 printed; 2 bad command line (missing, empty,\n"
                                     "unparsable or non-finite altitude, or outside -16404 to 1000000 ft).\n"
                                     "Full reference: docs/cli.md, 'tolip atmosphere'.");
  atmosphere
      ->add_option("--altitude-ft", options->altitude_ft, "Geometric altitude, ft, -16404 (-5 km) to 1000000")
      ->required()
      ->check(not_blank("an altitude in ft"))
      ->type_name("FT");
  add_json_flag(*atmosphere, &options->json,
                "Print one JSON object instead of text (keys\n"
                "altitude_ft, geopotential_altitude_ft, earth_radius_ft,\n"
                "density_slug_ft3, pressure_lbf_ft2, speed_of_sound_ft_s,\n"
                "temperature_R)");
  return atmosphere;
}

// tolip simulate: fly each case of a deck and report it.
CLI::App* add_simulate_command(CLI::App& app, SimulateCommandOptions* options) {
  CLI::App* simulate = add_command(app, "simulate",
                                   "Load a case deck (TOML, or a heritage card deck recognised by\n"
                                   "its content), fly the forward trajectory of each case (no\n"
                                   "optimization) and report it: a manual-style listing (page\n"
                                   "titles of data blocks 1-3, the points data block 9 selects,\n"
                                   "stage events, terminal conditions and orbit elements; with\n"
                                   "IP(17) the input data first), or one JSON document (--json;\n"
                                   "an array of one per case for a deck of several cases);\n"
                                   "--csv FILE adds every point (FILE.caseN.csv per case).",
                                   "Examples:\n"
                                   "  tolip simulate examples/scout/mission.toml\n"
                                   "  tolip simulate examples/scout/mission.dat --csv points.csv\n"
                                   "  tolip simulate examples/scout/mission.toml --json > result.json\n"
                                   "  tolip plot result.json --out plots\n"
                                   "Exit codes: 0 every case flown; 1 a trajectory or orbit failure in\n"
                                   "any case (everything is still printed) or the CSV not written\n"
                                   "(nothing printed); 2 bad command line or deck.\n"
                                   "Full reference: docs/cli.md, 'tolip simulate'.");
  add_deck_argument(*simulate, &options->deck_path, kDeckOfCasesHelp);
  add_csv_option(*simulate, &options->csv_path,
                 "Also write EVERY integration point (not thinned) to\n"
                 "FILE as CSV with a header row; for a deck of several\n"
                 "cases one file per case, FILE.caseN.csv. Written\n"
                 "atomically (FILE.tmp.<pid>, then rename): on failure an\n"
                 "existing FILE is left untouched and the exit code is 1");
  add_file_option(*simulate, "--radar-csv", &options->radar_csv_path,
                  "With IP(24) = 1: also write the radar look angles (the\n"
                  "columns of radar --csv) to FILE as CSV, atomically\n"
                  "(FILE.caseN.csv per case)");
  add_file_option(*simulate, "--hardover-csv", &options->hardover_csv_path,
                  "With IP(22) = 1: also write the hardover turns (the\n"
                  "columns of hardover --csv) to FILE as CSV, atomically\n"
                  "(FILE.caseN.csv per case)");
  add_json_flag(*simulate, &options->json,
                "Print one JSON document (status, burnout state,\n"
                "inertial velocity, orbit elements, stage events, every\n"
                "point) instead of the listing; a JSON array of one per\n"
                "case for a deck of several cases. Printed also when the\n"
                "trajectory fails (then with exit code 1)");
  return simulate;
}

// tolip optimize's files beside the listing: the final trajectory and the optional computations'
// results as CSV.
void add_optimize_csv_options(CLI::App* optimize, OptimizeCommandOptions* options) {
  add_csv_option(*optimize, &options->csv_path,
                 "Also write EVERY integration point of the final\n"
                 "trajectory to FILE as CSV (the columns of simulate\n"
                 "--csv; FILE.caseN.csv per case of a several-case deck),\n"
                 "atomically; on a write failure an existing FILE is left\n"
                 "untouched, nothing is printed and the exit code is 1");
  add_file_option(*optimize, "--dispersions-csv", &options->dispersions_csv_path,
                  "With IP(21) = 1: also write the dispersion analysis\n"
                  "(every dispersed trajectory's staging-point values and\n"
                  "dispersions, orbit elements, max q-bar alpha) to FILE as\n"
                  "CSV (FILE.caseN.csv per case of a several-case deck)");
  add_file_option(*optimize, "--impact-csv", &options->impact_csv_path,
                  "With IP(23) = 1: also write the impact locus (one row\n"
                  "per thrust failure and expended casing: failure and\n"
                  "impact times, latitudes, longitude, downrange,\n"
                  "crossrange) to FILE as CSV (FILE.caseN.csv per case)");
  add_file_option(*optimize, "--radar-csv", &options->radar_csv_path,
                  "With IP(24) = 1: also write the radar look angles (one\n"
                  "row per station and point; the columns of radar --csv)\n"
                  "to FILE as CSV, atomically (FILE.caseN.csv per case)");
  add_file_option(*optimize, "--hardover-csv", &options->hardover_csv_path,
                  "With IP(22) = 1: also write the hardover turns (the\n"
                  "columns of hardover --csv) to FILE as CSV, atomically\n"
                  "(FILE.caseN.csv per case)");
}

// tolip optimize's status line on stderr: --progress, --no-progress (excluding each other).
void add_optimize_progress_flags(CLI::App* optimize, OptimizeCommandOptions* options) {
  add_progress_flags(*optimize, &options->progress,
                     "Show the one-line status of the forward runs on\n"
                     "stderr ('forward run 7  payoff 301.2 lb  successful')\n"
                     "even when stderr is not a terminal. Default: shown only\n"
                     "on a terminal; it never reaches stdout",
                     "Never show the status line, not even on a terminal");
}

// tolip optimize: optimize each case of a deck.
CLI::App* add_optimize_command(CLI::App& app, OptimizeCommandOptions* options) {
  CLI::App* optimize = add_command(app, "optimize",
                                   "Load a case deck (TOML, or a card deck of one or more\n"
                                   "cases) and optimize each case in order: closed-loop steepest\n"
                                   "descent (manual Sec. 5, 9, 22) from the data block 40 pitch\n"
                                   "program: guidance runs into the data block 29 deadbands,\n"
                                   "optimization runs improving the payoff (IP(1): payload,\n"
                                   "velocity or altitude), a final guidance run. Prints the\n"
                                   "iteration history (per forward run: kind, success,\n"
                                   "constraint corrections, attempted payoff increment, payoff,\n"
                                   "corrected payoff, payload and its increment, partials of\n"
                                   "payoff with respect to each constraint), the final\n"
                                   "trajectory listed as by 'simulate', and a summary\n"
                                   "(constraints desired/achieved/tolerance, adjustable\n"
                                   "parameters; exchange ratios with IP(3)).",
                                   "Examples:\n"
                                   "  tolip optimize examples/scout/mission.toml\n"
                                   "  tolip optimize examples/scout/mission.dat --csv final.csv\n"
                                   "  tolip optimize examples/scout/mission.toml --json > result.json\n"
                                   "  tolip plot result.json --out plots\n"
                                   "Exit codes: 0 every case converged and every computation its\n"
                                   "deck asks for (exchange ratios, linearization) succeeded; 1 a case\n"
                                   "did not converge (guidance never did, no optimization run, final\n"
                                   "guidance failed), a later step failed, or the core failed\n"
                                   "(everything is still printed, with the best trajectory found),\n"
                                   "or the CSV not written (nothing printed);\n"
                                   "2 bad command line, deck, or a case the optimizer rejects\n"
                                   "(unsupported payoff, adjustable parameter or constraint code).\n"
                                   "Full reference: docs/cli.md, 'tolip optimize'.");
  add_deck_argument(*optimize, &options->deck_path, kDeckOfCasesHelp);
  add_optimize_csv_options(optimize, options);
  add_json_flag(*optimize, &options->json,
                "Print one JSON document instead of the listing: the\n"
                "simulate --json keys for the final trajectory plus\n"
                "converged, forward_runs, backward_runs, payoff,\n"
                "payload_lb, constraints, payoff_partials, adjustable,\n"
                "theta_history, iterations (docs/cli.md); a JSON array\n"
                "of one document per case for a deck of several cases");
  optimize
      ->add_option("--listing-level", options->listing_level,
                   "How much the listing prints (docs/cli.md): final (the\n"
                   "history, final trajectory and summary), full (adds the\n"
                   "third line group CHI BETA6D THETAC THETADOT DTHETA DELTA,\n"
                   "the Sec. 14 thrust page, the linearization runs' programs\n"
                   "and the linearized and 6D trajectories), runs (adds the\n"
                   "initial nominal and every forward run, thinned by data\n"
                   "block 9). Default: runs when data block 9 gives an initial\n"
                   "or intermediate frequency other than 1, else final")
      ->check(CLI::IsMember({"final", "full", "runs"}))
      ->type_name("LEVEL");
  add_optimize_progress_flags(optimize, options);
  return optimize;
}

// tolip dispersions: the dispersion analysis of each case of a deck about its final nominal.
CLI::App* add_dispersions_command(CLI::App& app, DispersionsCommandOptions* options) {
  CLI::App* dispersions =
      add_command(app, "dispersions",
                  "Dispersion analysis (manual Sec. 15, data blocks 46-55):\n"
                  "optimize each case as 'optimize' does, then fly every\n"
                  "dispersion code of the deck about the final nominal (the\n"
                  "linearized program under IP(7), else the optimum), whatever\n"
                  "IP(21) says. Prints per dispersed trajectory the staging\n"
                  "variables and orbit elements with their dispersions, the\n"
                  "summary of the individual dispersions and the three-sigma\n"
                  "variations by sum and root-sum-square, without and with\n"
                  "winds. With IP(21) = 1 'optimize' prints the same pages\n"
                  "after its own.",
                  "Examples:\n"
                  "  tolip dispersions examples/scout/mission.toml\n"
                  "  tolip dispersions examples/scout/mission.toml --csv dispersions.csv\n"
                  "  tolip dispersions examples/scout/mission.toml --json > dispersions.json\n"
                  "Exit codes: 0 every case's analysis computed; 1 a case has no final\n"
                  "nominal (the optimization did not converge) or a dispersed\n"
                  "trajectory failed (everything is still printed), or the CSV not\n"
                  "written (nothing printed); 2 bad command line or deck (also a deck\n"
                  "without data block 46, or dispersion data the core cannot hold:\n"
                  "the message names the block, the code and the field).\n"
                  "Full reference: docs/cli.md, 'tolip dispersions'.");
  add_deck_csv_json(*dispersions, options,
                    {kDeckOfCasesHelp,
                     "Also write the analysis to FILE as CSV, the rows of\n"
                     "'optimize --dispersions-csv' (FILE.caseN.csv per case of a\n"
                     "several-case deck), atomically; on failure an existing FILE\n"
                     "is left untouched",
                     "Print JSON instead of the listing: per case (an array for\n"
                     "a deck of several) case, optimizer_status and the member\n"
                     "'dispersions' of 'optimize --json' (docs/cli.md)"});
  return dispersions;
}

// tolip impact: the nominal impact locus of each case of a deck.
CLI::App* add_impact_command(CLI::App& app, ImpactCommandOptions* options) {
  CLI::App* impact = add_command(app, "impact",
                                 "Nominal impact locus (manual Sec. 17, data blocks 42-43,\n"
                                 "DA6D(17-19)): fly each case as 'simulate' does, then fly to\n"
                                 "impact on the geodetic Earth, with drag and no thrust, the\n"
                                 "vehicle after a thrust failure at every n-th integration\n"
                                 "point of stages 1-3 and the expended casings of stages 1-3.\n"
                                 "Prints per case the failure and impact times, geodetic and\n"
                                 "geocentric latitude, longitude, downrange and crossrange.\n"
                                 "With IP(23) = 1 'optimize' computes the same locus about\n"
                                 "the final nominal (the linearized program under IP(7)).",
                                 "Examples:\n"
                                 "  tolip impact examples/scout/mission.toml\n"
                                 "  tolip impact examples/scout/mission.toml --csv impact.csv\n"
                                 "  tolip impact examples/scout/mission.toml --json > impact.json\n"
                                 "  tolip plot impact.json --out plots\n"
                                 "Exit codes: 0 every case's locus computed; 1 a trajectory or an\n"
                                 "impact trajectory failed (everything is still printed) or the CSV\n"
                                 "not written (nothing printed); 2 bad command line or deck (also\n"
                                 "a deck without the data blocks 42-43, or an n of DA6D(17-19)\n"
                                 "past the end of its stage: the message names the block and word).\n"
                                 "Full reference: docs/cli.md, 'tolip impact'.");
  add_deck_csv_json(*impact, options,
                    {kDeckOfCasesHelp,
                     "Also write the locus to FILE as CSV, one row per case\n"
                     "(FILE.caseN.csv per case of a several-case deck),\n"
                     "atomically; on failure an existing FILE is left untouched",
                     "Print one JSON document instead of the listing: the\n"
                     "simulate --json document of the nominal with the member\n"
                     "'impact' (docs/cli.md); 'tolip plot' draws its locus"});
  return impact;
}

// tolip plot: draw the figures of a JSON result with gnuplot.
CLI::App* add_plot_command(CLI::App& app, PlotCommandOptions* options) {
  CLI::App* plot = add_command(app, "plot",
                               "Draw the figures of a result - the JSON printed by\n"
                               "'simulate --json' or 'optimize --json' - as PNG and SVG with\n"
                               "gnuplot: altitude (n.mi.) vs downrange (ascent and full\n"
                               "flight), velocity, flight-path angle, q-bar, alpha, q-bar x\n"
                               "alpha, pitch attitude theta (ascent and full flight; with\n"
                               "optimize the optimum, and the linearized program over it when\n"
                               "the result has one) and weight vs time, the ground track, and\n"
                               "the optimizer's convergence (payoff and constraint error /\n"
                               "deadband per forward run). Stage ignitions and burnouts, max q\n"
                               "and the zero-alpha window are marked; titles carry the case\n"
                               "heading and run status. A plot whose data the result lacks is\n"
                               "skipped, and so is one whose data hold no finite value (all\n"
                               "null, or beyond 1e30 in magnitude), with a note on stderr\n"
                               "naming it.",
                               "Files: DIR/NAME.png and DIR/NAME.svg, NAME =\n"
                               "altitude_downrange_ascent, altitude_downrange, velocity_time,\n"
                               "flight_path_angle_time, dynamic_pressure_time, alpha_time,\n"
                               "qalpha_time, theta_time_ascent, theta_time, weight_time,\n"
                               "ground_track, impact_locus (with IP(23) or from 'tolip impact'),\n"
                               "convergence; radar_<id> per radar station of a\n"
                               "result with 'radar' (azimuth, elevation, below the horizon dashed);\n"
                               "for a JSON array (a deck of several\n"
                               "cases) every case overlaid on the same figures, a colour and\n"
                               "a legend entry per case. Everything is drawn and checked in a\n"
                               "temporary directory first, then each file is written\n"
                               "atomically: a failure leaves DIR as it was.\n"
                               "Examples:\n"
                               "  tolip optimize examples/scout/mission.toml --json > result.json\n"
                               "  tolip plot result.json --out plots\n"
                               "Exit codes: 0 written; 1 gnuplot missing or failing, or DIR not\n"
                               "writable; 2 bad command line, unreadable file (a directory, or\n"
                               "larger than 64 MiB), or a result that is not valid JSON or lacks\n"
                               "the fields (the message names the field).\n"
                               "Full reference: docs/cli.md, 'tolip plot'.");
  add_required_file(*plot, "RESULT", &options->result_path,
                    "JSON result of simulate --json or optimize --json: one\n"
                    "document, or an array of one per case");
  plot->add_option("--out", options->out_dir, "Directory for the figures; made when missing")
      ->required()
      ->type_name("DIR");
  plot->add_option("--gnuplot", options->gnuplot,
                   "The gnuplot program to run (default: $TOLIP_GNUPLOT,\n"
                   "else gnuplot on PATH; Debian package gnuplot-nox)")
      ->type_name("PROGRAM");
  return plot;
}

// tolip export: write the guidance table image of a case (docs/table-format.md).
CLI::App* add_export_command(CLI::App& app, ExportCommandOptions* options) {
  CLI::App* export_command =
      add_command(app, "export",
                  "Build the guidance-computer table image (docs/table-format.md)\n"
                  "from a case deck (TOML or cards) and write it atomically:\n"
                  "the pitch segments (the linearized optimum when the deck\n"
                  "asks for linearization, IP(7) = 1, the case being optimized\n"
                  "first; else the data block 40 pitch table), lift-off,\n"
                  "spun-stage attitudes, autopilot gains, limits, CRC-32.",
                  "Examples:\n"
                  "  tolip export examples/scout/mission.toml --out table.bin\n"
                  "  tolip export examples/scout/mission.toml --out table.bin \\\n"
                  "      --c-header table.h --created-unix-s 0\n"
                  "  tolip inspect table.bin\n"
                  "The image is decoded again with the flight-side loader's checks\n"
                  "before anything is written; each file goes to FILE.tmp.<pid> and is\n"
                  "renamed over FILE.\n"
                  "Outputs are written only as regular files: an existing FILE that\n"
                  "is a symbolic link, FIFO, device or directory is refused.\n"
                  "Exit codes: 0 written; 1 prepare_case failed, the optimization\n"
                  "job failed (IP(7) = 1: the same rule as optimize), or a file could\n"
                  "not be written; 2 bad command line (also --out and --c-header\n"
                  "naming one file, or the deck), deck, or a case the image cannot\n"
                  "carry (the message names the data block).\n"
                  "Full reference: docs/cli.md, 'tolip export'; docs/table-format.md.");
  add_deck_argument(*export_command, &options->deck_path,
                    "TOML deck or card deck of one case\n"
                    "(docs/deck-format.md)");
  add_required_file(*export_command, "--out", &options->out_path, "The binary image (1580 bytes)");
  add_file_option(*export_command, "--c-header", &options->c_header_path,
                  "Also write the image as a C const array NAME in the\n"
                  "linker section .tolip_table, with the macros\n"
                  "TOLIP_TABLE_IMAGE_<SYMBOL>_H_SIZE (1580u) and\n"
                  "TOLIP_TABLE_IMAGE_<SYMBOL>_H_CRC32, <SYMBOL> = NAME\n"
                  "upper-cased (include guard TOLIP_TABLE_IMAGE_<SYMBOL>_H)");
  export_command
      ->add_option("--symbol", options->symbol,
                   "C array name in the header, a C identifier\n"
                   "(default tolip_pitch_table)")
      ->type_name("NAME");
  export_command
      ->add_option("--mission-id", options->mission_id,
                   "Mission identifier, 1-32 printable ASCII characters\n"
                   "(default: the case title, data block 1)")
      ->check(not_blank("1-32 printable ASCII characters (leave the option out for the case title)"))
      ->type_name("TEXT");
  export_command
      ->add_option("--created-unix-s", options->created_unix_s,
                   "Creation stamp, s since 1970-01-01Z, 0-253402300799\n"
                   "(default: SOURCE_DATE_EPOCH, else the current time);\n"
                   "fix it for byte-identical repeated exports")
      ->type_name("N");
  return export_command;
}

// tolip inspect: validate and print a guidance table image.
CLI::App* add_inspect_command(CLI::App& app, InspectCommandOptions* options) {
  CLI::App* inspect = add_command(app, "inspect",
                                  "Validate a guidance table image with the flight-side loader's\n"
                                  "checks and print it in engineering units; a bad image is\n"
                                  "named by its fault (exit 2).",
                                  "Prints the format version, size, CRC-32, mission id, creation stamp,\n"
                                  "lift-off duration, rate limits, maximum deflection, spun attitudes,\n"
                                  "gains of stage codes 1-10 and one row per segment.\n"
                                  "Examples:\n"
                                  "  tolip inspect table.bin\n"
                                  "  tolip inspect table.bin --json\n"
                                  "Exit codes: 0 valid; 2 bad command line, unreadable file (a\n"
                                  "directory, or larger than an image: at most 1580 bytes are read) or\n"
                                  "invalid image (stderr names the status, e.g. kTableImageCrcMismatch).\n"
                                  "Full reference: docs/cli.md, 'tolip inspect'.");
  add_required_file(*inspect, "IMAGE", &options->image_path, "Table image written by tolip export");
  add_json_flag(*inspect, &options->json,
                "Print the contents as one JSON document instead of the listing\n"
                "(degrees, deg/s, s; keys in docs/cli.md)");
  return inspect;
}

// tolip convert: card deck to TOML deck and back.
CLI::App* add_convert_command(CLI::App& app, ConvertCommandOptions* options) {
  CLI::App* convert = add_command(app, "convert",
                                  "Convert a deck between the heritage card format (80-column\n"
                                  "card images, manual Sec. 22) and the TOML deck: DECK (either\n"
                                  "format, recognised by content) is read and checked like any\n"
                                  "deck, converted, read back, and written atomically to the\n"
                                  "--to FILE.\n"
                                  "A card deck of several cases needs --case N for TOML; cards\n"
                                  "write every case (later cases as their changes).",
                                  "Examples:\n"
                                  "  tolip convert examples/scout/mission.toml --to mission.dat\n"
                                  "  tolip convert mission.dat --to mission.toml\n"
                                  "  tolip convert examples/scout/cases.dat --to case2.toml --case 2\n"
                                  "Exit codes: 0 written; 1 the file could not be written (an existing\n"
                                  "FILE is left untouched; one that is not a regular file is refused);\n"
                                  "2 bad command line (also FILE being DECK itself), deck, unknown output\n"
                                  "format, a several-case deck to TOML without --case, or a value the\n"
                                  "cards cannot hold.\n"
                                  "Full reference: docs/cli.md, 'tolip convert'; docs/deck-format.md.");
  add_deck_argument(*convert, &options->deck_path, "Card deck or TOML deck");
  add_required_file(*convert, "--to", &options->out_path,
                    "The converted deck; its format follows the name\n"
                    "(*.toml: TOML; *.dat, *.cards, *.crd: card deck)");
  convert->add_option("--format", options->format, "Output format regardless of the name: toml or cards")
      ->type_name("FORMAT");
  convert
      ->add_option("--case", options->case_number,
                   "Case of a several-case card deck to write as TOML\n"
                   "(1-based; a TOML deck holds one case)")
      ->type_name("N");
  return convert;
}

// tolip radar: the radar tracking coordinates of each case (Sec. 18).
CLI::App* add_radar_command(CLI::App& app, RadarCommandOptions* options) {
  CLI::App* radar = add_command(app, "radar",
                                "Radar tracking coordinates (manual Sec. 18): fly each case of\n"
                                "the deck as 'simulate' does and print, for every station of\n"
                                "data block 41, the slant range (yards), azimuth and elevation\n"
                                "(degrees, degrees-minutes, mils) at every integration point\n"
                                "from launch through the last burnout. With IP(24) = 1,\n"
                                "'simulate' and 'optimize' (the final nominal) add the same.",
                                "Examples:\n"
                                "  tolip radar examples/scout/mission.toml\n"
                                "  tolip radar examples/scout/mission.toml --json > radar.json\n"
                                "  tolip plot radar.json --out plots\n"
                                "Exit codes: 0 tracked; 1 the trajectory failed (the points flown\n"
                                "are tracked and printed) or the CSV not written (nothing printed);\n"
                                "2 bad command line or deck (also a deck without data block 41).\n"
                                "Full reference: docs/cli.md, 'tolip radar'; docs/theory/radar.md.");
  add_deck_csv_json(*radar, options,
                    {"TOML deck or card deck of one or more cases, with data\n"
                     "block 41 (docs/deck-format.md)",
                     "Also write one row per station and point (time, stage,\n"
                     "range ft and yd, azimuth and elevation deg and mils) to\n"
                     "FILE as CSV, atomically (FILE.caseN.csv per case)",
                     "Print one JSON document instead of the listing: the\n"
                     "case's title, status and the member 'radar' (docs/cli.md)"});
  return radar;
}

// tolip hardover: the failure-mode hardover turns of each case (Sec. 16).
CLI::App* add_hardover_command(CLI::App& app, HardoverCommandOptions* options) {
  CLI::App* hardover = add_command(app, "hardover",
                                   "Failure-mode hardover turns (manual Sec. 16): fly each case as\n"
                                   "'simulate' does and compute, from every n-th integration point\n"
                                   "of stages 1-3 (data block 45), the turn a control failure makes\n"
                                   "in up to ten seconds: stage 1 fins and jet vanes hard over with\n"
                                   "thrust misalignment, stages 2-3 control-jet modes 1-3. Prints\n"
                                   "TIME, CHG GAMMA, QBAR-A and the stop of every turn. With IP(22)\n"
                                   "= 1, 'simulate' and 'optimize' (the final nominal) add the same.",
                                   "Examples:\n"
                                   "  tolip hardover examples/scout/mission.toml\n"
                                   "  tolip hardover examples/scout/mission.toml --json > hardover.json\n"
                                   "  tolip plot hardover.json --out plots\n"
                                   "Exit codes: 0 computed; 1 the trajectory failed or the CSV not\n"
                                   "written (nothing printed); 2 bad command line or deck (also a\n"
                                   "deck without data blocks 44-45, or a bad word of them: the message\n"
                                   "names the block, word and stage).\n"
                                   "Full reference: docs/cli.md, 'tolip hardover'; docs/theory/hardover.md.");
  add_deck_csv_json(*hardover, options,
                    {"TOML deck or card deck of one or more cases, with data\n"
                     "blocks 44-45 and 33, 37 (docs/deck-format.md)",
                     "Also write one row per turn and output line (stage,\n"
                     "mode, failure time, time, change in gamma, q-bar alpha,\n"
                     "stop) to FILE as CSV, atomically (FILE.caseN.csv per case)",
                     "Print one JSON document instead of the listing: the\n"
                     "case's title, status and the member 'hardover' (docs/cli.md)"});
  return hardover;
}

// tolip hil: the hardware-in-the-loop bench (docs/hil.md).
CLI::App* add_hil_command(CLI::App& app, HilCommandOptions* options) {
  CLI::App* hil =
      add_command(app, "hil",
                  "Hardware-in-the-loop bench (docs/hil.md): upload a table image\n"
                  "through the flight-side loader of the flight application, fly it\n"
                  "minor cycle by minor cycle against the simulated vehicle (the\n"
                  "core's trajectory physics with rigid-body pitch and yaw, actuators,\n"
                  "noisy sensors) from lift-off to the final burnout, with a fault\n"
                  "scenario, and report burnout and orbit beside the ground prediction.",
                  "Examples:\n"
                  "  tolip export examples/scout/reference_optimum.toml --out table.bin\n"
                  "  tolip hil examples/scout/reference_optimum.toml --table table.bin\n"
                  "  tolip hil DECK --table table.bin --scenario sensor-dropout --telemetry tm.csv\n"
                  "  tolip hil DECK --table table.bin --target qemu --image tolip_flight_pil.elf\n"
                  "Scenarios: nominal, upload-corrupt, upload-truncated, sensor-dropout,\n"
                  "actuator-stuck, actuator-hardover, late-ignition, thrust-misalignment,\n"
                  "link-loss, link-corruption (docs/hil.md).\n"
                  "Exit codes: 0 flown (whatever the vehicle did: the report says); 1 the\n"
                  "prediction or the bench failed, or the telemetry not written; 2 bad\n"
                  "command line, deck, table image (fails validation), unknown scenario,\n"
                  "or a table that does not belong to the deck (mission identifier,\n"
                  "segment count).\n"
                  "Full reference: docs/cli.md, 'tolip hil'; docs/hil.md.");
  add_deck_argument(*hil, &options->deck_path,
                    "TOML deck or card deck of one case, with data blocks 33-37 and 44-45");
  add_required_file(*hil, "--table", &options->table_path, "The table image to upload (tolip export)");
  hil->add_option("--scenario", options->scenario, "Fault scenario (default nominal; docs/hil.md)")
      ->type_name("NAME");
  hil->add_option("--seed", options->seed, "Seed of the sensor noise and biases (default 1)")->type_name("S");
  hil->add_option("--rate-hz", options->rate_hz, "Minor-cycle rate, 10-1000 Hz (default 50)")
      ->type_name("HZ");
  add_file_option(*hil, "--telemetry", &options->telemetry_path,
                  "Write the telemetry, one row per cycle, as CSV");
  hil->add_option("--mission-id", options->mission_id,
                  "The mission identifier the table was exported with (default:\n"
                  "the case title's, as tolip export gives it)")
      ->type_name("TEXT");
  add_json_flag(*hil, &options->json, "Print one JSON document instead of the report (docs/cli.md)");
  hil->add_option("--target", options->target,
                  "Where the flight application runs: host (in process, the default)\n"
                  "or qemu (the Cortex-M7 image under qemu-system-arm, in lock-step\n"
                  "over its serial port; docs/hil.md, 'Processor in the loop')")
      ->type_name("host|qemu");
  add_file_option(*hil, "--image", &options->image_path,
                  "The processor-in-the-loop image for --target qemu (default\n"
                  "build-cortex-m7/flight_image/tolip_flight_pil.elf, the cortex-m7\n"
                  "preset's build)");
  hil->add_option("--duration-s", options->duration_s,
                  "Fly only the first S seconds from lift-off (default: to the final burnout)")
      ->type_name("S");
  return hil;
}

// The program's own footer and version flag; exactly one command, whose options stay its own.
void configure_program(CLI::App& app) {
  app.footer(kFooter);
  app.set_version_flag("--version", std::string("tolip ") + version_string(),
                       "Print the program version and exit");
  app.require_subcommand(1);
  app.fallthrough(false);
}

// Parses the command line: kRunCommand when a command is to run, else the exit code (help or
// version printed, or the parse error reported on err).
int parse_command_line(CLI::App& app, int argc, const char* const* argv, std::ostream& out,
                       std::ostream& err) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e, out, err);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e, out, err);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e, out, err);
  } catch (const CLI::ParseError& e) {
    // No command parsed and the first word is not one: say which word, and what the commands are
    // (CLI11 would only say that a subcommand is required).
    if (const std::string unknown = unknown_command_word(app, argc, argv); !unknown.empty()) {
      err << "tolip: unknown command '" << unknown << "'; the commands are: " << command_names(app) << "\n";
      err << "Run 'tolip --help' for more information.\n";
      return kExitBadInput;
    }
    err << "tolip: " << e.what() << "\n";
    err << "Run 'tolip --help' for more information.\n";
    return kExitBadInput;
  }
  return kRunCommand;
}

}  // namespace

int run_tolip(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App app{kDescription, "tolip"};
  configure_program(app);
  // The commands in the order of the help; the one parsed runs on the options its parse filled.
  AtmosphereCommandOptions atmosphere_options;
  SimulateCommandOptions simulate_options;
  OptimizeCommandOptions optimize_options;
  PlotCommandOptions plot_options;
  ExportCommandOptions export_options;
  InspectCommandOptions inspect_options;
  ConvertCommandOptions convert_options;
  MonteCarloCommandOptions monte_carlo_options;
  DispersionsCommandOptions dispersions_options;
  ImpactCommandOptions impact_options;
  RadarCommandOptions radar_options;
  HardoverCommandOptions hardover_options;
  HilCommandOptions hil_options;
  CLI::App* atmosphere = add_atmosphere_command(app, &atmosphere_options);
  CLI::App* simulate = add_simulate_command(app, &simulate_options);
  CLI::App* optimize = add_optimize_command(app, &optimize_options);
  CLI::App* plot = add_plot_command(app, &plot_options);
  CLI::App* export_command = add_export_command(app, &export_options);
  CLI::App* inspect = add_inspect_command(app, &inspect_options);
  CLI::App* convert = add_convert_command(app, &convert_options);
  CLI::App* monte_carlo = add_monte_carlo_command(app, &monte_carlo_options);
  CLI::App* dispersions = add_dispersions_command(app, &dispersions_options);
  CLI::App* impact = add_impact_command(app, &impact_options);
  CLI::App* radar = add_radar_command(app, &radar_options);
  CLI::App* hardover = add_hardover_command(app, &hardover_options);
  CLI::App* hil = add_hil_command(app, &hil_options);

  if (const int exit_code = parse_command_line(app, argc, argv, out, err); exit_code != kRunCommand) {
    return exit_code;
  }
  if (atmosphere->parsed()) return run_atmosphere_command(atmosphere_options, out, err);
  if (simulate->parsed()) return run_simulate_command(simulate_options, out, err);
  if (optimize->parsed()) return run_optimize_command(optimize_options, out, err);
  if (plot->parsed()) return run_plot_command(plot_options, out, err);
  if (export_command->parsed()) return run_export_command(export_options, out, err);
  if (inspect->parsed()) return run_inspect_command(inspect_options, out, err);
  if (convert->parsed()) return run_convert_command(convert_options, out, err);
  if (monte_carlo->parsed()) return run_monte_carlo_command(monte_carlo_options, out, err);
  if (dispersions->parsed()) return run_dispersions_command(dispersions_options, out, err);
  if (impact->parsed()) return run_impact_command(impact_options, out, err);
  if (radar->parsed()) return run_radar_command(radar_options, out, err);
  if (hardover->parsed()) return run_hardover_command(hardover_options, out, err);
  if (hil->parsed()) return run_hil_command(hil_options, out, err);
  err << "tolip: no command given\n";
  return kExitBadInput;
}

}  // namespace tolip::ground
