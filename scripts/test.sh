#!/usr/bin/env bash
# Builds the project (Release, build/) and runs the whole test suite with CTest, then the
# bare-metal Cortex-M7 check (cross build in build-cortex-m7/, QEMU run, host comparison).
# Installs missing Debian packages first (see scripts/lib/deps.sh). Extra arguments go to ctest
# (e.g. scripts/test.sh -R Atmosphere). Exits non-zero on any failure.
set -euo pipefail

ROOT_DIR=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# shellcheck source=scripts/lib/deps.sh
source "$ROOT_DIR/scripts/lib/deps.sh"

cd "$ROOT_DIR"
# The build folder; TOLIP_BUILD_DIR overrides it (e.g. to keep a second build side by side).
BUILD_DIR=${TOLIP_BUILD_DIR:-$ROOT_DIR/build}
tolip_ensure_packages
tolip_configure_and_build "$ROOT_DIR" "$BUILD_DIR"
ctest --test-dir "$BUILD_DIR" --output-on-failure -j2 "$@"

# The bare-metal Cortex-M7 target (docs/target.md): cross build of the core and the flight image
# into build-cortex-m7/, then the QEMU run and its comparison with the host program. The host
# tools and the host flight demo come from the host build above.
cmake --preset cortex-m7 -DTOLIP_HOST_BUILD_DIR="$(cd "$BUILD_DIR" && pwd)"
cmake --build --preset cortex-m7
ctest --preset cortex-m7
