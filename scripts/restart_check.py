# A restart continues the same trajectory (issues #32 item 9, #49 item 9): a settled packing, saved,
# loaded and run STEPS steps, against the uninterrupted run, in all six of YADE's file formats, for
# the classes this project adds: plain MesoPhys contacts (normal law with adhesion, lab-frame drag)
# and MesoTangentialPhys contacts with every mechanism (contact-relative drag), in a box of five
# boxes; and spheres with sliding settling on a box floor under gravity with Newton's damping 0.3,
# beside the same scene with YADE's FrictMat/CundallStrack. Two continuations are compared with the
# reloaded run: 'loaded' (the uninterrupted run also starts from a loaded file) and 'live' (it goes
# on from the running scene, as a user's does). YADE saves only real interactions; the collider
# makes the potential ones again after a load, in another order of the interaction container, so
# the contacts that start later add their forces in another order: the live continuation differs by
# rounding with any law unless InteractionLoop.loopOnSortedInteractions is set (--sorted). Prints
# and writes the largest difference of any body's position, velocity, angular velocity and
# orientation, of any meso contact's state (every number and vector of MesoPhys.dict(): springs,
# forces, history) and of the energies.
#   yade -j1 -n -x scripts/restart_check.py [--steps 5000] [--sorted] [--out FILE.json]
import argparse
import json
import os
import sys
import tempfile

from yade import O, pack, utils, wrapper as w

from mesocontact import outputs, scene


def steps(text):
    """--steps: O.run(0) and O.run(-n) run without end, and beyond 2**62 O.iter + steps overflows
    after the scenes were settled: refused before any work."""
    allowed = "must be a whole number of steps in [1, 2**62] (O.run(0) or less runs forever)"
    try:
        n = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is invalid: {allowed}") from None
    if not 1 <= n <= 2 ** 62:
        raise argparse.ArgumentTypeError(f"{text!r} is invalid: {allowed}")
    return n


ap = argparse.ArgumentParser(prog="yade -j1 -n -x scripts/restart_check.py")
ap.add_argument("--steps", type=steps, default=5000)
ap.add_argument("--out", default=None)
ap.add_argument("--sorted", action="store_true", help="InteractionLoop.loopOnSortedInteractions in every scene")
a = ap.parse_args(sys.argv[1:])
if a.out is not None and not os.access(os.path.dirname(os.path.abspath(a.out)), os.W_OK):  # not after the whole run
    ap.error(f"argument --out: {a.out!r} is invalid: its directory does not exist or is not writable")
MATERIALS = {
    "MesoPhys (normal, jump-in adhesion, lab drag)": (dict(k1=100.0, kp=500.0, kc=20.0, phiF=0.1, fa=1e-6, kca=100.0,
                                                           adhesion="jumpIn",
                                                           gammaN=1e-4, density=2000), "lab"),
    "MesoTangentialPhys (every mechanism, contact drag)": (dict(k1=100.0, kp=500.0, kc=20.0, phiF=0.1, fa=1e-6,
                                                                kca=100.0,
                                                                adhesion="jumpIn", gammaN=1e-4, density=2000, kt=50.0,
                                                                gammaT=1e-5,
                                                                frictionAngle=0.4, kr=10.0, gammaR=1e-6, muR=0.1,
                                                                ko=10.0,
                                                                gammaO=1e-6, muO=0.1, phiD=0.8), "contacts"),
}


FLOOR = {"MesoTangentialPhys (sliding, box floor, gravity, Newton damping 0.3)":
         dict(k1=100.0, kp=500.0, kc=20.0, phiF=0.1, density=2000, kt=50.0, frictionAngle=0.4),
         "FrictPhys, YADE's CundallStrack (box floor, gravity, Newton damping 0.3)": None}


def floor(kw):
    """60 spheres falling onto a box floor, run until most rest on it with sliding contacts."""
    scene.reset()
    if kw is not None:
        m = O.materials.append(w.MesoMat(**kw))
        O.engines = scene.engines(gravity=(0, 0, -9.81))
        O.engines[-1].damping = 0.3
    else:
        m = O.materials.append(w.FrictMat(young=1e7, poisson=0.3, density=2000, frictionAngle=0.4))
        O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb(), w.Bo1_Box_Aabb()]),
                     w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom(), w.Ig2_Box_Sphere_ScGeom()],
                                       [w.Ip2_FrictMat_FrictMat_FrictPhys()],
                                       [w.Law2_ScGeom_FrictPhys_CundallStrack()]),
                     w.NewtonIntegrator(damping=0.3, gravity=(0, 0, -9.81))]
    sp = pack.SpherePack()
    sp.makeCloud((0, 0, 0), (4e-3, 4e-3, 4e-3), rMean=4e-4, rRelFuzz=0.2, seed=5, num=60)
    sp.toSimulation(material=m)
    O.bodies.append(utils.box((2e-3, 2e-3, -5e-4), (4e-3, 4e-3, 5e-4), fixed=True, material=m))
    O.dt = 2e-6 if kw is not None else 0.3 * utils.PWaveTimeStep()
    sort_loop()
    O.trackEnergy = True
    O.run(30000, True)


def sort_loop():
    for e in O.engines:
        if isinstance(e, w.InteractionLoop):
            e.loopOnSortedInteractions = a.sorted


def packing(kw, reference):
    scene.reset()
    m = O.materials.append(w.MesoMat(**kw))
    sp = pack.SpherePack()
    sp.makeCloud((0, 0, 0), (4e-3, 4e-3, 4e-3), rMean=5e-4, rRelFuzz=0.2, seed=5)
    sp.toSimulation(material=m)
    # a floor and four side walls: a packing even without friction
    for c, h in (((2e-3, 2e-3, -5e-4), (3e-3, 3e-3, 5e-4)),
                 ((-7.5e-4, 2e-3, 2e-3), (2.5e-4, 3e-3, 3e-3)), ((4.75e-3, 2e-3, 2e-3), (2.5e-4, 3e-3, 3e-3)),
                 ((2e-3, -7.5e-4, 2e-3), (3e-3, 2.5e-4, 3e-3)), ((2e-3, 4.75e-3, 2e-3), (3e-3, 2.5e-4, 3e-3))):
        O.bodies.append(utils.box(c, h, fixed=True, material=m))
    O.engines = scene.engines(gravity=(0, 0, -50))
    O.engines = O.engines[:3] + [w.MesoBackgroundDamping(gammaB=2e-5, gammaBR=1e-9,
                                                         reference=reference)] + O.engines[3:]
    O.dt = scene.time_step(safety=0.05)
    sort_loop()
    O.trackEnergy = True
    O.run(30000, True)


def numbers(v):
    """The numbers of a state value: a float, or the components of a vector or quaternion (the
    springs and forces); flags and enums as numbers too."""
    if isinstance(v, (bool, int, float)):
        return [float(v)]
    if isinstance(v, str):  # e.g. the branch's name: compared as text (below)
        return []
    try:
        return [float(x) for x in v]
    except (TypeError, ValueError):
        return []


def state():
    bodies = [tuple(b.state.pos) + tuple(b.state.vel) + tuple(b.state.angVel) + tuple(b.state.ori) for b in O.bodies]
    real = [i for i in O.interactions if i.isReal]
    contacts = {(i.id1, i.id2): [x for k, v in sorted(i.phys.dict().items()) for x in numbers(v)]
                if isinstance(i.phys, w.MesoPhys)
                else list(i.phys.normalForce) + list(i.phys.shearForce) for i in real}
    texts = {(i.id1, i.id2): [v for k, v in sorted(i.phys.dict().items()) if isinstance(v, str)] for i in real
             if isinstance(i.phys, w.MesoPhys)}
    return bodies, contacts, dict(O.energy.items()), texts


def largest(x, y):
    """The largest difference; inf when the two differ in bodies, contacts, state or energy names,
    or a value is NaN in one of them (a NaN would slip through max())."""
    (b1, c1, e1, t1), (b2, c2, e2, t2) = x, y
    if (len(b1) != len(b2) or set(c1) != set(c2) or set(e1) != set(e2) or any(len(c1[k]) != len(c2[k]) for k in c1)
            or t1 != t2):
        return float("inf")
    diffs = [abs(p - q) for u, v in zip(b1, b2) for p, q in zip(u, v)] + \
        [abs(p - q) for k in c1 for p, q in zip(c1[k], c2[k])] + [abs(e1[k] - e2[k]) for k in e1]
    return float("inf") if any(d != d for d in diffs) else max(diffs, default=0.0)


tmp = tempfile.mkdtemp(prefix="restart-")
result = {"command": "yade -j1 -n -x scripts/restart_check.py " + " ".join(sys.argv[1:]), "steps": a.steps,
          "sorted_loop": a.sorted, "largest_difference": {}}
scenes = [(name, lambda kw=kw, ref=ref: packing(kw, ref)) for name, (kw, ref) in MATERIALS.items()] + \
         [(name, lambda kw=kw: floor(kw)) for name, kw in FLOOR.items()]
for name, make in scenes:
    make()
    start = os.path.join(tmp, "start.yade")
    O.save(start)
    for ext in (".xml", ".xml.gz", ".xml.bz2", ".yade", ".yade.gz", ".yade.bz2"):
        for continuation in ("loaded", "live"):
            O.load(start)
            if continuation == "live":
                O.run(100, True)  # the collider's potential interactions made again, as in a running scene
            path = os.path.join(tmp, "saved" + ext)
            O.save(path)
            O.run(a.steps, True)
            direct = state()
            O.load(path)
            O.run(a.steps, True)
            d = largest(direct, state())
            result["largest_difference"].setdefault(name, {}).setdefault(continuation, {})[ext] = d
            print(f"{name:52s} {ext:9s} {continuation:6s} {O.interactions.countReal()} contacts: "
                  f"largest difference after {a.steps} steps {d:.3g}", flush=True)
if a.out:
    outputs.write_atomic(a.out, json.dumps(result, indent=1))
worst = max(v for m in result["largest_difference"].values() for c in m.values() for v in c.values())
print("largest of all:", worst)
sys.exit(0 if worst == 0 else 1)
