// The flight demo's only output channel: one function, defined per platform (host: stdout;
// Cortex-M7: semihosting SYS_WRITE). No stdio, no printf, no allocation on the output path.
#pragma once

#include <cstddef>

namespace tolip::flight {

void console_write(const char* text, std::size_t length);

}  // namespace tolip::flight
