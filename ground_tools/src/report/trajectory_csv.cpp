// CSV table of every integration point (`tolip simulate --csv FILE`).
#include <ostream>

#include "number_format.hpp"
#include "tolip_ground/report.hpp"

namespace tolip::ground {

void write_trajectory_csv(std::ostream& out, const SimulationReport& report) {
  const std::span<const PointColumn> columns = trajectory_point_columns();
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (c > 0) out << ',';
    out << columns[c].name;
  }
  out << '\n';
  if (report.trajectory == nullptr) return;
  const Trajectory& trajectory = *report.trajectory;
  const int count = stored_point_count(trajectory);
  for (int i = 0; i < count; ++i) {
    const TrajectoryPoint& point = trajectory.points[i];
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (c > 0) out << ',';
      const double value = columns[c].value(point);
      if (columns[c].kind == ColumnKind::kReal) {
        out << report_detail::round_trip(value);  // empty field when not finite
      } else {
        out << static_cast<long long>(value);
      }
    }
    out << '\n';
  }
}

}  // namespace tolip::ground
