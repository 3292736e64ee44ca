// The guidance computer at the flight end of the frame link (docs/hil.md, "Processor in the loop"):
// the flight application on ports fed by the link's frames. The cycle's sensor frame is the clock
// (its arrival starts the minor cycle), it carries the platform sample and the stage discretes;
// the actuator port writes the actuator frame, the telemetry port the telemetry frame; the table
// store holds the last upload.
//
// Written once for both ends of the bench: the in-process bench (hal_sim) calls run_cycle with the
// frame's bytes directly; the Cortex-M7 image (flight_image/pil) calls serve, which reads the frames
// from the UART and writes the replies, in lock-step with the host. The same code therefore runs
// the cycle in both, and the same frames give the same telemetry. Allocates nothing; about 9 KiB,
// meant for static storage.
#pragma once

#include <cstddef>
#include <cstdint>

#include "tolip/core/status.hpp"
#include "tolip/hal/flight_application.hpp"
#include "tolip/hal/hal.hpp"
#include "tolip/hal/link.hpp"

namespace tolip::hal {

// A byte stream to the host (the target's UART; a socket in the host tests). read blocks until one
// byte arrived; write until every byte was accepted. A failure ends serve with that status.
struct ByteChannel {
  void* context = nullptr;
  Status (*read)(void* context, std::uint8_t* byte) = nullptr;
  Status (*write)(void* context, const std::uint8_t* bytes, std::size_t size) = nullptr;
};

class LinkedFlightComputer {
 public:
  explicit LinkedFlightComputer(double period_s);
  LinkedFlightComputer(const LinkedFlightComputer&) = delete;
  LinkedFlightComputer& operator=(const LinkedFlightComputer&) = delete;

  // The image becomes the table store's content (at most kMaxUploadBytes are kept; the size given is
  // the store's size) and is loaded: the first successful call boots the application
  // (FlightApplication::boot), later ones are uploads between cycles (load_table). The loader's
  // status.
  Status upload(const std::uint8_t* image, std::size_t size);
  // One minor cycle on the cycle's sensor frame as received (nullptr / 0 bytes: it did not arrive).
  // Writes the actuator frame (kActuatorFrameSize bytes) to `actuator_frame` and the telemetry frame
  // to *telemetry. The application's status (its faults are in its counters).
  Status run_cycle(const std::uint8_t* sensor, std::size_t size, std::uint8_t* actuator_frame,
                   TelemetryFrame* telemetry);
  // The flight side's account (counters, table in force, link faults seen).
  LinkReport report(std::uint32_t sequence, Status status) const;

  // Serves the host over `channel` until the end frame ('E'): uploads ('U') are loaded and answered
  // with a reply frame; each sensor frame ('S', or the tick 'K' of a lost one) runs one minor cycle
  // answered with its actuator and telemetry frames; the end frame is answered with the final
  // report and serve returns kOk. Bytes that are no frame are skipped up to the next sync byte; an
  // upload frame that fails its CRC is answered with kHalLinkFrameCorrupt (the table in force
  // stays). The channel's failure status otherwise.
  Status serve(const ByteChannel& channel);

  const FlightApplication& application() const { return app_; }
  std::uint32_t sensor_frames_missing() const { return sensor_missing_; }
  std::uint32_t sensor_frames_rejected() const { return sensor_rejected_; }

 private:
  static Ports ports_for(LinkedFlightComputer* self, double period_s);
  static Status clock_wait(void* context, std::uint32_t* cycle);
  static Status platform_read(void* context, PlatformSample* sample);
  static Status discretes_read(void* context, StageDiscretes* discretes);
  static Status actuators_command(void* context, const ActuatorCommand& command);
  static Status store_read(void* context, std::uint8_t* buffer, std::size_t capacity, std::size_t* size);
  static Status telemetry_emit(void* context, const TelemetryFrame& frame);

  FlightApplication app_;
  bool booted_ = false;
  // The cycle in progress.
  const std::uint8_t* sensor_bytes_ = nullptr;
  std::size_t sensor_size_ = 0;
  bool sensor_decoded_ = false;
  SensorFrame sensor_;
  std::uint32_t cycle_ = 0;  // cycles started (the next cycle's index)
  std::uint8_t* actuator_out_ = nullptr;
  TelemetryFrame* telemetry_out_ = nullptr;
  std::uint32_t sensor_missing_ = 0;
  std::uint32_t sensor_rejected_ = 0;
  // The table store.
  std::uint8_t store_[kMaxUploadBytes] = {};
  std::size_t store_size_ = 0;
  // serve's frame buffers.
  std::uint8_t rx_[kMaxUploadFrameSize] = {};
  std::uint8_t tx_[kActuatorFrameSize + kTelemetryFrameSize] = {};
};

}  // namespace tolip::hal
