// Nominal impact locus (manual Sec. 17, subroutines IMPACT, INTPIM, DEQIM, RKADIM; data blocks 42,
// 43 and DA6D(17-19); option IP(23); docs/theory/impact.md).
//
// From the final nominal, ballistic trajectories are flown to impact on the oblate (geodetic)
// Earth: the vehicle after a thrust failure at every n-th integration point of stages 1-3 (the
// failure-mode drag tables CD1F-CD3F, block 42) and the expended casings of stages 1-3 from their
// burnout points (the casing drag tables CD1E-CD3E, block 43), drag included throughout, no lift,
// no thrust. As the manual does ("coast stage 6 nomenclature is used"), each body is flown as a
// coast stage whose drag table and reference area are the body's: the same evaluate_flight(), so
// the same Earth, J2 gravity, 1962 ARDC atmosphere, HAERO bypass and equations of motion as every
// other trajectory, integrated with the trajectory module's Runge-Kutta step. The step size follows
// INTPIM's four regimes (in the atmosphere, out of it, re-entered, terminal velocity), and the
// surface crossing is found inside the last step by iteration, not taken as the first point below.
// Everything lives in the caller's fixed storage; nothing allocates.
#pragma once

#include "tolip/core/capacity.hpp"
#include "tolip/core/state.hpp"
#include "tolip/core/status.hpp"
#include "tolip/mission/mission.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip/vehicle/prepared_case.hpp"

namespace tolip {

// One drag table of data block 42 (failure mode, CDkF) or 43 (expended casing, CDkE): Mach from 0
// to C_D, with the reference area it is based on and, for a casing, the casing's weight.
struct ImpactBody {
  bool present = false;
  AeroTable drag_coefficient;       // Mach -> C_D (finalized, first Mach 0)
  double reference_area_ft2 = 0.0;  // deck extension; the deck reader defaults it to SGk(2)
  double casing_weight_lb = 0.0;    // block 43 only; the deck reader defaults it to SGk(1)
};

// The step sizes of INTPIM's four regimes (the manual names the regimes but prints no values;
// ours are docs/theory/impact.md's choices), and the limits of one impact trajectory.
struct ImpactStepSizes {
  double in_atmosphere_s = 5.0;       // not yet above HAERO since the failure or separation
  double out_of_atmosphere_s = 10.0;  // above HAERO (CT1(7)): no aerodynamics, a Kepler arc
  double reentered_s = 5.0;           // back below HAERO
  double terminal_velocity_s = 5.0;   // descending with drag balancing gravity (MTERMG set)
  // In the atmosphere (not at terminal velocity) a step changes V by at most this fraction, and
  // turns the flight path by at most this many radians: dt <= f V / max(D / m, g0). INTPIM's
  // "step dependent upon the magnitude of the drag acceleration" (gravity bounds the turn of a
  // slow body near its apex).
  double max_drag_velocity_fraction = 0.1;
  double min_step_s = 0.01;
  // Terminal velocity: descending, drag acceleration above half a g, and |dV/dt| below this
  // fraction of g.
  double terminal_velocity_tolerance = 0.05;
  double max_flight_s = 20000.0;  // without an impact by then: kImpactNotReached
};

// Data blocks 42, 43 and DA6D(17-19) in core units.
struct ImpactLocusData {
  ImpactBody failure_mode[kImpactStages];          // CD1F-CD3F
  ImpactBody expended_casing[kImpactStages];       // CD1E-CD3E
  int every_nth_point[kImpactStages] = {1, 1, 1};  // DA6D(17-19)
  ImpactStepSizes steps;
};

// Where validate_impact_data() found a fault: the data block (42, 43 or 33), the stage, the word.
struct ImpactFault {
  int data_block = 0;
  int stage = 0;
  const char* field = "";  // "CD1F", "reference area", "casing weight", "DA6D(17)", ...
  double value = 0.0;
  const char* expected = "";
};

// Checks the data against the case before anything flies: for every stage 1-3 in the sequence the
// failure-mode and casing tables present, finalized, from Mach 0, C_D finite and >= 0, areas > 0,
// casing weights > 0; n of DA6D(17-19) between 1 and the stage's integration steps (a larger n
// puts the first failure point after the first one past the end of the stage). kOk or
// kImpactDataMissing / kTableNotMonotonic / kImpactDragTableNotFromMach0 /
// kImpactDragCoefficientInvalid / kImpactReferenceAreaNotPositive / kImpactCasingWeightNotPositive /
// kImpactEveryNthPointOutOfRange / kImpactStepSizeNotPositive, with *fault.
Status validate_impact_data(const Mission& mission, const ImpactLocusData& data, ImpactFault* fault);

// validate_impact_data()'s check of the expended-casing tables (block 43) alone, for the stages k
// with stages[k - 1] set (each must be in the sequence: kImpactDataMissing otherwise), and of the
// step sizes: what flying the casings needs (the Monte Carlo's casing impacts, which fly no thrust
// failure and so need neither block 42 nor DA6D(17-19)).
Status validate_casing_data(const Mission& mission, const ImpactLocusData& data,
                            const bool (&stages)[kImpactStages], ImpactFault* fault);

enum class ImpactKind : int { kThrustFailure, kExpendedCasing };

// INTPIM's regimes.
enum class ImpactRegime : int { kInAtmosphere, kOutOfAtmosphere, kReentered, kTerminalVelocity };

// One ballistic trajectory to the surface.
struct ImpactFlight {
  Status status = Status::kNotPrepared;
  double impact_time_s = 0.0;  // from launch
  StateVector impact_state = StateVector::Zero();
  double max_altitude_ft = 0.0;
  int steps = 0;
  int regime_steps[4] = {};  // steps taken in each ImpactRegime
  bool reached_terminal_velocity = false;
};

// Flies one body (weight_lb, its drag table and area) from (t0_s, state0) with zero thrust to the
// oblate surface (altitude r - R_OBL(lambda) = 0). `scratch` becomes the body's coast stage (the
// manual's stage-6 arrays loaded with the body's drag curve). kOk, kNonFiniteState,
// kImpactNotReached, kImpactStartBelowSurface, or kImpactStartInvalid (a non-positive weight, a state
// or time not finite).
Status fly_to_impact(const Mission& mission, const PreparedCase& prepared, const ImpactBody& body,
                     double weight_lb, double t0_s, const StateVector& state0, const ImpactStepSizes& steps,
                     StageData* scratch, ImpactFlight* out);

// One line of the locus: the manual's output (failure time, impact time, geodetic latitude,
// longitude, downrange, geocentric latitude) and crossrange.
struct ImpactCase {
  ImpactKind kind = ImpactKind::kThrustFailure;
  int stage = 0;                // 1-3
  int nominal_point = 0;        // index of the nominal's point the body leaves from
  double failure_time_s = 0.0;  // from launch (casings: the stage's burnout)
  double weight_lb = 0.0;
  Status status = Status::kNotPrepared;
  double impact_time_s = 0.0;  // from launch
  double geodetic_latitude_rad = 0.0;
  double geocentric_latitude_rad = 0.0;
  double longitude_rad = 0.0;   // Earth-fixed, east positive, (-pi, pi]
  double downrange_rad = 0.0;   // great-circle central angle from the launch point (Sec. 4)
  double crossrange_rad = 0.0;  // from the launch azimuth's great circle, positive to the right
  double impact_velocity_ft_s = 0.0;
  double impact_flight_path_angle_rad = 0.0;
  double max_altitude_ft = 0.0;
  bool reached_terminal_velocity = false;
  int steps = 0;
};

struct ImpactLocus {
  Status status = Status::kNotPrepared;  // kOk when every case reached the surface
  int count = 0;                         // thrust failures of stages 1, 2, 3, then the casings
  ImpactCase cases[kMaxImpactCases];
};

// Scratch of the locus (the manual's stage-6 arrays).
struct ImpactWorkspace {
  StageData body_stage;
};

// The one record of an impact trajectory (a line of the locus, a Monte Carlo sample's casing):
// `body` of weight_lb flown with fly_to_impact() from point `point` of `flight` (a flight of
// `mission` / `prepared`), its impact recorded into *out with the ranges of Sec. 4 from
// `range_origin` (the launch site; the crossrange from the great circle of its azimuth). Returns
// out->status.
Status fly_impact_case(const Mission& mission, const PreparedCase& prepared,
                       const LaunchConditions& range_origin, const Trajectory& flight, ImpactKind kind,
                       int stage, int point, const ImpactBody& body, double weight_lb,
                       const ImpactStepSizes& steps, ImpactWorkspace* workspace, ImpactCase* out);

// The expended casings of the stages k with stages[k - 1] set that `flight` flew to their end
// (flight.stages: completed), each from its stage's burnout point with the block 43 casing weight
// plus weight_change_lb[k - 1] (null: none), in stage order into cases[0..count). *count the
// casings flown; returns kOk or the first casing's failure (each carries its own status).
Status fly_expended_casings(const Mission& mission, const PreparedCase& prepared,
                            const LaunchConditions& range_origin, const Trajectory& flight,
                            const ImpactLocusData& data, const bool (&stages)[kImpactStages],
                            const double* weight_change_lb, ImpactWorkspace* workspace,
                            ImpactCase (&cases)[kImpactStages], int* count);

// The whole locus about `nominal` (a completed flight of `mission` / `prepared`): thrust failures at
// every n-th integration point of stages 1-3 (stage 1 from the end of the vertical lift-off; a
// stage's end point is its burnout, not a failure), then the casings of stages 1-3 from their
// burnout points. Stages not in the sequence are left out. Returns validate_impact_data()'s fault,
// kImpactNominalFailed or kImpactNominalStageIncomplete for an incomplete nominal, else kOk or the
// first case's failure (every case is still attempted and carries its own status).
Status compute_impact_locus(const Mission& mission, const PreparedCase& prepared, const Trajectory& nominal,
                            const ImpactLocusData& data, ImpactWorkspace* workspace, ImpactLocus* locus);

// The cross-track angle of a surface point from the great circle through the launch point at the
// launch azimuth, positive to the right looking downrange (geocentric latitudes, Earth-fixed
// longitudes).
double launch_crossrange_angle_rad(double launch_latitude_rad, double launch_longitude_rad,
                                   double launch_azimuth_rad, double latitude_rad, double longitude_rad);

}  // namespace tolip
