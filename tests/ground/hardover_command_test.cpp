// Sec. 16, 22: `tolip hardover`, and the turns that simulate adds with IP(22) = 1: the listing
// (TIME, CHG GAMMA, QBAR-A and the stop of every turn), the JSON member `hardover`, the CSV, the
// figure, and bad data blocks 44-45 rejected with block, word and stage named and nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"
#include "support/reference_data.hpp"
#include "support/text_match.hpp"
#include "tolip_ground/plot.hpp"

namespace tolip::test {
namespace {

using json = nlohmann::json;

TEST(Sec16HardoverCommand, ListsEveryTurnWithTimeChangeInGammaQbarAlphaAndTheStop) {
  const CommandResult result = run_tolip_executable({"hardover", reference_deck()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(contains(result.out, "HARDOVER TURNS   PAGE"));
  EXPECT_TRUE(contains(result.out, "CHG GAMMA"));
  EXPECT_TRUE(contains(result.out, "QBAR-A"));
  EXPECT_TRUE(contains(result.out, "STAGE 1 FINS AND VANES"));
  EXPECT_TRUE(contains(result.out, "STAGE 2 MODE 1 THRUST MISALIGNMENT"));
  EXPECT_TRUE(contains(result.out, "STAGE 3 MODE 3 PITCH AND YAW JETS"));
  EXPECT_TRUE(contains(result.out, "STOP: "));
  EXPECT_FALSE(contains(result.err, "IP(22)")) << "hardover is computed: no unused-input warning";
}

TEST(Sec16HardoverCommand, JsonCsvAndSimulateCarryTheSameTurns) {
  ScratchDirectory scratch("hardover_csv");
  const std::string csv = (scratch / "turns.csv").string();
  const CommandResult alone = run_tolip_executable({"hardover", reference_deck(), "--json", "--csv", csv});
  ASSERT_EQ(alone.exit_code, 0) << alone.err;
  const json document = json::parse(alone.out);
  const json& h = document["hardover"];
  EXPECT_EQ(h["computed"], true);
  ASSERT_GT(h["turns"].size(), 10u);
  std::size_t rows = 0;
  for (const json& turn : h["turns"]) {
    rows += turn["samples"].size();
    EXPECT_LE(turn["duration_s"].get<double>(), 10.0 + 1e-9);
    EXPECT_EQ(turn["samples"][0]["change_in_gamma_deg"], 0.0);
  }
  const std::string text = read_text_file(csv);
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), static_cast<long>(rows + 1));
  EXPECT_EQ(text.rfind("stage,mode,failure_time_s,time_s,change_in_gamma_deg", 0), 0u);

  const CommandResult simulate = run_tolip_executable({"simulate", reference_deck(), "--json"});
  ASSERT_EQ(simulate.exit_code, 0) << simulate.err;
  EXPECT_EQ(json::parse(simulate.out)["hardover"], h);

  const ground::DocumentFigures figures = ground::figures_for_document(document);
  int found = 0;
  for (const ground::Figure& figure : figures.figures) {
    if (figure.name != "hardover_gamma") continue;
    ++found;
    EXPECT_EQ(figure.series.size(), h["turns"].size()) << "a curve per turn";
  }
  EXPECT_EQ(found, 1);
}

void expect_rejected(const std::string& deck, const std::string& command, const std::string& needle) {
  ScratchDirectory scratch("hardover_rejected");
  const std::string csv = (scratch / "out.csv").string();
  const CommandResult result = run_tolip_executable({command, deck, "--csv", csv});
  EXPECT_EQ(result.exit_code, 2) << command << ": " << result.err;
  EXPECT_TRUE(contains(result.err, needle)) << command << ": " << result.err;
  EXPECT_TRUE(result.out.empty()) << result.out;
  EXPECT_FALSE(std::filesystem::exists(csv));
}

std::string edited_reference(const ScratchDirectory& scratch, const std::string& from,
                             const std::string& to) {
  std::string text = read_text_file(reference_deck());
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  const std::string path = (scratch / "edited.toml").string();
  std::ofstream(path) << text;
  return path;
}

TEST(Sec16HardoverCommand, BadDataBlock45IsRejectedNamingBlockWordAndStage) {
  ScratchDirectory scratch("hardover_bad");
  const std::string interval =
      edited_reference(scratch, "output_interval_s = 0.5", "output_interval_s = 0.01");
  for (const char* command : {"hardover", "simulate", "optimize"}) {
    expect_rejected(interval, command, "data block 45, word 20: kHardoverOutputIntervalTooSmall");
  }
  const std::string steps = edited_reference(scratch, "stage1_min_step_s = 0.002", "stage1_min_step_s = 0.5");
  // The deck reader catches this one first, naming the key (the core's check names word 5 again).
  expect_rejected(steps, "hardover", "data block 45, field hardover.parameters.stage1_min_step_s");
}

TEST(Sec16HardoverCommand, OptionWithoutDataBlocks44And45IsRejectedNamingTheBlock) {
  ScratchDirectory scratch("hardover_missing");
  std::string text = read_text_file(reference_deck());
  const std::size_t from = text.find("[hardover.pitch_inertia.1]");
  const std::size_t to = text.find("# Data blocks 46-55");
  ASSERT_NE(from, std::string::npos);
  ASSERT_NE(to, std::string::npos);
  text.erase(from, to - from);
  const std::string deck = (scratch / "no_hardover.toml").string();
  std::ofstream(deck) << text;
  for (const char* command : {"hardover", "simulate"}) expect_rejected(deck, command, "data block 44");
}

}  // namespace
}  // namespace tolip::test
