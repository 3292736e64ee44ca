// No input silently dropped (issue 14's first item, the rule of the core's readers): an input the
// readers accept that this version does not act on is named on stderr by data block and word, for
// TOML and card decks alike, and a deck without such inputs prints no warning.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "cli_runner.hpp"
#include "support/repository_paths.hpp"

namespace tolip::test {
namespace {

int warning_count(const std::string& err) {
  int count = 0;
  for (std::size_t at = err.find("tolip: warning: "); at != std::string::npos;
       at = err.find("tolip: warning: ", at + 1)) {
    ++count;
  }
  return count;
}

// The example asks for the four analyses of Sec. 15-18, of which simulate computes three (hardover,
// Sec. 16; the impact locus, Sec. 17, with its step rate DA6D(17-19); radar, Sec. 18) and leaves
// the dispersions to optimize, gives a gyro uncage time and the stage-4 c.g. history of the
// reference data (XCG4, read by nothing): three warnings, each naming its block and word; the run
// itself succeeds.
TEST(UnusedInputs, TheExampleNamesEveryInputItDoesNotActOn) {
  for (const char* deck : {"scout/mission.toml", "scout/mission.dat"}) {
    const CommandResult run = run_tolip_executable(
        {"simulate", std::string(tolip::repository_paths::examples_dir()) + "/" + deck, "--json"});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    for (const char* named : {"data block 4, IP(21) (options.dispersions)",
                              "data block 17, DA2(8) (misc.gyro_uncage_s_before_launch)",
                              "data block 37, XCG4 (body_dynamics.cg.4)"}) {
      EXPECT_TRUE(contains(run.err, named)) << deck << ": " << named << "\n" << run.err;
    }
    for (const char* acted_on : {"IP(22)", "IP(23)", "IP(24)", "DA6D(17-19)"}) {
      EXPECT_FALSE(contains(run.err, acted_on)) << deck << ": " << acted_on << "\n" << run.err;
    }
    EXPECT_EQ(warning_count(run.err), 3) << deck << "\n" << run.err;
  }
}

// Each input on its own, and a deck with none of them: no warning at all.
TEST(UnusedInputs, EachInputWarnsAloneAndADeckWithoutThemIsSilent) {
  ScratchDirectory scratch("unused_inputs");
  const std::vector<std::pair<std::string, std::string>> quiet = {
      {"dispersions = true ", "dispersions = false "},
      {"hardover = true ", "hardover = false "},
      {"impact = true ", "impact = false "},
      {"radar = true ", "radar = false "},
      {"gyro_uncage_s_before_launch = 5.0", "gyro_uncage_s_before_launch = 0.0"},
      {"impact_every_nth_step = [2, 2, 2]", "impact_every_nth_step = [1, 1, 1]"},
      {"[body_dynamics.cg.4]  # data block 37, XCG4\nstage_time_s = [0.0, 14.0, 28.0]\n"
       "station_in = [110.0, 107.0, 104.0]\n",
       ""}};
  const std::string silent = edited_example_deck(scratch, "silent.toml", quiet);
  const CommandResult none = run_tolip_executable({"simulate", silent, "--json"});
  EXPECT_EQ(none.exit_code, 0) << none.err;
  EXPECT_EQ(none.err, "");

  const struct {
    std::vector<std::pair<std::string, std::string>> edits;
    const char* named;
  } alone[] = {
      {{{"ct1_13 = 1.0", "ct1_13 = 2.0"}}, "data block 10, CT1(13) (constants.ct1_13)"},
      // DA6D(12-15) act in 6D forward trajectories; with IP(6) = 0 none is flown.
      {{{"integration_frequency_multiplier = [1.0, 1.0, 1.0, 1.0]",
         "integration_frequency_multiplier = [2.0, 1.0, 1.0, 1.0]"},
        {"body_dynamics_6d = 1 ", "body_dynamics_6d = 0 "}},
       "data block 33, DA6D(12-15) (body_dynamics.integration_frequency_multiplier)"},
  };
  int n = 0;
  for (const auto& a : alone) {
    std::vector<std::pair<std::string, std::string>> edits = quiet;
    edits.insert(edits.end(), a.edits.begin(), a.edits.end());
    const std::string deck = edited_example_deck(scratch, "alone" + std::to_string(++n) + ".toml", edits);
    const CommandResult run = run_tolip_executable({"simulate", deck, "--json"});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    EXPECT_TRUE(contains(run.err, a.named)) << a.named << "\n" << run.err;
    EXPECT_EQ(warning_count(run.err), 1) << run.err;
  }
}

}  // namespace
}  // namespace tolip::test
