// Rules of the core: the pitch-program linearization (Sec. 6, 10: backward linearization runs, the
// eq. 6-22 fits with their rate repairs, forward linearization runs) allocates nothing.
#include <gtest/gtest.h>

#include "support/allocation_counter.hpp"
#include "support/linearized_reference.hpp"

namespace tolip {
namespace {

TEST(CoreNoHeap, LinearizationAllocatesNothing) {
  static test::LinearizedCase c;
  test::optimize_reference(&c);
  ASSERT_EQ(c.optimizer_status, Status::kOk);

  test::AllocationScope scope;
  test::linearize_optimum(&c);
  const auto allocations = scope.count();

  EXPECT_EQ(c.status, Status::kOk);
  EXPECT_GE(c.result.forward_runs, 1);       // the work really happened
  EXPECT_GE(c.result.programs_computed, 2);  // with rate repairs
  EXPECT_EQ(allocations, 0u);
}

}  // namespace
}  // namespace tolip
