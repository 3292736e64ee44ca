// Start-up code of the bare-metal Cortex-M7 flight image (MPS2 AN500 under QEMU):
// the vector table, the reset handler (FPU on, .data copied, .bss and .psram_bss zeroed, stack
// painted, constructors run), the fault handlers, and the C++ run-time hooks a program without exit needs.
// Memory map and sections: linker/cortex_m7_mps2_an500.ld. There is no heap.
#include <cstdint>

#include "cortex_m7/semihosting.hpp"
#include "demo/text_line.hpp"

extern "C" {
// Linker-script symbols.
extern std::uint32_t __data_load[];
extern std::uint32_t __data_start[];
extern std::uint32_t __data_end[];
extern std::uint32_t __bss_start[];
extern std::uint32_t __bss_end[];
extern std::uint32_t __psram_bss_start[];
extern std::uint32_t __psram_bss_end[];
extern std::uint32_t __stack_limit[];
extern std::uint32_t __stack_top[];
extern void (*__init_array_start[])();
extern void (*__init_array_end[])();

int tolip_target_main();
void Reset_Handler();
void tolip_reset_continue();
void Default_Handler();
void HardFault_Handler();
}

namespace {

constexpr std::uint32_t kStackPaint = 0xDEADBEEFu;

// Fills the unused stack with a pattern, up to a margin below the current stack pointer.
void paint_stack() {
  std::uint32_t* sp;
  asm volatile("mov %0, sp" : "=r"(sp));
  for (std::uint32_t* p = __stack_limit; p < sp - 64; ++p) *p = kStackPaint;
}

}  // namespace

namespace tolip::target {

// Bytes of stack ever used: from the top down to the lowest word that is no longer the paint.
std::uint32_t stack_high_water_bytes() {
  const std::uint32_t* p = __stack_limit;
  while (p < __stack_top && *p == kStackPaint) ++p;
  return static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(__stack_top) -
                                    reinterpret_cast<std::uintptr_t>(p));
}

std::uint32_t stack_size_bytes() {
  return static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(__stack_top) -
                                    reinterpret_cast<std::uintptr_t>(__stack_limit));
}

}  // namespace tolip::target

// The vector table: initial stack pointer, reset, NMI, HardFault, MemManage, BusFault, UsageFault,
// 4 reserved, SVCall, DebugMonitor, reserved, PendSV, SysTick. No peripheral interrupt is used.
__attribute__((section(".vectors"), used)) void (*const g_vector_table[16])() = {
    reinterpret_cast<void (*)()>(__stack_top),
    Reset_Handler,
    Default_Handler,
    HardFault_Handler,
    HardFault_Handler,
    HardFault_Handler,
    HardFault_Handler,
    nullptr,
    nullptr,
    nullptr,
    nullptr,
    Default_Handler,
    Default_Handler,
    nullptr,
    Default_Handler,
    Default_Handler,
};

// The FPU (CP10, CP11) must be enabled before any floating-point instruction, and the compiler may
// use FP registers anywhere in C++ code: the first instructions are assembly.
extern "C" __attribute__((naked, noreturn)) void Reset_Handler() {
  asm volatile(
      "ldr r0, =0xE000ED88 \n"  // CPACR
      "ldr r1, [r0]        \n"
      "orr r1, r1, #0xF00000 \n"  // CP10, CP11 full access
      "str r1, [r0]        \n"
      "dsb                 \n"
      "isb                 \n"
      "b tolip_reset_continue \n");
}

extern "C" __attribute__((noreturn, used)) void tolip_reset_continue() {
  const std::uint32_t* from = __data_load;
  for (std::uint32_t* to = __data_start; to < __data_end;) *to++ = *from++;
  for (std::uint32_t* p = __bss_start; p < __bss_end; ++p) *p = 0u;
  for (std::uint32_t* p = __psram_bss_start; p < __psram_bss_end; ++p) *p = 0u;
  paint_stack();
  for (void (**constructor)() = __init_array_start; constructor < __init_array_end; ++constructor)
    (*constructor)();
  const int code = tolip_target_main();
  tolip::target::semihosting_exit(code);
}

extern "C" void Default_Handler() {
  tolip::flight::TextLine line;
  line.text("TARGET unexpected exception");
  line.emit();
  tolip::target::semihosting_exit(3);
}

extern "C" void HardFault_Handler() {
  tolip::flight::TextLine line;
  line.text("TARGET hard fault");
  line.emit();
  tolip::target::semihosting_exit(2);
}

// C++ run-time hooks. The image never returns from main, so static destructors are never run:
// registering one does nothing (this also keeps newlib's atexit machinery out of the image).
extern "C" {
void* __dso_handle = nullptr;
int __aeabi_atexit(void*, void (*)(void*), void*) { return 0; }
int __cxa_atexit(void (*)(void*), void*, void*) { return 0; }
void __cxa_pure_virtual() { tolip::target::semihosting_exit(4); }
}
