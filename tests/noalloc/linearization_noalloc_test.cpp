// Rules of the core: the pitch-program linearization (Sec. 6, 10: backward linearization runs, the
// eq. 6-22 fits with their rate repairs, forward linearization runs) allocates nothing.
#include <gtest/gtest.h>

#include "support/allocation_counter.hpp"
#include "support/reference_mission.hpp"
#include "tolip/optimizer/linearization.hpp"
#include "tolip/optimizer/steepest_descent.hpp"

namespace tolip {
namespace {

TEST(CoreNoHeap, LinearizationAllocatesNothing) {
  static Mission mission;
  static OptimizerWorkspace optimized;
  static OptimizerResult optimum;
  static LinearizationWorkspace workspace;
  static LinearizationResult result;
  test::build_reference_mission(test::ReferenceProgram::kInitialNominal, &mission);
  ASSERT_EQ(optimize_trajectory(mission, &optimized, &optimum), Status::kOk);

  test::AllocationScope scope;
  const Status status = linearize_pitch_program(optimized, &workspace, &result);
  const auto allocations = scope.count();

  EXPECT_EQ(status, Status::kOk);
  EXPECT_GE(result.forward_runs, 1);       // the work really happened
  EXPECT_GE(result.programs_computed, 2);  // with rate repairs
  EXPECT_EQ(allocations, 0u);
}

}  // namespace
}  // namespace tolip
