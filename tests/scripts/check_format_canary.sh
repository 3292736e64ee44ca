#!/usr/bin/env bash
# Canary for Repository_SourcesFollowClangFormat: scripts/format.sh --check must flag a source that
# breaks the repository's .clang-format (here a line of 130 columns and a misplaced brace), or the
# format check could pass on anything.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cp "$root/.clang-format" "$scratch/.clang-format"
printf 'int f(int a)\n{\n  return a + a + a + a + a + a + a + a + a + a + a + a + a + a + a + a + a + a + a + a + a + a + a + a + a + a + a + a + a;\n}\n' \
  > "$scratch/unformatted.cpp"
if bash "$root/scripts/format.sh" --check "$scratch/unformatted.cpp"; then
  echo "canary: format.sh --check passed a file that breaks .clang-format" >&2
  exit 1
fi
echo "canary: format.sh --check flagged the unformatted file, as it must"
