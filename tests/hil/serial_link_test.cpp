// The processor-in-the-loop protocol on the host alone (docs/hil.md, "Processor in the loop"): the
// flight end's serve loop (hal::LinkedFlightComputer::serve, the code the Cortex-M7 image runs over
// its UART) in a thread at one end of a Unix socket pair, the host's half of the protocol
// (sim::SerialFlightLink, the code `tolip hil --target qemu` speaks to the emulator) at the other,
// the hal_sim plant behind it. Truth: the in-process bench, which calls the same flight end
// directly with the frames' bytes; the byte stream may change nothing, so the telemetry must be the
// in-process run's byte for byte. Seconds, no emulator: the QEMU proof is `ctest --preset
// cortex-m7` (FlightTarget_Pil*).
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "support/allocation_counter.hpp"
#include "support/reference_data.hpp"
#include "tolip/hal/link.hpp"
#include "tolip/hal/linked_flight_computer.hpp"
#include "tolip/table/table_image.hpp"
#include "tolip_ground/card_deck.hpp"
#include "tolip_ground/guidance_table.hpp"
#include "tolip_ground/hardover_run.hpp"
#include "tolip_ground/optimization_run.hpp"
#include "tolip_hal_sim/bench.hpp"
#include "tolip_hal_sim/qemu_target.hpp"

namespace tolip::test {
namespace {

// The reference deck's optimization job and the table image built of it (as bench/hil_bench.cpp).
struct LinkCase {
  ground::Deck deck;
  ground::OptimizationRun run;
  std::unique_ptr<HardoverData> hardover;
  std::uint8_t image[kTableImageSize] = {};
  sim::BenchInputs inputs() const {
    sim::BenchInputs in;
    in.mission = &run.linearization.workspace->mission;
    in.prepared = &run.linearization.workspace->prepared;
    in.hardover = hardover.get();
    in.table = image;
    in.table_size = sizeof image;
    return in;
  }
};

const LinkCase& link_case() {
  static LinkCase* loaded = [] {
    auto* c = new LinkCase;
    ground::DeckError error;
    EXPECT_TRUE(ground::load_deck(reference_deck(), &c->deck, &error)) << error.to_string();
    const ground::DeckCase& deck_case = c->deck.cases.front();
    std::ostringstream err;
    EXPECT_TRUE(ground::prepare_hardover_data(reference_deck(), "", deck_case, &c->hardover, err))
        << err.str();
    ground::run_optimization(*deck_case.mission, nullptr, &c->run);
    EXPECT_EQ(c->run.linearization.status, Status::kOk);
    GuidanceTable table;
    std::string build_error;
    EXPECT_TRUE(ground::build_guidance_table(c->run.linearization.workspace->mission, deck_case.extras,
                                             c->run.linearization.workspace->prepared,
                                             &c->run.linearization.result->program, {}, &table, &build_error))
        << build_error;
    EXPECT_EQ(encode_table_image(table, c->image, sizeof c->image), Status::kOk);
    return c;
  }();
  return *loaded;
}

// The flight end's byte stream: one end of the socket pair, read in blocks.
struct SocketChannel {
  int fd = -1;
  std::uint8_t buffer[512] = {};
  std::size_t have = 0;
  std::size_t next = 0;

  static Status read(void* context, std::uint8_t* byte) {
    SocketChannel& c = *static_cast<SocketChannel*>(context);
    if (c.next == c.have) {
      const ssize_t n = ::recv(c.fd, c.buffer, sizeof c.buffer, 0);
      if (n <= 0) return Status::kHalLinkFrameCorrupt;  // the host closed its end
      c.have = static_cast<std::size_t>(n);
      c.next = 0;
    }
    *byte = c.buffer[c.next++];
    return Status::kOk;
  }
  static Status write(void* context, const std::uint8_t* bytes, std::size_t size) {
    const SocketChannel& c = *static_cast<const SocketChannel*>(context);
    std::size_t sent = 0;
    while (sent < size) {
      const ssize_t n = ::send(c.fd, bytes + sent, size - sent, MSG_NOSIGNAL);
      if (n <= 0) return Status::kHalLinkFrameCorrupt;
      sent += static_cast<std::size_t>(n);
    }
    return Status::kOk;
  }
  hal::ByteChannel channel() { return hal::ByteChannel{this, read, write}; }
};

// A socket pair with the flight end serving one end in a thread. The host's end is host_fd();
// the destructor closes it first, so a serve loop still waiting for bytes returns and is joined.
class ServedFlightEnd {
 public:
  ServedFlightEnd()
      : computer_(std::make_unique<hal::LinkedFlightComputer>(1.0 / hal::kDefaultMinorCycleHz)) {
    int fds[2] = {-1, -1};
    EXPECT_EQ(::socketpair(AF_UNIX, SOCK_STREAM, 0, fds), 0);
    host_fd_ = fds[0];
    flight_.fd = fds[1];
    timeval timeout{10, 0};  // a test's own reads never hang on a silent flight end
    ::setsockopt(host_fd_, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
    thread_ = std::thread([this] { served_ = computer_->serve(flight_.channel()); });
  }
  ~ServedFlightEnd() {
    close_host_end();
    if (thread_.joinable()) thread_.join();
    if (flight_.fd >= 0) ::close(flight_.fd);
  }
  ServedFlightEnd(const ServedFlightEnd&) = delete;
  ServedFlightEnd& operator=(const ServedFlightEnd&) = delete;

  int host_fd() const { return host_fd_; }
  // Closes the host's end and waits for serve to return: kOk when it had answered the end frame,
  // the channel's failure when the host stopped before it (a failed flight never hangs the test).
  Status join() {
    close_host_end();
    if (thread_.joinable()) thread_.join();
    return served_;
  }
  void close_host_end() {
    if (host_fd_ >= 0) ::shutdown(host_fd_, SHUT_RDWR);
    if (host_fd_ >= 0) ::close(host_fd_);
    host_fd_ = -1;
  }
  const hal::LinkedFlightComputer& computer() const { return *computer_; }

 private:
  std::unique_ptr<hal::LinkedFlightComputer> computer_;
  SocketChannel flight_;
  int host_fd_ = -1;
  Status served_ = Status::kHalPortMissing;
  std::thread thread_;
};

sim::BenchConfig short_flight(sim::Scenario scenario) {
  sim::BenchConfig config;
  config.scenario = scenario;
  config.duration_s = 30.0;  // 1,500 cycles: lift-off, the pitch-over, 10 s of faults from 20 s
  return config;
}

std::unique_ptr<sim::BenchResult> fly_in_process(const sim::BenchConfig& config) {
  auto result = std::make_unique<sim::BenchResult>();
  EXPECT_EQ(sim::run_bench(link_case().inputs(), config, result.get()), Status::kOk);
  return result;
}

struct SocketFlight {
  std::unique_ptr<sim::BenchResult> result = std::make_unique<sim::BenchResult>();
  Status status = Status::kHalPortMissing;
  Status served = Status::kHalPortMissing;
  std::string link_error;
  std::uint64_t allocations = 0;
};

// The same flight with the flight end behind the socket pair; counts the allocations of the flight
// (both ends of the link, every cycle), not of the preparation.
SocketFlight fly_over_socket(const sim::BenchConfig& config) {
  SocketFlight flight;
  ServedFlightEnd end;
  sim::SerialFlightLink link(end.host_fd(), 10.0);
  sim::BenchInputs inputs = link_case().inputs();
  inputs.flight = &link;
  sim::BenchSession session;
  EXPECT_EQ(session.prepare(inputs, config, flight.result.get()), Status::kOk);
  {
    AllocationScope scope;
    flight.status = session.fly();
    flight.allocations = scope.count();
  }
  flight.link_error = link.error();
  flight.served = end.join();
  return flight;
}

void expect_same_flight(const sim::BenchResult& in_process, const SocketFlight& socket) {
  const sim::BenchResult& s = *socket.result;
  EXPECT_EQ(socket.status, Status::kOk) << status_name(socket.status) << ": " << socket.link_error;
  EXPECT_EQ(socket.served, Status::kOk) << status_name(socket.served);
  EXPECT_TRUE(s.truncated);
  ASSERT_EQ(s.telemetry.size(), in_process.telemetry.size());
  EXPECT_EQ(s.telemetry.size(), 1500u);
  EXPECT_TRUE(sim::telemetry_csv(s) == sim::telemetry_csv(in_process)) << "the telemetry CSV differs";
  EXPECT_EQ(s.burnout_state, in_process.burnout_state);
  EXPECT_EQ(s.table_crc, in_process.table_crc);
  EXPECT_EQ(s.boot_status, in_process.boot_status);
  EXPECT_EQ(s.upload_status, in_process.upload_status);
  const hal::FlightCounters& a = s.flight;
  const hal::FlightCounters& b = in_process.flight;
  EXPECT_EQ(a.cycles, b.cycles);
  EXPECT_EQ(a.platform_dropouts, b.platform_dropouts);
  EXPECT_EQ(a.neutral_cycles, b.neutral_cycles);
  EXPECT_EQ(a.table_loads, b.table_loads);
  EXPECT_EQ(a.table_rejections, b.table_rejections);
  EXPECT_EQ(a.total_faults(), b.total_faults());
  EXPECT_EQ(s.sensor_link.frames_sent, in_process.sensor_link.frames_sent);
  EXPECT_EQ(s.sensor_link.frames_lost, in_process.sensor_link.frames_lost);
  EXPECT_EQ(s.sensor_link.frames_corrupt, in_process.sensor_link.frames_corrupt);
  EXPECT_EQ(s.actuator_link.frames_lost, in_process.actuator_link.frames_lost);
  EXPECT_EQ(s.actuator_link.frames_corrupt, in_process.actuator_link.frames_corrupt);
}

TEST(HilSerialLink, ServeLoopOverASocketPairGivesTheInProcessTelemetryByteForByte) {
  const sim::BenchConfig config = short_flight(sim::Scenario::kNominal);
  const auto in_process = fly_in_process(config);
  const SocketFlight socket = fly_over_socket(config);
  expect_same_flight(*in_process, socket);
  EXPECT_EQ(socket.result->flight.total_faults(), 0u);
  // Neither end of the link allocates during the flight (the serve thread included).
  EXPECT_EQ(socket.allocations, 0u);
}

// Every 50th sensor frame from 20 s lost (sent as a tick frame) or with a byte flipped (it fails
// its CRC at the flight end), and every 50th actuator frame lost or corrupted on the way back:
// detected and counted exactly as in process, the same defined reaction, the same bytes.
TEST(HilSerialLink, LostAndCorruptFramesOverASocketPairAreCountedAndFlownAsInProcess) {
  for (sim::Scenario scenario : {sim::Scenario::kLinkLoss, sim::Scenario::kLinkCorruption}) {
    SCOPED_TRACE(sim::scenario_name(scenario));
    const sim::BenchConfig config = short_flight(scenario);
    const auto in_process = fly_in_process(config);
    const SocketFlight socket = fly_over_socket(config);
    expect_same_flight(*in_process, socket);
    const sim::BenchResult& s = *socket.result;
    const std::uint32_t sensor_faults = s.sensor_link.frames_lost + s.sensor_link.frames_corrupt;
    const std::uint32_t actuator_faults = s.actuator_link.frames_lost + s.actuator_link.frames_corrupt;
    EXPECT_EQ(sensor_faults, 10u);    // cycles 1000, 1050, ..., 1450
    EXPECT_EQ(actuator_faults, 10u);  // cycles 1043, 1093, ..., 1493
    EXPECT_EQ(s.flight.platform_dropouts, sensor_faults);
    if (scenario == sim::Scenario::kLinkLoss) EXPECT_EQ(s.sensor_link.frames_corrupt, 0u);
    if (scenario == sim::Scenario::kLinkCorruption) EXPECT_EQ(s.sensor_link.frames_lost, 0u);
    EXPECT_EQ(socket.allocations, 0u);
  }
}

// The serve loop's own framing: bytes that start no frame are skipped; an upload frame that fails
// its CRC is answered kHalLinkFrameCorrupt and loads nothing, before boot and after it (the table
// in force stays); the end frame is answered with the counters and ends serve with kOk.
TEST(HilSerialLink, CorruptUploadFramesAndStrayBytesAreRejectedAndTheTableInForceStays) {
  ServedFlightEnd end;
  const LinkCase& c = link_case();
  auto exchange = [&](const std::uint8_t* bytes, std::size_t size, hal::LinkReport* report) {
    std::size_t sent = 0;
    while (sent < size) {
      const ssize_t n = ::send(end.host_fd(), bytes + sent, size - sent, MSG_NOSIGNAL);
      ASSERT_GT(n, 0);
      sent += static_cast<std::size_t>(n);
    }
    std::uint8_t reply[hal::kReplyFrameSize];
    std::size_t got = 0;
    while (got < sizeof reply) {
      const ssize_t n = ::recv(end.host_fd(), reply + got, sizeof reply - got, 0);
      ASSERT_GT(n, 0);
      got += static_cast<std::size_t>(n);
    }
    ASSERT_EQ(hal::decode_reply_frame(reply, sizeof reply, report), Status::kOk);
  };
  std::vector<std::uint8_t> frame(hal::kMaxUploadFrameSize);
  std::size_t frame_size = 0;
  ASSERT_EQ(hal::encode_upload_frame(0, c.image, sizeof c.image, frame.data(), &frame_size), Status::kOk);
  std::vector<std::uint8_t> corrupt(frame.begin(), frame.begin() + static_cast<std::ptrdiff_t>(frame_size));
  corrupt[hal::kUploadHeaderSize + 100] ^= 0x01;  // one bit of the image: the frame's CRC fails

  hal::LinkReport report;
  // Before boot: rejected, no table.
  std::vector<std::uint8_t> stray = {0x00, 0x41, 0x7E, 0x00, 0xFF};  // no frame starts here
  stray.insert(stray.end(), corrupt.begin(), corrupt.end());
  exchange(stray.data(), stray.size(), &report);
  EXPECT_EQ(report.status, Status::kHalLinkFrameCorrupt);
  EXPECT_EQ(report.sequence, 0u);
  EXPECT_EQ(report.counters.table_loads, 0u);
  // The intact frame boots the application.
  exchange(frame.data(), frame_size, &report);
  EXPECT_EQ(report.status, Status::kOk);
  EXPECT_EQ(report.counters.table_loads, 1u);
  const std::uint32_t crc = report.table_crc;
  EXPECT_EQ(crc, stored_table_crc(c.image));
  // After boot: rejected, the table in force stays.
  exchange(corrupt.data(), corrupt.size(), &report);
  EXPECT_EQ(report.status, Status::kHalLinkFrameCorrupt);
  EXPECT_EQ(report.table_crc, crc);
  EXPECT_EQ(report.counters.table_loads, 1u);
  // The end frame.
  std::uint8_t end_frame[hal::kShortFrameSize];
  hal::encode_short_frame(hal::kEndFrameType, 0, end_frame);
  exchange(end_frame, sizeof end_frame, &report);
  EXPECT_EQ(report.status, Status::kOk);
  EXPECT_EQ(end.join(), Status::kOk);
}

}  // namespace
}  // namespace tolip::test
