// Frame codec of the plant / guidance-computer link (tolip/hal/link.hpp, docs/hil.md).
#include "tolip/hal/link.hpp"

#include <cstddef>
#include <cstring>

#include "tolip/table/crc32.hpp"

namespace tolip::hal {

namespace {

void put_header(std::uint8_t type, std::uint32_t sequence, std::uint8_t* out) {
  out[0] = kFrameSync;
  out[1] = type;
  put_u32_le(out + 2, sequence);
}

void put_crc(std::uint8_t* out, std::size_t size) { put_u32_le(out + size - 4, crc32(out, size - 4)); }

bool check_frame(const std::uint8_t* bytes, std::size_t size, std::size_t expected, std::uint8_t type) {
  if (bytes == nullptr || size != expected || bytes[0] != kFrameSync || bytes[1] != type) return false;
  return crc32(bytes, expected - 4) == get_u32_le(bytes + expected - 4);
}

}  // namespace

void encode_sensor_frame(const SensorFrame& frame, std::uint8_t* out) {
  put_header(kSensorFrameType, frame.sequence, out);
  put_f64_le(out + 6, frame.sample.theta_rad);
  put_f64_le(out + 14, frame.sample.chi_rad);
  put_f64_le(out + 22, frame.sample.pitch_rate_rad_s);
  put_f64_le(out + 30, frame.sample.yaw_rate_rad_s);
  out[38] = static_cast<std::uint8_t>(frame.discretes.stage_code);
  out[39] = static_cast<std::uint8_t>((frame.discretes.spun_up ? 1 : 0) | (frame.platform_invalid ? 2 : 0));
  put_u32_le(out + 40, frame.discretes.sequence);
  put_crc(out, kSensorFrameSize);
}

Status decode_sensor_frame(const std::uint8_t* bytes, std::size_t size, SensorFrame* frame) {
  if (!check_frame(bytes, size, kSensorFrameSize, kSensorFrameType)) return Status::kHalLinkFrameCorrupt;
  const int code = bytes[38];
  if (code < 1 || code > 10 || bytes[39] > 3) return Status::kHalLinkFrameCorrupt;
  SensorFrame f;
  f.sequence = get_u32_le(bytes + 2);
  f.sample.theta_rad = get_f64_le(bytes + 6);
  f.sample.chi_rad = get_f64_le(bytes + 14);
  f.sample.pitch_rate_rad_s = get_f64_le(bytes + 22);
  f.sample.yaw_rate_rad_s = get_f64_le(bytes + 30);
  f.discretes.stage_code = code;
  f.discretes.spun_up = (bytes[39] & 1) != 0;
  f.platform_invalid = (bytes[39] & 2) != 0;
  f.discretes.sequence = get_u32_le(bytes + 40);
  *frame = f;
  return Status::kOk;
}

void encode_actuator_frame(const ActuatorFrame& frame, std::uint8_t* out) {
  put_header(kActuatorFrameType, frame.sequence, out);
  out[6] = static_cast<std::uint8_t>(frame.command.kind);
  put_f64_le(out + 7, frame.command.pitch);
  put_f64_le(out + 15, frame.command.yaw);
  put_crc(out, kActuatorFrameSize);
}

Status decode_actuator_frame(const std::uint8_t* bytes, std::size_t size, ActuatorFrame* frame) {
  if (!check_frame(bytes, size, kActuatorFrameSize, kActuatorFrameType)) return Status::kHalLinkFrameCorrupt;
  if (bytes[6] > 2) return Status::kHalLinkFrameCorrupt;
  ActuatorFrame f;
  f.sequence = get_u32_le(bytes + 2);
  f.command.kind = static_cast<ActuatorKind>(bytes[6]);
  f.command.pitch = get_f64_le(bytes + 7);
  f.command.yaw = get_f64_le(bytes + 15);
  *frame = f;
  return Status::kOk;
}

void encode_telemetry_frame(std::uint32_t sequence, const TelemetryFrame& f, std::uint8_t* out) {
  put_header(kTelemetryFrameType, sequence, out);
  put_u32_le(out + 6, f.cycle);
  put_f64_le(out + 10, f.time_s);
  out[18] = static_cast<std::uint8_t>(f.stage_code);
  out[19] = static_cast<std::uint8_t>(f.guidance_mode);
  out[20] = static_cast<std::uint8_t>(f.actuator);
  out[21] = static_cast<std::uint8_t>((f.saturated ? 1 : 0) | (f.platform_valid ? 2 : 0));
  const double values[10] = {f.theta_command_rad,
                             f.chi_command_rad,
                             f.theta_measured_rad,
                             f.chi_measured_rad,
                             f.pitch_rate_rad_s,
                             f.yaw_rate_rad_s,
                             f.k_theta,
                             f.k_q_s,
                             f.pitch_command,
                             f.yaw_command};
  for (std::ptrdiff_t i = 0; i < 10; ++i) put_f64_le(out + 22 + 8 * i, values[i]);
  put_u32_le(out + 102, f.table_crc);
  put_u32_le(out + 106, f.fault_count);
  put_crc(out, kTelemetryFrameSize);
}

Status decode_telemetry_frame(const std::uint8_t* bytes, std::size_t size, std::uint32_t* sequence,
                              TelemetryFrame* frame) {
  if (!check_frame(bytes, size, kTelemetryFrameSize, kTelemetryFrameType)) {
    return Status::kHalLinkFrameCorrupt;
  }
  if (bytes[18] < 1 || bytes[18] > 10 || bytes[20] > 2 || bytes[21] > 3) return Status::kHalLinkFrameCorrupt;
  TelemetryFrame f;
  f.cycle = get_u32_le(bytes + 6);
  f.time_s = get_f64_le(bytes + 10);
  f.stage_code = bytes[18];
  f.guidance_mode = bytes[19];
  f.actuator = static_cast<ActuatorKind>(bytes[20]);
  f.saturated = (bytes[21] & 1) != 0;
  f.platform_valid = (bytes[21] & 2) != 0;
  double* values[10] = {&f.theta_command_rad,
                        &f.chi_command_rad,
                        &f.theta_measured_rad,
                        &f.chi_measured_rad,
                        &f.pitch_rate_rad_s,
                        &f.yaw_rate_rad_s,
                        &f.k_theta,
                        &f.k_q_s,
                        &f.pitch_command,
                        &f.yaw_command};
  for (std::ptrdiff_t i = 0; i < 10; ++i) *values[i] = get_f64_le(bytes + 22 + 8 * i);
  f.table_crc = get_u32_le(bytes + 102);
  f.fault_count = get_u32_le(bytes + 106);
  *sequence = get_u32_le(bytes + 2);
  *frame = f;
  return Status::kOk;
}

void encode_short_frame(std::uint8_t type, std::uint32_t sequence, std::uint8_t* out) {
  put_header(type, sequence, out);
  put_crc(out, kShortFrameSize);
}

Status decode_short_frame(const std::uint8_t* bytes, std::size_t size, std::uint8_t type,
                          std::uint32_t* sequence) {
  if (!check_frame(bytes, size, kShortFrameSize, type)) return Status::kHalLinkFrameCorrupt;
  *sequence = get_u32_le(bytes + 2);
  return Status::kOk;
}

namespace {

// The counters in the reply frame's order.
constexpr int kReplyWords = 14;
void reply_words(const LinkReport& r, std::uint32_t words[kReplyWords]) {
  const FlightCounters& c = r.counters;
  const std::uint32_t w[kReplyWords] = {c.cycles,
                                        c.clock_overruns,
                                        c.platform_dropouts,
                                        c.neutral_cycles,
                                        c.actuator_rejections,
                                        c.telemetry_drops,
                                        c.discrete_faults,
                                        c.stage_events_refused,
                                        c.guidance_faults,
                                        c.table_loads,
                                        c.table_rejections,
                                        c.saturated_cycles,
                                        r.sensor_frames_missing,
                                        r.sensor_frames_rejected};
  for (int i = 0; i < kReplyWords; ++i) words[i] = w[i];
}

}  // namespace

void encode_reply_frame(const LinkReport& report, std::uint8_t* out) {
  put_header(kReplyFrameType, report.sequence, out);
  put_u32_le(out + 6, static_cast<std::uint32_t>(static_cast<int>(report.status)));
  put_u32_le(out + 10, report.table_crc);
  std::uint32_t words[kReplyWords];
  reply_words(report, words);
  for (std::ptrdiff_t i = 0; i < kReplyWords; ++i) put_u32_le(out + 14 + 4 * i, words[i]);
  put_crc(out, kReplyFrameSize);
}

Status decode_reply_frame(const std::uint8_t* bytes, std::size_t size, LinkReport* report) {
  if (!check_frame(bytes, size, kReplyFrameSize, kReplyFrameType)) return Status::kHalLinkFrameCorrupt;
  LinkReport r;
  r.sequence = get_u32_le(bytes + 2);
  r.status = static_cast<Status>(static_cast<int>(get_u32_le(bytes + 6)));
  r.table_crc = get_u32_le(bytes + 10);
  std::uint32_t w[kReplyWords];
  for (std::ptrdiff_t i = 0; i < kReplyWords; ++i) w[i] = get_u32_le(bytes + 14 + 4 * i);
  FlightCounters& c = r.counters;
  c.cycles = w[0];
  c.clock_overruns = w[1];
  c.platform_dropouts = w[2];
  c.neutral_cycles = w[3];
  c.actuator_rejections = w[4];
  c.telemetry_drops = w[5];
  c.discrete_faults = w[6];
  c.stage_events_refused = w[7];
  c.guidance_faults = w[8];
  c.table_loads = w[9];
  c.table_rejections = w[10];
  c.saturated_cycles = w[11];
  r.sensor_frames_missing = w[12];
  r.sensor_frames_rejected = w[13];
  *report = r;
  return Status::kOk;
}

Status encode_upload_frame(std::uint32_t sequence, const std::uint8_t* image, std::size_t size,
                           std::uint8_t* out, std::size_t* frame_size) {
  if (size > kMaxUploadBytes || (size > 0 && image == nullptr)) return Status::kHalLinkFrameCorrupt;
  put_header(kUploadFrameType, sequence, out);
  put_u16_le(out + 6, static_cast<std::uint16_t>(size));
  if (size > 0) std::memcpy(out + kUploadHeaderSize, image, size);
  const std::size_t total = kUploadHeaderSize + size + 4;
  put_crc(out, total);
  *frame_size = total;
  return Status::kOk;
}

Status decode_upload_frame(const std::uint8_t* bytes, std::size_t size, std::uint32_t* sequence,
                           const std::uint8_t** image, std::size_t* image_size) {
  if (bytes == nullptr || size < kUploadHeaderSize + 4) return Status::kHalLinkFrameCorrupt;
  const std::size_t length = get_u16_le(bytes + 6);
  if (length > kMaxUploadBytes ||
      !check_frame(bytes, size, kUploadHeaderSize + length + 4, kUploadFrameType)) {
    return Status::kHalLinkFrameCorrupt;
  }
  *sequence = get_u32_le(bytes + 2);
  *image = bytes + kUploadHeaderSize;
  *image_size = length;
  return Status::kOk;
}

}  // namespace tolip::hal
