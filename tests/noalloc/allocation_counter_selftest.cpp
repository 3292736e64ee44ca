// Proof that the allocation counter works: it sees every kind of heap allocation (so a zero in a
// no-allocation test means something), and it does not see the fixed-size work the core does.
//
// Results are read inside the scope and checked after it, so GoogleTest's own bookkeeping never
// falls inside a counted window.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <string>
#include <thread>
#include <vector>

#include "support/allocation_counter.hpp"
#include "tolip/core/status.hpp"
#include "tolip/math/table.hpp"

namespace tolip::test {
namespace {

// Keeps the optimizer from removing an allocation whose result is otherwise unused (GCC may
// delete a malloc/free or new/delete pair it can see through).
template <class T>
void escape(T* pointer) {
  asm volatile("" : : "g"(pointer) : "memory");
}

TEST(AllocationCounter, CountsVectorPushBack) {
  std::uint64_t counted = 0;
  {
    AllocationScope scope;
    std::vector<double> values;
    values.push_back(1.0);
    escape(values.data());
    counted = scope.count();
  }
  EXPECT_GE(counted, 1u);
}

TEST(AllocationCounter, CountsVectorGrowthRepeatedly) {
  std::uint64_t counted = 0;
  std::uint64_t bytes = 0;
  {
    AllocationScope scope;
    std::vector<double> values;
    for (int i = 0; i < 1000; ++i) values.push_back(i);
    escape(values.data());
    counted = scope.count();
    bytes = scope.bytes();
  }
  EXPECT_GE(counted, 5u);  // geometric growth to 1000 elements reallocates several times
  EXPECT_GE(bytes, 1000u * sizeof(double));
}

TEST(AllocationCounter, CountsEveryOperatorNewVariant) {
  struct alignas(64) OverAligned {
    double value[8];
  };
  std::uint64_t counted = 0;
  {
    AllocationScope scope;
    int* single = new int(7);
    escape(single);
    int* array = new int[16];
    escape(array);
    int* nothrow_single = new (std::nothrow) int(3);
    escape(nothrow_single);
    int* nothrow_array = new (std::nothrow) int[4];
    escape(nothrow_array);
    auto* aligned = new OverAligned();
    escape(aligned);
    auto* aligned_array = new OverAligned[3];
    escape(aligned_array);
    auto* aligned_nothrow = new (std::nothrow) OverAligned();
    escape(aligned_nothrow);
    counted = scope.count();
    delete single;
    delete[] array;
    delete nothrow_single;
    delete[] nothrow_array;
    delete aligned;
    delete[] aligned_array;
    delete aligned_nothrow;
  }
  EXPECT_EQ(counted, 7u);
}

TEST(AllocationCounter, CountsSmartPointersAndStrings) {
  std::uint64_t counted = 0;
  {
    AllocationScope scope;
    auto owned = std::make_unique<double[]>(32);
    escape(owned.get());
    auto shared = std::make_shared<int>(5);
    escape(shared.get());
    std::string text(100, 'x');  // beyond the small-string buffer
    escape(text.data());
    counted = scope.count();
  }
  EXPECT_GE(counted, 3u);
}

TEST(AllocationCounter, CountsTheMallocFamily) {
  if (!counts_malloc_family()) GTEST_SKIP() << "malloc is not interposed on this C library";
  std::uint64_t counted = 0;
  {
    AllocationScope scope;
    void* a = std::malloc(64);
    escape(a);
    void* b = std::calloc(8, 8);
    escape(b);
    a = std::realloc(a, 4096);
    escape(a);
    void* c = nullptr;
    const int rc = posix_memalign(&c, 64, 256);
    escape(c);
    void* d = std::aligned_alloc(64, 128);
    escape(d);
    counted = scope.count();
    std::free(a);
    std::free(b);
    if (rc == 0) std::free(c);
    std::free(d);
  }
  EXPECT_EQ(counted, 5u);
}

TEST(AllocationCounter, CountsDynamicEigenStorage) {
  // Eigen's dynamic storage calls malloc directly; under a sanitizer (the asan preset) the
  // sanitizer owns malloc and only operator new is counted, so there is nothing to prove.
  if (!counts_malloc_family()) GTEST_SKIP() << "malloc is not counted (a sanitizer interposes it)";
  std::uint64_t counted = 0;
  double trace = 0.0;
  {
    AllocationScope scope;
    Eigen::MatrixXd a = Eigen::MatrixXd::Identity(20, 20);
    Eigen::MatrixXd b = a * 2.0;
    trace = b.trace();
    counted = scope.count();
  }
  EXPECT_DOUBLE_EQ(trace, 40.0);
  EXPECT_GE(counted, 2u);
}

TEST(AllocationCounter, CountsAllocationsOfOtherThreads) {
  constexpr int kPerThread = 1000;
  std::uint64_t counted = 0;
  {
    AllocationScope scope;
    auto work = [] {
      for (int i = 0; i < kPerThread; ++i) {
        int* p = new int(i);
        escape(p);
        delete p;
      }
    };
    std::thread first(work);
    std::thread second(work);
    first.join();
    second.join();
    counted = scope.count();
  }
  EXPECT_GE(counted, 2u * kPerThread);
}

TEST(AllocationCounter, NestedScopesKeepTheirOwnStart) {
  std::uint64_t outer_count = 0;
  std::uint64_t inner_count = 0;
  {
    AllocationScope outer;
    int* first = new int(1);
    escape(first);
    {
      AllocationScope inner;
      int* second = new int(2);
      escape(second);
      inner_count = inner.count();
      delete second;
    }
    outer_count = outer.count();
    delete first;
  }
  EXPECT_EQ(inner_count, 1u);
  EXPECT_EQ(outer_count, 2u);
}

TEST(AllocationCounter, FixedSizeEigenProductIsNotCounted) {
  Eigen::Matrix3d a;
  a << 1, 2, 3, 4, 5, 6, 7, 8, 10;
  Eigen::Matrix3d b = Eigen::Matrix3d::Identity() * 0.5;
  Eigen::Matrix<double, 6, 1> state;
  state << 1, 2, 3, 4, 5, 6;
  std::uint64_t counted = 0;
  double checksum = 0.0;
  {
    AllocationScope scope;
    for (int i = 0; i < 100; ++i) {
      Eigen::Matrix3d c = a * b;
      c = c.transpose() * a + b;
      const Eigen::Vector3d v = c * Eigen::Vector3d(1.0, -1.0, 0.5);
      Eigen::Matrix<double, 6, 1> next = state * 0.99;
      next.head<3>() += v;
      checksum += next.sum() + c.trace();
      escape(&checksum);
    }
    counted = scope.count();
  }
  EXPECT_TRUE(std::isfinite(checksum));
  EXPECT_EQ(counted, 0u);
}

TEST(AllocationCounter, TableAppendFinalizeLookupIsNotCounted) {
  std::uint64_t counted = 0;
  Status append_status = Status::kOk;
  Status finalize_status = Status::kNotPrepared;
  Status overflow_status = Status::kOk;
  double sum = 0.0;
  double slope_sum = 0.0;
  {
    AllocationScope scope;
    Table<120> table;
    for (int i = 0; i < 120 && ok(append_status); ++i) {
      append_status = table.append(static_cast<double>(i), static_cast<double>(i * i));
    }
    overflow_status = table.append(1000.0, 0.0);  // full: reported, never allocated
    finalize_status = table.finalize();
    for (int i = -10; i < 1300; ++i) {
      double slope = 0.0;
      sum += table(0.1 * i);
      sum += table.value_and_slope(0.1 * i + 0.05, &slope);
      slope_sum += slope;
    }
    escape(&sum);
    counted = scope.count();
  }
  EXPECT_EQ(append_status, Status::kOk);
  EXPECT_EQ(overflow_status, Status::kTooManyTablePoints);
  EXPECT_EQ(finalize_status, Status::kOk);
  EXPECT_GT(sum, 0.0);
  EXPECT_GT(slope_sum, 0.0);
  EXPECT_EQ(counted, 0u);
}

}  // namespace
}  // namespace tolip::test
