# Adversarial inputs against the plugin and the package (issue #14): material parameters and
# their types (constructor and assignment), the Ip2 and the background drag, the theory
# functions, damaged save files. Each input ends in one of (categories 7-12 added for issue #32:
# updateAttrs with mixed keys, edited save files of every class, contact bytes, extreme finite
# values, the Ip2's methods, a foreign IPhys; 13-17 for issue #49: phys and geometry assigned from
# Python, the contact store across geometry classes, the surface functors' detection factor,
# degenerate and extreme facets and walls, the loop registry; 18-27 for issue #57: every class the
# plugin registers made with its own keywords and saved alone as `yade --test` does, MesoMat's
# young/poisson/label/id, scene.set_detection's margin, scene.engines' gravity, Wall.axis under
# scene.check/set_detection/time_step, facet meshes with duplicated triangles under a dragged
# sphere, callbacks that raise in the loop, calibrate.fit_cycles, params.material_from and
# params.scale_material): rejected clearly (ValueError/TypeError/AttributeError naming what is
# wrong, the object left as it was), accepted and ran clean (finite state after a short run, or a
# finite result), or other (anything else: the count that must be 0). A crash ends the script (the
# count is then moot). Each input is also counted under the class or module it exercises
# ("by_class" in the JSON). The studies' command lines (the tablet's, which this script fuzzed up to
# issue #57) are checked by their own test, ctest `yade.cli` (tests/yade/test_cli.py): the library's
# scripts import no study (issue #58).
#   yade -j1 -n -x scripts/fuzz_inputs.py [--n N] [--seed S] [--out FILE.json] [--log FILE.jsonl]
# N inputs per category (default 200; the ctest smoke runs a few). Reproducible from the seed.
import argparse
import contextlib
import json
import math
import os
import random
import re
import signal
import sys
import tempfile
import time

from yade import O, utils
from yade import wrapper as w

from mesocontact import outputs, params, theory

ap = argparse.ArgumentParser(prog="yade -j1 -n -x scripts/fuzz_inputs.py")
ap.add_argument("--n", type=int, default=200, help="inputs per category")
ap.add_argument("--seed", type=int, default=2026)
ap.add_argument("--out", default=None, help="JSON summary (default: print only)")
ap.add_argument("--log", default=None, help="every input's category, class, outcome and detail, one JSON line each")
args = ap.parse_args(sys.argv[1:])
rng = random.Random(args.seed)
log = open(args.log, "w", buffering=1) if args.log else None  # line by line: a crash leaves the inputs before it

# The law's numbers as MesoMat declares them (pkg/core/MesoParamTable.hpp), and FrictMat's it checks.
NUMBERS = [k for k, v in w.MesoMat().dict().items() if isinstance(v, float) and k != "poisson"]
TEXTS = {"adhesion": ("none", "reversible", "jumpIn"), "k2Interpolation": ("linear", "sqrt")}
NAMES = NUMBERS + list(TEXTS) + ["dominant"]
BAD = [0.0, -1.0, -1e-300, float("nan"), float("inf"), -float("inf"), 1e300, 1e155, 1e-320, "abc", None, True, [1.0],
       {}, 3 + 0j]
tally = {}
# Every class the plugin registers (YADE's Serializable classes named Meso*: pkg/yade/*.cpp, YADE_PLUGIN).
import yade.system  # noqa: E402
PLUGIN_CLASSES = sorted(c for c in yade.system.childClasses("Serializable") if "Meso" in c)
others = []


by_class = {}
OUTCOMES = ("rejected clearly", "accepted and ran clean", "other")
# The class (or the package's module) each category exercises, where it is one; the others say it per input.
CATEGORY_CLASS = {"MesoMat(**kw)": "MesoMat", "assignment": "MesoMat", "updateAttrs mixed": "MesoMat",
                  "extreme values": "MesoMat", "MesoMat young/poisson/label/id": "MesoMat",
                  "theory": "mesocontact.theory",
                  "contact bytes": "MesoContactStore", "store across geometry classes": "MesoContactStore",
                  "phys replaced": "Law2_ScGeom_MesoPhys_Meso", "phys/geom from Python": "Law2_ScGeom_MesoPhys_Meso",
                  "loop registry": "mesocontact.loop", "loop callbacks that raise": "mesocontact.loop",
                  "set_detection margin": "mesocontact.scene", "engines gravity": "mesocontact.scene",
                  "Wall.axis checks": "mesocontact.scene", "fit_cycles": "mesocontact.calibrate",
                  "material_from": "mesocontact.params", "scale_material": "mesocontact.params"}
T0 = time.time()
seconds = {}  # per category: the time since the previous input was counted
_last = [T0]


def count(category, outcome, detail="", cls=None):
    now = time.time()
    seconds[category] = seconds.get(category, 0.0) + now - _last[0]
    _last[0] = now
    for table, key in ((tally, category), (by_class, cls or CATEGORY_CLASS[category])):
        table.setdefault(key, dict.fromkeys(OUTCOMES, 0))
        table[key][outcome] += 1
    if outcome == "other":
        others.append(f"{category}: {detail}")
    if log:
        log.write(json.dumps({"category": category, "class": cls or CATEGORY_CLASS[category], "outcome": outcome,
                              "detail": str(detail)[:1000]}) + "\n")


def timed_call(category, argnames, desc, call):
    """call() counted as rejected clearly (a ValueError/TypeError naming one of argnames) or other;
    its time kept as the category's slowest. The result, or None when it raised."""
    t = time.time()
    try:
        return call()
    except (ValueError, TypeError) as e:
        count(category, "rejected clearly" if named(e, argnames) else "other", f"{desc}: {type(e).__name__}: {e}")
    except Exception as e:  # noqa: BLE001
        count(category, "other", f"{desc}: {type(e).__name__}: {e}")
    finally:
        slowest[category] = max(slowest.get(category, 0.0), time.time() - t)
    return None


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
                 w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom6D(interactionDetectionFactor=1.2)], [ip2],
                                   [w.Law2_ScGeom_MesoPhys_Meso()]),
                 w.NewtonIntegrator(damping=0)]
    O.dt = 1e-7
    O.step()
    if math.isfinite(ip2.stableDt):  # the user's job: a stable step (the law warns otherwise)
        O.dt = min(O.dt, 0.5 * ip2.stableDt)
    O.run(200, True)
    return all(math.isfinite(x) for b in O.bodies
               for x in tuple(b.state.pos) + tuple(b.state.vel) + tuple(b.state.angVel))


@contextlib.contextmanager
def quiet_fd2():
    """The law's time-step warnings go to fd 2 from C++: to a file, not the terminal (stderr_since
    reads what came after a mark)."""
    sys.stderr.flush()
    saved, sink = os.dup(2), tempfile.TemporaryFile()
    os.dup2(sink.fileno(), 2)
    try:
        yield sink
    finally:
        os.dup2(saved, 2)
        os.close(saved)


def survives_in_a_fork(fn, timeout=60):
    """Calls fn() in a forked copy of this process (its main thread only; fn must not run YADE's engine
    thread): None if the copy returned or raised, else how it died (a signal, or a hang past ``timeout``
    seconds, then killed). The fuzz thus counts a crash and goes on."""
    sys.stdout.flush()
    sys.stderr.flush()
    pid = os.fork()
    if pid == 0:  # the copy: no cleanup, no atexit
        try:
            fn()
        except BaseException:  # noqa: BLE001 - a refusal is not a death
            pass
        os._exit(0)
    t0 = time.time()
    while True:
        done, status = os.waitpid(pid, os.WNOHANG)
        if done:
            break
        if time.time() - t0 > timeout:
            os.kill(pid, signal.SIGKILL)
            os.waitpid(pid, 0)
            return f"hung for {timeout} s"
        time.sleep(0.002)
    if os.WIFSIGNALED(status):
        return f"killed by {signal.Signals(os.WTERMSIG(status)).name}"
    return None if os.WEXITSTATUS(status) == 0 else f"exited with code {os.WEXITSTATUS(status)}"


def stderr_mark():
    sys.stderr.flush()
    return os.lseek(2, 0, os.SEEK_CUR)


def stderr_since(mark):
    """What fd 2 (a file inside quiet_fd2) received since ``mark`` (read without moving its offset)."""
    end = stderr_mark()
    return os.pread(2, end - mark, mark).decode(errors="replace") if end > mark else ""


def owner_class(text, pos):
    """The class of the object that holds text[pos] in a YADE XML save: the innermost element with
    a class name (Boost writes it at a class's first object, a class_id_reference at the others),
    "MesoPairParams" inside a contact's pairParams; YADE's own classes marked as such."""
    names, stack = {}, []
    for m in re.finditer(r'<(/?)(\w+)([^>]*?)(/?)>', text[:pos]):
        close, tag, attrs, empty = m.groups()
        if close:
            if stack:
                stack.pop()
            continue
        if empty:
            continue
        cid, name = re.search(r'class_id="(\d+)"', attrs), re.search(r'class_name="(?:yade::)?(\w+)"', attrs)
        if cid and name:
            names[cid.group(1)] = name.group(1)
        ref = re.search(r'class_id_reference="(\d+)"', attrs)
        stack.append("MesoPairParams" if tag == "pairParams" else names.get(ref.group(1)) if ref else name.group(1)
                     if name else None)
    owner = next((c for c in reversed(stack) if c), "Scene")
    return owner if owner in PLUGIN_CLASSES or owner == "MesoPairParams" else f"YADE {owner}"


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
            count("assignment", "rejected clearly" if names_it(e, kw) and same else "other",
                  f"{kw}: {e}; unchanged {same}")
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
            count("Ip2/MesoBackgroundDamping", "accepted and ran clean", cls=cls.__name__)
        except (ValueError, TypeError) as e:
            count("Ip2/MesoBackgroundDamping", "rejected clearly" if names_it(e, kw) else "other", f"{kw}: {e}",
                  cls=cls.__name__)
    # 4. The theory functions.
    funcs = [(theory.restitution_fa0, ("chi", "eta", "beta")), (theory.chi_c_c, ("eta", "beta")),
             (theory.max_sticking_overlap, ("eta", "beta")), (theory.low_velocity_restitution, ("chi", "eta")),
             (theory.pair_collision, ("v_inf", "k1", "kp", "kc", "phiF", "a12", "m_r")),
             (theory.plastic_limit_velocity, ("k1", "kp", "phiF", "a12", "m_r")),
             (params.resolved_step, ("kp", "m_min")),
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
            count("theory", "accepted and ran clean" if ok else "other", f"{f.__name__}{tuple(a)} = {vals}",
                  cls=f.__module__)
        except ValueError as e:
            count("theory", "rejected clearly" if names_it(e, list(names) + ["interpolation"]) else "other",
                  f"{f.__name__}{tuple(a)}: {e}",
                  cls=f.__module__)
    # 5. Damaged save files: a truncated or edited file is refused by O.load or loads a valid scene.
    tmp = tempfile.mkdtemp(prefix="fuzz-")
    clean_collision(w.MesoMat(k1=100.0, kp=500.0, kt=50.0, kr=20.0, muR=0.1, frictionAngle=0.3))
    good = os.path.join(tmp, "good.xml")
    O.save(good)
    text = open(good).read()
    for k in range(args.n // 2):
        if k % 2:
            damaged = text[: rng.randint(0, len(text) - 1)]
            owner = owner_class(text, len(damaged))
        else:  # a number of a material or contact replaced
            tags = ["k1", "kp", "kc", "phiF", "density", "deltaMax", "tangential", "radius1", "kt"]
            tag = rng.choice(tags)
            bad = rng.choice(["-1", "nan", "inf", "0", "1e308", "abc"])
            owner = owner_class(text, text.index(f"<{tag}>"))
            damaged = text.replace(f"<{tag}>", f"<{tag}>{bad}", 1) if rng.random() < 0.5 else \
                __import__("re").sub(f"<{tag}>[^<]*<", f"<{tag}>{bad}<", text, count=1)
        path = os.path.join(tmp, f"d{k}.xml")
        open(path, "w").write(damaged)
        died = survives_in_a_fork(lambda: O.load(path))  # a damaged file is read first in a copy of the process
        if died:
            count("save files", "other", f"[crash] file {k} ({path}): O.load {died}", cls=owner)
            continue
        try:
            O.load(path)
        except Exception:  # noqa: BLE001 (refused: the scene stays as it was)
            count("save files", "rejected clearly", cls=owner)
            continue
        try:
            O.run(50, True)
            ok = all(math.isfinite(x) for b in O.bodies for x in tuple(b.state.pos) + tuple(b.state.vel))
        except Exception as e:  # noqa: BLE001
            ok = False
            damaged = str(e)
        count("save files", "accepted and ran clean" if ok else "other", f"file {k}: loaded, then not clean", cls=owner)


def every_mechanism_pair(drag, ip2=None, law=None, steps=50):
    """Two touching spheres with every mechanism of the law (and the drag: True for the default
    one, or the engine to use; ip2, law: the functors to use): the scene the following categories
    damage, run ``steps`` steps."""
    O.reset()
    m = O.materials.append(w.MesoMat(k1=100, kp=500, kc=20, phiF=0.1, fa=1e-5, kca=100, adhesion="jumpIn",
                                     density=2000.0,
                                     kt=50, frictionAngle=0.3, kr=10, muR=0.1, ko=10, muO=0.1))
    O.bodies.append([utils.sphere((0, 0, 0), 1e-3, material=m), utils.sphere((2e-3 - 2e-5, 0, 0), 1e-3, material=m)])
    O.bodies[1].state.vel = (-0.01, 0.002, 0)
    O.bodies[1].state.angVel = (0, 0, 3.0)
    ip2 = ip2 or w.Ip2_MesoMat_MesoMat_MesoPhys()
    if drag is True:
        drag = w.MesoBackgroundDamping(gammaB=1e-3, gammaBR=1e-4)
    O.engines = ([w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb()]),
                  w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom6D()], [ip2], [law or w.Law2_ScGeom_MesoPhys_Meso()])]
                 + ([drag] if drag else []) + [w.NewtonIntegrator(damping=0)])
    O.dt = 1e-6
    O.trackEnergy = True
    if steps:
        O.run(steps, True)
    return ip2


def finite_scene():
    return all(math.isfinite(x) for b in O.bodies
               for x in tuple(b.state.pos) + tuple(b.state.vel) + tuple(b.state.angVel))


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
WRONG = [None, "a", b"1", True, -1, 0, 2 ** 31, 2 ** 63, [2 ** 31], [None], (), {}, 1e-300, float("nan"), float("inf"),
         3 + 0j]
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
        count("updateAttrs mixed", "accepted and ran clean" if clean_collision(mat) else "other",
              f"{kw}: non-finite state")
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
        owner = owner_class(text, h.start())
        damaged = text[:h.start(1)] + bad + text[h.end(1):]
        if rng.random() < 0.25:  # a vector shortened: its first item dropped, the count kept
            m = __import__("re").search(r"<item>[^<]*</item>", damaged[h.start():])
            if m:
                damaged = damaged[:h.start() + m.start()] + damaged[h.start() + m.end():]
        path = os.path.join(tmp, f"e{k}.xml")
        open(path, "w").write(damaged)
        died = survives_in_a_fork(lambda: O.load(path))
        if died:
            count("save files (every class)", "other", f"[crash] <{tag}> = {bad!r} ({path}): O.load {died}", cls=owner)
            continue
        try:
            O.load(path)
        except Exception:  # noqa: BLE001 (refused)
            count("save files (every class)", "rejected clearly", cls=owner)
            continue
        count("save files (every class)", run_outcome(), f"<{tag}> = {bad!r}: loaded, then not clean", cls=owner)
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
            data = bytearray(bytes(data).replace(b"\x01\x00\x00\x00",
                                                 rng.choice([b"\xff\xff\xff\x7f", b"\x00\xe1\xf5\x05"]), 1))
        with open(os.path.join(tmp, "contact-bytes"), "wb") as f:  # the input at hand, kept if the process dies on it
            f.write(bytes(data))
        # Boost's binary archive reads the bytes: tried first in a copy of this process, which may die on them
        died = survives_in_a_fork(lambda: store.importContacts(bytes(data)))
        if died:
            count("contact bytes", "other", f"[crash] {how}: importContacts {died}; the bytes (base64): "
                  f"{__import__('base64').b64encode(bytes(data)).decode()}")
            continue
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
            count("contact bytes",
                  "rejected clearly" if "#0+#1" in str(e) and "nothing was restored" in str(e) else "other",
                  f"{how}: restore: {e}")
            continue
        except Exception as e:  # noqa: BLE001
            count("contact bytes", "other", f"{how}: restore raised {type(e).__name__}: {e}")
            continue
        count("contact bytes", "accepted and ran clean" if runs_clean() else "other",
              f"{how}: imported, then not clean")
    # 10. Extreme finite values: every number near and beyond the range the law computes with.
    for _ in range(args.n):
        name = rng.choice(NUMBERS)
        val = rng.choice([10 ** rng.uniform(-320, 308), 1e-100, 1e100, 9.9e-101, 1.01e100, 5e-324, 1.7e308,
                          2.2250738585072014e-308])
        try:
            mat = w.MesoMat(**{name: val})
        except (ValueError, TypeError) as e:
            count("extreme values", "rejected clearly" if names_it(e, [name]) else "other", f"{name}={val}: {e}")
            continue
        count("extreme values", "accepted and ran clean" if clean_collision(mat) else "other",
              f"{name}={val}: non-finite state")
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
        owner = "MesoContactStore" if meth.endswith("Contacts") else "Ip2_MesoMat_MesoMat_MesoPhys"
        try:
            r = getattr(store if meth.endswith("Contacts") else ip2, meth)(*a)
        except (ValueError, TypeError, RuntimeError) as e:
            count("Ip2 methods", "rejected clearly" if any(n in str(e) for n in names) else "other",
                  f"{meth}{tuple(map(repr, a))}: {type(e).__name__}: {e}",
                  cls=owner)
            continue
        ok = not isinstance(r, float) or (math.isfinite(r) and r > 0)
        count("Ip2 methods", "accepted and ran clean" if ok and runs_clean(5) else "other",
              f"{meth}{tuple(map(repr, a))} = {r!r}", cls=owner)
    # 12. Another IPhys put on a live meso contact from Python, then O.run (the engine thread).
    kinds = [w.MesoPhys, w.MesoTangentialPhys, w.FrictPhys, w.NormShearPhys, w.ViscElPhys, w.RotStiffFrictPhys, w.IPhys]
    for _ in range(args.n // 4):
        every_mechanism_pair(drag=rng.random() < 0.5)
        kind = rng.choice(kinds)
        O.interactions[0, 1].phys = kind()
        count("phys replaced", "accepted and ran clean" if runs_clean(rng.choice([1, 20, 100])) else "other",
              f"{kind.__name__}")


def falling_onto(surface, functor, v=0.05, steps=400):
    """A sphere falling at v onto ``surface`` (a body) through ``functor``: finite at the end, and
    whether it touched (its velocity changed, or a contact with the surface is real)."""
    O.reset()
    m = O.materials.append(w.MesoMat(k1=100, kp=500, kc=20, phiF=0.1, density=2000.0))
    surface.material = O.materials[m]
    sid = O.bodies.append(surface)
    ball = O.bodies.append(utils.sphere((0, 0, 1.0e-3 + 2e-6), 1e-3, material=m))  # 40 steps from touching
    O.bodies[ball].state.vel = (0, 0, -v)
    O.engines = [w.ForceResetter(),
                 w.InsertionSortCollider([w.Bo1_Sphere_Aabb(), w.Bo1_Facet_Aabb(), w.Bo1_Wall_Aabb()]),
                 w.InteractionLoop([functor, w.Ig2_Sphere_Sphere_ScGeom()], [w.Ip2_MesoMat_MesoMat_MesoPhys()],
                                   [w.Law2_ScGeom_MesoPhys_Meso()]), w.NewtonIntegrator(damping=0)]
    O.dt = 1e-6
    O.run(steps, True)  # in one call: each O.run(n, True) waits about 40 ms for YADE's thread
    b = O.bodies[ball].state  # the sphere's state (a facet given a NaN vertex has a NaN position of its own)
    # nothing but a contact acts on the sphere (no gravity, no damping): it touched if its velocity changed
    touched = tuple(b.vel) != (0, 0, -v) or (O.interactions.has(sid, ball) and O.interactions[sid, ball].isReal)
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
        count("phys/geom from Python", "accepted and ran clean" if runs_clean(rng.choice([1, 30, 200])) else "other",
              what)
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
            count("store across geometry classes", "rejected clearly" if a in str(e) and b in str(e) else "other",
                  f"{a}->{b}: {e}")
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
                  f"{kind.__name__} {val!r}: {e}", cls=kind.__name__)
            continue
        surface = (utils.wall(0, axis=2, sense=0) if "Wall" in kind.__name__
                   else utils.facet([(-3e-3, -3e-3, 0), (3e-3, -3e-3, 0), (0, 3e-3, 0)], fixed=True))
        ok, touched = falling_onto(surface, f)
        count("functor attributes", "accepted and ran clean" if ok and touched else "other", f"{kind.__name__} {val!r}",
              cls=kind.__name__)
    # 16. Degenerate and extreme facets and walls: a falling sphere, finite throughout; an invalid
    #     wall axis makes no contact and is said (the functor warns; set_detection refuses it).
    for _ in range(args.n):
        if rng.random() < 0.3:
            axis, sense = rng.choice([-1, 0, 1, 2, 3, 7]), rng.choice([-1, 0, 1])
            ok, touched = falling_onto(utils.wall(0, axis=2, sense=sense), w.Ig2_Wall_Sphere_MesoScGeom())
            O.bodies[0].shape.axis = axis
            ok = ok and finite_scene() and runs_clean(50)
            count("facets and walls", "accepted and ran clean" if ok else "other", f"wall axis {axis}",
                  cls="Ig2_Wall_Sphere_MesoScGeom")
            continue
        a, b, c = [rng.uniform(-3e-3, 3e-3) for _ in range(3)], [rng.uniform(-3e-3, 3e-3) for _ in range(3)], \
            [rng.uniform(-3e-3, 3e-3) for _ in range(3)]
        how = rng.choice(["coincident", "collinear", "nan", "huge", "tiny", "flat", "regular"])
        functor = rng.choice(functors[:2])()
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
            count("facets and walls", "rejected clearly", f"{how}: {type(e).__name__}", cls=type(functor).__name__)
            continue
        ok, touched = falling_onto(surface, functor)
        count("facets and walls", "accepted and ran clean" if ok else "other", f"{how}: non-finite state",
              cls=type(functor).__name__)
    # 17. The loop registry: labels and periods of every kind; refused by name, or a runner that calls.
    from mesocontact import loop
    names = ["O", "sphere", "len", "__import__", "wrapper", "utils", "probe_a", "probeB", "two words", "1x", "", "None",
             5, None]
    for _ in range(args.n):
        label = rng.choice(names) if rng.random() < 0.6 else "fz" + "".join(rng.choice("abc_") for _ in range(4))
        period = rng.choice(WRONG + [1, 2, 7, 1.0, "3"])
        calls = []
        try:
            O.reset()
            O.engines = [loop.runner(lambda: calls.append(O.iter), period, label)]
        except (ValueError, TypeError) as e:
            count("loop registry",
                  "rejected clearly" if ("label" in str(e) or "period" in str(e) or "fn" in str(e)) else "other",
                  f"{label!r} {period!r}: {e}")
            continue
        O.run(7, True)
        count("loop registry", "accepted and ran clean" if len(calls) == len(range(period, 7, period)) else "other",
              f"{label!r} {period!r}: {len(calls)} calls")


# ---- Issue #57: every registered class, and the new inputs ----------------------------------------------
import numpy as np  # noqa: E402
from mesocontact import calibrate, loop, scene  # noqa: E402

R = 1e-3
# Attributes YADE does not save, by design: a material's id (O.materials gives it), the drag's sumInLaw and
# lawSumSteps (Attr::noSave, pkg/yade/MesoBackgroundDamping.hpp: True and 0 after O.load).
NOT_SAVED = ("id", "sumInLaw", "lawSumSteps")
FORMATS = (".xml", ".xml.gz", ".xml.bz2", ".bin", ".bin.gz", ".bin.bz2")  # YADE's six save formats
PLAIN = dict(k1=100.0, kp=500.0, kc=100.0, phiF=0.1, gammaN=0.05, density=2000.0)
MATERIALS = {"plain": PLAIN, "sliding": dict(PLAIN, kt=50.0, frictionAngle=0.5),
             "reversible": dict(PLAIN, fa=1e-5, kca=50.0, adhesion="reversible"),
             "jumpIn": dict(PLAIN, fa=1e-5, kca=50.0, adhesion="jumpIn")}


def same(a, b):
    """Equal values, NaN equal to NaN (Vector3 and sequences item by item)."""
    if isinstance(a, float) and isinstance(b, float):
        return a == b or (a != a and b != b)
    try:
        if len(a) == len(b) and not isinstance(a, str):
            return all(same(x, y) for x, y in zip(a, b))
    except TypeError:
        pass
    return a == b


def attrs_of(obj):
    return {k: v for k, v in obj.dict().items()}


def unchanged(before, obj):
    after = attrs_of(obj)
    return all(same(before[k], after.get(k)) for k in before)


def named(e, names):
    """The error's message names one of ``names``."""
    return any(str(n) in str(e) for n in names)


_WRITABLE = {}


def writable(name):
    """The attributes Python may set on the class (own and inherited)."""
    if name not in _WRITABLE:
        obj, out = getattr(w, name)(), []
        for k, v in obj.dict().items():
            try:
                setattr(obj, k, v)
                out.append(k)
            except Exception:  # noqa: BLE001 - read-only
                pass
        _WRITABLE[name] = out
    return _WRITABLE[name]


CHOICES = {"leverArm": ("reduced", "a12"), "reference": ("lab", "contacts"), "adhesion": TEXTS["adhesion"],
           "k2Interpolation": TEXTS["k2Interpolation"], "branch": ("new", "loading"), "label": ("", "fzLabel", "fz_b")}


def plausible(name, default):
    if name in CHOICES:
        return rng.choice(CHOICES[name])
    if isinstance(default, bool):
        return rng.random() < 0.5
    if isinstance(default, int):
        return rng.choice([0, 1, 5, -1, default])
    if isinstance(default, float):
        return value_for(name) if name in NAMES else rng.choice([0.0, 10 ** rng.uniform(-6, 4), default])
    if hasattr(default, "__len__") and len(default) == 3:
        return tuple(rng.uniform(-1e-3, 1e-3) for _ in range(3))
    return default


def saved_and_loaded(obj):
    """The object alone in O.miscParams, saved in one of YADE's formats and loaded (what `yade --test`'s
    testSaveAllClasses does to every class): None if it came back equal, else what went wrong."""
    before = attrs_of(obj)
    O.reset()
    O.miscParams = [obj]
    path = os.path.join(tmp, "misc" + rng.choice(FORMATS))
    try:
        O.save(path)
        O.load(path)
    except Exception as e:  # noqa: BLE001
        return f"save/load: {type(e).__name__}: {e}"
    back = attrs_of(O.miscParams[0])
    diff = [k for k in before if k not in NOT_SAVED and not same(before[k], back.get(k))]
    return f"loaded back with {diff} changed" if diff else None


def used_cleanly(name, obj):
    """The accepted object at work: a material in a collision, a phys on a live contact, a functor
    or engine in a scene; (outcome, detail)."""
    if name == "MesoMat":
        return ("accepted and ran clean" if clean_collision(obj) else "other"), "collision not finite"
    if name in ("MesoPhys", "MesoTangentialPhys"):
        every_mechanism_pair(drag=False)
        O.interactions[0, 1].phys = obj
        return run_outcome(20), "phys put on a live contact"
    if name.startswith("Ig2_"):
        surface = (utils.wall(0, axis=2, sense=0) if "Wall" in name
                   else utils.facet([(-3e-3, -3e-3, 0), (3e-3, -3e-3, 0), (0, 3e-3, 0)], fixed=True))
        ok, touched = falling_onto(surface, obj)
        return ("accepted and ran clean" if ok and touched else "other"), f"falling sphere ok {ok} touched {touched}"
    if name in ("Ip2_MesoMat_MesoMat_MesoPhys", "Law2_ScGeom_MesoPhys_Meso", "MesoBackgroundDamping"):
        every_mechanism_pair(drag=obj if name == "MesoBackgroundDamping" else rng.random() < 0.5,
                             ip2=obj if name.startswith("Ip2") else None, law=obj if name.startswith("Law2") else None,
                             steps=0)
        return run_outcome(50), "in a pair with every mechanism"
    return "accepted and ran clean", ""  # MesoPairParams, MesoContactStore: nothing to set


def live_pair(tangential):
    """Two spheres in contact (MesoTangentialPhys with sliding, else MesoPhys), run 20 steps."""
    O.reset()
    m = O.materials.append(w.MesoMat(**MATERIALS["sliding" if tangential else "jumpIn"]))
    O.bodies.append([utils.sphere((0, 0, 0), R, material=m), utils.sphere((2 * R - 2e-5, 0, 0), R, material=m)])
    O.bodies[1].state.vel = (-0.01, 0.002, 0)
    O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb()]),
                 w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom6D()], [w.Ip2_MesoMat_MesoMat_MesoPhys()],
                                   [w.Law2_ScGeom_MesoPhys_Meso()]),
                 w.NewtonIntegrator(damping=0)]
    O.dt = 1e-6
    O.run(20, True)


def mixed_collision(mat):
    """A MesoMat sphere against a FrictMat one through YADE's FrictMat pair (docs/usage.md, "Mixed
    materials": YADE's linear law reads young and poisson): finite throughout."""
    O.reset()
    m = O.materials.append(mat)
    f = O.materials.append(w.FrictMat(young=1e8, poisson=0.3, density=2000.0, frictionAngle=0.4))
    O.bodies.append([utils.sphere((0, 0, 0), R, material=m), utils.sphere((2 * R + 5e-7, 0, 0), R, material=f)])
    O.bodies[1].state.vel = (-0.05, 0.01, 0)
    O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb()]),
                 w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom()],
                                   [w.Ip2_MesoMat_MesoMat_MesoPhys(), w.Ip2_FrictMat_FrictMat_FrictPhys()],
                                   [w.Law2_ScGeom_MesoPhys_Meso(), w.Law2_ScGeom_FrictPhys_CundallStrack()]),
                 w.NewtonIntegrator(damping=0)]
    O.dt = min(1e-7, 0.3 * utils.PWaveTimeStep())
    O.run(200, True)
    return finite_scene()


def detection_state():
    """What set_detection may change: the colliders' bound functors and every geometry functor, with their factors."""
    return ([(type(f).__name__, getattr(f, "aabbEnlargeFactor", None)) for e in O.engines if isinstance(e, w.Collider)
             for f in e.boundDispatcher.functors],
            [(type(f).__name__, getattr(f, "interactionDetectionFactor", None)) for e in O.engines
             if isinstance(e, w.InteractionLoop) for f in e.geomDispatcher.functors], O.dt)


def surface_scene(mat, wall_axis=None):
    """Two spheres 1.5 range apart, a facet under them and a wall beside them, with YADE's facet and wall
    functors (set_detection replaces them); the wall along ``wall_axis`` (0-2)."""
    scene.reset()
    O.materials.append(w.MesoMat(**mat))
    gap = 1.5 * mat.get("fa", 0) / mat.get("kca", 1) if mat.get("fa") else 1e-6
    O.bodies.append([utils.sphere((0, 0, 0), R, material=0), utils.sphere((2 * R + gap, 0, 0), R, material=0)])
    O.bodies[1].state.vel = (-0.02, 0, 0)
    O.bodies.append(utils.facet([(-4 * R, -4 * R, -R - gap), (6 * R, -4 * R, -R - gap), (0, 6 * R, -R - gap)],
                                fixed=True, material=0))
    axis = 1 if wall_axis is None else wall_axis
    O.bodies.append(utils.wall(-R - gap if axis != 0 else -R - gap, axis=axis, sense=0, material=0))
    O.engines = [w.ForceResetter(),
                 w.InsertionSortCollider([w.Bo1_Sphere_Aabb(), w.Bo1_Facet_Aabb(), w.Bo1_Wall_Aabb()]),
                 w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom6D(), w.Ig2_Facet_Sphere_ScGeom(),
                                    rng.choice([w.Ig2_Wall_Sphere_ScGeom, w.Ig2_Wall_Sphere_MesoScGeom])()],
                                   [w.Ip2_MesoMat_MesoMat_MesoPhys()], [w.Law2_ScGeom_MesoPhys_Meso()]),
                 w.NewtonIntegrator(damping=0, gravity=(0, 0, -9.81))]
    O.dt = 1e-6
    return O.bodies[-1].id


with quiet_fd2():
    # 18. Every class the plugin registers: made with its own keywords (and unknown ones, wrong types),
    #     updated or assigned (a contact's phys also live, on a running contact); refused naming the key
    #     and unchanged, or saved alone and loaded back equal (yade --test's testSaveAllClasses) and then
    #     put to work. An "other" says its kind in brackets.
    for _ in range(args.n):
        name = rng.choice(PLUGIN_CLASSES)
        cls, keys = getattr(w, name), list(getattr(w, name)().dict())
        kw = {}
        if rng.random() > 0.2:  # else made by default, as yade --test does
            pool = keys + ["label", "nonexistent", "K1"]
            for k in rng.sample(pool, min(len(pool), rng.randint(1, 3))):
                default = getattr(cls(), k, 0.0) if k in keys else 0.0
                kw[k] = rng.choice(WRONG + BAD) if rng.random() < 0.35 else plausible(k, default)
        how = "constructor" if not kw or rng.random() < 0.4 else ("assignment" if len(kw) == 1 else "updateAttrs")
        live = name in ("MesoPhys", "MesoTangentialPhys") and how != "constructor" and rng.random() < 0.5
        if live:  # the phys of a running contact of that class
            live_pair(tangential=name == "MesoTangentialPhys")
            obj = O.interactions[0, 1].phys
            how += " (live contact)"
        else:
            obj = cls()
        before = None
        try:
            if how.startswith("constructor"):
                obj = cls(**kw)
            elif how.startswith("assignment"):
                before = attrs_of(obj)
                setattr(obj, *next(iter(kw.items())))
            else:
                before = attrs_of(obj)
                obj.updateAttrs(kw)
        except (ValueError, TypeError, AttributeError) as e:
            kept = before is None or unchanged(before, obj)
            # an assignment's statement names its attribute: a read-only one may say only "no setter"
            clear = named(e, kw) or (how.startswith("assignment") and "has no setter" in str(e))
            kind = ("" if clear and kept else "[unnamed error] " if not clear
                    else "[refused, but the keys before the bad one were set] ")
            count("every class", "rejected clearly" if clear and kept else "other",
                  f"{kind}{name} {how} {kw!r}: {type(e).__name__}: {e}", cls=name)
            continue
        except Exception as e:  # noqa: BLE001
            count("every class", "other", f"[unnamed error] {name} {how} {kw!r}: {type(e).__name__}: {e}", cls=name)
            continue
        unknown = [k for k in kw if k not in keys]
        if unknown:  # Boost.Python keeps it in the instance's __dict__: YADE never sees it
            count("every class", "other", f"[unknown attribute accepted, without effect] {name} {how} {kw!r}", cls=name)
            continue
        if live:
            count("every class", run_outcome(50), f"[run] {name} {how} {kw!r}", cls=name)
            continue
        problem = saved_and_loaded(obj)
        if problem:
            count("every class", "other", f"[save/load] {name} {how} {kw!r}: {problem}", cls=name)
            continue
        outcome, detail = used_cleanly(name, obj)
        count("every class", outcome, f"[run] {name} {how} {kw!r}: {detail}", cls=name)

    # 19. MesoMat's young and poisson (YADE's FrictMat laws read them), label and id: constructor,
    #     assignment, updateAttrs; an accepted value then runs a meso collision and a MesoMat-FrictMat one.
    YP = {"young": [float("nan"), float("inf"), -float("inf"), 1e300, 1e-300, 1e100, 1e-100, 1.01e100, 9.9e-101, 3,
                    -1.0, 0.0,
                    "abc", "1e9", True, False, None, 3 + 0j, [1e9], np.float64(1e9), np.bool_(True),
                    10 ** rng.uniform(6, 11)],
          "poisson": [float("nan"), float("inf"), -float("inf"), 3, 3.0, -0.1, 0.0, 1.0, 1.0000001, 0.25, 0.5, 1e300,
                      1e-300,
                      "abc", "0.3", True, False, None, [0.3], np.float64(0.3), np.bool_(False)],
          "label": ["grain", "", "two words", "é", 3, None, True, 1.5, b"x", ["a"], np.str_("np")],
          "id": [-1, 0, 5, 2 ** 31 - 1, 2 ** 31, -2 ** 40, "1", 1.5, None, True, float("nan"), np.int64(4)]}
    for _ in range(args.n):
        keys = rng.sample(sorted(YP), rng.choice([1, 1, 2]))
        kw = {k: rng.choice(YP[k]) if rng.random() < 0.8 else (rng.uniform(0, 0.5) if k == "poisson" else
                                                               10 ** rng.uniform(6, 11) if k == "young" else YP[k][0])
              for k in keys}
        if rng.random() < 0.3:
            kw.update({n: value_for(n) for n in rng.sample(NUMBERS, 1)})
        how = rng.choice(["constructor", "assignment" if len(kw) == 1 else "updateAttrs", "updateAttrs"])
        mat, before = w.MesoMat(k1=100.0, kp=500.0, density=2000.0), None
        try:
            if how == "constructor":
                mat = w.MesoMat(**kw)
            else:
                before = attrs_of(mat)
                if how == "assignment":
                    setattr(mat, *next(iter(kw.items())))
                else:
                    mat.updateAttrs(kw)
        except (ValueError, TypeError, AttributeError) as e:
            kept = before is None or unchanged(before, mat)
            count("MesoMat young/poisson/label/id", "rejected clearly" if named(e, kw) and kept else "other",
                  f"{how} {kw!r}: {type(e).__name__}: {e}; unchanged {kept}")
            continue
        except Exception as e:  # noqa: BLE001
            count("MesoMat young/poisson/label/id", "other", f"{how} {kw!r}: {type(e).__name__}: {e}")
            continue
        ok = clean_collision(mat) and mixed_collision(mat)
        count("MesoMat young/poisson/label/id", "accepted and ran clean" if ok else "other",
              f"{how} {kw!r}: non-finite state")

    # 20. scene.set_detection(margin): refused naming the margin with nothing changed, or the scene
    #     (adhesive or not, a facet and a wall with YADE's functors) runs clean.
    MARGINS = [float("inf"), -float("inf"), float("nan"), -1.0, 0.0, 0.5, 0.999, 1.0, 1.2, 2, 10.0, 1e6, 1e300, 1e-300,
               "abc", "1.2", None, True, False, [1.2], (1.2,), {}, 3 + 0j, np.float64(1.5), np.float32(2.0),
               np.int64(3),
               np.bool_(True), np.array([1.5])]
    for _ in range(args.n):
        mat = MATERIALS[rng.choice(sorted(MATERIALS))]
        surface_scene(mat)
        margin = rng.choice(MARGINS) if rng.random() < 0.8 else rng.uniform(1, 5)
        before = detection_state()
        try:
            factor = scene.set_detection(margin) if rng.random() < 0.5 else scene.set_detection(margin=margin)
        except (ValueError, TypeError) as e:
            kept = detection_state() == before
            count("set_detection margin", "rejected clearly" if "margin" in str(e) and kept else "other",
                  f"margin={margin!r}: {type(e).__name__}: {e}; unchanged {kept}")
            continue
        except Exception as e:  # noqa: BLE001
            count("set_detection margin", "other", f"margin={margin!r}: {type(e).__name__}: {e}")
            continue
        try:
            O.dt = scene.time_step()
            good = isinstance(factor, float) and math.isfinite(factor) and factor >= 1 and runs_clean(300)
        except Exception as e:  # noqa: BLE001
            good, factor = False, f"{factor!r}, then {type(e).__name__}: {e}"
        count("set_detection margin", "accepted and ran clean" if good else "other",
              f"margin={margin!r}: factor {factor!r}, finite {finite_scene()}")

    # 21. scene.engines(gravity, sorted_loop): refused naming the argument, or a sphere falls on a box clean.
    GRAVITY = [(0, 0, -9.81), [0, 0, -9.81], __import__("yade").Vector3(0, 0, -9.81), np.array([0.0, 0.0, -9.81]),
               (float("nan"), 0, 0),
               (0, float("inf"), 0), (0, 0, -float("inf")), None, (0, 0), (0, 0, 0, 0), (), "abc", "0,0,-9.81", b"xyz",
               9.81,
               (True, 0, 0), (0, 0, "x"), (None, 0, 0), (3 + 0j, 0, 0), (1e300, 0, 0), (1e-300, 0, 0), (0, 0, -1e6),
               (np.float32(1.0), 0, np.int64(-9)), {}, {0: 1, 1: 2, 2: 3}, {0.0, 1.0, -9.81}, iter([0, 0, -9.81])]
    for _ in range(args.n):
        g = rng.choice(GRAVITY) if rng.random() < 0.85 else tuple(rng.uniform(-20, 20) for _ in range(3))
        if isinstance(g, type(iter([]))):
            g = iter([0, 0, -9.81])  # a fresh iterator each time
        sl = rng.choice([False, True]) if rng.random() < 0.7 else rng.choice([0, 1, None, "yes", np.bool_(True), 1.0])
        try:
            engines = scene.engines(gravity=g, sorted_loop=sl) if rng.random() < 0.7 else scene.engines(g)
        except (ValueError, TypeError) as e:
            count("engines gravity",
                  "rejected clearly" if ("gravity" in str(e) or "sorted_loop" in str(e)) else "other",
                  f"gravity={g!r} sorted_loop={sl!r}: {type(e).__name__}: {e}")
            continue
        except Exception as e:  # noqa: BLE001
            count("engines gravity", "other", f"gravity={g!r} sorted_loop={sl!r}: {type(e).__name__}: {e}")
            continue
        if isinstance(g, (dict, set, frozenset)):  # no order of its own: taken as its keys, in some order
            count("engines gravity", "other",
                  f"[a mapping or set taken as a vector] gravity={g!r}: NewtonIntegrator.gravity = "
                  f"{[e.gravity for e in engines if isinstance(e, w.NewtonIntegrator)]}")
            continue
        scene.reset()
        O.materials.append(w.MesoMat(**MATERIALS[rng.choice(sorted(MATERIALS))]))
        O.bodies.append([utils.sphere((0, 0, R + 1e-6), R, material=0),
                         utils.box((0, 0, -R), (5 * R, 5 * R, R), fixed=True, material=0)])
        O.engines = engines
        try:
            O.dt = scene.time_step()
            good, why = runs_clean(300), "not clean"
        except Exception as e:  # noqa: BLE001
            good, why = False, f"{type(e).__name__}: {e}"
        count("engines gravity", "accepted and ran clean" if good else "other", f"gravity={g!r}: {why}")

    # 22. Wall.axis outside 0..2 (YADE's Bo1_Wall_Aabb aborts the process at the next bound update): refused
    #     by scene.check, set_detection and time_step naming the body, nothing changed; never run. A valid
    #     axis: accepted, and a sphere thrown at the wall runs clean.
    for _ in range(args.n):
        axis = rng.choice([-2 ** 31, -7, -1, 3, 4, 100, 2 ** 31 - 1]) if rng.random() < 0.7 else rng.randrange(3)
        valid = axis in (0, 1, 2)
        wid = surface_scene(MATERIALS[rng.choice(sorted(MATERIALS))], axis if valid else rng.randrange(3))
        O.bodies[wid].shape.axis = axis
        call = rng.choice(["check", "set_detection", "time_step"])
        before = detection_state()
        try:
            r = getattr(scene, call)()
            if call == "time_step":
                O.dt = r
        except ValueError as e:
            kept = detection_state() == before
            count("Wall.axis checks",
                  "rejected clearly" if not valid and "Wall.axis" in str(e) and f"#{wid}" in str(e) and kept
                  else "other", f"axis {axis} {call}: {e}; unchanged {kept}")
            continue
        except Exception as e:  # noqa: BLE001
            count("Wall.axis checks", "other", f"axis {axis} {call}: {type(e).__name__}: {e}")
            continue
        if not valid:  # not run: YADE would abort
            count("Wall.axis checks", "other", f"axis {axis} {call}: accepted")
            continue
        touched = False
        try:
            if call != "time_step":
                O.dt = scene.time_step()
            O.bodies[0].state.vel = tuple(-0.05 if k == axis else 0 for k in range(3))
            O.run(30, True)  # the sphere starts a few steps from the wall; the contact lasts about 70 steps
            touched = O.interactions.has(0, wid) and O.interactions[0, wid].isReal
            O.run(270, True)
        except Exception as e:  # noqa: BLE001
            count("Wall.axis checks", "other", f"axis {axis} {call}: accepted, then {type(e).__name__}: {e}")
            continue
        count("Wall.axis checks", "accepted and ran clean" if finite_scene() and touched else "other",
              f"axis {axis} {call}: finite {finite_scene()}, touched {touched}")


def mesh_drag(facets, start, direction, speed, mat, functor, press, hold, steps):
    """A sphere pressed onto ``facets`` (z = 0) with ``press`` [N], then held at ``hold`` and dragged
    at ``speed`` along ``direction`` (x, y prescribed, z free): the total force of its facet
    contacts at every step of the drag, the most real facet contacts at one step, finite throughout."""
    scene.reset()
    O.materials.append(w.MesoMat(**mat))
    ids = set(O.bodies.append(utils.facet(v, fixed=True, material=0)) for v in facets)
    ball = O.bodies.append(utils.sphere((start[0], start[1], R), R, material=0))
    b = O.bodies[ball]
    b.state.blockedDOFs = "xyXYZ"
    O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb(), w.Bo1_Facet_Aabb()], verletDist=0),
                 w.InteractionLoop([getattr(w, functor)()], [w.Ip2_MesoMat_MesoMat_MesoPhys()],
                                   [w.Law2_ScGeom_MesoPhys_Meso()]),
                 w.NewtonIntegrator(damping=0)]
    scene.set_detection()
    O.dt = 0.2 * math.sqrt(b.state.mass / mat["kp"])

    def contacts():
        return [i for i in O.interactions.withBody(ball) if i.isReal and (i.id1 in ids or i.id2 in ids)]
    O.forces.setPermF(ball, (0, 0, -press))
    O.run(300, True)
    pressed = len(contacts())
    O.forces.setPermF(ball, (0, 0, -hold))
    n = math.hypot(*direction)
    b.state.vel = (speed * direction[0] / n, speed * direction[1] / n, 0)
    forces, most, finite = [], pressed, finite_scene()
    for _ in range(steps):
        O.step()
        real = contacts()
        most = max(most, len(real))
        f = [0.0, 0.0, 0.0]
        for i in real:
            t = i.phys.normalForce + i.phys.shearForce
            f = [f[j] + t[j] for j in range(3)]
        forces.append(f)
        finite = finite and finite_scene()
    return forces, pressed, most, finite


def coplanar_mesh(kind, L):
    """Triangles of one flat surface (z = 0): a grid of squares split on random diagonals, four around
    a vertex, or a strip of small squares."""
    if kind == "grid":
        k = rng.randint(1, 4)
        h = 2 * L / k
        tris = []
        for i in range(k):
            for j in range(k):
                a, b, c, d = ((-L + i * h, -L + j * h, 0), (-L + (i + 1) * h, -L + j * h, 0),
                              (-L + (i + 1) * h, -L + (j + 1) * h, 0), (-L + i * h, -L + (j + 1) * h, 0))
                tris += [[a, b, c], [a, c, d]] if rng.random() < 0.5 else [[a, b, d], [b, c, d]]
        return tris
    if kind == "four":
        return [[(0, 0, 0), (L, -L, 0), (L, L, 0)], [(0, 0, 0), (L, L, 0), (-L, L, 0)],
                [(0, 0, 0), (-L, L, 0), (-L, -L, 0)], [(0, 0, 0), (-L, -L, 0), (L, -L, 0)]]
    S = 0.1 * R
    return [t for k in range(-30, 30) for t in ([(k * S, -S, 0), ((k + 1) * S, -S, 0), ((k + 1) * S, S, 0)],
                                                [(k * S, -S, 0), ((k + 1) * S, S, 0), (k * S, S, 0)])]


def with_duplicates(tris):
    """Some triangles repeated (as STL exports may): the same, with their vertices rotated or reversed,
    or shifted within the plane (overlapping)."""
    out, made = list(tris), []
    for _ in range(rng.choice([0, 1, 1, 2, 3])):
        a, b, c = rng.choice(tris)
        how = rng.choice(["same", "rotated", "reversed", "shifted"])
        if how == "shifted":
            s = [rng.uniform(-0.2, 0.2) * (b[k] - a[k]) for k in range(2)] + [0.0]
            a, b, c = [tuple(v[k] + s[k] for k in range(3)) for v in (a, b, c)]
        out.append({"same": [a, b, c], "rotated": [b, c, a], "reversed": [c, b, a], "shifted": [a, b, c]}[how])
        made.append(how)
    return out, made


LARGE = [[(-100 * R, -100 * R, 0), (100 * R, -100 * R, 0), (0, 100 * R, 0)]]  # one facet under every drag
with quiet_fd2():
    # 23. Facet meshes of one flat surface, with duplicated and overlapping triangles, a sphere pressed
    #     and dragged across their edges and vertices: finite, one contact at every step, the force of
    #     one large facet at every step (the history carried across), no contact dropped by YADE.
    for _ in range(args.n // 2):
        kind = rng.choice(["grid", "grid", "four", "strip"])
        L = 5 * R
        tris, dups = with_duplicates(coplanar_mesh(kind, L))
        rng.shuffle(tris)
        if kind == "strip":
            start, direction = (-1.0 * R, rng.uniform(-0.03, 0.03) * R), (1.0, rng.uniform(-0.02, 0.02))
        else:
            start = (rng.uniform(-0.3, 0.3) * L, rng.uniform(-0.3, 0.3) * L)
            a = rng.uniform(0, 2 * math.pi)
            direction = (math.cos(a), math.sin(a))
        mname = rng.choice(sorted(MATERIALS))
        functor = rng.choice(["Ig2_Facet_Sphere_ScGeom", "Ig2_Facet_Sphere_ScGeom6D", "Ig2_Facet_Sphere_MesoScGeom",
                              "Ig2_Facet_Sphere_MesoScGeom6D"])
        press = rng.choice([0.005, 0.03])
        setting = dict(start=start, direction=direction, speed=rng.choice([0.01, 0.05, 0.1]), mat=MATERIALS[mname],
                       functor=functor, press=press, hold=press * rng.uniform(0.2, 0.8), steps=250)
        mark = stderr_mark()
        f_mesh, pressed, most, finite = mesh_drag(tris, **setting)
        err = stderr_since(mark)
        f_ref, _, _, _ = mesh_drag(LARGE, **setting)
        gap = max(math.dist(a, c) for a, c in zip(f_mesh, f_ref))
        ok = finite and pressed == 1 and most == 1 and gap <= 1e-6 * press and "IGeomFunctor returned false" not in err
        # set_detection puts the package's in
        cls = functor if "Meso" in functor else functor.replace("_ScGeom", "_MesoScGeom")
        count("facet meshes", "accepted and ran clean" if ok else "other",
              f"{kind} {len(tris)} facets, duplicates {dups}, {mname}, {functor}: finite {finite}, contacts pressed "
              f"{pressed}, most {most}, |F - F(one facet)| {gap:.3g} N; stderr {err.strip()[:200]!r}", cls=cls)

    # 24. Callbacks that raise in the loop (mesocontact.loop): the step completes, the next step's start
    #     stops with an error naming the runner, no step is repeated and the run goes on. (SystemExit ends
    #     the process by design: ctest yade.loop_callbacks checks it in a subprocess.)
    for _ in range(args.n // 2):
        exc = rng.choice([ValueError("fuzz"), ZeroDivisionError, KeyboardInterrupt, RuntimeError("x" * 5000), TypeError,
                          KeyError("k")])
        fail_at = rng.randint(1, 6)
        before_calls, calls = [], []
        la, lb = "fzBefore" + str(rng.randrange(10 ** 6)), "fzRaising" + str(rng.randrange(10 ** 6))

        def raising(exc=exc, fail_at=fail_at, calls=calls):
            calls.append(O.iter)
            if O.iter == fail_at:
                raise exc
        O.reset()
        O.bodies.append(utils.sphere((0, 0, 0), R))
        O.engines = [loop.runner(lambda: before_calls.append(O.iter), 1, la), w.ForceResetter(),
                     w.NewtonIntegrator(damping=0, gravity=(0, 0, -10)), loop.runner(raising, 1, lb)]
        O.dt = 1e-4
        errors = []
        for _k in range(20):
            if O.iter >= 10:
                break
            try:
                O.step()
            except RuntimeError as e:
                errors.append(str(e))
        # a PyRunner of period 1 first acts at iteration 1; the failing call's step completes, the next stops
        ok = (len(errors) == 1 and lb in errors[0] and O.iter == 10 and before_calls == list(range(1, 10))
              and calls == list(range(1, 10)) and finite_scene())
        count("loop callbacks that raise", "accepted and ran clean" if ok else "other",
              f"{exc!r} at {fail_at}: errors {[e[:120] for e in errors]}, iter {O.iter}, calls {before_calls} "
              f"/ {calls}")
        loop._CALLBACKS.pop(la, None)
        loop._CALLBACKS.pop(lb, None)


# 25-27. The calibration on force-displacement cycles and the parameter helpers: plain Python.
A12 = 1e-3
DMP = theory.delta_max_p(100.0, 500.0, 0.1, A12)
CYCLE_ARGS = ("delta", "force", "a12", "free", "values", "sigma", "interpolation", "shift", "k1", "kp", "kc", "phiF")


def cycles_data(n):
    corners = (0, 0.6, 0.1, 1.6, 0.5, 0.9, 0.2, 2.0, 0.3) if rng.random() < 0.8 else (0, 0.5, 0.35, 1.2, 0.95, 2.0, 1.7)
    per = max(1, n // (len(corners) - 1))
    d = np.concatenate([np.linspace(a, b, per, endpoint=False) for a, b in zip(corners[:-1], corners[1:])]) * DMP
    F = theory.normal_force_path(d, 100.0, 500.0, 100.0, 0.1, A12, "linear")
    return d, (F + rng.choice([0.0, 0.01, 0.01, 0.1]) * np.max(np.abs(F))
               * np.random.default_rng(rng.randrange(1000)).standard_normal(len(F)))


def cycles_input():
    """fit_cycles' arguments: mostly valid cycles with one or two things made adversarial."""
    d, F = cycles_data(rng.choice([20, 40, 80]))
    a12 = A12
    how = rng.choice(["valid"] * 8 + ["scaled"] * 3
                     + ["empty", "one point", "two points", "equal delta", "equal force", "negative delta",
                        "negative force", "zero force", "bools", "numpy bools", "nan", "inf", "strings", "None", "2-D",
                        "lengths differ", "huge", "tiny", "ints", "lists", "constant"])
    if how == "scaled":
        s, t = 10 ** rng.uniform(-105, 105), 10 ** rng.uniform(-105, 105)  # the fit computes within 1e-100 to 1e100
        d, F, a12 = d * s, F * t, a12 * s
    elif how == "empty":
        d, F = [], []
    elif how == "one point":
        d, F = d[:1], F[:1]
    elif how == "two points":
        d, F = d[:2], F[:2]
    elif how == "equal delta":
        d = np.full(len(d), d[len(d) // 2])
    elif how == "equal force":
        F = np.full(len(F), F[len(F) // 2])
    elif how == "negative delta":
        d = -np.abs(d) - 1e-6
    elif how == "negative force":
        F = -np.abs(F) - 1e-6
    elif how == "zero force":
        F = np.zeros(len(F))
    elif how == "bools":
        d = [bool(rng.random() < 0.5) for _ in d] if rng.random() < 0.5 else d
        F = [bool(rng.random() < 0.5) for _ in F] if not isinstance(d, list) or rng.random() < 0.5 else F
    elif how == "numpy bools":
        d = np.asarray(d) > DMP
    elif how == "nan":
        d = np.array(d)
        d[rng.randrange(len(d))] = float("nan")
    elif how == "inf":
        F = np.array(F)
        F[rng.randrange(len(F))] = rng.choice([float("inf"), -float("inf")])
    elif how == "strings":
        d = [str(x) for x in d] if rng.random() < 0.5 else "abc"
    elif how == "None":
        d, F = rng.choice([(None, F), (d, None), (None, None)])
    elif how == "2-D":
        d = np.vstack([d, d])
    elif how == "lengths differ":
        F = F[:-1]
    elif how == "huge":
        d, F, a12 = d * 1e150, F * 1e150, a12 * 1e150
    elif how == "tiny":
        d, F, a12 = d * 1e-150, F * 1e-150, a12 * 1e-150
    elif how == "ints":
        d, F, a12 = np.round(d / DMP * 10).astype(int), np.round(F / np.max(np.abs(F)) * 100).astype(int), 100
    elif how == "lists":
        d, F = list(map(float, d)), list(map(float, F))
    elif how == "constant":
        d, F = np.linspace(0, DMP, len(d)), np.full(len(d), 1.0)
    kw = {}
    if rng.random() < 0.1:
        a12 = rng.choice([0, -1e-3, float("nan"), float("inf"), True, "1e-3", None, 1e300, 1e-300, np.float64(1e-3),
                          [1e-3]])
    if rng.random() < 0.1:
        kw["free"] = rng.choice([("k1",), ("kp", "kc"), ("k1", "k1"), ("shift",), "k1", [], ("x",), None, ("phiF",),
                                 "kpkc",
                                 ("k1", "kp", "kc", "phiF"), (1,)])
    if rng.random() < 0.1:
        kw["values"] = rng.choice([{"k1": 100.0}, {"k1": -1.0}, {"kp": 1.0}, {"phiF": 2.0}, {"kc": float("nan")},
                                   {"x": 1},
                                   {"k1": True}, {"shift": "a"}, "abc", [1], {"kp": 500.0, "kc": 100.0, "phiF": 0.1},
                                   {"k1": 1e300}, {"shift": 1e-3}])
    if rng.random() < 0.15:
        n = len(d) if hasattr(d, "__len__") else 3
        big = float(np.max(np.abs(np.asarray(F, dtype=float)))) if how in ("valid", "scaled") else 1.0
        kw["sigma"] = rng.choice([0, -1, float("nan"), 1e-3 * big, [1e-3 * big] * n, [1.0, 2.0], True, "s", np.zeros(n),
                                  np.full(n, 1e-2 * big), [True] * n, float("inf")])
    if rng.random() < 0.1:
        kw["interpolation"] = rng.choice(["sqrt", "cubic", None, 3, ""])
    if rng.random() < 0.1:
        kw["shift"] = rng.choice([True, 1, "yes", None, np.bool_(True), 0.0])
    return how, d, F, a12, kw


MF_BASE = dict(radius=1e-3, density=2500.0, impact_speed=0.5, restitution=0.6, contact_time=6e-4, phiF=0.1,
               kc_over_kp=0.2,
               fa=1e-4, kca=100.0)
MF_ARGS = ("radius", "density", "impact_speed", "restitution", "contact_time", "phiF", "plastic_overlap", "kc_over_kp",
           "pull_off_force", "fa", "kca", "adhesion", "radius2", "interpolation", "limit")
ADVERSE = [0, 0.0, -1.0, float("nan"), float("inf"), -float("inf"), 1e300, 1e-300, 1e155, 5e-324, 1.7e308, True, False,
           None,
           "abc", "0.5", [1.0], 3 + 0j, np.float64(float("nan")), np.bool_(True)]


def material_input():
    kw = dict(MF_BASE)
    for name in rng.sample(MF_ARGS, rng.randint(0, 3)):
        if rng.random() < 0.55:
            kw[name] = rng.choice(ADVERSE + (["none", "jumpin", "reversible"] if name == "adhesion" else []))
        elif name == "restitution":
            kw[name] = rng.uniform(0.02, 0.98)
        elif name == "adhesion":
            kw[name] = rng.choice(["none", "reversible", "jumpIn"])
        elif name == "interpolation":
            kw[name] = rng.choice(["linear", "sqrt"])
        elif name == "limit":
            kw[name] = rng.choice([None, True, False])
        elif name == "radius2":
            kw[name] = rng.choice([float("inf"), 1e-3 * rng.uniform(0.3, 3)])
        elif name == "plastic_overlap":
            kw[name] = 1e-4 * 10 ** rng.uniform(-1, 0.9)
            if rng.random() < 0.7:
                kw.pop("phiF", None)
        elif name == "pull_off_force":
            kw[name] = 10 ** rng.uniform(-6, -2)
        elif name == "phiF":
            kw[name] = rng.uniform(0.01, 1)
        else:
            kw[name] = (MF_BASE.get(name, 1e-3) * 10 ** rng.uniform(-2, 2) if MF_BASE.get(name, 1e-3)
                        else rng.uniform(0, 1))
    if kw.get("adhesion") == "none" and rng.random() < 0.7:
        kw["fa"] = 0.0
    return kw


def usable_material(m):
    """A helper's material: every number finite, and MesoMat takes it (None), or what is wrong."""
    bad = {k: v for k, v in m.items() if isinstance(v, float) and not math.isfinite(v)}
    if bad:
        return f"non-finite {bad}"
    try:
        w.MesoMat(**m)
    except Exception as e:  # noqa: BLE001
        return f"MesoMat refuses the result: {type(e).__name__}: {e}"
    return None


slowest = {}
with quiet_fd2():
    import warnings
    warnings.simplefilter("ignore")  # the helpers' warnings (e.g. an estimated sigma) are not outcomes
    # 25. calibrate.fit_cycles on valid, degenerate and adversarial data.
    for _ in range(args.n):
        how, d, F, a12, kw = cycles_input()
        desc = f"{how}, a12={a12!r}, {kw!r}"[:300]
        f = timed_call("fit_cycles", CYCLE_ARGS, desc, lambda: calibrate.fit_cycles(d, F, a12, **kw))
        if f is None:
            continue
        p = f.params
        ok = (all(isinstance(p[k], float) and math.isfinite(p[k]) for k in p) and p["k1"] > 0 and p["kp"] >= p["k1"]
              and p["kc"] >= 0
              and 0 < p["phiF"] <= 1 and math.isfinite(f.rms_residual))
        count("fit_cycles", "accepted and ran clean" if ok else "other", f"{desc}: params {p}, rms {f.rms_residual}")
    # 26. params.material_from with each argument made adversarial (empty, equal, negative, bools, extreme).
    for _ in range(args.n):
        kw = material_input()
        m = timed_call("material_from", MF_ARGS, repr(kw), lambda: params.material_from(**kw))
        if m is None:
            continue
        problem = usable_material(m)
        count("material_from", "other" if problem else "accepted and ran clean", f"{kw!r}: {problem}")
    # 27. params.scale_material: materials (dicts, MesoMat objects, broken) and factors.
    if hasattr(params, "scale_material"):
        for _ in range(args.n // 2):
            base = dict(MATERIALS[rng.choice(sorted(MATERIALS))])
            how = rng.choice(["dict", "dict", "MesoMat", "unknown key", "nan value", "string value", "not a material"])
            mat = {"dict": base, "MesoMat": w.MesoMat(**base), "unknown key": dict(base, nonexistent=1.0),
                   "nan value": dict(base, k1=float("nan")), "string value": dict(base, kp="abc"),
                   "not a material": rng.choice(["abc", None, [1.0], 5.0])}[how]
            factors = [10 ** rng.uniform(-3, 3) if rng.random() < 0.7 else rng.choice(ADVERSE) for _ in range(2)]
            try:
                out = (params.scale_material(mat, factors[0], factors[1]) if rng.random() < 0.7
                       else params.scale_material(mat, factors[0]))
            except (ValueError, TypeError) as e:
                count("scale_material",
                      "rejected clearly" if named(e, ("material", "radius_factor", "density_factor")) else "other",
                      f"{how} {factors!r}: {type(e).__name__}: {e}")
                continue
            except Exception as e:  # noqa: BLE001
                count("scale_material", "other", f"{how} {factors!r}: {type(e).__name__}: {e}")
                continue
            problem = usable_material(out)
            count("scale_material", "other" if problem else "accepted and ran clean", f"{how} {factors!r}: {problem}")


total = {k: sum(v[k] for v in tally.values()) for k in OUTCOMES}
uncovered = [c for c in PLUGIN_CLASSES if c not in by_class]
summary = {"command": "yade -j1 -n -x scripts/fuzz_inputs.py " + " ".join(sys.argv[1:]), "seed": args.seed,
           "inputs": sum(total.values()), "total": total, "seconds": round(time.time() - T0, 1),
           "plugin_classes": PLUGIN_CLASSES, "plugin_classes_without_input": uncovered,
           "by_category": tally, "by_class": dict(sorted(by_class.items())),
           "seconds_by_category": {k: round(v, 1) for k, v in seconds.items()},
           "slowest_call_s": {k: round(v, 2) for k, v in slowest.items()}, "others": others[:1000]}
print(json.dumps(summary, indent=1))
if args.out:
    outputs.write_atomic(args.out, json.dumps(summary, indent=1))
sys.exit(1 if total["other"] else 0)
