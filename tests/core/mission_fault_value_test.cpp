// validate_mission() names the value it rejected and the range it must lie in (MissionFault::value,
// range, unit, index), for every check; and a failed trajectory's stage events say which stages
// ended (issue 10 part 4).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>

#include "support/reference_mission.hpp"
#include "tolip/mission/mission.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip/vehicle/prepared_case.hpp"

namespace tolip {
namespace {

std::unique_ptr<Mission> reference() {
  auto mission = std::make_unique<Mission>();
  test::build_reference_mission(test::ReferenceProgram::kOptimum, mission.get());
  return mission;
}

using test::stage;

MissionFault fault_of(const Mission& mission, Status expected) {
  MissionFault fault;
  EXPECT_EQ(validate_mission(mission, &fault), expected) << status_name(validate_mission(mission, nullptr));
  return fault;
}

void expect_value(const MissionFault& fault, int block, const char* field, int index, double value) {
  EXPECT_EQ(fault.data_block, block);
  EXPECT_STREQ(fault.field, field);
  EXPECT_EQ(fault.index, index);
  EXPECT_TRUE(fault.has_value);
  EXPECT_EQ(fault.value, value);
}

TEST(MissionFaultValue, ReferenceMissionIsValid) {
  EXPECT_EQ(validate_mission(*reference(), nullptr), Status::kOk);
}

TEST(MissionFaultValue, NegativeThrustNamesThePointTheValueAndTheLowerBound) {
  auto mission = reference();
  stage(*mission, 2).vacuum_thrust_lbf.set_y(3, -5.0);
  ASSERT_EQ(stage(*mission, 2).vacuum_thrust_lbf.finalize(), Status::kOk);
  const MissionFault fault = fault_of(*mission, Status::kNegativeThrust);
  expect_value(fault, 30, "vacuum_thrust_lbf", 3, -5.0);
  EXPECT_EQ(fault.stage_code, 2);
  EXPECT_TRUE(fault.range.has_low);
  EXPECT_FALSE(fault.range.has_high);
  EXPECT_EQ(fault.range.low, 0.0);
  EXPECT_STREQ(fault.unit, "lbf");
}

TEST(MissionFaultValue, ZeroG0AndInverseFlatteningOneCarryTheirExclusiveLowerBound) {
  auto mission = reference();
  mission->constants.g0_ft_s2 = 0.0;
  MissionFault fault = fault_of(*mission, Status::kConstantOutOfRange);
  expect_value(fault, 10, "g0_ft_s2", -1, 0.0);
  EXPECT_FALSE(fault.range.low_inclusive);
  mission = reference();
  mission->constants.inverse_flattening = 1.0;
  fault = fault_of(*mission, Status::kConstantOutOfRange);
  expect_value(fault, 10, "inverse_flattening", -1, 1.0);
  EXPECT_EQ(fault.range.low, 1.0);
  EXPECT_FALSE(fault.range.low_inclusive);
}

// Data block 10: CT1(12) = 0 is the spherical Earth (Sec. 4's figure turned off, issue 17); any
// other value is 1 / flattening and must exceed 1; infinity is not a way to say "sphere".
TEST(Sec4Earth, InverseFlatteningZeroIsAcceptedAsTheSphereAndOtherValuesAtOrBelowOneAreNot) {
  auto mission = reference();
  mission->constants.inverse_flattening = 0.0;
  EXPECT_EQ(validate_mission(*mission, nullptr), Status::kOk);
  for (double bad : {1.0, 0.5, -298.3, 1e-300}) {
    mission = reference();
    mission->constants.inverse_flattening = bad;
    const MissionFault fault = fault_of(*mission, Status::kConstantOutOfRange);
    expect_value(fault, 10, "inverse_flattening", -1, bad);
    EXPECT_EQ(fault.range.low, 1.0);
    EXPECT_FALSE(fault.range.low_inclusive);
    EXPECT_STREQ(fault.expected, "or 0 for a spherical Earth");
  }
  mission = reference();
  mission->constants.inverse_flattening = std::numeric_limits<double>::infinity();
  EXPECT_STREQ(fault_of(*mission, Status::kValueNotFinite).field, "inverse_flattening");
}

TEST(MissionFaultValue, LatitudeBeyondNinetyDegreesCarriesPlusMinusHalfPi) {
  auto mission = reference();
  mission->launch.geocentric_latitude_rad = 95.0 * kDegToRad;
  const MissionFault fault = fault_of(*mission, Status::kLaunchConditionOutOfRange);
  expect_value(fault, 21, "geocentric_latitude_rad", -1, 95.0 * kDegToRad);
  EXPECT_DOUBLE_EQ(fault.range.low, -0.5 * kPi);
  EXPECT_DOUBLE_EQ(fault.range.high, 0.5 * kPi);
  EXPECT_STREQ(fault.unit, "rad");
}

TEST(MissionFaultValue, AbsurdAnglesAreRejectedWithinOneTurn) {
  auto mission = reference();
  mission->launch.azimuth_rad = 1e20 * kDegToRad;
  expect_value(fault_of(*mission, Status::kLaunchConditionOutOfRange), 21, "azimuth_rad", -1,
               1e20 * kDegToRad);
  mission = reference();
  mission->misc.stage4_theta_rad = 1e10 * kDegToRad;
  expect_value(fault_of(*mission, Status::kMiscellaneousDataOutOfRange), 17, "stage4_theta_rad", -1,
               1e10 * kDegToRad);
  mission = reference();
  mission->pitch_program_rad.set_y(2, 1e308);
  ASSERT_EQ(mission->pitch_program_rad.finalize(), Status::kOk);
  const MissionFault fault = fault_of(*mission, Status::kPitchAttitudeOutOfRange);
  expect_value(fault, 40, "pitch_program_rad", 2, 1e308);
  EXPECT_DOUBLE_EQ(fault.range.high, 2.0 * kPi);
}

TEST(MissionFaultValue, LaunchAltitudeIsBetweenMinus1500FtAndAnAirLaunch) {
  auto mission = reference();
  mission->launch.altitude_ft = -1e7;
  const MissionFault fault = fault_of(*mission, Status::kLaunchConditionOutOfRange);
  expect_value(fault, 21, "altitude_ft", -1, -1e7);
  EXPECT_EQ(fault.range.low, -1500.0);
  EXPECT_EQ(fault.range.high, 100000.0);
  mission = reference();
  mission->launch.altitude_ft = -1400.0;  // the Dead Sea shore
  EXPECT_EQ(validate_mission(*mission, nullptr), Status::kOk);
}

TEST(MissionFaultValue, ThrustWithNoPropellantIsRejected) {
  auto mission = reference();
  WeightTable& weight = stage(*mission, 4).consumable_weight_lb;
  for (int i = 0; i < weight.size(); ++i) weight.set_y(i, 0.0);
  ASSERT_EQ(weight.finalize(), Status::kOk);
  const MissionFault fault = fault_of(*mission, Status::kThrustWithoutPropellant);
  expect_value(fault, 38, "consumable_weight_lb", 0, 0.0);
  EXPECT_EQ(fault.stage_code, 4);
}

TEST(MissionFaultValue, ThrustAfterThePropellantIsGoneIsRejected) {
  auto mission = reference();
  WeightTable& weight = stage(*mission, 3).consumable_weight_lb;
  // Burn the propellant out at the middle of the table while the thrust goes on.
  for (int i = weight.size() / 2; i < weight.size(); ++i) weight.set_y(i, 0.0);
  ASSERT_EQ(weight.finalize(), Status::kOk);
  const MissionFault fault = fault_of(*mission, Status::kThrustWithoutPropellant);
  EXPECT_EQ(fault.data_block, 30);
  EXPECT_STREQ(fault.field, "vacuum_thrust_lbf");
  EXPECT_GT(fault.value, 0.0);
}

TEST(MissionFaultValue, ConsumableWeightIncreasingDuringTheBurnIsRejected) {
  auto mission = reference();
  WeightTable& weight = stage(*mission, 2).consumable_weight_lb;
  const double before = weight.y(4);
  weight.set_y(5, before + 100.0);
  ASSERT_EQ(weight.finalize(), Status::kOk);
  const MissionFault fault = fault_of(*mission, Status::kConsumableWeightIncreases);
  expect_value(fault, 38, "consumable_weight_lb", 5, before + 100.0);
  EXPECT_EQ(fault.range.high, before);
}

TEST(MissionFaultValue, ZeroOptimizationDeadbandIsADeckFaultNotAnOptimizerOne) {
  auto mission = reference();
  mission->constraints.deadband_optimization[1] = 0.0;  // constraint entry 2
  const MissionFault fault = fault_of(*mission, Status::kDeadbandNotPositive);
  expect_value(fault, 29, "deadband_optimization", 2, 0.0);
  EXPECT_FALSE(fault.range.low_inclusive);
}

TEST(MissionFaultValue, StagePointConstraintOnAStageNotFlownIsAnUnknownCode) {
  auto mission = reference();
  ASSERT_FALSE(mission->vehicle.stages[stage_index(9)].in_sequence);
  mission->constraints.codes[1] = 99;  // dynamic pressure at the end of stage 9
  const MissionFault fault = fault_of(*mission, Status::kUnknownConstraintCode);
  expect_value(fault, 8, "codes", 1, 99.0);
  EXPECT_GT(std::strlen(fault.expected), 0u);
}

TEST(MissionFaultValue, ZeroMaxForwardTrajectoriesAndNegativeLiftoffNameTheirBounds) {
  auto mission = reference();
  mission->convergence.max_forward_trajectories = 0;
  MissionFault fault = fault_of(*mission, Status::kConvergenceDataOutOfRange);
  expect_value(fault, 28, "max_forward_trajectories", -1, 0.0);
  EXPECT_EQ(fault.range.low, 1.0);
  mission = reference();
  mission->launch.liftoff_duration_s = -1.0;
  fault = fault_of(*mission, Status::kLiftoffNotPositive);
  expect_value(fault, 20, "liftoff_duration_s", -1, -1.0);
  // 0 too: the first step would start at V = 0, where the equations of motion are singular.
  mission->launch.liftoff_duration_s = 0.0;
  fault = fault_of(*mission, Status::kLiftoffNotPositive);
  expect_value(fault, 20, "liftoff_duration_s", -1, 0.0);
  EXPECT_EQ(fault.range.low, 0.0);
}

TEST(MissionFaultValue, ZeroAlphaWindowBeyondStage1CarriesTheWindow) {
  auto mission = reference();
  mission->options.ip[11] = 1;
  mission->control.zero_alpha_start_s = 15.0;
  mission->control.zero_alpha_end_s = 400.0;
  const MissionFault fault = fault_of(*mission, Status::kZeroAlphaWindowInvalid);
  expect_value(fault, 22, "zero_alpha_end_s", -1, 400.0);
  EXPECT_EQ(fault.range.low, 15.0);
  EXPECT_DOUBLE_EQ(fault.range.high, stage(*mission, 1).duration_s + mission->constants.time_epsilon_s);
}

TEST(MissionFaultValue, EveryValueFaultOfTheseEditsHasARangeOrAnExpectation) {
  auto mission = reference();
  mission->launch.velocity_ft_s = std::nan("");
  MissionFault fault = fault_of(*mission, Status::kValueNotFinite);
  EXPECT_STREQ(fault.expected, "a finite number");
  mission = reference();  // a data block 18 boundary 10 s into the spun stage 4 (the deck's 410)
  LinearizationData& l = mission->linearization;
  l.boundaries[l.segment_count + 1] = SegmentBoundary{4, 10.0};
  l.segment_weights[l.segment_count] = 1.0;
  l.segment_count += 1;
  fault = fault_of(*mission, Status::kCodedTimeInSpunStage);
  expect_value(fault, 18, "boundaries", l.segment_count, 10.0);
  EXPECT_EQ(fault.stage_code, 4);
  EXPECT_TRUE(fault.range.has_low || *fault.expected != '\0');
}

TEST(StageEventsOfAFailedRun, StagesThatEndedKeepTheirJettisonAndTheStoppedStageIsMarked) {
  auto mission = reference();
  // Point the vehicle at the ground after stage 2 so the run ends in the ground.
  PitchTable& pitch = mission->pitch_program_rad;
  for (int i = 0; i < pitch.size(); ++i) {
    if (pitch.x(i) > 60.0) pitch.set_y(i, -80.0 * kDegToRad);
  }
  ASSERT_EQ(pitch.finalize(), Status::kOk);
  ASSERT_EQ(validate_mission(*mission, nullptr), Status::kOk);
  auto prepared = std::make_unique<PreparedCase>();
  auto trajectory = std::make_unique<Trajectory>();
  ASSERT_EQ(prepare_case(*mission, prepared.get()), Status::kOk);
  EXPECT_NE(fly_trajectory(*mission, *prepared, trajectory.get()), Status::kOk);
  ASSERT_GE(trajectory->stage_count, 2);
  const int last = trajectory->stage_count - 1;
  EXPECT_FALSE(trajectory->stages[last].completed);
  EXPECT_EQ(trajectory->stages[last].weight_after_jettison_lb, trajectory->stages[last].burnout_weight_lb);
  for (int k = 0; k < last; ++k) {
    const StageEvent& event = trajectory->stages[k];
    EXPECT_TRUE(event.completed) << k;
    // What a stage drops is its own jettison weight, not the whole vehicle.
    const double dropped = event.burnout_weight_lb - event.weight_after_jettison_lb;
    EXPECT_NEAR(dropped, stage(*mission, event.code).jettison_weight_lb, 1e-6) << "stage " << event.code;
    EXPECT_GT(event.weight_after_jettison_lb, 0.0);
  }
}

}  // namespace
}  // namespace tolip
