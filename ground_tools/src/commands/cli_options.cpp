// The shared shapes of `tolip` command-line declarations (cli_options.hpp).
#include "cli_options.hpp"

namespace tolip::ground {

CLI::App* add_command(CLI::App& app, const std::string& name, const std::string& description,
                      const std::string& footer) {
  CLI::App* command = app.add_subcommand(name, description);
  command->footer(footer);
  return command;
}

CLI::Option* add_required_file(CLI::App& command, const std::string& name, std::string* path,
                               const std::string& help) {
  return command.add_option(name, *path, help)->required()->type_name("FILE");
}

CLI::Option* add_deck_argument(CLI::App& command, std::string* path, const std::string& help) {
  return add_required_file(command, "DECK", path, help);
}

CLI::Option* add_file_option(CLI::App& command, const std::string& name, std::string* path,
                             const std::string& help) {
  return command.add_option(name, *path, help)->type_name("FILE");
}

CLI::Option* add_csv_option(CLI::App& command, std::string* path, const std::string& help) {
  return add_file_option(command, "--csv", path, help);
}

CLI::Option* add_json_flag(CLI::App& command, bool* json, const std::string& help) {
  return command.add_flag("--json", *json, help);
}

void add_progress_flags(CLI::App& command, ProgressMode* mode, const std::string& on_help,
                        const std::string& off_help) {
  CLI::Option* on = command.add_flag_callback(
      "--progress", [mode] { *mode = ProgressMode::kOn; }, on_help);
  CLI::Option* off = command.add_flag_callback(
      "--no-progress", [mode] { *mode = ProgressMode::kOff; }, off_help);
  on->excludes(off);
}

}  // namespace tolip::ground
