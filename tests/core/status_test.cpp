#include <gtest/gtest.h>

#include <cstring>

#include "tolip/core/status.hpp"

namespace tolip {

TEST(Status, EveryStatusHasANameAndAMessage) {
  for (int i = 0; i <= static_cast<int>(Status::kBodyDynamicsNotFinite); ++i) {  // the last enumerator
    const auto s = static_cast<Status>(i);
    EXPECT_STRNE(status_name(s), "kUnknownStatus") << i;
    EXPECT_GT(std::strlen(status_message(s)), 5u) << i;
  }
}

// The loops above stop at the enumerator they name: it must be the last, or an appended one would
// go unchecked.
TEST(Status, TheTestsNameTheLastEnumerator) {
  const int last = static_cast<int>(Status::kBodyDynamicsNotFinite);
  EXPECT_STREQ(status_name(static_cast<Status>(last + 1)), "kUnknownStatus");
}

// Issue 18: one enumerator per cause, so no two share a name or a message.
TEST(Status, EveryStatusHasItsOwnNameAndMessage) {
  const int last = static_cast<int>(Status::kBodyDynamicsNotFinite);
  for (int i = 0; i <= last; ++i) {
    for (int j = i + 1; j <= last; ++j) {
      const auto a = static_cast<Status>(i);
      const auto b = static_cast<Status>(j);
      EXPECT_STRNE(status_name(a), status_name(b)) << i << " " << j;
      EXPECT_STRNE(status_message(a), status_message(b)) << status_name(a) << " " << status_name(b);
    }
  }
}

}  // namespace tolip
