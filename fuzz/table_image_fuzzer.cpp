// libFuzzer target: the flight side's table image loader (fsw_core/src/table: GuidanceTableService
// and decode_table_image) on arbitrary bytes, as an uplink would deliver them.
// Verifies: REQ-TBL-002, REQ-DCK-005
// The first byte chooses the mode: odd, the rest is loaded as it is (almost always a CRC or size
// fault); even, the rest is padded or cut to the image size and resealed (a correct CRC), so the
// fuzzer reaches the field checks behind the CRC. Properties: never a crash or undefined
// behaviour; a rejected image leaves the active table as it was; an accepted one is the image in
// force, byte for byte, and encoding its decoded table gives the same bytes back.
// docs/verification/fuzzing.md.
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "tolip/table/table_image.hpp"
#include "tolip/table/table_service.hpp"

namespace {

tolip::GuidanceTableService& service() {
  static tolip::GuidanceTableService instance;
  return instance;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const bool reseal = (data[0] & 1u) == 0;
  const std::uint8_t* bytes = data + 1;
  std::size_t count = size - 1;
  std::array<std::uint8_t, tolip::kTableImageSize> padded{};
  if (reseal) {
    std::memcpy(padded.data(), bytes, count < padded.size() ? count : padded.size());
    tolip::reseal_table_image(padded.data());
    bytes = padded.data();
    count = padded.size();
  }
  tolip::GuidanceTableService& s = service();
  const std::uint32_t commits_before = s.commit_count();
  const std::uint32_t crc_before = s.active_crc();
  if (s.load(bytes, count) != tolip::Status::kOk) {
    if (s.commit_count() != commits_before || s.active_crc() != crc_before) std::abort();
    return 0;
  }
  if (s.commit_count() != commits_before + 1 || count != tolip::kTableImageSize) std::abort();
  if (std::memcmp(s.active_image(), bytes, count) != 0) std::abort();
  std::array<std::uint8_t, tolip::kTableImageSize> again{};
  if (tolip::encode_table_image(*s.active(), again.data(), again.size()) != tolip::Status::kOk) std::abort();
  if (std::memcmp(again.data(), bytes, count) != 0) std::abort();
  return 0;
}
