#!/usr/bin/env bash
# Canary for StaticAnalysis_CoreIsCleanUnderClangTidyAndCppcheck: scripts/static_analysis.sh must
# flag a source that breaks the rule set (recursion, malloc, a C-style cast, an implicit narrowing,
# a variable read before it is written, a body on its own line without braces), or the clean result
# could mean that nothing was checked.
# The source is written to a scratch folder; the build directory lends its compile database.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=$1
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cat > "$scratch/canary.cpp" <<'CPP'
#include <cstdlib>
int depth(int n) { return n <= 0 ? 0 : 1 + depth(n - 1); }
int* buffer() { return (int*)std::malloc(16); }
int narrow(double x) {
  int unset;
  int y = x;
  return y + unset;
}
int unbraced(int x) {
  if (x > 0)
    return 1;
  return 0;
}
CPP
set +e
bash "$root/scripts/static_analysis.sh" --build "$build" --sources "$scratch" | tee "$scratch/out.txt"
status=${PIPESTATUS[0]}
set -e
if [[ $status -eq 77 ]]; then exit 77; fi
if [[ $status -eq 0 ]]; then
  echo "canary: static_analysis.sh passed a source that breaks the rule set" >&2
  exit 1
fi
if ! grep -q 'clang-tidy: readability-braces-around-statements: ' "$scratch/out.txt"; then
  echo "canary: static_analysis.sh did not flag the unbraced body" >&2
  exit 1
fi
