// `tolip --help` and every subcommand's --help: each command listed, each option named with an
// explanation on its line, examples and the exit codes in the footer (docs/cli.md is the long form).
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"

namespace tolip::test {
namespace {

struct CommandHelp {
  const char* command;
  std::vector<std::string> options;  // as the help prints them, positionals included
};

const std::vector<CommandHelp>& every_command() {
  static const std::vector<CommandHelp> commands = {
      {"atmosphere", {"--altitude-ft", "--json"}},
      {"simulate", {"DECK", "--csv", "--json", "--radar-csv", "--hardover-csv"}},
      {"optimize",
       {"DECK", "--csv", "--json", "--progress", "--no-progress", "--radar-csv", "--hardover-csv"}},
      {"plot", {"RESULT", "--out", "--gnuplot"}},
      {"export", {"DECK", "--out", "--c-header", "--symbol", "--mission-id", "--created-unix-s"}},
      {"inspect", {"IMAGE"}},
      {"convert", {"DECK", "--to", "--format", "--case"}},
      {"dispersions", {"DECK", "--csv", "--json"}},
      {"impact", {"DECK", "--csv", "--json"}},
      {"radar", {"DECK", "--csv", "--json"}},
      {"hardover", {"DECK", "--csv", "--json"}},
      {"hil",
       {"DECK", "--table", "--scenario", "--seed", "--rate-hz", "--telemetry", "--mission-id", "--json"}},
  };
  return commands;
}

// The help line that starts with the option (after the indent), or "".
std::string option_line(const std::string& help, const std::string& option) {
  std::istringstream lines(help);
  std::string line;
  while (std::getline(lines, line)) {
    const std::size_t start = line.find_first_not_of(' ');
    if (start == 2 && line.find(option, start) != std::string::npos) {
      // "--progress,--no-progress" share one line; a positional is "DECK FILE REQUIRED".
      const std::string head = line.substr(start, line.find(' ', start) - start);
      if (head == option || contains(head, option + ",") || contains(head, "," + option)) return line;
    }
  }
  return "";
}

TEST(Help, ProgramHelpListsEveryCommandWithExamples) {
  const CommandResult result = run_tolip_executable({"--help"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const CommandHelp& command : every_command()) {
    EXPECT_FALSE(option_line(result.out, command.command).empty()) << command.command << "\n" << result.out;
  }
  EXPECT_TRUE(contains(result.out, "--version"));
  EXPECT_TRUE(contains(result.out, "tolip plot result.json --out plots"));
  EXPECT_TRUE(contains(result.out, "docs/user-guide.md"));
  EXPECT_TRUE(contains(result.out, "Exit codes"));
}

TEST(Help, EverySubcommandExplainsEachOptionAndGivesExamples) {
  for (const CommandHelp& command : every_command()) {
    const CommandResult result = run_tolip_executable({command.command, "--help"});
    ASSERT_EQ(result.exit_code, 0) << command.command << ": " << result.err;
    EXPECT_TRUE(result.err.empty()) << result.err;
    const std::string& help = result.out;
    for (const std::string& option : command.options) {
      const std::string line = option_line(help, option);
      ASSERT_FALSE(line.empty()) << command.command << " does not list " << option << "\n" << help;
      // CLI11 puts the explanation in a column after the option (and its type): some words there.
      EXPECT_GT(line.size(), 32u) << command.command << " " << option << " has no explanation: '" << line
                                  << "'";
      EXPECT_NE(line.substr(30).find_first_not_of(' '), std::string::npos) << line;
    }
    EXPECT_TRUE(contains(help, "Example")) << command.command << "\n" << help;
    EXPECT_TRUE(contains(help, std::string("tolip ") + command.command)) << command.command;
    EXPECT_TRUE(contains(help, "Exit codes")) << command.command;
    EXPECT_TRUE(contains(help, "docs/cli.md")) << command.command;
  }
}

// A first word that is no command is named, and the commands are listed (not CLI11's "A
// subcommand is required").
TEST(Help, UnknownCommandIsNamedAndTheCommandsListed) {
  const CommandResult result = run_tolip_executable({"simulat", "examples/scout/mission.toml"});
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(
      result.err,
      "tolip: unknown command 'simulat'; the commands are: atmosphere, simulate, optimize, plot, export, "
      "inspect, convert, montecarlo, dispersions, impact, radar, hardover, hil\nRun 'tolip --help' for more "
      "information.\n");
  const CommandResult bare = run_tolip_executable({});
  EXPECT_EQ(bare.exit_code, 2);
  EXPECT_TRUE(contains(bare.err, "A subcommand is required")) << "no word at all: CLI11's own message";
}

}  // namespace
}  // namespace tolip::test
