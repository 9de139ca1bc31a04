# ctest (inside yade): golden regression: 27 pressed spheres of two unlike materials (both adhesion
# modes, both k2 rules) on a dominant adhesive wall with every mechanism on, 3000 steps on one
# thread; every contact's history, springs and forces, every body's state and every energy term
# equal to `tests/yade/golden/golden.json` to 1e-12 of the quantity's largest value. After a
# deliberate change of the law: `build/yade-meso -j1 -n -x tests/yade/test_golden.py --regenerate`
# (with `PYTHONPATH=tests/yade`), and say why in the commit.
#
# Golden regression. A small scene with every mechanism on (hysteresis with
# both interpolations, reversible and jump-in adhesion, viscosity, sliding, rolling and torsion with
# their dashpots, a dominant adhesive wall, unlike materials and radii, the background drag relative
# to the contacts, gravity) runs 3000 steps on one thread; every contact's history, springs and
# forces and every body's state must equal the stored ones to 1e-12 (relative to each quantity's
# largest value in the scene). Any change of the law's arithmetic shows here, however small
# against the closed-form tests' 1e-3 (e.g. the contact arm a - delta/2 written a - 0.4 delta).
# To regenerate on purpose, after a deliberate change of the law:
#   build/yade-meso -j1 -n -x tests/yade/test_golden.py --regenerate
import json
import math
import os
import sys

from yade import O, utils
from yade import wrapper as w
from mesocontact import scene
from harness import check, finish

import harness  # noqa: E402  (this directory, on PYTHONPATH under ctest)

HERE = os.path.dirname(os.path.abspath(harness.__file__))
GOLDEN = os.path.join(HERE, "golden", "golden.json")
STEPS = 3000
PHYS = ("deltaMax", "delta0", "k2", "touched", "hystereticForce", "adhesiveForce", "viscousForce", "normalForce",
        "shearForce", "slidingSpring", "rollingSpring", "rollingForce", "rollingTorque", "torsionSpring",
        "torsionForce",
        "torsionTorque")


def build():
    scene.reset()
    common = dict(k1=100.0, kp=500.0, kc=50.0, phiF=0.1, gammaN=2e-4, density=2000.0, frictionAngle=math.atan(0.5),
                  phiD=0.8, kt=40.0, gammaT=5e-5, kr=10.0, gammaR=1e-5, muR=0.1, ko=10.0, gammaO=1e-5, muO=0.1)
    a = w.MesoMat(fa=5e-6, kca=50.0, adhesion="reversible", **common)
    b = w.MesoMat(fa=5e-6, kca=50.0, adhesion="jumpIn", k2Interpolation="sqrt", **dict(common, kp=800.0))
    wall = w.MesoMat(fa=2e-5, kca=100.0, adhesion="reversible", dominant=True, **dict(common, kp=1000.0, k1=200.0))
    O.materials.append([a, b, wall])
    # a 3 x 3 x 3 block of pressed spheres, radii 0.5 and 0.45 mm on a checkerboard (1e-5 m overlaps),
    # the lowest layer pressed into the wall, the materials alternating along x
    for i in range(3):
        for j in range(3):
            for k in range(3):
                r = 0.5e-3 if (i + j + k) % 2 else 0.45e-3
                c = ((i - 1) * 0.94e-3, (j - 1) * 0.94e-3, 0.47e-3 + k * 0.94e-3 - 2e-5)
                O.bodies.append(utils.sphere(c, r, material=a if i % 2 else b))
    O.bodies.append(utils.box((0, 0, -0.5e-3), (6e-3, 6e-3, 0.5e-3), material=wall, fixed=True))
    for k, body in enumerate(O.bodies):
        if body.dynamic:
            body.state.vel = (0.01 * math.sin(k), 0.01 * math.cos(3 * k), -0.03)
            body.state.angVel = (20 * math.cos(k), 20 * math.sin(2 * k), 30 * math.sin(k))
    O.engines = [
        w.ForceResetter(),
        w.InsertionSortCollider([w.Bo1_Sphere_Aabb(), w.Bo1_Box_Aabb()]),
        w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom6D(), w.Ig2_Box_Sphere_ScGeom6D()],
                          [w.Ip2_MesoMat_MesoMat_MesoPhys()],
                          [w.Law2_ScGeom_MesoPhys_Meso()]),
        w.MesoBackgroundDamping(gammaB=1e-5, gammaBR=1e-5, reference="contacts"),
        w.NewtonIntegrator(damping=0, gravity=(0, 0, -9.81)),
    ]
    scene.set_detection()
    O.dt = scene.time_step(safety=0.05)


def snapshot():
    def vec(v):
        return [float(x) for x in v] if hasattr(v, "__len__") else float(v)
    contacts = {}
    for i in O.interactions:
        if i.isReal:
            contacts[f"{i.id1}-{i.id2}"] = {k: vec(getattr(i.phys, k)) for k in PHYS if hasattr(i.phys, k)}
    bodies = {str(b.id): {"pos": vec(b.state.pos), "vel": vec(b.state.vel), "angVel": vec(b.state.angVel)}
              for b in O.bodies if b.dynamic}
    return {"steps": STEPS, "dt": O.dt, "contacts": contacts, "bodies": bodies,
            "energy": {k: O.energy[k] for k in sorted(O.energy.keys())}}


build()
O.trackEnergy = True
O.run(STEPS, True)
now = snapshot()
if "--regenerate" in sys.argv[1:]:
    os.makedirs(os.path.dirname(GOLDEN), exist_ok=True)
    with open(GOLDEN, "w") as f:
        json.dump(now, f, indent=0, sort_keys=True)
    print(f"wrote {GOLDEN}: {len(now['contacts'])} contacts, {len(now['bodies'])} bodies")
    sys.exit(0)
with open(GOLDEN) as f:
    ref = json.load(f)


def flat(x):
    return x if isinstance(x, list) else [x]


check(set(now["contacts"]) == set(ref["contacts"]), "the same contacts exist",
      f"{len(now['contacts'])} now, {len(ref['contacts'])} stored; differ: "
      f"{sorted(set(now['contacts']) ^ set(ref['contacts']))[:6]}")
check(now["dt"] == ref["dt"], "the same time step", f"{now['dt']!r} vs {ref['dt']!r}")
kinds = {k for c in ref["contacts"].values() for k in c}
touched_mech = {"rollingSpring", "torsionSpring", "slidingSpring", "adhesiveForce", "viscousForce"}
check(touched_mech <= kinds, "the stored scene exercises springs, adhesion and viscosity", str(sorted(kinds)))
for k in sorted(kinds):
    scale = max((abs(x) for c in ref["contacts"].values() if k in c for x in flat(c[k])), default=0.0) or 1.0
    worst = 0.0
    for key, c in ref["contacts"].items():
        if key in now["contacts"] and k in c:
            worst = max(worst, max(abs(a - b) for a, b in zip(flat(now["contacts"][key][k]), flat(c[k]))) / scale)
    check(worst <= 1e-12, f"contacts' {k} as stored", f"worst {worst:.1e} of its largest value {scale:.3e}")
for k in ("pos", "vel", "angVel"):
    scale = max(abs(x) for b in ref["bodies"].values() for x in b[k])
    worst = max(abs(a - b)
                for key, body in ref["bodies"].items() for a, b in zip(now["bodies"][key][k], body[k])) / scale
    check(worst <= 1e-12, f"bodies' {k} as stored", f"worst {worst:.1e} of {scale:.3e}")
scale = max(abs(v) for v in ref["energy"].values())
worst = max(abs(now["energy"].get(k, 0.0) - v) for k, v in ref["energy"].items()) / scale
check(worst <= 1e-12, "energy terms as stored", f"worst {worst:.1e} of {scale:.3e}")
finish()
