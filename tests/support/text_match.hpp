// Text checks shared by the tests that read the program's output or a deck.
#pragma once

#include <gtest/gtest.h>

#include <string>

namespace tolip::test {

// Whether `text` holds `part`; on failure the message shows the start of the text.
inline ::testing::AssertionResult contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  constexpr std::size_t kShown = 2000;  // enough to see where the text went wrong, not a whole listing
  return ::testing::AssertionFailure() << "'" << text.substr(0, kShown) << (text.size() > kShown ? "..." : "")
                                       << "' does not contain '" << part << "'";
}

}  // namespace tolip::test
