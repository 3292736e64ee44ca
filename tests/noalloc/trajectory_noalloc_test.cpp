// Rules of the core: a full forward trajectory (prepare + lift-off + every stage + orbit elements)
// allocates nothing. The reference mission is built (with heap, JSON) before the counting window.
#include <gtest/gtest.h>

#include "support/allocation_counter.hpp"
#include "support/reference_mission.hpp"
#include "tolip/orbit/orbit_elements.hpp"
#include "tolip/trajectory/trajectory.hpp"

namespace tolip {
namespace {

TEST(CoreNoHeap, FullForwardTrajectoryAllocatesNothing) {
  static Mission mission;
  static PreparedCase prepared;
  static Trajectory trajectory;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &mission);
  MissionFault fault;

  test::AllocationScope scope;
  const Status valid = validate_mission(mission, &fault);
  const Status prepare = prepare_case(mission, &prepared);
  const Status fly = fly_trajectory(mission, prepared, &trajectory);
  OrbitElements elements;
  const Status orbit = compute_orbit_elements(mission.constants, trajectory.final_point().state,
                                              mission.launch.launch_space_age_date_days, &elements);
  const auto allocations = scope.count();

  EXPECT_EQ(valid, Status::kOk);
  EXPECT_EQ(prepare, Status::kOk);
  EXPECT_EQ(fly, Status::kOk);
  EXPECT_EQ(orbit, Status::kOk);
  EXPECT_GT(trajectory.point_count, 190);  // the work really happened
  EXPECT_EQ(allocations, 0u);
}

}  // namespace
}  // namespace tolip
