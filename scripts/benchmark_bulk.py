# The bulk tools' cost on a user's material (docs/performance.md): N glass-like beads (the
# material of docs/bulk.md) prepared with bulk.prepare and pulled through one tension cycle, with
# the wall time, steps and time per step of each stage, and YADE's own timing of each engine
# (where the time goes).
#   yade -j1 -n -x scripts/benchmark_bulk.py [--n 500] [--out FILE.json]
import argparse
import json
import math
import os
import tempfile
import time

from yade import O

from mesocontact import bulk, outputs, params
from mesocontact.bulk import sintering, uniaxial


def material():
    mat = dict(params.material_from(radius=1e-3, density=2500, impact_speed=0.5, restitution=0.6,
                                    contact_time=6e-4, phiF=0.1, kc_over_kp=0.2))
    kp = mat["kp"]
    mat.update(gammaN=2e-3, frictionAngle=math.atan(0.5), kt=0.2 * kp, gammaT=4e-4,
               kr=0.1 * kp, gammaR=2e-4, muR=0.1, ko=0.1 * kp, gammaO=2e-4, muO=0.1)
    return mat


def engine_times():
    """{engine: share of the engines' time} from YADE's timing (O.timingEnabled)."""
    t = {f"{type(e).__name__}" + (f" ({e.label})" if e.label else ""): e.execTime for e in O.engines}
    total = sum(t.values()) or 1
    return {k: v / total for k, v in sorted(t.items(), key=lambda kv: -kv[1])}


def timed(stages, name, call):
    t0, i0 = time.time(), O.iter
    O.timingEnabled = True
    for e in O.engines:
        e.execTime = 0
    out = call()
    dt = time.time() - t0
    stages[name] = {"wall_s": dt, "steps": O.iter - i0, "ms_per_step": 1e3 * dt / max(1, O.iter - i0),
                    "engines": engine_times()}
    print(f"{name}: {dt:.1f} s, {O.iter - i0} steps, {stages[name]['ms_per_step']:.3f} ms/step", flush=True)
    return out


def main():
    ap = argparse.ArgumentParser(prog="yade -n -x scripts/benchmark_bulk.py")
    ap.add_argument("--n", type=int, default=500, help="particles (default 500)")
    ap.add_argument("--out", default=None, help="write the measurements to this JSON")
    a = ap.parse_args()
    if a.n < 8:
        ap.error(f"--n {a.n}: at least 8 particles")
    p = bulk.Protocol.ratios(material(), d0=2e-3, sinter=0.02, n=a.n, packing="frictionless", glue="sinter")
    path = os.path.join(tempfile.mkdtemp(prefix="bench-bulk-"), "released.yade.gz")
    t0, stages = time.time(), {}
    # The preparation's own stages, timed one by one (prepare runs them in this order).
    info = {"built": bulk.sample.build(p)}
    O.engines = bulk.sample.engines(p, sintering.controller(p, p.sinter_stress), reference="lab")
    for name, stage in sintering.STAGES:
        timed(stages, name, lambda: stage(p, info, False))
    bulk.sample.save_atomic(path, info)
    timed(stages, "unconfined", lambda: uniaxial.make_unconfined(progress=False))
    test = uniaxial.Test(progress=False)
    timed(stages, "tension cycle", lambda: test.cycles("tension", 0.05, n_cycles=1, period=40.0))
    total = time.time() - t0
    out = {"n": a.n, "omp_threads": O.numThreads, "total_wall_s": total, "stages": stages,
           "released": {k: info["released"][k] for k in ("solid_fraction", "coordination", "rattlers")},
           "contacts": sum(1 for i in O.interactions if i.isReal)}
    print(f"total {total:.1f} s for {a.n} particles ({O.numThreads} thread(s))", flush=True)
    if a.out:
        outputs.write_atomic(a.out, json.dumps(out, indent=1))


main()
