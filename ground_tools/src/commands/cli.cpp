// The `tolip` command line (CLI11): subcommands, help text, exit codes (docs/cli.md).
#include <CLI/CLI.hpp>
#include <ostream>
#include <string>

#include "tolip_ground/commands.hpp"
#include "tolip_ground/version.hpp"

namespace tolip::ground {
namespace {

constexpr const char* kDescription =
    "TOLIP - Trajectory Optimization and Linearized Pitch (NASA CR-66515, 1966),\n"
    "a modern re-implementation for Scout-class launch vehicles.";

constexpr const char* kFooter =
    "Exit codes: 0 success; 1 run-time or core failure (trajectory, orbit elements,\n"
    "file write); 2 bad input (command line or deck). Errors go to stderr as\n"
    "'tolip: <message>'. Run 'tolip <command> --help' for a command's options.\n"
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
      "Load a TOML case deck, fly the forward trajectory (no\n"
      "optimization) and report it: a manual-style listing (page\n"
      "titles of data blocks 1-3, the points data block 9 selects,\n"
      "stage events, terminal conditions and orbit elements), or\n"
      "one JSON document (--json); --csv FILE adds every point.");
  simulate->add_option("DECK", simulate_options.deck_path, "TOML case deck (docs/deck-format.md)")
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
  err << "tolip: no command given\n";
  return kExitBadInput;
}

}  // namespace tolip::ground
