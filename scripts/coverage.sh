#!/usr/bin/env bash
# Structural coverage of fsw_core (issue 14; docs/verification/coverage.md): configures and builds
# the coverage preset (fsw_core alone instrumented by gcov), runs the host test suite without the
# clean-clone check, and measures the core's line and branch coverage with gcovr:
#   build-coverage/coverage/index.html     per file and line (HTML)
#   build-coverage/coverage/summary.txt    per file, lines (text); stdout: the totals
#   build-coverage/coverage/branches.txt   per file, branches (text)
#   build-coverage/coverage/summary.json   totals and per file (gcovr --json-summary)
#   build-coverage/coverage/functions.txt  functions never called (gcov's function counts)
#   build-coverage/coverage/gaps.txt       the branches never taken, by kind (scripts/coverage_gaps.py)
#
#   scripts/coverage.sh [--build DIR [--restore]] [CTEST ARGUMENTS...]
#
# --build DIR instruments an existing Release build directory instead (only fsw_core recompiles,
# the rest relinks); --restore turns the instrumentation off again afterwards. Extra arguments go
# to ctest (e.g. -R 'Sec4|Sec5' for a part of the suite). Needs gcovr (Debian package gcovr;
# scripts/lib/deps.sh). Runs with nice and two jobs.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build="$root/build-coverage"
restore=0
preset=1
if [[ "${1:-}" == "--build" ]]; then
  build=$(cd "$2" && pwd); preset=0; shift 2
  if [[ "${1:-}" == "--restore" ]]; then restore=1; shift; fi
fi
out="$build/coverage"
command -v gcovr >/dev/null || { echo "coverage.sh: gcovr not found (apt-get install gcovr)" >&2; exit 1; }
cd "$root"
if [[ $preset -eq 1 ]]; then
  nice -n 10 cmake --preset coverage >/dev/null
else
  nice -n 10 cmake -S "$root" -B "$build" -DTOLIP_COVERAGE=ON >/dev/null
fi
nice -n 10 cmake --build "$build" -j2
find "$build" -name '*.gcda' -delete
nice -n 10 ctest --test-dir "$build" -j2 -LE clean-clone --timeout 1800 "$@" \
  || echo "coverage.sh: some tests failed; coverage measured anyway" >&2
rm -rf "$out" && mkdir -p "$out"
# Branches: those the compiler adds for exception handling are left out (the core has none, and
# -fno-exceptions), and so are those gcov marks unreachable.
common=(--root "$root" --object-directory "$build" --filter "$root/fsw_core/"
        --exclude-unreachable-branches --exclude-throw-branches -j 2)
nice -n 10 gcovr "${common[@]}" --txt "$out/summary.txt" --html-details "$out/index.html" \
  --json-summary-pretty --json-summary "$out/summary.json" --json "$out/coverage.json" --print-summary
nice -n 10 gcovr "${common[@]}" --branches --txt "$out/branches.txt" >/dev/null
python3 - "$out/coverage.json" "$root" > "$out/functions.txt" <<'PY'
import json, sys
data = json.load(open(sys.argv[1]))
for f in sorted(data["files"], key=lambda f: f["file"]):
    for fn in f.get("functions", []):
        if fn.get("execution_count", 0) == 0:
            print(f"{f['file']}:{fn.get('lineno', 0)}: {fn.get('name', '?')}")
PY
echo "coverage.sh: $(wc -l < "$out/functions.txt") core functions never called ($out/functions.txt)"
python3 "$root/scripts/coverage_gaps.py" "$out/coverage.json" > "$out/gaps.txt"
echo "coverage.sh: $(head -1 "$out/gaps.txt") ($out/gaps.txt)"
if [[ $restore -eq 1 ]]; then
  nice -n 10 cmake -S "$root" -B "$build" -DTOLIP_COVERAGE=OFF >/dev/null
  nice -n 10 cmake --build "$build" -j2 >/dev/null
  echo "coverage.sh: $build is a plain Release build again"
fi
