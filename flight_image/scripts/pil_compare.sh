#!/usr/bin/env bash
# Processor in the loop against the in-process bench (docs/hil.md, "Processor in the loop"):
#
#   pil_compare.sh TOLIP DECK TABLE MISSION_ID PIL_ELF OUT_DIR SCENARIO DURATION_S
#     flies SCENARIO for DURATION_S seconds with `tolip hil` in process (--target host) and on the
#     emulated Cortex-M7 (--target qemu --image PIL_ELF) and requires byte-identical telemetry CSV,
#     the same flight and link counters, and the same flown table CRC.
#   pil_compare.sh TOLIP DECK TABLE MISSION_ID PIL_ELF OUT_DIR --dead OTHER_ELF
#     a target image that never answers (OTHER_ELF) and a missing image must each exit 2 with a
#     named cause, well inside the test's timeout.
set -euo pipefail

if [[ $# -ne 8 ]]; then
  echo "usage: $0 TOLIP DECK TABLE MISSION_ID PIL_ELF OUT_DIR (SCENARIO DURATION_S | --dead OTHER_ELF)" >&2
  exit 2
fi
tolip=$1 deck=$2 table=$3 mission_id=$4 image=$5 out=$6
mkdir -p "$out"
common=(hil "$deck" --table "$table" --mission-id "$mission_id")

if [[ $7 == --dead ]]; then
  other=$8
  status=0
  "$tolip" "${common[@]}" --target qemu --image "$other" --duration-s 1 >"$out/dead.out" 2>"$out/dead.err" || status=$?
  cat "$out/dead.err"
  [[ $status -eq 2 ]] || { echo "FAIL: a target that never answers exited $status, not 2"; exit 1; }
  grep -q -- "--target qemu: table upload: the target closed its serial link (QEMU exited with status 0" "$out/dead.err" ||
    { echo "FAIL: the cause is not named"; exit 1; }
  status=0
  "$tolip" "${common[@]}" --target qemu --image "$out/no-such-image.elf" >"$out/missing.out" 2>"$out/missing.err" || status=$?
  cat "$out/missing.err"
  [[ $status -eq 2 ]] || { echo "FAIL: a missing image exited $status, not 2"; exit 1; }
  grep -q "the target image '.*no-such-image.elf' cannot be read" "$out/missing.err" ||
    { echo "FAIL: the cause is not named"; exit 1; }
  echo "PASS: dead target and missing image exit 2 with a named cause"
  exit 0
fi

scenario=$7 duration=$8
run=(--scenario "$scenario" --duration-s "$duration" --json)
"$tolip" "${common[@]}" "${run[@]}" --telemetry "$out/$scenario.host.csv" >"$out/$scenario.host.json"
"$tolip" "${common[@]}" "${run[@]}" --target qemu --image "$image" --telemetry "$out/$scenario.qemu.csv" \
  >"$out/$scenario.qemu.json"
rows=$(($(wc -l <"$out/$scenario.host.csv") - 1))
if ! cmp "$out/$scenario.host.csv" "$out/$scenario.qemu.csv"; then
  echo "FAIL: $scenario: the telemetry differs between the host and the emulated target"
  diff "$out/$scenario.host.csv" "$out/$scenario.qemu.csv" | head -6
  exit 1
fi
python3 - "$out/$scenario.host.json" "$out/$scenario.qemu.json" "$rows" <<'PY'
import json, sys
host, qemu = (json.load(open(p)) for p in sys.argv[1:3])
rows = int(sys.argv[3])
for key in ("flight_counters", "sensor_link", "actuator_link", "flown_table_crc", "achieved", "boot", "upload"):
    if host[key] != qemu[key]:
        sys.exit(f"FAIL: {key} differs: host {host[key]} target {qemu[key]}")
if rows < 100 or host["flight_counters"]["cycles"] != rows:
    sys.exit(f"FAIL: {rows} telemetry rows for {host['flight_counters']['cycles']} cycles")
t = qemu["target"]
print(f"PASS: {rows} cycles, telemetry byte-identical; counters {qemu['flight_counters']}; "
      f"sensor link {qemu['sensor_link']}, actuator link {qemu['actuator_link']}; "
      f"QEMU {t['wall_s']:.2f} s wall, {t['cycles_per_s']:.0f} cycles/s, {t['real_time_factor']:.2f}x real time; "
      f"target: {t['console'].strip().splitlines()[-1] if t['console'].strip() else '(no console output)'}")
PY
