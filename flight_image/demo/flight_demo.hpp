// The flight demo program shared by the host build and the Cortex-M7 image (flight_demo.cpp).
#pragma once

namespace tolip::flight {

// Runs the demo, writing through console_write(). Returns 0 when every step succeeded.
int run_flight_demo();

}  // namespace tolip::flight
