# ctest (inside yade): O.save / O.load in the middle of a collision continues identically (the
# contact history, the jump-in flag and the energy bookkeeping survive), in YADE's binary and XML
# formats, at three moments: loading, on the -kc branch after a history reset, and in the pull-off
# tail after contact; the contact classes survive; a file with `MesoBackgroundDamping` written by
# 798c4df (`tests/yade/golden/drag_v0.*`) loads and runs on.
import os
import tempfile

from yade import O
from mesocontact import pair, params, theory
from harness import failures, finish

r = 1.1e-3
m_r = params.sphere_mass(r, 2000) / 2
fa = params.fa_from_alpha(0.42, 100, m_r, 0.01)
mat = dict(k1=100.0, kp=500.0, kc=100.0, phiF=0.1, fa=fa, kca=100.0, adhesion="jumpIn", gammaN=1e-4)
v = 1.5 * theory.plastic_limit_velocity(100, 500, 0.1, r, m_r, fa)


def snapshot():
    i = O.interactions[0, 1] if O.interactions.has(0, 1) else None
    hist = (i.phys.deltaMax, i.phys.k2, i.phys.delta0, i.phys.touched) if (i and i.isReal) else None
    return ([(tuple(b.state.pos), tuple(b.state.vel)) for b in O.bodies], hist, O.energy.total())


def phase(moment):
    i = O.interactions[0, 1] if O.interactions.has(0, 1) else None
    if i is None or not i.isReal:
        return None
    d, p = i.geom.penetrationDepth, i.phys
    if moment == "loading":
        return d > 0 and p.deltaMax == d
    if moment == "kc-branch":  # on -kc: the force equals -kc delta (to rounding) while unloading
        return d > 0 and abs(p.hystereticForce + p.kc * d) < 1e-9 * p.kc * d and p.deltaMax < 0.9 * p.deltaMaxP
    return d < 0 and p.touched  # pull-off tail


tmp = tempfile.mkdtemp()
for moment in ("loading", "kc-branch", "tail"):
    for ext in (".yade.gz", ".xml"):
        s = pair.build(r, v, mat, track_energy=True)
        steps = 0
        while not phase(moment):
            O.step()
            steps += 1
            if steps > 200000:
                break
        if steps > 200000:
            failures.append(f"{moment}: phase never reached")
            continue
        path = os.path.join(tmp, "mid" + ext)
        hist_before = snapshot()[1]
        O.save(path)
        for _ in range(3000):
            O.step()
        direct = snapshot()
        O.load(path)
        loaded_hist = snapshot()[1]
        if moment == "loading" and ext == ".yade.gz":  # checked with the shared parameters below
            loaded_class = type(O.interactions[0, 1].phys).__name__
        for _ in range(3000):
            O.step()
        resumed = snapshot()
        ok = direct == resumed and loaded_hist == hist_before
        print(("ok   " if ok else "FAIL ") + f"{moment:10s} {ext:9s} saved at step {steps}, history {hist_before}; "
              f"identical after 3000 more steps: {direct == resumed}", flush=True)
        if not ok:
            failures.append(f"{moment} {ext}")
# All three springs (sliding, rolling, torsion) of a spinning, sliding sphere on a box (ScGeom6D).
full = dict(mat, kt=40.0, gammaT=1e-3, frictionAngle=0.3, kr=20.0, gammaR=5e-4, muR=0.1, ko=20.0, gammaO=5e-4, muO=0.1,
            phiD=0.8)


def springs():
    i = O.interactions[0, 1]
    return (tuple(i.phys.slidingSpring), tuple(i.phys.rollingSpring), i.phys.torsionSpring, tuple(i.phys.shearForce),
            tuple(i.phys.rollingForce), i.phys.torsionForce)


for ext in (".yade.gz", ".xml"):
    s = pair.build_wall(r, 0.08, full, kind="box", six_d=True, tangential_velocity=(0.05, 0.02, 0), spin=(30, -50, 80),
                        track_energy=True)
    steps = 0
    while not (O.interactions.has(0, 1) and O.interactions[0, 1].isReal
               and O.interactions[0, 1].phys.slidingSpring.norm() > 0
               and abs(O.interactions[0, 1].phys.torsionSpring) > 0 and steps > 300):
        O.step()
        steps += 1
    path = os.path.join(tmp, "springs" + ext)
    before = springs()
    O.save(path)
    for _ in range(2000):
        O.step()
    direct = snapshot()
    O.load(path)
    after_load = springs()
    for _ in range(2000):
        O.step()
    resumed = snapshot()
    ok = direct == resumed and after_load == before
    print(("ok   " if ok else "FAIL ")
          + f"springs    {ext:9s} saved at step {steps}, springs {before[:3]}; identical after 2000 more steps: "
            f"{direct == resumed}",
          flush=True)
    if not ok:
        failures.append(f"springs {ext}")
# A small packing with every mechanism and the contact-relative drag settling on a box under
# gravity: saved, loaded and continued 2000 steps it is bitwise the uninterrupted run in all six of
# YADE's file formats, every contact's state (dict()) included.
# (Where contacts form after the load, YADE's collider re-creates the potential interactions in
# another order than the uninterrupted run had them, so a body's forces are summed in another order:
# 1-ulp differences that grow. docs/usage.md, "Saved scenes", gives the measurement.)
from yade import pack, utils, wrapper as w  # noqa: E402
from mesocontact import scene  # noqa: E402

every = w.MesoMat(k1=100.0, kp=500.0, kc=20.0, phiF=0.1, fa=1e-6, kca=100.0, adhesion="jumpIn", gammaN=1e-4,
                  density=2000,
                  kt=50.0, gammaT=1e-5, frictionAngle=0.4, kr=10.0, gammaR=1e-6, muR=0.1, ko=10.0, gammaO=1e-6, muO=0.1,
                  phiD=0.8)


def settled_packing():
    scene.reset()
    m = O.materials.append(every)
    sp = pack.SpherePack()
    sp.makeCloud((0, 0, 0), (4e-3, 4e-3, 4e-3), rMean=5e-4, rRelFuzz=0.2, seed=5)
    sp.toSimulation(material=m)
    O.bodies.append(utils.box((2e-3, 2e-3, -5e-4), (3e-3, 3e-3, 5e-4), fixed=True, material=m))
    O.engines = scene.engines(gravity=(0, 0, -50))
    O.engines = O.engines[:3] + [w.MesoBackgroundDamping(gammaB=2e-5, gammaBR=1e-9)] + O.engines[3:]
    O.dt = scene.time_step(safety=0.05)
    O.trackEnergy = True
    O.run(30000, True)


def everything():
    return ([(tuple(b.state.pos), tuple(b.state.vel), tuple(b.state.angVel), tuple(b.state.ori)) for b in O.bodies],
            sorted((i.id1, i.id2, repr(sorted(i.phys.dict().items()))) for i in O.interactions if i.isReal),
            O.energy.total())


settled_packing()
base = os.path.join(tmp, "packing")
O.save(base + ".start.yade")
made = None
for ext in (".xml", ".xml.gz", ".xml.bz2", ".yade", ".yade.gz", ".yade.bz2"):
    O.load(base + ".start.yade")
    contacts = O.interactions.countReal()
    O.save(base + ext)
    O.run(2000, True)
    direct, contacts_after = everything(), O.interactions.countReal()
    O.load(base + ext)
    O.run(2000, True)
    ok = direct == everything()
    print(("ok   " if ok else "FAIL ")
          + f"packing    {ext:9s} {len(O.bodies) - 1} spheres, {contacts} -> {contacts_after} contacts "
            f"(every mechanism, drag): "
          f"bitwise after 2000 more steps: {direct == everything()}", flush=True)
    if not ok:
        failures.append(f"packing {ext}")
# Contacts of one material pair share one MesoPairParams: saved once, shared again after loading,
# and new contacts after a change of the material get new parameters (old ones keep theirs).

O.reset()
shared = w.MesoMat(k1=100.0, kp=500.0, kc=100.0, kt=50.0, frictionAngle=0.3, density=2000)
O.materials.append(shared)
O.bodies.append([utils.sphere((i * 1.9e-3, 0, 0), 1e-3, material=shared) for i in range(6)])
O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb()]),
             w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom()], [w.Ip2_MesoMat_MesoMat_MesoPhys()],
                               [w.Law2_ScGeom_MesoPhys_Meso()]),
             w.NewtonIntegrator()]
O.dt = 1e-7
O.step()
path = os.path.join(tmp, "shared.xml")
O.save(path)
xml = open(path).read()
n_params, n_contacts = xml.count("<delta0PerMaxP>"), O.interactions.countReal()  # one per saved parameter set
ok = n_contacts == 5 and n_params == 1 and xml.count("<pairParams") == n_contacts
# A pair with sliding carries the springs (MesoTangentialPhys); the collisions above had none (MesoPhys).
classes = {type(i.phys).__name__ for i in O.interactions if i.isReal}
ok = ok and classes == {"MesoTangentialPhys"} and loaded_class == "MesoPhys"
print(("ok   " if ok else "FAIL ")
      + f"shared     {n_contacts} contacts saved with {n_params} MesoPairParams; classes {classes}, "
      f"without tangential mechanisms {loaded_class}", flush=True)
if not ok:
    failures.append("shared parameters saved once")
O.load(path)
O.step()
shared = O.materials[0]
shared.kt = 80.0  # a new contact takes the new value, the old ones keep theirs
O.bodies.append(utils.sphere((-1.9e-3, 0, 0), 1e-3, material=shared))
O.step()
kts = sorted(i.phys.kt for i in O.interactions if i.isReal)
ok = kts == [50.0] * 5 + [80.0]
print(("ok   " if ok else "FAIL ")
      + f"revision   sliding stiffness of the contacts after kt = 80 on the material: {kts}", flush=True)
if not ok:
    failures.append("material change after load")
# The background drag remembers the previous step's velocities and forces for its energy
# booking: saved with the engine, the balance goes on identically after loading.
for reference in ("lab", "contacts"):
    O.reset()
    mat = w.MesoMat(k1=100.0, kp=500.0, kc=100.0, kt=50.0, frictionAngle=0.3, density=2000)
    O.materials.append(mat)
    O.bodies.append([utils.sphere((i * 1.95e-3, 0.1e-3 * (i % 2), 0), 1e-3, material=mat) for i in range(6)])
    for i, b in enumerate(O.bodies):
        b.state.vel = (0.01 * (-1) ** i, 0.002 * i, 0)
    O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb()]),
                 w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom()], [w.Ip2_MesoMat_MesoMat_MesoPhys()],
                                   [w.Law2_ScGeom_MesoPhys_Meso()]),
                 w.MesoBackgroundDamping(gammaB=2e-3, gammaBR=2e-3, reference=reference), w.NewtonIntegrator(damping=0)]
    O.dt = 1e-6
    O.trackEnergy = True
    O.run(300, True)
    path = os.path.join(tmp, f"drag-{reference}.yade.gz")
    O.save(path)
    O.run(500, True)
    direct = {k: O.energy[k] for k in O.energy.keys()}
    O.load(path)
    O.run(500, True)
    resumed = {k: O.energy[k] for k in O.energy.keys()}
    ok = direct == resumed and direct.get("mesoBackground", 0) > 0
    print(("ok   " if ok else "FAIL ")
          + f"drag       reference '{reference}': energies identical 500 steps after loading: {direct == resumed} "
          f"(mesoBackground {direct.get('mesoBackground', 0):.9e} / {resumed.get('mesoBackground', 0):.9e})",
          flush=True)
    if not ok:
        failures.append(f"background drag energy after load ({reference})")
# A file written by the plugin of commit 798c4df, before MesoBackgroundDamping had sumInLaw (a new
# attribute must not shift the binary layout: such a file failed with "vector::_M_default_append"
# when sumInLaw was saved): it loads with its values and goes on, the law gathering the sums.
import json  # noqa: E402
from yade import wrapper as _w  # noqa: E402
HERE = os.path.dirname(os.path.abspath(__import__("harness").__file__))
with open(os.path.join(HERE, "golden", "drag_v0.json")) as f:
    v0 = json.load(f)
O.load(os.path.join(HERE, "golden", "drag_v0.yade.gz"))
drag = [e for e in O.engines if isinstance(e, _w.MesoBackgroundDamping)][0]
kept = ((drag.gammaB, drag.gammaBR, drag.reference, len(O.bodies), O.iter)
        == (v0["gammaB"], v0["gammaBR"], v0["reference"], v0["bodies"], v0["iter"])
        and O.energy["mesoBackground"] == v0["mesoBackground"])
O.run(100, True)
ok = kept and drag.sumInLaw and drag.lawSumSteps == 99 and O.energy["mesoBackground"] > v0["mesoBackground"]
print(("ok   " if ok else "FAIL ")
      + f"drag       a file of the first layout (798c4df) loads with its values ({kept}) and runs on, "
      f"the law gathering the sums in {drag.lawSumSteps} of 100 steps", flush=True)
if not ok:
    failures.append("drag file of the first layout")
finish()
