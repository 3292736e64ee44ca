// Bad decks are rejected with file, line, data block and field (manual Sec. 22; docs/deck-format.md).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

#include "deck_test_support.hpp"
#include "support/repository_paths.hpp"
#include "tolip/mission/mission.hpp"

namespace tolip::test {
namespace {

using ground::DeckError;
using ground::DeckExtras;

// The smallest deck the reader accepts: one powered stage, every optional block left out.
const char* const kMinimalDeck = R"(
[case]
title = "MINIMAL ONE-STAGE CASE"

[vehicle]
sequence = [1, 0]
payload_lb = 100.0

[stage.1]
integration_steps = 30
jettison_weight_lb = 1000.0
nozzle_exit_area_ft2 = 2.0
thrust = { time_s = [0.0, 10.0, 30.0], vacuum_thrust_lbf = [50000.0, 50000.0, 0.0] }
consumable_weight = { time_s = [0.0, 30.0], remaining_lb = [5000.0, 0.0] }

[launch]
liftoff_duration_s = 2.0
altitude_ft = 0.0
longitude_deg = -75.0
geocentric_latitude_deg = 37.5
azimuth_deg = 90.0

[[constraint]]
code = 0

[pitch_program]
time_s = [0.0, 30.0]
theta_deg = [90.0, 45.0]
)";

TEST(Sec22Deck, AcceptsMinimalDeckWithManualDefaults) {
  auto mission = ground::make_mission();
  DeckExtras extras;
  DeckError error;
  ASSERT_TRUE(ground::parse_toml_deck(kMinimalDeck, "minimal.toml", mission.get(), &extras, &error))
      << error.to_string();
  EXPECT_EQ(mission->vehicle.sequence.count, 1);
  EXPECT_EQ(mission->vehicle.stages[0].duration_s, 30.0);  // defaults to the last thrust time
  EXPECT_EQ(mission->constants.g0_ft_s2, 32.174);          // block 10 default
  EXPECT_EQ(mission->atmosphere.base_molecular_temperature_R[0], 518.69);
  EXPECT_DOUBLE_EQ(mission->launch.flight_path_angle_rad, 0.5 * kPi);
  EXPECT_EQ(mission->misc.payload_weighting_factor, 1.0);
  EXPECT_EQ(extras.listing.output.initial[9], 1);
  EXPECT_EQ(mission->constraints.count, 1);
  EXPECT_EQ(mission->adjustable.count, 0);
  EXPECT_EQ(extras.listing.title, "MINIMAL ONE-STAGE CASE");
  EXPECT_EQ(extras.listing.case_heading, "");
}

TEST(Sec22Deck, RejectsMissingLaunchBlockNamingBlock20) {
  const std::string text = removed(scout_mission_text(), "[launch]", "[control_constraints]");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 20);
  EXPECT_EQ(error.field, "launch");
  EXPECT_TRUE(contains(error.message, "missing required table [launch]"));
  EXPECT_TRUE(
      contains(error.to_string(), "edited.toml: data block 20, field launch: missing required table"));
}

TEST(Sec22Deck, RejectsMissingRequiredKeyNamingBlockAndField) {
  const std::string text = replaced(scout_mission_text(), "azimuth_deg = 100.0", "");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 21);
  EXPECT_EQ(error.field, "launch.azimuth_deg");
  EXPECT_EQ(error.line, line_of(text, "[launch]"));
  EXPECT_TRUE(contains(error.message, "DA6(5)"));
}

TEST(Sec22Deck, RejectsNonMonotonicThrustTableNamingBlock30) {
  // Stage 2 thrust times 0.0, 0.08, 0.2, 0.4, 1.0, 3.0 ... : make 1.0 come after 3.0.
  const std::string original = scout_mission_text();
  const std::string text =
      replaced(original, "0.0, 0.08, 0.2, 0.4, 1.0, 3.0", "0.0, 0.08, 0.2, 0.4, 3.5, 3.0");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 30);
  EXPECT_EQ(error.field, "stage.2.thrust.time_s[5]");
  EXPECT_EQ(error.line, line_of(text, "0.0, 0.08, 0.2, 0.4, 3.5, 3.0"));
  EXPECT_TRUE(contains(error.message, "not monotonic"));
  EXPECT_TRUE(contains(error.message, "strictly increasing"));
}

TEST(Sec22Deck, RejectsUnknownKeyInWeightTableNamingBlock38) {
  const std::string text = replaced(scout_mission_text(), "remaining_lb = [\n  560.0, 559.448",
                                    "time_s_x = 1\nremaining_lb = [\n  560.0, 559.448");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 38);
  EXPECT_EQ(error.field, "stage.4.consumable_weight.time_s_x");
  EXPECT_EQ(error.line, line_of(text, "time_s_x = 1"));
  EXPECT_TRUE(contains(error.message, "unknown key 'time_s_x'"));
}

TEST(Sec22Deck, RejectsNonMonotonicWeightTableNamingBlock38) {
  // The stage 4 weight table is the second "0.0, 0.1, 0.25, 0.5, 2.0" time array after [stage.4].
  std::string text = scout_mission_text();
  const std::size_t table = text.find("[stage.4.consumable_weight]");
  ASSERT_NE(table, std::string::npos);
  const std::size_t at = text.find("0.0, 0.1, 0.25, 0.5, 2.0", table);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 24, "0.0, 0.1, 0.25, 0.25, 2.0");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 38);
  EXPECT_EQ(error.field, "stage.4.consumable_weight.time_s[3]");
  EXPECT_TRUE(contains(error.message, "not monotonic"));
}

std::string thrust_table(int points, double duration) {
  std::string times;
  std::string thrusts;
  for (int i = 0; i < points; ++i) {
    const double t = duration * i / (points - 1);
    times += (i ? ", " : "") + std::to_string(t);
    thrusts += (i ? ", " : "") + std::string(i + 1 == points ? "0.0" : "1000.0");
  }
  return "thrust = { time_s = [" + times + "], vacuum_thrust_lbf = [" + thrusts + "] }\n";
}

std::string two_stage_deck(int stage1_points, int stage2_points) {
  return std::string(R"(
[case]
title = "THRUST CAPACITY"
[vehicle]
sequence = [1, 6, 2]
payload_lb = 10.0
[stage.1]
duration_s = 30.0
integration_steps = 30
jettison_weight_lb = 100.0
)") + thrust_table(stage1_points, 30.0) +
         R"(consumable_weight = { time_s = [0.0, 30.0], remaining_lb = [500.0, 0.0] }
[stage.6]
duration_s = 5.0
integration_steps = 5
[stage.2]
duration_s = 20.0
integration_steps = 20
jettison_weight_lb = 50.0
)" + thrust_table(stage2_points, 20.0) +
         R"(consumable_weight = { time_s = [0.0, 20.0], remaining_lb = [200.0, 0.0] }
[launch]
liftoff_duration_s = 1.0
altitude_ft = 0.0
longitude_deg = 0.0
geocentric_latitude_deg = 0.0
azimuth_deg = 90.0
[[constraint]]
code = 0
[pitch_program]
time_s = [0.0, 60.0]
theta_deg = [90.0, 10.0]
)";
}

TEST(Sec22Deck, AcceptsExactly120ThrustPointsOverAllStages) {
  auto mission = ground::make_mission();
  DeckError error;
  EXPECT_TRUE(ground::parse_toml_deck(two_stage_deck(60, 60), "cap.toml", mission.get(), &error))
      << error.to_string();
}

TEST(Sec22Deck, RejectsMoreThan120ThrustPointsOverAllStagesNamingBlock30) {
  const DeckError error = rejected(two_stage_deck(61, 60), "cap.toml");
  EXPECT_EQ(error.data_block, 30);
  EXPECT_EQ(error.field, "stage");
  EXPECT_TRUE(contains(error.message, "kTooManyThrustPointsInAllStages"));
  EXPECT_TRUE(contains(error.message, "121 thrust points over all stages; at most 120"));
}

TEST(Sec22Deck, RejectsMoreThan120ThrustPointsInOneStageNamingBlock30) {
  const DeckError error = rejected(two_stage_deck(121, 2), "cap.toml");
  EXPECT_EQ(error.data_block, 30);
  EXPECT_EQ(error.field, "stage.1.thrust.time_s");
  EXPECT_TRUE(contains(error.message, "121 points; at most 120"));
}

TEST(Sec22Deck, RejectsUnknownStageCodeInSequenceNamingBlock5) {
  const std::string text =
      replaced(scout_mission_text(), "sequence = [1, 6, 2, 7, 3, 8, 4]", "sequence = [1, 6, 2, 7, 3, 8, 11]");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 5);
  EXPECT_EQ(error.field, "vehicle.sequence[6]");
  EXPECT_EQ(error.line, line_of(text, "sequence = [1, 6, 2"));
  EXPECT_TRUE(contains(error.message, "unknown stage code 11"));
}

TEST(Sec22Deck, RejectsOutOfOrderSequenceNamingBlock5) {
  const std::string text =
      replaced(scout_mission_text(), "sequence = [1, 6, 2, 7, 3, 8, 4]", "sequence = [1, 2, 6]");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 5);
  EXPECT_EQ(error.field, "vehicle.sequence[2]");  // 1 2 is stage 2 directly after stage 1 (issue 17)
  EXPECT_TRUE(contains(error.message, "order 1 6 2 7 3 8 4 9 5 10")) << error.message;
  EXPECT_TRUE(contains(error.message, "expected 3 or its coast 7 here")) << error.message;
}

TEST(Sec22Deck, RejectsUnknownStageTableNamingBlock16) {
  const std::string text = replaced(scout_mission_text(), "[stage.6]", "[stage.11]");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 16);
  EXPECT_EQ(error.field, "stage.11");
  EXPECT_EQ(error.line, line_of(text, "[stage.11]"));
}

TEST(Sec22Deck, RejectsNegativeJettisonWeightNamingBlock39) {
  const std::string text =
      replaced(scout_mission_text(), "jettison_weight_lb = 560.0", "jettison_weight_lb = -560.0");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 39);
  EXPECT_EQ(error.field, "stage.3.jettison_weight_lb");
  EXPECT_EQ(error.line, line_of(text, "jettison_weight_lb = -560.0"));
  EXPECT_TRUE(contains(error.message, "kNegativeWeight"));
  EXPECT_TRUE(contains(error.message, "-560"));
}

TEST(Sec22Deck, RejectsNegativePayloadNamingBlock39) {
  const std::string text = replaced(scout_mission_text(), "payload_lb = 250.0", "payload_lb = -1.0");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 39);
  EXPECT_EQ(error.field, "vehicle.payload_lb");
  EXPECT_EQ(error.line, line_of(text, "payload_lb = -1.0"));
  EXPECT_TRUE(contains(error.message, "kNegativeWeight"));
}

TEST(Sec22Deck, RejectsNegativeConsumableWeightNamingBlock38) {
  const std::string text = replaced(scout_mission_text(), "0.757, 0.0,", "0.757, -1.0,");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 38);
  EXPECT_EQ(error.field, "stage.3.consumable_weight.remaining_lb[19]");
  EXPECT_TRUE(contains(error.message, "kNegativeWeight"));
  EXPECT_TRUE(contains(error.message, "remaining_lb[19] = -1 lb; expected >= 0 lb")) << error.message;
}

TEST(Sec22Deck, RejectsTomlSyntaxErrorWithItsLine) {
  const std::string text = replaced(scout_mission_text(), "altitude_ft = 10.0", "altitude_ft = = 10.0");
  const DeckError error = rejected(text, "syntax.toml");
  EXPECT_EQ(error.line, line_of(text, "altitude_ft = = 10.0"));
  EXPECT_GT(error.line, 0);
  EXPECT_TRUE(contains(error.message, "TOML syntax error"));
  EXPECT_TRUE(contains(error.to_string(), "syntax.toml:" + std::to_string(error.line) + ": "));
}

TEST(Sec22Deck, RejectsUnknownKeyNamingIt) {
  const std::string text =
      replaced(scout_mission_text(), "azimuth_deg = 100.0", "azimuth_deg = 100.0\nazimuth_degs = 100.0");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 20);
  EXPECT_EQ(error.field, "launch.azimuth_degs");
  EXPECT_EQ(error.line, line_of(text, "azimuth_degs"));
  EXPECT_TRUE(contains(error.message, "unknown key 'azimuth_degs'"));
  EXPECT_TRUE(contains(error.message, "expected one of: liftoff_duration_s"));
}

TEST(Sec22Deck, RejectsUnknownTopLevelTableNamingIt) {
  const std::string text = replaced(scout_mission_text(), "[launch]", "[lauch]");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.field, "lauch");
  EXPECT_EQ(error.line, line_of(text, "[lauch]"));
  EXPECT_TRUE(contains(error.message, "unknown key 'lauch' at the top level"));
}

TEST(Sec22Deck, RejectsAngleConstraintGivenInFeetNamingBlock19) {
  const std::string text = replaced(scout_mission_text(), "desired_deg = 0.0", "desired_ft = 0.0");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 19);
  EXPECT_EQ(error.field, "constraint[2].desired_deg");
  EXPECT_TRUE(contains(error.message, "found unknown key 'desired_ft'"));
}

TEST(Sec22Deck, RejectsWrongValueTypeNamingTheExpectation) {
  const std::string text =
      replaced(scout_mission_text(), "integration_steps = 42", "integration_steps = 42.5");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 16);
  EXPECT_EQ(error.field, "stage.1.integration_steps");
  EXPECT_TRUE(contains(error.message, "expected an integer"));
}

TEST(Sec22Deck, RejectsStageDurationMismatchNamingBlock16) {
  const std::string text = replaced(scout_mission_text(), "duration_s = 38.0", "duration_s = 38.5");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 16);
  EXPECT_EQ(error.field, "stage.2.duration_s");
  EXPECT_EQ(error.line, line_of(text, "duration_s = 38.5"));
  EXPECT_TRUE(contains(error.message, "kStageDurationMismatch"));
  EXPECT_TRUE(contains(error.message, "thrust table ends at 38 s"));
}

TEST(Sec22Deck, RejectsNonZeroInitialVelocityNamingBlock21) {
  const std::string text = replaced(scout_mission_text(), "velocity_ft_s = 0.0", "velocity_ft_s = 1.0");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 21);
  EXPECT_EQ(error.field, "launch.velocity_ft_s");
  EXPECT_TRUE(contains(error.message, "kInitialConditionsInvalid"));
}

TEST(Sec22Deck, RejectsLiftoffLongerThanStage1NamingBlock20) {
  const std::string text =
      replaced(scout_mission_text(), "liftoff_duration_s = 3.0", "liftoff_duration_s = 45.0");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 20);
  EXPECT_EQ(error.field, "launch.liftoff_duration_s");
  EXPECT_TRUE(contains(error.message, "kLiftoffLongerThanStage1"));
}

TEST(Sec22Deck, RejectsTooFewStage1StepsNamingBlock16) {
  const std::string text = replaced(scout_mission_text(), "integration_steps = 42", "integration_steps = 24");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 16);
  EXPECT_EQ(error.field, "stage.1.integration_steps");
  EXPECT_TRUE(contains(error.message, "kTooFewStage1Steps"));
}

TEST(Sec22Deck, RejectsMissingStageOfTheSequenceNamingBlock16) {
  const std::string text = removed(scout_mission_text(), "[stage.7]", "[stage.3]");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 16);
  EXPECT_EQ(error.field, "stage.7");
  EXPECT_TRUE(contains(error.message, "stage 7 is in the sequence"));
}

TEST(Sec22Deck, RejectsThrustTableInACoastNamingBlock30) {
  const std::string text =
      replaced(scout_mission_text(), "[stage.6.drag]",
               "[stage.6.thrust]\ntime_s = [0.0, 5.0]\nvacuum_thrust_lbf = [1.0, 1.0]\n\n[stage.6.drag]");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 30);
  EXPECT_EQ(error.field, "stage.6.thrust");
}

TEST(Sec22Deck, RejectsPayoffNotFirstNamingBlock8) {
  const std::string text = replaced(scout_mission_text(), "code = 0\n", "code = 1\n");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 8);
  EXPECT_EQ(error.field, "constraint[0].code");
  EXPECT_TRUE(contains(error.message, "payoff"));
}

// Data block 9 is the listing's (the core never sees it): the deck reader is its one check.
TEST(Sec22Deck, RejectsOutputFrequencyBelowOneNamingBlock9) {
  const std::string text = replaced(scout_mission_text(), "final = 1\n", "final = 0\n");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 9);
  EXPECT_EQ(error.field, "output_frequency.final");
  EXPECT_TRUE(contains(error.message, "at least 1"));
}

TEST(Sec22Deck, RejectsLinearizationTimeAfterBurnoutNamingBlock18) {
  const std::string text = replaced(scout_mission_text(), "300.0, 318.0, 336.0]", "300.0, 318.0, 337.0]");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 18);
  EXPECT_EQ(error.field, "linearization.coded_times[9]");
  EXPECT_TRUE(contains(error.message, "after its burnout"));
}

TEST(Sec22Deck, RejectsPitchProgramOverCapacityNamingBlock40) {
  std::string times = "0.0";
  std::string thetas = "90.0";
  for (int i = 1; i < 16; ++i) {
    times += ", " + std::to_string(10 * i) + ".0";
    thetas += ", 45.0";
  }
  std::string text = scout_mission_text();
  text = replaced(text, "time_s = [0.0, 3.0, 8.0, 15.0, 45.0, 50.0, 69.0, 88.0, 94.0, 112.0, 130.0]",
                  "time_s = [" + times + "]");
  text = replaced(text, "theta_deg = [90.0, 90.0, 80.0, 65.0, 49.0, 33.0, 27.0, 22.0, 21.0, 20.0, 18.0]",
                  "theta_deg = [" + thetas + "]");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 40);
  EXPECT_EQ(error.field, "pitch_program.time_s");
  EXPECT_TRUE(contains(error.message, "16 points; at most 15"));
}

TEST(Sec22Deck, RejectsOutOfOrderDispersionCodesNamingBlock46) {
  const std::string text = replaced(scout_mission_text(), "code = 9\n", "code = 1\n");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 46);
  EXPECT_EQ(error.field, "dispersion[8].code");
  EXPECT_TRUE(contains(error.message, "increasing order"));
}

TEST(Sec22Deck, RejectsNonMonotonicWindTableNamingBlock53) {
  const std::string text = replaced(scout_mission_text(), "altitude_ft = [\n  0.0, 1000.0, 5000.0",
                                    "altitude_ft = [\n  0.0, 6000.0, 5000.0");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 53);
  EXPECT_EQ(error.field, "dispersion[35].wind_speed.altitude_ft[2]");
}

TEST(Sec22Deck, RejectsImpactDragTableNotStartingAtMachZeroNamingBlock43) {
  const std::string text = replaced(scout_mission_text(), "casing_weight_lb = 560.0\nmach = [0.0,",
                                    "casing_weight_lb = 560.0\nmach = [0.1,");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 43);
  EXPECT_EQ(error.field, "impact.casing_drag.3.mach");
  EXPECT_TRUE(contains(error.message, "start at Mach 0"));
}

TEST(Sec22Deck, RejectsMissingHardoverWordNamingBlock45) {
  const std::string text = replaced(scout_mission_text(), "output_interval_s = 0.5", "");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 45);
  EXPECT_EQ(error.field, "hardover.parameters.output_interval_s");
}

TEST(Sec22Deck, RejectsRadarOptionWithoutStationsNamingBlock41) {
  const std::string text = removed(scout_mission_text(), "[[radar_station]]", "# Data blocks 42-43");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 41);
  EXPECT_EQ(error.field, "radar_station");
}

TEST(Sec22Deck, RejectsNonFiniteNumberNamingField) {
  const std::string text = replaced(scout_mission_text(), "altitude_ft = 10.0", "altitude_ft = nan");
  const DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 21);
  EXPECT_EQ(error.field, "launch.altitude_ft");
  EXPECT_TRUE(contains(error.message, "finite"));
}

template <int N>
void expect_same_table(const Table<N>& a, const Table<N>& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  EXPECT_EQ(a.finalized(), b.finalized()) << what;
  for (int i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a.x(i), b.x(i)) << what << " point " << i;
    EXPECT_EQ(a.y(i), b.y(i)) << what << " point " << i;
  }
}

// Field by field (memcmp would also compare padding bytes).
void expect_same_mission(const Mission& a, const Mission& b) {
  for (int n = 0; n < 25; ++n) EXPECT_EQ(a.options.ip[n], b.options.ip[n]);
  EXPECT_EQ(a.constants.g0_ft_s2, b.constants.g0_ft_s2);
  EXPECT_EQ(a.vehicle.sequence.count, b.vehicle.sequence.count);
  for (int k = 0; k < kMaxStages; ++k) {
    EXPECT_EQ(a.vehicle.sequence.codes[k], b.vehicle.sequence.codes[k]);
    const StageData& sa = a.vehicle.stages[k];
    const StageData& sb = b.vehicle.stages[k];
    const std::string what = "stage " + std::to_string(k + 1);
    EXPECT_EQ(sa.in_sequence, sb.in_sequence) << what;
    EXPECT_EQ(sa.duration_s, sb.duration_s) << what;
    EXPECT_EQ(sa.integration_steps, sb.integration_steps) << what;
    EXPECT_EQ(sa.jettison_weight_lb, sb.jettison_weight_lb) << what;
    EXPECT_EQ(sa.reference_area_ft2, sb.reference_area_ft2) << what;
    EXPECT_EQ(sa.nozzle_exit_area_ft2, sb.nozzle_exit_area_ft2) << what;
    EXPECT_EQ(sa.uses_lift_table, sb.uses_lift_table) << what;
    expect_same_table(sa.vacuum_thrust_lbf, sb.vacuum_thrust_lbf, what + " thrust");
    expect_same_table(sa.consumable_weight_lb, sb.consumable_weight_lb, what + " weight");
    expect_same_table(sa.drag_coefficient, sb.drag_coefficient, what + " drag");
  }
  expect_same_table(a.vehicle.lift_curve_slope_per_rad, b.vehicle.lift_curve_slope_per_rad, "lift");
  EXPECT_EQ(a.vehicle.payload_lb, b.vehicle.payload_lb);
  EXPECT_EQ(a.launch.liftoff_duration_s, b.launch.liftoff_duration_s);
  EXPECT_EQ(a.launch.azimuth_rad, b.launch.azimuth_rad);
  EXPECT_EQ(a.launch.geocentric_latitude_rad, b.launch.geocentric_latitude_rad);
  EXPECT_EQ(a.misc.stage4_theta_rad, b.misc.stage4_theta_rad);
  EXPECT_EQ(a.control.zero_alpha_end_s, b.control.zero_alpha_end_s);
  EXPECT_EQ(a.constraints.count, b.constraints.count);
  for (int i = 0; i <= kMaxConstraints; ++i) {
    EXPECT_EQ(a.constraints.codes[i], b.constraints.codes[i]);
    EXPECT_EQ(a.constraints.desired[i], b.constraints.desired[i]);
  }
  EXPECT_EQ(a.adjustable.count, b.adjustable.count);
  EXPECT_EQ(a.linearization.segment_count, b.linearization.segment_count);
  EXPECT_EQ(a.convergence.max_forward_trajectories, b.convergence.max_forward_trajectories);
  expect_same_table(a.pitch_program_rad, b.pitch_program_rad, "pitch");
}

TEST(Sec22Deck, FailedLoadLeavesPreviouslyLoadedMissionUnchanged) {
  auto mission = ground::make_mission();
  DeckExtras extras;
  DeckError error;
  ASSERT_TRUE(ground::parse_toml_deck(scout_mission_text(), "good.toml", mission.get(), &extras, &error))
      << error.to_string();
  const Mission before = *mission;
  const std::size_t stations = extras.radar_stations.size();
  const std::string title = extras.listing.title;

  // A deck that fails late (in validate_mission), after most of it was read.
  std::string bad = replaced(scout_optimum_text(), "duration_s = 38.0", "duration_s = 38.5");
  EXPECT_FALSE(ground::parse_toml_deck(bad, "bad.toml", mission.get(), &extras, &error));
  EXPECT_EQ(error.data_block, 16);
  // And one that fails early in the reader.
  bad = replaced(scout_optimum_text(), "[launch]", "[launch]\nbogus = 1");
  EXPECT_FALSE(ground::parse_toml_deck(bad, "bad.toml", mission.get(), &extras, &error));
  EXPECT_FALSE(ground::load_toml_deck("/nonexistent/deck.toml", mission.get(), &extras, &error));

  expect_same_mission(before, *mission);
  EXPECT_EQ(mission->vehicle.payload_lb, 250.0);
  EXPECT_EQ(extras.radar_stations.size(), stations);
  EXPECT_EQ(extras.listing.title, title);
}

TEST(Sec22Deck, RejectsMissingFileNamingIt) {
  auto mission = ground::make_mission();
  DeckError error;
  EXPECT_FALSE(ground::load_toml_deck("/nonexistent/deck.toml", mission.get(), &error));
  EXPECT_EQ(error.file, "/nonexistent/deck.toml");
  EXPECT_TRUE(contains(error.to_string(), "/nonexistent/deck.toml: cannot open the deck file"));
}

TEST(Sec22Deck, LoadErrorsNameTheFileOnDisk) {
  const std::string path = std::string(tolip::repository_paths::binary_dir()) + "/deck_errors_test_bad.toml";
  {
    std::ofstream out(path, std::ios::binary);
    out << replaced(scout_mission_text(), "jettison_weight_lb = 125.0", "jettison_weight_lb = -125.0");
  }
  auto mission = ground::make_mission();
  DeckError error;
  EXPECT_FALSE(ground::load_toml_deck(path, mission.get(), &error));
  EXPECT_TRUE(contains(error.to_string(), path + ":"));
  EXPECT_TRUE(
      contains(error.to_string(), ": data block 39, field stage.4.jettison_weight_lb: kNegativeWeight"));
  std::remove(path.c_str());
}

TEST(Sec22Deck, DeckErrorToStringFollowsFileLineBlockFieldMessage) {
  DeckError error;
  error.file = "deck.toml";
  error.line = 12;
  error.data_block = 30;
  error.field = "stage.2.thrust.time_s";
  error.message = "expected strictly increasing stage time";
  EXPECT_EQ(
      error.to_string(),
      "deck.toml:12: data block 30, field stage.2.thrust.time_s: expected strictly increasing stage time");
  error.line = 0;
  error.data_block = 0;
  error.field.clear();
  EXPECT_EQ(error.to_string(), "deck.toml: expected strictly increasing stage time");
}

}  // namespace
}  // namespace tolip::test
