// Rules of the core: the radar tracking of Sec. 18 (every station at every point) allocates
// nothing. The mission is built and flown (with heap, JSON) before the counting window.
#include <gtest/gtest.h>

#include <cstring>

#include "support/allocation_counter.hpp"
#include "support/reference_data.hpp"
#include "support/reference_mission.hpp"
#include "tolip/radar/radar.hpp"
#include "tolip/trajectory/trajectory.hpp"

namespace tolip {
namespace {

TEST(CoreNoHeap, RadarTrackingOfEveryStationAllocatesNothing) {
  static Mission mission;
  static PreparedCase prepared;
  static Trajectory trajectory;
  static RadarStations stations;
  static RadarResult result;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &mission);
  ASSERT_EQ(prepare_case(mission, &prepared), Status::kOk);
  ASSERT_EQ(fly_trajectory(mission, prepared, &trajectory), Status::kOk);
  for (const auto& s : test::scout_reference()["radar_stations_block41"]) {
    RadarStation& station = stations.stations[stations.count++];
    std::strncpy(station.id, s["id"].get<std::string>().c_str(), kRadarStationIdLength);
    station.geodetic_latitude_rad = s["geodetic_latitude_deg"].get<double>() * kDegToRad;
    station.longitude_rad = s["longitude_deg"].get<double>() * kDegToRad;
    station.altitude_ft = s["altitude_ft"].get<double>();
  }

  test::AllocationScope scope;
  const Status status = compute_radar_tracking(mission.constants, stations, trajectory, &result);
  const auto allocations = scope.count();

  EXPECT_EQ(status, Status::kOk);
  EXPECT_EQ(result.station_count, 6);  // the work really happened
  EXPECT_GT(result.point_count, 190);
  EXPECT_EQ(allocations, 0u);
}

}  // namespace
}  // namespace tolip
