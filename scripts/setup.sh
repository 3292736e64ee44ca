#!/usr/bin/env bash
# Sets up a fresh Debian 12 machine and runs the main job on the bundled example.
#
#   1. installs the Debian packages the build needs (only those missing; apt-get via sudo when
#      not root),
#   2. configures a Release build in build/ and builds, with two jobs, only what the main job
#      needs: the `tolip` program (scripts/test.sh builds the tests, benchmarks and flight demo),
#   3. runs the main job: `tolip optimize` on examples/scout/mission.toml (the Scout-class
#      maximum-payload case from its crude initial pitch program), which prints the iteration
#      history, the optimized trajectory and the summary (exit 0 when it converges).
#
# Safe to run again: installed packages are skipped and the build is incremental.
set -euo pipefail

ROOT_DIR=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# shellcheck source=scripts/lib/deps.sh
source "$ROOT_DIR/scripts/lib/deps.sh"

cd "$ROOT_DIR"
# The build folder; TOLIP_BUILD_DIR overrides it (e.g. to keep a second build side by side).
BUILD_DIR=${TOLIP_BUILD_DIR:-$ROOT_DIR/build}
tolip_ensure_packages
tolip_configure_and_build "$ROOT_DIR" "$BUILD_DIR" tolip

echo "-- running: tolip optimize examples/scout/mission.toml"
exec "$BUILD_DIR/ground_tools/tolip" optimize examples/scout/mission.toml
