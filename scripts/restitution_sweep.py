# The main job: restitution sweeps and force-overlap loops of the meso-particle law in YADE,
# regenerating Figs. 5-8 of the paper (CSV + PNG).
#   yade -n -x scripts/restitution_sweep.py [OUTPUT_DIR]      (default: ./results)
import argparse
import os
import sys
import time

from mesocontact import figures

parser = argparse.ArgumentParser(prog="yade -n -x scripts/restitution_sweep.py",
                                 description="Figs. 5-8 of the long paper: YADE pair collisions over the closed form (CSV + PNG).")
parser.add_argument("outdir", nargs="?", default="results", help="output directory (default: ./results)")
outdir = os.path.abspath(parser.parse_args(sys.argv[1:]).outdir)
os.makedirs(outdir, exist_ok=True)
t0 = time.time()
print(f"writing to {outdir}", flush=True)
f5 = figures.fig5(outdir)
f6 = figures.fig6_fig8(outdir)
figures.fig7(outdir)
worst5 = max(abs(r[4] - r[5]) for r in f5)
worst6 = max(abs(r[2] - r[3]) for r in f6)
print(f"Fig. 5: {len(f5)} collisions, max |e_yade - e_theory| = {worst5:.2e}")
print(f"Fig. 6: {len(f6)} collisions, max |e_yade - e_theory| = {worst6:.2e}")
print(f"done in {time.time() - t0:.1f} s; outputs:")
for name in sorted(os.listdir(outdir)):
    print("  " + os.path.join(outdir, name))
