#!/usr/bin/env bash
# Fails when a file of the repository reaches for a folder outside it (issue 9): the customer's
# shared/ folder beside the project, or a path that climbs above the repository root from CMake
# or a script. A user's clone has nothing beside it, so any such path breaks the build, the tests
# or the example generator there.
#
#   check_self_contained.sh REPOSITORY_ROOT
#
# Scans the files a clone would hold: `git ls-files` (tracked and untracked-but-not-ignored) when
# the root is a git work tree, else every file outside build folders. tests/reference/ is the
# imported data itself (its own README cites the customer's folder by name) and is not scanned.
set -euo pipefail

root=${1:?usage: check_self_contained.sh REPOSITORY_ROOT}
cd "$root"

if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files -co --exclude-standard)
else
  mapfile -t files < <(find . -type f -not -path './build*' -not -path './.git/*' | sed 's#^\./##')
fi

# What reaching outside looks like here:
#   shared/reference, shared/spec, TOLIP_SHARED_DIR   the customer's folder beside the project
#   ${CMAKE_SOURCE_DIR}/.. and the like                 CMake climbing above the root
#   $ROOT_DIR/.., os.path.join(ROOT, "..")              a script climbing above the root
pattern='(\.\./shared|shared/(reference|spec)|TOLIP_SHARED_DIR|(PROJECT|CMAKE|CMAKE_CURRENT)_SOURCE_DIR\}/\.\.|\$\{?ROOT(_DIR)?\}?/\.\.|join\(ROOT, *"\.\.")'
violations=0
for f in "${files[@]}"; do
  case "$f" in
    tests/reference/*) continue ;;
    tests/scripts/check_self_contained.sh) continue ;;    # this file names the patterns
  esac
  [[ -f "$f" ]] || continue
  if grep -IEnH "$pattern" -- "$f"; then violations=$((violations + 1)); fi
done

if [[ $violations -gt 0 ]]; then
  echo "reaches outside the repository: $violations file(s) above"
  exit 1
fi
echo "self-contained: ${#files[@]} files scanned, none reaches outside the repository"
