// The shapes of `tolip` command-line declarations that several commands share (CLI11): a command
// with its help and footer, the DECK argument, a required or optional file, the --json flag and the
// --progress / --no-progress pair. Each command still writes its own help strings; these helpers
// only fix how an argument of a kind is declared (required or not, the type name in the help), so
// that every command declares it alike. Internal to ground_tools/src/commands (cli.cpp,
// monte_carlo_command.cpp).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "tolip_ground/progress.hpp"

namespace tolip::ground {

// The DECK help of the commands that read every case of any deck.
inline constexpr const char* kDeckOfCasesHelp =
    "TOML deck or card deck of one or more cases, recognised\n"
    "by content (docs/deck-format.md)";

// A subcommand NAME of app: `description` is what `tolip --help` lists, `footer` ends
// `tolip NAME --help` (examples, exit codes, reference).
CLI::App* add_command(CLI::App& app, const std::string& name, const std::string& description,
                      const std::string& footer);

// A required file, positional (NAME in capitals: DECK, RESULT, IMAGE) or an option (--out, --to),
// shown as FILE in the help.
CLI::Option* add_required_file(CLI::App& command, const std::string& name, std::string* path,
                               const std::string& help);

// The positional DECK: the deck (TOML or cards) the command reads; required.
CLI::Option* add_deck_argument(CLI::App& command, std::string* path, const std::string& help);

// An optional file the command writes (--csv, --radar-csv, ...): empty when not given.
CLI::Option* add_file_option(CLI::App& command, const std::string& name, std::string* path,
                             const std::string& help);

// --csv FILE: an optional CSV file the command writes beside what it prints.
CLI::Option* add_csv_option(CLI::App& command, std::string* path, const std::string& help);

// --json: print a JSON document instead of the listing.
CLI::Option* add_json_flag(CLI::App& command, bool* json, const std::string& help);

// The help of each of the DECK / --csv / --json triplet of a deck analysis command.
struct DeckCsvJsonHelp {
  const char* deck;
  const char* csv;
  const char* json;
};

// DECK, --csv FILE and --json, in that order, into options->deck_path, csv_path and json: the
// options every deck analysis command (dispersions, impact, radar, hardover) takes.
template <typename Options>
void add_deck_csv_json(CLI::App& command, Options* options, const DeckCsvJsonHelp& help) {
  add_deck_argument(command, &options->deck_path, help.deck);
  add_csv_option(command, &options->csv_path, help.csv);
  add_json_flag(command, &options->json, help.json);
}

// --progress and --no-progress, excluding each other: the status line on stderr forced on or off
// (*mode stays kAuto when neither is given).
void add_progress_flags(CLI::App& command, ProgressMode* mode, const std::string& on_help,
                        const std::string& off_help);

}  // namespace tolip::ground
