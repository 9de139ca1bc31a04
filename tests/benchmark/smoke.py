"""the on-demand benchmark script (`scripts/benchmark_laws.py`) runs end to end on 300 spheres: every
report section, the serial and parallel forces equal to summation order, pooling with `--merge`; its
times are not checked.

usage: smoke.py YADE_LAUNCHER
Runs scripts/benchmark_laws.py on 300 spheres, one -j1 and one -j2 run, then pools that run's
measurements with themselves through --merge: every report section must be there, the serial and
parallel forces must agree to summation order, and pooling must double the rounds.
"""
import os
import re
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
driver = os.path.join(here, "..", "..", "scripts", "benchmark_laws.py")
yade = sys.argv[1]


def run(*extra):
    out = subprocess.run([sys.executable, driver, "--yade", yade, *extra], capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(f"benchmark_laws.py {' '.join(extra)} failed:\n{out.stdout[-3000:]}\n{out.stderr[-3000:]}")
    return out.stdout


with tempfile.TemporaryDirectory() as tmp:
    js = os.path.join(tmp, "m.json")
    text = run("--bodies", "300", "--steps", "5", "--rounds", "3", "--sessions", "1", "--json", js)
    for needed in ("criteria (whole-step time)", "speed-up (c) / speed-up (a)", "speed-up (d) / speed-up (e)",
                   "InteractionLoop speed-up", "contact physics: MesoPhys "):
        if needed not in text:
            sys.exit(f"missing from the report: {needed!r}\n{text}")
    pairs = re.findall(r"max \|F\(-j2\) - F\(-j1\)\| / max \|F\| = (\S+), same for torques (\S+)", text)
    diffs = [float(x) for forces_torques in pairs for x in forces_torques]
    if len(diffs) != 12 or max(diffs) > 1e-12:
        sys.exit(f"serial and parallel forces: {diffs}")
    rounds = int(re.search(r"; (\d+) rounds of", text).group(1))
    pooled = run("--sessions", "0", "--laws", "cundall-strack,meso-normal", "--merge", js, js)
    pooled_rounds = int(re.search(r"; (\d+) rounds of", pooled).group(1))
    if (rounds, pooled_rounds) != (3, 6) or "speed-up (c) / speed-up (a)" not in pooled:
        sys.exit(f"pooling: {rounds} rounds, pooled {pooled_rounds}\n{pooled}")
print("benchmark script: report complete, serial/parallel forces within", max(diffs), "; pooling OK")
