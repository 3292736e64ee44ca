// Rules of the core: a full optimization (initial nominal, guidance, optimization, final guidance,
// every backward run) allocates nothing.
#include <gtest/gtest.h>

#include "support/allocation_counter.hpp"
#include "support/reference_mission.hpp"
#include "tolip/optimizer/steepest_descent.hpp"

namespace tolip {
namespace {

TEST(CoreNoHeap, FullOptimizationAllocatesNothing) {
  static Mission mission;
  static OptimizerWorkspace workspace;
  static OptimizerResult result;
  test::build_reference_mission(test::ReferenceProgram::kInitialNominal, &mission);

  test::AllocationScope scope;
  const Status status = optimize_trajectory(mission, &workspace, &result);
  const auto allocations = scope.count();

  EXPECT_EQ(status, Status::kOk);
  EXPECT_GT(result.forward_runs, 5);  // the work really happened
  EXPECT_EQ(allocations, 0u);
}

}  // namespace
}  // namespace tolip

namespace tolip {
namespace {

// The same without the heading hold (a heritage deck): the near-vertical steps and their backward
// sweep in regular coordinates (tolip/dynamics/vertical_flight.hpp) allocate nothing either.
TEST(CoreNoHeap, OptimizationWithNearVerticalStepsAllocatesNothing) {
  static Mission mission;
  static OptimizerWorkspace workspace;
  static OptimizerResult result;
  test::build_reference_mission(test::ReferenceProgram::kInitialNominal, &mission);
  mission.launch.heading_hold_until_s = 0.0;

  test::AllocationScope scope;
  const Status status = optimize_trajectory(mission, &workspace, &result);
  const auto allocations = scope.count();

  EXPECT_EQ(status, Status::kOk);
  bool vertical_steps = false;
  for (int s = 0; s < workspace.nominal.step_count; ++s)
    vertical_steps |= workspace.nominal.steps[s].command.vertical_flight;
  EXPECT_TRUE(vertical_steps);
  EXPECT_GT(result.forward_runs, 5);
  EXPECT_EQ(allocations, 0u);
}

}  // namespace
}  // namespace tolip
