#!/usr/bin/env bash
# ctest mpi.campaign: scripts/tablet_fig16.py --quick for two amplitudes, serially and with
# --mpi 3 under mpiexec (one process runs both, so the second run splits a reloaded scene). The
# run bundles' rows must agree: Dx identical, F within 1e-8 of the peak (measured 2.7e-12: the
# order of summation; contacts remade at the split would be off by O(1)).
set -euo pipefail
launcher=$1
here=$(cd "$(dirname "$0")" && pwd)
scripts="$here/../../scripts"
dir=$(mktemp -d /tmp/mpi-campaign-XXXXXX)
trap 'rm -rf "$dir"' EXIT
job=(--quick --amplitudes 0.1,0.2 --periods 30)
"$launcher" -j1 -n -x "$scripts/tablet_fig16.py" "${job[@]}" --out "$dir/serial" > "$dir/serial.log" 2>&1 \
  || { tail -20 "$dir/serial.log"; exit 1; }
mkdir -p "$dir/mpi" && cp "$dir"/serial/*.yade.gz* "$dir/mpi/"  # the same unconfined start
if ! timeout -s KILL 600 mpiexec --allow-run-as-root --oversubscribe -n 3 "$launcher" -j1 -n -x \
    "$scripts/tablet_fig16.py" "${job[@]}" --out "$dir/mpi" --mpi 3 > "$dir/mpi.log" 2>&1; then
  grep -v "^XMLRPC\|TCP python\|Welcome\|Using python\|Running script" "$dir/mpi.log" | tail -30
  echo "mpi.campaign: FAILED: tablet_fig16.py --mpi 3 did not finish"; exit 1
fi
/usr/bin/python3 - "$dir" <<'PY'
import json, os, sys
d = sys.argv[1]
ok = True
for run in ("tension-Dx0.1-P30", "tension-Dx0.2-P30"):
    def rows(side):
        with open(os.path.join(d, side, "quick", "runs", run, run + ".csv")) as f:
            return [tuple(float(x) for x in line.split(",")) for line in f.read().split("\n")[1:] if line]
    s, m = rows("serial"), rows("mpi")
    with open(os.path.join(d, "mpi", "quick", "runs", run, run + ".json")) as f:
        ranks = json.load(f)["mpi_ranks"]
    peak = max(abs(r[2]) for r in s)
    same_dx = len(s) == len(m) and all(a[:2] == b[:2] for a, b in zip(s, m))
    worst = max(abs(a[2] - b[2]) for a, b in zip(s, m)) / peak
    good = same_dx and worst <= 1e-8 and ranks == 3
    ok = ok and good
    print(f"{run}: {len(s)} rows, Dx identical {same_dx}, F differs by at most {worst:.1e} of the peak {peak:.4g}, "
          f"ranks {ranks}: {'ok' if good else 'FAILED'}")
sys.exit(0 if ok else 1)
PY
echo "mpi.campaign: ok"
