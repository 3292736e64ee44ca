// Frame codec of the bench link (link.hpp, docs/hil.md).
#include "tolip_hal_sim/link.hpp"

#include "tolip/table/crc32.hpp"
#include "tolip/table/table_image.hpp"

namespace tolip::sim {

namespace {

void put_header(std::uint8_t type, std::uint32_t sequence, std::uint8_t* out) {
  out[0] = kFrameSync;
  out[1] = type;
  put_u32_le(out + 2, sequence);
}

bool check_frame(const std::uint8_t* bytes, std::size_t size, std::size_t expected, std::uint8_t type) {
  if (size != expected || bytes[0] != kFrameSync || bytes[1] != type) return false;
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
  out[39] = frame.discretes.spun_up ? 1 : 0;
  put_u32_le(out + 40, frame.discretes.sequence);
  put_u32_le(out + 44, crc32(out, 44));
}

Status decode_sensor_frame(const std::uint8_t* bytes, std::size_t size, SensorFrame* frame) {
  if (!check_frame(bytes, size, kSensorFrameSize, kSensorFrameType)) return Status::kHalLinkFrameCorrupt;
  const int code = bytes[38];
  if (code < 1 || code > 10 || bytes[39] > 1) return Status::kHalLinkFrameCorrupt;
  SensorFrame f;
  f.sequence = get_u32_le(bytes + 2);
  f.sample.theta_rad = get_f64_le(bytes + 6);
  f.sample.chi_rad = get_f64_le(bytes + 14);
  f.sample.pitch_rate_rad_s = get_f64_le(bytes + 22);
  f.sample.yaw_rate_rad_s = get_f64_le(bytes + 30);
  f.discretes.stage_code = code;
  f.discretes.spun_up = bytes[39] == 1;
  f.discretes.sequence = get_u32_le(bytes + 40);
  *frame = f;
  return Status::kOk;
}

void encode_actuator_frame(const ActuatorFrame& frame, std::uint8_t* out) {
  put_header(kActuatorFrameType, frame.sequence, out);
  out[6] = static_cast<std::uint8_t>(frame.command.kind);
  put_f64_le(out + 7, frame.command.pitch);
  put_f64_le(out + 15, frame.command.yaw);
  put_u32_le(out + 23, crc32(out, 23));
}

Status decode_actuator_frame(const std::uint8_t* bytes, std::size_t size, ActuatorFrame* frame) {
  if (!check_frame(bytes, size, kActuatorFrameSize, kActuatorFrameType)) return Status::kHalLinkFrameCorrupt;
  if (bytes[6] > 2) return Status::kHalLinkFrameCorrupt;
  ActuatorFrame f;
  f.sequence = get_u32_le(bytes + 2);
  f.command.kind = static_cast<hal::ActuatorKind>(bytes[6]);
  f.command.pitch = get_f64_le(bytes + 7);
  f.command.yaw = get_f64_le(bytes + 15);
  *frame = f;
  return Status::kOk;
}

}  // namespace tolip::sim
