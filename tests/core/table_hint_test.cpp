// The hinted table look-up of LOOK (manual Sec. 20) (tolip/math/table.hpp, Table::operator()(x, &hint)) that
// the trajectory and impact flights use (EvaluationScratch): whatever the hint, the value is the plain
// look-up's bit for bit, and the hint becomes the interval that holds x.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "tolip/math/table.hpp"

namespace tolip {
namespace {

std::uint64_t bits(double x) {
  std::uint64_t b = 0;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// A deterministic pseudo-random sequence (no library generator: its sequence is not portable).
double next_unit(std::uint64_t* state) {
  *state = *state * 6364136223846793005ull + 1442695040888963407ull;
  return static_cast<double>(*state >> 11) * 0x1.0p-53;
}

TEST(Sec20LookSubroutine, HintedLookupEqualsThePlainSearchBitForBitWhateverTheHint) {
  Table<64> table;
  std::uint64_t state = 12345;
  double x = -3.0;
  for (int i = 0; i < 40; ++i) {
    x += 0.01 + next_unit(&state);
    ASSERT_EQ(table.append(x, 100.0 * next_unit(&state) - 50.0), Status::kOk);
  }
  ASSERT_EQ(table.finalize(), Status::kOk);
  const double span = table.last_x() - table.first_x();
  int hint = -1;
  int moved = 0;
  for (int k = 0; k < 20000; ++k) {
    // Mostly small moves (as an integration makes), sometimes a jump, beyond both ends, a node.
    double query = 0.0;
    const double u = next_unit(&state);
    if (k % 97 == 0) {
      query = table.x(static_cast<int>(next_unit(&state) * table.size()));
    } else if (u < 0.1) {
      query = table.first_x() - 1.0 + (span + 2.0) * next_unit(&state);
    } else {
      query = table.first_x() + span * (0.5 + 0.5 * std::sin(0.001 * k)) + 0.05 * (u - 0.5);
    }
    if (k % 1000 == 0) hint = static_cast<int>(next_unit(&state) * 200.0) - 100;  // any int at all
    const int before = hint;
    const double hinted = table(query, &hint);
    ASSERT_EQ(bits(hinted), bits(table(query))) << "x = " << query << ", hint " << before;
    // The hint now names the interval of x (-1 below the table, the last index past its end).
    if (query < table.first_x()) {
      EXPECT_EQ(hint, -1);
    } else if (query >= table.last_x()) {
      EXPECT_EQ(hint, table.size() - 1);
    } else {
      ASSERT_GE(hint, 0);
      EXPECT_LE(table.x(hint), query);
      EXPECT_LT(query, table.x(hint + 1));
    }
    if (hint != before) ++moved;
  }
  EXPECT_GT(moved, 100);  // the walk crossed many intervals: the hint was exercised, not just kept
  // A NaN takes the plain search's answer too.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  hint = 5;
  EXPECT_EQ(bits(table(nan, &hint)), bits(table(nan)));
}

}  // namespace
}  // namespace tolip
