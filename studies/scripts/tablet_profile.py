# Where the tablet's step goes: yade.timing per engine on a tension cycle at the campaign's time
# step (the unconfined start of the tests), the interactions the InteractionLoop visits (touching
# and potential), ns per interaction and step, and the collider's verletDist swept in the same
# process (ratios, not absolute times, are what compare on a shared machine):
#   yade -j1 -n -x studies/scripts/tablet_profile.py [--out DIR] [--steps N] [--json FILE]
import argparse
import json
import os
import sys
import time

from yade import O, timing
from yade import wrapper as w

from mesocontact import outputs
from mesostudies.tablet import campaign, uniaxial

p = argparse.ArgumentParser(prog="tablet_profile.py")
p.add_argument("--out", default="results/tablet", help="the campaign directory (its cached unconfined start)")
p.add_argument("--steps", type=int, default=4000)
p.add_argument("--verlet", default="1,0.3,0.1", help="comma-separated multiples of the collider's verletDist")
p.add_argument("--json", default=None, help="write the profile here")
a = p.parse_args(sys.argv[1:])
if a.steps < 400:
    p.error(f"--steps {a.steps} is invalid: at least 400")


def one(verlet_factor, timed):
    campaign.prepare(a.out, progress=False)
    O.dt *= campaign.DT_FACTORS["tension"]
    col = next(e for e in O.engines if isinstance(e, w.InsertionSortCollider))
    col.verletDist *= verlet_factor
    test = uniaxial.Test(progress=False)
    runs0 = col.numAction
    O.timingEnabled = timed
    timing.reset()
    t0 = time.time()
    test.cycles("tension", 0.2, n_cycles=1, steps_per_cycle=a.steps, every=a.steps // 8)
    ms = 1e3 * (time.time() - t0) / a.steps
    total = len(O.interactions)
    real = sum(1 for _ in O.interactions)  # Python iterates over the real ones only
    out = {"verlet_factor": verlet_factor, "verletDist": col.verletDist, "ms_per_step": ms, "interactions": total,
           "touching": real, "potential": total - real, "collider_runs": col.numAction - runs0}
    if timed:
        engines = {}
        for e in O.engines:
            name = e.label or type(e).__name__
            if e.execTime:
                engines[name] = {"us_per_step": e.execTime / 1e3 / a.steps}
        s = sum(v["us_per_step"] for v in engines.values())
        for v in engines.values():
            v["share"] = v["us_per_step"] / s
        out["engines"] = engines
        loop = next(e for e in O.engines if isinstance(e, w.InteractionLoop))
        out["interaction_loop_ns_per_interaction"] = loop.execTime / a.steps / total
        out["bodies"] = len(O.bodies)
        out["newton_ns_per_body"] = (next(e for e in O.engines if isinstance(e, w.NewtonIntegrator)).execTime
                                     / a.steps / len(O.bodies))
    O.timingEnabled = False
    return out


res = {"threads": O.numThreads, "steps": a.steps, "dt_factor": campaign.DT_FACTORS["tension"],
       "profile": one(1.0, True)}
prof = res["profile"]
print(f"tablet step, -j{O.numThreads}: {prof['ms_per_step']:.3f} ms ({prof['bodies']} bodies, {prof['touching']} "
      f"touching and {prof['potential']} potential interactions)")
for name, v in sorted(prof["engines"].items(), key=lambda kv: -kv[1]["us_per_step"]):
    print(f"  {name:24s} {v['us_per_step']:9.1f} us/step  {100 * v['share']:5.1f} %")
print(f"  InteractionLoop: {prof['interaction_loop_ns_per_interaction']:.0f} ns per interaction and step; "
      f"NewtonIntegrator: {prof['newton_ns_per_body']:.0f} ns per body and step")
res["verlet"] = [one(float(f), False) for f in a.verlet.split(",")]
base = res["verlet"][0]["ms_per_step"]
for v in res["verlet"]:
    v["time_ratio"] = v["ms_per_step"] / base
    print(f"  verletDist x{v['verlet_factor']:g}: {v['interactions']} interactions ({v['potential']} potential), "
          f"{v['collider_runs']} collider runs, step time x{v['time_ratio']:.3f}")
if a.json:
    os.makedirs(os.path.dirname(a.json) or ".", exist_ok=True)
    outputs.write_atomic(a.json, json.dumps(res, indent=1))
