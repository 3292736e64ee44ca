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
  kLiftoffNotPositive,
  kZeroLengthCoast,
  kAdjustableCoastNotInSequence,
  kAdjustableAttitudeNotSpun,
  kSpinOptionInconsistent,
  kInitialConditionsInvalid,
  kAtmosphereTableInvalid,
  kBodyDynamicsDataMissing,
  kControlStationAtCenterOfGravity,
  kThrustWithoutPropellant,
  kConsumableWeightIncreases,
  // Range checks of validate_mission() (mission/mission.hpp), in its data-block order: one per
  // cause; its MissionFault names the data block, stage, field, element, value and range.
  kOptionOutOfRange,
  kBodyDynamicsRelinearizationWithoutLinearization,
  kConstantOutOfRange,
  kNegativeArea,
  kReferenceAreaMissing,
  kPropulsionInCoast,
  kTableTimeNegative,
  kNegativeThrust,
  kLaunchConditionOutOfRange,
  kPitchRateLimitNegative,
  kZeroAlphaWindowInvalid,
  kMiscellaneousDataOutOfRange,
  kCoastChangeLimitMissing,
  kNoPayoffConstraint,
  kPayloadCodeNotFirst,
  kDuplicateConstraintCode,
  kPayoffCodeMismatch,
  kHeatingCodeMismatch,
  kDeadbandNotPositive,
  kNegativeCount,
  kUnknownAdjustableParameterCode,
  kDuplicateAdjustableParameterCode,
  kWeightingFactorNotPositive,
  kCodedTimeAfterUnusedEntry,
  kCodedTimeStageInvalid,
  kLinearizationWithoutSegments,
  kSteeredStageWithoutSegments,
  kCodedTimeInSpunStage,
  kSegmentCountMismatch,
  kConvergenceDataOutOfRange,
  kOutputFrequencyNotPositive,
  kBodyDynamicsValueOutOfRange,
  kPitchAttitudeOutOfRange,
  // Constraint parameters (optimizer/constraint_parameters.hpp)
  kUnknownConstraintCode,
  kConstraintNotHyperbolic,
  kConstraintSingular,
  // Run-time failures
  kNonFiniteState,
  kAltitudeBelowSurface,
  kZeroVelocity,
  kMassNotPositive,
  kTrajectoryStorageFull,
  kControlProgramSizeMismatch,
  kSteeringMatrixSingular,
  // The optimizer did not converge (Sec. 22 sequence): which phase failed.
  kGuidanceDidNotConverge,
  kOptimizationNotStarted,
  kOptimizationBudgetExhausted,
  kFinalGuidanceFailed,
  kLinearizationDidNotConverge,
  kAdjustableParameterNotSupported,
  kPayoffNotSupported,
  kBodyDynamicsNotTrimmable,
  kNotPrepared,
  // Guidance table image, loader and executor (table/; docs/table-format.md)
  kTableImageTruncated,
  kTableImageSizeMismatch,
  kTableImageBadMagic,
  kTableImageUnsupportedVersion,
  kTableImageLayoutMismatch,
  kTableImageCrcMismatch,
  kTableImageReservedBytesSet,
  kTableImageTextInvalid,
  kSegmentStageInvalid,
  kSegmentTimesNotMonotonic,
  kSegmentRateExceedsLimit,
  kTableNotStaged,
  kTableNotValidated,
  kNoActiveTable,
  kStageEventOutOfOrder,
  // Dispersion analysis (dispersion/dispersion.hpp, manual Sec. 15)
  kDispersionNotImplemented,
  kDispersionNeedsBodyDynamics,
  kDispersionStageNotInSequence,
  kDispersionStageNotSpun,
  kDispersionCodeInvalid,
  // Radar tracking (radar/radar.hpp, manual Sec. 18)
  kRadarStationCountInvalid,
  kRadarStationLatitudeOutOfRange,
  kRadarStationNotFinite,
  kRadarNoTrajectory,
};

const char* status_name(Status status);
const char* status_message(Status status);

inline bool ok(Status status) { return status == Status::kOk; }

}  // namespace tolip
