#!/usr/bin/env bash
# The host suite under AddressSanitizer + UndefinedBehaviorSanitizer (issue 14;
# docs/verification/sanitizers.md): configures and builds the asan preset (GCC, build-asan/) and
# runs ctest --preset asan (the host suite without the clean-clone check; any sanitizer report
# fails its test). CI's second step (.ci/run runs scripts/test.sh, then this). Installs missing
# Debian packages first (scripts/lib/deps.sh). Extra arguments go to ctest (e.g. -R Sec4).
# Prints the wall time of the build and of the suite. Exits non-zero on any failure.
set -euo pipefail

ROOT_DIR=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# shellcheck source=scripts/lib/deps.sh
source "$ROOT_DIR/scripts/lib/deps.sh"

cd "$ROOT_DIR"
tolip_ensure_packages
start=$(date +%s)
cmake --preset asan
cmake --build --preset asan
built=$(date +%s)
ctest --preset asan "$@"
done_at=$(date +%s)
echo "sanitizers.sh: asan build $((built - start)) s, asan suite $((done_at - built)) s"
