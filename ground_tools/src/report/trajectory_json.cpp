// The JSON document of `tolip simulate --json` (schema: docs/cli.md).
#include <algorithm>
#include <cmath>

#include "case_document.hpp"
#include "number_format.hpp"
#include "tolip/core/constants.hpp"
#include "tolip/core/state.hpp"
#include "tolip_ground/deck_extras.hpp"
#include "tolip_ground/hardover_report.hpp"
#include "tolip_ground/radar_report.hpp"
#include "tolip_ground/report.hpp"

namespace tolip::ground {
namespace {

using json = nlohmann::ordered_json;
using report_detail::json_number;

// Radians in degrees, or null when not finite.
json degrees(double radians) { return json_number(radians * kRadToDeg); }

const char* orbit_type_name(OrbitType type) {
  switch (type) {
    case OrbitType::kElliptic: return "elliptic";
    case OrbitType::kParabolic: return "parabolic";
    case OrbitType::kHyperbolic: return "hyperbolic";
  }
  return "unknown";
}

json point_json(const TrajectoryPoint& point) {
  json object = json::object();
  for (const PointColumn& column : trajectory_point_columns()) {
    const double value = column.value(point);
    switch (column.kind) {
      case ColumnKind::kReal: object[column.name] = json_number(value); break;
      case ColumnKind::kInteger: object[column.name] = static_cast<long long>(value); break;
      case ColumnKind::kFlag: object[column.name] = value != 0.0; break;
    }
  }
  return object;
}

json burnout_json(const TrajectoryPoint& point) {
  return json{
      {"time_s", json_number(point.time_s)},
      {"stage", point.stage_code},
      {"stage_time_s", json_number(point.stage_time_s)},
      {"velocity_ft_s", json_number(point.state[kStateV])},
      {"gamma_deg", degrees(point.state[kStateGamma])},
      {"psi_deg", degrees(point.state[kStatePsi])},
      {"radius_ft", json_number(point.state[kStateR])},
      {"altitude_ft", json_number(point.altitude_ft)},
      {"geocentric_latitude_deg", degrees(point.state[kStateLambda])},
      {"geodetic_latitude_deg", degrees(point.geodetic_latitude_rad)},
      {"longitude_deg", json_number(wrap_degrees_180(point.earth_longitude_rad * kRadToDeg))},
      {"inertial_longitude_deg", json_number(wrap_degrees_180(point.state[kStateTau] * kRadToDeg))},
      {"range_nmi", json_number(point.downrange_rad * kNauticalMilesPerRadian)},
      {"weight_lb", json_number(point.weight_lb)},
  };
}

json inertial_json(const InertialVelocity& inertial) {
  return json{
      {"velocity_ft_s", json_number(inertial.velocity_ft_s)},
      {"gamma_deg", degrees(inertial.flight_path_angle_rad)},
      {"psi_deg", degrees(inertial.azimuth_rad)},
  };
}

json orbit_json(const OrbitElements& orbit, const Constants& constants) {
  const bool elliptic = orbit.has_semi_major_axis;
  const bool asymptote = orbit.has_asymptote;
  const OrbitSummary summary = summarize_orbit(constants, orbit);
  return json{
      {"type", orbit_type_name(orbit.type)},
      {"twoe_ft2_s2", json_number(orbit.twice_energy_ft2_s2)},
      {"angular_momentum_ft2_s", json_number(orbit.angular_momentum_ft2_s)},
      {"perigee_radius_ft", json_number(orbit.perigee_radius_ft)},
      {"apogee_radius_ft", elliptic ? json_number(orbit.apogee_radius_ft) : json(nullptr)},
      {"inclination_deg", degrees(orbit.inclination_rad)},
      {"argument_of_perigee_deg", degrees(orbit.argument_of_perigee_rad)},
      {"node_longitude_deg", degrees(orbit.node_longitude_rad)},
      {"right_ascension_deg", degrees(orbit.right_ascension_rad)},
      {"nu_deg", degrees(orbit.nu_rad)},
      {"in_plane_angle_from_node_deg", degrees(orbit.in_plane_angle_from_node_rad)},
      {"true_anomaly_deg", degrees(orbit.true_anomaly_rad)},
      {"eccentricity", json_number(orbit.eccentricity)},
      {"semi_major_axis_ft", elliptic ? json_number(orbit.semi_major_axis_ft) : json(nullptr)},
      {"period_min", elliptic ? json_number(orbit.period_s / 60.0) : json(nullptr)},
      {"hyperbolic_excess_velocity_ft_s",
       asymptote ? json_number(orbit.hyperbolic_excess_velocity_ft_s) : json(nullptr)},
      {"asymptote_right_ascension_deg",
       asymptote ? degrees(orbit.asymptote_right_ascension_rad) : json(nullptr)},
      {"asymptote_declination_deg", asymptote ? degrees(orbit.asymptote_declination_rad) : json(nullptr)},
      // In engineering terms (summarize_orbit): above the oblate Earth at their latitudes.
      {"path", path_class_name(summary.path)},
      {"perigee_altitude_ft", json_number(summary.perigee_altitude_ft)},
      {"perigee_altitude_nmi", json_number(summary.perigee_altitude_ft / kFeetPerNauticalMile)},
      {"apogee_altitude_ft", elliptic ? json_number(summary.apogee_altitude_ft) : json(nullptr)},
      {"apogee_altitude_nmi",
       elliptic ? json_number(summary.apogee_altitude_ft / kFeetPerNauticalMile) : json(nullptr)},
      {"perigee_geocentric_latitude_deg", degrees(summary.perigee_latitude_rad)},
      {"perigee_below_haero", summary.perigee_in_atmosphere},
  };
}

// A point's value, or null when the index is outside the points flown.
json at_point(const Trajectory& trajectory, int index, double (*value)(const TrajectoryPoint&)) {
  if (index < 0 || index >= stored_point_count(trajectory)) return json(nullptr);
  return json_number(value(trajectory.points[index]));
}

json stage_events_json(const Trajectory& trajectory) {
  json events = json::array();
  const int count = std::min(std::max(trajectory.stage_count, 0), kMaxStages);
  for (int s = 0; s < count; ++s) {
    const StageEvent& event = trajectory.stages[s];
    const auto time = [](const TrajectoryPoint& p) { return p.time_s; };
    const auto weight = [](const TrajectoryPoint& p) { return p.weight_lb; };
    const auto velocity = [](const TrajectoryPoint& p) { return p.state[kStateV]; };
    const auto altitude = [](const TrajectoryPoint& p) { return p.altitude_ft; };
    events.push_back(json{
        {"stage", event.code},
        {"kind", is_powered_stage(event.code) ? "powered" : "coast"},
        {"first_point", event.first_point},
        {"last_point", event.last_point},
        {"start_time_s", at_point(trajectory, event.first_point, time)},
        {"end_time_s", at_point(trajectory, event.last_point, time)},
        {"start_weight_lb", at_point(trajectory, event.first_point, weight)},
        {"end_velocity_ft_s", at_point(trajectory, event.last_point, velocity)},
        {"end_altitude_ft", at_point(trajectory, event.last_point, altitude)},
        {"burnout_weight_lb", json_number(event.burnout_weight_lb)},
        {"completed", event.completed},
        {"jettison_weight_lb", event.completed
                                   ? json_number(event.burnout_weight_lb - event.weight_after_jettison_lb)
                                   : json(nullptr)},
        {"weight_after_jettison_lb",
         event.completed ? json_number(event.weight_after_jettison_lb) : json(nullptr)},
    });
  }
  return events;
}

}  // namespace

nlohmann::ordered_json constraints_json(const std::vector<ConstraintSummary>& constraints) {
  nlohmann::ordered_json array = nlohmann::ordered_json::array();
  for (const ConstraintSummary& c : constraints) {
    array.push_back(nlohmann::ordered_json{
        {"code", c.code},
        {"name", c.name},
        {"stage", c.stage > 0 ? nlohmann::ordered_json(c.stage) : nlohmann::ordered_json(nullptr)},
        {"unit", c.unit},
        {"desired", json_number(c.desired)},
        {"achieved", json_number(c.achieved)},
        {"error", json_number(c.error)},
        {"tolerance", json_number(c.tolerance)},
        {"inequality", c.inequality},
        {"met", c.met},
    });
  }
  return array;
}

json trajectory_json(const SimulationReport& report) {
  const Mission& mission = *report.mission;
  const Trajectory& trajectory = *report.trajectory;
  const int count = stored_point_count(trajectory);

  static const DeckListingOptions kNoListing;  // blank titles
  json document = report_detail::case_document(
      report.deck_path, report.listing != nullptr ? *report.listing : kNoListing, report.status);
  document["launch_space_age_date_days"] = json_number(mission.launch.launch_space_age_date_days);
  document["point_count"] = count;
  document["heat_integral_btu_ft2"] = json_number(trajectory.heat_integral_btu_ft2);

  if (count > 0) {
    const TrajectoryPoint& last = trajectory.points[count - 1];
    document["burnout"] = burnout_json(last);
    document["inertial"] = inertial_json(report.has_orbit ? report.orbit.inertial : last.inertial);
  } else {
    document["burnout"] = nullptr;
    document["inertial"] = nullptr;
  }
  document["orbit"] = report.has_orbit ? orbit_json(report.orbit, mission.constants) : json(nullptr);
  if (!report.constraints.empty()) document["constraints"] = constraints_json(report.constraints);
  document["stage_events"] = stage_events_json(trajectory);
  if (report.hardover != nullptr) document["hardover"] = hardover_json(*report.hardover);
  if (report.radar != nullptr) document["radar"] = radar_json(*report.radar);

  document["trajectory"] = trajectory_points_json(trajectory);
  return document;
}

json trajectory_points_json(const Trajectory& trajectory) {
  json points = json::array();
  for (int i = 0; i < stored_point_count(trajectory); ++i) points.push_back(point_json(trajectory.points[i]));
  return points;
}

std::string dump_json(const nlohmann::ordered_json& document) {
  return document.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

}  // namespace tolip::ground
