# Adversarial inputs against the plugin and the package (issue #14): material parameters and
# their types (constructor and assignment), the Ip2 and the background drag, the theory
# functions, damaged save files and the tablet scripts' command-line values. Each input ends in
# one of (categories 7-12 added for issue #32: updateAttrs with mixed keys, edited save files of
# every class, contact bytes, extreme finite values, the Ip2's methods, a foreign IPhys; 13-17 for
# issue #49: phys and geometry assigned from Python, the contact store across geometry classes, the
# surface functors' detection factor, degenerate and extreme facets and walls, the loop registry): rejected clearly (ValueError/TypeError or argparse's error naming what is wrong),
# accepted and ran clean (finite state after a short collision, or a finite result), or other
# (anything else: the count that must be 0). A crash ends the script (the count is then moot).
#   yade -j1 -n -x scripts/fuzz_inputs.py [--n N] [--seed S] [--out FILE.json]
# N inputs per category (default 200; the ctest smoke runs a few). Reproducible from the seed.
import argparse
import contextlib
import io
import json
import math
import os
import random
import sys
import tempfile

from yade import O, utils
from yade import wrapper as w

from mesocontact import outputs, params, theory
from mesostudies.tablet import campaign

ap = argparse.ArgumentParser(prog="yade -j1 -n -x scripts/fuzz_inputs.py")
ap.add_argument("--n", type=int, default=200, help="inputs per category")
ap.add_argument("--seed", type=int, default=2026)
ap.add_argument("--out", default=None, help="JSON summary (default: print only)")
args = ap.parse_args(sys.argv[1:])
rng = random.Random(args.seed)

# The law's numbers as MesoMat declares them (pkg/core/MesoParamTable.hpp), and FrictMat's it checks.
NUMBERS = [k for k, v in w.MesoMat().dict().items() if isinstance(v, float) and k != "poisson"]
TEXTS = {"adhesion": ("none", "reversible", "jumpIn"), "k2Interpolation": ("linear", "sqrt")}
NAMES = NUMBERS + list(TEXTS) + ["dominant"]
BAD = [0.0, -1.0, -1e-300, float("nan"), float("inf"), -float("inf"), 1e300, 1e155, 1e-320, "abc", None, True, [1.0], {}, 3 + 0j]
tally = {}
others = []


def count(category, outcome, detail=""):
    tally.setdefault(category, {"rejected clearly": 0, "accepted and ran clean": 0, "other": 0})
    tally[category][outcome] += 1
    if outcome == "other":
        others.append(f"{category}: {detail}")


def value_for(name):
    """A plausible value most of the time, an adversarial one otherwise."""
    if rng.random() < 0.35:
        return rng.choice(BAD + ["jump-in", "cubic", "", 0, 1])
    if name in TEXTS:
        return rng.choice(TEXTS[name])
    if name == "dominant":
        return rng.random() < 0.2
    if name == "frictionAngle":
        return rng.uniform(0, 1.5)
    if name in ("phiF", "phiD"):
        return rng.uniform(0.01, 1)
    if name == "density":
        return 10 ** rng.uniform(2, 4)
    if name == "young":
        return 10 ** rng.uniform(6, 11)
    return 10 ** rng.uniform(-6, 4) if rng.random() < 0.8 else 0.0


def names_it(e, names):
    """The message starts with a parameter's name (for a rule between two parameters, e.g. kca
    for fa > 0, it names the other one too) and mentions one of those given."""
    m = str(e).replace("MesoBackgroundDamping.", "")
    if __import__("re").match(r"\w+\(", m):  # a helper's call with its arguments named: f(kp=..., m_min=...) = ...
        return any(f"{n}=" in m for n in names)
    return any(m.startswith((n + " ", n + ":")) for n in set(NAMES) | set(names)) and any(n in m for n in names)


def clean_collision(mat):
    """A short head-on collision of two spheres of this material: finite state throughout."""
    O.reset()
    m = O.materials.append(mat)
    O.bodies.append([utils.sphere((0, 0, 0), 1e-3, material=m), utils.sphere((2.0005e-3, 0, 0), 1e-3, material=m)])
    O.bodies[1].state.vel = (-0.05, 0, 0)
    ip2 = w.Ip2_MesoMat_MesoMat_MesoPhys()
    O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb(aabbEnlargeFactor=1.2)]),
                 w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom6D(interactionDetectionFactor=1.2)], [ip2], [w.Law2_ScGeom_MesoPhys_Meso()]),
                 w.NewtonIntegrator(damping=0)]
    O.dt = 1e-7
    O.step()
    if math.isfinite(ip2.stableDt):  # the user's job: a stable step (the law warns otherwise)
        O.dt = min(O.dt, 0.5 * ip2.stableDt)
    O.run(200, True)
    return all(math.isfinite(x) for b in O.bodies for x in tuple(b.state.pos) + tuple(b.state.vel) + tuple(b.state.angVel))


@contextlib.contextmanager
def quiet_fd2():
    """The law's time-step warnings go to fd 2 from C++: to a file, not the terminal."""
    sys.stderr.flush()
    saved, sink = os.dup(2), tempfile.TemporaryFile()
    os.dup2(sink.fileno(), 2)
    try:
        yield
    finally:
        os.dup2(saved, 2)
        os.close(saved)


with quiet_fd2():
    # 1. Constructor keywords.
    for _ in range(args.n * 3):
        kw = {n: value_for(n) for n in rng.sample(NAMES, rng.randint(1, 8))}
        try:
            mat = w.MesoMat(**kw)
        except (ValueError, TypeError) as e:
            count("MesoMat(**kw)", "rejected clearly" if names_it(e, kw) else "other", f"{kw}: {e}")
            continue
        except Exception as e:  # noqa: BLE001 (what the fuzz is for)
            count("MesoMat(**kw)", "other", f"{kw}: {type(e).__name__}: {e}")
            continue
        count("MesoMat(**kw)", "accepted and ran clean" if clean_collision(mat) else "other", f"{kw}: non-finite state")
    # 2. Assignment and updateAttrs: a refused value leaves every attribute as it was.
    for _ in range(args.n):
        mat = w.MesoMat(k1=100.0, kp=500.0, kc=50.0, density=2000.0)
        before = {n: getattr(mat, n) for n in NAMES}
        kw = {n: value_for(n) for n in rng.sample(NAMES, rng.randint(1, 3))}
        try:
            if len(kw) == 1:
                setattr(mat, *next(iter(kw.items())))
            else:
                mat.updateAttrs(kw)
        except (ValueError, TypeError) as e:
            after = {n: getattr(mat, n) for n in NAMES}
            same = all(after[n] == before[n] or (after[n] != after[n] and before[n] != before[n]) for n in NAMES)
            count("assignment", "rejected clearly" if names_it(e, kw) and same else "other", f"{kw}: {e}; unchanged {same}")
            continue
        count("assignment", "accepted and ran clean" if clean_collision(mat) else "other", f"{kw}: non-finite state")
    # 3. The functor and the engine.
    for _ in range(args.n // 2):
        kw = rng.choice([{"leverArm": rng.choice(["reduced", "a12", "x", 3, None])},
                         {"gammaB": value_for("gammaN"), "gammaBR": value_for("gammaN")},
                         {"reference": rng.choice(["lab", "contacts", "world", 0])}])
        cls = w.Ip2_MesoMat_MesoMat_MesoPhys if "leverArm" in kw else w.MesoBackgroundDamping
        try:
            cls(**kw)
            count("Ip2/MesoBackgroundDamping", "accepted and ran clean")
        except (ValueError, TypeError) as e:
            count("Ip2/MesoBackgroundDamping", "rejected clearly" if names_it(e, kw) else "other", f"{kw}: {e}")
    # 4. The theory functions.
    funcs = [(theory.restitution_fa0, ("chi", "eta", "beta")), (theory.chi_c_c, ("eta", "beta")),
             (theory.max_sticking_overlap, ("eta", "beta")), (theory.low_velocity_restitution, ("chi", "eta")),
             (theory.pair_collision, ("v_inf", "k1", "kp", "kc", "phiF", "a12", "m_r")),
             (theory.plastic_limit_velocity, ("k1", "kp", "phiF", "a12", "m_r")), (params.resolved_step, ("kp", "m_min")),
             (theory.max_overlap, ("v_i", "k1", "kp", "phiF", "a12", "m_r"))]
    for _ in range(args.n):
        f, names = rng.choice(funcs)
        a = [rng.choice(BAD[:9]) if rng.random() < 0.3 else 10 ** rng.uniform(-3, 1) for _ in names]
        if f in (theory.pair_collision, theory.plastic_limit_velocity, theory.max_overlap) and rng.random() < 0.7:
            a[names.index("phiF")] = rng.uniform(0.01, 1)
        try:
            r = f(*a)
            vals = [getattr(r, k) for k in ("e", "en", "delta_max")] if hasattr(r, "e") else [r]
            ok = all(isinstance(v, float) and math.isfinite(v) for v in vals)
            count("theory", "accepted and ran clean" if ok else "other", f"{f.__name__}{tuple(a)} = {vals}")
        except ValueError as e:
            count("theory", "rejected clearly" if names_it(e, list(names) + ["interpolation"]) else "other", f"{f.__name__}{tuple(a)}: {e}")
    # 5. Damaged save files: a truncated or edited file is refused by O.load or loads a valid scene.
    tmp = tempfile.mkdtemp(prefix="fuzz-")
    clean_collision(w.MesoMat(k1=100.0, kp=500.0, kt=50.0, kr=20.0, muR=0.1, frictionAngle=0.3))
    good = os.path.join(tmp, "good.xml")
    O.save(good)
    text = open(good).read()
    for k in range(args.n // 2):
        if k % 2:
            damaged = text[: rng.randint(0, len(text) - 1)]
        else:  # a number of a material or contact replaced
            tags = ["k1", "kp", "kc", "phiF", "density", "deltaMax", "tangential", "radius1", "kt"]
            tag = rng.choice(tags)
            bad = rng.choice(["-1", "nan", "inf", "0", "1e308", "abc"])
            damaged = text.replace(f"<{tag}>", f"<{tag}>{bad}", 1) if rng.random() < 0.5 else \
                __import__("re").sub(f"<{tag}>[^<]*<", f"<{tag}>{bad}<", text, count=1)
        path = os.path.join(tmp, f"d{k}.xml")
        open(path, "w").write(damaged)
        try:
            O.load(path)
        except Exception:  # noqa: BLE001 (refused: the scene stays as it was)
            count("save files", "rejected clearly")
            continue
        try:
            O.run(50, True)
            ok = all(math.isfinite(x) for b in O.bodies for x in tuple(b.state.pos) + tuple(b.state.vel))
        except Exception as e:  # noqa: BLE001
            ok = False
            damaged = str(e)
        count("save files", "accepted and ran clean" if ok else "other", f"file {k}: loaded, then not clean")
    # 6. Command-line values of the tablet scripts (checked before any work).
    for _ in range(args.n // 2):
        fig = rng.choice(campaign.FIGURES)
        opt = rng.choice(["--amplitudes", "--periods", "--speed", "--kc-over-kp", "--n", "--slow-amplitudes"])
        val = rng.choice(["0.1", "0.2,0.3", "inf", "nan", "-1", "abc", "1e-6", "10", "3", "1e9", "0", "0.05,x"])
        argv = ["--out", os.path.join(tmp, "cli"), opt, val] + (["--quick"] if rng.random() < 0.5 else [])
        err = io.StringIO()
        try:
            with contextlib.redirect_stderr(err):
                campaign.parse_args(fig, argv)
            count("CLI values", "accepted and ran clean")
        except SystemExit as e:
            msg = err.getvalue()
            count("CLI values", "rejected clearly" if e.code == 2 and opt.split("=")[0] in msg else "other", f"{fig} {argv}: {msg}")


def every_mechanism_pair(drag):
    """Two touching spheres with every mechanism of the law (and the drag): the scene the
    following categories damage."""
    O.reset()
    m = O.materials.append(w.MesoMat(k1=100, kp=500, kc=20, phiF=0.1, fa=1e-5, kca=100, adhesion="jumpIn", density=2000.0,
                                     kt=50, frictionAngle=0.3, kr=10, muR=0.1, ko=10, muO=0.1))
    O.bodies.append([utils.sphere((0, 0, 0), 1e-3, material=m), utils.sphere((2e-3 - 2e-5, 0, 0), 1e-3, material=m)])
    O.bodies[1].state.vel = (-0.01, 0.002, 0)
    O.bodies[1].state.angVel = (0, 0, 3.0)
    ip2 = w.Ip2_MesoMat_MesoMat_MesoPhys()
    O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb()]),
                 w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom6D()], [ip2], [w.Law2_ScGeom_MesoPhys_Meso()])] + \
                ([w.MesoBackgroundDamping(gammaB=1e-3, gammaBR=1e-4)] if drag else []) + [w.NewtonIntegrator(damping=0)]
    O.dt = 1e-6
    O.trackEnergy = True
    O.run(50, True)
    return ip2


def finite_scene():
    return all(math.isfinite(x) for b in O.bodies for x in tuple(b.state.pos) + tuple(b.state.vel) + tuple(b.state.angVel))


def run_outcome(steps=50):
    """After the damage: the run refused by an engine naming the attribute at fault (e.g. a drag
    too strong for the step), or a clean run (finite state), or other."""
    try:
        O.run(steps, True)
    except Exception as e:  # noqa: BLE001
        return "rejected clearly" if __import__("re").search(r"\b\w+ = ", str(e)) else "other"
    return "accepted and ran clean" if finite_scene() else "other"


def runs_clean(steps=50):
    return run_outcome(steps) == "accepted and ran clean"


# The classes of issue #32's second pass (items 1-3, 5-7, 12).
MISC = ["poisson", "young", "label", "density", "frictionAngle", "id", "nonexistent", "K1", 7]
WRONG = [None, "a", b"1", True, -1, 0, 2 ** 31, 2 ** 63, [2 ** 31], [None], (), {}, 1e-300, float("nan"), float("inf"), 3 + 0j]
with quiet_fd2():
    # 7. updateAttrs with the law's, the inherited and unknown keys mixed: all or nothing.
    for _ in range(args.n):
        mat = w.MesoMat(k1=100.0, kp=500.0, kc=50.0, density=2000.0, poisson=0.25, label="grain")
        keys = rng.sample(NAMES, rng.randint(1, 3)) + rng.sample(MISC, rng.randint(1, 2))
        kw = {k: (value_for(k) if k in NAMES else rng.choice(WRONG + [0.3, "wall", 1e9, 5])) for k in keys}
        before = {n: getattr(mat, n) for n in NAMES + ["poisson", "young", "label"]}
        try:
            mat.updateAttrs(kw)
        except (ValueError, TypeError, AttributeError) as e:
            after = {n: getattr(mat, n) for n in before}
            same = all(after[n] == before[n] or (after[n] != after[n] and before[n] != before[n]) for n in before)
            count("updateAttrs mixed", "rejected clearly" if same and any(str(k) in str(e) for k in kw) else "other",
                  f"{kw}: {type(e).__name__}: {e}; unchanged {same}")
            continue
        count("updateAttrs mixed", "accepted and ran clean" if clean_collision(mat) else "other", f"{kw}: non-finite state")
    # 8. Hand-edited save files of every class the project adds (material, pair parameters,
    #    contact state of both phys classes, functors, the drag and its bookkeeping vectors).
    ip2 = every_mechanism_pair(drag=True)
    i = O.interactions[0, 1]
    tags = set()
    for obj in (O.materials[0], i.phys, ip2, [e for e in O.engines if isinstance(e, w.MesoBackgroundDamping)][0]):
        tags |= {k for k in obj.dict() if k not in ("label", "id", "dict")}
    tags = sorted(tags)
    good = os.path.join(tmp, "every.xml")
    O.save(good)
    text = open(good).read()
    present = [t for t in tags if f"<{t}>" in text]
    for k in range(args.n):
        tag = rng.choice(present)
        bad = rng.choice(["-1", "nan", "inf", "-inf", "0", "1e308", "1e-320", "abc", "9", "-7", "4294967296", ""])
        pat = __import__("re").compile(f"<{tag}>([^<]*)<")
        hits = list(pat.finditer(text))
        h = rng.choice(hits)
        damaged = text[:h.start(1)] + bad + text[h.end(1):]
        if rng.random() < 0.25:  # a vector shortened: its first item dropped, the count kept
            m = __import__("re").search(r"<item>[^<]*</item>", damaged[h.start():])
            if m:
                damaged = damaged[:h.start() + m.start()] + damaged[h.start() + m.end():]
        path = os.path.join(tmp, f"e{k}.xml")
        open(path, "w").write(damaged)
        try:
            O.load(path)
        except Exception:  # noqa: BLE001 (refused)
            count("save files (every class)", "rejected clearly")
            continue
        count("save files (every class)", run_outcome(), f"<{tag}> = {bad!r}: loaded, then not clean")
    # 9. Contact bytes: exported, damaged (bytes flipped, cut, extended), imported, restored.
    for k in range(args.n // 2):
        every_mechanism_pair(drag=False)
        store = w.MesoContactStore()
        data = bytearray(store.exportContacts([0, 1]))
        how = rng.choice(["flip", "cut", "extend", "ids"])
        if how == "flip":
            for _ in range(rng.randint(1, 8)):
                data[rng.randrange(len(data))] = rng.randrange(256)
        elif how == "cut":
            data = data[: rng.randrange(len(data))]
        elif how == "extend":
            data += bytes(rng.randrange(256) for _ in range(rng.randint(1, 64)))
        else:  # a body id made large (ids are serialized as text in YADE's binary archives too)
            data = bytearray(bytes(data).replace(b"\x01\x00\x00\x00", rng.choice([b"\xff\xff\xff\x7f", b"\x00\xe1\xf5\x05"]), 1))
        try:
            store.importContacts(bytes(data))
        except Exception:  # noqa: BLE001 (refused)
            count("contact bytes", "rejected clearly")
            continue
        O.interactions.erase(0, 1)
        try:
            O.step()
            store.restore()
        except ValueError as e:  # a changed parameter: restore() names the pair and refuses the whole restore
            count("contact bytes", "rejected clearly" if "#0+#1" in str(e) and "nothing was restored" in str(e) else "other",
                  f"{how}: restore: {e}")
            continue
        except Exception as e:  # noqa: BLE001
            count("contact bytes", "other", f"{how}: restore raised {type(e).__name__}: {e}")
            continue
        count("contact bytes", "accepted and ran clean" if runs_clean() else "other", f"{how}: imported, then not clean")
    # 10. Extreme finite values: every number near and beyond the range the law computes with.
    for _ in range(args.n):
        name = rng.choice(NUMBERS)
        val = rng.choice([10 ** rng.uniform(-320, 308), 1e-100, 1e100, 9.9e-101, 1.01e100, 5e-324, 1.7e308, 2.2250738585072014e-308])
        try:
            mat = w.MesoMat(**{name: val})
        except (ValueError, TypeError) as e:
            count("extreme values", "rejected clearly" if names_it(e, [name]) else "other", f"{name}={val}: {e}")
            continue
        count("extreme values", "accepted and ran clean" if clean_collision(mat) else "other", f"{name}={val}: non-finite state")
    # 11. The Ip2's Python methods with wrong types and values.
    ip2, store = every_mechanism_pair(drag=False), w.MesoContactStore()
    live = O.interactions[0, 1]
    good_m = w.MesoMat(k1=100.0, kp=500.0)
    pool = WRONG + [good_m, w.FrictMat(), live, 1e-3]
    calls = {"stableStep": ("material1", "material2", "radius1", "radius2", "rotations"),
             "mixedParameters": ("material1", "material2", "rotations"), "adoptMaterials": ("interaction",),
             "exportContacts": ("ids",), "importContacts": ("data",)}
    for _ in range(args.n):
        meth = rng.choice(sorted(calls))
        names = calls[meth]
        a = [rng.choice(pool) for _ in names[: rng.randint(1, len(names))]]
        try:
            r = getattr(store if meth.endswith("Contacts") else ip2, meth)(*a)
        except (ValueError, TypeError, RuntimeError) as e:
            count("Ip2 methods", "rejected clearly" if any(n in str(e) for n in names) else "other", f"{meth}{tuple(map(repr, a))}: {type(e).__name__}: {e}")
            continue
        ok = not isinstance(r, float) or (math.isfinite(r) and r > 0)
        count("Ip2 methods", "accepted and ran clean" if ok and runs_clean(5) else "other", f"{meth}{tuple(map(repr, a))} = {r!r}")
    # 12. Another IPhys put on a live meso contact from Python, then O.run (the engine thread).
    kinds = [w.MesoPhys, w.MesoTangentialPhys, w.FrictPhys, w.NormShearPhys, w.ViscElPhys, w.RotStiffFrictPhys, w.IPhys]
    for _ in range(args.n // 4):
        every_mechanism_pair(drag=rng.random() < 0.5)
        kind = rng.choice(kinds)
        O.interactions[0, 1].phys = kind()
        count("phys replaced", "accepted and ran clean" if runs_clean(rng.choice([1, 20, 100])) else "other", f"{kind.__name__}")


def falling_onto(surface, functor, v=0.05, steps=400):
    """A sphere falling at v onto ``surface`` (a body) through ``functor``: finite throughout, and
    whether it ever touched (a contact with the surface was real)."""
    O.reset()
    m = O.materials.append(w.MesoMat(k1=100, kp=500, kc=20, phiF=0.1, density=2000.0))
    surface.material = O.materials[m]
    sid = O.bodies.append(surface)
    ball = O.bodies.append(utils.sphere((0, 0, 1.0e-3 + 2e-6), 1e-3, material=m))  # 40 steps from touching
    O.bodies[ball].state.vel = (0, 0, -v)
    O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb(), w.Bo1_Facet_Aabb(), w.Bo1_Wall_Aabb()]),
                 w.InteractionLoop([functor, w.Ig2_Sphere_Sphere_ScGeom()], [w.Ip2_MesoMat_MesoMat_MesoPhys()],
                                   [w.Law2_ScGeom_MesoPhys_Meso()]), w.NewtonIntegrator(damping=0)]
    O.dt = 1e-6
    touched = False
    for _ in range(steps // 20):
        O.run(20, True)
        touched = touched or (O.interactions.has(sid, ball) and O.interactions[sid, ball].isReal)
    b = O.bodies[ball].state  # the sphere's state (a facet given a NaN vertex has a NaN position of its own)
    return all(math.isfinite(x) for x in tuple(b.pos) + tuple(b.vel) + tuple(b.angVel)), touched


# What category 13 assigns to a live contact i (j: another contact, or i itself when there is none).
ASSIGNED = {"own phys": ("phys", lambda i, j: i.phys), "other's phys": ("phys", lambda i, j: j.phys),
            "new MesoPhys": ("phys", lambda i, j: w.MesoPhys()), "own geom": ("geom", lambda i, j: i.geom),
            "other's geom": ("geom", lambda i, j: j.geom), "new ScGeom": ("geom", lambda i, j: w.ScGeom()),
            "new ScGeom6D": ("geom", lambda i, j: w.ScGeom6D()),
            "phys of another class": ("phys", lambda i, j: rng.choice([w.FrictPhys, w.ViscElPhys, w.IPhys])())}


with quiet_fd2():
    # 13. Phys and geometry assigned from Python on live contacts (their own, another contact's, new
    #     or of another class), then O.run: the run goes on clean, or the law remakes them.
    for _ in range(args.n):
        every_mechanism_pair(drag=rng.random() < 0.5)
        O.bodies.append(utils.sphere((-2e-3 + 2e-5, 0, 0), 1e-3, material=0))
        O.run(5, True)
        i, j = O.interactions[0, 1], (O.interactions[0, 2] if O.interactions.has(0, 2) else O.interactions[0, 1])
        what, (attr, make) = rng.choice(sorted(ASSIGNED.items()))
        setattr(i, attr, make(i, j))
        del i, j
        count("phys/geom from Python", "accepted and ran clean" if runs_clean(rng.choice([1, 30, 200])) else "other", what)
    # 14. Contacts exported where the loop makes one geometry class, restored where it makes another.
    geoms = {"ScGeom": w.Ig2_Sphere_Sphere_ScGeom, "ScGeom6D": w.Ig2_Sphere_Sphere_ScGeom6D}
    for _ in range(args.n // 2):
        a, b = rng.choice(sorted(geoms)), rng.choice(sorted(geoms))
        every_mechanism_pair(drag=False)
        O.engines[2].geomDispatcher.functors = [geoms[a]()]
        O.interactions.clear()
        O.run(5, True)
        store = w.MesoContactStore()
        data = store.exportContacts([0, 1])
        every_mechanism_pair(drag=False)
        O.engines[2].geomDispatcher.functors = [geoms[b]()]
        O.interactions.clear()
        O.engines[1]()
        store.importContacts(data)
        try:
            store.restore()
        except ValueError as e:
            count("store across geometry classes", "rejected clearly" if a in str(e) and b in str(e) else "other", f"{a}->{b}: {e}")
            continue
        count("store across geometry classes", "accepted and ran clean" if a == b and runs_clean(50) else "other",
              f"{a}->{b}: restored")
    # 15. The surface functors' detection factor: refused by name, or a falling sphere is caught.
    functors = [w.Ig2_Facet_Sphere_MesoScGeom, w.Ig2_Facet_Sphere_MesoScGeom6D, w.Ig2_Wall_Sphere_MesoScGeom]
    for _ in range(args.n):
        kind = rng.choice(functors)
        val = rng.choice(BAD + [0.999, 1.0, 1.0 + 1e-12, 1.5, 10.0, rng.uniform(-2, 3)])
        f = kind()
        try:
            f.interactionDetectionFactor = val
        except (ValueError, TypeError) as e:
            count("functor attributes", "rejected clearly" if "interactionDetectionFactor" in str(e) else "other",
                  f"{kind.__name__} {val!r}: {e}")
            continue
        surface = (utils.wall(0, axis=2, sense=0) if "Wall" in kind.__name__
                   else utils.facet([(-3e-3, -3e-3, 0), (3e-3, -3e-3, 0), (0, 3e-3, 0)], fixed=True))
        ok, touched = falling_onto(surface, f)
        count("functor attributes", "accepted and ran clean" if ok and touched else "other", f"{kind.__name__} {val!r}")
    # 16. Degenerate and extreme facets and walls: a falling sphere, finite throughout; an invalid
    #     wall axis makes no contact and is said (the functor warns; set_detection refuses it).
    for _ in range(args.n):
        if rng.random() < 0.3:
            axis, sense = rng.choice([-1, 0, 1, 2, 3, 7]), rng.choice([-1, 0, 1])
            ok, touched = falling_onto(utils.wall(0, axis=2, sense=sense), w.Ig2_Wall_Sphere_MesoScGeom())
            O.bodies[0].shape.axis = axis
            ok = ok and finite_scene() and runs_clean(50)
            count("facets and walls", "accepted and ran clean" if ok else "other", f"wall axis {axis}")
            continue
        a, b, c = [rng.uniform(-3e-3, 3e-3) for _ in range(3)], [rng.uniform(-3e-3, 3e-3) for _ in range(3)], \
            [rng.uniform(-3e-3, 3e-3) for _ in range(3)]
        how = rng.choice(["coincident", "collinear", "nan", "huge", "tiny", "flat", "regular"])
        if how == "coincident":
            b = list(a)
        elif how == "collinear":
            c = [2 * b[k] - a[k] for k in range(3)]
        elif how == "nan":
            c[rng.randrange(3)] = float("nan")
        elif how == "huge":
            c = [x * 1e200 for x in c]
        elif how == "tiny":
            b, c = [a[k] + 1e-200 for k in range(3)], [a[k] - 1e-200 for k in range(3)]
        elif how == "flat":
            a[2] = b[2] = c[2] = 0.0
        try:
            surface = utils.facet([tuple(a), tuple(b), tuple(c)], fixed=True)
        except Exception as e:  # noqa: BLE001 - YADE's own refusal of the vertices
            count("facets and walls", "rejected clearly", f"{how}: {type(e).__name__}")
            continue
        ok, touched = falling_onto(surface, rng.choice(functors[:2])())
        count("facets and walls", "accepted and ran clean" if ok else "other", f"{how}: non-finite state")
    # 17. The loop registry: labels and periods of every kind; refused by name, or a runner that calls.
    from mesocontact import loop
    names = ["O", "sphere", "len", "__import__", "wrapper", "utils", "probe_a", "probeB", "two words", "1x", "", "None", 5, None]
    for _ in range(args.n):
        label = rng.choice(names) if rng.random() < 0.6 else "fz" + "".join(rng.choice("abc_") for _ in range(4))
        period = rng.choice(WRONG + [1, 2, 7, 1.0, "3"])
        calls = []
        try:
            O.reset()
            O.engines = [loop.runner(lambda: calls.append(O.iter), period, label)]
        except (ValueError, TypeError) as e:
            count("loop registry", "rejected clearly" if ("label" in str(e) or "period" in str(e) or "fn" in str(e)) else "other",
                  f"{label!r} {period!r}: {e}")
            continue
        O.run(7, True)
        count("loop registry", "accepted and ran clean" if len(calls) == len(range(period, 7, period)) else "other",
              f"{label!r} {period!r}: {len(calls)} calls")

total = {k: sum(v[k] for v in tally.values()) for k in ("rejected clearly", "accepted and ran clean", "other")}
summary = {"command": "yade -j1 -n -x scripts/fuzz_inputs.py " + " ".join(sys.argv[1:]), "seed": args.seed,
           "inputs": sum(total.values()), "total": total, "by_category": tally, "others": others[:50]}
print(json.dumps(summary, indent=1))
if args.out:
    outputs.write_atomic(args.out, json.dumps(summary, indent=1))
sys.exit(1 if total["other"] else 0)
