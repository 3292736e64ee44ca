// Absurd input (issue 10 part 4): every rejection names the block and the key (card deck: the card
// and columns), the value given and the allowed range; absurd values are rejected at the boundary;
// a rejected deck prints nothing; a failed run's stage events show what happened.
#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "deck_test_support.hpp"
#include "tolip_ground/card_deck.hpp"

namespace tolip::test {
namespace {

struct Edit {
  const char* from;
  const char* to;
  int block;
  const char* field;
  const char* value;  // "key = value unit" as the message gives it
  const char* range;  // "expected ..."
};

// Edits of examples/scout/mission.toml that a user reported, each rejected by the core's
// validate_mission with the value and the range carried in MissionFault.
const std::vector<Edit>& reported_edits() {
  static const std::vector<Edit> edits = {
      {"vacuum_thrust_lbf = [\n  0.0, 68199.8", "vacuum_thrust_lbf = [\n  0.0, -68199.8", 30,
       "stage.1.thrust.vacuum_thrust_lbf[1]", "vacuum_thrust_lbf[1] = -68199.8 lbf", "expected >= 0 lbf"},
      {"g0_ft_s2 = 32.174", "g0_ft_s2 = 0.0", 10, "constants.g0_ft_s2", "g0_ft_s2 = 0 ft/s^2",
       "expected > 0 ft/s^2"},
      {"inverse_flattening = 298.3", "inverse_flattening = 1.0", 10, "constants.inverse_flattening",
       "inverse_flattening = 1", "expected > 1 (or 0 for a spherical Earth)"},
      {"geocentric_latitude_deg = 37.653239661", "geocentric_latitude_deg = 95.0", 21,
       "launch.geocentric_latitude_deg", "geocentric_latitude_deg = 95 deg",
       "expected -90 <= geocentric_latitude_deg <= 90 deg"},
      {"liftoff_duration_s = 3.0", "liftoff_duration_s = -1.0", 20, "launch.liftoff_duration_s",
       "liftoff_duration_s = -1 s", "expected > 0 s"},
      // Before: accepted, then kNonFiniteState from the first step at V = 0 (issue 17).
      {"liftoff_duration_s = 3.0", "liftoff_duration_s = 0.0", 20, "launch.liftoff_duration_s",
       "liftoff_duration_s = 0 s", "expected > 0 s"},
      {"zero_alpha_end_s = 45.0", "zero_alpha_end_s = 400.0", 22, "control_constraints.zero_alpha_end_s",
       "zero_alpha_end_s = 400 s", "expected 15 < zero_alpha_end_s <= 45.02 s"},
      {"max_forward_trajectories = 30", "max_forward_trajectories = 0", 28,
       "convergence.max_forward_trajectories", "max_forward_trajectories = 0", "expected >= 1"},
      {"deadband_optimization_ft = 20000.0", "deadband_optimization_ft = 0.0", 29,
       "constraint[1].deadband_optimization_ft", "deadband_optimization_ft = 0 ft", "expected > 0 ft"},
      {"azimuth_deg = 100.0 ", "azimuth_deg = 1e20 ", 21, "launch.azimuth_deg", "azimuth_deg = 1e+20 deg",
       "expected -360 <= azimuth_deg <= 360 deg"},
      {"stage4_theta_deg = -20.0", "stage4_theta_deg = 1e10", 17, "misc.stage4_theta_deg",
       "stage4_theta_deg = 10000000000 deg", "expected -360 <= stage4_theta_deg <= 360 deg"},
      {"theta_deg = [90.0,", "theta_deg = [1e308,", 40, "pitch_program.theta_deg[0]",
       "theta_deg[0] = 1e+308 deg", "expected -360 <= theta_deg[0] <= 360 deg"},
      {"altitude_ft = 10.0", "altitude_ft = -1e7", 21, "launch.altitude_ft", "altitude_ft = -10000000 ft",
       "expected -1500 <= altitude_ft <= 100000 ft"},
      {"remaining_lb = [\n  560.0, 559.448, 557.048, 551.669, 518.897, 454.347, 368.279, 280.888",
       "remaining_lb = [\n  560.0, 559.448, 557.048, 551.669, 518.897, 454.347, 368.279, 380.888", 38,
       "stage.4.consumable_weight.remaining_lb[7]", "remaining_lb[7] = 380.888 lb", "expected <= 368.279 lb"},
  };
  return edits;
}

TEST(AbsurdDeck, EveryReportedRejectionNamesTheKeyTheValueAndTheAllowedRange) {
  for (const Edit& edit : reported_edits()) {
    const std::string text = replaced(scout_mission_text(), edit.from, edit.to);
    const ground::DeckError error = rejected(text);
    const std::string message = error.to_string();
    EXPECT_EQ(error.data_block, edit.block) << message;
    EXPECT_EQ(error.field, edit.field) << message;
    EXPECT_GT(error.line, 0) << message;
    EXPECT_TRUE(contains(message, edit.value)) << edit.to;
    EXPECT_TRUE(contains(message, edit.range)) << edit.to;
  }
}

TEST(AbsurdDeck, StageWithThrustButNoPropellantIsRejectedNamingBlock38) {
  const std::string weights =
      "remaining_lb = [\n  560.0, 559.448, 557.048, 551.669, 518.897, 454.347, 368.279, 280.888, 192.172, "
      "125.636,\n"
      "  71.292, 40.341, 22.135, 8.562, 2.383, 0.463, 0.0,\n]";
  std::string zeros = "remaining_lb = [";
  for (int i = 0; i < 17; ++i) zeros += i == 0 ? "0.0" : ", 0.0";
  zeros += "]";
  const ground::DeckError error = rejected(replaced(scout_mission_text(), weights, zeros));
  const std::string message = error.to_string();
  EXPECT_EQ(error.data_block, 38) << message;
  EXPECT_EQ(error.field, "stage.4.consumable_weight.remaining_lb[0]") << message;
  EXPECT_TRUE(contains(message, "kThrustWithoutPropellant")) << message;
  EXPECT_TRUE(contains(message, "remaining_lb[0] = 0 lb; expected > 0 lb")) << message;
}

TEST(AbsurdDeck, NegativeStageDurationIsBlamedOnTheStageDurationOfBlock16) {
  const std::string text = replaced(scout_mission_text(), "duration_s = 38.0", "duration_s = -38.0");
  const ground::DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 16) << error.to_string();
  EXPECT_EQ(error.field, "stage.2.duration_s") << error.to_string();
  EXPECT_EQ(error.line, line_of(text, "duration_s = -38.0"));
  EXPECT_TRUE(contains(error.to_string(), "duration_s = -38; expected > 0")) << error.to_string();
}

TEST(AbsurdDeck, UnknownConstraintCodeIsRejectedAsUnknownBeforeAnyUnitKeyIsAskedFor) {
  const std::string text = replaced(scout_mission_text(), "code = 7\ndesired_ft", "code = 99\ndesired_ft");
  const ground::DeckError error = rejected(text);
  const std::string message = error.to_string();
  EXPECT_EQ(error.data_block, 8) << message;
  EXPECT_EQ(error.field, "constraint[1].code") << message;
  EXPECT_TRUE(contains(message, "unknown constraint code 99")) << message;
  EXPECT_TRUE(contains(message, "stage 9 is not in the sequence 1 6 2 7 3 8 4")) << message;
  EXPECT_TRUE(contains(message, "expected 0-13 (terminal), 14 (heating, last), X5-X9")) << message;
  EXPECT_FALSE(contains(message, "lb_ft2")) << message;
  // A code that is no code at all is named the same way.
  const ground::DeckError other =
      rejected(replaced(scout_mission_text(), "code = 7\ndesired_ft", "code = 50\ndesired_ft"));
  EXPECT_TRUE(contains(other.to_string(), "unknown constraint code 50")) << other.to_string();
}

TEST(AbsurdCardDeck, RangeRejectionNamesTheCardColumnsTheValueAndTheRange) {
  const std::string cards = read_text(example_path("scout/mission.dat"));
  const std::string text =
      replaced(cards, "         10.      -75.4837.653239661          0.        100.         90.",
               "         10.      -75.4837.653239661          0.       1.E20         90.");
  auto deck = std::make_unique<ground::Deck>();
  ground::DeckError error;
  ASSERT_FALSE(ground::parse_deck(text, "absurd.dat", deck.get(), &error));
  const std::string message = error.to_string();
  EXPECT_TRUE(contains(message, "columns 49-60: case 1, data block 21, word 5")) << message;
  EXPECT_TRUE(contains(message, "azimuth_deg = 1e+20 deg; expected -360 <= azimuth_deg <= 360 deg"))
      << message;
}

std::string write_deck(const ScratchDirectory& scratch, const std::string& name, const std::string& text) {
  const std::string path = (scratch / name).string();
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

TEST(AbsurdCli, OptimizeOfADeckWithAZeroDeadbandPrintsNothingAndExitsTwo) {
  ScratchDirectory scratch("absurd_deadband");
  const std::string deck = write_deck(scratch, "deadband.toml",
                                      replaced(scout_mission_text(), "deadband_optimization_ft_s = 20.0",
                                               "deadband_optimization_ft_s = 0.0"));
  for (const bool json : {false, true}) {
    const CommandResult run = json ? run_tolip_executable({"optimize", deck, "--json", "--no-progress"})
                                   : run_tolip_executable({"optimize", deck, "--no-progress"});
    EXPECT_EQ(run.exit_code, 2) << run.err;
    EXPECT_TRUE(run.out.empty()) << run.out;
    EXPECT_TRUE(contains(run.err, "data block 29, field constraint[3].deadband_optimization_ft_s"))
        << run.err;
    EXPECT_TRUE(contains(run.err, "deadband_optimization_ft_s = 0 ft/s; expected > 0 ft/s")) << run.err;
  }
}

TEST(AbsurdCli, AtmosphereRejectsAnEmptyAltitude) {
  for (const char* value : {"", " "}) {
    const CommandResult run = run_tolip_executable({"atmosphere", "--altitude-ft", value});
    EXPECT_EQ(run.exit_code, 2) << "'" << value << "'";
    EXPECT_TRUE(run.out.empty()) << run.out;
    EXPECT_TRUE(contains(run.err, "--altitude-ft: an empty value")) << run.err;
  }
}

TEST(AbsurdCli, AtmosphereRejectsAltitudesOutsideTheModelNamingTheRange) {
  for (const char* value : {"1e308", "1000001", "-16405"}) {
    const CommandResult run = run_tolip_executable({"atmosphere", std::string("--altitude-ft=") + value});
    EXPECT_EQ(run.exit_code, 2) << value;
    EXPECT_TRUE(run.out.empty()) << run.out;
    EXPECT_TRUE(contains(run.err, "expected -16404 <= altitude <= 1000000 ft")) << run.err;
  }
  for (const char* value : {"1000000", "-16404", "250000"}) {
    const CommandResult run = run_tolip_executable({"atmosphere", std::string("--altitude-ft=") + value});
    EXPECT_EQ(run.exit_code, 0) << value << run.err;
    EXPECT_LT(run.out.size(), 1000u);
  }
}

TEST(AbsurdCli, ExportRejectsAnEmptyMissionIdInsteadOfUsingTheTitle) {
  ScratchDirectory scratch("absurd_mission_id");
  const std::string out = (scratch / "table.bin").string();
  const CommandResult run =
      run_tolip_executable({"export", example_path("scout/mission.toml"), "--out", out, "--mission-id", ""});
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_TRUE(run.out.empty()) << run.out;
  EXPECT_TRUE(contains(run.err, "--mission-id: an empty value: expected 1-32 printable ASCII characters"))
      << run.err;
  EXPECT_TRUE(scratch.entries().empty());
}

// The example with a pitch program that turns into the ground after stage 2 (it hits in stage 3).
std::string crash_deck(const ScratchDirectory& scratch) {
  std::string text = scout_mission_text();
  const std::size_t at = text.find("[pitch_program]");
  const std::size_t begin = text.find("theta_deg = [", at);
  const std::size_t end = text.find(']', begin);
  EXPECT_NE(end, std::string::npos);
  text.replace(begin, end + 1 - begin,
               "theta_deg = [90.0, 90.0, 80.0, 65.0, 49.0, 33.0, -60.0, -80.0, -80.0, -80.0, -80.0]");
  return write_deck(scratch, "crash.toml", text);
}

TEST(FailedRunListing, StageEventsShowWhatHappenedAndMarkTheRest) {
  ScratchDirectory scratch("absurd_crash");
  const std::string deck = crash_deck(scratch);
  const CommandResult listing = run_tolip_executable({"simulate", deck});
  ASSERT_EQ(listing.exit_code, 1) << listing.err;
  const std::size_t events = listing.out.find(" STAGE EVENTS");
  ASSERT_NE(events, std::string::npos) << listing.out;
  const std::string table = listing.out.substr(events, listing.out.find("\n\n", events) - events);
  EXPECT_TRUE(contains(table, "STOPPED")) << table;
  EXPECT_TRUE(contains(table, "NOT REACHED")) << table;
  // No stage that ended drops the whole vehicle: STAGE 1 jettisons its 4800 lb and leaves the rest.
  EXPECT_FALSE(contains(table, "          0.00\n")) << table;
  EXPECT_TRUE(contains(table, "4800.00")) << table;

  const CommandResult json = run_tolip_executable({"simulate", deck, "--json"});
  ASSERT_EQ(json.exit_code, 1);
  const nlohmann::json document = nlohmann::json::parse(json.out);
  const nlohmann::json& stages = document["stage_events"];
  ASSERT_GE(stages.size(), 2u);
  for (std::size_t i = 0; i + 1 < stages.size(); ++i) {
    EXPECT_TRUE(stages[i]["completed"].get<bool>()) << i;
    EXPECT_GT(stages[i]["weight_after_jettison_lb"].get<double>(), 0.0) << i;
  }
  EXPECT_FALSE(stages.back()["completed"].get<bool>());
  EXPECT_TRUE(stages.back()["jettison_weight_lb"].is_null());
  EXPECT_TRUE(stages.back()["weight_after_jettison_lb"].is_null());
}

}  // namespace
}  // namespace tolip::test
