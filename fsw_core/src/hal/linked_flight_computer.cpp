// The guidance computer at the flight end of the frame link (linked_flight_computer.hpp, docs/hil.md).
#include "tolip/hal/linked_flight_computer.hpp"

#include <cstring>

namespace tolip::hal {

Ports LinkedFlightComputer::ports_for(LinkedFlightComputer* self, double period_s) {
  Ports ports;
  ports.clock = {self, clock_wait, period_s};
  ports.platform = {self, platform_read};
  ports.actuators = {self, actuators_command};
  ports.table_store = {self, store_read};
  ports.discretes = {self, discretes_read};
  ports.telemetry = {self, telemetry_emit};
  return ports;
}

LinkedFlightComputer::LinkedFlightComputer(double period_s) : app_(ports_for(this, period_s)) {}

// The arrival of the cycle's sensor frame is the clock: the frame is checked here, once per cycle.
Status LinkedFlightComputer::clock_wait(void* context, std::uint32_t* cycle) {
  LinkedFlightComputer& c = *static_cast<LinkedFlightComputer*>(context);
  *cycle = c.cycle_;
  SensorFrame frame;
  c.sensor_decoded_ = c.sensor_size_ == kSensorFrameSize &&
                      ok(decode_sensor_frame(c.sensor_bytes_, c.sensor_size_, &frame)) &&
                      frame.sequence == c.cycle_;
  if (c.sensor_size_ == 0) {
    ++c.sensor_missing_;
  } else if (!c.sensor_decoded_) {
    ++c.sensor_rejected_;
  }
  if (c.sensor_decoded_) c.sensor_ = frame;
  ++c.cycle_;
  return Status::kOk;
}

Status LinkedFlightComputer::platform_read(void* context, PlatformSample* sample) {
  const LinkedFlightComputer& c = *static_cast<const LinkedFlightComputer*>(context);
  if (!c.sensor_decoded_) return Status::kHalLinkFrameCorrupt;
  if (c.sensor_.platform_invalid) return Status::kHalSensorInvalid;
  *sample = c.sensor_.sample;
  return Status::kOk;
}

Status LinkedFlightComputer::discretes_read(void* context, StageDiscretes* discretes) {
  const LinkedFlightComputer& c = *static_cast<const LinkedFlightComputer*>(context);
  if (!c.sensor_decoded_) return Status::kHalDiscretesInvalid;
  *discretes = c.sensor_.discretes;
  return Status::kOk;
}

Status LinkedFlightComputer::actuators_command(void* context, const ActuatorCommand& command) {
  LinkedFlightComputer& c = *static_cast<LinkedFlightComputer*>(context);
  ActuatorFrame frame;
  frame.sequence = c.cycle_ - 1;  // the cycle's index
  frame.command = command;
  if (c.actuator_out_ != nullptr) encode_actuator_frame(frame, c.actuator_out_);
  return Status::kOk;
}

Status LinkedFlightComputer::store_read(void* context, std::uint8_t* buffer, std::size_t capacity,
                                        std::size_t* size) {
  const LinkedFlightComputer& c = *static_cast<const LinkedFlightComputer*>(context);
  const std::size_t kept = c.store_size_ < sizeof c.store_ ? c.store_size_ : sizeof c.store_;
  const std::size_t n = kept < capacity ? kept : capacity;
  if (n > 0) std::memcpy(buffer, c.store_, n);
  *size = c.store_size_;
  return Status::kOk;
}

Status LinkedFlightComputer::telemetry_emit(void* context, const TelemetryFrame& frame) {
  LinkedFlightComputer& c = *static_cast<LinkedFlightComputer*>(context);
  if (c.telemetry_out_ != nullptr) *c.telemetry_out_ = frame;
  return Status::kOk;
}

Status LinkedFlightComputer::upload(const std::uint8_t* image, std::size_t size) {
  const std::size_t n = size < sizeof store_ ? size : sizeof store_;
  if (n > 0 && image != nullptr) std::memcpy(store_, image, n);
  store_size_ = image != nullptr ? size : 0;
  if (booted_) return app_.load_table();
  const Status status = app_.boot();
  booted_ = ok(status);
  return status;
}

Status LinkedFlightComputer::run_cycle(const std::uint8_t* sensor, std::size_t size,
                                       std::uint8_t* actuator_frame, TelemetryFrame* telemetry) {
  sensor_bytes_ = sensor;
  sensor_size_ = sensor != nullptr ? size : 0;
  actuator_out_ = actuator_frame;
  telemetry_out_ = telemetry;
  const Status status = app_.run_minor_cycle();
  sensor_bytes_ = nullptr;
  sensor_size_ = 0;
  actuator_out_ = nullptr;
  telemetry_out_ = nullptr;
  return status;
}

LinkReport LinkedFlightComputer::report(std::uint32_t sequence, Status status) const {
  LinkReport r;
  r.sequence = sequence;
  r.status = status;
  r.table_crc = app_.tables().active_crc();
  r.counters = app_.counters();
  r.sensor_frames_missing = sensor_missing_;
  r.sensor_frames_rejected = sensor_rejected_;
  return r;
}

namespace {

Status read_bytes(const ByteChannel& channel, std::uint8_t* out, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) {
    const Status status = channel.read(channel.context, out + i);
    if (!ok(status)) return status;
  }
  return Status::kOk;
}

}  // namespace

Status LinkedFlightComputer::serve(const ByteChannel& channel) {
  if (channel.read == nullptr || channel.write == nullptr) return Status::kHalPortMissing;
  TelemetryFrame telemetry;
  std::uint8_t reply[kReplyFrameSize];
  for (;;) {
    // Hunt for the sync byte, then the type says how long the frame is.
    Status status = read_bytes(channel, rx_, 1);
    if (!ok(status)) return status;
    if (rx_[0] != kFrameSync) continue;
    status = read_bytes(channel, rx_ + 1, 1);
    if (!ok(status)) return status;
    const std::uint8_t type = rx_[1];
    if (type == kSensorFrameType || type == kTickFrameType) {
      const std::size_t size = type == kSensorFrameType ? kSensorFrameSize : kShortFrameSize;
      status = read_bytes(channel, rx_ + 2, size - 2);
      if (!ok(status)) return status;
      // A tick is a cycle whose sensor frame was lost; a sensor frame that fails its check is
      // rejected inside the cycle (the application's dropout reaction).
      const bool tick = type == kTickFrameType;
      (void)run_cycle(tick ? nullptr : rx_, tick ? 0 : size, tx_, &telemetry);
      encode_telemetry_frame(cycle_ - 1, telemetry, tx_ + kActuatorFrameSize);
      status = channel.write(channel.context, tx_, sizeof tx_);
      if (!ok(status)) return status;
    } else if (type == kUploadFrameType) {
      status = read_bytes(channel, rx_ + 2, kUploadHeaderSize - 2);
      if (!ok(status)) return status;
      const std::size_t length = get_u16_le(rx_ + 6);
      std::uint32_t sequence = get_u32_le(rx_ + 2);
      Status loaded = Status::kHalLinkFrameCorrupt;
      if (length <= kMaxUploadBytes) {
        status = read_bytes(channel, rx_ + kUploadHeaderSize, length + 4);
        if (!ok(status)) return status;
        const std::uint8_t* image = nullptr;
        std::size_t image_size = 0;
        if (ok(decode_upload_frame(rx_, kUploadHeaderSize + length + 4, &sequence, &image, &image_size))) {
          loaded = upload(image, image_size);
        }
      }
      encode_reply_frame(report(sequence, loaded), reply);
      status = channel.write(channel.context, reply, sizeof reply);
      if (!ok(status)) return status;
    } else if (type == kEndFrameType) {
      status = read_bytes(channel, rx_ + 2, kShortFrameSize - 2);
      if (!ok(status)) return status;
      std::uint32_t sequence = get_u32_le(rx_ + 2);
      const Status checked = decode_short_frame(rx_, kShortFrameSize, kEndFrameType, &sequence);
      encode_reply_frame(report(sequence, checked), reply);
      status = channel.write(channel.context, reply, sizeof reply);
      if (!ok(status)) return status;
      if (ok(checked)) return Status::kOk;
    }
    // Any other type: not a frame start; hunt for the next sync byte.
  }
}

}  // namespace tolip::hal
