// `tolip optimize` with IP(3) = 1: the performance exchange ratios (manual Sec. 8, 12, 22) in the
// listing ("PERFORMANCE EXCHANGE RATIOS") and the JSON document (`exchange_ratios`).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli_runner.hpp"

namespace tolip::test {
namespace {

TEST(ExchangeRatioReport, JsonListsEveryPoweredStageWithTheSignsIntuitionAsks) {
  const CommandResult run = run_tolip_executable({"optimize", mission_deck(), "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(without_input_warnings(run.err).empty()) << run.err;
  const nlohmann::json document = nlohmann::json::parse(run.out);
  ASSERT_TRUE(document.contains("exchange_ratios"));
  const nlohmann::json& ratios = document["exchange_ratios"];
  ASSERT_TRUE(ratios.is_array());
  ASSERT_EQ(ratios.size(), 4u);  // sequence 1 6 2 7 3 8 4
  for (std::size_t s = 0; s < ratios.size(); ++s) {
    const nlohmann::json& r = ratios[s];
    EXPECT_EQ(r["stage"].get<int>(), static_cast<int>(s) + 1);
    for (const char* key :
         {"burn_rate", "propellant_weight", "specific_impulse", "drag", "jettison_weight"}) {
      ASSERT_TRUE(r[key].is_number()) << key;
    }
    EXPECT_GT(r["specific_impulse"].get<double>(), 0.0);   // lb of payload per 1% Isp
    EXPECT_GT(r["propellant_weight"].get<double>(), 0.0);  // lb per lb
    EXPECT_LT(r["jettison_weight"].get<double>(), 0.0);    // lb per lb
  }
  EXPECT_LT(ratios[0]["drag"].get<double>(), 0.0);  // lb per ft^2 of C_D S
  EXPECT_EQ(ratios[2]["drag"].get<double>(), 0.0);  // no drag table in stages 3 and 4
  // The payload is part of the last stage's jettison weight: -1 lb per lb.
  EXPECT_NEAR(ratios[3]["jettison_weight"].get<double>(), -1.0, 1e-3);
  EXPECT_FALSE(contains(run.out, "NaN"));
}

TEST(ExchangeRatioReport, ListingPrintsTheTableWithinTheLineWidth) {
  const CommandResult run = run_tolip_executable({"optimize", mission_deck()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string& text = run.out;
  for (const char* part :
       {"PERFORMANCE EXCHANGE RATIOS", "BURN RATE", "PROPELLANT WEIGHT", "SPECIFIC IMPULSE", "DRAG AREA",
        "JETTISON WEIGHT", "LB/PCT", "LB/FT2", "PRICE OF 1 LB OF PAYLOAD"}) {
    EXPECT_TRUE(contains(text, part)) << part;
  }
  EXPECT_FALSE(contains(text, "nan"));
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) EXPECT_LE(line.size(), 132u) << line;
}

TEST(ExchangeRatioReport, AbsentWithoutOption3AndNullWhenTheOptimizationDidNotConverge) {
  ScratchDirectory scratch("exchange_ratio_report");
  const std::string off =
      edited_example_deck(scratch, "off.toml", {{"exchange_ratios = true", "exchange_ratios = false"}});
  const CommandResult without = run_tolip_executable({"optimize", off, "--json"});
  ASSERT_EQ(without.exit_code, 0) << without.err;
  EXPECT_FALSE(nlohmann::json::parse(without.out).contains("exchange_ratios"));
  EXPECT_FALSE(contains(run_tolip_executable({"optimize", off}).out, "PERFORMANCE EXCHANGE RATIOS"));

  // A forward-run budget of 2 stops the optimization before it converges: no ratios.
  const std::string budget = edited_example_deck(
      scratch, "budget.toml", {{"max_forward_trajectories = 30", "max_forward_trajectories = 2"}});
  const CommandResult json_run = run_tolip_executable({"optimize", budget, "--json"});
  EXPECT_EQ(json_run.exit_code, 1);
  const nlohmann::json document = nlohmann::json::parse(json_run.out);
  ASSERT_TRUE(document.contains("exchange_ratios"));
  EXPECT_TRUE(document["exchange_ratios"].is_null());
  const CommandResult listing = run_tolip_executable({"optimize", budget});
  EXPECT_TRUE(contains(listing.out, "NOT COMPUTED: kGuidanceDidNotConverge")) << listing.out.substr(0, 200);
}

}  // namespace
}  // namespace tolip::test
