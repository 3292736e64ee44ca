#!/usr/bin/env bash
# `mpirun -np K tolip_montecarlo_mpi` takes the options of `tolip montecarlo` and prints the same
# JSON bytes for 1 and 3 ranks as the single-process command does on one thread (counter-based
# draws, records gathered in sample order, the same report code; docs/cli.md "tolip montecarlo").
# Usage: check_mpi_montecarlo.sh TOLIP DRIVER MPIEXEC DECK
set -euo pipefail
tolip=$1 driver=$2 mpiexec=$3 deck=$4
# Under AddressSanitizer (the asan preset) LeakSanitizer reports Open MPI's own allocations at
# exit (libmpi's op selection, its dlopen'ed components): not this program's. Leak checking of the
# same Monte Carlo code is done by the threaded tolip montecarlo tests; here it is off.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# CI runs as root; Open MPI refuses that unless told.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
options=(--samples 30 --seed 2026 --json)
"$tolip" montecarlo "$deck" "${options[@]}" --threads 1 > "$work/threads1.json" 2> "$work/threads1.err"
grep -q '"flown": 30' "$work/threads1.json" || { echo "tolip montecarlo did not fly 30 samples:"; cat "$work/threads1.json" "$work/threads1.err"; exit 1; }
for ranks in 1 3; do
  "$mpiexec" --oversubscribe -np "$ranks" "$driver" "$deck" "${options[@]}" > "$work/np$ranks.json" 2> "$work/np$ranks.err"
  if ! cmp -s "$work/threads1.json" "$work/np$ranks.json"; then
    echo "tolip montecarlo and mpirun -np $ranks differ:"
    diff "$work/threads1.json" "$work/np$ranks.json" | head -40 || true
    cat "$work/np$ranks.err"
    exit 1
  fi
done
# Bad input is reported once (by rank 0) with exit 2, as tolip does.
set +e
"$mpiexec" --oversubscribe -np 3 "$driver" "$deck" --samples 0 --seed 1 > "$work/bad.out" 2> "$work/bad.err"
status=$?
set -e
if [ "$status" -ne 2 ] || [ "$(grep -c -- '--samples 0: expected 1 to 100000 samples' "$work/bad.err")" -ne 1 ]; then
  echo "mpirun -np 3 with --samples 0: exit $status (expected 2, one message):"; cat "$work/bad.err"; exit 1
fi
echo "identical JSON for tolip montecarlo and mpirun -np 1 and 3"
