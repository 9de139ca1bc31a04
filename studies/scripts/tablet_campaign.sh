#!/usr/bin/env bash
# The Appendix F campaign in one command: the sample prepared once, the plan printed (jobs, steps,
# hours from a measured ms per step), the jobs of the table run by yade-batch on N lanes (each job
# single-threaded: on this project's 2-core machines two -j1 jobs beat one -j2 job, see
# docs/performance.md), the measured total printed (job time, wall time), then the figures and
# the data copied into DOCS:
#   bash studies/scripts/tablet_campaign.sh [--lanes N] [--yade YADE] [--out OUT] [--table TABLE] [--docs DOCS]
# Defaults: 2 lanes, build/yade-meso, results/tablet, studies/batch/tablet-campaign.table, campaigns/tablet/chosen.
# Runs whose bundles are in OUT already are read back, not repeated: a campaign stopped at any
# point goes on where it stopped when the same command runs again.
set -euo pipefail
cd "$(dirname "$0")/../.."
LANES=2 YADE=build/yade-meso OUT=results/tablet TABLE=studies/batch/tablet-campaign.table DOCS=campaigns/tablet/chosen
fail() { echo "tablet_campaign.sh: $*" >&2; exit 2; }
while [ $# -gt 0 ]; do
  case "$1" in
    --lanes|--yade|--out|--table|--docs)
      [ $# -ge 2 ] && [ -n "$2" ] && [ "${2#--}" = "$2" ] || fail "$1 needs a value"
      case "$1" in --lanes) LANES=$2 ;; --yade) YADE=$2 ;; --out) OUT=$2 ;; --table) TABLE=$2 ;; --docs) DOCS=$2 ;; esac
      shift 2 ;;
    *) fail "unknown option $1 (--lanes, --yade, --out, --table, --docs)" ;;
  esac
done
# Everything checked before the sample's preparation (minutes), not after it.
case "$LANES" in ''|*[!0-9]*|0) fail "--lanes $LANES is invalid: a positive integer" ;; esac
[ -f "$TABLE" ] || fail "--table $TABLE: no such file"
[ -x "$YADE" ] || command -v "$YADE" > /dev/null || fail "--yade $YADE: not an executable"
case "$OUT" in *[\'\"\\]*|*[[:space:]]*) fail "--out $OUT is invalid: no quotes, backslashes or blanks (it becomes a cell of the yade-batch table)" ;; esac
[ "$(realpath -m "$OUT")" != "$(realpath -m "$DOCS")" ] || fail "--docs $DOCS is --out: the data would be copied onto themselves"
BATCH=${YADE_BATCH_COMMAND:-yade-batch}  # the yade-batch that matches YADE (Debian's: yade-batch)
mkdir -p "$OUT"
start=$(date +%s)
"$YADE" -j1 -n -x studies/scripts/tablet.py prepare --out "$OUT"
"$YADE" -j1 -n -x studies/scripts/tablet_plan.py "$TABLE" --out "$OUT" --lanes "$LANES"
# The table with OUT in its column 'out' (added if the table has none), so that every job writes there.
awk -v out="'$OUT'" 'NF && $1 !~ /^#/ {
  if (!head++) { for (i = 1; i <= NF; i++) if ($i == "out") col = i; print $0 (col ? "" : " out"); next }
  if (col) { $col = out; print } else print $0, out }' "$TABLE" > "$OUT/campaign.table"
"$BATCH" -j "$LANES" --nice 0 --executable "$YADE" --log "$OUT/log-@.log" \
  "$OUT/campaign.table" studies/scripts/tablet.py
"$YADE" -j1 -n -x studies/scripts/tablet_totals.py --out "$OUT" --since "$start" --lanes "$LANES" \
  --wall-seconds "$(( $(date +%s) - start ))"
"$YADE" -j1 -n -x studies/scripts/tablet.py fig16 --out "$OUT"   # the figures, from the runs above
"$YADE" -j1 -n -x studies/scripts/tablet.py fig18 --out "$OUT"
"$YADE" -j1 -n -x studies/scripts/tablet.py rates --out "$OUT" --no-run
"$YADE" -j1 -n -x studies/scripts/tablet_report.py "$OUT" "$DOCS"
