# CMake toolchain file: bare-metal ARM Cortex-M7 with the double-precision FPU (FPv5-D16), hard
# float ABI, Debian's arm-none-eabi GCC and newlib. Used by the `cortex-m7` configure preset
# (CMakePresets.json); docs/target.md describes the target build.
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(TOLIP_CROSS_PREFIX arm-none-eabi- CACHE STRING "Prefix of the cross tools")
set(CMAKE_C_COMPILER ${TOLIP_CROSS_PREFIX}gcc)
set(CMAKE_CXX_COMPILER ${TOLIP_CROSS_PREFIX}g++)
set(CMAKE_ASM_COMPILER ${TOLIP_CROSS_PREFIX}gcc)
set(CMAKE_AR ${TOLIP_CROSS_PREFIX}ar CACHE FILEPATH "")
set(CMAKE_RANLIB ${TOLIP_CROSS_PREFIX}ranlib CACHE FILEPATH "")
set(CMAKE_NM ${TOLIP_CROSS_PREFIX}nm CACHE FILEPATH "")
set(CMAKE_OBJCOPY ${TOLIP_CROSS_PREFIX}objcopy CACHE FILEPATH "")
set(CMAKE_SIZE ${TOLIP_CROSS_PREFIX}size CACHE FILEPATH "")
set(CMAKE_OBJDUMP ${TOLIP_CROSS_PREFIX}objdump CACHE FILEPATH "")

# No start files or system library can link a test program before ours exist.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

# Cortex-M7, Thumb-2, double-precision FPU, hard-float calling convention. Floating-point
# contraction off (as on the host), so no fused multiply-add changes a result. Every function in
# its own section (the linker drops what is unused). -fstack-usage and -fcallgraph-info=su write
# the per-function stack usage and the call graph next to each object for the stack report.
set(TOLIP_TARGET_FLAGS
    "-mcpu=cortex-m7 -mthumb -mfpu=fpv5-d16 -mfloat-abi=hard -ffp-contract=off -ffunction-sections -fdata-sections -fstack-usage -fcallgraph-info=su")
#
# EIGEN_ALLOCA: on Linux hosts Eigen finds alloca and builds the temporaries of its blocked
# triangular solves and products (used by the optimizer) on the stack; newlib gives it no alloca,
# so without this Eigen falls back to aligned_malloc and the core would reference malloc/free on
# the target only. With it the target code matches the host's (the heap branch is compiled out for
# the core's fixed sizes; the freestanding check in flight_image/ proves it).
string(APPEND TOLIP_TARGET_FLAGS " -DEIGEN_ALLOCA=__builtin_alloca")
set(CMAKE_C_FLAGS_INIT "${TOLIP_TARGET_FLAGS}")
set(CMAKE_CXX_FLAGS_INIT "${TOLIP_TARGET_FLAGS} -fno-exceptions -fno-rtti -fno-threadsafe-statics")
set(CMAKE_ASM_FLAGS_INIT "${TOLIP_TARGET_FLAGS}")

# Programs (the host's cmake, python) from the host; headers may come from the host too (Eigen is
# header-only and target-independent); libraries only from the cross toolchain.
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE BOTH)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)
