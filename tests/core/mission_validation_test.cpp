// validate_mission() and vehicle_weight_lb() (fsw_core/src/mission/mission.cpp) on the Scout
// reference optimum deck, built without the deck reader (support/example_missions.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <string>

#include "support/example_missions.hpp"
#include "support/reference_data.hpp"
#include "support/reference_mission.hpp"
#include "tolip/mission/mission.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip/vehicle/prepared_case.hpp"

namespace tolip::test {
namespace {

std::unique_ptr<Mission> optimum() {
  auto mission = std::make_unique<Mission>();
  EXPECT_EQ(flight::build_reference_optimum_deck(mission.get()), Status::kOk);
  return mission;
}

struct Outcome {
  Status status;
  MissionFault fault;
};

Outcome validate(const Mission& mission) {
  Outcome outcome{Status::kOk, {}};
  outcome.status = validate_mission(mission, &outcome.fault);
  return outcome;
}

void expect_fault(const Mission& mission, Status status, int block, int stage, const char* field) {
  const Outcome outcome = validate(mission);
  EXPECT_EQ(outcome.status, status) << status_name(outcome.status);
  EXPECT_EQ(outcome.fault.data_block, block);
  EXPECT_EQ(outcome.fault.stage_code, stage);
  EXPECT_STREQ(outcome.fault.field, field);
}

TEST(MissionValidation, ReferenceOptimumIsValidAndFaultIsCleared) {
  auto mission = optimum();
  MissionFault fault{99, 9, "stale"};
  EXPECT_EQ(validate_mission(*mission, &fault), Status::kOk);
  EXPECT_EQ(fault.data_block, 0);
  EXPECT_STREQ(fault.field, "");
  EXPECT_EQ(validate_mission(*mission, nullptr), Status::kOk);
}

TEST(MissionValidation, SequenceMustStartWithStage1) {
  auto mission = optimum();
  mission->vehicle.sequence.codes[0] = 6;
  expect_fault(*mission, Status::kStageSequenceInvalid, 5, 6, "sequence");
}

TEST(MissionValidation, UnknownStageCodeInSequence) {
  auto mission = optimum();
  mission->vehicle.sequence.codes[3] = 12;
  expect_fault(*mission, Status::kUnknownStageCode, 5, 12, "sequence");
}

TEST(MissionValidation, EmptySequence) {
  auto mission = optimum();
  mission->vehicle.sequence.count = 0;
  expect_fault(*mission, Status::kStageSequenceInvalid, 5, 0, "sequence");
}

TEST(MissionValidation, InSequenceFlagsMustMatchTheSequence) {
  auto mission = optimum();
  stage(*mission, 5).in_sequence = true;
  expect_fault(*mission, Status::kStageSequenceInvalid, 5, 5, "in_sequence");
}

TEST(MissionValidation, PoweredStageNeedsThrustAndWeightTables) {
  auto mission = optimum();
  stage(*mission, 3).vacuum_thrust_lbf.clear();
  expect_fault(*mission, Status::kMissingThrustTable, 30, 3, "vacuum_thrust_lbf");
  mission = optimum();
  stage(*mission, 2).consumable_weight_lb.clear();
  expect_fault(*mission, Status::kMissingWeightTable, 38, 2, "consumable_weight_lb");
}

TEST(MissionValidation, UnfinalizedTableIsRejected) {
  auto mission = optimum();
  stage(*mission, 4).vacuum_thrust_lbf.set_y(3, 6000.0);  // set_y clears the finalized flag
  expect_fault(*mission, Status::kMissingThrustTable, 30, 4, "vacuum_thrust_lbf");
}

TEST(MissionValidation, TotalThrustPointsOverAllStagesAtMost120) {
  auto mission = optimum();                                   // 25 + 22 + 20 + 17 = 84 points in stages 1-4
  ThrustTable& table = stage(*mission, 5).vacuum_thrust_lbf;  // stage 5 is not flown, but its table is stored
  for (int i = 0; i < 37; ++i) ASSERT_EQ(table.append(i, 1.0), Status::kOk);
  ASSERT_EQ(table.finalize(), Status::kOk);
  expect_fault(*mission, Status::kTooManyThrustPointsInAllStages, 30, 0, "vacuum_thrust_lbf");
  table.clear();
  for (int i = 0; i < 36; ++i) ASSERT_EQ(table.append(i, 1.0), Status::kOk);
  ASSERT_EQ(table.finalize(), Status::kOk);
  EXPECT_EQ(validate(*mission).status, Status::kOk);
}

TEST(MissionValidation, NegativeWeights) {
  auto mission = optimum();
  stage(*mission, 2).jettison_weight_lb = -1.0;
  expect_fault(*mission, Status::kNegativeWeight, 39, 2, "jettison_weight_lb");
  mission = optimum();
  stage(*mission, 7).jettison_weight_lb = -1.0;
  expect_fault(*mission, Status::kNegativeWeight, 39, 7, "jettison_weight_lb");
  mission = optimum();
  mission->vehicle.payload_lb = -0.5;
  expect_fault(*mission, Status::kNegativeWeight, 39, 4, "payload_lb");
}

TEST(MissionValidation, DurationsAndStepCounts) {
  auto mission = optimum();
  stage(*mission, 7).duration_s = -1.0;
  expect_fault(*mission, Status::kNonPositiveDuration, 16, 7, "duration_s");
  mission = optimum();
  stage(*mission, 7).duration_s = 0.0;  // issue 17: leave the coast out of the sequence instead
  expect_fault(*mission, Status::kZeroLengthCoast, 16, 7, "duration_s");
  mission = optimum();
  stage(*mission, 8).integration_steps = 0;
  expect_fault(*mission, Status::kNonPositiveStepCount, 16, 8, "integration_steps");
  mission = optimum();
  stage(*mission, 8).integration_steps = kMaxCoastSteps + 1;
  expect_fault(*mission, Status::kTooManyCoastSteps, 16, 8, "integration_steps");
  mission = optimum();
  stage(*mission, 1).integration_steps = 24;
  expect_fault(*mission, Status::kTooFewStage1Steps, 16, 1, "integration_steps");
}

TEST(MissionValidation, PoweredStepTotals) {
  auto mission = optimum();                   // 42 + 30 + 40 + 35 = 147 powered steps, coast 6 has 4
  stage(*mission, 3).integration_steps = 61;  // 168
  EXPECT_EQ(validate(*mission).status, Status::kOk);
  stage(*mission, 3).integration_steps = 62;  // 169
  expect_fault(*mission, Status::kTooManyPoweredSteps, 16, 0, "integration_steps");
  stage(*mission, 3).integration_steps = 61;
  stage(*mission, 6).integration_steps = 9;  // 168 + 9 = 177
  EXPECT_EQ(validate(*mission).status, Status::kOk);
  stage(*mission, 6).integration_steps = 10;
  expect_fault(*mission, Status::kTooManyPoweredStepsWithFollowingCoast, 16, 6, "integration_steps");
}

TEST(MissionValidation, DurationMustEqualLastThrustTimeWithinTimeEpsilon) {
  auto mission = optimum();
  stage(*mission, 2).duration_s = 38.0 + 0.5 * mission->constants.time_epsilon_s;
  EXPECT_EQ(validate(*mission).status, Status::kOk);
  stage(*mission, 2).duration_s = 38.0 + 2.0 * mission->constants.time_epsilon_s;
  expect_fault(*mission, Status::kStageDurationMismatch, 16, 2, "duration_s");
}

TEST(MissionValidation, ThrustAndWeightTablesEndTogether) {
  auto mission = optimum();
  WeightTable& weight = stage(*mission, 3).consumable_weight_lb;
  WeightTable shorter;
  for (int i = 0; i + 1 < weight.size(); ++i)
    ASSERT_EQ(shorter.append(weight.x(i), weight.y(i)), Status::kOk);
  ASSERT_EQ(shorter.finalize(), Status::kOk);
  weight = shorter;
  expect_fault(*mission, Status::kThrustWeightTimesDiffer, 38, 3, "consumable_weight_lb");
}

TEST(MissionValidation, LiftoffAndInitialConditions) {
  auto mission = optimum();
  mission->launch.liftoff_duration_s = -0.1;
  expect_fault(*mission, Status::kLiftoffNotPositive, 20, 0, "liftoff_duration_s");
  mission->launch.liftoff_duration_s = 0.0;  // the equations of motion are singular at V = 0
  expect_fault(*mission, Status::kLiftoffNotPositive, 20, 0, "liftoff_duration_s");
  mission->launch.liftoff_duration_s = 45.0;
  expect_fault(*mission, Status::kLiftoffLongerThanStage1, 20, 1, "liftoff_duration_s");
  mission = optimum();
  mission->launch.velocity_ft_s = 1.0;
  expect_fault(*mission, Status::kInitialConditionsInvalid, 21, 0, "velocity_ft_s");
  mission = optimum();
  mission->launch.flight_path_angle_rad = 89.0 * kDegToRad;
  expect_fault(*mission, Status::kInitialConditionsInvalid, 21, 0, "flight_path_angle_rad");
}

TEST(MissionValidation, EveryDoubleMustBeFinite) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto mission = optimum();
  mission->launch.azimuth_rad = nan;
  expect_fault(*mission, Status::kValueNotFinite, 21, 0, "azimuth_rad");
  mission = optimum();
  mission->constants.j2 = std::numeric_limits<double>::infinity();
  expect_fault(*mission, Status::kValueNotFinite, 10, 0, "j2");
  mission = optimum();
  mission->constraints.deadband_linearization[12] = nan;  // unused slot: still checked
  expect_fault(*mission, Status::kValueNotFinite, 29, 0, "deadband_linearization");
  mission = optimum();
  mission->misc.nose_radius_ft = nan;
  expect_fault(*mission, Status::kValueNotFinite, 17, 0, "nose_radius_ft");
  mission = optimum();
  mission->vehicle.payload_lb = nan;
  expect_fault(*mission, Status::kValueNotFinite, 39, 4, "payload_lb");
}

TEST(MissionValidation, CountsWithinCapacity) {
  auto mission = optimum();
  mission->constraints.count = kMaxConstraints + 1;
  expect_fault(*mission, Status::kTooManyConstraints, 8, 0, "count");
  mission = optimum();
  mission->adjustable.count = kMaxAdjustableParameters + 1;
  expect_fault(*mission, Status::kTooManyAdjustableParameters, 6, 0, "count");
  mission = optimum();
  mission->linearization.segment_count = kMaxLinearSegments + 1;
  expect_fault(*mission, Status::kTooManyLinearSegments, 18, 0, "segment_count");
}

TEST(MissionValidation, AtmosphereTableMustBeOrdered) {
  auto mission = optimum();
  mission->atmosphere.base_geopotential_altitude_ft[3] = 1.0;
  expect_fault(*mission, Status::kAtmosphereTableInvalid, 11, 0, "base_geopotential_altitude_ft");
}

TEST(MissionValidation, AdjustableCoastMustBeFlown) {
  auto mission = optimum();
  mission->adjustable.codes[1] = 10;  // coast after stage 4 (code 9) is not in the sequence
  expect_fault(*mission, Status::kAdjustableCoastNotInSequence, 6, 9, "codes");
}

// Vehicle weight against the oracle's stage events (README section 3).
TEST(MissionValidation, VehicleWeightMatchesTheOracleStageEvents) {
  auto mission = optimum();
  const Vehicle& vehicle = mission->vehicle;
  const nlohmann::json& oracle = scout_reference()["oracle_solution"];
  EXPECT_NEAR(vehicle_weight_lb(vehicle, 1, 0.0), oracle["launch_weight_lb"].get<double>(), 1e-6);
  for (const nlohmann::json& event : oracle["stage_events"]) {
    const int code = event["stage"].get<int>();
    const bool end = event["event"].get<std::string>() == "end";
    double stage_time = 0.0;
    if (code == 1) stage_time = end ? 45.0 : 3.0;  // stage 1 starts flying at the end of the lift-off
    else if (end) stage_time = vehicle.stages[stage_index(code)].duration_s;
    EXPECT_NEAR(vehicle_weight_lb(vehicle, code, stage_time), event["weight_lb"].get<double>(), 1e-5)
        << "stage " << code << " " << event["event"].get<std::string>();
  }
  EXPECT_NEAR(vehicle_weight_lb(vehicle, 4, 28.0), oracle["final_weight_lb"].get<double>(), 1e-9);
  // After stage 1 burnout the Algol jettison (4800 lb) is dropped: coast 6 = 13928.405 lb.
  EXPECT_NEAR(vehicle_weight_lb(vehicle, 1, 45.0) - vehicle_weight_lb(vehicle, 6, 0.0), 4800.0, 1e-9);
  // Coasts carry no consumable weight of their own and do not change the weight.
  EXPECT_EQ(vehicle_weight_lb(vehicle, 8, 0.0), vehicle_weight_lb(vehicle, 8, 400.0));
  // A stage code not in the sequence weighs nothing.
  EXPECT_EQ(vehicle_weight_lb(vehicle, 5, 0.0), 0.0);
}

TEST(MissionValidation, PayloadRidesWithTheLastPoweredStageOfTheSequence) {
  auto mission = optimum();
  Vehicle& vehicle = mission->vehicle;
  // Fly only 1 6 2: the payload is now part of stage 2's jettison weight.
  vehicle.sequence.count = 3;
  const double stage2_end = vehicle_weight_lb(vehicle, 2, 38.0);
  EXPECT_NEAR(stage2_end, 1900.0 + vehicle.payload_lb, 1e-9);
  EXPECT_NEAR(vehicle_weight_lb(vehicle, 1, 0.0), 20200.0 + 4800.0 + 8000.0 + 1900.0 + vehicle.payload_lb,
              1e-9);
  // A coast after the last powered stage flies what that stage burned out with (Addendum H's
  // integrated coast following the final stage): nothing is staged after it.
  vehicle.sequence.count = 4;  // 1 6 2 7
  EXPECT_EQ(vehicle_weight_lb(vehicle, 7, 0.0), vehicle_weight_lb(vehicle, 7, 6.0));
  EXPECT_NEAR(vehicle_weight_lb(vehicle, 7, 0.0), stage2_end, 1e-9);
}

// Addendum H: "an integrated coast following the final stage". The reference optimum with a coast 9
// after its last stage (4) flies it with the burnout weight, payload included, to a finite end
// (before the fix the coast weighed 0 lb and the run stopped with kNonFiniteState).
TEST(MissionValidation, AddendumH_ACoastAfterTheLastPoweredStageKeepsThePayload) {
  auto mission = optimum();
  Vehicle& vehicle = mission->vehicle;
  const double burnout_lb = vehicle_weight_lb(vehicle, 4, vehicle.stages[stage_index(4)].duration_s);
  vehicle.sequence.codes[vehicle.sequence.count++] = 9;
  StageData& coast = vehicle.stages[stage_index(9)];
  coast.in_sequence = true;
  coast.duration_s = 600.0;
  coast.integration_steps = 10;
  ASSERT_EQ(validate(*mission).status, Status::kOk);
  EXPECT_NEAR(vehicle_weight_lb(vehicle, 9, 0.0), burnout_lb, 1e-9);
  EXPECT_NEAR(burnout_lb, vehicle.stages[stage_index(4)].jettison_weight_lb + vehicle.payload_lb, 1e-9);
  auto prepared = std::make_unique<PreparedCase>();
  auto trajectory = std::make_unique<Trajectory>();
  ASSERT_EQ(prepare_case(*mission, prepared.get()), Status::kOk);
  ASSERT_EQ(fly_trajectory(*mission, *prepared, trajectory.get()), Status::kOk);
  const TrajectoryPoint& last = trajectory->points[trajectory->point_count - 1];
  EXPECT_EQ(last.stage_code, 9);
  EXPECT_NEAR(last.weight_lb, burnout_lb, 1e-9);
  EXPECT_TRUE(last.state.allFinite());
}

}  // namespace
}  // namespace tolip::test
