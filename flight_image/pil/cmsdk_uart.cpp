// Polled CMSDK APB UART driver (cmsdk_uart.hpp).
#include "pil/cmsdk_uart.hpp"

namespace tolip::target {
namespace {

// Register offsets and bits (DDI0479C, 4.3).
constexpr std::uintptr_t kData = 0x00;
constexpr std::uintptr_t kState = 0x04;  // bit 0 TX buffer full, 1 RX buffer full, 2 TX overrun, 3 RX overrun
constexpr std::uintptr_t kCtrl = 0x08;   // bit 0 TX enable, 1 RX enable, 2-5 interrupt enables
constexpr std::uintptr_t kBaudDiv = 0x10;
constexpr std::uint32_t kTxFull = 1u << 0;
constexpr std::uint32_t kRxFull = 1u << 1;
constexpr std::uint32_t kRxOverrun = 1u << 3;
constexpr std::uint32_t kTxEnable = 1u << 0;
constexpr std::uint32_t kRxEnable = 1u << 1;

volatile std::uint32_t& reg(const CmsdkUart& uart, std::uintptr_t offset) {
  return *reinterpret_cast<volatile std::uint32_t*>(uart.base + offset);
}

}  // namespace

void uart_init(CmsdkUart* uart, std::uint32_t baud) {
  std::uint32_t divider = baud > 0 ? kApbClockHz / baud : 16u;
  if (divider < 16u) divider = 16u;
  reg(*uart, kCtrl) = 0u;
  reg(*uart, kBaudDiv) = divider;
  reg(*uart, kState) = kRxOverrun | (1u << 2);  // clear both overrun flags (write one to clear)
  reg(*uart, kCtrl) = kTxEnable | kRxEnable;
}

Status uart_read(void* context, std::uint8_t* byte) {
  CmsdkUart& uart = *static_cast<CmsdkUart*>(context);
  std::uint32_t state;
  while (((state = reg(uart, kState)) & kRxFull) == 0u) {
  }
  if ((state & kRxOverrun) != 0u) {
    ++uart.rx_overruns;
    reg(uart, kState) = kRxOverrun;
  }
  *byte = static_cast<std::uint8_t>(reg(uart, kData) & 0xFFu);
  return Status::kOk;
}

Status uart_write(void* context, const std::uint8_t* bytes, std::size_t size) {
  CmsdkUart& uart = *static_cast<CmsdkUart*>(context);
  for (std::size_t i = 0; i < size; ++i) {
    while ((reg(uart, kState) & kTxFull) != 0u) {
    }
    reg(uart, kData) = bytes[i];
  }
  return Status::kOk;
}

hal::ByteChannel uart_channel(CmsdkUart* uart) { return hal::ByteChannel{uart, uart_read, uart_write}; }

}  // namespace tolip::target
