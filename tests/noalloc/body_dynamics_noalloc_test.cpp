// Rules of the core: a 6D forward trajectory (body dynamics in stage 1 and coast 6, Sec. 7 and 11)
// allocates nothing, validation of data blocks 33-37 included.
#include <gtest/gtest.h>

#include "support/allocation_counter.hpp"
#include "support/reference_mission.hpp"
#include "tolip/body/body_dynamics.hpp"
#include "tolip/trajectory/trajectory.hpp"

namespace tolip {
namespace {

TEST(CoreNoHeap, BodyDynamicsForwardTrajectoryAllocatesNothing) {
  static Mission mission;
  static PreparedCase prepared;
  static Trajectory trajectory;
  test::build_reference_mission(test::ReferenceProgram::kInitialNominal, &mission);
  MissionFault fault;

  test::AllocationScope scope;
  const Status valid = validate_mission(mission, &fault);
  const Status body = validate_body_dynamics(mission, &fault);
  const Status prepare = prepare_case(mission, &prepared);
  FlightInputs inputs;
  inputs.body_dynamics = true;
  const Status fly = fly_trajectory(mission, prepared, inputs, &trajectory);
  BodyDynamicsInputs direct;
  direct.conditions.dynamic_pressure_lbf_ft2 = 1000.0;
  direct.conditions.mach = 1.5;
  direct.conditions.vacuum_thrust_lbf = 100000.0;
  direct.command.theta_rad = 0.8;
  BodyDynamicsResult result;
  const Status direct_status = evaluate_body_dynamics(mission.body_dynamics, direct, &result);
  const auto allocations = scope.count();

  EXPECT_EQ(valid, Status::kOk);
  EXPECT_EQ(body, Status::kOk);
  EXPECT_EQ(prepare, Status::kOk);
  EXPECT_EQ(fly, Status::kOk);
  EXPECT_EQ(direct_status, Status::kOk);
  int six_d_points = 0;
  for (int i = 0; i < trajectory.point_count; ++i) six_d_points += trajectory.points[i].body_dynamics ? 1 : 0;
  EXPECT_GT(six_d_points, 40);  // the 6D work really happened
  EXPECT_EQ(allocations, 0u);
}

}  // namespace
}  // namespace tolip
