#!/usr/bin/env bash
# Proves the repository stands alone (issue 9): copies the files a clone would hold into a new
# temporary folder with nothing beside it, and runs the README's test command there
# (scripts/test.sh: configure, build, the whole CTest suite, the Cortex-M7 check under QEMU).
# Any path into a folder beside the project (the customer's shared/ reference data, say) fails
# there, because no such folder exists next to the copy.
#
#   check_clean_clone.sh REPOSITORY_ROOT
#
# The copy is the work tree as `git ls-files -co --exclude-standard` lists it (what a commit of it
# would hold, so uncommitted work is checked too), made a git repository of its own as a user's
# clone is. The nested run sets TOLIP_IN_CLEAN_CLONE=1, which leaves this test out of its suite.
# The temporary folder is removed afterwards unless TOLIP_KEEP_CLEAN_CLONE=1.
# The copy's build compiles through ccache with the copy as its base folder (scripts/lib/deps.sh),
# so the sources the first build compiled come from the cache; a hit still needs every file the
# compile reads, at its path inside the copy, so a file missing from the copy still fails here.
set -euo pipefail

root=$(cd "${1:?usage: check_clean_clone.sh REPOSITORY_ROOT}" && pwd)
parent=$(mktemp -d "${TMPDIR:-/tmp}/tolip-clean-clone.XXXXXX")
if [[ "${TOLIP_KEEP_CLEAN_CLONE:-0}" != 1 ]]; then trap 'rm -rf "$parent"' EXIT; fi
clone="$parent/tolip"
mkdir "$clone"

cd "$root"
if command -v git >/dev/null 2>&1 && git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  git ls-files -co --exclude-standard -z | while IFS= read -r -d '' f; do [[ -e "$f" ]] && printf '%s\0' "$f"; done |
    tar --null -T - -cf - | tar -C "$clone" -xf -
else
  tar --exclude='./build*' --exclude='./.git' -cf - . | tar -C "$clone" -xf -
fi
cd "$clone"
if command -v git >/dev/null 2>&1; then  # a user's clone is a git repository; the build does not need one
  git init -q
  git add -A
  git -c user.name=clean-clone -c user.email=clean-clone@localhost commit -q -m "clean clone" >/dev/null
fi

beside=$(ls -A "$parent")
if [[ "$beside" != "tolip" ]]; then
  echo "error: the clone's folder holds more than the clone: $beside" >&2
  exit 1
fi
echo "-- clean copy of $(find . -type f -not -path './.git/*' | wc -l) files in $clone (nothing beside it); running scripts/test.sh"
start=$(date +%s)
TOLIP_IN_CLEAN_CLONE=1 TOLIP_BUILD_DIR="$clone/build" scripts/test.sh
echo "-- clean clone passed scripts/test.sh in $(( $(date +%s) - start )) s"
