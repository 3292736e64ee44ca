// The heritage card deck (manual Sec. 22, docs/deck-format.md "The card deck"): hand-written decks
// with every card format, successive cases and the optional groups; malformed decks and their
// messages; the bundled example against its TOML twin; conversions both ways; a fuzz smoke test.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "deck_test_support.hpp"
#include "tolip/core/constants.hpp"
#include "tolip/mission/mission.hpp"
#include "tolip_ground/card_deck.hpp"
#include "tolip_ground/input_echo.hpp"
#include "tolip_ground/mission_source.hpp"

namespace tolip::test {
namespace {

using ground::Deck;
using ground::DeckError;
using ground::DeckExtras;
using ground::DeckFormat;

double deg(double value) { return value * kDegToRad; }

// ---- hand-written decks -------------------------------------------------------------------------
// A one-stage vehicle. Every card below is punched by hand in its columns: header cards 4I3
// (data block, first word, last word, stage code), 12A6 text, 24I1 options, I3 integers, E12.8
// numbers (six 12-column fields per card), tables "blank, x, y, ..., 1.0E10" (block 40) and the
// time/value pairs of blocks 30 and 38, stage codes in columns 10-12.
const char* const kTitleCards = R"(  1  1 12     MAIN HEADING
CARD TEST VEHICLE, ONE STAGE
  3  1  2     DATE
1966-07-01
)";

const char* const kVehicleCards = R"(  5  1  2     STAGE SEQUENCE
  1  0
  6  1  2     ADJUSTABLE PARAMETERS
  1  6
  8  1  2     CONSTRAINTS: ONE, THE PAYOFF (PAYLOAD)
  1  0
  9  1  4     OUTPUT FREQUENCY OF STAGE 1
  2  3  1  1
 16  1  2
         10.         30.
 20  1  2
          2.      2373.5
 21  1  6
         10.      -75.48         37.          0.        100.         90.
 27  6  6     WEIGHT OF ADJUSTABLE PARAMETER CODE 6 (BY CODE NUMBER)
          2.
 30  1  6  1  THRUST, STAGE 1
          0.      10000.          5.      10000.         10.      10000.
 38  1  6  1
          0.       1000.          5.        500.         10.          0.
 39  1  3  1
        200.         1.5          .5
 40  1  6     THETA TABLE: BLANK, TIME, THETA, ..., 1.0E10
                      0.         90.         10.         60.      1.0E10
)";

// 6D data (blocks 33-37) in the optimization data, for the dispersion group.
const char* const kBodyCards = R"( 33  1 16
         1.2          1.          1.         .35          .5          .5
        842.        548.        296.       .0011        600.          1.
          1.          1.          1.     3.33333
 34  1  6
                      0.          .3         10.         .08      1.0E10
 35  1  6
                      0.         -8.         10.        -2.6      1.0E10
 36  1  6
                      0.      -1.815         10.       -.484      1.0E10
 37  1  6  1
                      0.        515.         10.        480.      1.0E10
 37  1  6  2
                      0.        330.         38.        300.      1.0E10
 37  1  6  3
                      0.        190.         36.        175.      1.0E10
)";

std::string options_card(const std::string& digits) {
  return "  4  1 24     OPTIONS IP(1..24)\n" + digits + "\n";
}

// The deck: title, options, vehicle (and extra optimization cards), the blank card, the optional
// groups (each with its blank card), the 999 card.
std::string deck_text(const std::string& options = "001000000000001000000000", const std::string& extra = "",
                      const std::string& groups = "") {
  return std::string(kTitleCards) + options_card(options) + kVehicleCards + extra + "\n" + groups + "999\n";
}

struct Parsed {
  bool ok = false;
  Deck deck;
  DeckError error;
};

Parsed parse(const std::string& text, const std::string& name = "test.dat") {
  Parsed parsed;
  parsed.ok = ground::parse_card_deck(text, name, &parsed.deck, &parsed.error);
  return parsed;
}

// A deck that must be rejected; returns its message.
std::string rejection(const std::string& text) {
  const Parsed parsed = parse(text);
  EXPECT_FALSE(parsed.ok) << "the deck was accepted";
  EXPECT_TRUE(parsed.error.card_deck);
  return parsed.error.to_string();
}

std::string edited(const std::string& text, const std::string& from, const std::string& to) {
  return replaced(text, from, to);
}

// ---- every format type --------------------------------------------------------------------------

TEST(CardDeck, ReadsEveryFormatTypeIntoTheMission) {
  const Parsed parsed = parse(deck_text());
  ASSERT_TRUE(parsed.ok) << parsed.error.to_string();
  ASSERT_EQ(parsed.deck.cases.size(), 1u);
  EXPECT_EQ(parsed.deck.format, DeckFormat::kCards);
  const Mission& m = *parsed.deck.cases[0].mission;
  const ground::DeckListingOptions& listing = parsed.deck.cases[0].extras.listing;
  // 12A6 and 2A6 text.
  EXPECT_EQ(listing.title, "CARD TEST VEHICLE, ONE STAGE");
  EXPECT_EQ(listing.date, "1966-07-01");
  // 24I1 options.
  EXPECT_EQ(m.options.ip[3], 1);
  EXPECT_EQ(m.options.ip[15], 1);
  EXPECT_EQ(m.options.ip[1], 0);
  // 11I3 sequence (ended by 0), 12I3 adjustable parameters, 14I3 constraints, 40I3 output frequency.
  ASSERT_EQ(m.vehicle.sequence.count, 1);
  EXPECT_EQ(m.vehicle.sequence.codes[0], 1);
  ASSERT_EQ(m.adjustable.count, 1);
  EXPECT_EQ(m.adjustable.codes[0], 6);
  EXPECT_EQ(m.adjustable.weights[0], 2.0);
  EXPECT_EQ(m.constraints.count, 1);
  EXPECT_EQ(m.constraints.codes[0], 0);
  EXPECT_EQ(listing.output.initial[0], 2);
  EXPECT_EQ(listing.output.intermediate[0], 3);
  EXPECT_EQ(listing.output.final_trajectory[0], 1);
  EXPECT_EQ(listing.output.initial[1], 1);  // stages not given keep every point
  // E12.8 words, converted to the core's units.
  const StageData& stage = m.vehicle.stages[0];
  EXPECT_EQ(stage.duration_s, 10.0);
  EXPECT_EQ(stage.integration_steps, 30);
  EXPECT_EQ(stage.jettison_weight_lb, 200.0);
  EXPECT_EQ(stage.reference_area_ft2, 1.5);
  EXPECT_EQ(stage.nozzle_exit_area_ft2, 0.5);
  EXPECT_EQ(m.launch.liftoff_duration_s, 2.0);
  EXPECT_EQ(m.launch.launch_space_age_date_days, 2373.5);
  EXPECT_EQ(m.launch.altitude_ft, 10.0);
  EXPECT_EQ(m.launch.longitude_rad, deg(-75.48));
  EXPECT_EQ(m.launch.geocentric_latitude_rad, deg(37.0));
  EXPECT_EQ(m.launch.azimuth_rad, deg(100.0));
  EXPECT_EQ(m.launch.flight_path_angle_rad, deg(90.0));
  EXPECT_EQ(m.vehicle.payload_lb, 0.0);  // no block 15: the payload rides in the jettison weight
  // Time/value pairs (blocks 30, 38) with a stage code.
  ASSERT_EQ(stage.vacuum_thrust_lbf.size(), 3);
  EXPECT_EQ(stage.vacuum_thrust_lbf.x(2), 10.0);
  EXPECT_EQ(stage.vacuum_thrust_lbf.y(1), 10000.0);
  ASSERT_EQ(stage.consumable_weight_lb.size(), 3);
  EXPECT_EQ(stage.consumable_weight_lb.y(1), 500.0);
  // Blank, x, y, ..., 1.0E10 (block 40), theta in degrees -> rad.
  ASSERT_EQ(m.pitch_program_rad.size(), 2);
  EXPECT_EQ(m.pitch_program_rad.x(1), 10.0);
  EXPECT_EQ(m.pitch_program_rad.y(1), deg(60.0));
  // Nominal constants stay when block 10 is not punched.
  EXPECT_EQ(m.constants.g0_ft_s2, Constants{}.g0_ft_s2);
}

TEST(CardDeck, HandWrittenDeckFlies) {
  ScratchDirectory scratch("card_flies");
  const std::string path = (scratch / "one_stage.dat").string();
  std::ofstream(path) << deck_text();
  const CommandResult result = run_tolip_executable({"simulate", path, "--json"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json document = nlohmann::json::parse(result.out);
  EXPECT_EQ(document["status"], "kOk");
  EXPECT_EQ(document["title"], "CARD TEST VEHICLE, ONE STAGE");
  EXPECT_GT(document["burnout"]["altitude_ft"].get<double>(), 10000.0);
}

TEST(CardDeck, ConstantsPatchedWordByWord) {
  // The manual's example: header "10 2 4" puts the next card's first three fields in CT1(2)-CT1(4).
  const Parsed parsed = parse(deck_text("001000000000001000000000",
                                        " 10  2  4\n  1.40774E16   20925700.   1716.5\n"
                                        " 12  3  3\n     390.001\n"));
  ASSERT_TRUE(parsed.ok) << parsed.error.to_string();
  const Mission& m = *parsed.deck.cases[0].mission;
  EXPECT_EQ(m.constants.gravitational_parameter_ft3_s2, 1.40774e16);
  EXPECT_EQ(m.constants.earth_equatorial_radius_ft, 20925700.0);
  EXPECT_EQ(m.constants.gas_constant_ft2_s2_R, 1716.5);
  EXPECT_EQ(m.constants.earth_rotation_rate_rad_s, Constants{}.earth_rotation_rate_rad_s);
  EXPECT_EQ(m.atmosphere.base_molecular_temperature_R[2], 390.001);
  EXPECT_EQ(m.atmosphere.base_molecular_temperature_R[1], AtmosphereTable{}.base_molecular_temperature_R[1]);
}

// Issue 17: CT1 word 12 = 0 is the spherical Earth (docs/deck-format.md, data block 10), read
// and validated like the TOML deck's `inverse_flattening = 0`; 1 or a negative value stay errors.
TEST(CardDeck, Sec4Earth_InverseFlatteningZeroInCt1Word12IsTheSphere) {
  const Parsed parsed =
      parse(deck_text("001000000000001000000000", " 10 12 12     SPHERICAL EARTH\n          0.\n"));
  ASSERT_TRUE(parsed.ok) << parsed.error.to_string();
  const Mission& m = *parsed.deck.cases[0].mission;
  EXPECT_EQ(m.constants.inverse_flattening, 0.0);
  EXPECT_EQ(validate_mission(m, nullptr), Status::kOk);
  const Parsed one = parse(deck_text("001000000000001000000000", " 10 12 12\n          1.\n"));
  ASSERT_FALSE(one.ok);
  EXPECT_NE(one.error.to_string().find("or 0 for a spherical Earth"), std::string::npos)
      << one.error.to_string();
}

TEST(CardDeck, FortranNumberFormsAreRead) {
  // Blanks around a number, a leading point, exponents with E, D or only a sign (FORTRAN E input).
  const Parsed parsed =
      parse(deck_text("001000000000001000000000", " 21  1  3\n1.0E1       -.7548D2    +3.7+1\n"));
  ASSERT_TRUE(parsed.ok) << parsed.error.to_string();
  const Mission& m = *parsed.deck.cases[0].mission;
  EXPECT_EQ(m.launch.altitude_ft, 10.0);
  EXPECT_EQ(m.launch.longitude_rad, deg(-75.48));
  EXPECT_EQ(m.launch.geocentric_latitude_rad, deg(37.0));
}

// ---- successive cases ---------------------------------------------------------------------------

TEST(CardDeck, SuccessiveCasesGiveOnlyTheChangedWords) {
  const std::string text = std::string(kTitleCards) + options_card("001000000000001000000000") +
                           kVehicleCards +
                           "\n"
                           "  2  1 12\n"
                           "SECOND CASE: AZIMUTH 95, ONE THRUST LEVEL\n"
                           " 21  5  5\n"
                           "         95.\n"
                           " 30  1  4  1\n"
                           "          0.      12000.         10.      12000.\n"
                           "\n"
                           " 20  1  1\n"
                           "         2.5\n"
                           "\n"
                           "999\n";
  const Parsed parsed = parse(text);
  ASSERT_TRUE(parsed.ok) << parsed.error.to_string();
  ASSERT_EQ(parsed.deck.cases.size(), 3u);
  const Mission& first = *parsed.deck.cases[0].mission;
  const Mission& second = *parsed.deck.cases[1].mission;
  const Mission& third = *parsed.deck.cases[2].mission;
  EXPECT_EQ(parsed.deck.cases[1].number, 2);
  EXPECT_EQ(parsed.deck.cases[1].first_card, 32);
  // Case 1 as punched.
  EXPECT_EQ(first.launch.azimuth_rad, deg(100.0));
  EXPECT_EQ(first.vehicle.stages[0].vacuum_thrust_lbf.size(), 3);
  const ground::DeckListingOptions& first_listing = parsed.deck.cases[0].extras.listing;
  const ground::DeckListingOptions& second_listing = parsed.deck.cases[1].extras.listing;
  EXPECT_EQ(first_listing.case_heading, "");
  // Case 2: the changed words, everything else from case 1; a re-input table replaces the old one.
  EXPECT_EQ(second_listing.title, first_listing.title);
  EXPECT_EQ(second_listing.case_heading, "SECOND CASE: AZIMUTH 95, ONE THRUST LEVEL");
  EXPECT_EQ(second.launch.azimuth_rad, deg(95.0));
  EXPECT_EQ(second.launch.altitude_ft, first.launch.altitude_ft);
  ASSERT_EQ(second.vehicle.stages[0].vacuum_thrust_lbf.size(), 2);
  EXPECT_EQ(second.vehicle.stages[0].vacuum_thrust_lbf.y(1), 12000.0);
  EXPECT_EQ(second.vehicle.stages[0].consumable_weight_lb.size(), 3);
  // Case 3 starts from case 2.
  EXPECT_EQ(third.launch.liftoff_duration_s, 2.5);
  EXPECT_EQ(third.launch.azimuth_rad, deg(95.0));
  EXPECT_EQ(parsed.deck.cases[2].extras.listing.case_heading, second_listing.case_heading);
}

TEST(CardDeck, SeveralCasesSimulateAsAJsonArray) {
  ScratchDirectory scratch("card_cases");
  const std::string path = (scratch / "cases.dat").string();
  std::ofstream(path) << std::string(kTitleCards) + options_card("001000000000001000000000") + kVehicleCards +
                             "\n 21  5  5\n         95.\n\n999\n";
  const CommandResult result =
      run_tolip_executable({"simulate", path, "--json", "--csv", (scratch / "p.csv").string()});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json documents = nlohmann::json::parse(result.out);
  ASSERT_TRUE(documents.is_array());
  ASSERT_EQ(documents.size(), 2u);
  EXPECT_NEAR(documents[0]["trajectory"][0]["psi_deg"].get<double>(), 100.0, 1e-9);
  EXPECT_NEAR(documents[1]["trajectory"][0]["psi_deg"].get<double>(), 95.0, 1e-9);
  EXPECT_TRUE(std::filesystem::exists(scratch / "p.case1.csv"));
  EXPECT_TRUE(std::filesystem::exists(scratch / "p.case2.csv"));

  const CommandResult listing = run_tolip_executable({"simulate", path});
  ASSERT_EQ(listing.exit_code, 0) << listing.err;
  std::size_t terminal = 0;
  for (std::size_t at = listing.out.find("TERMINAL CONDITIONS"); at != std::string::npos;
       at = listing.out.find("TERMINAL CONDITIONS", at + 1)) {
    ++terminal;
  }
  EXPECT_GE(terminal, 2u) << "one listing per case";
}

// ---- optional groups ----------------------------------------------------------------------------

TEST(CardDeck, RadarGroupFollowsTheBlankCard) {
  const std::string radar =
      " 41        2  RADAR: 2 STATION CARDS\n"
      "WALLOPS            37.86      -75.51         40. Wallops Island, VA\n"
      "BERMUDA            32.35      -64.66         60.\n"
      "\n";
  const Parsed parsed = parse(deck_text("001000000000001000000001", "", radar));
  ASSERT_TRUE(parsed.ok) << parsed.error.to_string();
  const DeckExtras& x = parsed.deck.cases[0].extras;
  ASSERT_EQ(x.radar_stations.size(), 2u);
  EXPECT_EQ(x.radar_stations[0].id, "WALLOPS");
  EXPECT_EQ(x.radar_stations[0].name, "Wallops Island, VA");
  EXPECT_EQ(x.radar_stations[0].geodetic_latitude_rad, deg(37.86));
  EXPECT_EQ(x.radar_stations[1].longitude_rad, deg(-64.66));
  EXPECT_EQ(x.radar_stations[1].altitude_ft, 60.0);
  EXPECT_EQ(x.radar_stations[1].name, "");
}

TEST(CardDeck, ImpactGroupWithItsBlock33WordsAndExtensions) {
  const std::string impact =
      " 42  1  8  1\n"
      "                      0.         .45          1.          .7          5.\n"
      "         .46      1.0E10\n"
      " 43  1  8  1\n"
      "                      0.         8.5          1.         11.          5.\n"
      "          9.      1.0E10\n"
      " 23  1  3  1  EXTENSION: AREAS AND CASING WEIGHT\n"
      "          9.         10.       4500.\n"
      " 33 17 19\n"
      "  3.  2.  2.\n"
      "\n";
  // The last card of block 33 packs its numbers: E12.8 fields are 12 columns wide.
  const std::string fixed_impact = edited(impact, "  3.  2.  2.", "          3.          2.          2.");
  const Parsed parsed = parse(deck_text("001000000000001000000010", "", fixed_impact));
  ASSERT_TRUE(parsed.ok) << parsed.error.to_string();
  const DeckExtras& x = parsed.deck.cases[0].extras;
  ASSERT_TRUE(x.impact.present);
  ASSERT_TRUE(x.impact.failure_mode[0].present);
  EXPECT_EQ(x.impact.failure_mode[0].cd_vs_mach.x, (std::vector<double>{0.0, 1.0, 5.0}));
  EXPECT_EQ(x.impact.failure_mode[0].cd_vs_mach.y, (std::vector<double>{0.45, 0.7, 0.46}));
  EXPECT_EQ(x.impact.failure_mode[0].reference_area_ft2, 9.0);
  EXPECT_EQ(x.impact.expended_casing[0].reference_area_ft2, 10.0);
  EXPECT_EQ(x.impact.expended_casing[0].casing_weight_lb, 4500.0);
  EXPECT_EQ(x.body_dynamics.impact_every_nth_step, (std::array<int, 3>{3, 2, 2}));
  // The same numbers packed into 4 columns are not 12-column fields: the reader says so.
  const std::string message = rejection(deck_text("001000000000001000000010", "", impact));
  EXPECT_TRUE(contains(message, "data block 33")) << message;
  EXPECT_TRUE(contains(message, "columns 1-12")) << message;
}

TEST(CardDeck, HardoverGroupWithBlocks44And45) {
  const std::string hardover =
      " 44  1  6  1  IYY STAGE 1\n"
      "                      0.     300000.         10.     150000.      1.0E10\n"
      " 44  1  6  4  CMQ (STAGE CODE 4)\n"
      "                      0.        -30.          5.        -20.      1.0E10\n"
      " 45  1 26\n"
      "          2.       3000.          2.          .1         .01        100.\n"
      "         .25          .1          .1        800.          5.        150.\n"
      "        100.        100.         70.        400.        200.        450.\n"
      "        250.          .5          3.          3.          3.          .2\n"
      "         .01        100.\n"
      " 33  7 16\n"
      "        842.        548.        296.       .0011        600.          1.\n"
      "          1.          1.          1.     3.33333\n"
      " 37  1  6  1\n"
      "                      0.        515.         10.        480.      1.0E10\n"
      " 37  1  6  2\n"
      "                      0.        330.         38.        300.      1.0E10\n"
      " 37  1  6  3\n"
      "                      0.        190.         36.        175.      1.0E10\n"
      "\n";
  const Parsed parsed = parse(deck_text("001000000000001000000100", "", hardover));
  ASSERT_TRUE(parsed.ok) << parsed.error.to_string();
  const DeckExtras& x = parsed.deck.cases[0].extras;
  ASSERT_TRUE(x.hardover.present);
  EXPECT_EQ(x.hardover.pitch_inertia_slug_ft2[0].y, (std::vector<double>{300000.0, 150000.0}));
  EXPECT_EQ(x.hardover.stage1_pitch_damping_per_rad.y, (std::vector<double>{-30.0, -20.0}));
  EXPECT_EQ(x.hardover.stage1_every_nth_step, 2);
  EXPECT_EQ(x.hardover.max_qbar_alpha_lb_rad_ft2, 3000.0 * kDegToRad);
  EXPECT_EQ(x.hardover.upper_max_steps_per_turn, 100);
  EXPECT_EQ(x.hardover.stage3_every_nth_step, 3);
  ASSERT_TRUE(x.body_dynamics.present);
  const BodyDynamicsBlocks& body = parsed.deck.cases[0].mission->body_dynamics;  // stations in ft
  EXPECT_DOUBLE_EQ(body.control_station_ft[0], 842.0 / 12.0);
  EXPECT_DOUBLE_EQ(body.control_station_ft[1], 548.0 / 12.0);
  EXPECT_DOUBLE_EQ(body.control_station_ft[2], 296.0 / 12.0);
  EXPECT_EQ(body.reference_length_ft, 3.33333);
  ASSERT_EQ(body.cg_station_ft[2].size(), 2);
  EXPECT_DOUBLE_EQ(body.cg_station_ft[2].y(0), 190.0 / 12.0);
  EXPECT_DOUBLE_EQ(body.cg_station_ft[2].y(1), 175.0 / 12.0);
}

TEST(CardDeck, DispersionGroupEntriesStartWithBlock46) {
  const std::string dispersion =
      " 46        9  BLANK RANGE: THE WHOLE TITLE\n"
      "WEIGHT HI S1\n"
      " 47  1  1  1\n"
      "        150.\n"
      " 46  1  2 17\n"
      "DRAG HIGH\n"
      " 48  1  1\n"
      "         .15\n"
      " 46  1  2 36\n"
      "WINDS HIGH\n"
      " 53  1  6\n"
      "                      0.         25.      40000.        250.      1.0E10\n"
      " 54  1  6\n"
      "                      0.        280.     250000.        280.      1.0E10\n"
      " 46  1  2 40\n"
      "NOMINAL TRAJ\n"
      "\n";
  const Parsed parsed = parse(deck_text("001000000000001000001000", kBodyCards, dispersion));
  ASSERT_TRUE(parsed.ok) << parsed.error.to_string();
  const DeckExtras& x = parsed.deck.cases[0].extras;
  ASSERT_EQ(x.dispersions.size(), 4u);
  EXPECT_EQ(x.dispersions[0].code, 9);
  EXPECT_EQ(x.dispersions[0].title, "WEIGHT HI S1");
  EXPECT_EQ(x.dispersions[0].weight_increment_lb, 150.0);
  EXPECT_EQ(x.dispersions[0].stage, 1);
  EXPECT_EQ(x.dispersions[1].drag_variation_fraction, 0.15);
  EXPECT_EQ(x.dispersions[2].wind_speed_ft_s.y, (std::vector<double>{25.0, 250.0}));
  EXPECT_EQ(x.dispersions[2].wind_azimuth_rad.y[1], deg(280.0));
  EXPECT_EQ(x.dispersions[3].code, 40);
  EXPECT_EQ(x.dispersions[3].title, "NOMINAL TRAJ");
  const BodyDynamicsBlocks& body = parsed.deck.cases[0].mission->body_dynamics;
  EXPECT_EQ(body.position_gain[0], 1.2);
  EXPECT_EQ(body.position_gain[1], 1.0);
  EXPECT_EQ(body.position_gain[2], 1.0);
  ASSERT_EQ(body.pitching_moment_per_rad.size(), 2);
  EXPECT_EQ(body.pitching_moment_per_rad.y(0), -8.0);
  EXPECT_EQ(body.pitching_moment_per_rad.y(1), -2.6);
}

TEST(CardDeck, GroupsAreReadInTheManualsOrderAndAfreshPerCase) {
  const std::string radar = " 41        1\nWALLOPS            37.86      -75.51         40.\n\n";
  const std::string impact =
      " 42  1  6  1\n                      0.         .45          5.         .46      1.0E10\n"
      " 43  1  6  1\n                      0.         8.5          5.          9.      1.0E10\n"
      " 33 17 19\n          3.          2.          2.\n\n";
  // Impact (IP(23)) comes before radar (IP(24)); the second case repeats both groups, with one
  // station only this time.
  const std::string radar2 = " 41        1\nBERMUDA            32.35      -64.66         60.\n\n";
  const std::string text = std::string(kTitleCards) + options_card("001000000000001000000011") +
                           kVehicleCards + "\n" + impact + radar + " 21  5  5\n         95.\n\n" + impact +
                           radar2 + "999\n";
  const Parsed parsed = parse(text);
  ASSERT_TRUE(parsed.ok) << parsed.error.to_string();
  ASSERT_EQ(parsed.deck.cases.size(), 2u);
  ASSERT_EQ(parsed.deck.cases[0].extras.radar_stations.size(), 1u);
  ASSERT_EQ(parsed.deck.cases[1].extras.radar_stations.size(), 1u);
  EXPECT_EQ(parsed.deck.cases[1].extras.radar_stations[0].id, "BERMUDA");
  EXPECT_TRUE(parsed.deck.cases[1].extras.impact.present);
  // Radar before impact is out of the manual's order.
  const std::string swapped = std::string(kTitleCards) + options_card("001000000000001000000011") +
                              kVehicleCards + "\n" + radar + impact + "999\n";
  const std::string message = rejection(swapped);
  EXPECT_TRUE(contains(message,
                       "data block 41 (RADAR STATION LOCATIONS) belongs to the radar data (IP(24)), not to "
                       "the impact data (IP(23))"))
      << message;
}

// ---- malformed decks ----------------------------------------------------------------------------

TEST(CardDeckErrors, LetterInANumericField) {
  const std::string message =
      rejection(edited(deck_text(), "        100.         90.", "        1O0.         90."));
  EXPECT_EQ(message,
            "test.dat: card 20, columns 49-60: case 1, data block 21, word 5: letter 'O' in a numeric field: "
            "'1O0.' is "
            "not an E12.8 number such as 1.5, -.25 or 1.0E10 (data card 1 of 1 for the header on card 19, "
            "words 1-6)");
}

TEST(CardDeckErrors, LetterInAnIntegerField) {
  const std::string message = rejection(edited(deck_text(), "  2  3  1  1", "  2  X  1  1"));
  EXPECT_TRUE(
      contains(message, "card 14, columns 4-6: case 1, data block 9, word 2: letter 'X' in a numeric field"))
      << message;
}

// Sec. 22, data block 27: DA12(1)...DA12(11) weight the adjustable parameters "identified by code
// number as listed for Data Block 6": word k weights code k, unused words blank or zero.
TEST(CardDeck, Sec22_Block27WeightsAreByCodeNumber) {
  // Codes 1 and 3 (stage-4 theta, coast after stage 3) with the manual's layout: DA12(1), DA12(3).
  const std::string scout = read_text_file(example_path("scout/mission.dat"));
  ASSERT_TRUE(contains(scout,
                       " 27  1  1     OPTIMIZATION PARAMETER WEIGHTS DA12\n         10.\n"
                       " 27  3  3     OPTIMIZATION PARAMETER WEIGHTS DA12\n       .0001\n"));
  const Parsed manual = parse(scout);
  ASSERT_TRUE(manual.ok) << manual.error.to_string();
  const AdjustableParameters& a = manual.deck.cases[0].mission->adjustable;
  ASSERT_EQ(a.count, 2);
  EXPECT_EQ(a.codes[0], 1);
  EXPECT_EQ(a.weights[0], 10.0);
  EXPECT_EQ(a.codes[1], 3);
  EXPECT_EQ(a.weights[1], 1e-4);
  // One card with the unused word 2 blank is the same deck.
  const Parsed blank_word =
      parse(replaced(scout,
                     " 27  1  1     OPTIMIZATION PARAMETER WEIGHTS DA12\n         10.\n"
                     " 27  3  3     OPTIMIZATION PARAMETER WEIGHTS DA12\n       .0001\n",
                     " 27  1  3\n         10.                   .0001\n"));
  ASSERT_TRUE(blank_word.ok) << blank_word.error.to_string();
  EXPECT_EQ(blank_word.deck.cases[0].mission->adjustable.weights[1], 1e-4);

  // The positional layout (weights in block 6's order, as tolip 0.1.0's convert wrote them) puts a
  // weight in the word of code 2, which block 6 does not select: rejected, naming the word.
  const std::string positional = replaced(scout,
                                          " 27  1  1     OPTIMIZATION PARAMETER WEIGHTS DA12\n         10.\n"
                                          " 27  3  3     OPTIMIZATION PARAMETER WEIGHTS DA12\n       .0001\n",
                                          " 27  1  2\n         10.       .0001\n");
  const std::string message = rejection(positional);
  EXPECT_TRUE(contains(message,
                       "data block 27, word 2: DA12(2) = 1e-04 weights adjustable parameter code 2, which "
                       "data block 6 does not select: block 27 words are by code number"))
      << message;
}

TEST(CardDeckErrors, UnknownAndUndefinedBlocks) {
  EXPECT_TRUE(contains(rejection(edited(deck_text(), " 27  6  6 ", " 57  1  1 ")),
                       "card 21, columns 1-3: case 1, data block 57: unknown data block 57: expected 1-55"));
  EXPECT_TRUE(contains(rejection(edited(deck_text(), " 27  6  6 ", "  7  1  1 ")),
                       "data block 7 is not defined in the manual (blocks 7, 24 and 25 are not used)"));
  const std::string message = rejection(edited(deck_text(), " 27  6  6 ", " 45  1  1 "));
  EXPECT_TRUE(contains(message,
                       "data block 45 (HARDOVER DATA) belongs to the hardover data (IP(22)), not to the "
                       "optimization data"))
      << message;
}

TEST(CardDeckErrors, MissingThe999Card) {
  std::string text = deck_text();
  text.resize(text.size() - 4);  // "999\n"
  EXPECT_EQ(rejection(text),
            "test.dat: card 31: the deck ends without the 999 card: expected a card with 999 in columns 1-3 "
            "after the "
            "blank card ending the last case (case 1)");
  std::string no_blank = deck_text();
  no_blank.replace(no_blank.size() - 5, 1, "");  // the blank card before 999
  EXPECT_TRUE(
      contains(rejection(no_blank), "999 card inside case 1: the case's data must be ended by a blank card"));
}

TEST(CardDeckErrors, HeaderRangeBeyondTheBlock) {
  EXPECT_EQ(rejection(edited(deck_text(), " 21  1  6\n", " 21  1  8\n")),
            "test.dat: card 19, columns 7-9: case 1, data block 21, word 8: header range beyond the block: "
            "words 1-8 "
            "asked but data block 21 has 6 words");
  EXPECT_TRUE(contains(rejection(edited(deck_text(), " 39  1  3  1\n", " 39  1  3  6\n")),
                       "data block 39 (stage code 6) has 2 words"));
  EXPECT_TRUE(
      contains(rejection(edited(deck_text(), " 21  1  6\n", " 21  4  2\n")),
               "columns 7-9: case 1, data block 21: header card: the last word to fill (columns 7-9) is 2, "
               "before the first word 4"));
}

TEST(CardDeckErrors, ShortCards) {
  // A data block short of a data card: the next header is read as data, and said to look like one.
  const std::string short_block =
      edited(deck_text(), " 16  1  2\n         10.         30.\n", " 16  1  8\n         10.         30.\n");
  const std::string message = rejection(short_block);
  EXPECT_TRUE(contains(message, "card 17, columns 1-12: case 1, data block 16, word 7")) << message;
  EXPECT_TRUE(contains(message,
                       "(data card 2 of 2 for the header on card 15, words 1-8); card 17 looks like a header "
                       "card: is the data block short of data cards?"))
      << message;
  // A short line whose integer field is cut: FORTRAN would read "1 " as 10.
  EXPECT_TRUE(
      contains(rejection(edited(deck_text(), "\n  1  0\n  6", "\n  1 0\n  6")),
               "card 8, columns 4-6: case 1, data block 5, word 2: integer ' 0 ' is not right-justified"));
  // The deck ends inside a block.
  const std::string cut = std::string(kTitleCards) + " 16  1  8\n         10.\n";
  EXPECT_TRUE(contains(rejection(cut),
                       "the deck ends inside data block 16: the header on card 5 asks for words 1-8, "
                       "2 data cards; found 1"));
}

TEST(CardDeckErrors, CardFormMistakes) {
  EXPECT_TRUE(contains(
      rejection(edited(deck_text(), "          2.      2373.5", "          2       2373.5")),
      "'2' has no decimal point: in an E12.8 field FORTRAN scales such a number by 1.0E-8; write '2.'"));
  EXPECT_TRUE(contains(rejection(edited(deck_text(), "          2.      2373.5", "          2.      23 3.5")),
                       "columns 13-24: case 1, data block 20, word 2: blank inside the number '23 3.5'"));
  EXPECT_TRUE(contains(rejection(edited(deck_text(), "          2.      2373.5",
                                        "          2.      2373.5" + std::string(60, '-'))),
                       "card 18, columns 81-84: case 1: card has 84 columns: a card has at most 80"));
  EXPECT_TRUE(contains(rejection(edited(deck_text(), "          2.      2373.5", "\t2.      2373.5")),
                       "card 18, column 1: case 1: tab character"));
  EXPECT_TRUE(contains(
      rejection(edited(deck_text(), " 30  1  6  1", " 30  1  6   ")),
      "data block 30 (VACUUM THRUST TABLE) needs a stage code in columns 10-12: expected 1-5, got blank"));
  EXPECT_TRUE(contains(rejection(edited(deck_text(), " 21  1  6\n", " 21  1  6  2\n")),
                       "data block 21 takes no stage code: columns 10-12 must be blank, got 2"));
  EXPECT_TRUE(
      contains(rejection(edited(deck_text(), " 30  1  6  1", " 30  3  6  1")),
               "data block 30 is input complete (the manual: the entire table for the given stage must be "
               "re-input to change it): the first word must be 1, got 3"));
  EXPECT_TRUE(contains(rejection(edited(deck_text(), "60.      1.0E10", "60.         20.")),
                       "data block 40, word 7: word 7 not given: the ordinate paired with word 6"));
  EXPECT_TRUE(contains(rejection(edited(deck_text(), " 40  1  6", " 40  1  4")),
                       "data block 40, word 5: word 5 not given: the ordinate paired with word 4"));
  std::string full_table = " 40  1 32\n";
  for (int w = 1; w <= 32; ++w) {
    char field[16];
    std::snprintf(field, sizeof field, "%11d.", w == 1 ? 0 : w);
    full_table += field;
    if (w % 6 == 0 || w == 32) full_table += "\n";
  }
  EXPECT_TRUE(
      contains(rejection(deck_text("001000000000001000000000", full_table)),
               "data block 40, word 32: abscissa in the block's last word: no room for its ordinate and the "
               "1.0E10 terminator"));
  EXPECT_TRUE(
      contains(rejection(edited(deck_text(), "                      0.         90.",
                                "          3.          0.         90.")),
               "card 30, columns 1-12: case 1, data block 40, word 1: word 1 of the table must be blank"));
  EXPECT_TRUE(contains(rejection(edited(deck_text(), "001000000000001000000000", "001100000000001000000000")),
                       "card 6, column 4: case 1, data block 4, word 4: IP(4) is not used by the manual"));
  EXPECT_TRUE(contains(rejection(std::string(kTitleCards) + options_card("001000000000001000000000") +
                                 kVehicleCards + "\n\n999\n"),
                       "blank card where case 2 should start"));
}

TEST(CardDeckErrors, TomlReaderChecksComeBackOnTheCard) {
  // A non-monotonic table: the TOML reader's check, located on the word's card and columns.
  EXPECT_EQ(
      rejection(edited(deck_text(), "          0.      10000.          5.      10000.",
                       "          0.      10000.          0.      10000.")),
      "test.dat: card 24, columns 25-36: case 1, data block 30, stage code 1, word 3: table not monotonic: "
      "time_s[1] = 0 is not greater than time_s[0] = 0; expected strictly increasing stage time in s");
  // A fault validate_mission finds: the stage duration against the thrust table.
  EXPECT_EQ(rejection(edited(deck_text(), "         10.         30.", "         12.         30.")),
            "test.dat: card 16, columns 1-12: case 1, data block 16, word 1: kStageDurationMismatch: a "
            "powered stage "
            "duration differs from the last time of its thrust table; stage 1 duration_s = 12 s but its "
            "thrust table "
            "ends at 10 s; expected them equal within CT1(10) = 0.02 s");
  // A word the TOML reader requires but the deck does not punch.
  EXPECT_EQ(
      rejection(edited(deck_text(),
                       " 21  1  6\n         10.      -75.48         37.          0.        100.         90.",
                       " 21  1  4\n         10.      -75.48         37.          0.")),
      "test.dat: card 19: case 1, data block 21, word 5: word 5 not punched: missing required key "
      "'azimuth_deg' in "
      "[launch]: expected a number (DA6(5) launch azimuth, deg east of north)");
  // A missing stage table.
  const std::string message = rejection(
      edited(deck_text(),
             " 38  1  6  1\n          0.       1000.          5.        500.         10.          0.\n", ""));
  EXPECT_TRUE(contains(message, "data block 38, stage code 1")) << message;
  EXPECT_TRUE(contains(message, "missing required table [stage.1.consumable_weight]")) << message;
}

TEST(CardDeckErrors, GroupMistakes) {
  const std::string dispersion = " 47  1  1  1\n        150.\n\n";
  EXPECT_TRUE(contains(rejection(deck_text("001000000000001000001000", kBodyCards, dispersion)),
                       "data block 47 before the first data block 46"));
  const std::string wrong_block = " 46  1  2  9\nWEIGHT HI S1\n 48  1  1\n         .15\n\n";
  EXPECT_TRUE(contains(rejection(deck_text("001000000000001000001000", kBodyCards, wrong_block)),
                       "data block 48 is not data of dispersion code 9 (weight increment, block 46 on card"));
  const std::string wrong_stage = " 46  1  2  9\nWEIGHT HI S1\n 47  1  1  2\n        150.\n\n";
  EXPECT_TRUE(
      contains(rejection(deck_text("001000000000001000001000", kBodyCards, wrong_stage)),
               "dispersion code 9 (weight increment) applies to stage 1: expected stage code 1 in columns "
               "10-12, got 2"));
  EXPECT_TRUE(contains(rejection(deck_text("001000000000001000000001")),
                       "999 card where the radar data (IP(24)) of case 1 was expected"));
}

TEST(CardDeckErrors, EmptyAndNonDecks) {
  EXPECT_TRUE(contains(rejection(""), "empty card deck"));
  EXPECT_TRUE(contains(rejection("999\n"), "the 999 card ends the deck before any case"));
  DeckError error;
  EXPECT_FALSE(ground::load_deck("/nonexistent/deck.dat", nullptr, &error));
  EXPECT_TRUE(contains(error.to_string(), "cannot open the deck file"));
}

// ---- recognition by content ---------------------------------------------------------------------

TEST(CardDeck, RecognisedByContent) {
  EXPECT_EQ(ground::detect_deck_format(deck_text()), DeckFormat::kCards);
  EXPECT_EQ(ground::detect_deck_format("\n\n  1  1 12\nTITLE\n"), DeckFormat::kCards);
  EXPECT_EQ(ground::detect_deck_format(scout_mission_text()), DeckFormat::kToml);
  EXPECT_EQ(ground::detect_deck_format("[case]\ntitle = \"x\"\n"), DeckFormat::kToml);
  EXPECT_EQ(ground::detect_deck_format(""), DeckFormat::kToml);
  Deck deck;
  DeckError error;
  ASSERT_TRUE(ground::parse_deck(deck_text(), "x.dat", &deck, &error)) << error.to_string();
  EXPECT_EQ(deck.format, DeckFormat::kCards);
  ASSERT_TRUE(ground::parse_deck(scout_mission_text(), "x.toml", &deck, &error)) << error.to_string();
  EXPECT_EQ(deck.format, DeckFormat::kToml);
  ASSERT_EQ(deck.cases.size(), 1u);
}

// ---- the bundled example and its TOML twin ------------------------------------------------------

void expect_same_table(const ground::DeckTable& a, const ground::DeckTable& b, const std::string& what) {
  EXPECT_EQ(a.x, b.x) << what;
  EXPECT_EQ(a.y, b.y) << what;
}

void expect_same_extras(const DeckExtras& a, const DeckExtras& b) {
  // Blocks 33-37 are the Mission's (compared with fields_of), DA6D(12-15) included; DA6D(17-19)
  // are kept here.
  const ground::BodyDynamicsData& p = a.body_dynamics;
  const ground::BodyDynamicsData& q = b.body_dynamics;
  EXPECT_EQ(p.present, q.present);
  EXPECT_EQ(p.impact_every_nth_step, q.impact_every_nth_step);
  EXPECT_EQ(a.listing.lines_per_page, b.listing.lines_per_page);
  EXPECT_EQ(a.listing.deg_to_rad_as_printed, b.listing.deg_to_rad_as_printed);
  ASSERT_EQ(a.radar_stations.size(), b.radar_stations.size());
  for (std::size_t i = 0; i < a.radar_stations.size(); ++i) {
    EXPECT_EQ(a.radar_stations[i].id, b.radar_stations[i].id);
    EXPECT_EQ(a.radar_stations[i].name, b.radar_stations[i].name);
    EXPECT_EQ(a.radar_stations[i].geodetic_latitude_rad, b.radar_stations[i].geodetic_latitude_rad);
    EXPECT_EQ(a.radar_stations[i].longitude_rad, b.radar_stations[i].longitude_rad);
    EXPECT_EQ(a.radar_stations[i].altitude_ft, b.radar_stations[i].altitude_ft);
  }
  EXPECT_EQ(a.impact.present, b.impact.present);
  for (std::size_t i = 0; i < 3; ++i) {
    for (const auto* pair : {&a.impact.failure_mode, &a.impact.expended_casing}) {
      const auto& mine = (*pair)[i];
      const auto& theirs =
          pair == &a.impact.failure_mode ? b.impact.failure_mode[i] : b.impact.expended_casing[i];
      EXPECT_EQ(mine.present, theirs.present);
      expect_same_table(mine.cd_vs_mach, theirs.cd_vs_mach, "blocks 42-43");
      EXPECT_EQ(mine.reference_area_ft2, theirs.reference_area_ft2);
      EXPECT_EQ(mine.casing_weight_lb, theirs.casing_weight_lb);
    }
  }
  const ground::HardoverData& h = a.hardover;
  const ground::HardoverData& k = b.hardover;
  EXPECT_EQ(h.present, k.present);
  for (std::size_t i = 0; i < 3; ++i)
    expect_same_table(h.pitch_inertia_slug_ft2[i], k.pitch_inertia_slug_ft2[i], "block 44");
  expect_same_table(h.stage1_pitch_damping_per_rad, k.stage1_pitch_damping_per_rad, "block 44 CMQ");
  EXPECT_EQ(h.stage1_every_nth_step, k.stage1_every_nth_step);
  EXPECT_EQ(h.max_qbar_alpha_lb_rad_ft2, k.max_qbar_alpha_lb_rad_ft2);
  EXPECT_EQ(h.stage1_max_attitude_step_rad, k.stage1_max_attitude_step_rad);
  EXPECT_EQ(h.stage1_max_step_s, k.stage1_max_step_s);
  EXPECT_EQ(h.stage1_min_step_s, k.stage1_min_step_s);
  EXPECT_EQ(h.stage1_max_steps_per_turn, k.stage1_max_steps_per_turn);
  EXPECT_EQ(h.thrust_misalignment_rad, k.thrust_misalignment_rad);
  EXPECT_EQ(h.stage1_thrust_station_in, k.stage1_thrust_station_in);
  EXPECT_EQ(h.stage1_fin_vane_deflection_rad, k.stage1_fin_vane_deflection_rad);
  EXPECT_EQ(h.mode_b_jet_force_lb, k.mode_b_jet_force_lb);
  EXPECT_EQ(h.mode_c_jet_force_lb, k.mode_c_jet_force_lb);
  EXPECT_EQ(h.thrust_station_in, k.thrust_station_in);
  EXPECT_EQ(h.control_jet_station_in, k.control_jet_station_in);
  EXPECT_EQ(h.output_interval_s, k.output_interval_s);
  EXPECT_EQ(h.stage2_every_nth_step, k.stage2_every_nth_step);
  EXPECT_EQ(h.stage3_every_nth_step, k.stage3_every_nth_step);
  EXPECT_EQ(h.upper_max_attitude_step_rad, k.upper_max_attitude_step_rad);
  EXPECT_EQ(h.upper_max_step_s, k.upper_max_step_s);
  EXPECT_EQ(h.upper_min_step_s, k.upper_min_step_s);
  EXPECT_EQ(h.upper_max_steps_per_turn, k.upper_max_steps_per_turn);
  ASSERT_EQ(a.dispersions.size(), b.dispersions.size());
  for (std::size_t i = 0; i < a.dispersions.size(); ++i) {
    const ground::DispersionCase& d = a.dispersions[i];
    const ground::DispersionCase& e = b.dispersions[i];
    const std::string what = "dispersion code " + std::to_string(e.code);
    EXPECT_EQ(d.code, e.code);
    EXPECT_EQ(d.stage, e.stage) << what;
    EXPECT_EQ(d.title, e.title) << what;
    expect_same_table(d.vacuum_thrust_lbf, e.vacuum_thrust_lbf, what);
    expect_same_table(d.consumable_weight_lb, e.consumable_weight_lb, what);
    EXPECT_EQ(d.has_stage_durations, e.has_stage_durations) << what;
    EXPECT_EQ(d.stage4_5_durations_s, e.stage4_5_durations_s) << what;
    EXPECT_EQ(d.weight_increment_lb, e.weight_increment_lb) << what;
    EXPECT_EQ(d.drag_variation_fraction, e.drag_variation_fraction) << what;
    expect_same_table(d.pitching_moment_per_rad, e.pitching_moment_per_rad, what);
    EXPECT_EQ(d.misalignment_rad, e.misalignment_rad) << what;
    EXPECT_EQ(d.thrust_station_in, e.thrust_station_in) << what;
    EXPECT_EQ(d.deadband_rad, e.deadband_rad) << what;
    EXPECT_EQ(d.tipoff_rad, e.tipoff_rad) << what;
    EXPECT_EQ(d.launch_change_rad, e.launch_change_rad) << what;
    expect_same_table(d.wind_speed_ft_s, e.wind_speed_ft_s, what);
    expect_same_table(d.wind_azimuth_rad, e.wind_azimuth_rad, what);
  }
}

// Every field of a mission, as the exact hexadecimal literals mission_cpp_source writes, and the
// listing data beside it (blocks 1-3 in the source, block 9 appended).
std::string fields_of(const Mission& mission, const ground::DeckListingOptions& listing) {
  std::string fields = ground::mission_cpp_source(mission, listing, "f", "deck");
  for (const auto* every :
       {&listing.output.initial, &listing.output.intermediate, &listing.output.final_trajectory}) {
    for (const int n : *every) fields += " " + std::to_string(n);
  }
  return fields;
}
std::string fields_of(const ground::DeckCase& deck_case) {
  return fields_of(*deck_case.mission, deck_case.extras.listing);
}

TEST(CardDeck, ScoutExampleLoadsToTheSameCaseAsItsTomlTwin) {
  Deck cards;
  DeckError error;
  ASSERT_TRUE(ground::load_deck(example_path("scout/mission.dat"), &cards, &error)) << error.to_string();
  ASSERT_EQ(cards.format, DeckFormat::kCards);
  ASSERT_EQ(cards.cases.size(), 1u);
  auto toml = ground::make_mission();
  DeckExtras toml_extras;
  ASSERT_TRUE(ground::load_toml_deck(example_path("scout/mission.toml"), toml.get(), &toml_extras, &error))
      << error.to_string();
  Mission card = *cards.cases[0].mission;
  // The only words an E12.8 field cannot hold exactly: the 1 deg and 0.05 deg deadbands of the
  // inertial flight-path angle in radians (0.0174532925199 has 12 significant digits).
  for (int i = 0; i < kMaxConstraints; ++i) {
    EXPECT_NEAR(card.constraints.deadband_optimization[i], toml->constraints.deadband_optimization[i],
                1e-10 * std::abs(toml->constraints.deadband_optimization[i]));
    EXPECT_NEAR(card.constraints.deadband_linearization[i], toml->constraints.deadband_linearization[i],
                1e-8 * std::abs(toml->constraints.deadband_linearization[i]));
    card.constraints.deadband_optimization[i] = toml->constraints.deadband_optimization[i];
    card.constraints.deadband_linearization[i] = toml->constraints.deadband_linearization[i];
  }
  EXPECT_EQ(fields_of(card, cards.cases[0].extras.listing), fields_of(*toml, toml_extras.listing));
  expect_same_extras(cards.cases[0].extras, toml_extras);
}

TEST(CardDeck, ScoutExampleSimulatesLikeItsTomlTwin) {
  const CommandResult cards = run_tolip_executable({"simulate", example_path("scout/mission.dat"), "--json"});
  const CommandResult toml = run_tolip_executable({"simulate", example_path("scout/mission.toml"), "--json"});
  ASSERT_EQ(cards.exit_code, 0) << cards.err;
  ASSERT_EQ(toml.exit_code, 0) << toml.err;
  nlohmann::json a = nlohmann::json::parse(cards.out);
  nlohmann::json b = nlohmann::json::parse(toml.out);
  a.erase("deck");
  b.erase("deck");
  // A deadband of 1 deg in radians has more digits than a card field holds (12 columns): the same
  // within 1e-10, as the decks' own comparison allows.
  ASSERT_EQ(a["constraints"].size(), b["constraints"].size());
  for (std::size_t i = 0; i < a["constraints"].size(); ++i) {
    const double ta = a["constraints"][i]["tolerance"].get<double>(),
                 tb = b["constraints"][i]["tolerance"].get<double>();
    EXPECT_NEAR(ta, tb, 1e-10 * std::fabs(tb));
    a["constraints"][i].erase("tolerance");
    b["constraints"][i].erase("tolerance");
  }
  EXPECT_EQ(a, b);
}

TEST(CardDeck, ScoutExampleIsWhatConvertWrites) {
  ScratchDirectory scratch("card_convert_example");
  const std::string out = (scratch / "mission.dat").string();
  const CommandResult result =
      run_tolip_executable({"convert", example_path("scout/mission.toml"), "--to", out});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(contains(result.out, "card deck of 1 case from the TOML deck")) << result.out;
  EXPECT_EQ(read_text_file(out), read_text(example_path("scout/mission.dat")))
      << "tolip convert and scripts/make_scout_examples.py punch the deck differently";
}

// ---- conversions --------------------------------------------------------------------------------

TEST(CardDeck, RoundTripCardTomlCardIsExact) {
  Deck first;
  DeckError error;
  ASSERT_TRUE(ground::load_deck(example_path("scout/mission.dat"), &first, &error)) << error.to_string();
  std::string toml;
  ASSERT_TRUE(ground::deck_to_toml(first, 0, &toml, &error)) << error.to_string();
  Deck middle;
  ASSERT_TRUE(ground::parse_deck(toml, "converted.toml", &middle, &error)) << error.to_string();
  ASSERT_EQ(middle.format, DeckFormat::kToml);
  std::string cards;
  int rounded = -1;
  ASSERT_TRUE(ground::deck_to_cards(middle, &cards, &rounded, &error)) << error.to_string();
  EXPECT_EQ(cards, read_text(example_path("scout/mission.dat")));
  Deck last;
  ASSERT_TRUE(ground::parse_deck(cards, "again.dat", &last, &error)) << error.to_string();
  EXPECT_EQ(fields_of(last.cases[0]), fields_of(first.cases[0]));
  EXPECT_EQ(fields_of(middle.cases[0]), fields_of(first.cases[0]));
  expect_same_extras(last.cases[0].extras, first.cases[0].extras);
}

TEST(CardDeck, RoundTripThroughTheCommandGivesIdenticalResults) {
  ScratchDirectory scratch("card_round_trip");
  const std::string toml = (scratch / "mission.toml").string();
  const std::string cards = (scratch / "mission.dat").string();
  ASSERT_EQ(run_tolip_executable({"convert", example_path("scout/mission.dat"), "--to", toml}).exit_code, 0);
  ASSERT_EQ(run_tolip_executable({"convert", toml, "--to", cards}).exit_code, 0);
  EXPECT_EQ(read_text_file(cards), read_text(example_path("scout/mission.dat")));
  const CommandResult original =
      run_tolip_executable({"simulate", example_path("scout/mission.dat"), "--json"});
  const CommandResult via_toml = run_tolip_executable({"simulate", toml, "--json"});
  const CommandResult back = run_tolip_executable({"simulate", cards, "--json"});
  ASSERT_EQ(original.exit_code, 0) << original.err;
  ASSERT_EQ(via_toml.exit_code, 0) << via_toml.err;
  ASSERT_EQ(back.exit_code, 0) << back.err;
  nlohmann::json a = nlohmann::json::parse(original.out);
  nlohmann::json b = nlohmann::json::parse(via_toml.out);
  nlohmann::json c = nlohmann::json::parse(back.out);
  for (nlohmann::json* document : {&a, &b, &c}) document->erase("deck");
  EXPECT_EQ(a, b);
  EXPECT_EQ(a, c);
}

TEST(CardDeck, SuccessiveCasesSurviveConversionToCards) {
  const std::string text =
      std::string(kTitleCards) + options_card("001000000000001000000001") + kVehicleCards +
      "\n 41        1\nWALLOPS            37.86      -75.51         40.\n\n"
      " 21  5  5\n         95.\n 30  1  4  1\n          0.      12000.         10.      12000.\n\n"
      " 41        1\nBERMUDA            32.35      -64.66         60.\n\n999\n";
  const Parsed first = parse(text);
  ASSERT_TRUE(first.ok) << first.error.to_string();
  std::string cards;
  DeckError error;
  ASSERT_TRUE(ground::deck_to_cards(first.deck, &cards, nullptr, &error)) << error.to_string();
  const Parsed again = parse(cards, "again.dat");
  ASSERT_TRUE(again.ok) << again.error.to_string() << "\n" << cards;
  ASSERT_EQ(again.deck.cases.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(fields_of(again.deck.cases[i]), fields_of(first.deck.cases[i])) << "case " << i + 1;
    expect_same_extras(again.deck.cases[i].extras, first.deck.cases[i].extras);
  }
  // The second case is written as its changes only.
  const std::size_t second = cards.find("\n\n", cards.find(" 41  1  5  1")) + 2;
  EXPECT_EQ(cards.substr(second, 40).rfind(" 21  5  5", 0), 0u) << cards.substr(second, 200);
  // A TOML deck holds one case: --case picks it.
  std::string toml;
  EXPECT_FALSE(ground::deck_to_toml(first.deck, 0, &toml, &error));
  EXPECT_TRUE(contains(error.to_string(),
                       "the card deck has 2 cases and a TOML deck holds one: choose one with --case N"));
  ASSERT_TRUE(ground::deck_to_toml(first.deck, 2, &toml, &error)) << error.to_string();
  EXPECT_TRUE(contains(toml, "azimuth_deg = 95.0"));
}

// Data block 31 in every stage (issue 17): the manual stores drag tables for stages 1, 6 and 2 only
// (a 1966 storage limit); a stage-3 table and one for the coast after stage 2 are read, act on the
// flight, and survive `convert` to cards and back. (Before: rejected naming block 31.)
TEST(CardDeck, Sec22_DragTablesOfEveryStageActAndSurviveConversion) {
  ScratchDirectory scratch("card_drag_every_stage");
  std::string text =
      replaced(scout_mission_text(), "[stage.3.thrust]",
               "[stage.3.drag]\nmach = [0.0, 5.0, 30.0]\ncd = [0.6, 0.6, 0.6]\n\n[stage.3.thrust]");
  text = replaced(text, "reference_area_ft2 = 0.0                     # block 39 SG7(2)",
                  "reference_area_ft2 = 4.9087\n\n[stage.7.drag]\nmach = [0.0, 30.0]\ncd = [0.9, 0.9]");
  // The example is above HAERO (250,000 ft) by stage-2 burnout: raise it so that the upper stages
  // fly in the (thin) tabulated atmosphere, in both runs.
  text = replaced(text, "haero_ft = 250000.0", "haero_ft = 600000.0");
  const std::string toml = (scratch / "drag.toml").string();
  std::ofstream(toml) << text;
  const std::string base_toml = (scratch / "base.toml").string();
  std::ofstream(base_toml) << replaced(scout_mission_text(), "haero_ft = 250000.0", "haero_ft = 600000.0");
  const CommandResult base = run_tolip_executable({"simulate", base_toml, "--json"});
  const CommandResult with_drag = run_tolip_executable({"simulate", toml, "--json"});
  ASSERT_EQ(with_drag.exit_code, 0) << with_drag.err;
  const nlohmann::json a = nlohmann::json::parse(base.out), b = nlohmann::json::parse(with_drag.out);
  // Drag where there was none: stage 3 (94-130 s) and coast 7 (88-94 s) still fly in air.
  double drag_stage3_lbf = 0.0, drag_coast7_lbf = 0.0;
  for (const nlohmann::json& p : b["trajectory"]) {
    if (p["stage"] == 3) drag_stage3_lbf = std::max(drag_stage3_lbf, p["drag_lbf"].get<double>());
    if (p["stage"] == 7) drag_coast7_lbf = std::max(drag_coast7_lbf, p["drag_lbf"].get<double>());
  }
  for (const nlohmann::json& p : a["trajectory"]) {
    if (p["stage"] == 3 || p["stage"] == 7) EXPECT_EQ(p["drag_lbf"].get<double>(), 0.0);
  }
  EXPECT_GT(drag_stage3_lbf, 0.0);
  EXPECT_GT(drag_coast7_lbf, 0.0);
  EXPECT_LT(b["burnout"]["velocity_ft_s"].get<double>(), a["burnout"]["velocity_ft_s"].get<double>());

  const std::string cards = (scratch / "drag.dat").string();
  ASSERT_EQ(run_tolip_executable({"convert", toml, "--to", cards}).exit_code, 0);
  const std::string punched = read_text_file(cards);
  EXPECT_TRUE(contains(punched, " 31  1  8  3")) << "no stage-3 block 31 header";
  EXPECT_TRUE(contains(punched, " 31  1  6  7")) << "no coast-7 block 31 header";
  const CommandResult from_cards = run_tolip_executable({"simulate", cards, "--json"});
  ASSERT_EQ(from_cards.exit_code, 0) << from_cards.err;
  nlohmann::json c = nlohmann::json::parse(from_cards.out);
  EXPECT_EQ(c["burnout"], b["burnout"]);
}

TEST(CardDeck, ConvertCommandErrors) {
  ScratchDirectory scratch("card_convert_errors");
  const CommandResult unknown = run_tolip_executable(
      {"convert", example_path("scout/mission.toml"), "--to", (scratch / "x.txt").string()});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_TRUE(contains(unknown.err, "cannot tell the output format")) << unknown.err;
  const CommandResult forced = run_tolip_executable({"convert", example_path("scout/mission.toml"), "--to",
                                                     (scratch / "x.txt").string(), "--format", "cards"});
  EXPECT_EQ(forced.exit_code, 0) << forced.err;
  const CommandResult bad =
      run_tolip_executable({"convert", "/nonexistent.dat", "--to", (scratch / "y.toml").string()});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_FALSE(std::filesystem::exists(scratch / "y.toml"));
}

// ---- IP(17) -------------------------------------------------------------------------------------

TEST(CardDeck, InputEchoListsEveryBlockWithItsWords) {
  Deck deck;
  DeckError error;
  ASSERT_TRUE(ground::load_deck(example_path("scout/mission.dat"), &deck, &error)) << error.to_string();
  ASSERT_TRUE(deck.cases[0].mission->options.print_input());
  std::ostringstream echo;
  ground::write_input_echo(echo, deck, deck.cases[0]);
  const std::string text = echo.str();
  for (const char* part :
       {"INPUT DATA OF CASE 1 (OPTION IP(17)), card deck", "DATA BLOCK 1  MAIN HEADING",
        "DATA BLOCK 4  OPTIONS IP", "IP(17) OUTPUT OF INPUT DATA",
        "IP( 1) PAYOFF: 0 PAYLOAD, 1 VELOCITY, 2 ALT.", "DATA BLOCK 10  NOMINAL CONSTANTS CT1",
        "HAERO, AERO BYPASS ALT., FT", "DATA BLOCK 21  INITIAL CONDITIONS DA6", "AZIMUTH, DEG EAST OF NORTH",
        "1.00000000E+02", "DATA BLOCK 30  VACUUM THRUST TABLE  STAGE CODE 1",
        "25 POINTS: STAGE TIME, S VS VACUUM THRUST, LB", "DATA BLOCK 15  EXTENSIONS",
        "DISPERSION DATA (IP(21))", "DISPERSION CODE 36  winds", "HARDOVER DATA (IP(22))",
        "IMPACT DATA (IP(23))", "DATA BLOCK 41  RADAR STATION LOCATIONS", "WALLOPS"}) {
    EXPECT_TRUE(contains(text, part)) << part;
  }
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) EXPECT_LE(line.size(), 132u) << line;
  // A TOML deck echoes the same words.
  Deck toml;
  ASSERT_TRUE(ground::load_deck(example_path("scout/mission.toml"), &toml, &error)) << error.to_string();
  std::ostringstream toml_echo;
  ground::write_input_echo(toml_echo, toml, toml.cases[0]);
  EXPECT_TRUE(contains(toml_echo.str(), "DATA BLOCK 30  VACUUM THRUST TABLE  STAGE CODE 1"));
  EXPECT_TRUE(contains(toml_echo.str(), "TOML deck"));
}

TEST(CardDeck, SimulatePrintsTheEchoWhenIp17IsSet) {
  const CommandResult with = run_tolip_executable({"simulate", example_path("scout/mission.dat")});
  ASSERT_EQ(with.exit_code, 0) << with.err;
  EXPECT_TRUE(contains(with.out, "INPUT DATA OF CASE 1"));
  EXPECT_LT(with.out.find("INPUT DATA OF CASE 1"), with.out.find("TERMINAL CONDITIONS"));
  ScratchDirectory scratch("card_no_echo");
  const std::string path = (scratch / "d.dat").string();
  std::ofstream(path) << deck_text();  // IP(17) = 0
  const CommandResult without = run_tolip_executable({"simulate", path});
  ASSERT_EQ(without.exit_code, 0) << without.err;
  EXPECT_FALSE(contains(without.out, "INPUT DATA"));
}

// ---- robustness ---------------------------------------------------------------------------------

// Deterministic mutations of valid decks: whatever the input, the reader returns (true, or false
// with a located message) and never throws or crashes.
TEST(CardDeckFuzz, MutatedDecksNeverCrashTheReader) {
  const std::vector<std::string> seeds = {
      read_text(example_path("scout/mission.dat")),
      deck_text("001000000000001000001111", kBodyCards,
                " 46  1  2 17\nDRAG HIGH\n 48  1  1\n         .15\n\n"
                " 44  1  6  1\n                      0.     300000.      1.0E10\n\n"
                " 42  1  6  1\n                      0.         .45      1.0E10\n\n"
                " 41        1\nWALLOPS            37.86      -75.51         40.\n\n")};
  std::uint64_t state = 0x9E3779B97F4A7C15ull;
  auto next = [&state](std::uint64_t bound) {
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return bound == 0 ? 0 : state % bound;
  };
  const std::string alphabet = " 0123456789.-+EeD\t\nX,;#[]=\"999";
  int accepted = 0;
  int rejected = 0;
  // TOLIP_CARD_FUZZ_ROUNDS raises the count for a longer run (e.g. under the sanitizers).
  const char* rounds_text = std::getenv("TOLIP_CARD_FUZZ_ROUNDS");
  const int rounds = rounds_text != nullptr ? std::atoi(rounds_text) : 600;
  for (int round = 0; round < rounds; ++round) {
    std::string text = seeds[static_cast<std::size_t>(round) % seeds.size()];
    if (round % seeds.size() == 0 && round % 3 != 0) text = text.substr(0, 6000);  // short decks parse fast
    const int edits = 1 + static_cast<int>(next(6));
    for (int e = 0; e < edits && !text.empty(); ++e) {
      const std::size_t at = next(text.size());
      switch (next(8)) {
        case 6:
        case 7: {  // a plausible header card: deep paths (groups, tables, TOML checks)
          const std::size_t line = text.rfind('\n', at);
          const std::size_t begin = line == std::string::npos ? 0 : line + 1;
          char header[16];
          std::snprintf(header, sizeof header, "%3d%3d%3d%3d", static_cast<int>(next(58)),
                        static_cast<int>(next(45)), static_cast<int>(next(45)), static_cast<int>(next(12)));
          text.replace(begin, std::min<std::size_t>(12, text.size() - begin), header);
          break;
        }
        case 0: text[at] = alphabet[next(alphabet.size())]; break;
        case 1: text.erase(at, 1 + next(40)); break;
        case 2: text.insert(at, text.substr(next(text.size()), next(120))); break;
        case 3: text.insert(at, std::string(1 + next(90), ' ')); break;
        case 4: text[at] = static_cast<char>(next(256)); break;
        default: {
          const std::size_t line = text.find('\n', at);
          if (line != std::string::npos) text.insert(line + 1, "\n");
          break;
        }
      }
    }
    Deck deck;
    DeckError error;
    bool ok_parse = false;
    EXPECT_NO_THROW(ok_parse = ground::parse_deck(text, "fuzz.dat", &deck, &error));
    if (ok_parse) {
      ++accepted;
      EXPECT_FALSE(deck.cases.empty());
    } else {
      ++rejected;
      EXPECT_FALSE(error.message.empty());
    }
  }
  EXPECT_GT(rejected, 0);
  EXPECT_GT(accepted + rejected, 0);
}

}  // namespace
}  // namespace tolip::test
