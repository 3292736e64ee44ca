// The impact locus end to end (manual Sec. 17, IP(23); docs/cli.md "tolip impact"): `tolip impact`
// on the bundled example (listing, JSON, CSV, plot), `optimize` with IP(23) = 1 about the linearized
// program (the dispersions' nominal), and bad input - a missing block, a non-increasing drag table,
// a failure point past the end of a stage - exiting 2 with the field named and nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"
#include "support/pinned_figures.hpp"
#include "support/reference_data.hpp"

namespace tolip::test {
namespace {

struct Runs {
  ScratchDirectory scratch{"impact_command"};
  std::string csv_path;
  CommandResult json_run;
  CommandResult listing_run;
  nlohmann::json document;
};

const Runs& runs() {
  static const std::unique_ptr<Runs> r = [] {
    auto x = std::make_unique<Runs>();
    x->csv_path = (x->scratch / "impact.csv").string();
    x->json_run = run_tolip_executable({"impact", mission_deck(), "--json", "--csv", x->csv_path});
    x->listing_run = run_tolip_executable({"impact", mission_deck()});
    x->document = nlohmann::json::parse(x->json_run.out, nullptr, false);
    return x;
  }();
  return *r;
}

TEST(Sec17ImpactCommand, ExampleLocusHasEveryFailurePointAndCasing) {
  const Runs& r = runs();
  ASSERT_EQ(r.json_run.exit_code, 0) << r.json_run.err;
  const nlohmann::json& impact = r.document.at("impact");
  EXPECT_EQ(impact.at("status"), "kOk");
  EXPECT_EQ(impact.at("nominal_kind"), "deck program");
  EXPECT_EQ(impact.at("every_nth_point"), nlohmann::json::array({2, 2, 2}));
  // Stage 1: 42 steps after the 3 s lift-off, every 2nd: 21; stage 2: 30 steps, 15; stage 3: 40, 20.
  const nlohmann::json& cases = impact.at("cases");
  int failures[4] = {}, casings[4] = {};
  for (const nlohmann::json& c : cases) {
    EXPECT_EQ(c.at("status"), "kOk");
    EXPECT_GT(c.at("impact_time_s").get<double>(), c.at("failure_time_s").get<double>());
    EXPECT_GE(c.at("downrange_nmi").get<double>(), 0.0);
    const int stage = c.at("stage").get<int>();
    (c.at("kind") == "thrust_failure" ? failures : casings)[stage] += 1;
  }
  EXPECT_EQ(failures[1], 21);
  EXPECT_EQ(failures[2], 15);
  EXPECT_EQ(failures[3], 20);
  EXPECT_EQ(casings[1] + casings[2] + casings[3], 3);
  // The member comes before the point array, whose ground track the plot draws.
  EXPECT_TRUE(r.document.contains("trajectory"));
  // The listing page and the CSV (a header and one row per case).
  ASSERT_EQ(r.listing_run.exit_code, 0) << r.listing_run.err;
  EXPECT_TRUE(contains(r.listing_run.out, "NOMINAL IMPACT LOCUS (SEC. 17)"));
  EXPECT_TRUE(contains(r.listing_run.out, "EXPENDED CASING"));
  EXPECT_TRUE(contains(r.listing_run.out, "GEOCENTRIC"));
  const std::string csv = read_text_file(r.csv_path);
  EXPECT_EQ(csv.rfind("kind,stage,status,failure_time_s,impact_time_s,geodetic_latitude_deg,", 0), 0u);
  EXPECT_EQ(static_cast<std::size_t>(std::count(csv.begin(), csv.end(), '\n')), cases.size() + 1);
}

TEST(Sec17ImpactCommand, OptimizeTakesTheDispersionsNominal) {
  ScratchDirectory scratch("impact_optimize");
  const std::string csv = (scratch / "impact.csv").string();
  const CommandResult run = run_tolip_executable({"optimize", mission_deck(), "--json", "--impact-csv", csv});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json document = nlohmann::json::parse(run.out);
  const nlohmann::json& impact = document.at("impact");
  EXPECT_EQ(impact.at("status"), "kOk");
  EXPECT_EQ(impact.at("nominal_kind"), document.at("dispersions").at("nominal_kind"));
  EXPECT_EQ(impact.at("nominal_kind"), "linearized program");
  EXPECT_TRUE(std::filesystem::exists(csv));
  EXPECT_EQ(document.at("payload_lb").get<double>(), tolip::test::kPinnedReferencePayloadLb);  // unchanged
}

// Nothing on stdout and no CSV, exit 2, the block and field named.
void expect_bad_input(const std::string& deck, const std::vector<std::string>& named) {
  ScratchDirectory scratch("impact_bad");
  const std::string csv = (scratch / "impact.csv").string();
  for (const std::string& command : {std::string("impact"), std::string("simulate")}) {
    const CommandResult run = run_tolip_executable({command, deck, "--csv", csv});
    EXPECT_EQ(run.exit_code, 2) << command << "\n" << run.err;
    EXPECT_EQ(run.out, "") << command;
    for (const std::string& word : named)
      EXPECT_TRUE(contains(run.err, word)) << command << ": " << word << "\n" << run.err;
    EXPECT_FALSE(std::filesystem::exists(csv)) << command;
  }
}

TEST(Sec17ImpactCommand, MissingBlockIsBadInputNamingIt) {
  ScratchDirectory scratch("impact_missing");
  // Without any [impact] section (the tables renamed away), IP(23) = 1 asks for blocks 42-43.
  std::string text = read_text_file(mission_deck());
  for (std::size_t at = text.find("[impact."); at != std::string::npos; at = text.find("[impact.", at)) {
    const std::size_t end = text.find("\n\n", at);
    text.erase(at, (end == std::string::npos ? text.size() : end + 2) - at);
  }
  const std::string deck = (scratch / "missing.toml").string();
  std::ofstream(deck) << text;
  expect_bad_input(deck, {"data block 42", "impact"});
}

TEST(Sec17ImpactCommand, NonIncreasingDragTableIsBadInputNamingTheField) {
  ScratchDirectory scratch("impact_table");
  const std::string deck = edited_example_deck(
      scratch, "table.toml",
      {{"[impact.casing_drag.2]  # data block 43, CD2E\n# tumbling Castor casing with transition B\n"
        "reference_area_ft2 = 5.2414\ncasing_weight_lb = 1650.0\nmach = [0.0, 0.6, 0.8, 0.9,",
        "[impact.casing_drag.2]  # data block 43, CD2E\n# tumbling Castor casing with transition B\n"
        "reference_area_ft2 = 5.2414\ncasing_weight_lb = 1650.0\nmach = [0.0, 0.6, 0.8, 0.7,"}});
  expect_bad_input(deck, {"data block 43", "impact.casing_drag.2"});
}

TEST(Sec17ImpactCommand, FailurePointPastTheEndOfAStageIsBadInputNamingTheWord) {
  ScratchDirectory scratch("impact_nth");
  // Stage 3 has 40 integration steps: n = 41 puts the first failure after the lift-off past its end.
  const std::string deck = edited_example_deck(
      scratch, "nth.toml", {{"impact_every_nth_step = [2, 2, 2]", "impact_every_nth_step = [2, 2, 41]"}});
  expect_bad_input(deck, {"data block 33", "DA6D(19)", "body_dynamics.impact_every_nth_step[2]", "n = 41",
                          "kImpactEveryNthPointOutOfRange"});
}

// Issue 18: the cause is named (not a generic out-of-range) together with the block, word and key.
TEST(Sec17ImpactCommand, ZeroCasingWeightIsBadInputNamingTheCauseAndTheField) {
  ScratchDirectory scratch("impact_casing");
  const std::string deck = edited_example_deck(
      scratch, "casing.toml",
      {{"[impact.casing_drag.2]  # data block 43, CD2E\n# tumbling Castor casing with transition B\n"
        "reference_area_ft2 = 5.2414\ncasing_weight_lb = 1650.0\n",
        "[impact.casing_drag.2]  # data block 43, CD2E\n# tumbling Castor casing with transition B\n"
        "reference_area_ft2 = 5.2414\ncasing_weight_lb = 0.0\n"}});
  expect_bad_input(
      deck, {"data block 43", "impact.casing_drag.2", "casing weight", "kImpactCasingWeightNotPositive"});
}

TEST(Sec17ImpactCommand, PlotDrawsTheLocus) {
  const Runs& r = runs();
  ASSERT_EQ(r.json_run.exit_code, 0);
  ScratchDirectory scratch("impact_plot");
  const std::string result = (scratch / "impact.json").string();
  std::ofstream(result) << r.json_run.out;
  const CommandResult plot = run_tolip_executable({"plot", result, "--out", (scratch / "plots").string()});
  ASSERT_EQ(plot.exit_code, 0) << plot.err;
  EXPECT_TRUE(contains(plot.out, "impact_locus.png")) << plot.out;
  EXPECT_TRUE(std::filesystem::exists(scratch / "plots" / "impact_locus.svg"));
}

}  // namespace
}  // namespace tolip::test
