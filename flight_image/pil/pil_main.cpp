// The processor-in-the-loop flight image (docs/hil.md, "Processor in the loop"; docs/target.md):
// the flight application (fsw_core hal::FlightApplication) behind the frame link, served over
// UART0 of the mps2-an500 in lock-step with the host's plant (`tolip hil --target qemu`). It waits
// for the table upload, then runs one minor cycle per sensor frame and answers each with the
// actuator and telemetry frames, until the end frame; then it prints one line through
// semihosting and exits 0 (1 if the link failed).
#include <cstdint>

#include "demo/text_line.hpp"
#include "pil/cmsdk_uart.hpp"
#include "tolip/hal/hal.hpp"
#include "tolip/hal/linked_flight_computer.hpp"

namespace tolip::target {
std::uint32_t stack_high_water_bytes();
std::uint32_t stack_size_bytes();
}  // namespace tolip::target

namespace {

// The minor-cycle rate of the image: the bench's default, 50 Hz (`tolip hil --target qemu`
// requires --rate-hz 50).
constexpr double kPeriodS = 1.0 / tolip::hal::kDefaultMinorCycleHz;
constexpr std::uint32_t kBaud = 115200u;  // QEMU does not pace the bytes; the divider is the board's

tolip::hal::LinkedFlightComputer g_computer(kPeriodS);
tolip::target::CmsdkUart g_uart;

}  // namespace

extern "C" int tolip_target_main() {
  tolip::target::uart_init(&g_uart, kBaud);
  const tolip::Status status = g_computer.serve(tolip::target::uart_channel(&g_uart));
  tolip::flight::TextLine line;
  line.text("PIL END ").text(tolip::status_name(status)).text(" cycles ");
  line.integer(g_computer.application().counters().cycles).text(" rx overruns ").integer(g_uart.rx_overruns);
  line.text(" stack high-water ").integer(tolip::target::stack_high_water_bytes()).text(" bytes of ");
  line.integer(tolip::target::stack_size_bytes());
  line.emit();
  return tolip::ok(status) ? 0 : 1;
}
