// Issue 17, manual Sec. 22 data blocks 5, 6 and 16: powered stages back to back in the decks. The
// bundled example without coast 7 (sequence 1 6 2 3 8 4) reads from TOML, converts to cards and
// back to the same case, simulates with stage 3 igniting at stage 2's burnout in the report's stage
// events, and optimizes; a coast of 0 s and the length of an absent coast are refused with
// messages that say what to do.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <utility>

#include "cli_runner.hpp"
#include "deck_test_support.hpp"
#include "tolip/mission/mission.hpp"

namespace tolip::test {
namespace {

const std::string kSequence = "sequence = [1, 6, 2, 7, 3, 8, 4]";
const std::string kWithoutCoast7 = "sequence = [1, 6, 2, 3, 8, 4]";

const std::string kCodedTimes =
    "segment_count = 9                            # TLIN(1)\n"
    "coded_times = [103.0, 108.0, 115.0, 145.0, 200.0, 219.0, 238.0, 300.0,";
// Without coast 7 stage 2's burnout (238.0) is stage 3's ignition (300.0): block 18 lists one.
const std::string kCodedTimesWithoutCoast7 =
    "segment_count = 8\n"
    "coded_times = [103.0, 108.0, 115.0, 145.0, 200.0, 219.0, 300.0,";

std::string without_coast7() {
  return replaced(replaced(scout_mission_text(), kSequence, kWithoutCoast7), kCodedTimes,
                  kCodedTimesWithoutCoast7);
}

std::string written(const ScratchDirectory& scratch, const std::string& name, const std::string& text) {
  const std::string path = (scratch / name).string();
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

TEST(Sec22Block5Deck, SequenceWithoutCoast7IsRead) {
  auto mission = ground::make_mission();
  ground::DeckError error;
  ASSERT_TRUE(ground::parse_toml_deck(without_coast7(), "no_coast7.toml", mission.get(), &error))
      << error.to_string();
  const StageSequence& sequence = mission->vehicle.sequence;
  ASSERT_EQ(sequence.count, 6);
  const int expected[] = {1, 6, 2, 3, 8, 4};
  for (int k = 0; k < 6; ++k) EXPECT_EQ(sequence.codes[k], expected[k]);
  EXPECT_FALSE(mission->vehicle.stages[stage_index(7)].in_sequence);
  EXPECT_EQ(validate_mission(*mission, nullptr), Status::kOk);
}

TEST(Sec22Block5Deck, OutOfOrderSequenceSaysWhatMayComeNext) {
  // A coast after the wrong stage (coast 8 after stage 2), and a skipped powered stage.
  ground::DeckError error =
      rejected(replaced(scout_mission_text(), kSequence, "sequence = [1, 6, 2, 8, 3, 4]"));
  EXPECT_EQ(error.data_block, 5);
  EXPECT_EQ(error.field, "vehicle.sequence[3]");
  EXPECT_TRUE(contains(error.message, "expected 3 or its coast 7 here")) << error.message;
  error = rejected(replaced(scout_mission_text(), kSequence, "sequence = [1, 6, 3, 8, 4]"));
  EXPECT_EQ(error.field, "vehicle.sequence[2]");
  EXPECT_TRUE(contains(error.message, "expected 2 here")) << error.message;
}

TEST(Sec22Block18Deck, BurnoutAndNextIgnitionAtTheSameInstantAreRefused) {
  // Coast 7 left out but block 18 still codes stage 2's burnout 238.0 and stage 3's ignition 300.0.
  const ground::DeckError error = rejected(replaced(scout_mission_text(), kSequence, kWithoutCoast7));
  EXPECT_EQ(error.data_block, 18);
  EXPECT_TRUE(contains(error.message, "kTableNotMonotonic")) << error.message;
  EXPECT_TRUE(contains(error.message, "list one of the two")) << error.message;
}

TEST(Sec22Block16Deck, ZeroLengthCoastIsRefusedTellingToLeaveItOutOfTheSequence) {
  const std::string text = replaced(scout_mission_text(), "duration_s = 6.0 ", "duration_s = 0.0 ");
  const ground::DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 16);
  EXPECT_TRUE(contains(error.message, "kZeroLengthCoast")) << error.message;
  EXPECT_TRUE(contains(error.message, "coast 7 left out of vehicle.sequence (data block 5)"))
      << error.message;
}

TEST(Sec22Block6Deck, LengthOfAnAbsentCoastIsRefusedNamingBlock6) {
  // The example adjusts the length of coast 8 (code 3); leave coast 8 out.
  const std::string text = replaced(scout_mission_text(), kSequence, "sequence = [1, 6, 2, 7, 3, 4]");
  const ground::DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 6);
  EXPECT_TRUE(contains(error.message, "kAdjustableCoastNotInSequence")) << error.message;
  EXPECT_TRUE(contains(error.message, "data block 6")) << error.message;
}

TEST(Sec22Block5Deck, ConvertRoundTripKeepsTheSequenceAndTheFlight) {
  // TOML -> cards (punched to E12.8) -> TOML -> cards: the cards come back exactly and all three
  // card-precision decks fly alike.
  ScratchDirectory scratch("no_coast7_convert");
  const std::string toml = written(scratch, "no_coast7.toml", without_coast7());
  const std::string cards = (scratch / "no_coast7.dat").string();
  const std::string back = (scratch / "back.toml").string();
  const std::string again = (scratch / "again.dat").string();
  for (const auto& [from, to] : {std::pair{toml, cards}, std::pair{cards, back}, std::pair{back, again}}) {
    const CommandResult result = run_tolip_executable({"convert", from, "--to", to});
    ASSERT_EQ(result.exit_code, 0) << result.err;
  }
  EXPECT_TRUE(contains(read_text_file(back), "sequence = [1, 6, 2, 3, 8, 4")) << read_text_file(back);
  EXPECT_EQ(read_text_file(again), read_text_file(cards));
  const CommandResult original = run_tolip_executable({"simulate", cards, "--json"});
  const CommandResult via_toml = run_tolip_executable({"simulate", back, "--json"});
  const CommandResult via_again = run_tolip_executable({"simulate", again, "--json"});
  ASSERT_EQ(original.exit_code, 0) << original.err;
  ASSERT_EQ(via_toml.exit_code, 0) << via_toml.err;
  ASSERT_EQ(via_again.exit_code, 0) << via_again.err;
  nlohmann::json a = nlohmann::json::parse(original.out);
  nlohmann::json b = nlohmann::json::parse(via_toml.out);
  nlohmann::json c = nlohmann::json::parse(via_again.out);
  for (nlohmann::json* document : {&a, &b, &c}) document->erase("deck");
  EXPECT_EQ(a, b);
  EXPECT_EQ(a, c);

  // The report's stage events: stage 3 ignites at stage 2's burnout, after its jettison.
  const nlohmann::json& events = a["stage_events"];
  ASSERT_EQ(events.size(), 6u);
  EXPECT_EQ(events[2]["stage"].get<int>(), 2);
  EXPECT_EQ(events[3]["stage"].get<int>(), 3);
  EXPECT_EQ(events[3]["kind"].get<std::string>(), "powered");
  EXPECT_EQ(events[3]["start_time_s"].get<double>(), events[2]["end_time_s"].get<double>());
  EXPECT_NEAR(events[2]["jettison_weight_lb"].get<double>(), 1900.0, 1e-9);  // stage 2's block 39 SG2(1)
  EXPECT_NEAR(events[3]["start_weight_lb"].get<double>(), events[2]["weight_after_jettison_lb"].get<double>(),
              1e-9);
}

TEST(Sec22Block5Deck, BundledExampleOptimizesWithCoast7Removed) {
  ScratchDirectory scratch("no_coast7_optimize");
  const std::string toml = written(scratch, "no_coast7.toml", without_coast7());
  const CommandResult result = run_tolip_executable({"optimize", toml, "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err << result.out.substr(0, 2000);
  const nlohmann::json document = nlohmann::json::parse(result.out);
  EXPECT_TRUE(document["converged"].get<bool>());
  EXPECT_EQ(document["case_status"].get<std::string>(), "kOk");
  const double payload = document["payload_lb"].get<double>();
  std::printf("without coast 7: payload %.10f lb in %d forward runs (with it: 307.678 lb)\n", payload,
              document["forward_runs"].get<int>());
  // Same vehicle and orbit, 6 s less coast between stages 2 and 3: a payload of the same order.
  EXPECT_GT(payload, 250.0);
  EXPECT_LT(payload, 360.0);
  for (const nlohmann::json& c : document["constraints"]) EXPECT_TRUE(c["met"].get<bool>()) << c.dump();
}

}  // namespace
}  // namespace tolip::test
