#!/usr/bin/env bash
# Fails when a test binary holds code of the ground library (tolip::ground::, ground_tools/):
# the core and noalloc binaries test the core without the deck reader, the reports or the
# commands (issue 18 item 7). Run on the ground test binary it must flag it (the canary).
#
#   check_no_ground_code.sh NM BINARY...
set -euo pipefail
nm=${1:?usage: check_no_ground_code.sh NM BINARY...}
shift
[[ $# -gt 0 ]] || { echo "usage: check_no_ground_code.sh NM BINARY..." >&2; exit 2; }
found=0
for binary in "$@"; do
  symbols=$("$nm" -C --defined-only "$binary")
  if grep -q 'tolip::ground::' <<< "$symbols"; then
    echo "holds ground code: $binary, e.g. $(grep -m 1 'tolip::ground::' <<< "$symbols" | cut -c1-160)"
    found=$((found + 1))
  fi
done
if [[ $found -gt 0 ]]; then exit 1; fi
echo "no ground code in $# binaries"
