// Every adjustable-parameter code of data block 6 (manual Sec. 9's eleven columns of S, Sec. 22) in
// a whole optimization somewhere in the suite (issue 15): 1 and 3 on the reference
// (examples/scout), 6 on examples/strapon and Sec5WeakDirections, 7 on the five-element strap-on
// deck and the escape example, 8, 9 and 10 on the escape example (escape_example_test.cpp). This
// file adds the remaining ones: 2 (the spun stage-4 yaw), 4 and 5 (the coasts after stages 2 and 1)
// on the reference mission with an inclination it can only reach by yawing, and 11 (the coast after
// stage 5) on the escape example. Each case converges with every constraint inside its deadband and
// each parameter moves from its deck value.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_runner.hpp"
#include "support/repository_paths.hpp"

namespace tolip::test {
namespace {

const nlohmann::json* adjustable(const nlohmann::json& d, int code) {
  for (const nlohmann::json& a : d["adjustable"]) {
    if (a["code"].get<int>() == code) return &a;
  }
  ADD_FAILURE() << "code " << code << " not reported";
  return nullptr;
}

void expect_converged_inside_every_deadband(const nlohmann::json& d) {
  EXPECT_EQ(d["status"], "kOk");
  EXPECT_EQ(d["converged"], true);
  for (const nlohmann::json& c : d["constraints"]) EXPECT_EQ(c["met"], true) << c["code"];
}

// Sec. 9 codes 2, 4, 5: the reference's crude start aimed 0.2 deg above the 38.80 deg inclination
// its launch azimuth gives. In-plane pitch cannot turn the plane: the spun stage 4's yaw (code 2)
// does, and the coasts 6 and 7 (codes 5, 4) shorten to their floor (the 1 ms a step of DA2(17) = 0:
// less gravity loss). Measured: chi4 0 -> 1.27 deg, coasts 6 and 7 5 and 6 s -> 0.004 s,
// 303.29 lb in 21 forward runs.
TEST(Sec9AdjustableCodes, StageFourYawAndTheCoastsAfterStagesOneAndTwoInAWholeOptimization) {
  ScratchDirectory scratch("adjustable_codes_2_4_5");
  const std::string deck = edited_example_deck(
      scratch, "yaw_and_coasts.toml",
      {{"linearization = true ", "linearization = false "},
       {"exchange_ratios = true ", "exchange_ratios = false "},
       {"body_dynamics_6d = 1 ", "body_dynamics_6d = 0 "},
       {"dispersions = true ", "dispersions = false "},
       {"# Data blocks 6 and 27",
        "[[constraint]]  # inclination 0.2 deg above the reference's\ncode = 10\ndesired_deg = 39.0\n"
        "deadband_optimization_deg = 0.02\ndeadband_linearization_deg = 0.01\n\n# Data blocks 6 and 27"},
       {"[linearization]",
        "[[adjustable_parameter]]  # stage-4 yaw (spun)\ncode = 2\nweight = 10.0\n\n"
        "[[adjustable_parameter]]  # coast 7\ncode = 4\nweight = 0.0001\n\n"
        "[[adjustable_parameter]]  # coast 6\ncode = 5\nweight = 0.0001\n\n[linearization]"}});
  const CommandResult run = run_tolip_executable({"optimize", deck, "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json d = nlohmann::json::parse(run.out);
  expect_converged_inside_every_deadband(d);
  ASSERT_EQ(d["constraints"].size(), 4u);
  EXPECT_EQ(d["constraints"][3]["code"], 10);
  const nlohmann::json* yaw = adjustable(d, 2);
  const nlohmann::json* coast7 = adjustable(d, 4);
  const nlohmann::json* coast6 = adjustable(d, 5);
  ASSERT_TRUE(yaw != nullptr && coast7 != nullptr && coast6 != nullptr);
  EXPECT_GT(std::fabs((*yaw)["value"].get<double>()), 0.5);  // deg
  EXPECT_LT((*coast7)["value"].get<double>(), 1.0);          // from 6 s
  EXPECT_LT((*coast6)["value"].get<double>(), 1.0);          // from 5 s
  EXPECT_NEAR(d["payload_lb"].get<double>(), 303.29, 1.0);
}

// Sec. 9 code 11: the escape example with the length of its final coast (10) adjusted too. The
// asymptote hardly depends on it (the J2 perturbation of the departure coast), so it moves little;
// the case converges as without it.
TEST(Sec9AdjustableCodes, CoastAfterStageFiveInTheEscapeOptimization) {
  ScratchDirectory scratch("adjustable_code_11");
  std::string text =
      read_text_file(std::string(tolip::repository_paths::examples_dir()) + "/escape/mission.toml");
  const std::size_t at = text.find("[linearization]");
  ASSERT_NE(at, std::string::npos);
  text.insert(at, "[[adjustable_parameter]]  # coast 10\ncode = 11\nweight = 0.0001\n\n");
  const std::string deck = (scratch / "coast10.toml").string();
  std::ofstream(deck) << text;
  const CommandResult run = run_tolip_executable({"optimize", deck, "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json d = nlohmann::json::parse(run.out);
  expect_converged_inside_every_deadband(d);
  const nlohmann::json* coast10 = adjustable(d, 11);
  ASSERT_NE(coast10, nullptr);
  EXPECT_NE((*coast10)["value"].get<double>(), (*coast10)["initial_value"].get<double>());
}

}  // namespace
}  // namespace tolip::test
