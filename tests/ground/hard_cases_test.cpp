// An optimizer that survives hard cases (issue 17; manual Sec. 5 steering law, Sec. 22 sequence,
// docs/theory/optimizer.md "Weak directions" and "Failed runs"). Each deck is the bundled example
// with a few fields changed; the second example vehicle (examples/strapon) converges from its
// crude start.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "cli_runner.hpp"

namespace tolip::test {
namespace {

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

void expect_every_constraint_met(const nlohmann::json& document) {
  ASSERT_TRUE(document["constraints"].is_array());
  for (const nlohmann::json& c : document["constraints"]) EXPECT_EQ(c["met"], true) << c["code"];
}

// The example launched due east (azimuth 90 deg, adjusted) with an inclination constraint equal to
// the launch latitude: at its minimum the inclination has no first-order dependence on any
// control, so the steering matrix is singular in its direction. The constraint starts inside its
// 1 deg deadband. Before the hold the optimization runs all failed (the tiny in-deadband error
// asked for an enormous step) and the case ended kFinalGuidanceFailed at the first feasible
// trajectory (252.49 lb); with the constraint held by its deadband it converges.
TEST(Sec5WeakDirections, InclinationAtTheLaunchLatitudeIsHeldByItsDeadbandAndTheCaseConverges) {
  ScratchDirectory scratch("hard_cases_inclination");
  const std::string deck = edited_example_deck(
      scratch, "due_east.toml",
      {{"azimuth_deg = 100.0 ", "azimuth_deg = 90.0 "},
       {"# Data blocks 6 and 27",
        "[[constraint]]  # inclination = the launch site's geocentric latitude\ncode = 10\n"
        "desired_deg = 37.653239661\ndeadband_optimization_deg = 1.0\ndeadband_linearization_deg = 0.05\n\n"
        "# Data blocks 6 and 27"},
       {"[linearization]",
        "[[adjustable_parameter]]  # launch azimuth\ncode = 6\nweight = 1.0\n\n[linearization]"}});
  const CommandResult run = run_tolip_executable({"optimize", deck, "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json d = nlohmann::json::parse(run.out);
  EXPECT_EQ(d["converged"], true);
  EXPECT_EQ(d["status"], "kOk");
  expect_every_constraint_met(d);
  EXPECT_GT(d["payload_lb"].get<double>(), 300.0);  // measured 308.97 lb
  // The inclination (the fourth constraint) is reported held; the others never are.
  const nlohmann::json& held = d["held_constraints"];
  ASSERT_EQ(held.size(), 4u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(held[i]["held_runs"].get<int>(), 0) << i;
    EXPECT_GT(held[i]["steerability_deadbands"].get<double>(), 1.0) << i;  // 1.07 to 12.3
  }
  EXPECT_EQ(held[3]["code"], 10);
  EXPECT_GT(held[3]["held_runs"].get<int>(), 0);
  EXPECT_LT(held[3]["steerability_deadbands"].get<double>(), 0.02);
  EXPECT_EQ(held[3]["message"], "constraint 4 (code 10) has no first-order effect: held by deadband");
  bool some_run_held = false;
  for (const nlohmann::json& r : d["iterations"])
    some_run_held = some_run_held || r["constraints_held"][3] == true;
  EXPECT_TRUE(some_run_held);
  const CommandResult listing = run_tolip_executable({"optimize", deck});
  EXPECT_TRUE(contains(listing.out, "CONSTRAINT 4 (CODE 10) HAS NO FIRST-ORDER EFFECT: HELD BY DEADBAND ON "))
      << listing.out;
  EXPECT_TRUE(contains(listing.out, "  HELD: 4\n"));
}

// The bundled example's constraints are all steerable: nothing is held, nothing fails.
TEST(Sec5WeakDirections, TheExampleHoldsNothing) {
  const CommandResult run =
      run_tolip_executable({"optimize", std::string(TOLIP_EXAMPLES_DIR) + "/scout/mission.toml", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json d = nlohmann::json::parse(run.out);
  for (const nlohmann::json& h : d["held_constraints"]) EXPECT_EQ(h["held_runs"].get<int>(), 0) << h["code"];
  EXPECT_EQ(d["failed_runs_recovered"].get<int>(), 0);
}

// A flat crude program (theta 5 deg from 88 s): guidance struggles and its 29th forward run, a
// guidance step, goes below the surface. That run is listed with its own status and no payoff;
// the next attempt starts again from the last good nominal at half the step, flies, and the case
// goes on to its final guidance run instead of ending with kAltitudeBelowSurface at run 29.
TEST(Sec22FailedRuns, ARunBelowTheSurfaceIsRetriedFromTheLastGoodNominalAndTheCaseGoesOn) {
  ScratchDirectory scratch("hard_cases_crash");
  const std::string deck =
      edited_example_deck(scratch, "flat.toml",
                          {{"theta_deg = [90.0, 90.0, 80.0, 65.0, 49.0, 33.0, 27.0, 22.0, 21.0, 20.0, 18.0]",
                            "theta_deg = [90.0, 90.0, 70.0, 45.0, 30.0, 15.0, 10.0, 5.0, 5.0, 5.0, 5.0]"},
                           {"max_forward_trajectories = 30", "max_forward_trajectories = 32"}});
  const CommandResult run = run_tolip_executable({"optimize", deck, "--json"});
  const nlohmann::json d = nlohmann::json::parse(run.out);
  EXPECT_EQ(d["forward_runs"].get<int>(), 32);
  EXPECT_GE(d["failed_runs_recovered"].get<int>(), 1);
  const nlohmann::json& runs = d["iterations"];
  ASSERT_EQ(runs.size(), 32u);
  const nlohmann::json& crashed = runs[28];
  EXPECT_EQ(crashed["forward_run"].get<int>(), 29);
  EXPECT_EQ(crashed["kind"], "guidance");
  EXPECT_EQ(crashed["run_status"], "kAltitudeBelowSurface");
  EXPECT_TRUE(crashed["payoff"].is_null());
  for (const nlohmann::json& c : crashed["constraint_corrections"]) EXPECT_TRUE(c.is_null());
  // The retry: a guidance run from the same nominal (same payload base) that flew.
  const nlohmann::json& retry = runs[29];
  EXPECT_EQ(retry["kind"], "guidance");
  EXPECT_EQ(retry["run_status"], "kOk");
  EXPECT_FALSE(retry["payoff"].is_null());
  EXPECT_NEAR(retry["payload_increment_lb"].get<double>(),
              0.5 * crashed["payload_increment_lb"].get<double>(), 1e-6);
  EXPECT_EQ(runs[31]["kind"], "final_guidance");
  // Not converged (the budget ends guidance), but for that reason, not because a run crashed.
  EXPECT_EQ(d["status"], "kGuidanceDidNotConverge");
  EXPECT_FALSE(d["trajectory"].empty());
  const CommandResult listing = run_tolip_executable({"optimize", deck});
  EXPECT_TRUE(contains(listing.out, "RUN FAILED: kAltitudeBelowSurface"));
  EXPECT_TRUE(std::regex_search(listing.out, std::regex("\n   FAILED RUNS RECOVERED +=  +[1-9]")));
}

}  // namespace
}  // namespace tolip::test
