// ARM semihosting (the debugger / QEMU services reached by BKPT 0xAB in Thumb state): just the
// three operations the flight image needs. Implemented here instead of newlib's rdimon library so
// that no stdio, no printf and no allocator is linked (docs/target.md).
#pragma once

#include <cstddef>

namespace tolip::target {

// SYS_OPEN ":tt" for writing, then SYS_WRITE; returns false when the host refused.
bool semihosting_write(const char* text, std::size_t length);

// SYS_EXIT: ADP_Stopped_ApplicationExit for code 0 (QEMU exits 0), ADP_Stopped_RunTimeErrorUnknown
// otherwise (QEMU exits 1). Does not return.
[[noreturn]] void semihosting_exit(int code);

}  // namespace tolip::target
