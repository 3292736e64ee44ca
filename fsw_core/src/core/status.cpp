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
    case Status::kLiftoffNotPositive: return "kLiftoffNotPositive";
    case Status::kZeroLengthCoast: return "kZeroLengthCoast";
    case Status::kAdjustableCoastNotInSequence: return "kAdjustableCoastNotInSequence";
    case Status::kAdjustableAttitudeNotSpun: return "kAdjustableAttitudeNotSpun";
    case Status::kSpinOptionInconsistent: return "kSpinOptionInconsistent";
    case Status::kInitialConditionsInvalid: return "kInitialConditionsInvalid";
    case Status::kAtmosphereTableInvalid: return "kAtmosphereTableInvalid";
    case Status::kBodyDynamicsDataMissing: return "kBodyDynamicsDataMissing";
    case Status::kControlStationAtCenterOfGravity: return "kControlStationAtCenterOfGravity";
    case Status::kThrustWithoutPropellant: return "kThrustWithoutPropellant";
    case Status::kConsumableWeightIncreases: return "kConsumableWeightIncreases";
    case Status::kOptionOutOfRange: return "kOptionOutOfRange";
    case Status::kBodyDynamicsRelinearizationWithoutLinearization:
      return "kBodyDynamicsRelinearizationWithoutLinearization";
    case Status::kConstantOutOfRange: return "kConstantOutOfRange";
    case Status::kNegativeArea: return "kNegativeArea";
    case Status::kReferenceAreaMissing: return "kReferenceAreaMissing";
    case Status::kPropulsionInCoast: return "kPropulsionInCoast";
    case Status::kTableTimeNegative: return "kTableTimeNegative";
    case Status::kNegativeThrust: return "kNegativeThrust";
    case Status::kLaunchConditionOutOfRange: return "kLaunchConditionOutOfRange";
    case Status::kPitchRateLimitNegative: return "kPitchRateLimitNegative";
    case Status::kZeroAlphaWindowInvalid: return "kZeroAlphaWindowInvalid";
    case Status::kMiscellaneousDataOutOfRange: return "kMiscellaneousDataOutOfRange";
    case Status::kCoastChangeLimitMissing: return "kCoastChangeLimitMissing";
    case Status::kNoPayoffConstraint: return "kNoPayoffConstraint";
    case Status::kPayloadCodeNotFirst: return "kPayloadCodeNotFirst";
    case Status::kDuplicateConstraintCode: return "kDuplicateConstraintCode";
    case Status::kPayoffCodeMismatch: return "kPayoffCodeMismatch";
    case Status::kHeatingCodeMismatch: return "kHeatingCodeMismatch";
    case Status::kDeadbandNotPositive: return "kDeadbandNotPositive";
    case Status::kNegativeCount: return "kNegativeCount";
    case Status::kUnknownAdjustableParameterCode: return "kUnknownAdjustableParameterCode";
    case Status::kDuplicateAdjustableParameterCode: return "kDuplicateAdjustableParameterCode";
    case Status::kWeightingFactorNotPositive: return "kWeightingFactorNotPositive";
    case Status::kCodedTimeAfterUnusedEntry: return "kCodedTimeAfterUnusedEntry";
    case Status::kCodedTimeStageInvalid: return "kCodedTimeStageInvalid";
    case Status::kLinearizationWithoutSegments: return "kLinearizationWithoutSegments";
    case Status::kSteeredStageWithoutSegments: return "kSteeredStageWithoutSegments";
    case Status::kCodedTimeInSpunStage: return "kCodedTimeInSpunStage";
    case Status::kSegmentCountMismatch: return "kSegmentCountMismatch";
    case Status::kConvergenceDataOutOfRange: return "kConvergenceDataOutOfRange";
    case Status::kOutputFrequencyNotPositive: return "kOutputFrequencyNotPositive";
    case Status::kBodyDynamicsValueOutOfRange: return "kBodyDynamicsValueOutOfRange";
    case Status::kPitchAttitudeOutOfRange: return "kPitchAttitudeOutOfRange";
    case Status::kUnknownConstraintCode: return "kUnknownConstraintCode";
    case Status::kConstraintNotHyperbolic: return "kConstraintNotHyperbolic";
    case Status::kConstraintSingular: return "kConstraintSingular";
    case Status::kNonFiniteState: return "kNonFiniteState";
    case Status::kAltitudeBelowSurface: return "kAltitudeBelowSurface";
    case Status::kZeroVelocity: return "kZeroVelocity";
    case Status::kMassNotPositive: return "kMassNotPositive";
    case Status::kTrajectoryStorageFull: return "kTrajectoryStorageFull";
    case Status::kControlProgramSizeMismatch: return "kControlProgramSizeMismatch";
    case Status::kSteeringMatrixSingular: return "kSteeringMatrixSingular";
    case Status::kGuidanceDidNotConverge: return "kGuidanceDidNotConverge";
    case Status::kOptimizationNotStarted: return "kOptimizationNotStarted";
    case Status::kOptimizationBudgetExhausted: return "kOptimizationBudgetExhausted";
    case Status::kFinalGuidanceFailed: return "kFinalGuidanceFailed";
    case Status::kLinearizationDidNotConverge: return "kLinearizationDidNotConverge";
    case Status::kAdjustableParameterNotSupported: return "kAdjustableParameterNotSupported";
    case Status::kPayoffNotSupported: return "kPayoffNotSupported";
    case Status::kBodyDynamicsNotTrimmable: return "kBodyDynamicsNotTrimmable";
    case Status::kBodyDynamicsNotFinite: return "kBodyDynamicsNotFinite";
    case Status::kNotPrepared: return "kNotPrepared";
    case Status::kTableImageTruncated: return "kTableImageTruncated";
    case Status::kTableImageSizeMismatch: return "kTableImageSizeMismatch";
    case Status::kTableImageBadMagic: return "kTableImageBadMagic";
    case Status::kTableImageUnsupportedVersion: return "kTableImageUnsupportedVersion";
    case Status::kTableImageLayoutMismatch: return "kTableImageLayoutMismatch";
    case Status::kTableImageCrcMismatch: return "kTableImageCrcMismatch";
    case Status::kTableImageReservedBytesSet: return "kTableImageReservedBytesSet";
    case Status::kTableImageTextInvalid: return "kTableImageTextInvalid";
    case Status::kSegmentStageInvalid: return "kSegmentStageInvalid";
    case Status::kSegmentTimesNotMonotonic: return "kSegmentTimesNotMonotonic";
    case Status::kSegmentRateExceedsLimit: return "kSegmentRateExceedsLimit";
    case Status::kTableNotStaged: return "kTableNotStaged";
    case Status::kTableNotValidated: return "kTableNotValidated";
    case Status::kNoActiveTable: return "kNoActiveTable";
    case Status::kStageEventOutOfOrder: return "kStageEventOutOfOrder";
    case Status::kDispersionNotImplemented: return "kDispersionNotImplemented";
    case Status::kDispersionNeedsBodyDynamics: return "kDispersionNeedsBodyDynamics";
    case Status::kDispersionStageNotInSequence: return "kDispersionStageNotInSequence";
    case Status::kDispersionStageNotSpun: return "kDispersionStageNotSpun";
    case Status::kDispersionCodeInvalid: return "kDispersionCodeInvalid";
    case Status::kImpactDataMissing: return "kImpactDataMissing";
    case Status::kImpactNotReached: return "kImpactNotReached";
    case Status::kRadarStationCountInvalid: return "kRadarStationCountInvalid";
    case Status::kRadarStationLatitudeOutOfRange: return "kRadarStationLatitudeOutOfRange";
    case Status::kRadarStationNotFinite: return "kRadarStationNotFinite";
    case Status::kRadarNoTrajectory: return "kRadarNoTrajectory";
    case Status::kHardoverEveryNthStepInvalid: return "kHardoverEveryNthStepInvalid";
    case Status::kHardoverStepLimitsInvalid: return "kHardoverStepLimitsInvalid";
    case Status::kHardoverAttitudeStepInvalid: return "kHardoverAttitudeStepInvalid";
    case Status::kHardoverMaxStepsInvalid: return "kHardoverMaxStepsInvalid";
    case Status::kHardoverOutputIntervalTooSmall: return "kHardoverOutputIntervalTooSmall";
    case Status::kHardoverQbarAlphaLimitInvalid: return "kHardoverQbarAlphaLimitInvalid";
    case Status::kHardoverInertiaMissing: return "kHardoverInertiaMissing";
    case Status::kHardoverInertiaNotPositive: return "kHardoverInertiaNotPositive";
    case Status::kHardoverDampingTableMissing: return "kHardoverDampingTableMissing";
    case Status::kHardoverValueNotFinite: return "kHardoverValueNotFinite";
    case Status::kHardoverBodyDataMissing: return "kHardoverBodyDataMissing";
    case Status::kHardoverPointInvalid: return "kHardoverPointInvalid";
    case Status::kTooManyHardoverTurns: return "kTooManyHardoverTurns";
    case Status::kHalPortMissing: return "kHalPortMissing";
    case Status::kHalClockOverrun: return "kHalClockOverrun";
    case Status::kHalSensorInvalid: return "kHalSensorInvalid";
    case Status::kHalActuatorRejected: return "kHalActuatorRejected";
    case Status::kHalTableStoreFailed: return "kHalTableStoreFailed";
    case Status::kHalTelemetryFailed: return "kHalTelemetryFailed";
    case Status::kHalDiscretesInvalid: return "kHalDiscretesInvalid";
    case Status::kHalLinkFrameCorrupt: return "kHalLinkFrameCorrupt";
    case Status::kAutopilotDampingNotPositive: return "kAutopilotDampingNotPositive";
    case Status::kAutopilotFrequencyNotPositive: return "kAutopilotFrequencyNotPositive";
    case Status::kAutopilotRequestInvalid: return "kAutopilotRequestInvalid";
    case Status::kAutopilotModelInvalid: return "kAutopilotModelInvalid";
    case Status::kAutopilotFrequencyBeyondDeflection: return "kAutopilotFrequencyBeyondDeflection";
    case Status::kAutopilotGainOutOfRange: return "kAutopilotGainOutOfRange";
    case Status::kTooManyGainSchedulePoints: return "kTooManyGainSchedulePoints";
    case Status::kGainScheduleStageInvalid: return "kGainScheduleStageInvalid";
    case Status::kGainScheduleTimesNotMonotonic: return "kGainScheduleTimesNotMonotonic";
    case Status::kTableImageVersion2: return "kTableImageVersion2";
    case Status::kOutputPointerNull: return "kOutputPointerNull";
    case Status::kOutputAliasesInput: return "kOutputAliasesInput";
    case Status::kNoseRadiusNotPositive: return "kNoseRadiusNotPositive";
    case Status::kSeaLevelDensityNotPositive: return "kSeaLevelDensityNotPositive";
    case Status::kHeatingStateNegative: return "kHeatingStateNegative";
    case Status::kAtmosphereRadiusNotPositive: return "kAtmosphereRadiusNotPositive";
    case Status::kAtmosphereTemperatureNotPositive: return "kAtmosphereTemperatureNotPositive";
    case Status::kFeedbackWithoutLiveProgram: return "kFeedbackWithoutLiveProgram";
    case Status::kResumeInputsIncompatible: return "kResumeInputsIncompatible";
    case Status::kResumeStageSlotInvalid: return "kResumeStageSlotInvalid";
    case Status::kResumeStageNotRecorded: return "kResumeStageNotRecorded";
    case Status::kModifiedThrustIdealVelocityInvalid: return "kModifiedThrustIdealVelocityInvalid";
    case Status::kConstraintPointNotInTrajectory: return "kConstraintPointNotInTrajectory";
    case Status::kLinearizedPayloadNegative: return "kLinearizedPayloadNegative";
    case Status::kBackwardRunWithoutTrajectory: return "kBackwardRunWithoutTrajectory";
    case Status::kOptimizerResultIncomplete: return "kOptimizerResultIncomplete";
    case Status::kFinalTrajectoryMissing: return "kFinalTrajectoryMissing";
    case Status::kExchangePercentChangeTooNegative: return "kExchangePercentChangeTooNegative";
    case Status::kExchangeStageWithoutPropellant: return "kExchangeStageWithoutPropellant";
    case Status::kExchangePropellantChangeTooNegative: return "kExchangePropellantChangeTooNegative";
    case Status::kUnknownExchangeParameter: return "kUnknownExchangeParameter";
    case Status::kImpactDragTableNotFromMach0: return "kImpactDragTableNotFromMach0";
    case Status::kImpactDragCoefficientInvalid: return "kImpactDragCoefficientInvalid";
    case Status::kImpactReferenceAreaNotPositive: return "kImpactReferenceAreaNotPositive";
    case Status::kImpactCasingWeightNotPositive: return "kImpactCasingWeightNotPositive";
    case Status::kImpactEveryNthPointOutOfRange: return "kImpactEveryNthPointOutOfRange";
    case Status::kImpactStepSizeNotPositive: return "kImpactStepSizeNotPositive";
    case Status::kImpactStartInvalid: return "kImpactStartInvalid";
    case Status::kImpactStartBelowSurface: return "kImpactStartBelowSurface";
    case Status::kImpactNominalFailed: return "kImpactNominalFailed";
    case Status::kImpactNominalStageIncomplete: return "kImpactNominalStageIncomplete";
    case Status::kDispersionNominalNotPrepared: return "kDispersionNominalNotPrepared";
    case Status::kDispersionStageCodeMismatch: return "kDispersionStageCodeMismatch";
    case Status::kDispersionThrustTableTimesInvalid: return "kDispersionThrustTableTimesInvalid";
    case Status::kDispersionThrustNegative: return "kDispersionThrustNegative";
    case Status::kDispersionDragVariationOutOfRange: return "kDispersionDragVariationOutOfRange";
    case Status::kTrajectoryEmpty: return "kTrajectoryEmpty";
    case Status::kMonteCarloBurnTimeNotPositive: return "kMonteCarloBurnTimeNotPositive";
    case Status::kMonteCarloThrustNegative: return "kMonteCarloThrustNegative";
    case Status::kTableSpinOptionOutOfRange: return "kTableSpinOptionOutOfRange";
    case Status::kTableCreationTimeOutOfRange: return "kTableCreationTimeOutOfRange";
    case Status::kTableLiftoffDurationOutOfRange: return "kTableLiftoffDurationOutOfRange";
    case Status::kTablePitchRateLimitOutOfRange: return "kTablePitchRateLimitOutOfRange";
    case Status::kTableMinPitchRateOutOfRange: return "kTableMinPitchRateOutOfRange";
    case Status::kTablePitchRateChangeOutOfRange: return "kTablePitchRateChangeOutOfRange";
    case Status::kTableDeflectionLimitOutOfRange: return "kTableDeflectionLimitOutOfRange";
    case Status::kTableUpperStageAttitudeOutOfRange: return "kTableUpperStageAttitudeOutOfRange";
    case Status::kTableGainOutOfRange: return "kTableGainOutOfRange";
    case Status::kSegmentStartTimeOutOfRange: return "kSegmentStartTimeOutOfRange";
    case Status::kSegmentAttitudeOutOfRange: return "kSegmentAttitudeOutOfRange";
    case Status::kGainScheduleTimeOutOfRange: return "kGainScheduleTimeOutOfRange";
    case Status::kLinearizationNotFinished: return "kLinearizationNotFinished";
    case Status::kIntegrationMultiplierNotInteger: return "kIntegrationMultiplierNotInteger";
    case Status::kIntegrationMultiplierBelowOne: return "kIntegrationMultiplierBelowOne";
    case Status::kIntegrationMultiplierAboveCapacity: return "kIntegrationMultiplierAboveCapacity";
    case Status::kDispersionStageDurationsMismatch: return "kDispersionStageDurationsMismatch";
    case Status::kDispersionStackedTablesNotSplittable: return "kDispersionStackedTablesNotSplittable";
    case Status::kDispersionStackedTablesNeedStage5: return "kDispersionStackedTablesNeedStage5";
    case Status::kStage5YawOptionInconsistent: return "kStage5YawOptionInconsistent";
  }
  return "kUnknownStatus";
}

const char* status_message(Status status) {
  switch (status) {
    case Status::kOk: return "success";
    case Status::kTooManyTablePoints: return "a table has more points than its capacity";
    case Status::kTooManyThrustPointsInAllStages:
      return "the thrust tables of all stages together exceed 120 points";
    case Status::kTooManyWeightPointsInAllStages:
      return "the weight tables of all stages together exceed 120 points";
    case Status::kTooManyPoweredSteps:
      return "the powered stages together have more than 168 integration steps";
    case Status::kTooManyPoweredStepsWithFollowingCoast:
      return "the powered stages and coast 6 together have more than 177 integration steps";
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
    case Status::kStageSequenceInvalid:
      return "the stage sequence must start with stage 1 and follow the order 1 6 2 7 3 8 4 9 5 10: each "
             "powered stage is the next one, each coast n+5 comes directly after its stage n, and a coast "
             "may be left out (powered stages then burn back to back)";
    case Status::kUnknownStageCode: return "a stage code is not one of 1-10";
    case Status::kMissingThrustTable: return "a powered stage has no vacuum thrust table";
    case Status::kMissingWeightTable: return "a powered stage has no consumable-weight table";
    case Status::kThrustWeightTimesDiffer:
      return "thrust and weight tables of a stage end at different times";
    case Status::kStageDurationMismatch:
      return "a powered stage duration differs from the last time of its thrust table";
    case Status::kLiftoffLongerThanStage1: return "the lift-off interval is not shorter than stage 1";
    case Status::kLiftoffNotPositive:
      return "the closed-form lift-off DA5(1) must last more than 0 s: the integration starts from its end "
             "state, and at V = 0 the equations of motion are singular (flight-path angle and heading "
             "undefined)";
    case Status::kZeroLengthCoast:
      return "a coast of the stage sequence lasts 0 s: leave the coast out of the stage sequence (data block "
             "5) instead, the powered stages around it then burn back to back with the jettison at the "
             "boundary";
    case Status::kAdjustableCoastNotInSequence:
      return "a coast length is an adjustable parameter (data block 6) but that coast is not in the stage "
             "sequence (data block 5)";
    case Status::kAdjustableAttitudeNotSpun:
      return "a spun-stage attitude is an adjustable parameter (data block 6 codes 1, 2, 8, 9) but IP(9) "
             "does not spin that stage on its own attitudes";
    case Status::kSpinOptionInconsistent:
      return "IP(9) does not fit the stage sequence: stage 4 flown needs 1, 2 or 3, and 3 (stages 4 and 5 "
             "continuous) needs stage 5";
    case Status::kInitialConditionsInvalid:
      return "initial conditions must have zero velocity and a 90 degree flight-path angle";
    case Status::kAtmosphereTableInvalid: return "the atmosphere table is inconsistent";
    case Status::kBodyDynamicsDataMissing:
      return "a 6D (body dynamics) trajectory needs data blocks 33-37 (gains, stations, reference length and "
             "area, the block 34-36 tables and the stage-1 c.g. history), which the case does not give "
             "completely";
    case Status::kControlStationAtCenterOfGravity:
      return "the stage-1 control station DA6D(7) lies within the range of the stage-1 c.g. stations of data "
             "block 37, so X_delta - X_CG would vanish";
    case Status::kThrustWithoutPropellant:
      return "a powered stage has thrust where no consumable weight (propellant) remains";
    case Status::kConsumableWeightIncreases:
      return "the consumable weight remaining of a powered stage increases during the burn";
    case Status::kOptionOutOfRange:
      return "an option IP(n) of data block 4 has a value the manual does not define for it";
    case Status::kBodyDynamicsRelinearizationWithoutLinearization:
      return "IP(6) = 1 (the 6D re-linearization) needs IP(7) = 1 (the linearization)";
    case Status::kConstantOutOfRange: return "a constant of data block 10 is outside its physical range";
    case Status::kNegativeArea: return "a reference or nozzle exit area of data block 39 is negative";
    case Status::kReferenceAreaMissing:
      return "a stage with a drag or lift table (data blocks 31, 32) has no positive reference area (data "
             "block 39)";
    case Status::kPropulsionInCoast:
      return "a coast carries a thrust table, a consumable weight table or a nozzle exit area";
    case Status::kTableTimeNegative: return "a thrust or consumable weight table starts before stage time 0";
    case Status::kNegativeThrust: return "a vacuum thrust of data block 30 is negative";
    case Status::kLaunchConditionOutOfRange:
      return "a launch condition of data block 21 (altitude, longitude, latitude, azimuth, heading hold) is "
             "outside its range";
    case Status::kPitchRateLimitNegative: return "a pitch-rate limit of data block 22 is negative";
    case Status::kZeroAlphaWindowInvalid:
      return "the zero-alpha window of data block 22 (IP(11)) does not lie inside stage 1";
    case Status::kMiscellaneousDataOutOfRange: return "a word of data block 17 is outside its range";
    case Status::kCoastChangeLimitMissing:
      return "a coast length is an adjustable parameter but the coast change limit DA2(16) of data block 17 "
             "is not positive";
    case Status::kNoPayoffConstraint:
      return "data block 8 lists no constraint: the payoff entry comes first and is required";
    case Status::kPayloadCodeNotFirst:
      return "the payload code 0 of data block 8 may only be the payoff, the first entry";
    case Status::kDuplicateConstraintCode: return "a constraint code is listed twice in data block 8";
    case Status::kPayoffCodeMismatch:
      return "the payoff code of data block 8 does not match the payoff IP(1) asks for";
    case Status::kHeatingCodeMismatch:
      return "the heating code 14 must follow the counted constraints of data block 8 exactly when IP(2) = 1";
    case Status::kDeadbandNotPositive: return "a deadband of data block 29 is not positive";
    case Status::kNegativeCount:
      return "the count of adjustable parameters (data block 6) or of linear segments (data block 18) is "
             "negative";
    case Status::kUnknownAdjustableParameterCode:
      return "an adjustable-parameter code of data block 6 is not one of 1-11";
    case Status::kDuplicateAdjustableParameterCode:
      return "an adjustable-parameter code is listed twice in data block 6";
    case Status::kWeightingFactorNotPositive:
      return "a weighting factor of data block 26 or 27 is not positive";
    case Status::kCodedTimeAfterUnusedEntry:
      return "a coded segment start time of data block 18 follows an unused (zero) entry";
    case Status::kCodedTimeStageInvalid:
      return "a coded segment start time 100 n + t of data block 18 names no powered stage n of the sequence";
    case Status::kLinearizationWithoutSegments:
      return "IP(7) = 1 (linearization) needs the segment start times of data block 18";
    case Status::kSteeredStageWithoutSegments:
      return "IP(7) = 1 (linearization): a stage that flies the pitch program (stages 4 and 5 too when IP(9) "
             "steers them) has no coded start time 100 n + t in data block 18";
    case Status::kCodedTimeInSpunStage:
      return "a data block 18 coded time 100 n + t lies in a stage that IP(9) spins (a spun stage holds its "
             "data block 17 attitudes; it has no pitch segments)";
    case Status::kSegmentCountMismatch:
      return "the segment count of data block 18 is not the number of coded start times less one";
    case Status::kConvergenceDataOutOfRange:
      return "a convergence control of data block 28 is outside its range";
    case Status::kOutputFrequencyNotPositive: return "an output frequency of data block 9 is below 1";
    case Status::kBodyDynamicsValueOutOfRange:
      return "a body-dynamics word of data block 33 is outside its range";
    case Status::kPitchAttitudeOutOfRange:
      return "an attitude of the data block 40 pitch program is beyond one turn";
    case Status::kUnknownConstraintCode:
      return "a data block 8 constraint code is not 0-14, 10X+5 to 10X+9 (X = 1-9) or 100-102";
    case Status::kConstraintNotHyperbolic:
      return "a hyperbolic-asymptote constraint (100-102) needs a hyperbolic orbit (2E > 0)";
    case Status::kConstraintSingular:
      return "the constraint has no derivative at this state (equatorial or circular orbit, vertical "
             "inertial velocity, zero range)";
    case Status::kNonFiniteState: return "the integration produced a NaN or infinite state";
    case Status::kAltitudeBelowSurface: return "the vehicle went below the Earth surface";
    case Status::kZeroVelocity: return "the velocity is zero where a direction is needed";
    case Status::kMassNotPositive: return "the vehicle mass is not positive";
    case Status::kTrajectoryStorageFull:
      return "the trajectory has more integration points than its fixed storage";
    case Status::kControlProgramSizeMismatch:
      return "the pitch program has a different number of points than the case's trajectory";
    case Status::kSteeringMatrixSingular:
      return "the steering matrix (integral of Lambda Lambda^T plus S Y^-1 S^T) could not be inverted: the "
             "constraints cannot be controlled independently";
    case Status::kLinearizationDidNotConverge:
      return "the linearized pitch program did not meet the constraints within the linearization deadbands "
             "and the rate limits in DA13(4) forward runs";
    case Status::kGuidanceDidNotConverge:
      return "not converged: the guidance runs used the forward-run budget DA13(3) without bringing every "
             "constraint inside its data block 29 deadband, so no optimization run was made";
    case Status::kOptimizationNotStarted:
      return "not converged: guidance met every deadband but no optimization run was made (the first "
             "payoff-improvement attempt was below DA13(2), or the forward-run budget DA13(3) left no room); "
             "the trajectory is feasible, not optimized";
    case Status::kOptimizationBudgetExhausted:
      return "not converged: the forward-run budget DA13(3) ended the optimization while payoff-improvement "
             "attempts above DA13(2) remained; the last feasible optimization run is reported (raise DA13(3) "
             "to go on)";
    case Status::kFinalGuidanceFailed:
      return "not converged: the final guidance run did not meet every data block 29 deadband; the last "
             "feasible optimization run is reported instead";
    case Status::kAdjustableParameterNotSupported:
      return "an adjustable parameter code of data block 6 is not supported by this optimizer yet";
    case Status::kBodyDynamicsNotTrimmable:
      return "the autopilot has no steady state (Sec. 7): K_theta M_delta - M_alpha is not positive, a "
             "statically unstable vehicle with too little control moment";
    case Status::kBodyDynamicsNotFinite:
      return "the autopilot's steady state (Sec. 7, eqs. 7-6 and 7-7) is not a finite number: a unit moment "
             "M_alpha or M_delta, an autopilot gain or the commanded attitude is not finite";
    case Status::kPayoffNotSupported:
      return "the payoff of data block 8 does not match option IP(1) or is not supported";
    case Status::kNotPrepared: return "the case was not prepared (prepare_case) before use";
    case Status::kTableImageTruncated: return "the table image is shorter than the format's fixed size";
    case Status::kTableImageSizeMismatch:
      return "the table image is longer than the format's fixed size, or its size field disagrees";
    case Status::kTableImageBadMagic: return "the table image does not start with the magic bytes TLGT";
    case Status::kTableImageUnsupportedVersion:
      return "the table image has a format version this loader does not read";
    case Status::kTableImageLayoutMismatch:
      return "the table image header's size fields do not match its format version";
    case Status::kTableImageCrcMismatch: return "the table image CRC-32 does not match its contents";
    case Status::kTableImageReservedBytesSet:
      return "a reserved or unused byte of the table image is not zero";
    case Status::kTableImageTextInvalid:
      return "the mission identifier or generator version is not NUL-padded printable ASCII";
    case Status::kSegmentStageInvalid:
      return "a pitch segment's stage code is not 1, 2, 3 or a coast 6, 7, 8 after them";
    case Status::kSegmentTimesNotMonotonic:
      return "pitch segments must follow the flight order of stages and strictly increasing start times "
             "within a stage";
    case Status::kSegmentRateExceedsLimit:
      return "a pitch segment's rate exceeds the maximum pitch rate the image carries";
    case Status::kTableNotStaged: return "no table image has been staged in the inactive buffer";
    case Status::kTableNotValidated: return "the staged table image has not passed validation";
    case Status::kNoActiveTable: return "no guidance table is active";
    case Status::kStageEventOutOfOrder:
      return "a stage event is earlier in time or in the flight order than the stage in force";
    case Status::kDispersionNotImplemented: return "this dispersion code is not computed by this version";
    case Status::kDispersionNeedsBodyDynamics:
      return "this dispersion acts through the body dynamics (Sec. 7, 15): the nominal must fly stage 1 with "
             "body dynamics (IP(6) = 1 with IP(7) = 1) and data blocks 33-37";
    case Status::kDispersionStageNotInSequence:
      return "the dispersion's stage is not in the stage sequence (data block 5)";
    case Status::kDispersionStageNotSpun:
      return "tip-off dispersions apply to a spin-stabilized stage 4 or 5 (IP(9))";
    case Status::kDispersionCodeInvalid:
      return "dispersion codes must be 1-38 or 40, in increasing order, each with the data its code needs "
             "(Sec. 22, data block 46)";
    case Status::kImpactDataMissing:
      return "the impact locus needs the failure-mode and casing drag tables (data blocks 42, 43) of every "
             "stage 1-3 in the sequence";
    case Status::kImpactNotReached:
      return "an impact trajectory did not reach the Earth's surface within its time limit";
    case Status::kRadarStationCountInvalid:
      return "the number of radar stations must be 1 to 20 (data block 41, header field 4)";
    case Status::kRadarStationLatitudeOutOfRange:
      return "a radar station's geodetic latitude must be within -90 to 90 deg (data block 41)";
    case Status::kRadarStationNotFinite:
      return "a radar station's latitude, longitude or altitude is not a finite number (data block 41)";
    case Status::kRadarNoTrajectory: return "radar tracking needs a trajectory with at least one point";
    case Status::kHardoverEveryNthStepInvalid:
      return "the hardover turns' every-n-th-step selector must be at least 1 (data block 45 words 1, 21, "
             "22)";
    case Status::kHardoverStepLimitsInvalid:
      return "the hardover step sizes must satisfy 0 < (DT)min <= (DT)max (data block 45 words 4-5, 24-25)";
    case Status::kHardoverAttitudeStepInvalid:
      return "the maximum attitude change per hardover step must be positive (data block 45 words 3, 23)";
    case Status::kHardoverMaxStepsInvalid:
      return "the maximum number of hardover steps per turn must be at least 1 (data block 45 words 6, 26)";
    case Status::kHardoverOutputIntervalTooSmall:
      return "the hardover output interval must be at least 0.1 s (data block 45 word 20): at most 101 "
             "lines per ten-second turn";
    case Status::kHardoverQbarAlphaLimitInvalid:
      return "(q-bar alpha)max must be positive (data block 45 word 2)";
    case Status::kHardoverInertiaMissing:
      return "a stage with hardover turns has no pitch moment of inertia table (data block 44, IYY1-IYY3)";
    case Status::kHardoverInertiaNotPositive:
      return "a pitch moment of inertia of data block 44 is not positive";
    case Status::kHardoverDampingTableMissing:
      return "the stage-1 pitch damping table CMQ (data block 44, stage code 4) is missing";
    case Status::kHardoverValueNotFinite: return "a hardover datum (data blocks 44-45) is not finite";
    case Status::kHardoverBodyDataMissing:
      return "hardover turns need data blocks 33 (X_FS, l_ref, K_TV) and 37 (the c.g. histories of stages "
             "1-3)";
    case Status::kHardoverPointInvalid:
      return "a hardover turn must start at a moving point of powered stage 1, 2 or 3 before its burnout";
    case Status::kTooManyHardoverTurns: return "more hardover turns than the core holds";
    case Status::kHalPortMissing:
      return "a hardware-abstraction port of the flight application has no function or a non-positive clock "
             "period";
    case Status::kHalClockOverrun:
      return "the minor-cycle clock reports an overrun: the previous cycle ran past its frame";
    case Status::kHalSensorInvalid: return "the inertial platform gave no valid sample this cycle";
    case Status::kHalActuatorRejected: return "the actuators refused the command";
    case Status::kHalTableStoreFailed: return "the non-volatile table store could not be read";
    case Status::kHalTelemetryFailed: return "the telemetry sink refused a frame";
    case Status::kHalDiscretesInvalid: return "the stage discretes could not be read";
    case Status::kHalLinkFrameCorrupt: return "a link frame was lost or failed its CRC";
    case Status::kAutopilotDampingNotPositive: return "autopilot damping ratio must be positive";
    case Status::kAutopilotFrequencyNotPositive: return "autopilot natural frequency must be positive";
    case Status::kAutopilotRequestInvalid:
      return "autopilot design attitude error and deflection limit must be positive, actuator time constant "
             "not negative";
    case Status::kAutopilotModelInvalid:
      return "no short-period model at this point: pitch inertia and control moment M_delta must be positive";
    case Status::kAutopilotFrequencyBeyondDeflection:
      return "the deflection limit cannot deliver the requested autopilot frequency for the design attitude "
             "error";
    case Status::kAutopilotGainOutOfRange:
      return "designed autopilot gain outside the table's range [0, 100]";
    case Status::kTooManyGainSchedulePoints: return "more gain schedule points than the table holds";
    case Status::kGainScheduleStageInvalid:
      return "gain schedule record of a stage code outside 1-10, or records not in flight order";
    case Status::kGainScheduleTimesNotMonotonic:
      return "gain schedule times not strictly increasing within a stage";
    case Status::kTableImageVersion2:
      return "table image format version 2 (812 bytes, no autopilot gain schedule): this loader reads "
             "version 3 "
             "only; export the case again";
    case Status::kOutputPointerNull:
      return "an output argument is a null pointer (a caller's programming error)";
    case Status::kOutputAliasesInput:
      return "the output argument is the input argument itself; they must be distinct objects";
    case Status::kNoseRadiusNotPositive:
      return "the heating rate (Sec. 13) needs a positive nose radius DA2(7) of data block 17";
    case Status::kSeaLevelDensityNotPositive:
      return "the heating rate (Sec. 13) needs a positive sea-level density (the first layer of the "
             "atmosphere table, Sec. 19)";
    case Status::kHeatingStateNegative:
      return "the heating rate (Sec. 13) was asked at a negative air density or velocity";
    case Status::kAtmosphereRadiusNotPositive:
      return "the atmosphere was asked at a point at or below the Earth's centre, or with an Earth radius "
             "that is not positive";
    case Status::kAtmosphereTemperatureNotPositive:
      return "the molecular temperature of the atmosphere layer falls to zero or below at this altitude: no "
             "atmosphere exists there";
    case Status::kFeedbackWithoutLiveProgram:
      return "a trajectory flown with guidance feedback needs the live pitch program it corrects "
             "(FlightInputs::live_program)";
    case Status::kResumeInputsIncompatible:
      return "a trajectory resumed from another (FlightInputs::resume_from) cannot have guidance feedback, "
             "an injection point or an air-relative angle-of-attack output";
    case Status::kResumeStageSlotInvalid:
      return "the trajectory to resume from failed, or the stage to resume at is not a later stage of both "
             "timelines with the same stage code";
    case Status::kResumeStageNotRecorded:
      return "the stage to resume at has no recorded start point after the pad point in the trajectory "
             "resumed from";
    case Status::kModifiedThrustIdealVelocityInvalid:
      return "thrust modification (Sec. 6): the ideal velocity of a powered stage over its integration grid "
             "is not positive, or that of its input thrust table is not finite";
    case Status::kConstraintPointNotInTrajectory:
      return "a constraint's point is not in the trajectory: the stage X of a stage-end code 10X+5 to 10X+9 "
             "(data block 8) was not flown, or the trajectory is empty";
    case Status::kLinearizedPayloadNegative:
      return "the linearization's payload change made the payload negative";
    case Status::kBackwardRunWithoutTrajectory:
      return "the backward (adjoint) run needs a flown trajectory of at least two points";
    case Status::kOptimizerResultIncomplete:
      return "the optimizer did not reach its summary: its result lists no constraints (or more than the "
             "core holds)";
    case Status::kFinalTrajectoryMissing:
      return "the exchange ratios need the optimizer's final trajectory, which failed or is empty";
    case Status::kExchangePercentChangeTooNegative:
      return "a burn-rate or specific-impulse change of -100 % or less leaves the stage no thrust";
    case Status::kExchangeStageWithoutPropellant:
      return "a propellant-weight exchange ratio needs a stage whose consumable weight table (data block 38) "
             "starts above 0 lb";
    case Status::kExchangePropellantChangeTooNegative:
      return "the propellant-weight change removes all of the stage's propellant";
    case Status::kUnknownExchangeParameter:
      return "the exchange-ratio parameter is not one of burn rate, propellant weight, specific impulse, "
             "drag, jettison weight";
    case Status::kImpactDragTableNotFromMach0:
      return "an impact drag table (data block 42 or 43) does not start at Mach 0";
    case Status::kImpactDragCoefficientInvalid:
      return "a C_D of an impact drag table (data block 42 or 43) is negative or not finite";
    case Status::kImpactReferenceAreaNotPositive:
      return "the reference area of an impact drag table (data block 42 or 43) is not positive";
    case Status::kImpactCasingWeightNotPositive:
      return "the casing weight of an expended-casing table (data block 43) is not positive";
    case Status::kImpactEveryNthPointOutOfRange:
      return "the impact failure-point selector n DA6D(17-19) of data block 33 is not between 1 and the "
             "stage's integration steps (data block 16)";
    case Status::kImpactStepSizeNotPositive:
      return "an impact trajectory step size or limit (ImpactStepSizes) is not positive";
    case Status::kImpactStartInvalid:
      return "an impact trajectory starts with a non-positive weight or a state or time that is not finite";
    case Status::kImpactStartBelowSurface: return "an impact trajectory starts below the Earth's surface";
    case Status::kImpactNominalFailed:
      return "the impact locus needs a nominal trajectory that flew without failure";
    case Status::kImpactNominalStageIncomplete:
      return "the impact locus needs a nominal trajectory that completed every stage 1-3 of the sequence";
    case Status::kDispersionNominalNotPrepared:
      return "dispersion analysis needs the nominal case (mission, pitch program) prepared first";
    case Status::kDispersionStageCodeMismatch:
      return "the stage code of a thrust (1-8) or weight-increment (11-16) dispersion is not its code's "
             "stage (or 5 for the stage-4 codes 7-8, 15-16)";
    case Status::kDispersionThrustTableTimesInvalid:
      return "a dispersion's thrust table (data block 30 of the dispersion group) does not start at stage "
             "time 0 or has no positive burn time";
    case Status::kDispersionThrustNegative:
      return "a dispersion's vacuum thrust (data block 30 of the dispersion group) is negative";
    case Status::kDispersionDragVariationOutOfRange:
      return "a drag variation (data block 48, or a Monte Carlo sample's sum of them) is not strictly "
             "between -100 % and +100 %";
    case Status::kTrajectoryEmpty: return "the trajectory has no recorded points";
    case Status::kMonteCarloBurnTimeNotPositive:
      return "a Monte Carlo sample's blended burn time of a thrust dispersion (codes 1-8) is not positive";
    case Status::kMonteCarloThrustNegative:
      return "a Monte Carlo sample's blended vacuum thrust of a thrust dispersion (codes 1-8) is negative";
    case Status::kTableSpinOptionOutOfRange: return "the table's spin option IP(9) is not 0-3";
    case Status::kTableCreationTimeOutOfRange:
      return "the table's creation time stamp is negative or beyond the year 9999";
    case Status::kTableLiftoffDurationOutOfRange:
      return "the table's lift-off duration is not positive or exceeds the format's limit";
    case Status::kTablePitchRateLimitOutOfRange:
      return "the table's maximum pitch rate is not positive or exceeds the format's limit";
    case Status::kTableMinPitchRateOutOfRange:
      return "the table's minimum pitch rate is negative or above its maximum pitch rate";
    case Status::kTablePitchRateChangeOutOfRange:
      return "the table's minimum pitch-rate change is negative or above twice its maximum pitch rate";
    case Status::kTableDeflectionLimitOutOfRange:
      return "the table's maximum control deflection is not positive or exceeds the format's limit";
    case Status::kTableUpperStageAttitudeOutOfRange:
      return "a stage 4 or 5 attitude (theta, chi) of the table is beyond the format's attitude limit";
    case Status::kTableGainOutOfRange:
      return "an autopilot gain of the table (constant or scheduled K_theta, K_q) is outside [0, 100]";
    case Status::kSegmentStartTimeOutOfRange:
      return "a pitch segment's start time is negative or beyond the format's limit";
    case Status::kSegmentAttitudeOutOfRange:
      return "a pitch segment's start attitude is beyond the format's attitude limit";
    case Status::kGainScheduleTimeOutOfRange:
      return "a gain schedule point's stage time is negative or beyond the format's limit";
    case Status::kLinearizationNotFinished:
      return "the linearization (IP(7) = 1) was skipped or stopped before it finished, so there is no "
             "linearized program to fly about";
    case Status::kIntegrationMultiplierNotInteger:
      return "a 6D integration frequency multiplier (DA6D(12-15)) is not a whole number of substeps";
    case Status::kIntegrationMultiplierBelowOne:
      return "a 6D integration frequency multiplier (DA6D(12-15)) is below 1 (a step takes at least one "
             "substep)";
    case Status::kIntegrationMultiplierAboveCapacity:
      return "a 6D integration frequency multiplier (DA6D(12-15)) is above "
             "kMaxIntegrationFrequencyMultiplier";
    case Status::kDispersionStageDurationsMismatch:
      return "a data block 55 stage 4 or 5 duration is not positive or is not the final time of that "
             "stage's part of the stacked stage-4 tables of data blocks 30 and 38 (codes 7-8)";
    case Status::kDispersionStackedTablesNotSplittable:
      return "the stacked stage-4 tables of data blocks 30 and 38 (codes 7-8 with data block 55) do not "
             "split into stage 4's table from time 0, a coast of zero thrust and stage 5's table "
             "(restarting at 0 or continuing)";
    case Status::kDispersionStackedTablesNeedStage5:
      return "codes 7-8 with data block 55 (stacked stage 4 and 5 tables) need a five-stage vehicle: "
             "stage 5 is not in the stage sequence";
    case Status::kStage5YawOptionInconsistent:
      return "IP(10) (the stage-5 yaw) does not fit IP(9) and the stage sequence: 1 or 2 when stage 5 is "
             "spun apart from stage 4 (IP(9) = 2), 0 or 1 under IP(9) = 1, 0 without a spun stage 5";
  }
  return "unknown status";
}

}  // namespace tolip
