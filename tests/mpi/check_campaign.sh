#!/usr/bin/env bash
# ctest mpi.campaign: the tablet scripts with --mpi 3 under mpiexec against the same scripts run
# serially, from the same unconfined start: tablet.py fig16 --quick for two amplitudes (one
# process runs both, so the second run splits a reloaded scene) and tablet.py fig17 --quick, the
# pull, to Dx = 0.1 (it stops at the first check past it, Dx = 0.13). Their CSV rows must agree:
# Dx identical, F within 1e-8 of the peak (measured 2.7e-12 for the cycles and 1.0e-11 for the
# pull: the order of summation; the serial pull with -j2 differs from -j1 by 2.4e-11 there. It
# grows along a run as trajectories do: 5.1e-9 up to Dx = 0.2, 1.7e-6 up to 0.4, hence the short
# pull. Contacts remade at the split would be off by O(1).)
set -euo pipefail
launcher=$1
here=$(cd "$(dirname "$0")" && pwd)
scripts="$here/../../studies/scripts"
dir=$(mktemp -d /tmp/mpi-campaign-XXXXXX)
trap 'rm -rf "$dir"' EXIT
quiet="^XMLRPC\|TCP python\|Welcome\|Using python\|Running script"
# both ways: serially into $dir/serial, then under mpiexec into $dir/mpi
both() {
  local script=$1; shift
  "$launcher" -j1 -n -x "$scripts/$script" "$@" --out "$dir/serial" > "$dir/serial.log" 2>&1 \
    || { tail -20 "$dir/serial.log"; exit 1; }
  mkdir -p "$dir/mpi" && cp "$dir"/serial/*.yade.gz* "$dir/mpi/"  # the same unconfined start
  if ! timeout -s KILL 600 mpiexec --allow-run-as-root --oversubscribe -n 3 "$launcher" -j1 -n -x \
      "$scripts/$script" "$@" --out "$dir/mpi" --mpi 3 > "$dir/mpi.log" 2>&1; then
    grep -v "$quiet" "$dir/mpi.log" | tail -30
    echo "mpi.campaign: FAILED: $script --mpi 3 did not finish"; exit 1
  fi
}
both tablet.py fig16 --quick --amplitudes 0.1,0.2 --periods 30
both tablet.py fig17 --quick --until 0.1
/usr/bin/python3 - "$dir" <<'PY'
import json, os, sys
d = sys.argv[1]
ok = True
for run in ("runs/tension-Dx0.1-P30/tension-Dx0.1-P30", "runs/tension-Dx0.2-P30/tension-Dx0.2-P30", "fig17/fig17"):
    def rows(side):
        with open(os.path.join(d, side, "quick", run + ".csv")) as f:
            return [tuple(float(x) for x in line.split(",")) for line in f.read().split("\n")[1:] if line]
    s, m = rows("serial"), rows("mpi")
    with open(os.path.join(d, "mpi", "quick", run + ".json")) as f:
        ranks = json.load(f)["mpi_ranks"]
    peak = max(abs(r[2]) for r in s)
    same_dx = len(s) == len(m) and all(a[:2] == b[:2] for a, b in zip(s, m))
    worst = max(abs(a[2] - b[2]) for a, b in zip(s, m)) / peak
    good = same_dx and worst <= 1e-8 and ranks == 3
    ok = ok and good
    print(f"{os.path.basename(run)}: {len(s)} rows, Dx identical {same_dx}, F differs by at most {worst:.1e} of the "
          f"peak {peak:.4g}, ranks {ranks}: {'ok' if good else 'FAILED'}")
sys.exit(0 if ok else 1)
PY
echo "mpi.campaign: ok"
