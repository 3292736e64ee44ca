// Deterministic text formatting (text_line.hpp).
#include "demo/text_line.hpp"

#include <bit>

#include "demo/console.hpp"

namespace tolip::flight {

void TextLine::put(char c) {
  if (length_ < kCapacity) {
    buffer_[length_++] = c;
  } else {
    truncated_ = true;
  }
}

void TextLine::pad_to(std::size_t start, int width) {
  // Right-aligns the characters written since `start` in `width` characters.
  const std::size_t written = length_ - start;
  if (width <= 0 || written >= static_cast<std::size_t>(width)) return;
  const std::size_t pad = static_cast<std::size_t>(width) - written;
  if (length_ + pad > kCapacity) return;
  for (std::size_t i = length_; i > start; --i) buffer_[i - 1 + pad] = buffer_[i - 1];
  for (std::size_t i = 0; i < pad; ++i) buffer_[start + i] = ' ';
  length_ += pad;
}

TextLine& TextLine::text(const char* s) {
  while (*s != '\0') put(*s++);
  return *this;
}

TextLine& TextLine::integer(long long value, int width) {
  const std::size_t start = length_;
  unsigned long long magnitude =
      value < 0 ? 0ull - static_cast<unsigned long long>(value) : static_cast<unsigned long long>(value);
  char digits[24];
  int n = 0;
  do {
    digits[n++] = static_cast<char>('0' + static_cast<int>(magnitude % 10u));
    magnitude /= 10u;
  } while (magnitude != 0u && n < 24);
  if (value < 0) put('-');
  while (n > 0) put(digits[--n]);
  pad_to(start, width);
  return *this;
}

TextLine& TextLine::hex32(std::uint32_t value) {
  static const char kHex[] = "0123456789abcdef";
  text("0x");
  for (int shift = 28; shift >= 0; shift -= 4) put(kHex[(value >> shift) & 0xFu]);
  return *this;
}

TextLine& TextLine::bits(double value) {
  static const char kHex[] = "0123456789abcdef";
  const std::uint64_t pattern = std::bit_cast<std::uint64_t>(value);
  for (int shift = 60; shift >= 0; shift -= 4) put(kHex[(pattern >> shift) & 0xFu]);
  return *this;
}

TextLine& TextLine::fixed(double value, int decimals, int width) {
  const std::size_t start = length_;
  if (value != value) {
    text("nan");
    pad_to(start, width);
    return *this;
  }
  if (decimals < 0) decimals = 0;
  if (decimals > 15) decimals = 15;
  unsigned long long scale = 1;
  for (int i = 0; i < decimals; ++i) scale *= 10u;
  const bool negative = std::bit_cast<std::uint64_t>(value) >> 63 != 0u;
  const double magnitude = negative ? -value : value;
  const double scaled = magnitude * static_cast<double>(scale);  // one IEEE rounding
  if (!(scaled < 9.0e18)) {
    text(negative ? "-big" : "+big");
    pad_to(start, width);
    return *this;
  }
  // Round half up in integer arithmetic: the integer part is exact, the fraction is compared.
  unsigned long long units = static_cast<unsigned long long>(scaled);
  if (scaled - static_cast<double>(units) >= 0.5) ++units;
  const unsigned long long whole = units / scale;
  const unsigned long long fraction = units % scale;
  put(negative && units != 0u ? '-' : '+');
  integer(static_cast<long long>(whole));
  if (decimals > 0) {
    put('.');
    unsigned long long divisor = scale / 10u;
    for (int i = 0; i < decimals; ++i) {
      put(static_cast<char>('0' + static_cast<int>((fraction / divisor) % 10u)));
      divisor = divisor > 1u ? divisor / 10u : 1u;
    }
  }
  pad_to(start, width);
  return *this;
}

void TextLine::emit() {
  if (truncated_ && length_ > 0) buffer_[length_ - 1] = '~';
  buffer_[length_] = '\n';
  console_write(buffer_, length_ + 1);
  length_ = 0;
  truncated_ = false;
}

}  // namespace tolip::flight
