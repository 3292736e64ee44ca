// CRC-32 (IEEE 802.3), table driven; the table is computed at compile time.
#include "tolip/table/crc32.hpp"

namespace tolip {
namespace {

struct Crc32Table {
  std::uint32_t entry[256];
};

constexpr Crc32Table make_crc32_table() {
  Crc32Table table{};
  for (std::uint32_t i = 0; i < 256u; ++i) {
    std::uint32_t c = i;
    for (int bit = 0; bit < 8; ++bit) c = (c & 1u) != 0u ? (0xEDB88320u ^ (c >> 1)) : (c >> 1);
    table.entry[i] = c;
  }
  return table;
}

constexpr Crc32Table kTable = make_crc32_table();

}  // namespace

std::uint32_t crc32_update(std::uint32_t crc, const std::uint8_t* data, std::size_t size) {
  std::uint32_t c = crc ^ 0xFFFFFFFFu;
  for (std::size_t i = 0; i < size; ++i) c = kTable.entry[(c ^ data[i]) & 0xFFu] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

std::uint32_t crc32(const std::uint8_t* data, std::size_t size) { return crc32_update(0u, data, size); }

}  // namespace tolip
