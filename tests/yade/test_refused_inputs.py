# ctest (inside yade): what a user can feed the plugin through files and `updateAttrs` is refused
# naming the field (issue #32 items 3, 5, 6, 12; #57): edited saved contacts and engines refused on
# load, `updateAttrs` all-or-nothing, the pair drivers' step checks, the Ip2's Python methods naming
# the argument they refuse (ids out of range, None, strings), numpy numbers taken as numbers and
# numpy's `bool_` refused.
#
# What a user can feed the plugin through files and updateAttrs is refused with
# a message naming the field, not run on (issue #32 items 3, 5, 6, 12):
# - the Ip2's Python methods name the argument they refuse; numpy numbers are numbers;
# - updateAttrs with an unknown name or a wrong type of an inherited attribute (poisson, label, id)
#   changes nothing (kc = -5 was kept when 'poisson' was 'abc');
# - a saved contact whose pair parameters or state were edited (kp = nan or -500, k1 = inf or 0,
#   an adhesion mode of 9, deltaA, invDeltaMaxP = nan, deltaMax = nan, lastDelta = inf) does not load;
#   the unedited file still loads and runs;
# - a saved MesoBackgroundDamping whose bookkeeping vectors have different lengths runs (it
#   segfaulted), its energy balance intact;
# - the pair drivers refuse a step above the pair's stable step (a collision there made e = 6.9),
#   naming what set it (dt or steps_per_contact), and a radius whose mass leaves floating point.
# - (issue #57 items 3, 5) scene.engines' gravity: NaN was taken (NaN positions followed), None or a
#   pair gave Boost's unnamed converter error; export_contacts' base and number; scripts/restart_check.py
#   --steps 0 or less ran forever and an unwritable --out failed only after the whole run.
import math
import os
import re
import tempfile

from yade import O, utils
from yade.wrapper import (ForceResetter, InsertionSortCollider, Bo1_Sphere_Aabb, InteractionLoop,
                          Ig2_Sphere_Sphere_ScGeom6D,
                          Ip2_MesoMat_MesoMat_MesoPhys, Law2_ScGeom_MesoPhys_Meso, NewtonIntegrator, MesoMat,
                          MesoBackgroundDamping,
                          MesoContactStore)
from harness import check, finish

A, RHO = 1e-3, 2000.0

# 1. updateAttrs: every name known and every type right before any value is set.
for attrs, error, named in (({"kc": -5.0, "poisson": "abc"}, TypeError, "poisson"),
                            ({"k1": float("nan"), "nonexistent": 1}, AttributeError, "nonexistent"),
                            ({"kp": 1.0, "label": 3}, TypeError, "label"), ({"kc": 2.0, 7: 1}, AttributeError, "7"),
                            ({"kc": -1.0, "id": float("nan")}, TypeError, "id"),
                            ({"phiF": 0.5, "id": [None]}, TypeError, "id"),
                            ({"kc": 3.0, "id": 2 ** 40}, ValueError, "id"),
                            # valid types, a refused value: the inherited ones set before it are undone too (the fuzz
                            # found poisson kept)
                            ({"fa": 3.6e-3, "poisson": 0.3, "label": "x"}, ValueError, "kca")):
    m = MesoMat(k1=100, kp=500, kc=100, poisson=0.25, label="grain")
    try:
        m.updateAttrs(attrs)
        check(False, f"updateAttrs({attrs}) refused", "accepted")
    except error as e:
        check(named in str(e) and (m.k1, m.kp, m.kc, m.poisson, m.label) == (100, 500, 100, 0.25, "grain"),
              f"updateAttrs({attrs}): {error.__name__} naming {named}, nothing changed", str(e))
m.updateAttrs({"kc": 50.0, "poisson": 0.3, "label": "wall"})
check((m.kc, m.poisson, m.label) == (50.0, 0.3, "wall"), "updateAttrs with valid inherited attributes sets them")
for bad in ({"poisson": "abc"}, {"label": 3}):
    try:
        MesoMat(**bad)
        check(False, f"MesoMat({bad}) refused", "accepted")
    except TypeError as e:
        check(str(e).startswith(list(bad)[0] + " = "), f"MesoMat({bad}): TypeError naming it", str(e))


# 2. A saved contact, edited.
def pair_scene(drag=False):
    O.reset()
    m = O.materials.append(MesoMat(k1=100, kp=500, kc=20, phiF=0.1, fa=1e-5, kca=100, adhesion="jumpIn", density=RHO,
                                   kt=50, frictionAngle=0.3, kr=10, muR=0.1))
    O.bodies.append([utils.sphere((0, 0, 0), A, material=m), utils.sphere((2 * A - 2e-5, 0, 0), A, material=m)])
    O.bodies[1].state.vel = (-0.01, 0.002, 0)
    O.engines = ([ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                  InteractionLoop([Ig2_Sphere_Sphere_ScGeom6D()], [Ip2_MesoMat_MesoMat_MesoPhys()],
                                  [Law2_ScGeom_MesoPhys_Meso()])]
                 + ([MesoBackgroundDamping(gammaB=1e-3, gammaBR=1e-4)] if drag else []) + [NewtonIntegrator(damping=0)])
    O.dt = 1e-6
    O.trackEnergy = True
    O.run(50, True)


pair_scene()
with tempfile.TemporaryDirectory() as d:
    good = os.path.join(d, "good.xml")
    O.save(good)
    text = open(good).read()

    def tag(name, value, within):
        """text with <name>...</name>'s content replaced inside the first <within ...> block (the
        pair's <params>, the contact's <history> or <geometry>; MesoMat has its own k1, kp)."""
        block = re.search(rf"<{within}[ >].*?</{within}>", text, re.S)
        h = re.search(rf"<{name}>([^<]*)</{name}>", block.group(0))
        start = block.start() + h.start(1)
        return text[:start] + value + text[block.start() + h.end(1):]

    for name, value, within in (("kp", "nan", "params"), ("kp", "-500", "params"), ("k1", "inf", "params"),
                                ("k1", "0", "params"),
                                ("adhesion", "9", "params"), ("deltaA", "-1", "params"),
                                ("invDeltaMaxP", "nan", "geometry"),
                                ("deltaMax", "nan", "history"), ("lastDelta", "inf", "lastDelta"),
                                ("radius1", "-1", "geometry")):
        bad = os.path.join(d, f"bad-{name}-{value}.xml")
        open(bad, "w").write(tag(name, value, within) if within != name  # lastDelta is a plain member of the contact
                             else re.sub(rf"<{name}>[^<]*</{name}>", f"<{name}>{value}</{name}>", text, count=1))
        try:
            O.load(bad)
            check(False, f"saved {name} = {value} refused on load", "loaded")
        except RuntimeError as e:
            check(f"{name} = " in str(e) and "saved contact" in str(e), f"saved {name} = {value} refused on load",
                  str(e)[:120])
    O.load(good)
    O.run(10, True)
    check(O.interactions[0, 1].isReal and math.isfinite(O.interactions[0, 1].phys.normalForce.norm()),
          "the unedited file loads and runs")

# 3. The drag's bookkeeping vectors with different lengths (an edited or mixed-up file).
pair_scene(drag=True)
with tempfile.TemporaryDirectory() as d:
    good = os.path.join(d, "drag.xml")
    O.save(good)
    text = open(good).read()
    for name in ("hasPrev", "prevForce", "prevAngVel"):
        # keep only the vector's first element: <name><count>2</count>...<item>..</item><item>..</item></name>
        body = re.search(rf"<{name}>(.*?)</{name}>", text, re.S)
        items = re.findall(r"<item>.*?</item>", body.group(1), re.S)
        short = re.sub(r"<count>\d+</count>", "<count>1</count>", body.group(1), count=1)
        for it in items[1:]:
            short = short.replace(it, "", 1)
        bad = os.path.join(d, f"drag-{name}.xml")
        open(bad, "w").write(text[:body.start(1)] + short + text[body.end(1):])
        O.load(bad)
        O.run(20, True)
        e = O.energy
        check(len(items) == 2 and math.isfinite(sum(e[k] for k in e.keys())), f"the drag with a shortened {name} runs",
              f"{len(items)} items before")

# 4. The pair drivers and an unstable step.
from mesocontact import pair  # noqa: E402
for kw, named in ((dict(steps_per_contact=0.5), "steps_per_contact"), (dict(steps_per_contact=1), "steps_per_contact"),
                  (dict(dt=1.0), "dt")):
    for build in (lambda **k: pair.build(1e-3, 0.1, dict(k1=100, kp=500), **k),
                  lambda **k: pair.build_wall(1e-3, 0.1, dict(k1=100, kp=500), **k)):
        try:
            build(**kw)
            check(False, f"pair driver with {kw} refused", "accepted")
        except ValueError as e:
            check(str(e).startswith(named + " = ") and "stable step" in str(e), f"pair driver with {kw} refused",
                  str(e))
s = pair.build(1e-3, 0.1, dict(k1=100, kp=500), steps_per_contact=4)  # 4 per half period: stable, and runs
check(abs(pair.collide(s).e - 1) < 0.5, "pair driver at 4 steps per contact accepted")
for kw, named in ((dict(radius2=1e-300), "radius = 1e-300"), (dict(dt=True), "dt = True")):
    try:
        pair.build(1e-3, 0.1, dict(k1=100, kp=500), **kw)
        check(False, f"pair.build({kw}) refused", "accepted")
    except ValueError as e:
        check(str(e).startswith(named), f"pair.build({kw}) refused, naming it", str(e))

# 12. The Ip2's and the contact store's Python methods name the argument they refuse (Boost's
#     converters named none), and numpy's numbers are numbers (numpy's bool_ is not).
import numpy as np  # noqa: E402

ip2, m, store = Ip2_MesoMat_MesoMat_MesoPhys(), MesoMat(k1=100.0, kp=500.0, density=RHO), MesoContactStore()
for what, call, error, words in (
        ("exportContacts(None)", lambda: store.exportContacts(None), TypeError, "ids = None"),
        ("exportContacts([2**31])", lambda: store.exportContacts([2 ** 31]), ValueError, "ids[0] = 2147483648"),
        ("exportContacts([1.5])", lambda: store.exportContacts([1.5]), TypeError, "ids[0] = 1.5"),
        ("adoptMaterials(5)", lambda: ip2.adoptMaterials(5), TypeError, "interaction = 5"),
        ("stableStep(m, m, 1e-3, 'a')", lambda: ip2.stableStep(m, m, 1e-3, "a"), TypeError, "radius2 = 'a'"),
        ("stableStep(m, None, 1e-3)", lambda: ip2.stableStep(m, None, 1e-3), TypeError, "material2 = None"),
        ("stableStep(m, m, -1)", lambda: ip2.stableStep(m, m, -1.0), ValueError, "radius1 = -1 is invalid"),
        ("stableStep(m, m, -1e-20)", lambda: ip2.stableStep(m, m, -1e-20), ValueError,
         "radius1 = -9.9999999999999995e-21"),
        ("mixedParameters(m, m, None)", lambda: ip2.mixedParameters(m, m, None), TypeError, "rotations = None"),
        ("MesoMat(k1=np.bool_(True))", lambda: MesoMat(k1=np.bool_(True)), TypeError, "k1 = ")):
    try:
        call()
        check(False, f"{what} refused", "accepted")
    except error as e:
        check(str(e).startswith(words), f"{what}: {error.__name__} naming the argument", str(e)[:120])
    except Exception as e:  # noqa: BLE001 - the wrong kind of error is the finding
        check(False, f"{what}: {error.__name__} naming the argument", f"{type(e).__name__}: {e}"[:160])
n = MesoMat(k1=np.float32(100.0), kp=np.int64(500), density=np.float64(RHO))
check((n.k1, n.kp, n.density) == (100.0, 500.0, RHO), "numpy float32, int64 and float64 are numbers",
      f"{n.k1}, {n.kp}, {n.density}")
upd = {"kc": np.float32(20.0)}
n.updateAttrs(upd)
n.kp = np.int32(600)
check(n.kc == 20.0 and n.kp == 600.0 and isinstance(upd["kc"], np.float32),
      "numpy numbers in updateAttrs and assignments; the caller's dict untouched")
d = MesoBackgroundDamping(gammaB=np.float32(0.5))
check(d.gammaB == 0.5, "numpy numbers in an engine's keywords")
check(store.exportContacts(np.array([0, 1], dtype=np.int64)) is not None and ip2.stableStep(m, m, np.float32(1e-3)) > 0,
      "numpy ids and radii are taken")
try:
    MesoMat(frictionAngle=5e-324)
    check(False, "frictionAngle = 5e-324 refused", "accepted")
except ValueError as e:
    check(str(e).startswith("frictionAngle = "),
          "frictionAngle whose tangent leaves the law's range: named as frictionAngle", str(e))


# A drag too strong for the step: refused by the engine at the first step, naming its coefficients
# (gamma dt / m >= 1 reverses the velocity within a step; a saved scene with gammaB = 4294967296 ran to NaN).
def drag_pair(gammaB, gammaBR=0.0):
    O.reset()
    mat = O.materials.append(MesoMat(k1=100, kp=500, density=RHO))
    O.bodies.append([utils.sphere((0, 0, 0), A, material=mat), utils.sphere((3 * A, 0, 0), A, material=mat)])
    O.bodies[1].state.vel = (-0.01, 0, 0)
    O.bodies[1].state.angVel = (0, 0, 1.0)
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom6D()], [Ip2_MesoMat_MesoMat_MesoPhys()],
                                 [Law2_ScGeom_MesoPhys_Meso()]),
                 MesoBackgroundDamping(gammaB=gammaB, gammaBR=gammaBR), NewtonIntegrator(damping=0)]
    O.dt = 1e-6
    return O.bodies[1].state.mass, O.bodies[1].state.inertia[0]


mass, inertia = drag_pair(0.0)
for gB, gBR, refused in ((1.01 * mass / 1e-6, 0.0, True), (0.99 * mass / 1e-6, 0.0, False),
                         (0.0, 1.01 * inertia / A ** 2 / 1e-6, True), (0.0, 0.99 * inertia / A ** 2 / 1e-6, False)):
    drag_pair(gB, gBR)
    # O.step: after an engine error, O.run(n, True) returned without a step and without the error 5 times in 200 (YADE's
    # thread runner)
    try:
        for _ in range(5):
            O.step()
        check(not refused and all(math.isfinite(x) for x in O.bodies[1].state.vel),
              f"gammaB {gB:.4g}, gammaBR {gBR:.4g}: runs", "ran")
    except RuntimeError as e:
        check(refused and "gammaB = " in str(e) and "O.dt" in str(e) and O.iter == 0,
              f"gammaB {gB:.4g}, gammaBR {gBR:.4g}: refused at the first step, naming them", str(e)[:150])

# 13. (issue #57) The scene helpers' arguments and restart_check's options, named before anything runs.
import subprocess  # noqa: E402
import time  # noqa: E402
from yade import Vector3  # noqa: E402
import mesocontact  # noqa: E402
from mesocontact import scene  # noqa: E402

for gravity, error in ((None, TypeError), ((0, 0), ValueError), ((0, 0, -9.81, 0), ValueError),
                       ((math.nan, 0, 0), ValueError),
                       ((0, math.inf, 0), ValueError), ((0, 0, "-9.81"), TypeError), ("xyz", TypeError),
                       (9.81, TypeError),
                       ((True, 0, 0), TypeError), ({0: 1, 1: 2, 2: 3}, TypeError), ({0.0, 1.0, -9.81}, TypeError)):
    try:
        scene.engines(gravity=gravity)
        check(False, f"engines(gravity={gravity!r}) refused", "accepted")
    except error as e:
        check(str(e).startswith(f"gravity = {gravity!r} is invalid"),
              f"engines(gravity={gravity!r}): {error.__name__} naming it", str(e))
    except Exception as e:  # noqa: BLE001 - the wrong kind of error is the finding
        check(False, f"engines(gravity={gravity!r}): {error.__name__} naming it", f"{type(e).__name__}: {e}"[:160])
for gravity in (Vector3(0, 0, -9.81), np.array([0.0, 0.0, -9.81]), [0, 0, -9.81]):
    check(tuple(scene.engines(gravity=gravity)[-1].gravity) == (0, 0, -9.81), f"engines(gravity={gravity!r}) taken")
pair_scene()  # a contact to write
with tempfile.TemporaryDirectory() as d:
    for base, number, error, words in ((None, None, TypeError, "base = None"), (3, None, TypeError, "base = 3"),
                                       (os.path.join(d, "c"), -1, ValueError, "number = -1"),
                                       (os.path.join(d, "c"), 1.0, ValueError, "number = 1.0")):
        try:
            scene.export_contacts(base, number)
            check(False, f"export_contacts({base!r}, {number!r}) refused",
                  f"accepted: {os.listdir(d) + os.listdir('.')}"[:200])
        except error as e:
            check(str(e).startswith(words), f"export_contacts({base!r}, {number!r}): {error.__name__} naming it",
                  str(e))
    try:
        name = scene.export_contacts(os.path.join(d, "c"), np.int64(7))
    except ValueError as e:
        name = f"ValueError: {e}"
    check(name is not None and name.endswith("c-intrs-00000007.vtk"), "export_contacts takes a numpy integer as number",
          str(name))

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(mesocontact.__file__))))
launcher = os.path.abspath("yade-meso")  # ctest runs this from the build directory
for args, option in ((["--steps", "0"], "--steps"), (["--steps", "-5"], "--steps"), (["--steps", "2.5"], "--steps"),
                     (["--out", os.path.join(ROOT, "no-such-directory", "r.json")], "--out")):
    t0 = time.time()
    try:
        p = subprocess.run([launcher, "-j1", "-n", "-x", os.path.join(ROOT, "scripts", "restart_check.py"), *args],
                           capture_output=True, text=True, timeout=90)
        rc, text = p.returncode, p.stdout + p.stderr
    except subprocess.TimeoutExpired:
        rc, text = None, "still running after 90 s"
    last = [line for line in text.splitlines() if option in line][-1:] or text.splitlines()[-1:]
    check(rc == 2 and f"argument {option}: " in text and time.time() - t0 < 90,
          f"restart_check.py {' '.join(args)}: refused at once, naming {option}",
          f"rc {rc}, {time.time() - t0:.0f} s: {last}")
finish()
