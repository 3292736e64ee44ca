#!/usr/bin/env bash
# The canary of Repository_SelfContainedCheckRejectsOutsidePaths: writes a CMakeLists.txt that
# reaches for the customer's folder beside the project into a new temporary folder (assembled
# here, so that no file of the repository holds such a path) and runs the check on it, which must
# flag it.
set -euo pipefail
dir=$(mktemp -d "${TMPDIR:-/tmp}/tolip-self-contained-canary.XXXXXX")
trap 'rm -rf "$dir"' EXIT
printf 'set(REFERENCE "${CMAKE_CURRENT_SOURCE_DIR}/%s/%s/reference")\n' ".." "shared" > "$dir/CMakeLists.txt"
bash "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/check_self_contained.sh" "$dir"
