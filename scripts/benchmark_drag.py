# Inside yade: what MesoBackgroundDamping costs, in one process on the same scenes.
#   yade -j1 -n -x scripts/benchmark_drag.py [--tablet FILE] [--rounds N] [--steps N] [--out FILE.json]
# Scenes: a dense periodic simple-cubic lattice of 14^3 = 2744 spheres with every mechanism
# (sliding, rolling, torsion, reversible adhesion) and thermal velocities, and (with --tablet) the
# unconfined tablet of the campaign (results/tablet/unconfined.yade.gz). Variants, toggled on the
# same scene in turns of STEPS steps, ROUNDS times (a shared machine has slow periods of seconds:
# the variants of one round see the same machine, so the ratios are taken within rounds):
#   none      the engine dead
#   engine    reference='contacts', sumInLaw=False: the engine's own pass over the interactions
#   law       reference='contacts', sumInLaw=True: the sums gathered by the law
#   lab       reference='lab'
# Also each variant's share of the step by YADE's engine timing (O.timingEnabled).
import argparse
import json
import math
import random
import statistics
import sys
import time

from yade import O, Vector3, utils
from yade import wrapper as w

p = argparse.ArgumentParser(prog="benchmark_drag.py")
p.add_argument("--tablet", default=None, help="a saved unconfined tablet (results/tablet/unconfined.yade.gz)")
p.add_argument("--rounds", type=int, default=10)
p.add_argument("--steps", type=int, default=200)
p.add_argument("--out", default=None)
a = p.parse_args(sys.argv[1:])
VARIANTS = ("none", "engine", "law", "lab")


def lattice():
    """14^3 spheres, spacing 1.98 R in a periodic cell, every mechanism, random thermal motion."""
    O.reset()
    O.periodic = True
    n, R = 14, 1e-3
    s = 1.98 * R
    O.cell.setBox(n * s, n * s, n * s)
    K = 1e4
    O.materials.append(w.MesoMat(k1=K, kp=5 * K, kc=K, phiF=0.05, gammaN=1e-4, fa=1e-4, kca=1e3, adhesion="reversible",
                                 frictionAngle=0.5, kt=0.2 * K, gammaT=2e-5, kr=0.1 * K, gammaR=5e-6, muR=0.1,
                                 ko=0.1 * K,
                                 gammaO=5e-6, muO=0.1, density=2000.0))
    rng = random.Random(1)
    for i in range(n):
        for j in range(n):
            for k in range(n):
                b = O.bodies.append(utils.sphere(((i + 0.5) * s, (j + 0.5) * s, (k + 0.5) * s), R))
                O.bodies[b].state.vel = Vector3(*(rng.gauss(0, 1e-3) for _ in range(3)))
    O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb()]),
                 w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom6D()], [w.Ip2_MesoMat_MesoMat_MesoPhys()],
                                   [w.Law2_ScGeom_MesoPhys_Meso()]),
                 w.MesoBackgroundDamping(gammaB=1e-3, gammaBR=1e-3, reference="contacts", label="background"),
                 w.NewtonIntegrator(damping=0)]
    m = 4 / 3 * math.pi * R ** 3 * 2000.0
    O.dt = 0.02 * math.pi * math.sqrt(0.5 * m / (5 * K))
    O.run(20, True)


def tablet(path):
    O.load(path)
    O.run(20, True)


def set_variant(drag, v):
    drag.dead = v == "none"
    drag.reference = "lab" if v == "lab" else "contacts"
    drag.sumInLaw = v == "law"


def measure(name):
    drag = [e for e in O.engines if isinstance(e, w.MesoBackgroundDamping)][0]
    contacts = sum(1 for i in O.interactions if i.isReal and i.geom.penetrationDepth > 0)
    per = {v: [] for v in VARIANTS}
    for r in range(a.rounds):
        for v in VARIANTS:
            set_variant(drag, v)
            O.run(5, True)  # untimed: the first step after a switch sums in the engine
            t0 = time.perf_counter()
            O.run(a.steps, True)
            per[v].append((time.perf_counter() - t0) / a.steps * 1e3)
    ratios = {v: statistics.median(per[v][k] / per["none"][k] for k in range(a.rounds)) for v in VARIANTS}
    shares, engines = {}, {}
    for v in VARIANTS:  # engine timing: the drag's share of the step, and every engine's
        set_variant(drag, v)
        O.run(5, True)
        O.timingEnabled = True
        for e in O.engines:
            e.execTime = 0
        O.run(a.steps, True)
        total = sum(e.execTime for e in O.engines)
        shares[v] = drag.execTime / total if total else None
        # ms per step
        engines[v] = {f"{k}:{type(e).__name__}": e.execTime * 1e-6 / a.steps for k, e in enumerate(O.engines)}
        O.timingEnabled = False
    used = drag.lawSumSteps
    rep = {"scene": name, "bodies": len(O.bodies), "contacts": contacts,
           "ms_per_step_median": {v: statistics.median(per[v]) for v in VARIANTS},
           "ratio_to_none_median": ratios, "drag_share_of_step": shares, "law_sum_steps": used,
           "engine_ms_per_step": engines,
           "ns_per_contact_and_step_median": {v: statistics.median(per[v]) * 1e6 / contacts for v in VARIANTS},
           "rounds": a.rounds, "steps_per_turn": a.steps}
    print(f"{name}: {len(O.bodies)} bodies, {contacts} contacts", flush=True)
    for v in VARIANTS:
        print(f"  {v:7s} {rep['ms_per_step_median'][v]:7.3f} ms/step  x{ratios[v]:.3f} of none  drag share "
              + (f"{shares[v] * 100:5.1f} %" if shares[v] is not None else "-"), flush=True)
    for v in ("engine", "law"):
        print(f"  by engine ({v}): " + ", ".join(f"{k.split(':')[1]} {t:.3f}" for k, t in engines[v].items())
              + " ms/step", flush=True)
    return rep


reports = []
lattice()
reports.append(measure("periodic lattice 14^3, every mechanism"))
if a.tablet:
    tablet(a.tablet)
    reports.append(measure("unconfined tablet"))
if a.out:
    with open(a.out, "w") as f:
        json.dump({"threads": O.numThreads, "reports": reports}, f, indent=1)
