// Data blocks 33-37 reach the core's Mission (manual Sec. 7, 11; docs/theory/body-dynamics.md):
// from the TOML and the card deck, stations in ft, and the same model the reference data give.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "deck_test_support.hpp"
#include "support/reference_mission.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip_ground/card_deck.hpp"

namespace tolip::test {
namespace {

void expect_same_table(const AeroTable& a, const AeroTable& b, const char* what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (int i = 0; i < a.size(); ++i) {
    EXPECT_DOUBLE_EQ(a.x(i), b.x(i)) << what << i;
    EXPECT_DOUBLE_EQ(a.y(i), b.y(i)) << what << i;
  }
}

void expect_reference_model(const BodyDynamicsBlocks& deck) {
  static Mission reference;
  build_reference_mission(ReferenceProgram::kInitialNominal, &reference);
  const BodyDynamicsBlocks& ref = reference.body_dynamics;
  ASSERT_TRUE(deck.present);
  for (int k = 0; k < kBodyDynamicsStages; ++k) {
    EXPECT_DOUBLE_EQ(deck.position_gain[k], ref.position_gain[k]);
    EXPECT_DOUBLE_EQ(deck.rate_gain_s[k], ref.rate_gain_s[k]);
    EXPECT_DOUBLE_EQ(deck.control_station_ft[k], ref.control_station_ft[k]);
  }
  EXPECT_DOUBLE_EQ(deck.control_station_ft[0], 842.0 / 12.0);
  EXPECT_DOUBLE_EQ(deck.moment_reference_station_ft, 50.0);  // 600 in
  EXPECT_DOUBLE_EQ(deck.jet_vane_effectiveness_per_rad, ref.jet_vane_effectiveness_per_rad);
  EXPECT_DOUBLE_EQ(deck.reference_length_ft, ref.reference_length_ft);
  EXPECT_DOUBLE_EQ(deck.reference_area_ft2, ref.reference_area_ft2);  // SG1(2) = block 34 area
  EXPECT_EQ(deck.control_surfaces_per_plane, 2.0);
  expect_same_table(deck.fin_normal_force_per_rad, ref.fin_normal_force_per_rad, "block 34 ");
  expect_same_table(deck.pitching_moment_per_rad, ref.pitching_moment_per_rad, "block 35 ");
  expect_same_table(deck.fin_pitching_moment_per_rad, ref.fin_pitching_moment_per_rad, "block 36 ");
  for (int k = 0; k < kCgTableStages; ++k) {
    ASSERT_EQ(deck.cg_station_ft[k].size(), ref.cg_station_ft[k].size()) << k;
    EXPECT_TRUE(deck.cg_station_ft[k].finalized());
    for (int i = 0; i < deck.cg_station_ft[k].size(); ++i) {
      EXPECT_DOUBLE_EQ(deck.cg_station_ft[k].y(i), ref.cg_station_ft[k].y(i));
    }
  }
  EXPECT_DOUBLE_EQ(deck.cg_station_ft[0].y(0), 515.0 / 12.0);
}

TEST(Sec22BodyDynamicsDeck, TomlDeckFillsTheCoreModelInFeet) {
  auto mission = ground::make_mission();
  ground::DeckError error;
  ASSERT_TRUE(ground::parse_toml_deck(scout_mission_text(), "mission.toml", mission.get(), &error))
      << error.to_string();
  expect_reference_model(mission->body_dynamics);
  MissionFault fault;
  EXPECT_EQ(validate_body_dynamics(*mission, &fault), Status::kOk);
}

TEST(Sec22BodyDynamicsDeck, CardDeckFillsTheSameModel) {
  auto mission = ground::make_mission();
  ground::DeckExtras extras;
  ground::DeckError error;
  ASSERT_TRUE(
      ground::load_single_case_deck(example_path("scout/mission.dat"), mission.get(), &extras, &error))
      << error.to_string();
  expect_reference_model(mission->body_dynamics);
}

TEST(Sec22BodyDynamicsDeck, DeckCaseFliesSixD) {
  auto mission = ground::make_mission();
  ground::DeckError error;
  ASSERT_TRUE(ground::parse_toml_deck(scout_optimum_text(), "reference_optimum.toml", mission.get(), &error))
      << error.to_string();
  auto prepared = std::make_unique<PreparedCase>();
  auto trajectory = std::make_unique<Trajectory>();
  ASSERT_EQ(prepare_case(*mission, prepared.get()), Status::kOk);
  FlightInputs inputs;
  inputs.body_dynamics = true;
  EXPECT_EQ(fly_trajectory(*mission, *prepared, inputs, trajectory.get()), Status::kOk);
  EXPECT_TRUE(trajectory->points[10].body_dynamics);
}

TEST(Sec22BodyDynamicsDeck, WithoutBodyDynamicsSectionTheModelIsAbsent) {
  std::string text = replaced(scout_mission_text(), "body_dynamics_6d = 1", "body_dynamics_6d = 0");
  text = replaced(text, "dispersions = true", "dispersions = false");
  text = replaced(text, "hardover = true", "hardover = false");
  text = replaced(text, "impact = true", "impact = false");
  text = removed(text, "[body_dynamics]", "# Data block 41");
  auto mission = ground::make_mission();
  ground::DeckError error;
  ASSERT_TRUE(ground::parse_toml_deck(text, "edited.toml", mission.get(), &error)) << error.to_string();
  EXPECT_FALSE(mission->body_dynamics.present);
}

TEST(Sec22BodyDynamicsDeck, ControlStationInsideTheCgRangeIsNamed) {
  const std::string text = replaced(scout_mission_text(), "control_station_in = [842.0, 548.0, 296.0]",
                                    "control_station_in = [500.0, 548.0, 296.0]");
  const ground::DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 33);
  EXPECT_EQ(error.field, "body_dynamics.control_station_in[0]");
  EXPECT_NE(error.message.find("kControlStationAtCenterOfGravity"), std::string::npos) << error.message;
  EXPECT_NE(error.message.find("478-515 in"), std::string::npos) << error.message;
  EXPECT_GT(error.line, 0);
}

TEST(Sec22BodyDynamicsDeck, CgTableLongerThanTheCardsIsRejected) {
  const std::string text =
      replaced(scout_mission_text(),
               "stage_time_s = [0.0, 10.0, 20.0, 30.0, 40.0, 45.0]\nstation_in = [515.0, 510.0, 502.0, "
               "492.0, 482.0, 478.0]",
               "stage_time_s = [0, 4, 8, 12, 16, 20, 24, 28, 32, 36, 40, 45]\n"
               "station_in = [515, 513, 511, 509, 506, 502, 498, 494, 490, 486, 482, 478]");
  const ground::DeckError error = rejected(text);
  EXPECT_EQ(error.data_block, 37);
  EXPECT_NE(error.message.find("at most 10"), std::string::npos) << error.message;
}

}  // namespace
}  // namespace tolip::test
