// Rules of the core (issue 16): the autopilot design (model, pole placement, margins), the gain
// schedule along the reference trajectory and the executor flying a schedule allocate nothing.
#include <gtest/gtest.h>

#include "support/allocation_counter.hpp"
#include "support/guidance_table_fixture.hpp"
#include "support/reference_hardover.hpp"
#include "support/reference_mission.hpp"
#include "tolip/autopilot/gain_schedule_design.hpp"
#include "tolip/table/guidance_executor.hpp"
#include "tolip/table/table_service.hpp"
#include "tolip/trajectory/trajectory.hpp"

namespace tolip {
namespace {

TEST(CoreNoHeap, AutopilotDesignAndScheduledExecutorAllocateNothing) {
  static Mission mission;
  static PreparedCase prepared;
  static Trajectory trajectory;
  static GainScheduleDesign schedule;
  static GuidanceTableService service;
  static std::uint8_t image[kTableImageSize];
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &mission);
  ASSERT_EQ(prepare_case(mission, &prepared), Status::kOk);
  ASSERT_EQ(fly_trajectory(mission, prepared, &trajectory), Status::kOk);
  const HardoverData hardover = test::reference_hardover();
  AutopilotRequest request;
  request.natural_frequency_rad_s = 2.0;
  request.damping_ratio = 0.7;
  request.attitude_error_rad = 1.0 * kDegToRad;
  request.max_deflection_rad = 10.0 * kDegToRad;
  request.actuator_time_constant_s = 0.02;
  const AutopilotRequest requests[kGainScheduleStages] = {request, request, request};
  const bool designed[kGainScheduleStages] = {true, true, true};
  GuidanceTable table = test::make_test_table(0);

  test::AllocationScope scope;
  int stage = 0;
  const Status designed_status =
      design_gain_schedule(mission, trajectory, hardover, requests, designed, 6, &schedule, &stage);
  table.schedule_count = schedule.count;
  for (int i = 0; i < schedule.count; ++i) {
    const GainScheduleDesignPoint& p = schedule.points[i];
    table.schedule[i] = GainSchedulePoint{p.stage_code, p.stage_time_s, p.design.k_theta, p.design.k_q_s};
  }
  const Status encoded = encode_table_image(table, image, sizeof image);
  const Status loaded = service.load(image, sizeof image);
  GuidanceExecutor executor(service);
  double sum = 0.0;
  const int failures = test::fly_test_timeline(executor, [&sum](const GuidanceCommand& command) {
    sum += command.k_theta + command.k_q_s;
    return true;
  });
  const auto allocations = scope.count();

  EXPECT_EQ(designed_status, Status::kOk) << stage;
  EXPECT_EQ(encoded, Status::kOk);
  EXPECT_EQ(loaded, Status::kOk);
  EXPECT_EQ(failures, 0);
  EXPECT_GT(sum, 0.0);
  EXPECT_EQ(allocations, 0u);
}

}  // namespace
}  // namespace tolip
