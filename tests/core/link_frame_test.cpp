// The link frames of docs/hil.md ("Link frames", "Processor in the loop"; tolip/hal/link.hpp):
// telemetry, tick and end, reply and upload frames decode to what was encoded, field for field;
// any one byte changed, a wrong size or type, or a field out of its range is rejected as
// kHalLinkFrameCorrupt with the output untouched. The CRC is recomputed here (crc32 of the table
// image) to reach the field checks behind it.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "tolip/hal/link.hpp"
#include "tolip/table/crc32.hpp"

namespace tolip::hal {
namespace {

using Bytes = std::vector<std::uint8_t>;

// The CRC of everything before the last four bytes, little-endian, as the sender writes it.
void reseal(Bytes* frame) {
  const std::uint32_t crc = crc32(frame->data(), frame->size() - 4);
  for (int i = 0; i < 4; ++i) (*frame)[frame->size() - 4 + i] = static_cast<std::uint8_t>(crc >> (8 * i));
}

// Every single-byte change of the frame is refused by `decode`.
template <class Decode>
void expect_every_byte_guarded(const Bytes& frame, Decode decode) {
  for (std::size_t i = 0; i < frame.size(); ++i) {
    Bytes altered = frame;
    altered[i] ^= 0x10u;
    EXPECT_EQ(decode(altered), Status::kHalLinkFrameCorrupt) << "byte " << i;
  }
  Bytes shorter(frame.begin(), frame.end() - 1);
  EXPECT_EQ(decode(shorter), Status::kHalLinkFrameCorrupt) << "one byte short";
}

TEST(HalLink, TelemetryFrameRoundTripsAndEveryByteIsGuarded) {
  TelemetryFrame t;
  t.cycle = 123456;
  t.time_s = 61.25;
  t.stage_code = 7;
  t.guidance_mode = 2;
  t.theta_command_rad = 0.5;
  t.chi_command_rad = -0.25;
  t.theta_measured_rad = 0.49;
  t.chi_measured_rad = -0.26;
  t.pitch_rate_rad_s = 0.01;
  t.yaw_rate_rad_s = -0.02;
  t.k_theta = 3.5;
  t.k_q_s = 0.75;
  t.actuator = static_cast<ActuatorKind>(2);
  t.pitch_command = 0.125;
  t.yaw_command = -0.0625;
  t.saturated = true;
  t.platform_valid = false;
  t.table_crc = 0xDEADBEEFu;
  t.fault_count = 17;
  Bytes frame(kTelemetryFrameSize);
  encode_telemetry_frame(42u, t, frame.data());
  std::uint32_t sequence = 0;
  TelemetryFrame d;
  ASSERT_EQ(decode_telemetry_frame(frame.data(), frame.size(), &sequence, &d), Status::kOk);
  EXPECT_EQ(sequence, 42u);
  EXPECT_EQ(d.cycle, t.cycle);
  EXPECT_EQ(d.time_s, t.time_s);
  EXPECT_EQ(d.stage_code, t.stage_code);
  EXPECT_EQ(d.guidance_mode, t.guidance_mode);
  EXPECT_EQ(d.theta_command_rad, t.theta_command_rad);
  EXPECT_EQ(d.chi_command_rad, t.chi_command_rad);
  EXPECT_EQ(d.theta_measured_rad, t.theta_measured_rad);
  EXPECT_EQ(d.chi_measured_rad, t.chi_measured_rad);
  EXPECT_EQ(d.pitch_rate_rad_s, t.pitch_rate_rad_s);
  EXPECT_EQ(d.yaw_rate_rad_s, t.yaw_rate_rad_s);
  EXPECT_EQ(d.k_theta, t.k_theta);
  EXPECT_EQ(d.k_q_s, t.k_q_s);
  EXPECT_EQ(d.actuator, t.actuator);
  EXPECT_EQ(d.pitch_command, t.pitch_command);
  EXPECT_EQ(d.yaw_command, t.yaw_command);
  EXPECT_EQ(d.saturated, true);
  EXPECT_EQ(d.platform_valid, false);
  EXPECT_EQ(d.table_crc, t.table_crc);
  EXPECT_EQ(d.fault_count, t.fault_count);
  expect_every_byte_guarded(frame, [](const Bytes& b) {
    std::uint32_t s = 0;
    TelemetryFrame f;
    return decode_telemetry_frame(b.data(), b.size(), &s, &f);
  });
  // Fields out of range behind a good CRC: stage code 0 and 11, actuator kind 3, flags 4.
  const std::pair<std::size_t, std::uint8_t> bad[] = {{18, 0}, {18, 11}, {20, 3}, {21, 4}};
  for (const auto& [offset, value] : bad) {
    Bytes altered = frame;
    altered[offset] = value;
    reseal(&altered);
    TelemetryFrame untouched;
    untouched.cycle = 99;
    EXPECT_EQ(decode_telemetry_frame(altered.data(), altered.size(), &sequence, &untouched),
              Status::kHalLinkFrameCorrupt)
        << "offset " << offset;
    EXPECT_EQ(untouched.cycle, 99u);
  }
  EXPECT_EQ(decode_telemetry_frame(nullptr, kTelemetryFrameSize, &sequence, &d),
            Status::kHalLinkFrameCorrupt);
}

TEST(HalLink, TickEndAndReplyFramesRoundTripAndEveryByteIsGuarded) {
  for (std::uint8_t type : {kTickFrameType, kEndFrameType}) {
    Bytes frame(kShortFrameSize);
    encode_short_frame(type, 0x01020304u, frame.data());
    std::uint32_t sequence = 0;
    ASSERT_EQ(decode_short_frame(frame.data(), frame.size(), type, &sequence), Status::kOk);
    EXPECT_EQ(sequence, 0x01020304u);
    const std::uint8_t other = (type == kTickFrameType) ? kEndFrameType : kTickFrameType;
    EXPECT_EQ(decode_short_frame(frame.data(), frame.size(), other, &sequence), Status::kHalLinkFrameCorrupt);
    expect_every_byte_guarded(frame, [type](const Bytes& b) {
      std::uint32_t s = 0;
      return decode_short_frame(b.data(), b.size(), type, &s);
    });
  }
  LinkReport r;
  r.sequence = 77;
  r.status = Status::kTableImageCrcMismatch;
  r.table_crc = 0xCAFEF00Du;
  r.counters.cycles = 5000;
  r.counters.clock_overruns = 1;
  r.counters.platform_dropouts = 2;
  r.counters.neutral_cycles = 3;
  r.counters.actuator_rejections = 4;
  r.counters.telemetry_drops = 5;
  r.counters.discrete_faults = 6;
  r.counters.stage_events_refused = 7;
  r.counters.guidance_faults = 8;
  r.counters.table_loads = 9;
  r.counters.table_rejections = 10;
  r.counters.saturated_cycles = 11;
  r.sensor_frames_missing = 12;
  r.sensor_frames_rejected = 13;
  Bytes frame(kReplyFrameSize);
  encode_reply_frame(r, frame.data());
  LinkReport d;
  ASSERT_EQ(decode_reply_frame(frame.data(), frame.size(), &d), Status::kOk);
  EXPECT_EQ(d.sequence, r.sequence);
  EXPECT_EQ(d.status, r.status);
  EXPECT_EQ(d.table_crc, r.table_crc);
  EXPECT_EQ(d.counters.cycles, 5000u);
  EXPECT_EQ(d.counters.total_faults(), r.counters.total_faults());
  EXPECT_EQ(d.counters.neutral_cycles, 3u);
  EXPECT_EQ(d.counters.table_loads, 9u);
  EXPECT_EQ(d.counters.saturated_cycles, 11u);
  EXPECT_EQ(d.sensor_frames_missing, 12u);
  EXPECT_EQ(d.sensor_frames_rejected, 13u);
  expect_every_byte_guarded(frame, [](const Bytes& b) {
    LinkReport report;
    return decode_reply_frame(b.data(), b.size(), &report);
  });
}

TEST(HalLink, UploadFrameCarriesTheImageAndRefusesWhatCannotBeAnUpload) {
  Bytes image(kTableImageSize);
  for (std::size_t i = 0; i < image.size(); ++i) image[i] = static_cast<std::uint8_t>(i * 7u + 3u);
  Bytes frame(kMaxUploadFrameSize, 0xAAu);
  std::size_t frame_size = 0;
  ASSERT_EQ(encode_upload_frame(9u, image.data(), image.size(), frame.data(), &frame_size), Status::kOk);
  EXPECT_EQ(frame_size, kUploadHeaderSize + image.size() + 4);
  frame.resize(frame_size);
  std::uint32_t sequence = 0;
  const std::uint8_t* carried = nullptr;
  std::size_t carried_size = 0;
  ASSERT_EQ(decode_upload_frame(frame.data(), frame.size(), &sequence, &carried, &carried_size), Status::kOk);
  EXPECT_EQ(sequence, 9u);
  ASSERT_EQ(carried_size, image.size());
  EXPECT_EQ(std::memcmp(carried, image.data(), image.size()), 0);
  EXPECT_EQ(carried, frame.data() + kUploadHeaderSize) << "the image is read in place";
  expect_every_byte_guarded(frame, [](const Bytes& b) {
    std::uint32_t s = 0;
    const std::uint8_t* i = nullptr;
    std::size_t n = 0;
    return decode_upload_frame(b.data(), b.size(), &s, &i, &n);
  });
  // An empty upload is a frame; more than kMaxUploadBytes, or bytes without an image, are not.
  Bytes empty(kMaxUploadFrameSize);
  ASSERT_EQ(encode_upload_frame(1u, nullptr, 0, empty.data(), &frame_size), Status::kOk);
  EXPECT_EQ(frame_size, kUploadHeaderSize + 4);
  ASSERT_EQ(decode_upload_frame(empty.data(), frame_size, &sequence, &carried, &carried_size), Status::kOk);
  EXPECT_EQ(carried_size, 0u);
  Bytes untouched(kMaxUploadFrameSize + 8, 0x55u);
  Bytes large(kMaxUploadBytes + 1);
  EXPECT_EQ(encode_upload_frame(1u, large.data(), large.size(), untouched.data(), &frame_size),
            Status::kHalLinkFrameCorrupt);
  EXPECT_EQ(encode_upload_frame(1u, nullptr, 10, untouched.data(), &frame_size),
            Status::kHalLinkFrameCorrupt);
  EXPECT_EQ(untouched, Bytes(kMaxUploadFrameSize + 8, 0x55u)) << "nothing written";
  EXPECT_EQ(decode_upload_frame(nullptr, 100, &sequence, &carried, &carried_size),
            Status::kHalLinkFrameCorrupt);
  EXPECT_EQ(decode_upload_frame(empty.data(), kUploadHeaderSize + 3, &sequence, &carried, &carried_size),
            Status::kHalLinkFrameCorrupt);
  // A length word beyond kMaxUploadBytes, behind a good CRC.
  Bytes long_word = empty;
  long_word.resize(kUploadHeaderSize + 4);
  long_word[6] = 0xFFu;
  long_word[7] = 0xFFu;
  reseal(&long_word);
  EXPECT_EQ(decode_upload_frame(long_word.data(), long_word.size(), &sequence, &carried, &carried_size),
            Status::kHalLinkFrameCorrupt);
}

}  // namespace
}  // namespace tolip::hal
