#!/usr/bin/env bash
# The Monte Carlo statistics of tolip_montecarlo_mpi are the same bytes for 1, 2 and 3 ranks
# (counter-based draws, records gathered in sample order; docs/theory/dispersions.md).
# Usage: check_mpi_montecarlo.sh DRIVER MPIEXEC DECK
set -euo pipefail
driver=$1 mpiexec=$2 deck=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# CI runs as root; Open MPI refuses that unless told.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
for ranks in 1 2 3; do
  "$mpiexec" --oversubscribe -np "$ranks" "$driver" "$deck" 30 2026 > "$work/np$ranks.json"
done
grep -q '"flown": 30' "$work/np1.json" || { echo "np 1 did not fly 30 samples:"; cat "$work/np1.json"; exit 1; }
for ranks in 2 3; do
  if ! cmp -s "$work/np1.json" "$work/np$ranks.json"; then
    echo "-np 1 and -np $ranks differ:"
    diff "$work/np1.json" "$work/np$ranks.json" || true
    exit 1
  fi
done
echo "identical statistics for 1, 2 and 3 ranks"
