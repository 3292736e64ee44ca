// CRC-32 of the guidance table image (docs/table-format.md): the IEEE 802.3 / ISO-HDLC CRC,
// polynomial 0x04C11DB7 processed bit-reflected (0xEDB88320), initial value 0xFFFFFFFF, final
// exclusive-or 0xFFFFFFFF. Check value: crc32("123456789") == 0xCBF43926.
#pragma once

#include <cstddef>
#include <cstdint>

namespace tolip {

inline constexpr std::uint32_t kCrc32CheckValue = 0xCBF43926u;  // CRC of the 9 bytes "123456789"

// CRC of `size` bytes. Table driven (256 entries in read-only storage), one pass, no allocation.
std::uint32_t crc32(const std::uint8_t* data, std::size_t size);

// Incremental form: start with crc = 0 and feed the bytes in pieces; the result equals crc32()
// of the concatenation.
std::uint32_t crc32_update(std::uint32_t crc, const std::uint8_t* data, std::size_t size);

}  // namespace tolip
