// The entry point of the Cortex-M7 flight image (called by the start-up code; ISO C++ forbids calling main):
// the flight demo, then the measured stack high-water mark
// ("TARGET" lines are target-only; the host prints none). Also the optimizer's workspace, in the
// PSRAM.
#include <cstdint>

#include "demo/flight_demo.hpp"
#include "demo/text_line.hpp"
#include "demo/workspace.hpp"

namespace tolip::flight {

// 1.1 MiB: in the board's 16 MiB PSRAM at 0x60000000 rather than the 4 MiB SSRAM2/3 that holds
// the flight data and the stack. ".bss." makes it a zero-filled (NOBITS) section; the linker script
// places it in PSRAM and the start-up code zeroes it before the constructors run.
namespace {
__attribute__((section(".bss.psram"))) OptimizerWorkspace g_optimizer_workspace;
}  // namespace

OptimizerWorkspace* optimizer_workspace() { return &g_optimizer_workspace; }

}  // namespace tolip::flight

namespace tolip::target {
std::uint32_t stack_high_water_bytes();
std::uint32_t stack_size_bytes();
}  // namespace tolip::target

extern "C" const unsigned char tolip_pitch_table[];

extern "C" int tolip_target_main() {
  const int code = tolip::flight::run_flight_demo();
  tolip::flight::TextLine line;
  line.text("TARGET table image at ")
      .hex32(static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(tolip_pitch_table)));
  line.emit();
  line.text("TARGET stack high-water ").integer(tolip::target::stack_high_water_bytes()).text(" bytes of ");
  line.integer(tolip::target::stack_size_bytes());
  line.emit();
  return code;
}
