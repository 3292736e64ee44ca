// The bench's frame link between the plant and the guidance computer (docs/hil.md, "Link frames"):
// a sensor frame in (platform sample and stage discretes) and an actuator frame out per minor
// cycle. Each frame is: sync byte, frame type, u32 sequence number, payload, CRC-32 (IEEE, the
// table image's, tolip/table/crc32.hpp) of everything before it; little-endian, written byte by
// byte like the table image. A frame that fails its CRC, has the wrong sync/type, or whose sequence
// number is not the expected one is rejected and counted; the receiver's defined reaction is that
// of a failed port call (docs/hil.md).
#pragma once

#include <cstddef>
#include <cstdint>

#include "tolip/core/status.hpp"
#include "tolip/hal/hal.hpp"

namespace tolip::sim {

inline constexpr std::uint8_t kFrameSync = 0x7E;
inline constexpr std::uint8_t kSensorFrameType = 0x53;    // 'S'
inline constexpr std::uint8_t kActuatorFrameType = 0x41;  // 'A'
// sync, type, sequence (4), theta, chi, pitch rate, yaw rate (4 x 8), stage code (1), spun up (1),
// discrete sequence (4), CRC (4)
inline constexpr std::size_t kSensorFrameSize = 2 + 4 + 32 + 1 + 1 + 4 + 4;  // 48
// sync, type, sequence (4), kind (1), pitch, yaw (2 x 8), CRC (4)
inline constexpr std::size_t kActuatorFrameSize = 2 + 4 + 1 + 16 + 4;  // 27

struct SensorFrame {
  std::uint32_t sequence = 0;
  hal::PlatformSample sample;
  hal::StageDiscretes discretes;
};
struct ActuatorFrame {
  std::uint32_t sequence = 0;
  hal::ActuatorCommand command;
};

void encode_sensor_frame(const SensorFrame& frame, std::uint8_t* out);
// kHalLinkFrameCorrupt on a bad sync, type, CRC or stage code; *frame untouched then.
Status decode_sensor_frame(const std::uint8_t* bytes, std::size_t size, SensorFrame* frame);
void encode_actuator_frame(const ActuatorFrame& frame, std::uint8_t* out);
Status decode_actuator_frame(const std::uint8_t* bytes, std::size_t size, ActuatorFrame* frame);

}  // namespace tolip::sim
