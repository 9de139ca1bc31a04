#!/usr/bin/env bash
# The full Appendix F campaign on a 2-core machine, as two independent single-threaded lanes
# (faster here than one -j2 job), then its data and figures copied into docs/tablet/:
#   bash scripts/tablet_campaign.sh [YADE] [OUT]
# YADE defaults to the build-tree launcher, OUT to results/tablet. Runs whose CSV and JSON are
# in OUT already are read back, not repeated; the cached states are made once (stages.ensure).
set -euo pipefail
cd "$(dirname "$0")/.."
YADE=${1:-build/yade-meso}
OUT=${2:-results/tablet}
run() { "$YADE" -j1 -n -x "$@" --out "$OUT"; }
mkdir -p "$OUT"
run scripts/tablet_prepare.py
( run scripts/tablet_fig16.py --amplitudes 0.2 --periods 30,120,480
  run scripts/tablet_fig16.py
  run scripts/tablet_fig17.py ) > "$OUT/lane-a.log" 2>&1 &
( run scripts/tablet_fig18.py --amplitudes 0.2 --periods 30,120,480
  run scripts/tablet_fig18.py
  run scripts/tablet_fig19.py
  for set in "table2 0" "appendixF 0.2" "table2 0.5"; do
    read -r material kc <<< "$set"
    "$YADE" -j1 -n -x scripts/tablet_prepare.py --material "$material" --kc-over-kp "$kc" --out "$OUT/kc-$material-$kc"
  done ) > "$OUT/lane-b.log" 2>&1 &
wait
run scripts/tablet_rates.py   # the rate table from the runs above (nothing is re-run)
"$YADE" -j1 -n -x scripts/tablet_report.py "$OUT" docs/tablet
