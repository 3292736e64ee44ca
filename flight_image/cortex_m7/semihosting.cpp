// ARM semihosting calls (semihosting.hpp).
#include "cortex_m7/semihosting.hpp"

#include <cstdint>

#include "demo/console.hpp"

namespace tolip::target {
namespace {

constexpr int kSysOpen = 0x01;
constexpr int kSysWrite = 0x05;
constexpr int kSysExit = 0x18;
constexpr std::uintptr_t kAdpStoppedApplicationExit = 0x20026;
constexpr std::uintptr_t kAdpStoppedRunTimeErrorUnknown = 0x20023;

int semihosting_call(int operation, const void* argument) {
  register int r0 asm("r0") = operation;
  register const void* r1 asm("r1") = argument;
  asm volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
  return r0;
}

int g_console_handle = -1;

}  // namespace

bool semihosting_write(const char* text, std::size_t length) {
  if (g_console_handle < 0) {
    static const char kConsole[] = ":tt";
    const std::uintptr_t open_block[3] = {reinterpret_cast<std::uintptr_t>(kConsole), 4u /* "w" */, 3u};
    g_console_handle = semihosting_call(kSysOpen, open_block);
    if (g_console_handle < 0) return false;
  }
  const std::uintptr_t write_block[3] = {static_cast<std::uintptr_t>(g_console_handle),
                                         reinterpret_cast<std::uintptr_t>(text), length};
  return semihosting_call(kSysWrite, write_block) == 0;  // returns the number of bytes NOT written
}

void semihosting_exit(int code) {
  const std::uintptr_t reason = code == 0 ? kAdpStoppedApplicationExit : kAdpStoppedRunTimeErrorUnknown;
  semihosting_call(kSysExit, reinterpret_cast<const void*>(reason));
  for (;;) {
    asm volatile("wfi");
  }
}

}  // namespace tolip::target

namespace tolip::flight {

void console_write(const char* text, std::size_t length) { tolip::target::semihosting_write(text, length); }

}  // namespace tolip::flight
