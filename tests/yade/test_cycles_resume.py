# ctest (inside yade): a cyclic test saved on the way (uniaxial.Test.cycles' checkpoint, as the
# tablet's runs of hours need): two tension cycles of 0.05 d0 on a small unconfined sample with a
# save after every quarter cycle, the run going on from each file as loaded; then loaded from its
# first save (Test.load, as a new process would) and resumed, saving on: every row, branch record, length,
# energy record, the energy balance and the final state the same, bit for bit. Against the same
# cycles run whole, without saves: the same to rounding (a load renews the collider's order of new
# contacts, so the force sums' order; measured 2.3e-13 of the force scale), while a 1e-9 change of the
# time step moves it by orders more. The checkpoint's files are removed at the end; bad arguments
# are refused, naming them.
import os
import tempfile

from yade import O

from mesocontact import bulk
from mesocontact.bulk import uniaxial
from harness import FirstSaveKept, check, finish

USER = dict(density=2500.0, k1=125.0, kp=250.0, kc=25.0, phiF=0.05, gammaN=1.25e-5, frictionAngle=0.5,
            kt=50.0, gammaT=2.5e-6, kr=25.0, gammaR=1.25e-6, muR=0.1, ko=25.0, gammaO=1.25e-6, muO=0.1)
D0 = 1e-4
out = tempfile.mkdtemp(prefix="cycles-resume-")
p = bulk.Protocol.ratios(USER, D0, sinter=0.02, n=64, seed=3, release_steps=4000, packing="frictionless")
bulk.prepare(os.path.join(out, "released.yade.gz"), p, progress=False)
uniaxial.make_unconfined(progress=False)
start = os.path.join(out, "unconfined.yade.gz")
O.save(start)


def cycled(dt_factor=1.0, **kw):
    O.load(start)
    O.dt *= dt_factor
    t = uniaxial.Test(progress=False)
    t.track_energy()
    t.cycles("tension", 0.05, n_cycles=2, period=40.0, **kw)
    return t


def records(t):
    return t.rows, t.branches, t.lengths, t.energy


def final():
    return [(tuple(b.state.pos), tuple(b.state.vel), tuple(b.state.angVel)) for b in O.bodies]


def apart(a, b):
    """The largest difference of two runs' rows: Dx, and F over the run's largest |F|."""
    scale = max(abs(r[2]) for r in b.rows)
    return (max(abs(x[1] - y[1]) for x, y in zip(a.rows, b.rows)),
            max(abs(x[2] - y[2]) for x, y in zip(a.rows, b.rows)) / scale)


whole = cycled()
nudged = cycled(dt_factor=1 + 1e-9)
ck, kept = os.path.join(out, "cycles.checkpoint.yade.gz"), os.path.join(out, "kept.yade.gz")
with FirstSaveKept(uniaxial.Test, kept) as first:
    saved = cycled(checkpoint=ck)
    saved_balance, saved_final = saved.energy_balance(), final()
saves = first.steps
near, far = apart(saved, whole), apart(nudged, whole)
same_iters = [r[0] for r in saved.rows] == [r[0] for r in whole.rows]
check(len(saves) == 7 and len(saved.rows) == len(whole.rows) > 700 and same_iters and near[1] < 1e-11
      and far[1] > 100 * near[1],
      f"checkpoint: {len(saves)} saves in two cycles; against the whole run F within {near[1]:.1e} of its scale, "
      f"Dx within {near[0]:.1e} (the step x (1 + 1e-9): F {far[1]:.1e}, Dx {far[0]:.1e})")
check(not os.path.exists(ck) and not os.path.exists(ck + ".json"), "checkpoint: its files removed at the end")
resumed = uniaxial.Test.load(kept)
check(O.iter == saves[0] and len(resumed.rows) < len(whole.rows), f"loaded at step {O.iter}, the first save")
resumed.resume(ck)  # saving on, as the first process did: both go on from the same files
check(records(resumed) == records(saved) and resumed.energy_balance() == saved_balance and final() == saved_final,
      f"resumed from the first save: the same {len(resumed.rows)} rows, branch records, lengths, energy records, "
      f"energy balance ((dE - W)/gross = {saved_balance['residual_over_gross']:.1e}) and final state, bit for bit")

# Refused, naming what is wrong.
for name, call, kind in (
        ("checkpoint", lambda: cycled(checkpoint="x.xml"), ValueError),
        ("checkpoint", lambda: uniaxial.Test(progress=False, run=lambda n: O.run(n, True)).cycles(
            "tension", 0.05, n_cycles=1, checkpoint=ck), ValueError),
        ("Test.save", lambda: uniaxial.Test(progress=False).save(ck), RuntimeError),
        ("Test.resume", lambda: uniaxial.Test(progress=False).resume(), RuntimeError),
        ("path", lambda: uniaxial.Test.load(os.path.join(out, "x.xml")), ValueError)):
    try:
        call()
        refused = "no exception"
    except kind as e:
        refused = str(e)
    check(refused.startswith(name), f"refused: {name}", refused)
finish()
