// The `tolip` command line (CLI11): subcommands, help text, exit codes (docs/cli.md).
#include <CLI/CLI.hpp>
#include <ostream>
#include <string>

#include "tolip_ground/commands.hpp"
#include "tolip_ground/table_commands.hpp"
#include "tolip_ground/version.hpp"

namespace tolip::ground {
namespace {

constexpr const char* kDescription =
    "TOLIP - Trajectory Optimization and Linearized Pitch (NASA CR-66515, 1966),\n"
    "a modern re-implementation for Scout-class launch vehicles.";

constexpr const char* kFooter =
    "Exit codes: 0 success; 1 run-time or core failure (trajectory, orbit elements,\n"
    "file write, optimization not converged); 2 bad input (command line or deck).\n"
    "Errors go to stderr as 'tolip: <message>'. Run 'tolip <command> --help' for a\n"
    "command's options.\n"
    "Full reference: docs/cli.md.";

}  // namespace

int run_tolip(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App app{kDescription, "tolip"};
  app.footer(kFooter);
  app.set_version_flag("--version", std::string("tolip ") + version_string(),
                       "Print the program version and exit");
  app.require_subcommand(1);
  app.fallthrough(false);

  // ---- atmosphere ------------------------------------------------------------------------------
  AtmosphereCommandOptions atmosphere_options;
  CLI::App* atmosphere = app.add_subcommand(
      "atmosphere",
      "Evaluate the 1962 ARDC standard atmosphere of manual\n"
      "Sec. 19 at one geometric altitude: density (slug/ft^3),\n"
      "pressure (lbf/ft^2), speed of sound (ft/s) and molecular-\n"
      "scale temperature (deg R). The geopotential altitude uses\n"
      "the equatorial radius CT1(3) = 20,925,696 ft.");
  atmosphere
      ->add_option("--altitude-ft", atmosphere_options.altitude_ft,
                   "Geometric altitude, ft (finite, negative allowed, above -CT1(3))")
      ->required()
      ->type_name("FT");
  atmosphere->add_flag("--json", atmosphere_options.json,
                       "Print one JSON object instead of text (keys\n"
                       "altitude_ft, geopotential_altitude_ft, earth_radius_ft,\n"
                       "density_slug_ft3, pressure_lbf_ft2, speed_of_sound_ft_s,\n"
                       "temperature_R)");

  // ---- simulate --------------------------------------------------------------------------------
  SimulateCommandOptions simulate_options;
  CLI::App* simulate = app.add_subcommand(
      "simulate",
      "Load a case deck (TOML, or a heritage card deck recognised by\n"
      "its content), fly the forward trajectory of each case (no\n"
      "optimization) and report it: a manual-style listing (page\n"
      "titles of data blocks 1-3, the points data block 9 selects,\n"
      "stage events, terminal conditions and orbit elements; with\n"
      "IP(17) the input data first), or one JSON document (--json;\n"
      "an array of one per case for a deck of several cases);\n"
      "--csv FILE adds every point (FILE.caseN.csv per case).");
  simulate->add_option("DECK", simulate_options.deck_path, "TOML deck or card deck (docs/deck-format.md)")
      ->required()
      ->type_name("FILE");
  simulate
      ->add_option("--csv", simulate_options.csv_path,
                   "Also write EVERY integration point (not thinned) to\n"
                   "FILE as CSV with a header row. Written atomically\n"
                   "(FILE.tmp.<pid>, then rename): on failure an existing\n"
                   "FILE is left untouched and the exit code is 1")
      ->type_name("FILE");
  simulate->add_flag("--json", simulate_options.json,
                     "Print one JSON document (status, burnout state,\n"
                     "inertial velocity, orbit elements, stage events, every\n"
                     "point) instead of the listing; printed also when the\n"
                     "trajectory fails (then with exit code 1)");

  // ---- optimize --------------------------------------------------------------------------------
  OptimizeCommandOptions optimize_options;
  CLI::App* optimize = app.add_subcommand(
      "optimize",
      "Load a case deck (TOML, or a card deck of one case) and\n"
      "optimize it: closed-loop steepest\n"
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
      "parameters). Exit 0 when converged; 1 when not converged\n"
      "or on a core failure (everything is still printed, with\n"
      "the best trajectory found); 2 on bad input.");
  optimize->add_option("DECK", optimize_options.deck_path, "TOML deck or card deck (docs/deck-format.md)")
      ->required()
      ->type_name("FILE");
  optimize
      ->add_option("--csv", optimize_options.csv_path,
                   "Also write EVERY integration point of the final\n"
                   "trajectory to FILE as CSV (the columns of simulate\n"
                   "--csv), atomically; on a write failure an existing\n"
                   "FILE is left untouched and the exit code is 1")
      ->type_name("FILE");
  optimize->add_flag("--json", optimize_options.json,
                     "Print one JSON document instead of the listing: the\n"
                     "simulate --json keys for the final trajectory plus\n"
                     "converged, forward_runs, backward_runs, payoff,\n"
                     "payload_lb, constraints, payoff_partials, adjustable,\n"
                     "theta_history, iterations (docs/cli.md)");

  // ---- export / inspect (guidance table image, docs/table-format.md) ----------------------------
  ExportCommandOptions export_options;
  CLI::App* export_command = app.add_subcommand(
      "export",
      "Build the guidance-computer table image (docs/table-format.md)\n"
      "from a case deck (TOML or cards) and write it atomically:\n"
      "segments (interim: from the data block 40 pitch table),\n"
      "lift-off, spun-stage attitudes, autopilot gains, limits,\n"
      "CRC-32.");
  export_command->add_option("DECK", export_options.deck_path, "TOML deck or card deck (docs/deck-format.md)")
      ->required()
      ->type_name("FILE");
  export_command->add_option("--out", export_options.out_path, "The binary image (812 bytes)")
      ->required()
      ->type_name("FILE");
  export_command->add_option("--c-header", export_options.c_header_path,
                             "Also write the image as a C const array in the\n"
                             "linker section .tolip_table")
      ->type_name("FILE");
  export_command->add_option("--symbol", export_options.symbol, "C array name (default tolip_pitch_table)")
      ->type_name("NAME");
  export_command->add_option("--mission-id", export_options.mission_id,
                             "Mission identifier, 1-32 printable ASCII characters\n"
                             "(default: the case title, data block 1)")
      ->type_name("TEXT");
  export_command->add_option("--created-unix-s", export_options.created_unix_s,
                             "Creation stamp, s since 1970-01-01Z (default:\n"
                             "SOURCE_DATE_EPOCH, else the current time)")
      ->type_name("N");

  InspectCommandOptions inspect_options;
  CLI::App* inspect = app.add_subcommand(
      "inspect",
      "Validate a guidance table image with the flight-side loader's\n"
      "checks and print it in engineering units; a bad image is\n"
      "named by its fault (exit 2).");
  inspect->add_option("IMAGE", inspect_options.image_path, "Table image written by tolip export")
      ->required()
      ->type_name("FILE");

  // ---- convert ---------------------------------------------------------------------------------
  ConvertCommandOptions convert_options;
  CLI::App* convert = app.add_subcommand(
      "convert",
      "Convert a deck between the heritage card format (80-column\n"
      "card images, manual Sec. 22) and the TOML deck: DECK (either\n"
      "format, recognised by content) is read and checked like any\n"
      "deck, converted, read back, and written atomically to the\n"
      "--to FILE.\n"
      "A card deck of several cases needs --case N for TOML; cards\n"
      "write every case (later cases as their changes).");
  convert->add_option("DECK", convert_options.deck_path, "Card deck or TOML deck")->required()->type_name("FILE");
  convert->add_option("--to", convert_options.out_path,
                      "The converted deck; its format follows the name\n"
                      "(*.toml: TOML; *.dat, *.cards, *.crd: card deck)")
      ->required()
      ->type_name("FILE");
  convert->add_option("--format", convert_options.format, "Output format regardless of the name: toml or cards")
      ->type_name("FORMAT");
  convert->add_option("--case", convert_options.case_number,
                      "Case of a several-case card deck to write as TOML\n"
                      "(1-based; a TOML deck holds one case)")
      ->type_name("N");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e, out, err);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e, out, err);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e, out, err);
  } catch (const CLI::ParseError& e) {
    err << "tolip: " << e.what() << "\n";
    err << "Run 'tolip --help' for more information.\n";
    return kExitBadInput;
  }

  if (atmosphere->parsed()) return run_atmosphere_command(atmosphere_options, out, err);
  if (simulate->parsed()) return run_simulate_command(simulate_options, out, err);
  if (optimize->parsed()) return run_optimize_command(optimize_options, out, err);
  if (export_command->parsed()) return run_export_command(export_options, out, err);
  if (inspect->parsed()) return run_inspect_command(inspect_options, out, err);
  if (convert->parsed()) return run_convert_command(convert_options, out, err);
  err << "tolip: no command given\n";
  return kExitBadInput;
}

}  // namespace tolip::ground
