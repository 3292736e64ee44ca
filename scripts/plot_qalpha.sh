#!/bin/sh
# The reference optimum and the q-bar x alpha limited optimum overlaid (issue 15): theta, alpha and
# q-bar x alpha against time, drawn by `tolip plot` from the two `optimize --json` documents as one
# array (a colour per case; docs/cli.md "tolip plot").
#
#     scripts/plot_qalpha.sh [TOLIP] [OUT_DIR]
#
# TOLIP: the executable (default build/ground_tools/tolip); OUT_DIR: the figures' directory
# (default qalpha_plots). Writes OUT_DIR/theta_time_ascent, alpha_time and qalpha_time (.png, .svg)
# among the other figures of the two cases. Needs gnuplot and python3.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
tolip=${1:-$root/build/ground_tools/tolip}
out=${2:-qalpha_plots}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$tolip" optimize "$root/examples/scout/mission.toml" --json > "$work/reference.json" 2> "$work/reference.err"
"$tolip" optimize "$root/examples/scout/mission_qalpha.toml" --json > "$work/qalpha.json" 2> "$work/qalpha.err"
python3 - "$work/reference.json" "$work/qalpha.json" "$work/both.json" <<'PY'
import json, sys
cases = [json.load(open(path)) for path in sys.argv[1:3]]
for case in cases:
    q = case["qbar_alpha"]
    print("%s: %s, payload %.4f lb, peak q-bar x alpha %.1f lb deg/ft^2 at %.2f s"
          % (case["case_heading"], case["status"], case["payload_lb"], q["lift_peak_lb_deg_ft2"], q["lift_peak_time_s"]))
json.dump(cases, open(sys.argv[3], "w"))
PY
"$tolip" plot "$work/both.json" --out "$out"
