// Dispersion analysis of the final nominal (manual Sec. 15, Sec. 22 data blocks 46-55 and the
// DISPERSION TRAJECTORY CODES table; docs/theory/dispersions.md).
//
// For each dispersion code given (1-38; code 40 asks for the three-sigma summary) the final
// nominal - the linearized program (IP(7) = 1) or the optimum, flown from its payload - is changed
// as the code says and flown again with the same trajectory code (fly_trajectory: the same
// integrator, atmosphere and Earth), and the staging-point variables, the orbit elements and the
// maximum q-bar alpha are recorded with their dispersions (dispersed - nominal; the manual's GIANT
// array, plane 40 the nominal). The three-sigma groups (SUM) follow from those by sum and by
// root-sum-square. Everything lives in the caller's fixed storage; nothing allocates.
#pragma once

#include "tolip/core/capacity.hpp"
#include "tolip/core/status.hpp"
#include "tolip/mission/mission.hpp"
#include "tolip/orbit/orbit_elements.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip/trajectory/wind.hpp"
#include "tolip/vehicle/prepared_case.hpp"

namespace tolip {

inline constexpr int kNominalDispersionCode = 40;  // block 46 code 40: "nominal traj.", three sigma
inline constexpr int kMaxDispersionCode = 38;      // codes 1-38 are dispersed trajectories
inline constexpr int kMaxDispersionSources = kMaxDispersionCode + 1;  // 1-38 and 40
// Staging points (the manual's AA(i, j), j = 1-4 on a four-stage vehicle): the ignition of every
// powered stage after the first, then the final point. A five-stage vehicle gets a fifth column
// (stage 5 ignition) instead of the manual's squeeze of five stages into four.
inline constexpr int kMaxStagingPoints = kMaxPoweredStages;
inline constexpr int kStagingVariables = 5;         // AA(i, j), i = 1-5
inline constexpr int kOrbitDispersionElements = 6;  // AA(i, 5), i = 1-6

// What a code disperses (the "Type" column of the code table).
enum class DispersionKind : int {
  kVacuumThrust,        // 1-8   blocks 30 and 38 replacement tables of one stage (55: five stages)
  kWeightIncrement,     // 9-16  block 47: jettison weight increment of one stage
  kDrag,                // 17-18 block 48: fractional drag change in stages 1, 6, 2
  kPitchingMoment,      // 19-20 block 35: the complete C_M_alpha table (body dynamics)
  kThrustMisalignment,  // 21-23 block 49: stage-1 misalignment angle and thrust station (body dynamics)
  kControlDeadband,     // 24-29 block 50: attitude offset of stage 2 or 3
  kTipoff,              // 30-32 block 51: effective attitude change of spun stage 4 or 5
  kLaunchAzimuth,       // 33    block 52: launch azimuth change
  kLaunchAttitude,      // 34-35 block 52: launch attitude (pitch reference) change
  kWind,                // 36-38 blocks 53-54: wind speed and azimuth vs altitude
  kNominal,             // 40    the nominal and the three-sigma summary
};

// The plane of a code (data block 46 designates the groups): high/low codes are pitch-plane
// dispersions (IDSP = +1), yaw codes are yaw-plane (IDSP = -1).
enum class DispersionPlane : int { kHighLow, kYaw, kNone };

struct DispersionCodeInfo {
  int code = 0;
  DispersionKind kind = DispersionKind::kNominal;
  DispersionPlane plane = DispersionPlane::kNone;
  int stage = 0;          // the stage the code table names (0: none, or given by the deck: 30-32)
  bool high = false;      // "High" / "Forward" in the table (documentation; grouping uses the sign rule)
  const char* name = "";  // e.g. "vacuum thrust high, stage 1"
};

// The code table of Sec. 22. False for codes outside 1-38 and 40.
bool dispersion_code_info(int code, DispersionCodeInfo* info);

// One block 46 card with its data, in core units (angles rad, stations ft).
struct DispersionSource {
  int code = 0;
  int stage = 0;        // codes 30-32: spun stage 4 or 5; 7-8, 15-16: 4 or 5; otherwise the table's stage
  char title[13] = {};  // block 46 title, 2A6
  ThrustTable vacuum_thrust_lbf;     // codes 1-8: block 30 replacement table (stage time)
  WeightTable consumable_weight_lb;  // codes 1-8: block 38 replacement table
  // Codes 7-8 with block 55 (page 22-30, five-stage Scout): stages 4 and 5 stacked in the stage-4
  // tables above - stage 4's own table (stage time 0 to d4), the coast (zero thrust, "input
  // arbitrarily as two seconds"), stage 5's own table (restarting at 0, or continuing) - split by
  // the block 55 durations d4, d5 (find_stacked_stage4_5_split) and flown as the replacement tables
  // of both stages; the coast keeps its optimized length.
  bool stacked_stage4_5_tables = false;
  double stage4_5_durations_s[2] = {};   // block 55: (1) stage 4, (2) stage 5 duration
  double weight_increment_lb = 0.0;      // codes 9-16, signed
  double drag_variation_fraction = 0.0;  // codes 17-18, signed (0.xxxx)
  AeroTable pitching_moment_per_rad;     // codes 19-20: Mach -> C_M_alpha about X_FS
  double misalignment_rad = 0.0;         // codes 21-23, signed (+: nose up / yaw right moment)
  double thrust_station_ft = 0.0;        // codes 21-23
  double deadband_rad = 0.0;             // codes 24-29, signed
  double tipoff_rad = 0.0;               // codes 30-32, signed
  double launch_change_rad = 0.0;        // codes 33-35, signed
  WindProfile wind;                      // codes 36-38
};

// Data blocks 46-55 of a case, in increasing code order.
struct DispersionData {
  int count = 0;
  DispersionSource sources[kMaxDispersionSources];
};

// The final nominal the dispersions are taken about: the case (optimized payload, coasts, spun
// attitudes), the per-point pitch program flown (null: the data block 40 table) and whether stage 1
// flew with body dynamics. The analysis prepares the case itself (prepare_case: the Sec. 14 tables
// at the case's own payload), for the nominal and for every dispersed case alike, so a dispersion
// is the change its code makes and nothing else. Pointers must outlive the analysis.
struct DispersionNominal {
  const Mission* mission = nullptr;
  const ControlProgram* program = nullptr;
  bool body_dynamics = false;
};

// AA(i, j) / GIANT(i, j, JILL), i = 1-5.
enum class StagingVariable : int { kAltitude, kVelocity, kFlightPathAngle, kDownrange, kCrossrange };

// One GIANT plane: a dispersed trajectory (or the nominal, code 40).
struct DispersedTrajectory {
  int code = 0;
  // kOk: flown and recorded. Otherwise why not, by name: kDispersionNeedsBodyDynamics,
  // kDispersionStageNotInSequence, kDispersionStackedTablesNeedStage5, kDispersionStageNotSpun, or the
  // failure of the dispersed flight itself (kAltitudeBelowSurface, ...). Only kOk entries are grouped.
  Status status = Status::kNotPrepared;
  char title[13] = {};
  // Staging variables as flown (ft, ft/s, rad, n.mi., n.mi.) and minus the nominal's.
  double values[kMaxStagingPoints][kStagingVariables] = {};
  double dispersions[kMaxStagingPoints][kStagingVariables] = {};
  // TWOE (ft^2/s^2), EH (ft^2/s), RP (ft), EYE, BETAP, OMEGAE (rad) at the final point, and their
  // dispersions (angles wrapped into (-pi, pi]).
  double orbit[kOrbitDispersionElements] = {};
  double orbit_dispersions[kOrbitDispersionElements] = {};
  double max_qbar_alpha_lbf_rad_ft2 = 0.0;  // max |q-bar alpha| (air-relative alpha under winds)
  double max_qbar_alpha_time_s = 0.0;       // TIMCT of the maximum
};

// SUM(i, j, k): one three-sigma group.
struct ThreeSigmaGroup {
  int member_count = 0;
  int members[kMaxDispersionSources] = {};                // codes, increasing
  double sum[kMaxStagingPoints][kStagingVariables] = {};  // sum of the dispersions
  double rss[kMaxStagingPoints][kStagingVariables] = {};  // root sum of their squares
};

struct ThreeSigmaSummary {
  bool computed = false;            // code 40 was given
  ThreeSigmaGroup yaw;              // every yaw code, winds included (computed first, Sec. 15)
  ThreeSigmaGroup high;             // high/low codes without winds, final altitude dispersion > 0
  ThreeSigmaGroup low;              //   ... < 0 (velocity decides when the altitude dispersion is 0)
  ThreeSigmaGroup high_with_winds;  // the same with the high/low wind codes added
  ThreeSigmaGroup low_with_winds;
};

struct DispersionResult {
  Status status = Status::kNotPrepared;  // kOk when the nominal flew; per-code statuses below
  int fault_code = 0;     // the data block 46 code at fault when validate_dispersion_data() failed, else 0
  int staging_count = 0;  // columns: ignitions of stages 2.., then the final point
  int staging_stage_code[kMaxStagingPoints] = {};  // powered stage code at ignition; 0: final point
  DispersedTrajectory nominal;                     // GIANT plane 40
  int count = 0;                                   // dispersed trajectories, in the data's code order
  DispersedTrajectory trajectories[kMaxDispersionSources];
  ThreeSigmaSummary three_sigma;
};

// The half of a Monte Carlo sample's case that does not depend on its draws, worked out once per
// Monte Carlo (prepare_monte_carlo with the data; build_monte_carlo_case): per source the code
// table's entry, whether it is drawn, its leader, stage and low partner; per thrust table (codes
// 1-8) and C_M_alpha table (19-20) the union grid with the nominal's and the table's values at its
// points, so a sample only blends them with its c, in the same operations as before. The statuses
// a sample would meet before its first c-dependent step are kept and returned where it meets them.
struct MonteCarloThrustBlend {  // one table blended into one stage
  int slot = 0;                 // the stage's index
  double nominal_burn_s = 0.0;  // the nominal's burn time; the table's is its last time
  double source_burn_s = 0.0;
  bool merged = false;  // the union grid fits the table (else kTooManyTablePoints)
  int count = 0;        // normalized times tau of the union grid, and the four tables at them
  double tau[kMaxThrustPoints] = {};
  double nominal_thrust_lbf[kMaxThrustPoints] = {};
  double source_thrust_lbf[kMaxThrustPoints] = {};
  double nominal_weight_lb[kMaxThrustPoints] = {};
  double source_weight_lb[kMaxThrustPoints] = {};
};

struct MonteCarloMomentBlend {
  bool merged = false;
  int count = 0;
  double mach[kMaxAeroTablePoints] = {};
  double nominal_per_rad[kMaxAeroTablePoints] = {};
  double source_per_rad[kMaxAeroTablePoints] = {};
};

// Two wind profiles of a sample (the first two drawn of codes 36-38) summed as vectors: the
// union altitude grid, each profile's speed and the cosine and sine of its azimuth at its points.
struct MonteCarloWindBlend {
  bool merged = false;
  int count = 0;
  double altitude_ft[kMaxWindTablePoints] = {};
  double speed_ft_s[2][kMaxWindTablePoints] = {};
  double cos_azimuth[2][kMaxWindTablePoints] = {};
  double sin_azimuth[2][kMaxWindTablePoints] = {};
};

struct MonteCarloPlan {
  // What the plan was made for; null data: made for one build_monte_carlo_case only.
  const Mission* mission = nullptr;
  const ControlProgram* program = nullptr;
  bool body_dynamics = false;
  const DispersionData* data = nullptr;
  struct TableSide {              // a table source's own table (0) or its low partner's (1)
    Status status = Status::kOk;  // stacked tables that do not unstack
    bool stacked = false;
    int parts = 0;             // stages blended: 1, or 2 (stacked: stages 4 and 5)
    int slots[2] = {};         // their indices
    int blends[2] = {-1, -1};  // into thrust / moment; -1: worked out per sample (repeated codes)
  };
  struct Source {
    bool known = false;  // dispersion_code_info() knows the code
    bool drawn = false;  // monte_carlo_draws_source()
    DispersionKind kind = DispersionKind::kNominal;
    bool yaw = false;
    int leader = 0;    // the code whose draw it takes
    int stage = 0;     // dispersion_source_stage()
    int partner = -1;  // monte_carlo_low_partner() of a table source
    TableSide sides[2];
  } sources[kMaxDispersionSources];
  int thrust_count = 0;
  MonteCarloThrustBlend thrust[kMaxMonteCarloThrustBlends];
  int moment_count = 0;
  MonteCarloMomentBlend moment[kMaxMonteCarloMomentBlends];
  int wind_count = 0;  // drawn wind sources, at most the two a sample sums
  int wind_sources[2] = {-1, -1};
  MonteCarloWindBlend wind[2][2];        // by the side (own or low table) of each
  MonteCarloThrustBlend thrust_scratch;  // a blend worked out per sample
  MonteCarloMomentBlend moment_scratch;
};

// Scratch of the analysis (large: keep it static or on the heap).
struct DispersionWorkspace {
  PreparedCase nominal_prepared;
  Mission mission;
  PreparedCase prepared;
  ControlProgram program;       // the nominal program on a changed timeline (codes 1-8)
  bool program_mapped = false;  // `program` is to be flown (else the nominal's)
  FlightPerturbation perturbation;
  Trajectory nominal;
  Trajectory dispersed;
  WindProfile wind;  // a Monte Carlo sample's wind (the drawn profiles, scaled and summed)
  // A Monte Carlo sample's stacked stage-4/5 tables (codes 7-8 with block 55) as stage 4's and
  // stage 5's own (unstack_stage4_5_tables): only their thrust, weight and burn time are used.
  StageData unstacked[2];
  // The dispersed flight's air-relative angle of attack at every point (FlightInputs::air_alpha_rad).
  double air_alpha_rad[kMaxTrajectoryPoints] = {};
  // `mission` as the Monte Carlo left it: a copy of *base but for the stage weights, the launch
  // azimuth and the tables marked here (build_monte_carlo_case). The next sample of the same nominal
  // restores only those from it instead of copying the whole Mission (about 68 kB) again; null base:
  // no such copy (build_dispersed_case, which changes other members, and a new workspace).
  struct MonteCarloEdits {
    const Mission* base = nullptr;
    bool thrust_blended[kMaxStages] = {};  // thrust, consumable weight and burn time (codes 1-8)
    bool drag_scaled = false;              // every stage's drag table (17-18)
    bool pitching_moment_blended = false;  // C_M_alpha (19-20)
  } monte_carlo_edits;
  // The Monte Carlo's plan (MonteCarloPlan), made by prepare_monte_carlo() with the data.
  MonteCarloPlan monte_carlo_plan;
};

// Where stacked stage-4/5 tables (codes 7-8 with block 55) split: entries [0, stage4_last] are
// stage 4's table; [stage5_first, size) are stage 5's, at table time stage5_offset_s + stage time
// (0 when stage 5's entries restart at 0, else the stage 4 duration plus the coast as input); the
// entries between are the coast (zero thrust, not flown: the coast keeps its optimized length).
struct StackedStage45Split {
  int stage4_last = 0;
  int stage5_first = 0;
  double stage5_offset_s = 0.0;
};

// Splits a stacked source by its block 55 durations. Stage 4 runs from the first entry (time 0) to
// the entry at d4 of the first increasing run of times; stage 5 is the last run when the times
// restart (it must start at 0 and end at d5), else the entries from t_last - d5 (one must lie
// there). Each part obeys the rules of a per-stage replacement table (validate_dispersion_data).
// kOk, or kDispersionStageDurationsMismatch (d4 or d5 not positive, or not a part's final time),
// kDispersionStackedTablesNotSplittable (a restart not at 0, thrust in the coast, no coast),
// kThrustWeightTimesDiffer or a per-stage table rule's status.
Status find_stacked_stage4_5_split(const DispersionSource& source, StackedStage45Split* split);

// The two parts of a split stacked source as stage 4's and stage 5's replacement tables (stage
// time from 0 at each ignition), each stage's burn time its table's last time.
Status unstack_stage4_5_tables(const DispersionSource& source, StageData* stage4, StageData* stage5);

// The stage a source disperses: the code table's, the card's stage for a tip-off (30-32), and
// stage 5 for the stage-4 thrust and weight codes (7-8, 15-16) whose card names stage 5 (five
// stages without the manual's squeeze; docs/theory/dispersions.md).
int dispersion_source_stage(const DispersionSource& source);

// Checks the data against the nominal before anything flies: known codes in increasing order,
// the tables finalized, tables of codes 1-8 within the capacities. kOk or the first fault
// (kDispersionCodeInvalid, kDispersionStageCodeMismatch, kTableEmpty, ...), with *fault_code the
// code at fault.
Status validate_dispersion_data(const DispersionData& data, int* fault_code);

// Builds the dispersed case of one source about the nominal: *mission, *prepared and *perturbation
// ready for fly_trajectory, with inputs.program = &workspace->program when program_mapped, else the
// nominal's program. A code that cannot be flown returns its named status.
// `nominal_prepared` is the nominal's prepare_case() result (its timeline maps the program onto a
// dispersed timeline: a thrust code changes the burn time, and the program is flown in stage time).
Status build_dispersed_case(const DispersionNominal& nominal, const PreparedCase& nominal_prepared,
                            const DispersionSource& source, DispersionWorkspace* workspace);

// The flight inputs of every dispersion-analysis flight, nominal and dispersed: the nominal's
// program and body dynamics, the state's sines inside a step by the addition theorem
// (FlightInputs::trig_by_series).
FlightInputs dispersion_flight_inputs(const DispersionNominal& nominal);

// Flies the case build_dispersed_case (or build_monte_carlo_case) left in the workspace about the
// nominal, lean (only what the record reads, with the flight's air-relative alpha), and records
// it into *out with record_dispersed_trajectory: the one flight of a dispersed trajectory, shared
// by the deterministic codes and the Monte Carlo samples. Leaves out->status alone.
Status fly_dispersed_case(const DispersionNominal& nominal, DispersionWorkspace* workspace,
                          DispersedTrajectory* out);

// The nominal per-point program carried onto a dispersed timeline (codes 1-8 change a burn time):
// a stage whose grid is the nominal's keeps its values; one whose grid changed flies the nominal
// program as a function of stage time, linear between the nominal points and continued at the
// last step's rate past the nominal burnout. `nominal` and `dispersed` are prepare_case() results.
void map_control_program(const PreparedCase& nominal, const ControlProgram& program,
                         const PreparedCase& dispersed, ControlProgram* out);

// The same rule for a data block 40 nominal (no per-point program): the table, its zero-alpha
// window and its latched segments read on a program clock that starts each stage at the nominal's
// start of it (FlightPerturbation::program_clock_shift_s: its start on `dispersed` minus its start
// on `nominal`); in stage 1 the clock runs with the step grid (program_clock_rate: the nominal's
// step over the dispersed), so the window opens and closes on the nominal's integration points.
void set_program_clock_shifts(const PreparedCase& nominal, const PreparedCase& dispersed,
                              FlightPerturbation* perturbation);

// Records the staging variables, orbit elements and max q-bar alpha of `flown` into *out (values
// only; dispersions are filled by run_dispersions). `reference` is the nominal trajectory (its
// staging points define the columns and the crossrange planes); `wind` may be null.
Status record_dispersed_trajectory(const Mission& mission, const PreparedCase& prepared,
                                   const Trajectory& reference, const Trajectory& flown,
                                   const WindProfile* wind, DispersedTrajectory* out);
// The same with the flight's air-relative angles of attack (FlightInputs::air_alpha_rad of the
// flight of `flown`; null: recomputed from the points under `wind` as above), bit for bit the same.
Status record_dispersed_trajectory(const Mission& mission, const PreparedCase& prepared,
                                   const Trajectory& reference, const Trajectory& flown,
                                   const WindProfile* wind, const double* air_alpha_rad,
                                   DispersedTrajectory* out);

// The whole analysis: flies the nominal (code 40 plane), every source, and the three-sigma groups
// when code 40 is among the sources. Returns the nominal's status (a dispersed trajectory that
// fails is recorded with its status and left out of the groups).
Status run_dispersions(const DispersionNominal& nominal, const DispersionData& data,
                       DispersionWorkspace* workspace, DispersionResult* result);

// The Sec. 15 groupings of result->trajectories into result->three_sigma.
void compute_three_sigma(DispersionResult* result);

// The one sign rule of the high/low groups (Sec. 15, 22): the final-point altitude dispersion,
// the velocity dispersion when that is zero; true for "high".
bool is_high_dispersion(const DispersedTrajectory& trajectory, int final_column);

}  // namespace tolip
