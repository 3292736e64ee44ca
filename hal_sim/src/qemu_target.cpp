// The processor-in-the-loop link (qemu_target.hpp, docs/hil.md "Processor in the loop").
#include "tolip_hal_sim/qemu_target.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

extern char** environ;

namespace tolip::sim {

namespace {

using Clock = std::chrono::steady_clock;

int remaining_ms(Clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
  return left < 0 ? 0 : static_cast<int>(left);
}

Clock::time_point deadline_after(double seconds) {
  return Clock::now() + std::chrono::microseconds(static_cast<long long>(seconds * 1e6));
}

std::string errno_text() { return std::strerror(errno); }

}  // namespace

// ---- the host's half of the protocol --------------------------------------------------------------

SerialFlightLink::SerialFlightLink(int fd, double reply_timeout_s) : fd_(fd), timeout_s_(reply_timeout_s) {}

Status SerialFlightLink::fail(const std::string& cause) {
  if (error_.empty()) {
    error_ = cause;
    const std::string peer = peer_state();
    if (!peer.empty()) error_ += " (" + peer + ")";
  }
  return Status::kHalLinkFrameCorrupt;
}

bool SerialFlightLink::send_all(const std::uint8_t* bytes, std::size_t size, std::string* cause) {
  const Clock::time_point deadline = deadline_after(timeout_s_);
  std::size_t sent = 0;
  while (sent < size) {
    const ssize_t n = ::send(fd_, bytes + sent, size - sent, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n > 0) {
      sent += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) {
      *cause = "the target's serial link closed while sending: " + errno_text();
      return false;
    }
    pollfd p{fd_, POLLOUT, 0};
    const int ready = ::poll(&p, 1, remaining_ms(deadline));
    if (ready == 0) {
      *cause = "the target accepted no byte for " + std::to_string(timeout_s_) + " s";
      return false;
    }
  }
  return true;
}

bool SerialFlightLink::receive_exactly(std::uint8_t* bytes, std::size_t size, std::string* cause) {
  const Clock::time_point deadline = deadline_after(timeout_s_);
  std::size_t got = 0;
  while (got < size) {
    pollfd p{fd_, POLLIN, 0};
    const int ready = ::poll(&p, 1, remaining_ms(deadline));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) {
      char text[160];
      std::snprintf(text, sizeof text, "no reply from the target within %g s (%zu of %zu bytes)", timeout_s_,
                    got, size);
      *cause = text;
      return false;
    }
    const ssize_t n = ::recv(fd_, bytes + got, size - got, 0);
    if (n == 0 || (n < 0 && errno == ECONNRESET)) {
      *cause = "the target closed its serial link";
      return false;
    }
    if (n < 0) {
      if (errno == EINTR || errno == EAGAIN) continue;
      *cause = "reading the target's serial link: " + errno_text();
      return false;
    }
    got += static_cast<std::size_t>(n);
  }
  return true;
}

Status SerialFlightLink::upload(const std::uint8_t* image, std::size_t size) {
  if (!error_.empty()) return Status::kHalLinkFrameCorrupt;
  std::size_t frame_size = 0;
  const std::uint32_t sequence = uploads_++;
  if (!ok(hal::encode_upload_frame(sequence, image, size, frame_, &frame_size))) {
    return fail("a table image of " + std::to_string(size) + " bytes does not fit an upload frame");
  }
  std::string cause;
  std::uint8_t reply[hal::kReplyFrameSize];
  if (!send_all(frame_, frame_size, &cause) || !receive_exactly(reply, sizeof reply, &cause)) {
    return fail("table upload: " + cause);
  }
  hal::LinkReport report;
  if (!ok(hal::decode_reply_frame(reply, sizeof reply, &report)) || report.sequence != sequence) {
    return fail("table upload: the target's reply frame failed its check");
  }
  return report.status;
}

Status SerialFlightLink::cycle(const std::uint8_t* sensor, std::size_t size, std::uint8_t* actuator,
                               hal::TelemetryFrame* telemetry) {
  if (!error_.empty()) return Status::kHalLinkFrameCorrupt;
  std::string cause;
  bool sent = false;
  if (size == 0) {
    // A sensor frame lost in the link: the tick frame starts the cycle without one.
    std::uint8_t tick[hal::kShortFrameSize];
    hal::encode_short_frame(hal::kTickFrameType, cycle_, tick);
    sent = send_all(tick, sizeof tick, &cause);
  } else {
    sent = send_all(sensor, size, &cause);
  }
  if (!sent || !receive_exactly(reply_, sizeof reply_, &cause)) {
    return fail("cycle " + std::to_string(cycle_) + ": " + cause);
  }
  // The actuator frame goes to the plant as received (the plant side checks it: a bad one is held
  // as a corrupt frame); the telemetry frame must be intact and of this cycle.
  std::memcpy(actuator, reply_, hal::kActuatorFrameSize);
  std::uint32_t sequence = 0;
  if (!ok(hal::decode_telemetry_frame(reply_ + hal::kActuatorFrameSize, hal::kTelemetryFrameSize, &sequence,
                                      telemetry)) ||
      sequence != cycle_) {
    return fail("cycle " + std::to_string(cycle_) + ": the target's telemetry frame failed its check");
  }
  ++cycle_;
  return Status::kOk;
}

Status SerialFlightLink::finish(hal::LinkReport* report) {
  if (!error_.empty()) return Status::kHalLinkFrameCorrupt;
  std::uint8_t end[hal::kShortFrameSize];
  hal::encode_short_frame(hal::kEndFrameType, cycle_, end);
  std::string cause;
  std::uint8_t reply[hal::kReplyFrameSize];
  if (!send_all(end, sizeof end, &cause) || !receive_exactly(reply, sizeof reply, &cause)) {
    return fail("end of flight: " + cause);
  }
  if (!ok(hal::decode_reply_frame(reply, sizeof reply, report)) || report->sequence != cycle_ ||
      !ok(report->status)) {
    return fail("end of flight: the target's reply frame failed its check");
  }
  return Status::kOk;
}

// ---- the emulator ----------------------------------------------------------------------------------

QemuTarget::QemuTarget() : SerialFlightLink(-1, 10.0) {}

QemuTarget::~QemuTarget() {
  if (pid_ > 0 && exit_status_ < 0) {
    ::kill(pid_, SIGKILL);
    int status = 0;
    ::waitpid(pid_, &status, 0);
  }
  if (socket_fd_ >= 0) ::close(socket_fd_);
  if (listen_fd_ >= 0) ::close(listen_fd_);
  if (!socket_path_.empty()) ::unlink(socket_path_.c_str());
  if (!log_path_.empty()) ::unlink(log_path_.c_str());
  if (!directory_.empty()) ::rmdir(directory_.c_str());
}

std::string QemuTarget::peer_state() {
  if (pid_ <= 0) return "";
  if (exit_status_ < 0) {
    int status = 0;
    // A closed link usually means the emulator is going: give it a moment to be reaped.
    for (int i = 0; i < 20 && exit_status_ < 0; ++i) {
      if (::waitpid(pid_, &status, WNOHANG) == pid_) {
        exit_status_ = status;
        break;
      }
      ::usleep(10000);
    }
  }
  std::string state;
  if (exit_status_ < 0) {
    state = "QEMU still running";
  } else if (WIFEXITED(exit_status_)) {
    state = "QEMU exited with status " + std::to_string(WEXITSTATUS(exit_status_));
  } else if (WIFSIGNALED(exit_status_)) {
    state = "QEMU killed by signal " + std::to_string(WTERMSIG(exit_status_));
  }
  std::string text = log();
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  if (!text.empty()) {
    const std::size_t last = text.rfind('\n');
    state += "; its last output: " + (last == std::string::npos ? text : text.substr(last + 1));
  }
  return state;
}

std::string QemuTarget::log() const {
  if (log_path_.empty()) return "";
  std::ifstream in(log_path_, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool QemuTarget::start(const QemuOptions& options, std::string* error) {
  if (options.image.empty() || ::access(options.image.c_str(), R_OK) != 0) {
    *error = "the target image '" + options.image +
             "' cannot be read (build it with the cortex-m7 preset: docs/target.md)";
    return false;
  }
  char pattern[] = "/tmp/tolip-pil-XXXXXX";
  if (::mkdtemp(pattern) == nullptr) {
    *error = "cannot make a directory for the serial socket: " + errno_text();
    return false;
  }
  directory_ = pattern;
  socket_path_ = directory_ + "/uart0.sock";
  log_path_ = directory_ + "/qemu.log";

  listen_fd_ = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  std::snprintf(address.sun_path, sizeof address.sun_path, "%s", socket_path_.c_str());
  if (listen_fd_ < 0 || ::bind(listen_fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
      ::listen(listen_fd_, 1) != 0) {
    *error = "cannot listen on " + socket_path_ + ": " + errno_text();
    return false;
  }

  // qemu-system-arm -M mps2-an500 -cpu cortex-m7 ... -serial unix:SOCKET (UART0, QEMU connects as
  // the client) -kernel IMAGE; its console output (semihosting) to the log.
  const std::vector<std::string> args = {options.qemu,
                                         "-M",
                                         "mps2-an500",
                                         "-cpu",
                                         "cortex-m7",
                                         "-display",
                                         "none",
                                         "-monitor",
                                         "none",
                                         "-serial",
                                         "unix:" + socket_path_,
                                         "-semihosting-config",
                                         "enable=on,target=native",
                                         "-kernel",
                                         options.image};
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  const int spawned = ::posix_spawnp(&pid_, options.qemu.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) {
    pid_ = -1;
    *error = "cannot start " + options.qemu + ": " + std::strerror(spawned);
    return false;
  }

  // Wait for the emulator to connect its serial port (or to die).
  const Clock::time_point deadline = deadline_after(options.start_timeout_s);
  for (;;) {
    pollfd p{listen_fd_, POLLIN, 0};
    const int ready = ::poll(&p, 1, remaining_ms(deadline) < 100 ? remaining_ms(deadline) : 100);
    if (ready > 0) {
      socket_fd_ = ::accept4(listen_fd_, nullptr, nullptr, SOCK_CLOEXEC);
      if (socket_fd_ >= 0) break;
    }
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
      exit_status_ = status;
      *error = "QEMU ended before it connected its serial port (" + peer_state() + ")";
      return false;
    }
    if (remaining_ms(deadline) == 0) {
      *error =
          "QEMU did not connect its serial port within " + std::to_string(options.start_timeout_s) + " s";
      return false;
    }
  }
  attach(socket_fd_, options.reply_timeout_s);
  return true;
}

bool QemuTarget::stop(std::string* error) {
  if (pid_ <= 0) return false;
  const Clock::time_point deadline = deadline_after(5.0);
  while (exit_status_ < 0) {
    int status = 0;
    if (::waitpid(pid_, &status, WNOHANG) == pid_) {
      exit_status_ = status;
      break;
    }
    if (remaining_ms(deadline) == 0) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, &status, 0);
      exit_status_ = status;
      *error = "the target image did not exit after the end of the flight; QEMU killed";
      return false;
    }
    ::usleep(5000);
  }
  if (!WIFEXITED(exit_status_) || WEXITSTATUS(exit_status_) != 0) {
    *error = "the target image ended badly (" + peer_state() + ")";
    return false;
  }
  return true;
}

}  // namespace tolip::sim
