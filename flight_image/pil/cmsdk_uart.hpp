// Polled driver of the ARM CMSDK APB UART (Cortex-M System Design Kit TRM, ARM DDI0479C), UART0 of
// the MPS2 AN500 board at 0x40004000 as qemu-system-arm -M mps2-an500 models it (hw/char/
// cmsdk-apb-uart.c; docs/target.md, "Processor in the loop"). It is the guidance computer's link
// to the plant: a hal::ByteChannel for LinkedFlightComputer::serve. No interrupts: the image does
// nothing but serve the link, so it polls the status register.
#pragma once

#include <cstddef>
#include <cstdint>

#include "tolip/core/status.hpp"
#include "tolip/hal/linked_flight_computer.hpp"

namespace tolip::target {

inline constexpr std::uintptr_t kUart0Base = 0x40004000u;
inline constexpr std::uint32_t kApbClockHz = 25000000u;  // the AN500's peripheral clock (25 MHz)

struct CmsdkUart {
  std::uintptr_t base = kUart0Base;
  std::uint32_t rx_overruns = 0;  // bytes the receiver lost (the frame CRC then rejects the frame)
};

// Sets the baud-rate divider (the APB clock over the rate; at least 16) and enables the
// transmitter and the receiver, interrupts off.
void uart_init(CmsdkUart* uart, std::uint32_t baud);
// Blocks until a byte arrived.
Status uart_read(void* uart, std::uint8_t* byte);
// Blocks until every byte went into the transmit buffer.
Status uart_write(void* uart, const std::uint8_t* bytes, std::size_t size);
hal::ByteChannel uart_channel(CmsdkUart* uart);

}  // namespace tolip::target
