// Sec. 22 IP(9) = 2 ("Stage 4 continuous and Stage 5 spun") end to end: the bundled Scout example
// with a continuous stage 4 optimizes, meets its constraints, carries at least the payload of the
// spun stage 4 (a constant stage-4 attitude is one of the programs a continuous stage 4 can fly),
// linearizes with data block 18 segments in stage 4, and exports a table image whose stage 4 flies
// segments. The deck readers act on IP(9) and the unused-input warnings say what it leaves unused.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "cli_runner.hpp"
#include "support/repository_paths.hpp"
#include "tolip/table/table_image.hpp"
#include "tolip_ground/deck.hpp"
#include "tolip_ground/unused_inputs.hpp"

namespace tolip::test {
namespace {

// The example with IP(9) = 2: the spun stage-4 attitude (adjustable code 1) leaves data block 6,
// data block 18 gains the stage-4 ignition and burnout (coast 8 becomes one intermediate segment),
// and the initial data block 40 program reaches the deck's stage-4 attitude (-20 deg) before
// ignition, so both cases start from the same trajectory.
const std::vector<std::pair<std::string, std::string>> kStage4Continuous = {
    {"spin_stages_4_5 = 1", "spin_stages_4_5 = 2"},
    {"[[adjustable_parameter]]  # block 6 IB1(2)\ncode = 1\nweight = 10.0                                # "
     "block 27 DA12(1)\n\n",
     ""},
    {"segment_count = 9 ", "segment_count = 11"},
    {"300.0, 318.0, 336.0]", "300.0, 318.0, 336.0, 400.0, 428.0]"},
    {"112.0, 130.0] # s from launch", "112.0, 130.0, 580.0] # s from launch"},
    {"20.0, 18.0] # pitch attitude", "20.0, 18.0, -20.0] # pitch attitude"},
};

struct Runs {
  ScratchDirectory scratch{"ip9_stage4"};
  std::string deck;
  CommandResult spun;
  CommandResult continuous;
  CommandResult exported;
  CommandResult inspected;
  nlohmann::json spun_doc;
  nlohmann::json continuous_doc;
  nlohmann::json table_doc;
};

const Runs& runs() {
  static const std::unique_ptr<Runs> r = [] {
    auto runs = std::make_unique<Runs>();
    runs->deck = edited_example_deck(runs->scratch, "stage4_continuous.toml", kStage4Continuous);
    runs->spun = run_tolip_executable(
        {"optimize", std::string(tolip::repository_paths::examples_dir()) + "/scout/mission.toml", "--json"});
    runs->continuous = run_tolip_executable({"optimize", runs->deck, "--json"});
    const std::string image = (runs->scratch / "table.bin").string();
    runs->exported = run_tolip_executable({"export", runs->deck, "--out", image, "--created-unix-s", "0"});
    runs->inspected = run_tolip_executable({"inspect", image, "--json"});
    runs->spun_doc = nlohmann::json::parse(runs->spun.out, nullptr, false);
    runs->continuous_doc = nlohmann::json::parse(runs->continuous.out, nullptr, false);
    runs->table_doc = nlohmann::json::parse(runs->inspected.out, nullptr, false);
    return runs;
  }();
  return *r;
}

TEST(Sec22Optimizer,
     IP9Is2_ScoutWithAContinuousStage4ConvergesMeetsItsConstraintsAndCarriesAtLeastTheSpunPayload) {
  const Runs& r = runs();
  ASSERT_EQ(r.spun.exit_code, 0) << r.spun.err;
  ASSERT_EQ(r.continuous.exit_code, 0) << r.continuous.err;
  ASSERT_FALSE(r.continuous_doc.is_discarded());
  const nlohmann::json& d = r.continuous_doc;
  EXPECT_TRUE(d["converged"].get<bool>());
  for (const nlohmann::json& c : d["constraints"]) EXPECT_TRUE(c["met"].get<bool>()) << c.dump();
  const double spun_lb = r.spun_doc["payload_lb"].get<double>();
  const double continuous_lb = d["payload_lb"].get<double>();
  std::printf("payload: stage 4 spun %.4f lb, continuous %.4f lb (%+.4f lb), %d forward runs\n", spun_lb,
              continuous_lb, continuous_lb - spun_lb, d["forward_runs"].get<int>());
  RecordProperty("continuous_stage4_payload_lb", std::to_string(continuous_lb));
  // The optimizer stops when its attempt falls under DA13(2) = 0.5 lb: that is the tolerance.
  EXPECT_GE(continuous_lb, spun_lb - 0.5);
  // The stage-4 attitude is a program, not a constant: the optimizer steered it.
  double lowest = 1e9, highest = -1e9;
  for (const nlohmann::json& p : d["trajectory"]) {
    if (p["stage"].get<int>() != 4) continue;
    lowest = std::fmin(lowest, p["theta_deg"].get<double>());
    highest = std::fmax(highest, p["theta_deg"].get<double>());
  }
  std::printf("stage-4 theta from %.3f to %.3f deg\n", lowest, highest);
  EXPECT_GT(highest - lowest, 0.01);
}

TEST(Sec22Optimizer, IP9Is2_LinearizationAndTheTableImageCarryStage4PitchSegments) {
  const Runs& r = runs();
  ASSERT_EQ(r.continuous.exit_code, 0) << r.continuous.err;
  const nlohmann::json& lin = r.continuous_doc["linearized"];
  EXPECT_EQ(lin["status"].get<std::string>(), "kOk") << lin.dump();
  int stage4_segments = 0;
  for (const nlohmann::json& s : lin["segments"]) stage4_segments += s["stage"].get<int>() == 4 ? 1 : 0;
  EXPECT_GE(stage4_segments, 1);

  ASSERT_EQ(r.exported.exit_code, 0) << r.exported.err;
  ASSERT_EQ(r.inspected.exit_code, 0) << r.inspected.err;
  ASSERT_FALSE(r.table_doc.is_discarded());
  const nlohmann::json& t = r.table_doc;
  EXPECT_EQ(t["format_version"].get<int>(), kTableFormatVersion);
  EXPECT_EQ(t["spin_option_ip9"].get<int>(), 2);
  int table_stage4 = 0;
  for (const nlohmann::json& s : t["segments"]) table_stage4 += s["stage"].get<int>() == 4 ? 1 : 0;
  EXPECT_EQ(table_stage4, stage4_segments);
  // A continuous stage 4 has no spun attitude; it takes stage 3's autopilot gains.
  EXPECT_EQ(t["stage4_theta_deg"].get<double>(), 0.0);
  EXPECT_EQ(t["gains"][3]["k_theta_deg_per_deg"].get<double>(),
            t["gains"][2]["k_theta_deg_per_deg"].get<double>());
  EXPECT_GT(t["gains"][3]["k_theta_deg_per_deg"].get<double>(), 0.0);
}

// The deck readers act on IP(9): its stage-4 attitude words are reported unused under IP(9) = 2,
// and a spun-attitude code with a continuous stage 4 is rejected, naming data block 6.
TEST(Sec22Deck, IP9Is2_Stage4AttitudeWordsAreReportedUnusedAndItsAdjustableCodeIsRejected) {
  const Runs& r = runs();
  EXPECT_NE(r.continuous.err.find("DA2(5)"), std::string::npos) << r.continuous.err;
  EXPECT_EQ(r.spun.err.find("DA2(5)"), std::string::npos) << r.spun.err;

  ScratchDirectory scratch("ip9_rejected");
  const std::string rejected =
      edited_example_deck(scratch, "code1.toml", {{"spin_stages_4_5 = 1", "spin_stages_4_5 = 2"}});
  const CommandResult result = run_tolip_executable({"optimize", rejected});
  EXPECT_NE(result.exit_code, 0);
  EXPECT_NE(result.err.find("data block 6"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("IP(9)"), std::string::npos) << result.err;
}

// Sec. 22 IP(10) ("0 fewer than 5 stages"): a stage-5 yaw option on the four-stage example is a
// deck fault (exit 2) that names IP(10), its key and its own status, not IP(9), which is right.
TEST(Sec22Deck, IP10FaultIsReportedNamingIP10NotIP9) {
  ScratchDirectory scratch("ip10_rejected");
  const std::string rejected =
      edited_example_deck(scratch, "ip10.toml", {{"stage5_chi = 0", "stage5_chi = 1"}});
  const CommandResult result = run_tolip_executable({"optimize", rejected});
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_NE(result.err.find("kStage5YawOptionInconsistent"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("options.stage5_chi"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("IP(10)"), std::string::npos) << result.err;
  EXPECT_EQ(result.err.find("IP(9) does not fit"), std::string::npos) << result.err;
  EXPECT_EQ(result.err.find("kSpinOptionInconsistent"), std::string::npos) << result.err;
}

// The card deck (80 columns, Sec. 22) acts on IP(9) as the TOML deck does: converted, it optimizes
// to the same payload (to the E12.8 rounding of two words).
TEST(Sec22Deck, IP9Is2_TheCardDeckOptimizesLikeTheTomlDeck) {
  const Runs& r = runs();
  ASSERT_EQ(r.continuous.exit_code, 0) << r.continuous.err;
  const std::string cards = (r.scratch / "stage4_continuous.dat").string();
  const CommandResult converted = run_tolip_executable({"convert", r.deck, "--to", cards});
  ASSERT_EQ(converted.exit_code, 0) << converted.err;
  const CommandResult run = run_tolip_executable({"optimize", cards, "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json d = nlohmann::json::parse(run.out, nullptr, false);
  ASSERT_FALSE(d.is_discarded());
  EXPECT_TRUE(d["converged"].get<bool>());
  EXPECT_NEAR(d["payload_lb"].get<double>(), r.continuous_doc["payload_lb"].get<double>(), 1e-3);
}

// Sec. 22 IP(9) = 3 ("Stages 4 and 5 continuous"; "set = 3 only when there are five stages"): the
// example with an illustrative fifth stage (a 1,500 lbf, 15 s kick motor after a 6 s coast 9)
// optimizes with both upper stages steered, linearizes with segments in stages 4 and 5, and exports.
TEST(Sec22Optimizer, IP9Is3_AFiveStageScoutSteersStages4And5LinearizesAndExports) {
  ScratchDirectory scratch("ip9_five_stages");
  std::vector<std::pair<std::string, std::string>> edits = kStage4Continuous;
  edits[0].second = "spin_stages_4_5 = 3";
  edits[2].second = "segment_count = 13";
  edits[3].second = "300.0, 318.0, 336.0, 400.0, 428.0, 500.0, 515.0]";
  edits.push_back({"sequence = [1, 6, 2, 7, 3, 8, 4] ", "sequence = [1, 6, 2, 7, 3, 8, 4, 9, 5] "});
  edits.push_back(
      {"[launch]  # data blocks 20 and 21",
       "[stage.9]\nduration_s = 6.0\nintegration_steps = 3\njettison_weight_lb = 0.0\nreference_area_ft2 = "
       "0.0\n\n"
       "[stage.5]\nname = \"illustrative kick motor\"\nduration_s = 15.0\nintegration_steps = 12\n"
       "jettison_weight_lb = 30.0\nreference_area_ft2 = 1.0\nnozzle_exit_area_ft2 = 0.3\n\n"
       "[stage.5.thrust]\ntime_s = [0.0, 0.2, 14.8, 15.0]\nvacuum_thrust_lbf = [0.0, 1500.0, 1500.0, 0.0]\n\n"
       "[stage.5.consumable_weight]\ntime_s = [0.0, 0.2, 14.8, 15.0]\nremaining_lb = [80.0, 79.99, 0.01, "
       "0.0]\n\n"
       "[launch]  # data blocks 20 and 21"});
  const std::string deck = edited_example_deck(scratch, "five_stages.toml", edits);
  const CommandResult run = run_tolip_executable({"optimize", deck, "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json d = nlohmann::json::parse(run.out, nullptr, false);
  ASSERT_FALSE(d.is_discarded());
  EXPECT_TRUE(d["converged"].get<bool>());
  for (const nlohmann::json& c : d["constraints"]) EXPECT_TRUE(c["met"].get<bool>()) << c.dump();
  std::printf("five stages, IP(9) = 3: payload %.4f lb in %d forward runs, linearized %.4f lb\n",
              d["payload_lb"].get<double>(), d["forward_runs"].get<int>(),
              d["linearized"]["payoff"].get<double>());
  for (int code : {4, 5}) {
    double lowest = 1e9, highest = -1e9;
    for (const nlohmann::json& p : d["trajectory"]) {
      if (p["stage"].get<int>() != code) continue;
      lowest = std::fmin(lowest, p["theta_deg"].get<double>());
      highest = std::fmax(highest, p["theta_deg"].get<double>());
    }
    EXPECT_GT(highest - lowest, 0.01) << "stage " << code << " is steered";
  }
  EXPECT_EQ(d["linearized"]["status"].get<std::string>(), "kOk");
  int stage5_segments = 0;
  for (const nlohmann::json& s : d["linearized"]["segments"])
    stage5_segments += s["stage"].get<int>() == 5 ? 1 : 0;
  EXPECT_GE(stage5_segments, 1);

  const std::string image = (scratch / "table.bin").string();
  const CommandResult exported =
      run_tolip_executable({"export", deck, "--out", image, "--created-unix-s", "0"});
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  const CommandResult inspected = run_tolip_executable({"inspect", image, "--json"});
  ASSERT_EQ(inspected.exit_code, 0) << inspected.err;
  const nlohmann::json t = nlohmann::json::parse(inspected.out, nullptr, false);
  EXPECT_EQ(t["spin_option_ip9"].get<int>(), 3);
  int table_stage5 = 0;
  for (const nlohmann::json& s : t["segments"]) table_stage5 += s["stage"].get<int>() == 5 ? 1 : 0;
  EXPECT_EQ(table_stage5, stage5_segments);
}

}  // namespace
}  // namespace tolip::test
