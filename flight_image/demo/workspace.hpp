// The optimizer's workspace (OptimizerWorkspace, about 1.1 MiB): one function, defined per
// platform, like the console. Host (host/host_main.cpp): a static object. Cortex-M7
// (cortex_m7/target_main.cpp): a static object in the board's 16 MiB PSRAM (section .bss.psram,
// linker/cortex_m7_mps2_an500.ld; docs/target.md gives the memory map). Nothing allocates.
#pragma once

#include "tolip/optimizer/steepest_descent.hpp"

namespace tolip::flight {

OptimizerWorkspace* optimizer_workspace();

}  // namespace tolip::flight
