// The case: every datum of the manual's data blocks 1-40 that the core uses, in internal units.
//
// A Mission is plain fixed-size data. Ground tools fill it from a deck (converting degrees,
// nautical miles, ...) and call validate_mission() at the boundary; the core trusts a Mission
// that validated. Field comments name the data block and word (manual Sec. 22).
#pragma once

#include "tolip/core/capacity.hpp"
#include "tolip/core/constants.hpp"
#include "tolip/core/stage_codes.hpp"
#include "tolip/core/status.hpp"
#include "tolip/math/table.hpp"

namespace tolip {

using ThrustTable = Table<kMaxThrustPoints>;     // stage time s -> vacuum thrust lbf (block 30)
using WeightTable = Table<kMaxWeightPoints>;     // stage time s -> consumable weight lb (block 38)
using AeroTable = Table<kMaxAeroTablePoints>;    // Mach -> coefficient (blocks 31, 32)
using PitchTable = Table<kMaxPitchTablePoints>;  // s from launch -> theta rad (block 40)
using CgTable = Table<kMaxCgTablePoints>;        // stage time s -> c.g. body station ft (block 37)

// Data block 5 order: whether stage `code` may directly follow stage `previous` (0: the start).
// The sequence starts with 1; after powered stage n comes the next powered stage n+1 or its coast
// n+5; after coast n+5 comes stage n+1. So the codes keep the order 1 6 2 7 3 8 4 9 5 10, no
// powered stage is skipped, and a coast may be left out (powered stages burning back to back:
// hot staging, parallel boosters), e.g. 1 2 7 3 8 4. The sequence may end after any stage.
inline constexpr bool may_follow_in_sequence(int previous, int code) {
  if (previous == 0) return code == 1;
  if (is_powered_stage(previous)) return code == previous + 1 || code == previous + 5;
  if (is_coast_stage(previous)) return code == previous - 4;
  return false;
}

// Data block 5: the flown order (may_follow_in_sequence() between neighbours), ending after any
// stage.
struct StageSequence {
  int codes[kMaxStages] = {};
  int count = 0;
};

struct StageData {
  bool in_sequence = false;
  double duration_s = 0.0;            // block 16 DA1(2k-1); for powered stages the last table time
  int integration_steps = 0;          // block 16 DA1(2k); stage 1 counts steps after lift-off
  double jettison_weight_lb = 0.0;    // block 39 SGk(1), dropped at the end of the stage
  double reference_area_ft2 = 0.0;    // block 39 SGk(2)
  double nozzle_exit_area_ft2 = 0.0;  // block 39 SGk(3); net thrust T = Tv - p Ae
  ThrustTable vacuum_thrust_lbf;      // block 30, powered stages
  WeightTable consumable_weight_lb;   // block 38, powered stages: consumable weight remaining
  AeroTable drag_coefficient;         // block 31: stages 1, 6, 2 (empty: no drag)
  bool uses_lift_table = false;       // block 32 is used in stages 1 and 6
};

struct Vehicle {
  StageSequence sequence;
  StageData stages[kMaxStages];        // indexed by stage_index(code)
  AeroTable lift_curve_slope_per_rad;  // block 32, C_L per radian of alpha
  double payload_lb = 0.0;             // part of the jettison weight of the last powered stage (Sec. 14)
};

// Data block 4. Named options of IP(1..24) that the core reads; the raw words are kept for echo.
struct Options {
  int ip[25] = {};                      // ip[n] = IP(n), ip[0] unused
  int payoff() const { return ip[1]; }  // 0 payload, 1 velocity, 2 altitude
  bool heating_constraint() const { return ip[2] == 1; }
  bool exchange_ratios() const { return ip[3] == 1; }
  int body_dynamics_6d() const { return ip[6]; }
  bool linearization() const { return ip[7] == 1; }
  int spin_stages_4_5() const { return ip[9]; }
  int stage5_chi() const { return ip[10]; }
  bool zero_alpha_window() const { return ip[11] == 1; }
  bool alpha_zero_at_stage2_ignition() const { return ip[12] == 1; }
  int qbar_constraint_type() const { return ip[13]; }
  bool memory_dump() const { return ip[15] != 0; }  // the 1966 core dump: not acted on
  bool print_input() const { return ip[17] == 1; }
  bool dispersions() const { return ip[21] == 1; }
  bool hardover() const { return ip[22] == 1; }
  bool impact() const { return ip[23] == 1; }
  bool radar() const { return ip[24] == 1; }
  // IP(9) through the one rule above (tolip::stage_is_spun, tolip::stage_is_steered).
  bool stage_is_spun(int stage_code) const { return tolip::stage_is_spun(spin_stages_4_5(), stage_code); }
  bool stage_is_steered(int stage_code) const {
    return tolip::stage_is_steered(spin_stages_4_5(), stage_code);
  }
  // The linearization flies the optimized case without the in-flight attitudes (IP(11), IP(12)).
  void set_zero_alpha_window(bool on) { ip[11] = on ? 1 : 0; }
  void set_alpha_zero_at_stage2_ignition(bool on) { ip[12] = on ? 1 : 0; }
  // Not in the manual (issue 15; docs/theory/constraints-and-ics.md "q-bar x alpha"): the limit of
  // |q-bar alpha| over the phases with aerodynamic lift, lbf rad/ft^2 (deck: lb deg/ft^2); 0: none.
  double qbar_alpha_limit_lbf_rad_ft2 = 0.0;
  bool qbar_alpha_constraint() const { return qbar_alpha_limit_lbf_rad_ft2 > 0.0; }
};

// Data blocks 20 and 21 (angles in rad).
struct LaunchConditions {
  double liftoff_duration_s = 0.0;          // DA5(1): vertical lift-off
  double launch_space_age_date_days = 0.0;  // DA5(2): Julian date - 2,436,934.5
  double altitude_ft = 0.0;                 // DA6(1)
  double longitude_rad = 0.0;               // DA6(2), east positive
  double geocentric_latitude_rad = 0.0;     // DA6(3)
  double velocity_ft_s = 0.0;               // DA6(4), must be 0
  double azimuth_rad = 0.0;                 // DA6(5), east of north
  double flight_path_angle_rad = 0.0;       // DA6(6), must be 90 deg
  // Not in the manual (docs/theory/liftoff.md): dpsi/dt is held at zero on integration steps
  // that start before this time, where gamma is near 90 deg and the psi equation is singular.
  double heading_hold_until_s = 0.0;
};

// Data block 22 (times from launch; rates in rad/s).
struct ControlConstraints {
  double zero_alpha_start_s = 0.0;           // DA7(1)
  double zero_alpha_end_s = 0.0;             // DA7(2)
  double max_pitch_rate_rad_s = 0.0;         // DA7(3)
  double min_pitch_rate_rad_s = 0.0;         // DA7(4)
  double min_pitch_rate_change_rad_s = 0.0;  // DA7(5)
};

// Data block 17 (angles in rad).
struct MiscellaneousData {
  double stage4_theta_rad = 0.0;             // DA2(5)
  double stage4_chi_rad = 0.0;               // DA2(6)
  double nose_radius_ft = 0.0;               // DA2(7), heating rate (Sec. 13)
  double gyro_uncage_s_before_launch = 0.0;  // DA2(8)
  double stage5_theta_rad = 0.0;             // DA2(9)
  double stage5_chi_rad = 0.0;               // DA2(10)
  double payload_weighting_factor = 1.0;     // DA2(15)
  double coast_change_limit_s = 0.0;         // DA2(16)
  double minimum_coast_s = 0.0;              // DA2(17)
};

// The data block 17 attitude a spun stage, and the coast after it, holds (Sec. 22 IP(9), IP(10)):
// the one rule, asked by the trajectory, the linearization, the table builder and the deck checks.
// IP(9) = 1 spins stages 4 and 5 together on stage 4's words (theta5 = theta4, chi5 = chi4);
// IP(9) = 2 spins stage 5 alone on theta5 of DA2(9), with its yaw by IP(10): 1 chi5 = chi4 (DA2(6)),
// 2 chi5 independent (DA2(10)). validate_mission() admits IP(10) only where it has this meaning.
struct SpunAttitude {
  double theta_rad = 0.0;
  double chi_rad = 0.0;
};
inline SpunAttitude spun_stage_attitude(const Options& options, const MiscellaneousData& misc,
                                        int stage_code) {
  const bool fifth = stage_code == 5 || stage_code == 10;
  if (!fifth || options.stage_is_spun(4)) return {misc.stage4_theta_rad, misc.stage4_chi_rad};
  return {misc.stage5_theta_rad, options.stage5_chi() == 1 ? misc.stage4_chi_rad : misc.stage5_chi_rad};
}

// Data blocks 8, 19, 29: the payoff first, then terminal, then stage-point constraints.
struct ConstraintList {
  int count = 0;                                        // IB3(1), includes the payoff
  int codes[kMaxConstraints + 1] = {};                  // IB3(2..14); heating (14) may follow
  double desired[kMaxConstraints + 1] = {};             // DA4, pure units (ft, rad, ft/s, n.mi., Btu/ft^2)
  double deadband_optimization[kMaxConstraints] = {};   // DA14(1..12)
  double deadband_linearization[kMaxConstraints] = {};  // DA14(14..25)
};

// Data blocks 6 and 27.
struct AdjustableParameters {
  int count = 0;
  int codes[kMaxAdjustableParameters] = {};
  double weights[kMaxAdjustableParameters] = {};
};

// One boundary of the linear pitch segments (data block 18): a time in a powered stage. The deck
// codes it as 100 n + t; the deck readers decode it (tolip_ground), the core never sees the code.
struct SegmentBoundary {
  int stage = 0;                      // n, the powered stage code 1-5; 0 (with t = 0): unused entry
  double time_from_ignition_s = 0.0;  // t, from stage n's ignition
};

// Data block 18 (TLIN) and 26 (ETALIN).
struct LinearizationData {
  int segment_count = 0;
  // The segments' boundaries in flight order, one more than the segments (data block 18 words
  // 2-17); unused entries {0, 0}.
  SegmentBoundary boundaries[kMaxLinearSegments + 1] = {};
  double segment_weights[kMaxLinearSegments] = {};  // eta, default 1
};

// Data block 28 (DA13).
struct ConvergenceData {
  double initial_payoff_improvement = 0.0;
  double stop_improvement = 0.0;
  int max_forward_trajectories = 30;
  int max_linearization_iterations = 4;
};

// Data blocks 33-37: the body-dynamics (6D) data of manual Sec. 7 and 11 (DA6D, CNDELTA, CMALPHA,
// CMDELTA, XCG1-XCG4). Body stations are measured aft from the nose, in ft (the deck gives inches);
// "per radian" everywhere (the deck's per-degree jet-vane effectiveness is converted at the edge).
// docs/theory/body-dynamics.md explains how body_dynamics.cpp uses each datum.
struct BodyDynamicsBlocks {
  bool present = false;                                 // the deck gave data blocks 33-37
  double position_gain[kBodyDynamicsStages] = {};       // DA6D(1-3) K_theta, rad/rad, stages 1-3
  double rate_gain_s[kBodyDynamicsStages] = {};         // DA6D(4-6) K_theta-dot (K_q), s
  double control_station_ft[kBodyDynamicsStages] = {};  // DA6D(7-9) X_delta: stage-1 jet vanes and fins,
                                                        // stage 2-3 control jets
  double jet_vane_effectiveness_per_rad = 0.0;          // DA6D(10) K_TV-delta, lbf per lbf vacuum thrust
                                                        // per rad, per vane
  double moment_reference_station_ft = 0.0;             // DA6D(11) X_FS of the moment coefficients
  double reference_length_ft = 0.0;                     // DA6D(16) l_ref of the moment coefficients
  // DA6D(12-15): each step of stage k (and of the coast after it) of a 6D forward trajectory is
  // integrated as this many RK4 substeps (Sec. 22, "if a more frequent integration is desired
  // during 6D forward trajectories"), k = 1-4; a whole number in 1..kMaxIntegrationFrequencyMultiplier.
  // The trajectory keeps its points (one per step); 1 leaves every run as before, bit for bit.
  double integration_frequency_multiplier[kIntegrationMultiplierStages] = {1.0, 1.0, 1.0, 1.0};
  // S of Sec. 11: the area blocks 34-36 are referred to. DA6D has no word for it; the deck mapping
  // takes stage 1's block 39 area SG1(2).
  double reference_area_ft2 = 0.0;
  // Fins and jet vanes acting in one plane, multiplying the per-fin and per-vane coefficients of
  // blocks 34, 36 and DA6D(10) in M_delta (the factor 2 of Sec. 16's FORCEN; the Scout has four fins
  // and four vanes in a cross). Not a manual word.
  double control_surfaces_per_plane = 2.0;
  AeroTable fin_normal_force_per_rad;     // block 34: Mach -> C_N_delta, per rad per fin
  AeroTable pitching_moment_per_rad;      // block 35: Mach -> C_M_alpha about X_FS, per rad
  AeroTable fin_pitching_moment_per_rad;  // block 36: Mach -> C_M_delta about X_FS, per rad per fin
  CgTable cg_station_ft[kCgTableStages];  // block 37: XCG1-XCG4, stage time s -> c.g. station ft
  // Designed stage-1 autopilot gains (issue 16, docs/theory/autopilot-design.md): when
  // stage1_schedule_count > 0 the steady state of Sec. 7 (stage 1 and the coast after it) takes
  // K_theta and K_q from this schedule, linear in stage-1 time and held at its ends, instead of
  // DA6D(1), DA6D(4). 0 (the deck's constants) leaves every result as before, bit for bit.
  int stage1_schedule_count = 0;
  double stage1_schedule_time_s[kMaxGainSchedulePointsPerStage] = {};
  double stage1_schedule_k_theta[kMaxGainSchedulePointsPerStage] = {};
  double stage1_schedule_k_q_s[kMaxGainSchedulePointsPerStage] = {};
};

// The listing's data (blocks 1-3 title, heading and date; block 9 print frequencies; CT1(8),
// CT1(9)) is not the core's: the ground's DeckListingOptions carries it beside the Mission.
struct Mission {
  Options options;
  Constants constants;
  AtmosphereTable atmosphere;
  Vehicle vehicle;
  LaunchConditions launch;
  ControlConstraints control;
  MiscellaneousData misc;
  ConstraintList constraints;
  AdjustableParameters adjustable;
  LinearizationData linearization;
  ConvergenceData convergence;
  PitchTable pitch_program_rad;      // block 40: theta (rad) vs time from launch (s)
  BodyDynamicsBlocks body_dynamics;  // blocks 33-37 (checked by validate_mission when IP(6) >= 1)
};

// The allowed range of a value (core units); a side without a bound has has_low / has_high false.
struct ValueRange {
  bool has_low = false;
  bool has_high = false;
  bool low_inclusive = true;
  bool high_inclusive = true;
  double low = 0.0;
  double high = 0.0;
};

// Where validate_mission() found a fault, in the manual's vocabulary, and what it found there: the
// value (core units, `unit`) and the range it must lie in, or a phrase saying what was expected
// when a range cannot say it. Ground tools turn it into a message naming the deck key or card word.
struct MissionFault {
  int data_block = 0;  // manual data block number
  int stage_code = 0;  // 0 when not stage-coded
  const char* field = "";
  int index = -1;             // element of `field` (table point, IP(n), constraint entry, ...); -1: none
  bool has_value = false;     // `value` is the value found
  double value = 0.0;         // core units
  ValueRange range;           // where the value must lie (core units), when has_low or has_high
  const char* unit = "";      // core unit of value and range: "s", "ft", "lb", "lbf", "rad", "rad/s", ...
  const char* expected = "";  // what was expected, when the range does not say it ("" otherwise)
};

// Checks the case at the boundary: sequence, capacities, tables, weights, durations, steps,
// initial conditions. Returns kOk or the first fault, described in *fault.
Status validate_mission(const Mission& mission, MissionFault* fault);

// Checks the body-dynamics data a 6D trajectory needs (Sec. 7, 11: stage 1 and the following
// coast): present, finite, K_theta > 0, K_q >= 0, l_ref > 0, S > 0, tables of blocks 34-36 and the
// stage-1 c.g. history given and finalized, the stage-1 control station outside the range of
// the stage-1 c.g. stations (so X_delta - X_CG never vanishes), and DA6D(12-15) whole numbers in
// 1..kMaxIntegrationFrequencyMultiplier. validate_mission() calls it when
// IP(6) >= 1; fly_trajectory() when a 6D run is asked for.
Status validate_body_dynamics(const Mission& mission, MissionFault* fault);

// The RK4 substeps of a step of stage `stage_code` in a 6D forward trajectory: DA6D(12-15) of
// stages 1-4 and of the coasts after them (6-9); 1 for stage 5, its coast, or a point-mass run.
int integration_substeps(const BodyDynamicsBlocks& blocks, int stage_code, bool body_dynamics);

// Vehicle weight (lb) in stage `code` at stage time t: consumable weight remaining of the current
// powered stage + jettison weights of this and all later stages (+ payload) + the initial
// consumable weights of all later stages.
double vehicle_weight_lb(const Vehicle& vehicle, int code, double stage_time_s);

}  // namespace tolip
