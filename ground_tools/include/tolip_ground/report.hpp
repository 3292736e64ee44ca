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

#include <nlohmann/json.hpp>

#include "tolip/core/status.hpp"
#include "tolip/mission/mission.hpp"
#include "tolip/orbit/orbit_elements.hpp"
#include "tolip/trajectory/trajectory.hpp"

namespace tolip::ground {

// What `simulate` computed. `trajectory` may be partial (status not kOk): its points are those
// flown up to the failure. The orbit elements exist only when the trajectory completed.
struct SimulationReport {
  const Mission* mission = nullptr;         // required
  const Trajectory* trajectory = nullptr;   // required (point_count 0 when prepare_case failed)
  Status status = Status::kNotPrepared;     // first failure of prepare/fly/orbit, or kOk
  bool has_orbit = false;
  OrbitElements orbit;                      // meaningful when has_orbit
  std::string deck_path;                    // echoed in the JSON document
};

// One column of the point table (CSV header, JSON point keys).
enum class ColumnKind : int { kReal, kInteger, kFlag };
struct PointColumn {
  const char* name;      // snake_case, unit suffix: "velocity_ft_s"
  const char* unit;      // for documentation: "ft/s"
  const char* meaning;   // for documentation
  ColumnKind kind;
  double (*value)(const TrajectoryPoint& point);  // flags give 0 or 1
};

// Every column of the CSV and of the JSON "trajectory" points, in CSV order.
std::span<const PointColumn> trajectory_point_columns();

// Angle in degrees reduced to (-180, 180].
double wrap_degrees_180(double degrees);

// The number of stored points that may be read (point_count clamped to the storage).
int stored_point_count(const Trajectory& trajectory);

// Manual-style listing: page titles from data blocks 1-3, the points that data block 9 selects for
// a final trajectory (is_output_point), the stage events, the terminal conditions and orbit.
void write_trajectory_listing(std::ostream& out, const SimulationReport& report);

// CSV: a header row of column names, then EVERY stored point (not thinned).
void write_trajectory_csv(std::ostream& out, const SimulationReport& report);

// The JSON document of `tolip simulate --json` (schema in docs/cli.md).
nlohmann::ordered_json trajectory_json(const SimulationReport& report);

// Serializes a document for stdout: 2-space indent, invalid UTF-8 replaced, trailing newline.
std::string dump_json(const nlohmann::ordered_json& document);

}  // namespace tolip::ground
