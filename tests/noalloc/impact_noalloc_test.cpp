// Rules of the core: the impact locus (manual Sec. 17) - validating the data and flying every
// thrust-failure and casing trajectory to impact - allocates nothing. The data and the nominal are
// built before the counting window.
#include <gtest/gtest.h>

#include "support/allocation_counter.hpp"
#include "support/reference_impact.hpp"
#include "support/reference_mission.hpp"
#include "tolip/impact/impact.hpp"

namespace tolip {
namespace {

TEST(CoreNoHeap, ImpactLocusAllocatesNothing) {
  static Mission mission;
  static PreparedCase prepared;
  static Trajectory nominal;
  static ImpactLocusData data;
  static ImpactWorkspace workspace;
  static ImpactLocus locus;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &mission);
  ASSERT_EQ(prepare_case(mission, &prepared), Status::kOk);
  ASSERT_EQ(fly_trajectory(mission, prepared, &nominal), Status::kOk);
  test::build_reference_impact_data(&data);

  test::AllocationScope scope;
  const Status status = compute_impact_locus(mission, prepared, nominal, data, &workspace, &locus);
  const auto allocations = scope.count();

  EXPECT_EQ(status, Status::kOk);
  EXPECT_GT(locus.count, 50);  // the work really happened
  EXPECT_EQ(locus.cases[locus.count - 1].status, Status::kOk);
  EXPECT_EQ(allocations, 0u);
}

}  // namespace
}  // namespace tolip
