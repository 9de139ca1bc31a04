# One pair collision per line of a yade-batch parameter table, or one with the defaults below:
#   yade-batch --executable build/yade-meso examples/pair-batch.table scripts/pair_batch.py
#   yade -n -x scripts/pair_batch.py
# Table columns (any subset; the rest keep the defaults; strings quoted, as yade-batch evaluates
# each cell): description k1 kp kc phiF fa kca adhesion k2Interpolation gammaN radius density v
# against ('particle': two equal spheres, 'wall': a sphere on a box) out (directory).
# Each job writes <out>/<description>.json: its parameters, e from YADE and from the closed form
# (theory.pair_collision, exact without viscosity), whether it stuck, and the cost.
import json
import math
import os
import sys
import time

from yade import O, utils

from mesocontact import batch, outputs, pair, theory

batch.help_requested(sys.argv[1:], sys.argv[0])
batch.check_descriptions()

utils.readParamsFromTable(k1=100.0, kp=500.0, kc=100.0, phiF=0.05, fa=0.0, kca=100.0, adhesion="none",
                          k2Interpolation="linear", gammaN=0.0, radius=1e-3, density=2500.0, v=0.05,
                          against="particle", out="results/batch")
from yade.params import table as t  # noqa: E402  (filled by readParamsFromTable)

if t.against not in ("particle", "wall"):
    raise ValueError(f"against = {t.against!r} is invalid: must be 'particle' or 'wall'")
mat = dict(k1=t.k1, kp=t.kp, kc=t.kc, phiF=t.phiF, adhesion=t.adhesion, k2Interpolation=t.k2Interpolation,
           gammaN=t.gammaN, density=t.density)
if t.adhesion != "none":
    mat.update(fa=t.fa, kca=t.kca)
t0 = time.time()
s = pair.build(t.radius, t.v, dict(mat)) if t.against == "particle" else \
    pair.build_wall(t.radius, t.v, dict(mat), wall_material=dict(mat))
r = pair.collide(s)
p = s.mixed
th = theory.pair_collision(t.v, p["k1"], p["kp"], p["kc"], p["phiF"], s.a12, s.m_r, p["fa"],
                           p["kca"] if p["fa"] > 0 else math.inf, p["adhesion"], p["k2Interpolation"])
name = O.tags["description"] if O.tags["line"] != "l!" else "defaults"
result = {"description": name, "params": O.tags["params"], "material": mat, "radius": t.radius, "v": t.v,
          "against": t.against, "e_yade": r.e, "stuck": r.stuck, "e_theory": th.e, "regime": th.regime,
          "viscous": t.gammaN > 0, "steps": r.steps, "wall_clock_s": time.time() - t0}
os.makedirs(t.out, exist_ok=True)
outputs.write_atomic(os.path.join(t.out, name + ".json"), json.dumps(result, indent=1))
print(f"{name}: e_yade = {r.e:.6f}, e_theory = {th.e:.6f} "
      f"({th.regime}){' (viscous: theory without it)' if t.gammaN > 0 else ''}",
      flush=True)
