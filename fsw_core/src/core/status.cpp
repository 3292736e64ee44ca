// Names and messages of Status (status.hpp).
#include "tolip/core/status.hpp"

namespace tolip {

const char* status_name(Status status) {
  switch (status) {
    case Status::kOk: return "kOk";
    case Status::kTooManyTablePoints: return "kTooManyTablePoints";
    case Status::kTooManyThrustPointsInAllStages: return "kTooManyThrustPointsInAllStages";
    case Status::kTooManyWeightPointsInAllStages: return "kTooManyWeightPointsInAllStages";
    case Status::kTooManyPoweredSteps: return "kTooManyPoweredSteps";
    case Status::kTooManyPoweredStepsWithFollowingCoast: return "kTooManyPoweredStepsWithFollowingCoast";
    case Status::kTooManyCoastSteps: return "kTooManyCoastSteps";
    case Status::kTooFewStage1Steps: return "kTooFewStage1Steps";
    case Status::kTooManyConstraints: return "kTooManyConstraints";
    case Status::kTooManyAdjustableParameters: return "kTooManyAdjustableParameters";
    case Status::kTooManyLinearSegments: return "kTooManyLinearSegments";
    case Status::kTooManyRadarStations: return "kTooManyRadarStations";
    case Status::kTableEmpty: return "kTableEmpty";
    case Status::kTableNotMonotonic: return "kTableNotMonotonic";
    case Status::kValueNotFinite: return "kValueNotFinite";
    case Status::kValueOutOfRange: return "kValueOutOfRange";
    case Status::kNegativeWeight: return "kNegativeWeight";
    case Status::kNonPositiveDuration: return "kNonPositiveDuration";
    case Status::kNonPositiveStepCount: return "kNonPositiveStepCount";
    case Status::kStageSequenceInvalid: return "kStageSequenceInvalid";
    case Status::kUnknownStageCode: return "kUnknownStageCode";
    case Status::kMissingThrustTable: return "kMissingThrustTable";
    case Status::kMissingWeightTable: return "kMissingWeightTable";
    case Status::kThrustWeightTimesDiffer: return "kThrustWeightTimesDiffer";
    case Status::kStageDurationMismatch: return "kStageDurationMismatch";
    case Status::kLiftoffLongerThanStage1: return "kLiftoffLongerThanStage1";
    case Status::kInitialConditionsInvalid: return "kInitialConditionsInvalid";
    case Status::kAtmosphereTableInvalid: return "kAtmosphereTableInvalid";
    case Status::kNonFiniteState: return "kNonFiniteState";
    case Status::kAltitudeBelowSurface: return "kAltitudeBelowSurface";
    case Status::kZeroVelocity: return "kZeroVelocity";
    case Status::kMassNotPositive: return "kMassNotPositive";
    case Status::kTrajectoryStorageFull: return "kTrajectoryStorageFull";
    case Status::kControlProgramSizeMismatch: return "kControlProgramSizeMismatch";
    case Status::kNotPrepared: return "kNotPrepared";
  }
  return "kUnknownStatus";
}

const char* status_message(Status status) {
  switch (status) {
    case Status::kOk: return "success";
    case Status::kTooManyTablePoints: return "a table has more points than its capacity";
    case Status::kTooManyThrustPointsInAllStages: return "the thrust tables of all stages together exceed 120 points";
    case Status::kTooManyWeightPointsInAllStages: return "the weight tables of all stages together exceed 120 points";
    case Status::kTooManyPoweredSteps: return "the powered stages together have more than 168 integration steps";
    case Status::kTooManyPoweredStepsWithFollowingCoast: return "the powered stages and coast 6 together have more than 177 integration steps";
    case Status::kTooManyCoastSteps: return "a coast has more integration steps than the per-coast capacity";
    case Status::kTooFewStage1Steps: return "stage 1 needs at least 25 integration steps";
    case Status::kTooManyConstraints: return "more than 13 constraints";
    case Status::kTooManyAdjustableParameters: return "more than 11 adjustable parameters";
    case Status::kTooManyLinearSegments: return "more than 15 linear segments";
    case Status::kTooManyRadarStations: return "more than 20 radar stations";
    case Status::kTableEmpty: return "a required table is empty";
    case Status::kTableNotMonotonic: return "table abscissae must strictly increase";
    case Status::kValueNotFinite: return "a value is NaN or infinite";
    case Status::kValueOutOfRange: return "a value is outside its allowed range";
    case Status::kNegativeWeight: return "a weight is negative";
    case Status::kNonPositiveDuration: return "a stage duration must be positive";
    case Status::kNonPositiveStepCount: return "a stage needs at least one integration step";
    case Status::kStageSequenceInvalid: return "the stage sequence must follow 1 6 2 7 3 8 4 9 5 10, starting with 1";
    case Status::kUnknownStageCode: return "a stage code is not one of 1-10";
    case Status::kMissingThrustTable: return "a powered stage has no vacuum thrust table";
    case Status::kMissingWeightTable: return "a powered stage has no consumable-weight table";
    case Status::kThrustWeightTimesDiffer: return "thrust and weight tables of a stage end at different times";
    case Status::kStageDurationMismatch: return "a powered stage duration differs from the last time of its thrust table";
    case Status::kLiftoffLongerThanStage1: return "the lift-off interval is not shorter than stage 1";
    case Status::kInitialConditionsInvalid: return "initial conditions must have zero velocity and a 90 degree flight-path angle";
    case Status::kAtmosphereTableInvalid: return "the atmosphere table is inconsistent";
    case Status::kNonFiniteState: return "the integration produced a NaN or infinite state";
    case Status::kAltitudeBelowSurface: return "the vehicle went below the Earth surface";
    case Status::kZeroVelocity: return "the velocity is zero where a direction is needed";
    case Status::kMassNotPositive: return "the vehicle mass is not positive";
    case Status::kTrajectoryStorageFull: return "the trajectory has more integration points than its fixed storage";
    case Status::kControlProgramSizeMismatch: return "the pitch program has a different number of points than the case's trajectory";
    case Status::kNotPrepared: return "the case was not prepared (prepare_case) before use";
  }
  return "unknown status";
}

}  // namespace tolip
