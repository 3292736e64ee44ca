// Compile-time capacities of the core, sized like the 1966 program (manual Sec. 9, 14, 22).
//
// Every fixed array in fsw_core is dimensioned from this header. Exceeding a capacity is
// reported as a Status (never an overflow); see status.hpp.
#pragma once

namespace tolip {

inline constexpr int kMaxConstraints = 13;                      // data block 8 / 19 / 29
inline constexpr int kMaxPoweredSteps = 168;                    // stages 1-5 together (data block 16)
inline constexpr int kMaxPoweredStepsWithFollowingCoast = 177;  // stages 1-5 plus coast 6
inline constexpr int kMaxIntegrationVariables = 240;            // Sec. 9 storage of the adjoint runs
inline constexpr int kMaxLinearSegments = 15;                   // data block 18 / 26
inline constexpr int kMaxThrustPoints = 120;                    // data block 30, all stages together
inline constexpr int kMaxWeightPoints = 120;                    // data block 38, all stages together
inline constexpr int kMaxRadarStations = 20;                    // data block 41
inline constexpr int kRadarStationIdLength = 12;                // data block 41: 2A6 identification
inline constexpr int kMaxAdjustableParameters = 11;             // data block 6 / 27
inline constexpr int kMaxClosedLoopPoints = 20;                 // Sec. 5: closed loop for the first 20 points
inline constexpr int kMaxStages = 10;                           // codes 1-5 powered, 6-10 coasts
inline constexpr int kMaxPoweredStages = 5;

// Tables whose size the manual fixes by its card formats.
inline constexpr int kMaxAeroTablePoints = 20;          // blocks 31/32: 42E12.8 = blank + 20 pairs + 1.0E10
inline constexpr int kMaxPitchTablePoints = 15;         // block 40: 32E12.8 = blank + 15 pairs + 1.0E10
inline constexpr int kMaxCgTablePoints = 10;            // block 37: 22E12.8 = blank + 10 pairs + 1.0E10
inline constexpr int kBodyDynamicsStages = 3;           // block 33: gains and control stations of stages 1-3
inline constexpr int kCgTableStages = 4;                // block 37: c.g. histories of stages 1-4
inline constexpr int kMaxHardoverTablePoints = 10;      // block 44: 22E12.8 = blank + 10 pairs + 1.0E10
inline constexpr int kIntegrationMultiplierStages = 4;  // block 33 DA6D(12-15): stages 1-4

// Our choices where the manual sets no limit (docs/architecture.md, "Capacities").
inline constexpr int kMinStage1Steps = 25;  // data block 16: "at least 25 steps in stage 1"
inline constexpr int kMaxCoastSteps = 100;  // per coast; the manual asks for 10-15 s steps
// DA6D(12-15): RK4 substeps per step of a 6D forward trajectory. The manual suggests 2 or 3; 16
// already makes a 6D run 16 times the point-mass cost and its truncation error 65,536 times smaller.
inline constexpr int kMaxIntegrationFrequencyMultiplier = 16;
// Blocks 53-54 (32E12.8) hold 15 pairs; the reference wind profile has 18 points, so a little more.
inline constexpr int kMaxWindTablePoints = 32;
// Every integration point of one trajectory: the start of every step of every stage, the end point
// of every stage (kept separately from the next stage's first point, so the burnout values of the
// stage are listed), and the pad point at t = 0.
inline constexpr int kMaxTrajectoryPoints = kMaxPoweredSteps + 5 * kMaxCoastSteps + kMaxStages + 1;
// The impact locus (Sec. 17, data blocks 42-43): thrust failures at every n-th integration point
// of the powered stages 1-3 (at most one per step of those stages, n = 1) and the casings of the
// same three stages.
inline constexpr int kImpactStages = 3;
inline constexpr int kMaxImpactCases = kMaxPoweredSteps + kImpactStages;

// Hardover turns (Sec. 16): a turn from every point of stages 1-3 at most, stages 2 and 3 in three
// modes; our choice of 102 output lines per turn (every 0.1 s for ten seconds, and the stop).
inline constexpr int kMaxHardoverTurns = 3 * (kMaxPoweredSteps + 3);
inline constexpr int kMaxHardoverSamples = 102;
// Modified (Sec. 14) thrust table of one stage: one entry per integration time plus the lift-off one.
inline constexpr int kMaxModifiedThrustPoints = kMaxPoweredSteps + 2;
// Autopilot gain schedules (issue 16, docs/theory/autopilot-design.md): designed in stages 1-3 (the
// stages data block 33 gives gains for), at most 8 points per stage; the table image (format
// version 3) holds them all.
inline constexpr int kGainScheduleStages = 3;
inline constexpr int kMaxGainSchedulePointsPerStage = 8;
inline constexpr int kMaxGainSchedulePoints = kGainScheduleStages * kMaxGainSchedulePointsPerStage;
// The Monte Carlo plan (dispersion.hpp, MonteCarloPlan): the thrust blends a sample can fly, once
// per Monte Carlo. Codes 1-8 are four high/low families (stages 1-3 and 4 or 5), each with its high
// and its low table, each table one stage or, stacked (block 55), stages 4 and 5; the pitching
// moment (19-20) is one family with two tables. Data with more (repeated codes) blend the rest per
// sample.
inline constexpr int kMonteCarloThrustFamilies = 4;
inline constexpr int kMaxMonteCarloThrustBlends = kMonteCarloThrustFamilies * 2 * 2;
inline constexpr int kMaxMonteCarloMomentBlends = 2;

}  // namespace tolip
