#!/usr/bin/env bash
# A bounded libFuzzer campaign over every target of fuzz/ (issue 14; docs/verification/fuzzing.md).
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]     default 60 s each; targets toml_deck card_deck
#                                             table_image plot_result
#   TOLIP_FUZZ_RUNS=N scripts/fuzz.sh ...     also stop each target after N executions
#   TOLIP_FUZZ_SEEDS='compact_*' scripts/fuzz.sh ...   start from the seeds matching the pattern
#                                             only (a target with none: its whole corpus)
#
# Builds the fuzz preset (clang 14, ASan + UBSan) when needed, then runs each target for SECONDS
# on one core, starting from its checked-in corpus (fuzz/corpus/TARGET, read only) and growing a
# working corpus in build-fuzz/work/TARGET; its keyword dictionary (fuzz/dict) when it has one.
# A crash, leak, timeout or undefined behaviour leaves its input in build-fuzz/artifacts/TARGET/:
# reproduce it with build-fuzz/fuzz/tolip_fuzz_TARGET FILE, fix it, and copy the file into
# fuzz/regressions/TARGET/ so that ctest --preset fuzz replays it from then on.
# Prints one line per target: executions, seconds, executions per second, corpus size, findings.
set -uo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
seconds=${1:-60}
shift || true
targets=("$@")
[[ ${#targets[@]} -gt 0 ]] || targets=(toml_deck card_deck table_image plot_result)
build="$root/build-fuzz"
cd "$root"
if [[ "${TOLIP_FUZZ_NO_BUILD:-0}" != 1 ]]; then  # TOLIP_FUZZ_NO_BUILD=1: run the targets as built
  if [[ ! -f "$build/CMakeCache.txt" ]]; then nice -n 10 cmake --preset fuzz >/dev/null || exit 1; fi
  nice -n 10 cmake --build --preset fuzz || exit 1
fi
status=0
for t in "${targets[@]}"; do
  exe="$build/fuzz/tolip_fuzz_$t"
  work="$build/work/$t"
  artifacts="$build/artifacts/$t"
  mkdir -p "$work" "$artifacts"
  dict=()
  [[ -f "$root/fuzz/dict/$t.dict" ]] && dict=(-dict="$root/fuzz/dict/$t.dict")
  # TOLIP_FUZZ_RUNS=N: stop after N executions as well (whichever comes first, N or SECONDS),
  # e.g. TOLIP_FUZZ_RUNS=1000000 scripts/fuzz.sh 36000 table_image for the 10^6 campaign.
  limit=()
  [[ -n "${TOLIP_FUZZ_RUNS:-}" ]] && limit=(-runs="$TOLIP_FUZZ_RUNS")
  # TOLIP_FUZZ_SEEDS=PATTERN: the seeds of fuzz/corpus/TARGET matching PATTERN, e.g. 'compact_*'
  # (the compact decks of scripts/make_fuzz_seeds.py), copied to build-fuzz/seeds/TARGET.
  seeds="$root/fuzz/corpus/$t"
  if [[ -n "${TOLIP_FUZZ_SEEDS:-}" ]] && compgen -G "$seeds/${TOLIP_FUZZ_SEEDS}" >/dev/null; then
    rm -rf "$build/seeds/$t" && mkdir -p "$build/seeds/$t"
    cp "$seeds"/${TOLIP_FUZZ_SEEDS} "$build/seeds/$t/"
    seeds="$build/seeds/$t"
  fi
  log="$build/work/$t.log"
  nice -n 10 "$exe" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
    -artifact_prefix="$artifacts/" -print_final_stats=1 "${dict[@]}" "${limit[@]}" \
    "$work" "$seeds" > "$log" 2>&1
  rc=$?
  runs=$(grep -oE '^stat::number_of_executed_units: *[0-9]+' "$log" | grep -oE '[0-9]+$' || echo 0)
  secs=$(grep -oE '^Done [0-9]+ runs in [0-9]+ second' "$log" | grep -oE 'in [0-9]+' | grep -oE '[0-9]+' || echo "$seconds")
  corpus=$(find "$work" -type f | wc -l)
  found=$(find "$artifacts" -type f | wc -l)
  cov=$(grep -oE '(DONE|INITED)[[:space:]]+cov: [0-9]+ ft: [0-9]+' "$log" | tail -1 | grep -oE 'cov: [0-9]+ ft: [0-9]+' || echo "cov: ?")
  echo "fuzz.sh: $t: ${runs} executions in ${secs} s ($(( runs / (secs > 0 ? secs : 1) ))/s), ${cov}, corpus ${corpus}, findings ${found}, exit ${rc} (log $log)"
  [[ $rc -eq 0 && $found -eq 0 ]] || status=1
done
exit $status
