// The frame link between the plant and the guidance computer (docs/hil.md, "Link frames"): a sensor
// frame in (platform sample and stage discretes) and an actuator frame out per minor cycle, plus,
// on a serial port (processor in the loop, docs/hil.md "Processor in the loop"), the table upload,
// the cycle's telemetry, the clock tick of a cycle whose sensor frame was lost, and the end of the
// flight with the flight side's counters.
//
// Each frame is: sync byte, frame type, u32 sequence number, payload, CRC-32 (IEEE, the table
// image's, tolip/table/crc32.hpp) of everything before it; little-endian, written byte by byte like
// the table image. A frame that fails its CRC, has the wrong sync/type/size, or whose sequence
// number is not the expected one is rejected and counted; the receiver's defined reaction is that
// of a failed port call (docs/hil.md). Core code: builds for the host and the Cortex-M7, allocates
// nothing.
#pragma once

#include <cstddef>
#include <cstdint>

#include "tolip/core/status.hpp"
#include "tolip/hal/flight_application.hpp"
#include "tolip/hal/hal.hpp"
#include "tolip/table/table_image.hpp"

namespace tolip::hal {

inline constexpr std::uint8_t kFrameSync = 0x7E;
inline constexpr std::uint8_t kSensorFrameType = 0x53;     // 'S' host -> flight: a minor cycle's sensors
inline constexpr std::uint8_t kActuatorFrameType = 0x41;   // 'A' flight -> host: the actuator command
inline constexpr std::uint8_t kTelemetryFrameType = 0x54;  // 'T' flight -> host: the cycle's telemetry
inline constexpr std::uint8_t kUploadFrameType = 0x55;     // 'U' host -> flight: a table image upload
inline constexpr std::uint8_t kTickFrameType = 0x4B;   // 'K' host -> flight: a cycle, its sensor frame lost
inline constexpr std::uint8_t kEndFrameType = 0x45;    // 'E' host -> flight: end of the flight
inline constexpr std::uint8_t kReplyFrameType = 0x52;  // 'R' flight -> host: reply to U and E

// sync, type, sequence (4), theta, chi, pitch rate, yaw rate (4 x 8), stage code (1), flags (1:
// bit 0 spun up, bit 1 platform sample invalid), discrete sequence (4), CRC (4)
inline constexpr std::size_t kSensorFrameSize = 2 + 4 + 32 + 1 + 1 + 4 + 4;  // 48
// sync, type, sequence (4), kind (1), pitch, yaw (2 x 8), CRC (4)
inline constexpr std::size_t kActuatorFrameSize = 2 + 4 + 1 + 16 + 4;  // 27
// sync, type, sequence (4), cycle (4), time (8), stage code, guidance mode, actuator kind, flags
// (bit 0 saturated, bit 1 platform valid) (4 x 1), theta_c, chi_c, theta, chi, pitch rate, yaw rate,
// K_theta, K_q, pitch and yaw command (10 x 8), table CRC (4), fault count (4), CRC (4)
inline constexpr std::size_t kTelemetryFrameSize = 2 + 4 + 4 + 8 + 4 + 80 + 4 + 4 + 4;  // 114
// sync, type, sequence (4), CRC (4): the tick and end frames
inline constexpr std::size_t kShortFrameSize = 2 + 4 + 4;  // 10
// sync, type, sequence (4), u32 status, u32 active table CRC, the 12 flight counters, sensor frames
// missing and rejected (14 x 4), CRC (4)
inline constexpr std::size_t kReplyFrameSize = 2 + 4 + 4 + 4 + 56 + 4;  // 74
// sync, type, sequence (4), u16 length, the image (length bytes), CRC (4)
inline constexpr std::size_t kUploadHeaderSize = 2 + 4 + 2;
inline constexpr std::size_t kMaxUploadBytes = kTableImageSize + 1;  // one more: an oversized image is seen
inline constexpr std::size_t kMaxUploadFrameSize = kUploadHeaderSize + kMaxUploadBytes + 4;

struct SensorFrame {
  std::uint32_t sequence = 0;
  PlatformSample sample;
  StageDiscretes discretes;
  bool platform_invalid = false;  // the platform's own validity flag: no valid sample this cycle
};
struct ActuatorFrame {
  std::uint32_t sequence = 0;
  ActuatorCommand command;
};
// The flight side's account at the end of the flight or after an upload.
struct LinkReport {
  std::uint32_t sequence = 0;
  Status status = Status::kOk;  // of the upload; kOk for the end frame
  std::uint32_t table_crc = 0;  // of the table in force
  FlightCounters counters;
  std::uint32_t sensor_frames_missing = 0;   // cycles whose sensor frame did not arrive (tick frames)
  std::uint32_t sensor_frames_rejected = 0;  // sensor frames that failed their CRC, type or sequence
};

void encode_sensor_frame(const SensorFrame& frame, std::uint8_t* out);
// kHalLinkFrameCorrupt on a bad sync, type, size, CRC, stage code or flags; *frame untouched then.
Status decode_sensor_frame(const std::uint8_t* bytes, std::size_t size, SensorFrame* frame);
void encode_actuator_frame(const ActuatorFrame& frame, std::uint8_t* out);
Status decode_actuator_frame(const std::uint8_t* bytes, std::size_t size, ActuatorFrame* frame);
void encode_telemetry_frame(std::uint32_t sequence, const TelemetryFrame& frame, std::uint8_t* out);
Status decode_telemetry_frame(const std::uint8_t* bytes, std::size_t size, std::uint32_t* sequence,
                              TelemetryFrame* frame);
// The tick ('K') and end ('E') frames.
void encode_short_frame(std::uint8_t type, std::uint32_t sequence, std::uint8_t* out);
Status decode_short_frame(const std::uint8_t* bytes, std::size_t size, std::uint8_t type,
                          std::uint32_t* sequence);
void encode_reply_frame(const LinkReport& report, std::uint8_t* out);
Status decode_reply_frame(const std::uint8_t* bytes, std::size_t size, LinkReport* report);
// Writes kUploadHeaderSize + size + 4 bytes; kHalLinkFrameCorrupt (nothing written) when size is
// more than kMaxUploadBytes.
Status encode_upload_frame(std::uint32_t sequence, const std::uint8_t* image, std::size_t size,
                           std::uint8_t* out, std::size_t* frame_size);
// The image inside a checked upload frame: *image points into `bytes`.
Status decode_upload_frame(const std::uint8_t* bytes, std::size_t size, std::uint32_t* sequence,
                           const std::uint8_t** image, std::size_t* image_size);

}  // namespace tolip::hal
