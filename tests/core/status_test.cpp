#include <gtest/gtest.h>

#include <cstring>

#include "tolip/core/status.hpp"

namespace tolip {

TEST(Status, EveryStatusHasANameAndAMessage) {
  for (int i = 0; i <= static_cast<int>(Status::kTableImageVersion2); ++i) {  // the last enumerator
    const auto s = static_cast<Status>(i);
    EXPECT_STRNE(status_name(s), "kUnknownStatus") << i;
    EXPECT_GT(std::strlen(status_message(s)), 5u) << i;
  }
}

}  // namespace tolip
