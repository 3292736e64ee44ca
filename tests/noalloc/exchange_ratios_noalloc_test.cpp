// Rules of the core: the exchange-ratio pass (Sec. 8, 12: every perturbed forward run, each with
// its own prepare_case) allocates nothing.
#include <gtest/gtest.h>

#include "support/allocation_counter.hpp"
#include "support/reference_mission.hpp"
#include "tolip/optimizer/exchange_ratios.hpp"
#include "tolip/optimizer/steepest_descent.hpp"

namespace tolip {
namespace {

TEST(CoreNoHeap, ExchangeRatiosAllocateNothing) {
  static Mission mission;
  static OptimizerWorkspace workspace;
  static OptimizerResult result;
  static ExchangeRatioScratch scratch;
  static ExchangeRatios ratios;
  static Mission changed;
  test::build_reference_mission(test::ReferenceProgram::kOptimum, &mission);
  ASSERT_EQ(optimize_trajectory(mission, &workspace, &result), Status::kOk);

  test::AllocationScope scope;
  const Status status = compute_exchange_ratios(workspace, result, &scratch, &ratios);
  const Status perturbed = perturb_stage_parameter(mission, 1, ExchangeParameter::kBurnRate, 1.0, &changed);
  const auto allocations = scope.count();

  EXPECT_EQ(status, Status::kOk);
  EXPECT_EQ(perturbed, Status::kOk);
  EXPECT_GT(ratios.forward_runs, 20);  // the work really happened
  EXPECT_EQ(allocations, 0u);
}

}  // namespace
}  // namespace tolip
