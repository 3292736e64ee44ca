// `tolip optimize` with IP(7) = 1: the linearized pitch program (manual Sec. 6, 10, 22) in the
// listing ("LINEARIZED PITCH PROGRAM") and the JSON document (`linearized`).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>

#include "cli_runner.hpp"

namespace tolip::test {
namespace {

const nlohmann::json& example_document() {
  static const nlohmann::json document = [] {
    const CommandResult run = run_tolip_executable({"optimize", mission_deck(), "--json"});
    EXPECT_EQ(run.exit_code, 0) << run.err;
    return nlohmann::json::parse(run.out);
  }();
  return document;
}

TEST(LinearizedReport, Sec10_JsonGivesSegmentsThatMeetTheLimitsAndConstraints) {
  const nlohmann::json& document = example_document();
  ASSERT_TRUE(document.contains("linearized"));
  const nlohmann::json& l = document["linearized"];
  EXPECT_EQ(l["status"], "kOk");
  EXPECT_TRUE(l["constraints_met"].get<bool>());
  EXPECT_TRUE(l["rate_limits_met"].get<bool>());
  const nlohmann::json& segments = l["segments"];
  ASSERT_EQ(segments.size(), 9u);  // data block 18 of the example
  double previous_start = -1.0;
  for (std::size_t s = 0; s < segments.size(); ++s) {
    const nlohmann::json& seg = segments[s];
    for (const char* key : {"stage", "start_stage_time_s", "start_time_s", "theta_deg", "rate_deg_s"}) {
      ASSERT_TRUE(seg[key].is_number()) << key;
    }
    EXPECT_GT(seg["start_time_s"].get<double>(), previous_start);
    previous_start = seg["start_time_s"].get<double>();
    EXPECT_LE(std::fabs(seg["rate_deg_s"].get<double>()), 5.0 * (1.0 + 1e-9));   // data block 22 word 3
    EXPECT_GE(std::fabs(seg["rate_deg_s"].get<double>()), 0.05 * (1.0 - 1e-9));  // word 4
    // Continuity: the next start is this start plus rate times duration.
    const double end_time = s + 1 < segments.size() ? segments[s + 1]["start_time_s"].get<double>()
                                                    : l["end_time_s"].get<double>();
    const double end_theta = s + 1 < segments.size() ? segments[s + 1]["theta_deg"].get<double>()
                                                     : l["end_theta_deg"].get<double>();
    EXPECT_NEAR(seg["theta_deg"].get<double>() +
                    seg["rate_deg_s"].get<double>() * (end_time - seg["start_time_s"].get<double>()),
                end_theta, 1e-9)
        << "segment " << s;
  }
  EXPECT_NEAR(segments[0]["theta_deg"].get<double>(), 90.0, 1e-12);  // the end of the vertical lift-off
  EXPECT_EQ(segments[0]["start_time_s"].get<double>(), 3.0);
  // Payload payoff: what the linearized trajectory carries, within 0.5% of the optimum.
  const double payoff = l["payoff"].get<double>();
  const double optimum = l["optimum_payoff"].get<double>();
  EXPECT_DOUBLE_EQ(optimum, document["payoff"]["value"].get<double>());
  EXPECT_LE(payoff, optimum * (1.0 + 1e-6));
  EXPECT_GE(payoff, 0.995 * optimum);
  for (const nlohmann::json& c : l["constraints"]) {
    EXPECT_LE(std::fabs(c["achieved"].get<double>() - c["desired"].get<double>()),
              c["tolerance"].get<double>())
        << c["code"];
    EXPECT_TRUE(c["met"].get<bool>()) << c["code"];
  }
}

TEST(LinearizedReport, ListingPrintsTheProgramAndItsConstraints) {
  const CommandResult run = run_tolip_executable({"optimize", mission_deck()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* part :
       {"LINEARIZED PITCH PROGRAM", "PITCH RATE", "END OF PROGRAM", "LINEARIZATION DEADBANDS",
        "AGAINST THE OPTIMUM'S", "RATE LIMITS (DATA BLOCK 22) MET; CONSTRAINTS MET"}) {
    EXPECT_TRUE(contains(run.out, part)) << part;
  }
  std::istringstream in(run.out);
  std::string line;
  while (std::getline(in, line)) EXPECT_LE(line.size(), 132u) << line;
}

TEST(LinearizedReport, AbsentWithoutOption7AndNotComputedWhenTheOptimizationDidNotConverge) {
  ScratchDirectory scratch("linearized_report");
  const std::string off = edited_example_deck(
      scratch, "off.toml",
      {{"linearization = true", "linearization = false"}, {"body_dynamics_6d = 1", "body_dynamics_6d = 0"}});
  const CommandResult without = run_tolip_executable({"optimize", off, "--json"});
  ASSERT_EQ(without.exit_code, 0) << without.err;
  EXPECT_FALSE(nlohmann::json::parse(without.out).contains("linearized"));

  // A forward-run budget of 2 cannot converge: the linearization is not run and says why.
  const std::string short_run = edited_example_deck(
      scratch, "short.toml", {{"max_forward_trajectories = 30", "max_forward_trajectories = 2"}});
  const CommandResult stopped = run_tolip_executable({"optimize", short_run, "--json"});
  EXPECT_EQ(stopped.exit_code, 1) << stopped.err;
  const nlohmann::json document = nlohmann::json::parse(stopped.out);
  ASSERT_TRUE(document.contains("linearized"));
  EXPECT_EQ(document["linearized"]["status"], "kGuidanceDidNotConverge");
  EXPECT_TRUE(document["linearized"]["segments"].empty());
}

// IP(6) = 1 (the example): the body_dynamics object reports the 6D re-linearization.
TEST(LinearizedReport, Sec10_BodyDynamicsObjectReportsTheSixDRelinearization) {
  const nlohmann::json& document = example_document();
  ASSERT_TRUE(document.contains("body_dynamics"));
  const nlohmann::json& b = document["body_dynamics"];
  EXPECT_EQ(b["option"], 1);
  EXPECT_EQ(b["mode"], "relinearization");
  EXPECT_EQ(b["status"], "kOk");
  EXPECT_TRUE(b["point_mass_met"].get<bool>());
  EXPECT_TRUE(b["relinearized"].get<bool>());
  EXPECT_DOUBLE_EQ(b["body_dynamics_payoff"].get<double>(), document["linearized"]["payoff"].get<double>());
  EXPECT_NEAR(b["payoff_difference"].get<double>(),
              b["body_dynamics_payoff"].get<double>() - b["point_mass_payoff"].get<double>(), 1e-9);
  // Body dynamics alone moves the accepted program's altitude far outside its deadband.
  const nlohmann::json& altitude = b["point_mass_program_flown_6d"][0];
  EXPECT_EQ(altitude["code"], 7);
  EXPECT_GT(std::fabs(altitude["body_dynamics"].get<double>() - altitude["desired"].get<double>()), 10000.0);
  EXPECT_LT(std::fabs(altitude["point_mass"].get<double>() - altitude["desired"].get<double>()), 2000.0);
}

// IP(6) = 2, "6D on initial nominal": optimize compares the deck's program flown point mass and
// 6D, and simulate flies the 6D trajectory itself (the same final state).
TEST(LinearizedReport, Sec22_Option6Equal2FliesTheInitialNominalSixD) {
  ScratchDirectory scratch("body_dynamics_ip6_2");
  const std::string deck =
      edited_example_deck(scratch, "ip6_2.toml", {{"body_dynamics_6d = 1", "body_dynamics_6d = 2"}});
  const CommandResult optimized = run_tolip_executable({"optimize", deck, "--json"});
  ASSERT_EQ(optimized.exit_code, 0) << optimized.err;
  const nlohmann::json document = nlohmann::json::parse(optimized.out);
  const nlohmann::json& b = document["body_dynamics"];
  EXPECT_EQ(b["option"], 2);
  EXPECT_EQ(b["mode"], "initial_nominal");
  EXPECT_EQ(b["status"], "kOk");
  EXPECT_GT(std::fabs(b["difference"]["altitude_ft"].get<double>()), 1000.0);
  EXPECT_NEAR(
      b["difference"]["velocity_ft_s"].get<double>(),
      b["body_dynamics"]["velocity_ft_s"].get<double>() - b["point_mass"]["velocity_ft_s"].get<double>(),
      1e-9);
  const CommandResult simulated = run_tolip_executable({"simulate", deck, "--json"});
  ASSERT_EQ(simulated.exit_code, 0) << simulated.err;
  const nlohmann::json flown = nlohmann::json::parse(simulated.out)["trajectory"];
  ASSERT_FALSE(flown.empty());
  EXPECT_DOUBLE_EQ(flown.back()["altitude_ft"].get<double>(),
                   b["body_dynamics"]["altitude_ft"].get<double>());
}

}  // namespace
}  // namespace tolip::test
