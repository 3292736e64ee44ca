// Processor in the loop (docs/hil.md, "Processor in the loop"): the flight side of the bench as the
// Cortex-M7 image (flight_image/pil) under qemu-system-arm -M mps2-an500, its UART0 connected to a
// Unix socket of this process, exchanging the frames of tolip/hal/link.hpp in lock-step.
//
// SerialFlightLink speaks the host's half of the protocol over any connected byte stream (the
// QEMU socket; a socket pair to a thread running hal::LinkedFlightComputer::serve in the host
// tests). QemuTarget starts and stops the emulator. Every wait has a timeout; a dead emulator, a
// timeout and a frame that fails its check end the run with a named cause (error()), never a hang.
#pragma once

#include <sys/types.h>

#include <cstddef>
#include <cstdint>
#include <string>

#include "tolip_hal_sim/bench.hpp"

namespace tolip::sim {

class SerialFlightLink : public FlightLink {
 public:
  // fd: a connected stream socket (not owned). reply_timeout_s: the longest wait for one reply.
  SerialFlightLink(int fd, double reply_timeout_s);
  Status upload(const std::uint8_t* image, std::size_t size) override;
  Status cycle(const std::uint8_t* sensor, std::size_t size, std::uint8_t* actuator,
               hal::TelemetryFrame* telemetry) override;
  Status finish(hal::LinkReport* report) override;
  // Why the link failed (empty while it works).
  const std::string& error() const { return error_; }
  std::uint32_t cycles() const { return cycle_; }

 protected:
  // What the other end's state says about a failure (QemuTarget: whether the emulator exited).
  virtual std::string peer_state() { return ""; }
  void attach(int fd, double reply_timeout_s) {
    fd_ = fd;
    timeout_s_ = reply_timeout_s;
  }

 private:
  Status fail(const std::string& cause);
  bool send_all(const std::uint8_t* bytes, std::size_t size, std::string* cause);
  bool receive_exactly(std::uint8_t* bytes, std::size_t size, std::string* cause);

  int fd_;
  double timeout_s_;
  std::uint32_t cycle_ = 0;
  std::uint32_t uploads_ = 0;
  std::string error_;
  std::uint8_t frame_[hal::kMaxUploadFrameSize] = {};
  std::uint8_t reply_[hal::kActuatorFrameSize + hal::kTelemetryFrameSize] = {};
};

struct QemuOptions {
  std::string qemu = "qemu-system-arm";
  std::string image;              // the ELF (tolip_flight_pil.elf)
  double start_timeout_s = 30.0;  // until the emulator connected its serial port
  double reply_timeout_s = 10.0;  // per reply
};

class QemuTarget final : public SerialFlightLink {
 public:
  QemuTarget();
  ~QemuTarget() override;
  QemuTarget(const QemuTarget&) = delete;
  QemuTarget& operator=(const QemuTarget&) = delete;
  // Starts the emulator on the image and waits for its serial port to connect. False with the
  // cause in *error.
  bool start(const QemuOptions& options, std::string* error);
  // After finish(): waits (at most a few seconds) for the image to exit; kills the emulator if it
  // does not. True when it exited with status 0.
  bool stop(std::string* error);
  // The emulator's console output (semihosting, QEMU's own messages).
  std::string log() const;

 protected:
  std::string peer_state() override;

 private:
  int socket_fd_ = -1;
  int listen_fd_ = -1;
  pid_t pid_ = -1;
  int exit_status_ = -1;  // waitpid status once reaped
  std::string directory_;
  std::string socket_path_;
  std::string log_path_;
};

}  // namespace tolip::sim
