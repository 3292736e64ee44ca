#!/usr/bin/env bash
# Static analysis of fsw_core (issue 14; docs/verification/static-analysis.md): clang-tidy with the
# checked-in .clang-tidy and cppcheck with tests/static_analysis/cppcheck-suppressions.txt, over
# every source of fsw_core/src (and, through them, the headers of fsw_core/include). Prints each
# finding as file:line: tool: check: message and the counts; exits 1 when there is any finding.
#
#   scripts/static_analysis.sh [--build DIR] [--only clang-tidy|cppcheck] [--sources DIR] [--ground]
#
# DIR is a configured build directory holding compile_commands.json (every build directory does:
# CMAKE_EXPORT_COMPILE_COMMANDS is on); default build/. --sources replaces fsw_core/src (the
# canary uses it). --only makes the other tool's count 0. --ground analyses the ground side
# instead (ground_tools/src and hal_sim/src) with clang-tidy alone and its bug-class rule set,
# tests/static_analysis/ground.clang-tidy (docs/verification/static-analysis.md, "The ground side"). Exit 77 when a tool is missing (the CTest skips; scripts/lib/deps.sh installs
# clang-tidy and cppcheck).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build="$root/build"
only=""
sources=("$root/fsw_core/src")
config="$root/.clang-tidy"
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build=$2; shift 2 ;;
    --only) only=$2; shift 2 ;;
    --sources) sources=("$2"); shift 2 ;;
    --ground)
      sources=("$root/ground_tools/src" "$root/hal_sim/src")
      config="$root/tests/static_analysis/ground.clang-tidy"
      only=clang-tidy
      shift ;;
    *) echo "usage: $0 [--build DIR] [--only clang-tidy|cppcheck] [--sources DIR] [--ground]" >&2; exit 2 ;;
  esac
done
tidy=$(command -v clang-tidy-14 || command -v clang-tidy || true)
cppcheck=$(command -v cppcheck || true)
if [[ ( -z "$tidy" && "$only" != cppcheck ) || ( -z "$cppcheck" && "$only" != clang-tidy ) ]]; then
  echo "static_analysis.sh: SKIPPED: clang-tidy or cppcheck not installed (apt-get install clang-tidy cppcheck)"
  exit 77
fi
[[ -f "$build/compile_commands.json" ]] || { echo "static_analysis.sh: no $build/compile_commands.json: configure first" >&2; exit 2; }
mapfile -t files < <(find "${sources[@]}" -name '*.cpp' | sort)
[[ ${#files[@]} -gt 0 ]] || { echo "static_analysis.sh: no source under ${sources[*]}" >&2; exit 2; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# clang-tidy reads the compile database without GCC's link-time optimization flags (the fat LTO
# objects of a host Release build, CMakeLists.txt TOLIP_LTO): clang 14 rejects -ffat-lto-objects.
mkdir -p "$scratch/db"
sed -E 's/ -flto(=[a-z0-9]+)?//g; s/ -f(no-)?fat-lto-objects//g' "$build/compile_commands.json" \
  > "$scratch/db/compile_commands.json"
tidy_count=0
cppcheck_count=0

if [[ "$only" != cppcheck ]]; then
  # One clang-tidy per file, two at a time (a file outside the compile database, the canary's,
  # gets the flags of the nearest file in it).
  printf '%s\n' "${files[@]}" | xargs -P 2 -I{} sh -c \
    '"$1" -p "$2" --quiet --config-file="$3" "$4" 2>/dev/null' \
    _ "$tidy" "$scratch/db" "$config" {} > "$scratch/tidy.txt" || true
  grep -E '^[^ ]+:[0-9]+:[0-9]+: (warning|error): ' "$scratch/tidy.txt" \
    | sed -E "s#^$root/##; s#^([^:]+:[0-9]+):[0-9]+: (warning|error): (.*) \[([^],]+)[^]]*\]\$#\1: clang-tidy: \4: \3#" \
    | sort -u > "$scratch/tidy-findings.txt" || true
  tidy_count=$(wc -l < "$scratch/tidy-findings.txt")
  cat "$scratch/tidy-findings.txt"
fi

if [[ "$only" != clang-tidy ]]; then
  # cppcheck 2.10: warnings, style, performance and portability; the rules left out are listed,
  # with the reason, in the suppressions file; a finding kept on purpose carries an inline
  # "cppcheck-suppress id" with its reason beside it.
  "$cppcheck" --enable=warning,style,performance,portability --std=c++20 --language=c++ \
    --inline-suppr --suppressions-list="$root/tests/static_analysis/cppcheck-suppressions.txt" \
    -I "$root/fsw_core/include" -D__GNUC__ -j 2 --quiet \
    --template='{file}:{line}: cppcheck: {id}: {message}' "${files[@]}" 2> "$scratch/cppcheck.txt" || true
  sed -E "s#^$root/##" "$scratch/cppcheck.txt" | grep -E '^[^ ]+:[0-9]+: cppcheck: ' | sort -u > "$scratch/cppcheck-findings.txt" || true
  cppcheck_count=$(wc -l < "$scratch/cppcheck-findings.txt")
  cat "$scratch/cppcheck-findings.txt"
fi

total=$((tidy_count + cppcheck_count))
echo "static_analysis.sh: ${#files[@]} files: clang-tidy ${tidy_count}, cppcheck ${cppcheck_count} finding(s)"
[[ $total -eq 0 ]]
