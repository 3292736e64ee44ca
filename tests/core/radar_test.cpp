// Sec. 18: radar look angles and slant range against GeographicLib (an independent geodesy
// library: its Geocentric and LocalCartesian on the ellipsoid a = CT1(3), f = 1/298.3) for every
// reference station at every point of the reference trajectory, and against the oracle's vectors.
#include <gtest/gtest.h>
#include <GeographicLib/Geocentric.hpp>
#include <GeographicLib/LocalCartesian.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "support/reference_data.hpp"
#include "support/reference_mission.hpp"
#include "tolip/earth/earth_model.hpp"
#include "tolip/frames/frames.hpp"
#include "tolip/radar/radar.hpp"
#include "tolip/trajectory/trajectory.hpp"

namespace tolip {
namespace {

struct Flown {
  Mission mission;
  PreparedCase prepared;
  Trajectory trajectory;
  RadarStations stations;
  RadarResult radar;
};

RadarStations reference_stations() {
  RadarStations stations;
  for (const auto& s : test::scout_reference()["radar_stations_block41"]) {
    RadarStation& station = stations.stations[stations.count++];
    std::strncpy(station.id, s["id"].get<std::string>().c_str(), kRadarStationIdLength);
    station.geodetic_latitude_rad = s["geodetic_latitude_deg"].get<double>() * kDegToRad;
    station.longitude_rad = s["longitude_deg"].get<double>() * kDegToRad;
    station.altitude_ft = s["altitude_ft"].get<double>();
  }
  return stations;
}

// The oracle optimum flown once, and tracked from the six reference stations (static storage).
const Flown& reference_tracking() {
  static Flown* flown = [] {
    static Flown f;
    test::build_reference_mission(test::ReferenceProgram::kOptimum, &f.mission);
    EXPECT_EQ(prepare_case(f.mission, &f.prepared), Status::kOk);
    EXPECT_EQ(fly_trajectory(f.mission, f.prepared, &f.trajectory), Status::kOk);
    f.stations = reference_stations();
    EXPECT_EQ(compute_radar_tracking(f.mission.constants, f.stations, f.trajectory, &f.radar), Status::kOk);
    return &f;
  }();
  return *flown;
}

double wrap_deg(double angle_deg) {  // into (-180, 180]
  double a = std::fmod(angle_deg, 360.0);
  if (a > 180.0) a -= 360.0;
  if (a <= -180.0) a += 360.0;
  return a;
}

TEST(Sec18Radar, StationPositionsMatchGeographicLibGeocentric) {
  const Flown& f = reference_tracking();
  const double a_ft = f.mission.constants.earth_equatorial_radius_ft;
  ASSERT_EQ(f.mission.constants.inverse_flattening, 298.3);
  const GeographicLib::Geocentric earth(a_ft, 1.0 / 298.3);
  for (int s = 0; s < f.stations.count; ++s) {
    const RadarStation& st = f.stations.stations[s];
    double x, y, z;
    earth.Forward(st.geodetic_latitude_rad * kRadToDeg, st.longitude_rad * kRadToDeg, st.altitude_ft, x, y,
                  z);
    const Vector3& mine = f.radar.sites[s].position_ft;
    EXPECT_NEAR(mine.x(), x, 1e-6) << st.id;
    EXPECT_NEAR(mine.y(), y, 1e-6) << st.id;
    EXPECT_NEAR(mine.z(), z, 1e-6) << st.id;
  }
}

TEST(Sec18Radar, LookAnglesMatchGeographicLibAtEveryReferencePointFromEveryStation) {
  const Flown& f = reference_tracking();
  const double a_ft = f.mission.constants.earth_equatorial_radius_ft;
  const GeographicLib::Geocentric earth(a_ft, 1.0 / 298.3);
  ASSERT_EQ(f.radar.station_count, 6);
  // Launch through the stage-4 burnout: every point of the reference trajectory.
  ASSERT_EQ(f.radar.point_count, f.trajectory.point_count);
  double worst_az_deg = 0.0, worst_el_deg = 0.0, worst_range_ft = 0.0;
  int compared = 0, below_horizon = 0;
  for (int s = 0; s < f.stations.count; ++s) {
    const RadarStation& st = f.stations.stations[s];
    const GeographicLib::LocalCartesian site(st.geodetic_latitude_rad * kRadToDeg,
                                             st.longitude_rad * kRadToDeg, st.altitude_ft, earth);
    for (int i = 0; i < f.radar.point_count; ++i) {
      const TrajectoryPoint& p = f.trajectory.points[i];
      // The vehicle's Earth-fixed position from its geocentric spherical coordinates, then its
      // geodetic coordinates by GeographicLib's inverse, then east-north-up at the station.
      const double r = p.state[kStateR], lat = p.state[kStateLambda], lon = p.earth_longitude_rad;
      const double x = r * std::cos(lat) * std::cos(lon), y = r * std::cos(lat) * std::sin(lon),
                   z = r * std::sin(lat);
      double glat, glon, gh;
      earth.Reverse(x, y, z, glat, glon, gh);
      double east, north, up;
      site.Forward(glat, glon, gh, east, north, up);
      const double az_deg = std::atan2(east, north) * kRadToDeg;
      const double el_deg = std::atan2(up, std::hypot(east, north)) * kRadToDeg;
      const double range_ft = std::sqrt(east * east + north * north + up * up);
      const LookAngles& mine = f.radar.look[s][i];
      EXPECT_EQ(f.radar.time_s[i], p.time_s);
      EXPECT_GE(mine.azimuth_rad, 0.0);
      EXPECT_LT(mine.azimuth_rad, 2.0 * kPi);
      worst_az_deg = std::fmax(worst_az_deg, std::fabs(wrap_deg(mine.azimuth_rad * kRadToDeg - az_deg)));
      worst_el_deg = std::fmax(worst_el_deg, std::fabs(mine.elevation_rad * kRadToDeg - el_deg));
      worst_range_ft = std::fmax(worst_range_ft, std::fabs(mine.slant_range_ft - range_ft));
      below_horizon += mine.elevation_rad < 0.0 ? 1 : 0;
      ++compared;
    }
  }
  std::printf(
      "compared %d look angles (%d below the horizon); worst |d az| %.3e deg, |d el| %.3e deg, "
      "|d range| %.3e ft\n",
      compared, below_horizon, worst_az_deg, worst_el_deg, worst_range_ft);
  EXPECT_GT(below_horizon, 0);  // the far stations see the launch below their horizon
  EXPECT_LT(worst_az_deg, 1e-6);
  EXPECT_LT(worst_el_deg, 1e-6);
  EXPECT_LT(worst_range_ft, 0.01);
}

TEST(Sec18Radar, LookAnglesMatchTheOracleVectors) {
  const Flown& f = reference_tracking();
  const auto& vectors = test::oracle_test_vectors()["radar_look_angles_section18"];
  ASSERT_FALSE(vectors.empty());
  const double omega = f.mission.constants.earth_rotation_rate_rad_s;
  for (const auto& v : vectors) {
    int s = 0;
    while (s < f.stations.count && v["station"].get<std::string>() != f.stations.stations[s].id) ++s;
    ASSERT_LT(s, f.stations.count) << v["station"];
    TrajectoryPoint point;
    point.state = test::state_from_json(v["state"]);
    point.earth_longitude_rad = point.state[kStateTau] - omega * v["t_s"].get<double>();
    const LookAngles look = look_angles(f.radar.sites[s], earth_fixed_position_ft(point));
    EXPECT_NEAR(wrap_deg(look.azimuth_rad * kRadToDeg - v["azimuth_deg"].get<double>()), 0.0, 1e-8) << v;
    EXPECT_NEAR(look.elevation_rad * kRadToDeg, v["elevation_deg"].get<double>(), 1e-8) << v;
    EXPECT_NEAR(look.slant_range_ft, v["slant_range_ft"].get<double>(), 1e-4) << v;
  }
}

TEST(Sec18Radar, TopocentricMatrixIsTheNorthEastDownRotation) {
  for (const double lat_deg : {-90.0, -37.5, 0.0, 28.48, 90.0}) {
    for (const double lon_deg : {-180.0, -75.51, 0.0, 120.0}) {
      const double lat = lat_deg * kDegToRad, lon = lon_deg * kDegToRad;
      const Matrix3 a = earth_fixed_to_topocentric(lat, lon);
      EXPECT_LT((a * a.transpose() - Matrix3::Identity()).norm(), 1e-15);
      EXPECT_NEAR(a.determinant(), 1.0, 1e-15);
      // North-east-down is the passive turn about z by the longitude, then about y by -(90 + lat).
      const Matrix3 sequence = frame_rotation_y(-(0.5 * kPi + lat)) * frame_rotation_z(lon);
      EXPECT_LT((a - sequence).norm(), 1e-15) << lat_deg << " " << lon_deg;
    }
  }
}

TEST(Sec18Radar, VehicleOverheadIsAtNinetyDegreesElevation) {
  Constants constants;
  RadarStation station;
  station.geodetic_latitude_rad = 37.86 * kDegToRad;
  station.longitude_rad = -75.51 * kDegToRad;
  RadarSite site;
  ASSERT_EQ(prepare_radar_site(constants, station, &site), Status::kOk);
  const Vector3 above =
      geodetic_to_earth_fixed_ft(constants, station.geodetic_latitude_rad, station.longitude_rad, 100000.0);
  const LookAngles look = look_angles(site, above);
  EXPECT_NEAR(look.elevation_rad, 0.5 * kPi, 1e-12);
  EXPECT_NEAR(look.slant_range_ft, 100000.0, 1e-6);
  // Due north along the surface: azimuth 0; east: 90 deg; both below the horizon (the Earth curves).
  const Vector3 north = geodetic_to_earth_fixed_ft(constants, 38.86 * kDegToRad, station.longitude_rad, 0.0);
  const double north_azimuth = look_angles(site, north).azimuth_rad;
  EXPECT_TRUE(north_azimuth < 1e-12 || north_azimuth > 2.0 * kPi - 1e-12) << north_azimuth;
  EXPECT_LT(north_azimuth, 2.0 * kPi) << "the azimuth lies in [0, 360) deg";
  EXPECT_LT(look_angles(site, north).elevation_rad, 0.0);
  const Vector3 east =
      geodetic_to_earth_fixed_ft(constants, station.geodetic_latitude_rad, -75.50 * kDegToRad, 0.0);
  EXPECT_NEAR(look_angles(site, east).azimuth_rad, 0.5 * kPi, 1e-4);  // a parallel is no great circle
  EXPECT_LT(look_angles(site, east).elevation_rad, 0.0);
}

TEST(Sec18Radar, BadStationsAreRejectedNamingTheStationBeforeAnythingIsComputed) {
  const Flown& f = reference_tracking();
  static RadarResult result;
  RadarStations stations = reference_stations();
  stations.stations[3].geodetic_latitude_rad = 90.0001 * kDegToRad;
  EXPECT_EQ(compute_radar_tracking(f.mission.constants, stations, f.trajectory, &result),
            Status::kRadarStationLatitudeOutOfRange);
  EXPECT_EQ(result.failed_station, 3);
  EXPECT_EQ(result.point_count, 0);
  stations = reference_stations();
  stations.stations[1].altitude_ft = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(compute_radar_tracking(f.mission.constants, stations, f.trajectory, &result),
            Status::kRadarStationNotFinite);
  EXPECT_EQ(result.failed_station, 1);
  for (const int count : {0, -1, kMaxRadarStations + 1}) {
    stations.count = count;
    EXPECT_EQ(compute_radar_tracking(f.mission.constants, stations, f.trajectory, &result),
              Status::kRadarStationCountInvalid)
        << count;
    EXPECT_EQ(result.station_count, 0);
  }
  // Exactly the poles are stations like any other.
  stations = reference_stations();
  stations.stations[0].geodetic_latitude_rad = -0.5 * kPi;
  EXPECT_EQ(compute_radar_tracking(f.mission.constants, stations, f.trajectory, &result), Status::kOk);
  static Trajectory empty;
  empty.point_count = 0;
  EXPECT_EQ(compute_radar_tracking(f.mission.constants, reference_stations(), empty, &result),
            Status::kRadarNoTrajectory);
}

TEST(Sec18Radar, TracksThroughTheLastPoweredBurnoutOnly) {
  static Trajectory trajectory;
  trajectory.point_count = 12;
  trajectory.stage_count = 3;
  trajectory.stages[0] = {1, 0, 4, 0.0, 0.0, true};
  trajectory.stages[1] = {2, 5, 8, 0.0, 0.0, true};
  trajectory.stages[2] = {7, 9, 11, 0.0, 0.0, true};  // a coast after the last burnout: not tracked
  EXPECT_EQ(radar_last_point(trajectory), 8);
  trajectory.stage_count = 2;
  EXPECT_EQ(radar_last_point(trajectory), 8);
  trajectory.stage_count = 0;
  EXPECT_EQ(radar_last_point(trajectory), 11);
}

}  // namespace
}  // namespace tolip
