// Deterministic text formatting for the flight demo: the same bytes on the host and on the
// Cortex-M7 for the same values. Decimals are formed by one IEEE multiplication and integer
// arithmetic (no printf, no locale, no libm), and every double can also be printed as its exact
// bit pattern. Fixed capacity; overflowing text is cut (and marked with '~').
#pragma once

#include <cstddef>
#include <cstdint>

namespace tolip::flight {

class TextLine {
 public:
  static constexpr std::size_t kCapacity = 400;

  TextLine& text(const char* s);
  TextLine& integer(long long value, int width = 0);  // right-aligned in `width` characters
  TextLine& hex32(std::uint32_t value);               // 0x + 8 digits
  TextLine& bits(double value);                       // 16 hex digits of the IEEE-754 pattern
  // Fixed point with `decimals` digits (0-15), sign always shown ('+' or '-'), right-aligned in
  // `width`; values whose scaled magnitude reaches 9e18 print as "big", NaN as "nan".
  TextLine& fixed(double value, int decimals, int width = 0);

  // Writes the line and a newline to the console, then clears it.
  void emit();
  const char* data() const { return buffer_; }
  std::size_t size() const { return length_; }

 private:
  void put(char c);
  void pad_to(std::size_t start, int width);

  char buffer_[kCapacity + 2] = {};
  std::size_t length_ = 0;
  bool truncated_ = false;
};

}  // namespace tolip::flight
