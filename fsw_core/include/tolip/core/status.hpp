// Status codes of every fsw_core operation that can fail.
//
// One enumerator per cause, named so that a user understands it; status_name() gives the
// enumerator's spelling and status_message() a sentence. Operations return Status and write
// their results through out-parameters; nothing in the core throws.
#pragma once

namespace tolip {

// [[nodiscard]], on this opaque declaration (the definition's head, so written, is one clang-format 14
// misreads): a caller that drops a Status fails the build (-Werror in the core, ground tools and
// hal_sim; -Werror=unused-result in the tests and benchmarks): Power of Ten rule 7, every return
// value checked (docs/verification/static-analysis.md).
enum class [[nodiscard]] Status : int;

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
  // Generic: the core returns a named cause instead (the enumerators after kTableImageVersion2); kept
  // so that the numbers after it stay, for a caller outside the core with no better name.
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
  // Returned by nothing since data block 9 left the core (the deck readers check it, issue 18); kept
  // so that the numbers after it stay (the HIL link and the MPI transport carry a status by number).
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
  // The case was not prepared: prepare_case() did not run (PreparedCase::prepared is false), and the
  // initial status of a result nothing has filled yet.
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
  // Returned by nothing since the stacked stage-4/5 tables fly (issue 11); kept so that the
  // enumerators after it keep their numbers.
  kDispersionNotImplemented,
  kDispersionNeedsBodyDynamics,
  kDispersionStageNotInSequence,
  kDispersionStageNotSpun,
  kDispersionCodeInvalid,
  // Impact locus (impact/impact.hpp, manual Sec. 17)
  kImpactDataMissing,
  kImpactNotReached,
  // Radar tracking (radar/radar.hpp, manual Sec. 18)
  kRadarStationCountInvalid,
  kRadarStationLatitudeOutOfRange,
  kRadarStationNotFinite,
  kRadarNoTrajectory,
  // Hardover turns (hardover/hardover.hpp, manual Sec. 16); HardoverFault names block, word, stage
  kHardoverEveryNthStepInvalid,
  kHardoverStepLimitsInvalid,
  kHardoverAttitudeStepInvalid,
  kHardoverMaxStepsInvalid,
  kHardoverOutputIntervalTooSmall,
  kHardoverQbarAlphaLimitInvalid,
  kHardoverInertiaMissing,
  kHardoverInertiaNotPositive,
  kHardoverDampingTableMissing,
  kHardoverValueNotFinite,
  kHardoverBodyDataMissing,
  kHardoverPointInvalid,
  kTooManyHardoverTurns,
  // Hardware abstraction and the flight application (hal/hal.hpp, docs/hil.md)
  kHalPortMissing,
  kHalClockOverrun,
  kHalSensorInvalid,
  kHalActuatorRejected,
  kHalTableStoreFailed,
  kHalTelemetryFailed,
  kHalDiscretesInvalid,
  kHalLinkFrameCorrupt,
  // Autopilot gain design and schedules (autopilot/autopilot_design.hpp, table/table_image.hpp; issue 16)
  kAutopilotDampingNotPositive,
  kAutopilotFrequencyNotPositive,
  kAutopilotRequestInvalid,
  kAutopilotModelInvalid,
  kAutopilotFrequencyBeyondDeflection,
  kAutopilotGainOutOfRange,
  kTooManyGainSchedulePoints,
  kGainScheduleStageInvalid,
  kGainScheduleTimesNotMonotonic,
  kTableImageVersion2,
  // Causes that once shared kValueOutOfRange or kNotPrepared (issue 18), by module; appended so that the
  // numbers of the enumerators above (the HIL link and the MPI transport carry them) stay the same.
  // Arguments (every module): a programming error at a function boundary.
  kOutputPointerNull,
  kOutputAliasesInput,
  // Heating rate (orbit/orbit_elements.hpp, optimizer/constraint_parameters.hpp; manual Sec. 13)
  kNoseRadiusNotPositive,
  kSeaLevelDensityNotPositive,
  kHeatingStateNegative,
  // Atmosphere (atmosphere/atmosphere.hpp; manual Sec. 19)
  kAtmosphereRadiusNotPositive,
  kAtmosphereTemperatureNotPositive,
  // Trajectory (trajectory/trajectory.hpp): FlightInputs that do not fit together
  kFeedbackWithoutLiveProgram,
  kResumeInputsIncompatible,
  kResumeStageSlotInvalid,
  kResumeStageNotRecorded,
  // Thrust modification (vehicle/prepared_case.hpp; manual Sec. 6)
  kModifiedThrustIdealVelocityInvalid,
  // Constraints and the optimizer (optimizer/; manual Sec. 9-13, 21)
  kConstraintPointNotInTrajectory,
  kLinearizedPayloadNegative,
  kBackwardRunWithoutTrajectory,
  kOptimizerResultIncomplete,
  kFinalTrajectoryMissing,
  // Exchange ratios (optimizer/exchange_ratios.hpp; manual Sec. 8)
  kExchangePercentChangeTooNegative,
  kExchangeStageWithoutPropellant,
  kExchangePropellantChangeTooNegative,
  kUnknownExchangeParameter,
  // Impact locus (impact/impact.hpp; manual Sec. 17); ImpactFault names block, stage, word
  kImpactDragTableNotFromMach0,
  kImpactDragCoefficientInvalid,
  kImpactReferenceAreaNotPositive,
  kImpactCasingWeightNotPositive,
  kImpactEveryNthPointOutOfRange,
  kImpactStepSizeNotPositive,
  kImpactStartInvalid,
  kImpactStartBelowSurface,
  kImpactNominalFailed,
  kImpactNominalStageIncomplete,
  // Dispersions and Monte Carlo (dispersion/; manual Sec. 15): the data block 46 code at fault is reported
  kDispersionNominalNotPrepared,
  kDispersionStageCodeMismatch,
  kDispersionThrustTableTimesInvalid,
  kDispersionThrustNegative,
  kDispersionDragVariationOutOfRange,
  kTrajectoryEmpty,
  kMonteCarloBurnTimeNotPositive,
  kMonteCarloThrustNegative,
  // Guidance table image (table/table_image.hpp; docs/table-format.md): the field out of its range
  kTableSpinOptionOutOfRange,
  kTableCreationTimeOutOfRange,
  kTableLiftoffDurationOutOfRange,
  kTablePitchRateLimitOutOfRange,
  kTableMinPitchRateOutOfRange,
  kTablePitchRateChangeOutOfRange,
  kTableDeflectionLimitOutOfRange,
  kTableUpperStageAttitudeOutOfRange,
  kTableGainOutOfRange,
  kSegmentStartTimeOutOfRange,
  kSegmentAttitudeOutOfRange,
  kGainScheduleTimeOutOfRange,
  // Ground runs (ground_tools/): a step that needs an earlier one that did not finish
  kLinearizationNotFinished,
  // Data block 33, DA6D(12-15): the 6D integration frequency multipliers (Sec. 22)
  kIntegrationMultiplierNotInteger,
  kIntegrationMultiplierBelowOne,
  kIntegrationMultiplierAboveCapacity,
  // Codes 7-8 with data block 55: the stacked stage-4/5 tables of page 22-30 (dispersion.hpp)
  kDispersionStageDurationsMismatch,
  kDispersionStackedTablesNotSplittable,
  kDispersionStackedTablesNeedStage5,
  // Data block 4 against data block 5 and IP(9): the stage-5 yaw option IP(10) (Sec. 22)
  kStage5YawOptionInconsistent,
  // Sec. 7: a unit moment, an autopilot gain or the command that reaches eqs. 7-6 and 7-7 not finite
  kBodyDynamicsNotFinite,
};

const char* status_name(Status status);
const char* status_message(Status status);

inline bool ok(Status status) { return status == Status::kOk; }

}  // namespace tolip
