// Radar tracking coordinates, manual Sec. 18 (docs/theory/radar.md).
#include "tolip/radar/radar.hpp"

#include <cmath>

#include "tolip/core/constants.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/frames/frames.hpp"

namespace tolip {

Status prepare_radar_site(const Constants& constants, const RadarStation& station, RadarSite* site) {
  if (!std::isfinite(station.geodetic_latitude_rad) || !std::isfinite(station.longitude_rad) ||
      !std::isfinite(station.altitude_ft)) {
    return Status::kRadarStationNotFinite;
  }
  if (std::fabs(station.geodetic_latitude_rad) > 0.5 * kPi) return Status::kRadarStationLatitudeOutOfRange;
  site->position_ft = geodetic_to_earth_fixed_ft(constants, station.geodetic_latitude_rad,
                                                 station.longitude_rad, station.altitude_ft);
  site->to_topocentric = earth_fixed_to_topocentric(station.geodetic_latitude_rad, station.longitude_rad);
  return Status::kOk;
}

LookAngles look_angles(const RadarSite& site, const Vector3& earth_fixed_ft) {
  const Vector3 g = site.to_topocentric * (earth_fixed_ft - site.position_ft);  // north, east, down
  const double horizontal_ft = std::hypot(g.x(), g.y());
  LookAngles look;
  // atan2 rather than the printed arctangent of the quotient: the quadrant of the azimuth, and a
  // vehicle straight overhead (X = Y = 0) gives azimuth 0 and elevation 90 deg.
  double azimuth_rad = std::atan2(g.y(), g.x());
  if (azimuth_rad < 0.0) azimuth_rad += 2.0 * kPi;
  // A hair west of north (atan2 of -1e-17) rounds to 2 pi itself: that is north, 0.
  if (azimuth_rad >= 2.0 * kPi) azimuth_rad = 0.0;
  look.azimuth_rad = azimuth_rad;
  look.elevation_rad = std::atan2(-g.z(), horizontal_ft);
  look.slant_range_ft = g.norm();
  return look;
}

Vector3 earth_fixed_position_ft(const TrajectoryPoint& point) {
  return geocentric_to_earth_fixed_ft(point.state[kStateR], point.state[kStateLambda],
                                      point.earth_longitude_rad);
}

int radar_last_point(const Trajectory& trajectory) {
  int last = trajectory.point_count - 1;
  for (int i = trajectory.stage_count - 1; i >= 0; --i) {
    const int code = trajectory.stages[i].code;
    if (code >= 1 && code <= kMaxPoweredStages) {
      last = trajectory.stages[i].last_point;
      break;
    }
  }
  if (last > trajectory.point_count - 1) last = trajectory.point_count - 1;
  return last;
}

Status compute_radar_tracking(const Constants& constants, const RadarStations& stations,
                              const Trajectory& trajectory, RadarResult* result) {
  result->station_count = 0;
  result->point_count = 0;
  result->failed_station = -1;
  if (stations.count < 1 || stations.count > kMaxRadarStations) return Status::kRadarStationCountInvalid;
  for (int s = 0; s < stations.count; ++s) {
    const Status status = prepare_radar_site(constants, stations.stations[s], &result->sites[s]);
    if (!ok(status)) {
      result->failed_station = s;
      return status;
    }
  }
  if (trajectory.point_count < 1) return Status::kRadarNoTrajectory;
  const int count = radar_last_point(trajectory) + 1;
  for (int i = 0; i < count; ++i) {
    const TrajectoryPoint& point = trajectory.points[i];
    result->time_s[i] = point.time_s;
    result->stage_code[i] = point.stage_code;
    const Vector3 position_ft = earth_fixed_position_ft(point);
    for (int s = 0; s < stations.count; ++s) result->look[s][i] = look_angles(result->sites[s], position_ft);
  }
  result->station_count = stations.count;
  result->point_count = count;
  return Status::kOk;
}

}  // namespace tolip
