#!/usr/bin/env bash
# Formats the repository's C++ sources with clang-format and the checked-in .clang-format.
#
#   scripts/format.sh            rewrite every tracked *.cpp, *.hpp, *.h in place
#   scripts/format.sh --check    change nothing; list the files that differ, exit 1 if any
#   scripts/format.sh [--check] FILE...   the same for the named files only
#
# CLANG_FORMAT names the program (default clang-format; Debian package clang-format).
# tests/reference/ is imported data and is never formatted.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
clang_format=${CLANG_FORMAT:-clang-format}
command -v "$clang_format" >/dev/null || { echo "format.sh: $clang_format not found (apt-get install clang-format)" >&2; exit 2; }

check=no
if [[ "${1:-}" == "--check" ]]; then check=yes; shift; fi
if [[ $# -gt 0 ]]; then
  files=("$@")
else
  if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    mapfile -t files < <(git ls-files -- '*.cpp' '*.hpp' '*.h' | grep -v '^tests/reference/')
  else  # a copy without git (the clean-clone check): the same files, minus build folders
    mapfile -t files < <(find . \( -path './build*' -o -path './tests/reference' -o -path './.git' \) -prune \
                           -o -type f \( -name '*.cpp' -o -name '*.hpp' -o -name '*.h' \) -print | sed 's|^\./||' | sort)
  fi
fi

if [[ $check == no ]]; then
  "$clang_format" -i --style=file "${files[@]}"
  exit 0
fi
differ=0
for f in "${files[@]}"; do
  if ! "$clang_format" --style=file --dry-run --Werror "$f" >/dev/null 2>&1; then
    echo "not formatted: $f"
    differ=$((differ + 1))
  fi
done
if [[ $differ -gt 0 ]]; then
  echo "format.sh --check: $differ of ${#files[@]} file(s) differ from .clang-format (run scripts/format.sh)"
  exit 1
fi
echo "format.sh --check: ${#files[@]} file(s) formatted"
