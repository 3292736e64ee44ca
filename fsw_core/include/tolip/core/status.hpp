// Status codes of every fsw_core operation that can fail.
//
// One enumerator per cause, named so that a user understands it; status_name() gives the
// enumerator's spelling and status_message() a sentence. Operations return Status and write
// their results through out-parameters; nothing in the core throws.
#pragma once

namespace tolip {

enum class Status : int {
  kOk = 0,
  // Capacities (capacity.hpp)
  kTooManyTablePoints,
  kTooManyThrustPointsInAllStages,
  kTooManyWeightPointsInAllStages,
  kTooManyPoweredSteps,
  kTooManyPoweredStepsWithFollowingCoast,
  kTooManyCoastSteps,
  kTooFewStage1Steps,
  kTooManyConstraints,
  kTooManyAdjustableParameters,
  kTooManyLinearSegments,
  kTooManyRadarStations,
  // Input validation
  kTableEmpty,
  kTableNotMonotonic,
  kValueNotFinite,
  kValueOutOfRange,
  kNegativeWeight,
  kNonPositiveDuration,
  kNonPositiveStepCount,
  kStageSequenceInvalid,
  kUnknownStageCode,
  kMissingThrustTable,
  kMissingWeightTable,
  kThrustWeightTimesDiffer,
  kStageDurationMismatch,
  kLiftoffLongerThanStage1,
  kInitialConditionsInvalid,
  kAtmosphereTableInvalid,
  // Run-time failures
  kNonFiniteState,
  kAltitudeBelowSurface,
  kZeroVelocity,
  kMassNotPositive,
  kTrajectoryStorageFull,
  kControlProgramSizeMismatch,
  kNotPrepared,
};

const char* status_name(Status status);
const char* status_message(Status status);

inline bool ok(Status status) { return status == Status::kOk; }

}  // namespace tolip
