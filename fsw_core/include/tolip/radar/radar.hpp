// Radar tracking coordinates (manual Sec. 18, data block 41, IP(24) = 1): the azimuth, elevation
// and slant range from up to twenty Earth-fixed stations to the vehicle at every stored point of
// a trajectory, from launch through the burnout of its last powered stage.
//
// A station is given by geodetic latitude, longitude and altitude on the deck's ellipsoid (data
// block 10: CT1(3) the equatorial radius, CT1(12) = 298.3 the inverse flattening Sec. 18 names);
// its Earth-fixed position comes from the earth module (geodetic_to_earth_fixed_ft) and the
// topocentric frame (north, east, down) from the frames module (earth_fixed_to_topocentric), the
// same Earth the trajectory flies over. docs/theory/radar.md gives the equations and choices.
#pragma once

#include "tolip/core/capacity.hpp"
#include "tolip/core/constants.hpp"
#include "tolip/core/state.hpp"
#include "tolip/core/status.hpp"
#include "tolip/trajectory/trajectory.hpp"

namespace tolip {

// One card of data block 41: identification (2A6) and location.
struct RadarStation {
  char id[kRadarStationIdLength + 1] = {};  // NUL-terminated
  double geodetic_latitude_rad = 0.0;
  double longitude_rad = 0.0;  // Greenwich longitude, east positive
  double altitude_ft = 0.0;    // above the ellipsoid
};

// Data block 41: the stations (header field 4 is the count).
struct RadarStations {
  int count = 0;
  RadarStation stations[kMaxRadarStations];
};

// A station made ready for tracking (RADAR's "geocentric position and transformation matrix").
struct RadarSite {
  Vector3 position_ft = Vector3::Zero();         // Earth-fixed x_i, y_i, z_i
  Matrix3 to_topocentric = Matrix3::Identity();  // A(lambda_d, u_i)
};

// Look angles and slant range of one point from one station (Sec. 18 equations 1-3). Azimuth
// clockwise from north in [0, 2 pi); elevation above the geodetic horizontal plane (negative:
// below the horizon).
struct LookAngles {
  double azimuth_rad = 0.0;
  double elevation_rad = 0.0;
  double slant_range_ft = 0.0;
};

// Checks a station (latitude within +-90 deg, finite values) and makes its site.
Status prepare_radar_site(const Constants& constants, const RadarStation& station, RadarSite* site);

// Look angles of an Earth-fixed position from a site: [X Y Z]_g = A (x - x_i),
// a = atan2(Y, X), e = atan2(-Z, sqrt(X^2 + Y^2)), SR = |(X, Y, Z)|.
LookAngles look_angles(const RadarSite& site, const Vector3& earth_fixed_ft);

// The Earth-fixed position of a trajectory point (r, geocentric latitude, tau - omega t).
Vector3 earth_fixed_position_ft(const TrajectoryPoint& point);

// Index of the last point tracked: the last point of the last powered stage flown (the manual's
// "through stage-four burnout" for a four-stage vehicle); the trajectory's last point when it has
// no powered stage event.
int radar_last_point(const Trajectory& trajectory);

// The tracking of every station over the same points.
struct RadarResult {
  int station_count = 0;
  int point_count = 0;  // points tracked: 0 .. radar_last_point()
  double time_s[kMaxTrajectoryPoints] = {};
  int stage_code[kMaxTrajectoryPoints] = {};
  RadarSite sites[kMaxRadarStations];
  LookAngles look[kMaxRadarStations][kMaxTrajectoryPoints];
  int failed_station = -1;  // the station a validation failure names (-1: none)
};

// Validates every station (the count 1..kMaxRadarStations, each station as prepare_radar_site)
// before computing anything; then fills *result. On failure result->failed_station names the
// station (or -1 for the count or the trajectory) and no look angle is computed.
Status compute_radar_tracking(const Constants& constants, const RadarStations& stations,
                              const Trajectory& trajectory, RadarResult* result);

}  // namespace tolip
