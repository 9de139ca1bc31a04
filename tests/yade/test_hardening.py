# ctest (inside yade): what must not crash or go silently wrong, the faults of `docs/hardening/`
# (issue #14's items 1-4, 6, 7, 11): hand-made or mismatched contacts, overflow, density, overlapped
# starts, the stable time step (`Ip2.stableDt`) and its warning, the pair driver's own checks, wrong
# types named; values outside 1e-100 … 1e100 refused naming the parameter, mixing at those limits
# finite, and one warning for contacts born deeper than a radius.
#
# What must not crash or go silently wrong (issue #14's items 1-4, 6, 7, 11).
# - a MesoPhys assigned from Python to a live contact is dropped with a warning and remade by the
#   Ip2 (it used to crash: no pair parameters);
# - a saved plain MesoPhys whose pair has tangential mechanisms is refused on load, naming the class;
# - mixing huge finite parameters gives the harmonic mean, not inf/NaN;
# - density and young are validated (constructor, assignment, updateAttrs); a rejected updateAttrs
#   leaves every attribute as it was, frictionAngle to the bit;
# - spheres that start overlapped store energy (mesoElastic), they do not dissipate a negative amount;
# - the Ip2's stableDt is the leapfrog stability bound of the stiffest element (checked against the
#   spectral radius of the integrator's amplification matrix, computed here), and O.dt above it warns.
import math
import os
import tempfile

import numpy as np
from yade import O, utils
from yade.wrapper import (ForceResetter, InsertionSortCollider, Bo1_Sphere_Aabb, InteractionLoop,
                          Ig2_Sphere_Sphere_ScGeom,
                          Ig2_Sphere_Sphere_ScGeom6D, Ip2_MesoMat_MesoMat_MesoPhys, Law2_ScGeom_MesoPhys_Meso,
                          NewtonIntegrator,
                          MesoMat, MesoPhys, MesoTangentialPhys)
from harness import Stderr, check, finish


A, RHO = 1e-3, 2000.0
MASS = 4 / 3 * math.pi * A ** 3 * RHO


def two_spheres(mat, overlap=0.0, v=0.0, dt=1e-6, six=False):
    O.reset()
    m = O.materials.append(mat)
    O.bodies.append([utils.sphere((0, 0, 0), A, material=m), utils.sphere((2 * A - overlap, 0, 0), A, material=m)])
    O.bodies[1].state.vel = (-v, 0, 0)
    ig2 = Ig2_Sphere_Sphere_ScGeom6D() if six else Ig2_Sphere_Sphere_ScGeom()
    ip2 = Ip2_MesoMat_MesoMat_MesoPhys()
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([ig2], [ip2], [Law2_ScGeom_MesoPhys_Meso()]),
                 NewtonIntegrator(damping=0)]
    O.dt = dt
    return ip2


# 1. A MesoPhys made in Python on a live contact.
two_spheres(MesoMat(k1=100, kp=500, density=RHO), overlap=1e-5)
O.step()
O.interactions[0, 1].phys = MesoPhys()
with Stderr() as err:
    O.step()
    O.step()
i = O.interactions[0, 1]
check(i.isReal and i.phys.kp == 500 and math.isfinite(i.phys.normalForce.norm()) and "adoptMaterials" in err.text
      and err.text.count("WARNING") == 1, "hand-made MesoPhys: warned once, dropped and remade by the Ip2",
      f"real {i.isReal}, kp {i.phys.kp}")
two_spheres(MesoMat(k1=100, kp=500, density=RHO, kt=50, frictionAngle=0.3), overlap=1e-5)
O.step()
O.interactions[0, 1].phys = MesoTangentialPhys()
O.step()
O.step()
check(type(O.interactions[0, 1].phys).__name__ == "MesoTangentialPhys" and O.interactions[0, 1].phys.kt == 50,
      "hand-made MesoTangentialPhys: remade")

# 1b. The same under O.run (the law in YADE's engine thread with the GIL released: dropping the
#     Python-made object there aborted the interpreter), and other IPhys classes on a meso contact
#     (the law took them for a MesoPhys: a segfault), on plain and tangential pairs.
import yade.wrapper as W  # noqa: E402
for tangential in (False, True):
    kw = dict(kt=50, frictionAngle=0.3) if tangential else {}
    want = "MesoTangentialPhys" if tangential else "MesoPhys"
    for cls in ("MesoPhys", "MesoTangentialPhys", "FrictPhys", "NormShearPhys", "ViscElPhys", "RotStiffFrictPhys",
                "IPhys"):
        two_spheres(MesoMat(k1=100, kp=500, density=RHO, **kw), overlap=1e-5, six=tangential)
        O.step()
        O.interactions[0, 1].phys = getattr(W, cls)()
        with Stderr() as err:
            O.run(100, True)
        i = O.interactions[0, 1]
        check(i.isReal and type(i.phys).__name__ == want and f"has a {cls} not made" in err.text
              and err.text.count("WARNING") == 1
              and math.isfinite(i.phys.normalForce.norm()),
              f"{cls} on a live {'tangential' if tangential else 'plain'} contact under O.run: warned, "
              f"dropped, remade as {want}")

# 2. A saved plain MesoPhys whose pair parameters have tangential mechanisms (the file edited).
two_spheres(MesoMat(k1=100, kp=500, density=RHO), overlap=1e-5, dt=1e-5)
O.step()
with tempfile.TemporaryDirectory() as d:
    good, bad = os.path.join(d, "good.xml"), os.path.join(d, "bad.xml")
    O.save(good)
    text = open(good).read()
    n = text.count("<tangential>0</tangential>")
    open(bad, "w").write(text.replace("<tangential>0</tangential>", "<tangential>1</tangential>"))
    try:
        O.load(bad)
        check(False, "plain MesoPhys with tangential pair parameters refused on load", "loaded")
    except RuntimeError as e:
        # the pair's own check (its flags must follow its elements) sees it first; the class check stays behind it
        check(n == 1 and ("plain MesoPhys" in str(e) or "tangential flags are invalid" in str(e)),
              "plain MesoPhys with tangential pair parameters refused on load", str(e)[:80])
    O.load(good)
    O.step()
    check(O.interactions[0, 1].phys.kp == 500, "the unedited file still loads and runs")

# 3. Mixing at the limits of the accepted values (1e-100 ... 1e100): the harmonic mean 2/(1/x + 1/y),
#    written independently, stays finite (2xy/(x+y) itself would overflow from ~1e154 on); values
#    beyond are refused, naming the parameter (k1 = kp = 1e200 gave a NaN plastic energy, kp = 1e308 a
#    stable step 0, fa = 1e300 an infinite kinetic energy, density 1e-310 NaN positions).
for x, y in ((1e99, 1e99), (1e99, 1e100), (1e-100, 3e-100)):
    two_spheres(MesoMat(k1=x, kp=y, density=RHO), overlap=1e-6, dt=1e-60)
    O.bodies[0].material = O.materials[O.materials.append(MesoMat(k1=y, kp=y, density=RHO))]
    O.step()
    p = O.interactions[0, 1].phys
    hm = 2 / (1 / x + 1 / y)
    f = max(abs(c) for c in p.normalForce)
    check(abs(p.k1 - hm) <= 1e-15 * hm and abs(p.kp - y) <= 1e-15 * y and math.isfinite(p.k2) and math.isfinite(f)
          and f > 0,
          f"mixing k1 = {x:g} with {y:g}",
          f"k1 {p.k1:.6g} (harmonic mean {hm:.6g}), kp {p.kp:.6g}, k2 {p.k2:.6g}, |F| {f:.3g}")
for kw, name in ((dict(k1=1e200, kp=1e200), "k1"), (dict(kp=1e308), "kp"), (dict(kt=1e308), "kt"),
                 (dict(fa=1e300, kca=1.0, adhesion="reversible"), "fa"), (dict(density=1e-310), "density"),
                 (dict(gammaN=1e-320), "gammaN")):
    try:
        MesoMat(**kw)
        check(False, f"MesoMat({kw}) refused", "accepted")
    except (ValueError, RuntimeError) as e:
        check(str(e).startswith(f"{name} = "), f"MesoMat({kw}) refused, naming {name}", str(e)[:120])

# 4 and 11. density and young, and rejected assignments that leave everything as it was.
for kw in (dict(density=0), dict(density=-1), dict(density=float("nan")), dict(density=float("inf")), dict(young=0),
           dict(young=-1e9), dict(young=float("nan"))):
    name = next(iter(kw))
    try:
        MesoMat(**kw)
        check(False, f"MesoMat({kw}) rejected", "accepted")
    except ValueError as e:
        check(str(e).startswith(name + " = "), f"MesoMat({kw}) rejected, naming it", str(e))
m = MesoMat(density=1234.0, young=2e9)
for name, value in (("density", -3.0), ("young", float("inf"))):
    try:
        setattr(m, name, value)
        check(False, f"{name} = {value} on assignment rejected", "accepted")
    except ValueError:
        check(m.density == 1234.0 and m.young == 2e9, f"{name} = {value} on assignment rejected, value kept")
rng = np.random.default_rng(7)
changed = 0
for _ in range(500):
    angle = float(rng.uniform(0, 1.5))
    m = MesoMat(frictionAngle=angle, density=1500.0, k1=100, kp=500)
    before = (m.frictionAngle, m.density, m.k1, m.kp)
    try:
        m.updateAttrs({"density": 99.0, "frictionAngle": 0.2, "kp": -1.0})
    except ValueError:
        pass
    changed += (m.frictionAngle, m.density, m.k1, m.kp) != before
check(changed == 0, "a rejected updateAttrs leaves density, frictionAngle (bitwise), k1, kp as they were",
      f"{changed} of 500 changed")

# 13. Wrong types name the attribute (TypeError), in the constructor, on assignment and in
# updateAttrs (which then changes nothing); Boost.Python's own message named none.
from yade.wrapper import MesoBackgroundDamping  # noqa: E402

for label, make in (("MesoMat(k1='abc')", lambda: MesoMat(k1="abc")), ("MesoMat(kp=None)", lambda: MesoMat(kp=None)),
                    ("MesoMat(adhesion=0)", lambda: MesoMat(adhesion=0)),
                    ("MesoMat(dominant='yes')", lambda: MesoMat(dominant="yes")),
                    ("MesoMat(density=[1])", lambda: MesoMat(density=[1])),
                    ("Ip2(leverArm=3)", lambda: Ip2_MesoMat_MesoMat_MesoPhys(leverArm=3)),
                    ("MesoBackgroundDamping(gammaB='x')", lambda: MesoBackgroundDamping(gammaB="x"))):
    name = label.split("(")[1].split("=")[0]
    try:
        make()
        check(False, f"{label} refused", "accepted")
    except TypeError as e:
        check(str(e).startswith(name + " = "), f"{label}: TypeError naming it", str(e))
m = MesoMat(k1=10.0, kp=50.0, kc=5.0)
for name, value in (("k1", "abc"), ("kp", True), ("adhesion", 0), ("frictionAngle", None), ("young", "1e9")):
    try:
        setattr(m, name, value)
        check(False, f"m.{name} = {value!r} refused", "accepted")
    except TypeError as e:
        check(str(e).startswith(name + " = ") and (m.k1, m.kp) == (10.0, 50.0),
              f"m.{name} = {value!r}: TypeError naming it", str(e))
try:
    m.updateAttrs({"kc": 7.0, "gammaO": None})
    check(False, "updateAttrs with a wrong type refused", "accepted")
except TypeError as e:
    check(str(e).startswith("gammaO = ") and m.kc == 5.0, "updateAttrs with a wrong type: names it, changes nothing",
          f"{e}; kc {m.kc}")
try:
    MesoBackgroundDamping(gammaB=1.0).gammaB = -1.0
    check(False, "gammaB = -1 on assignment refused", "accepted")
except ValueError as e:
    check("gammaB = -1" in str(e), "gammaB = -1 on assignment refused, naming it", str(e))

# 6. Spheres that start overlapped, at rest: the stored energy is the initial state. Fresh contact
# at overlap d: force k1 d, unloading line k2(d) (linear interpolation), so E0 = (k1 d)^2 / (2 k2).
k1, kp, phiF = 100.0, 500.0, 0.1
a12 = A  # equal spheres: 2 a a/(a + a)
d = 0.02 * A
k2 = k1 + (kp - k1) * d / (kp / (kp - k1) * phiF * a12)
E0 = (k1 * d) ** 2 / (2 * k2)
tc = math.pi * math.sqrt(MASS / 2 / k2)
for steps_per_contact in (100, 400):
    two_spheres(MesoMat(k1=k1, kp=kp, phiF=phiF, density=RHO), overlap=d, dt=tc / steps_per_contact)
    O.trackEnergy = True
    O.step()
    e1 = O.energy.total()
    worst = 0.0
    for _ in range(2 * steps_per_contact):
        O.step()
        worst = max(worst, abs(O.energy.total() - e1))
    kin = sum(0.5 * b.state.mass * b.state.vel.squaredNorm() for b in O.bodies)
    plastic = O.energy["mesoPlastic"]
    # The trapezoidal work misses the kink where the force reaches zero between two steps: at most
    # k2 dd^2 / 2 with dd = v dt, v^2 = 2 E0 / m_r, i.e. (omega dt)^2 E0 = (pi / steps)^2 E0.
    tol = (math.pi / steps_per_contact) ** 2
    apart = not O.interactions.has(0, 1) or not O.interactions[0, 1].isReal
    check(apart and abs(plastic) <= tol * E0 and abs(e1 - E0) <= 1e-12 * E0 and worst <= 1e-9 * E0
          and abs(kin - E0) <= tol * E0,
          f"overlapped start, {steps_per_contact} steps per contact: energy stored, not dissipated",
          f"mesoPlastic/E0 {plastic / E0:.1e}, E(step 1)/E0 - 1 {e1 / E0 - 1:.1e}, drift {worst / E0:.1e}, final "
          f"E_kin/E0 - 1 {kin / E0 - 1:.1e}")


# 7. The stable step against the integrator's own stability: YADE's leapfrog advances
# v' = v (1 - g dt/m) - k x dt/m, x' = x + v' dt; stable while the spectral radius is <= 1.
def leapfrog_bound(k, g, m):
    def radius(dt):
        c = g * dt / m
        amp = np.array([[1 - k * dt * dt / m, dt * (1 - c)], [-k * dt / m, 1 - c]])
        return max(abs(np.linalg.eigvals(amp)))
    lo, hi = 0.0, 10 * math.sqrt(m / k)
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if radius(mid) <= 1 + 1e-12 else (lo, mid)
    return lo


m_r = MASS / 2
for gamma in (0.0, 3e-3):
    ip2 = two_spheres(MesoMat(k1=100, kp=500, gammaN=gamma, density=RHO), overlap=1e-6)
    O.step()
    ref = leapfrog_bound(500, gamma, m_r)
    check(abs(ip2.stableDt - ref) <= 1e-9 * ref, f"stableDt, normal kp, gamma0 = {gamma}",
          f"{ip2.stableDt:.9e} vs {ref:.9e}")
# Rolling much stiffer than the normal law: v_r = a'(w1 - w2), torque a' f_r on each sphere, a' = a/2.
I = 0.4 * MASS * A * A
ip2 = two_spheres(MesoMat(k1=100, kp=500, kr=1e5, gammaR=1e-3, muR=0.1, density=RHO), overlap=1e-6, six=True)
O.step()
ref = leapfrog_bound(1e5, 1e-3, 1 / ((A / 2) ** 2 * 2 / I))
check(abs(ip2.stableDt - ref) <= 1e-9 * ref, "stableDt, stiff rolling", f"{ip2.stableDt:.9e} vs {ref:.9e}")
# Above the bound: one warning, naming the contact.
ip2 = two_spheres(MesoMat(k1=100, kp=500, density=RHO), v=0.01, dt=1.0)
ip2.stableDt  # inf before any contact
O.dt = 1.5 * leapfrog_bound(500, 0, m_r)
with Stderr() as err:
    O.run(20, True)
check("exceeds the stable step" in err.text and "#0+#1" in err.text,
      "O.dt above the stable step warns, naming the contact")
ip2 = two_spheres(MesoMat(k1=100, kp=500, density=RHO), v=0.01)
O.dt = 0.5 * leapfrog_bound(500, 0, m_r)
with Stderr() as err:
    O.run(20, True)
check("exceeds" not in err.text, "O.dt below it: no warning")

# #15: reversible adhesion without detection at the gap warns once; with it (pair.build) it does not.
rev = dict(k1=100.0, kp=500.0, fa=1e-5, kca=50.0, adhesion="reversible", density=RHO)
two_spheres(MesoMat(**rev), overlap=-5e-6, v=0.05, dt=1e-6)  # a gap beyond the range 2e-7; YADE's default detection
with Stderr() as err:
    O.run(300, True)
check("pull-in over the range" in err.text and err.text.count("pull-in") == 1,
      "reversible adhesion detected only in contact: warned")
from mesocontact import pair as _pair  # noqa: E402

with Stderr() as err:
    _pair.collide(_pair.build(A, 0.05, rev))
check("pull-in" not in err.text, "reversible adhesion detected at the gap (pair.build): no warning")

# 8 and 12. The pair drivers check their arguments and their own results.
from mesocontact import pair  # noqa: E402

mat = dict(k1=100.0, kp=500.0, kc=100.0, phiF=0.1)


def refused(label, exc, name, f, *args, **kw):
    try:
        f(*args, **kw)
        check(False, label, "no exception")
    except exc as e:
        check(name in str(e), label, str(e)[:110])


for dt in (0, -1e-7, float("nan"), float("inf")):
    refused(f"pair.build(dt={dt}) refused", ValueError, "dt = ", pair.build, 1e-3, 0.05, mat, dt=dt)
refused("pair.build(gap=-1e-3) refused", ValueError, "gap = ", pair.build, 1e-3, 0.05, mat, gap=-1e-3)
refused("pair.collide at 100 m/s refused (tunnelling)", ValueError, "too fast",
        lambda: pair.collide(pair.build(1e-3, 100.0, mat)))
refused("pair.collide with gap = 1 m refused (budget)", ValueError, "max_steps",
        lambda: pair.collide(pair.build(1e-3, 0.05, mat, gap=1.0)))
rev = dict(mat, fa=1e-5, kca=50.0, adhesion="reversible")
refused("pair.collide at 1e-9 m/s across a reversible range, refused (budget)", ValueError, "max_steps",
        lambda: pair.collide(pair.build(1e-3, 1e-9, rev)))
# Jump-in pairs feel nothing before the first touch, so they start 3 v dt apart: the same slow
# approach is cheap and ends stuck (the pull-off tail holds it).
r = pair.collide(pair.build(1e-3, 1e-9, dict(rev, adhesion="jumpIn")))
check(r.stuck and r.steps < 1e6, "pair.collide at 1e-9 m/s, jump-in: starts close, sticks", f"{r.steps} steps")
refused("pair.collide after build_wall(v_inf=0) refused", ValueError, "v_inf",
        lambda: pair.collide(pair.build_wall(1e-3, 0.0, mat)))
s = pair.build(1e-3, 0.05, mat, gap=2e-5)
O.bodies[0].state.vel, O.bodies[1].state.vel = (0, 0, 0), (0, 1e-2, 0)  # sideways: they never meet
refused("a pair that never touches is reported", RuntimeError, "never came into contact", pair.collide, s,
        max_contact_times=3)
# The start gap and the separation test come from the Ip2's own mixing (a dominant wall here).
wall = MesoMat(k1=100.0, kp=500.0, fa=4e-5, kca=100.0, adhesion="reversible", dominant=True, density=RHO)
s = pair.build_wall(1e-3, 0.05, dict(mat, fa=1e-5, kca=50.0, adhesion="reversible"), wall_material=wall)
O.run(5, True)
i = O.interactions[s.ids]
check(i.isReal and s.delta_a == i.phys.deltaA == -4e-5 / 100.0,
      "pair.build_wall: delta_a of a dominant wall is the contact's deltaA",
      f"{s.delta_a} vs {i.phys.deltaA}")
O.tags["description"] = "job 1"
pair.build(1e-3, 0.05, mat)
check(O.tags["description"] == "job 1", "pair.build keeps O.tags (yade-batch's description)")

# #32 item 10: a contact born deeper than a radius (energy from nothing) is named once; one within
# the law's range (a tenth of a radius) is not.
for depth, warned in ((1.5 * A, True), (0.1 * A, False)):
    two_spheres(MesoMat(k1=100.0, kp=500.0, density=RHO), overlap=depth, dt=1e-7)
    # a second such pair: still one warning
    O.bodies.append([utils.sphere((0, 5 * A, 0), A, material=0),
                     utils.sphere((2 * A - depth, 5 * A, 0), A, material=0)])
    with Stderr() as err:
        O.run(3, True)
    said = err.text.count("deeper than the radius")
    check(said == (1 if warned else 0),
          f"overlap {depth / A:g} radius at the start: {'one warning' if warned else 'no warning'}",
          err.text.strip()[:160])

finish()
