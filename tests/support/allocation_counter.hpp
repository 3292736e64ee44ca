// Allocation counting for the no-allocation proofs (tests/noalloc/).
//
// allocation_counter.cpp replaces, for the whole test binary that links it:
//   * every global operator new / new[] (plain, nothrow, aligned, aligned nothrow) and the
//     matching operator delete / delete[] (plain, sized, nothrow, aligned, sized aligned);
//   * on glibc (unless a sanitizer owns malloc), malloc, calloc, realloc, reallocarray, free,
//     aligned_alloc, posix_memalign, memalign, valloc and pvalloc, forwarded to glibc's own
//     __libc_* entry points. Eigen's dynamic storage, C libraries and anything else that calls
//     malloc directly are therefore counted too.
// Each allocation (including a realloc, which may move the block) increments one process-wide
// atomic counter; operator new does not go through the malloc hooks, so nothing counts twice.
//
// Only the tolip_noalloc_tests binary links this file (it changes the global allocator).
//
//   tolip::test::AllocationScope scope;
//   run_the_code_under_test();
//   EXPECT_EQ(scope.count(), 0u);
#pragma once

#include <cstddef>
#include <cstdint>

namespace tolip::test {

// Allocations and bytes requested since the process started, all threads together.
std::uint64_t total_allocation_count();
std::uint64_t total_allocated_bytes();

// True when malloc and its family are counted as well as operator new (glibc builds).
bool counts_malloc_family();

// RAII window: count() and bytes() are the allocations made (by any thread) between the
// construction of the scope and the call. Scopes may nest; each keeps its own starting point.
class AllocationScope {
 public:
  AllocationScope();
  AllocationScope(const AllocationScope&) = delete;
  AllocationScope& operator=(const AllocationScope&) = delete;

  std::uint64_t count() const;  // number of allocation calls since construction
  std::uint64_t bytes() const;  // bytes requested by those calls

 private:
  std::uint64_t start_count_;
  std::uint64_t start_bytes_;
};

}  // namespace tolip::test
