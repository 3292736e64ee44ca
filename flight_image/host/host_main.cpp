// The flight demo on the host: console_write() is stdout. Same program, same output bytes as the
// Cortex-M7 image under QEMU (flight_image/CMakeLists.txt compares them).
#include <cstdio>

#include "demo/console.hpp"
#include "demo/flight_demo.hpp"
#include "demo/workspace.hpp"

namespace tolip::flight {

void console_write(const char* text, std::size_t length) { std::fwrite(text, 1, length, stdout); }

OptimizerWorkspace* optimizer_workspace() {
  static OptimizerWorkspace workspace;
  return &workspace;
}

}  // namespace tolip::flight

int main() {
  const int code = tolip::flight::run_flight_demo();
  std::fflush(stdout);
  return code;
}
