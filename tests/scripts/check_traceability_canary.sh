#!/usr/bin/env bash
# Canary for Verification_EveryRequirementIsTracedToAKnownTest: tests/scripts/traceability.py
# check must flag a deliberately broken mapping (a requirement without a test, a requirement
# naming a test that does not exist, a test source naming a requirement that does not exist, a
# test of the build that no requirement traces: Canary.Other),
# or the traceability check could pass on anything. Made in a scratch folder so that the
# repository's own check never sees the broken tag.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
python=${1:-python3}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
mkdir -p "$scratch/tests"
cat > "$scratch/requirements.md" <<'REQ'
# Canary requirements
## Group
### REQ-CAN-001 Traced to a test that exists
- Source: canary
- Method: T
- Tests: Canary.Exists
### REQ-CAN-002 Traced to no test
- Source: canary
- Method: T
- Tests:
### REQ-CAN-003 Traced to a test that does not exist
- Source: canary
- Method: T
- Tests: Canary.Exists, Canary.DoesNotExist
REQ
printf 'Canary.Exists\nCanary.Other\n' > "$scratch/tests.txt"
tag="Verif""ies:"  # split, so that the repository's own check does not read this line as a tag
printf '// %s REQ-CAN-001, REQ-CAN-999\nint main() { return 0; }\n' "$tag" > "$scratch/tests/canary_test.cpp"
set +e
"$python" "$here/traceability.py" check --requirements "$scratch/requirements.md" \
  --tests-file "$scratch/tests.txt" --tags "$scratch/tests"
status=$?
set -e
if [[ $status -eq 0 ]]; then
  echo "canary: traceability.py check passed a broken mapping" >&2
  exit 1
fi
