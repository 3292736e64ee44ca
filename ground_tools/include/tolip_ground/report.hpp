// Reports of a simulated trajectory: the manual-style listing (Sec. 22 "OUTPUT FORMAT"), the CSV
// table of every integration point and the JSON document of `tolip simulate --json`.
//
// All three read the same SimulationReport and the same column table, so a column has one name,
// one unit and one meaning everywhere (docs/cli.md lists them). Non-finite values are never
// printed as "nan": JSON gets null, CSV an empty field, the listing "-".
#pragma once

#include <ostream>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tolip/core/status.hpp"
#include "tolip/mission/mission.hpp"
#include "tolip/orbit/orbit_elements.hpp"
#include "tolip/trajectory/trajectory.hpp"
#include "tolip_ground/units.hpp"

namespace tolip::ground {

struct DeckListingOptions;  // tolip_ground/deck_extras.hpp
struct OutputFrequency;     // tolip_ground/deck_extras.hpp
struct ImpactStep;          // tolip_ground/impact_run.hpp
struct RadarStep;           // tolip_ground/radar_run.hpp
struct HardoverStep;        // tolip_ground/hardover_run.hpp

// One constraint of data blocks 8/19/29 after the payoff, in the units of data block 19 (ft, rad,
// ft/s, n.mi., ft^2/s^2, Btu/ft^2, lbf/ft^2).
struct ConstraintSummary {
  int code = 0;
  std::string name;    // snake_case quantity: "altitude", "inertial_flight_path_angle", ...
  int stage = 0;       // X of a stage-point code 10 X + 5..9; 0 for a terminal constraint
  std::string unit;    // data block 19 unit: "ft", "rad", "ft/s", "nmi", ...
  bool angle = false;  // unit "rad" (the listing adds degrees)
  double desired = 0.0;
  double achieved = 0.0;        // on the trajectory; NaN when it could not be evaluated
  double error = 0.0;           // achieved - desired (angles 12, 13, 101 wrapped into [-pi, pi))
  double tolerance = 0.0;       // data block 29 optimization deadband
  double payoff_partial = 0.0;  // d payoff / d constraint (eq. 9-22), payoff unit per `unit`
  // An upper limit, not an equality: total heating (14, Sec. 13) and the dynamic pressure X9
  // under IP(13) = 1. Only an excess (error > 0) counts.
  bool inequality = false;
  bool met = false;  // |error| <= tolerance (inequality: error <= tolerance)
};

// Which of the trajectory kinds of data block 9 a run is, for output thinning.
enum class TrajectoryKind : int { kInitial, kIntermediate, kFinal };

// What `simulate` computed. `trajectory` may be partial (status not kOk): its points are those
// flown up to the failure. The orbit elements exist only when the trajectory completed.
struct SimulationReport {
  const Mission* mission = nullptr;  // required
  // Data blocks 1-3, 9 and 10 words 8-9 (the deck's DeckExtras::listing); null: blank titles, every
  // point, the nominal page layout.
  const DeckListingOptions* listing = nullptr;
  const Trajectory* trajectory = nullptr;  // required (point_count 0 when prepare_case failed)
  Status status = Status::kNotPrepared;    // first failure of prepare/fly/orbit, or kOk
  bool has_orbit = false;
  OrbitElements orbit;    // meaningful when has_orbit
  std::string deck_path;  // echoed in the JSON document
  // `simulate`: the deck's constraints on this trajectory (deck_constraint_summaries), listed after
  // the terminal conditions and in the JSON member "constraints". Empty for optimize's final
  // trajectory, whose summary reports them against the optimizer's deadbands.
  std::vector<ConstraintSummary> constraints;
  // `simulate` with IP(23) = 1: the impact locus about this trajectory, listed after it
  // (impact_report.hpp). Null: none.
  const ImpactStep* impact = nullptr;
  // `simulate` with IP(24) = 1: the radar tracking of this trajectory (radar_run.hpp), listed after
  // it and in the JSON member "radar"; null otherwise (optimize reports its own).
  const RadarStep* radar = nullptr;
  // `simulate` with IP(22) = 1: the hardover turns from this trajectory (hardover_run.hpp).
  const HardoverStep* hardover = nullptr;
  // The other trajectory listings of `optimize --listing-level full|runs` (docs/cli.md): the
  // section title of the points' pages, the data block 9 frequency they are thinned with, and
  // `all_columns`, the third line group of Sec. 22's columns (CHI, BETA6D, THETAC, THETADOT,
  // DTHETA, DELTA). The defaults list the final trajectory as simulate always has.
  std::string section = "FINAL TRAJECTORY";
  TrajectoryKind kind = TrajectoryKind::kFinal;
  bool all_columns = false;
  // DTHETA's "current nominal" (Sec. 22): the trajectory this one was flown about, point for point
  // (a different grid: "-"); null: no DTHETA.
  const Trajectory* reference = nullptr;
};

// The deck's constraints (data blocks 8, 19, 29: code, desired value, optimization deadband) as
// the optimizer evaluates them, on a trajectory that may have stopped early (then NaN achieved).
std::vector<ConstraintSummary> deck_constraint_summaries(const Mission& mission,
                                                         const Trajectory& trajectory);
// Their JSON array (docs/cli.md: `constraints` of simulate and optimize).
nlohmann::ordered_json constraints_json(const std::vector<ConstraintSummary>& constraints);

// One column of the point table (CSV header, JSON point keys).
enum class ColumnKind : int { kReal, kInteger, kFlag };
struct PointColumn {
  const char* name;     // snake_case, unit suffix: "velocity_ft_s"
  const char* unit;     // for documentation: "ft/s"
  const char* meaning;  // for documentation
  ColumnKind kind;
  double (*value)(const TrajectoryPoint& point);  // flags give 0 or 1
};

// Every column of the CSV and of the JSON "trajectory" points, in CSV order.
std::span<const PointColumn> trajectory_point_columns();

// Angle in degrees reduced to (-180, 180].
double wrap_degrees_180(double degrees);

// What the terminal state's path is, in a trajectory engineer's terms.
enum class PathClass : int {
  kOrbit,       // elliptic, perigee above the surface
  kSuborbital,  // elliptic with the perigee below the surface: it comes down within a revolution
  kEscape,      // parabolic or hyperbolic (2E >= 0)
};
const char* path_class_name(PathClass path);  // "orbit", "suborbital", "escape"

// The orbit elements in engineering terms: perigee and apogee altitude above the oblate Earth at
// their latitudes (sin(latitude) = sin(EYE) sin(BETAP) at perigee, its negative at apogee), and the
// path class. Apogee values are NaN unless the orbit is elliptic.
struct OrbitSummary {
  PathClass path = PathClass::kOrbit;
  double perigee_altitude_ft = 0.0;
  double apogee_altitude_ft = 0.0;
  double perigee_latitude_rad = 0.0;   // geocentric
  bool perigee_in_atmosphere = false;  // above the surface but below CT1(7) HAERO
};
OrbitSummary summarize_orbit(const Constants& constants, const OrbitElements& orbit);

// The number of stored points that may be read (point_count clamped to the storage).
int stored_point_count(const Trajectory& trajectory);

// True when point `index` is listed at the data block 9 frequency: every n-th point of its stage,
// and always the first and last point of each stage (and the pad point).
bool is_output_point(const OutputFrequency& output, const Trajectory& trajectory, int index,
                     TrajectoryKind kind);

// Manual-style listing: page titles from data blocks 1-3, the points that data block 9 selects for
// a final trajectory (is_output_point), the stage events, the terminal conditions and orbit.
void write_trajectory_listing(std::ostream& out, const SimulationReport& report);

// CSV: a header row of column names, then EVERY stored point (not thinned).
void write_trajectory_csv(std::ostream& out, const SimulationReport& report);

// The JSON document of `tolip simulate --json` (schema in docs/cli.md).
nlohmann::ordered_json trajectory_json(const SimulationReport& report);

// The "trajectory" array of that document: every stored point of `trajectory`, one object each
// (also the linearized trajectory's points in `optimize --json`).
nlohmann::ordered_json trajectory_points_json(const Trajectory& trajectory);

// Serializes a document for stdout: 2-space indent, invalid UTF-8 replaced, trailing newline.
std::string dump_json(const nlohmann::ordered_json& document);

}  // namespace tolip::ground
