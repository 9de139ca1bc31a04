#!/usr/bin/env bash
# The full Appendix F campaign on a 2-core machine: independent single-threaded jobs, two at a
# time (faster here than -j2 jobs), longest first; then the figures from the runs' files and
# the data and figures copied into docs/tablet/ (the time-step study is a campaign of its own:
# batch/tablet-timestep.table):
#   bash scripts/tablet_campaign.sh [YADE] [OUT]
# YADE defaults to the build-tree launcher, OUT to results/tablet. Runs whose CSV and JSON are
# in OUT already are read back, not repeated; the cached states are made once (stages.ensure).
set -euo pipefail
cd "$(dirname "$0")/.."
YADE=${1:-build/yade-meso}
OUT=${2:-results/tablet}
mkdir -p "$OUT"
"$YADE" -j1 -n -x scripts/tablet_prepare.py --out "$OUT"
jobs="fig16.py --amplitudes 0.2 --periods 30,120,480,1920
fig18.py --amplitudes 0.2 --periods 30,120,480
fig16.py --amplitudes 0.025
fig16.py --amplitudes 0.05
fig16.py --amplitudes 0.1
fig16.py --amplitudes 0.3
fig18.py --amplitudes 0.05
fig18.py --amplitudes 0.1
fig18.py --amplitudes 0.3
fig17.py
fig19.py
drag.py
prepare.py --material table2 --kc-over-kp 0 --out $OUT/kc-table2-0
prepare.py --material appendixF --kc-over-kp 0.2 --out $OUT/kc-appendixF-0.2
prepare.py --material table2 --kc-over-kp 0.5 --out $OUT/kc-table2-0.5"
export YADE OUT
# Each line: a script of scripts/tablet_*.py and its options (a later --out overrides OUT).
echo "$jobs" | xargs -P 2 -I{} sh -c 'set -f; set -- {}; script=$1; shift; name=$(echo "{}" | tr " ./" "___"); \
  "$YADE" -j1 -n -x "scripts/tablet_$script" --out "$OUT" "$@" > "$OUT/log-$name.txt" 2>&1 \
  && echo "done: {}" || { echo "FAILED: {} (see $OUT/log-$name.txt)"; exit 255; }'
"$YADE" -j1 -n -x scripts/tablet_fig16.py --out "$OUT"   # the figures, from the runs above
"$YADE" -j1 -n -x scripts/tablet_fig18.py --out "$OUT"
"$YADE" -j1 -n -x scripts/tablet_rates.py --out "$OUT" --periods 30,120,480,1920
"$YADE" -j1 -n -x scripts/tablet_report.py "$OUT" docs/tablet
