// The link frames of docs/hil.md ("Link frames", "Processor in the loop"; tolip/hal/link.hpp):
// telemetry, tick and end, reply and upload frames decode to what was encoded, field for field;
// any one byte changed, a wrong size or type, or a field out of its range is rejected as
// kHalLinkFrameCorrupt with the output untouched. The CRC is recomputed here (crc32 of the table
// image) to reach the field checks behind it. The flight side's serial loop (LinkedFlightComputer::
// serve) answers a byte stream frame by frame: noise skipped, each upload and end frame replied to
// with its status, each sensor or tick frame with an actuator and a telemetry frame.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "support/guidance_table_fixture.hpp"
#include "tolip/hal/link.hpp"
#include "tolip/hal/linked_flight_computer.hpp"
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

// A byte stream in, the flight side's frames out.
struct Stream {
  Bytes in;
  std::size_t next = 0;
  Bytes out;
  static Status read(void* context, std::uint8_t* byte) {
    Stream& s = *static_cast<Stream*>(context);
    if (s.next >= s.in.size()) return Status::kHalPortMissing;  // the stream ran out
    *byte = s.in[s.next++];
    return Status::kOk;
  }
  static Status write(void* context, const std::uint8_t* bytes, std::size_t size) {
    Stream& s = *static_cast<Stream*>(context);
    s.out.insert(s.out.end(), bytes, bytes + size);
    return Status::kOk;
  }
  void add(const Bytes& frame) { in.insert(in.end(), frame.begin(), frame.end()); }
};

Bytes short_frame(std::uint8_t type, std::uint32_t sequence) {
  Bytes frame(kShortFrameSize);
  encode_short_frame(type, sequence, frame.data());
  return frame;
}

TEST(HalLink, SerialLoopAnswersEveryFrameAndSkipsNoise) {
  static LinkedFlightComputer computer(0.02);
  EXPECT_EQ(computer.serve(ByteChannel{}), Status::kHalPortMissing) << "no channel";
  Stream stream;
  stream.in = {0x00u, 0x13u, kFrameSync, 0x99u};  // noise, then a sync byte before an unknown type
  const test::Image image = test::encode(test::make_test_table());
  Bytes upload(kMaxUploadFrameSize);
  std::size_t upload_size = 0;
  ASSERT_EQ(encode_upload_frame(1u, image.data(), image.size(), upload.data(), &upload_size), Status::kOk);
  upload.resize(upload_size);
  stream.add(upload);
  Bytes corrupt_upload = upload;
  corrupt_upload[2] = 2u;  // sequence 2, CRC now wrong
  stream.add(corrupt_upload);
  Bytes oversized(kUploadHeaderSize);
  oversized[0] = kFrameSync;
  oversized[1] = kUploadFrameType;
  oversized[2] = 3u;
  oversized[6] = 0xFFu;
  oversized[7] = 0xFFu;  // a length beyond kMaxUploadBytes: answered without reading it
  stream.add(oversized);
  stream.add(short_frame(kTickFrameType, 4u));
  SensorFrame sensor;
  sensor.sequence = 1u;  // the cycle it belongs to (the tick was cycle 0)
  sensor.discretes.stage_code = 1;
  Bytes sensor_frame(kSensorFrameSize);
  encode_sensor_frame(sensor, sensor_frame.data());
  stream.add(sensor_frame);
  Bytes bad_sensor = sensor_frame;
  bad_sensor[10] ^= 0x01u;
  stream.add(bad_sensor);
  Bytes bad_end = short_frame(kEndFrameType, 7u);
  bad_end[9] ^= 0x01u;
  stream.add(bad_end);
  stream.add(short_frame(kEndFrameType, 8u));
  stream.add(short_frame(kTickFrameType, 9u));  // after the end: never read
  ASSERT_EQ(computer.serve(ByteChannel{&stream, Stream::read, Stream::write}), Status::kOk);
  EXPECT_EQ(stream.next, stream.in.size() - kShortFrameSize);

  // Out: reply 1 (loaded), reply 2 (corrupt), reply 3 (corrupt), three cycles (actuator and
  // telemetry frames), reply 7 (corrupt end), reply 8 (the end, with the counters).
  const Bytes& out = stream.out;
  const std::size_t cycle_bytes = kActuatorFrameSize + kTelemetryFrameSize;
  ASSERT_EQ(out.size(), 5 * kReplyFrameSize + 3 * cycle_bytes);
  const auto reply_at = [&](std::size_t offset) {
    LinkReport r;
    EXPECT_EQ(decode_reply_frame(out.data() + offset, kReplyFrameSize, &r), Status::kOk) << offset;
    return r;
  };
  const LinkReport loaded = reply_at(0);
  EXPECT_EQ(loaded.sequence, 1u);
  EXPECT_EQ(loaded.status, Status::kOk);
  EXPECT_EQ(reply_at(kReplyFrameSize).status, Status::kHalLinkFrameCorrupt);
  EXPECT_EQ(reply_at(kReplyFrameSize).sequence, 2u);
  EXPECT_EQ(reply_at(2 * kReplyFrameSize).status, Status::kHalLinkFrameCorrupt);
  EXPECT_EQ(reply_at(2 * kReplyFrameSize).sequence, 3u);
  std::size_t at = 3 * kReplyFrameSize;
  for (std::uint32_t cycle = 0; cycle < 3; ++cycle, at += cycle_bytes) {
    ActuatorFrame actuator;
    EXPECT_EQ(decode_actuator_frame(out.data() + at, kActuatorFrameSize, &actuator), Status::kOk);
    std::uint32_t sequence = 99;
    TelemetryFrame telemetry;
    EXPECT_EQ(decode_telemetry_frame(out.data() + at + kActuatorFrameSize, kTelemetryFrameSize, &sequence,
                                     &telemetry),
              Status::kOk);
    EXPECT_EQ(sequence, cycle) << "the telemetry of cycle " << cycle;
  }
  const LinkReport bad = reply_at(at);
  EXPECT_EQ(bad.status, Status::kHalLinkFrameCorrupt);
  EXPECT_EQ(bad.sequence, 7u);
  const LinkReport end = reply_at(at + kReplyFrameSize);
  EXPECT_EQ(end.status, Status::kOk);
  EXPECT_EQ(end.sequence, 8u);
  EXPECT_EQ(end.sensor_frames_missing, 1u) << "the tick";
  EXPECT_EQ(end.sensor_frames_rejected, 1u) << "the sensor frame with a changed byte";
  EXPECT_EQ(end.table_crc, loaded.table_crc);

  // A stream that ends inside a frame returns the channel's failure.
  Stream cut;
  cut.add(Bytes(upload.begin(), upload.begin() + 20));
  EXPECT_EQ(computer.serve(ByteChannel{&cut, Stream::read, Stream::write}), Status::kHalPortMissing);
}

// The flight side without the serial loop: an upload of nothing does not boot it, nor replace the
// table in force once booted; a sensor frame of another cycle is rejected, a missing one counted,
// with or without somewhere to put the actuator and telemetry frames.
TEST(HalLink, UploadsAndCyclesOutsideTheLoopKeepTheirAccount) {
  static LinkedFlightComputer computer(0.02);
  EXPECT_NE(computer.upload(nullptr, 0), Status::kOk) << "an empty store does not boot";
  const test::Image image = test::encode(test::make_test_table());
  ASSERT_EQ(computer.upload(image.data(), image.size()), Status::kOk);
  const std::uint32_t crc = computer.application().tables().active_crc();
  EXPECT_NE(computer.upload(nullptr, 0), Status::kOk);
  EXPECT_EQ(computer.application().tables().active_crc(), crc) << "the table in force stays";
  SensorFrame sensor;
  sensor.sequence = 5u;  // cycle 0 expects sequence 0
  Bytes frame(kSensorFrameSize);
  encode_sensor_frame(sensor, frame.data());
  (void)computer.run_cycle(frame.data(), frame.size(), nullptr, nullptr);
  EXPECT_EQ(computer.sensor_frames_rejected(), 1u);
  (void)computer.run_cycle(nullptr, 0, nullptr, nullptr);
  EXPECT_EQ(computer.sensor_frames_missing(), 1u);
  EXPECT_EQ(computer.application().counters().cycles, 2u);
}

}  // namespace
}  // namespace tolip::hal
