# ctest (inside yade): what a user could reach that crashed or passed silently (issue #49): a
# contact's own phys or geometry assigned back from Python, and another contact's phys, while
# contacts end under `O.run` (each aborted the process: released without the GIL); contacts restored
# onto a loop that makes another geometry class (refused, nothing restored); the facet and wall
# functors given a geometry of another class; slivers (two coincident or three collinear vertices)
# detected; `Wall.axis` 3; `interactionDetectionFactor` outside [1, ∞). Each item runs alone (`yade
# -n -x tests/yade/test_reliability.py item2`) to show it before a fix.
#
# What a user could reach that crashed or passed silently (issue #49).
# - a valid MesoPhys assigned from Python (a contact's own, or another contact's) while contacts end
#   under O.run: the process aborted (the Python object released without the GIL); now the own one
#   runs on unchanged and is released safely, another contact's is dropped with a warning and remade;
# - contacts restored onto pairs whose loop makes another geometry class: YADE's functor cast it to
#   the wrong type (segfault); now restore() refuses, naming the pair and both classes, and restores
#   nothing; likewise contacts whose parameters the bodies' materials no longer give (item9); the facet
#   and wall functors replace a geometry of another class instead of casting it;
# - Wall.axis outside 0-2 read pos[3]: the wall functor makes no contact and says so, set_detection
#   refuses it;
# - interactionDetectionFactor of the surface functors below 1 or not finite: spheres passed through;
# - facets with two coincident vertices (slivers) were never detected;
# - loop.runner took labels that replace O or sphere, and periods that never run or fail unnamed;
# - a loop callback that raised left a half-applied step, which resuming ran twice (item10).
import math
import sys

from yade import O, utils
from yade import wrapper as w
from mesocontact import scene
from harness import Stderr, check, finish

A, RHO = 1e-3, 2000.0


def pair(n_targets=1, v=0.05, six=False, tangential=False, ig2=None):
    """A sphere at the origin moving along +x into n_targets resting spheres (1: at +x; 2: also
    one at -x moving along -x), apart at the start; returns the law."""
    O.reset()
    kw = dict(kt=50, frictionAngle=0.3) if tangential else {}
    m = O.materials.append(w.MesoMat(k1=100, kp=500, kc=100, phiF=0.1, density=RHO, **kw))
    O.bodies.append(utils.sphere((0, 0, 0), A, material=m))
    O.bodies.append(utils.sphere((2 * A + 2e-6, 0, 0), A, material=m))
    if n_targets == 2:
        O.bodies.append(utils.sphere((-2 * A - 4e-6, 0, 0), A, material=m))  # touches later
        O.bodies[2].state.vel = (v, 0, 0)
    O.bodies[1].state.vel = (-v, 0, 0)
    law = w.Law2_ScGeom_MesoPhys_Meso()
    ig2 = ig2 or (w.Ig2_Sphere_Sphere_ScGeom6D() if six else w.Ig2_Sphere_Sphere_ScGeom())
    O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb()]),
                 w.InteractionLoop([ig2], [w.Ip2_MesoMat_MesoMat_MesoPhys()], [law]), w.NewtonIntegrator(damping=0)]
    O.dt = 1e-6
    return law


def until_touch(*ids):
    for _ in range(10000):
        O.step()
        if all(O.interactions.has(0, i) and O.interactions[0, i].isReal for i in ids):
            return
    raise AssertionError("no contact")


def outcome():
    return [tuple(O.bodies[i].state.vel) + tuple(O.bodies[i].state.pos) for i in range(len(O.bodies))]


# 1. The contact's own phys assigned back from Python (i.phys = i.phys), then the contact ends under
#    O.run: the same collision as without the assignment, to the bit, and the process lives on.
def item1():
    for tangential in (False, True):
        pair(six=tangential, tangential=tangential)
        until_touch(1)
        O.run(3000, True)
        reference = outcome()
        pair(six=tangential, tangential=tangential)
        until_touch(1)
        i = O.interactions[0, 1]
        i.phys = i.phys
        with Stderr() as err:
            O.run(3000, True)
        check(not O.interactions.has(0, 1) or not O.interactions[0, 1].isReal,
              "own phys re-assigned: the contact ended under O.run")
        check(outcome() == reference and "WARNING" not in err.text,
              f"own phys re-assigned ({'tangential' if tangential else 'plain'}): the collision bitwise as "
              f"without, no warning")


# 2. Another contact's phys assigned to a contact: one history for two contacts. It is dropped and
#    remade from the materials (warned once); each contact keeps its own history; both end under O.run.
def item2():
    pair(n_targets=2)
    until_touch(1, 2)
    O.run(5, True)
    O.interactions[0, 2].phys = O.interactions[0, 1].phys
    with Stderr() as err:
        O.step()
        O.step()
    p1, p2 = O.interactions[0, 1].phys, O.interactions[0, 2].phys
    check("of another contact" in err.text and err.text.count("WARNING") == 1, "another contact's phys: warned once",
          err.text.strip()[:120])
    check(p1 is not p2 and p1.deltaMax > 0 and p2.deltaMax > 0 and p2.deltaMax < p1.deltaMax,
          "another contact's phys: remade, each contact its own history",
          f"deltaMax {p1.deltaMax:.3e} {p2.deltaMax:.3e}")
    O.run(3000, True)
    check(not any(O.interactions.has(0, k) and O.interactions[0, k].isReal for k in (1, 2)),
          "both contacts ended under O.run, process alive")


# 3. The contact store across geometry classes: contacts exported with Ig2_Sphere_Sphere_ScGeom,
#    restored where the loop makes ScGeom6D.
def item3():
    pair()
    until_touch(1)
    store = w.MesoContactStore()
    data = store.exportContacts([0, 1])
    pair(six=True)
    until_touch(1)
    store.keep()
    O.interactions.clear()
    O.engines[1]()  # the collider makes the candidate pair anew, without geometry
    store.importContacts(data)
    try:
        n = store.restore()
        check(False, "ScGeom restored onto a ScGeom6D loop: refused", f"restored {n}")
    except ValueError as e:
        check("ScGeom6D" in str(e) and "#0+#1" in str(e) and "nothing was restored" in str(e),
              "ScGeom restored onto a ScGeom6D loop: refused, naming the pair and both classes", str(e)[:160])
    O.run(10, True)
    i = O.interactions[0, 1]
    check(type(i.geom).__name__ == "ScGeom6D" and math.isfinite(i.phys.normalForce.norm()),
          "after the refusal the loop goes on with its own geometry")
    # the same classes still restore
    pair(six=True)
    until_touch(1)
    O.run(5, True)
    store.keep()
    O.interactions.clear()
    O.engines[1]()  # the collider makes the candidate pair anew, without geometry
    check(store.restore() == 1 and type(O.interactions[0, 1].geom).__name__ == "ScGeom6D",
          "ScGeom6D restored onto a ScGeom6D loop")
    # item 10: ids given as a dict (whose ids: keys or values?) refused; a set taken; bytes with a tail refused
    O.run(2, True)
    try:
        store.exportContacts({0: 1})
        check(False, "exportContacts({0: 1}) refused")
    except TypeError as e:
        check("ids" in str(e), "exportContacts({0: 1}) refused", str(e)[:80])
    check(store.exportContacts({0, 1}) == store.exportContacts([0, 1]), "exportContacts of a set as of a list")
    # a tail or one flipped byte of the archive (which could crash Boost's reader, issue #57): the checksum refuses them
    good = store.exportContacts([0, 1])
    flipped = bytearray(good)
    flipped[len(good) // 2] ^= 0x5A
    for name, data in (("trailing bytes", good + b"tail"), ("a flipped byte", bytes(flipped))):
        try:
            store.importContacts(data)
            check(False, f"importContacts with {name} refused")
        except ValueError as e:
            check("checksum" in str(e), f"importContacts with {name} refused", str(e)[:80])


# 4. The surface functors given a geometry of another class (assigned from Python, or restored): a
#    new geometry of their own class, the old one released safely; a sphere pair's own geometry
#    assigned back from Python is released safely when the contact ends.
def on_facet(ig2, vertices=((-2e-3, -2e-3, 0), (2e-3, -2e-3, 0), (0, 3e-3, 0)), z=0.9e-3):
    O.reset()
    m = O.materials.append(w.MesoMat(k1=100, kp=500, kc=100, phiF=0.1, density=RHO, kt=50, frictionAngle=0.3))
    O.bodies.append(utils.facet(vertices, material=m))
    O.bodies.append(utils.sphere((0, 0, z), A, material=m))
    O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb(), w.Bo1_Facet_Aabb()]),
                 w.InteractionLoop([ig2], [w.Ip2_MesoMat_MesoMat_MesoPhys()], [w.Law2_ScGeom_MesoPhys_Meso()]),
                 w.NewtonIntegrator(damping=0, gravity=(0, 0, -9.81))]
    O.dt = 1e-6


def item4():
    for cls, made in (("Ig2_Facet_Sphere_MesoScGeom6D", "ScGeom6D"), ("Ig2_Facet_Sphere_MesoScGeom", "ScGeom")):
        on_facet(getattr(w, cls)())
        O.step()
        O.interactions[0, 1].geom = w.IGeom()  # from Python: released in YADE's thread it aborted the process
        O.run(5, True)
        i = O.interactions[0, 1]
        check(type(i.geom).__name__ == made and abs(i.geom.penetrationDepth - 0.1e-3) < 1e-6,
              f"{cls} given an IGeom: a new {made}",
              f"{type(i.geom).__name__} overlap {i.geom.penetrationDepth:.3e}")
    # a sphere's own geometry assigned back from Python, then the contact ends under O.run
    pair()
    until_touch(1)
    O.interactions[0, 1].geom = O.interactions[0, 1].geom
    O.run(3000, True)
    check(not O.interactions[0, 1].isReal if O.interactions.has(0, 1) else True,
          "own geometry re-assigned: the contact ended under O.run")


# 5. Slivers: a facet with two coincident vertices (a segment) and one with three collinear ones.
def item5():
    for label, vertices in (("two coincident vertices", ((-2e-3, 0, 0), (-2e-3, 0, 0), (2e-3, 0, 0))),
                            ("collinear vertices", ((-2e-3, 0, 0), (0, 0, 0), (2e-3, 0, 0)))):
        on_facet(w.Ig2_Facet_Sphere_MesoScGeom(), vertices)
        O.step()
        real = O.interactions.has(0, 1) and O.interactions[0, 1].isReal
        check(real and abs(O.interactions[0, 1].geom.penetrationDepth - 0.1e-3) < 1e-9,
              f"facet with {label}: detected with its overlap",
              f"real {real}")
    # A vertex that is not finite: no collider finds the facet (its box is NaN); set_detection says so.
    on_facet(w.Ig2_Facet_Sphere_MesoScGeom(), ((-2e-3, -2e-3, 0), (2e-3, -2e-3, 0), (0, float("nan"), 0)))
    try:
        scene.set_detection()
        check(False, "a facet with a NaN vertex: set_detection refuses it")
    except ValueError as e:
        check("#0" in str(e) and "not finite" in str(e),
              "a facet with a NaN vertex: set_detection refuses it, naming the body", str(e))


# 6. Wall.axis outside 0-2: no contact, a warning naming the value; set_detection refuses it.
def item6():
    O.reset()
    m = O.materials.append(w.MesoMat(k1=100, kp=500, kc=100, phiF=0.1, density=RHO, fa=1e-5, kca=100,
                                     adhesion="reversible"))
    O.bodies.append(utils.wall(0, axis=2, material=m))
    O.bodies.append(utils.sphere((0, 0, 0.9e-3), A, material=m))
    O.bodies[0].shape.axis = 3
    O.engines = [w.ForceResetter(),
                 w.InteractionLoop([w.Ig2_Wall_Sphere_MesoScGeom()], [w.Ip2_MesoMat_MesoMat_MesoPhys()],
                                   [w.Law2_ScGeom_MesoPhys_Meso()]), w.NewtonIntegrator(damping=0)]
    O.dt = 1e-6
    with Stderr() as err:
        try:
            utils.createInteraction(0, 1)
            made = O.interactions.has(0, 1) and O.interactions[0, 1].isReal
        except Exception:
            made = False
    check(not made and "Wall.axis = 3 is invalid" in err.text, "Wall.axis 3: no contact, warned",
          err.text.strip()[:120])
    O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb(), w.Bo1_Wall_Aabb()]), O.engines[1],
                 O.engines[2]]
    try:
        scene.set_detection()
        check(False, "set_detection refuses Wall.axis 3")
    except ValueError as e:
        check("Wall.axis = 3" in str(e) and "#0" in str(e), "set_detection refuses Wall.axis 3", str(e))


# 7. interactionDetectionFactor of the three functors: refused outside [1, inf), by name, value kept.
def item7():
    for cls in ("Ig2_Facet_Sphere_MesoScGeom", "Ig2_Facet_Sphere_MesoScGeom6D", "Ig2_Wall_Sphere_MesoScGeom"):
        f = getattr(w, cls)()
        f.interactionDetectionFactor = 1.25
        refused = []
        for bad in (0, -1, float("nan"), -math.inf, math.inf, 1e-300, 0.999):
            try:
                f.interactionDetectionFactor = bad
            except ValueError as e:
                if "interactionDetectionFactor" in str(e) and f.interactionDetectionFactor == 1.25:
                    refused.append(bad)
            try:
                getattr(w, cls)(interactionDetectionFactor=bad)
            except ValueError as e:
                if "interactionDetectionFactor" in str(e):
                    refused.append(bad)
        f.interactionDetectionFactor = 1.0
        check(len(refused) == 14 and f.interactionDetectionFactor == 1.0,
              f"{cls}.interactionDetectionFactor: 7 bad values refused on "
              "assignment and in the constructor, the old value kept; 1 accepted", f"refused {len(refused)} of 14")
        named = []  # wrong types name the attribute (Boost said "None.None(..., complex) did not match C++ signature")
        for bad in (None, 3 + 0j, "1.2", [1.2]):
            try:
                f.interactionDetectionFactor = bad
            except TypeError as e:
                if "interactionDetectionFactor" in str(e) and f.interactionDetectionFactor == 1.0:
                    named.append(bad)
        check(len(named) == 4, f"{cls}.interactionDetectionFactor: a wrong type is named", f"{len(named)} of 4")


# 8. loop.runner: a label that already names something (O, sphere, a builtin) is refused, since YADE
#    makes labels global names; the period is an integer number of steps >= 1.
def item8():
    import builtins
    import __main__
    from mesocontact import loop
    before = [getattr(builtins, "O"), getattr(__main__, "sphere"), builtins.__import__, builtins.len]
    for label in ("O", "sphere", "__import__", "len"):
        try:  # YADE binds an engine's label as a global name when the engine joins O.engines
            O.engines = O.engines + [loop.runner(lambda: None, 1, label)]
            check(False, f"loop.runner label {label!r} refused")
        except ValueError as e:
            check("already names" in str(e), f"loop.runner label {label!r} refused", str(e)[:100])
    after = [getattr(builtins, "O"), getattr(__main__, "sphere"), builtins.__import__, builtins.len]
    check(all(a is b for a, b in zip(before, after)), "O, sphere, __import__ and len still the objects they were")
    for period in (0, -1, 1.5, float("nan"), "2", 10 ** 30, True):
        try:
            loop.runner(lambda: None, period, "probeRunner")
            check(False, f"loop.runner period {period!r} refused")
        except ValueError as e:
            check("period" in str(e), f"loop.runner period {period!r} refused, naming the period")
    calls = []
    O.reset()
    O.engines = [loop.runner(lambda: calls.append(O.iter), 2, "probeRunner")]
    O.engines = [loop.runner(lambda: calls.append(-O.iter), 2, "probeRunner")]  # one of ours, installed again
    O.run(4, True)  # steps 0-3: the runner acts at step 2, calling what was registered last
    check(calls == [-2], "a runner installed again under its label calls its new callable", str(calls))


# 9. (the item 6) Contacts restored onto pairs whose materials give them other parameters:
#    a plain contact (no sliding) where the materials have kt, or one of another kc, ran on with the
#    other scene's law; now restore() refuses, naming the pair and the first parameter that
#    differs, and restores nothing; the same materials restore.
def item9():
    pair()
    until_touch(1)
    store = w.MesoContactStore()
    data = store.exportContacts([0, 1])
    for change, says in ((dict(tangential=True), "kt"), (dict(), "kc")):
        pair(**change)
        if says == "kc":
            O.materials[0].kc = 200
        until_touch(1)
        store.keep()
        O.interactions.clear()
        O.engines[1]()
        store.importContacts(data)
        try:
            n = store.restore()
            check(False, f"a contact restored where the materials give another {says}: refused", f"restored {n}")
        except ValueError as e:
            check(f"another {says} " in str(e) and "#0+#1" in str(e) and "nothing was restored" in str(e),
                  f"a contact restored where the materials give another {says}: refused, naming it", str(e)[:120])
    pair()
    until_touch(1)
    store.keep()
    O.interactions.clear()
    O.engines[1]()
    store.importContacts(data)
    check(store.restore() == 1 and O.interactions[0, 1].phys.kc == 100, "the same materials restore")


# 10. (the item 7) A loop callback that raises: YADE stopped at the failing engine, so the
#    step was half applied (O.iter not advanced) and resuming ran its first engines again (x off
#    by one step). Now the step is completed, the run stops before the next step with an error
#    naming the runner, and resuming after a fix gives the run without the failure, to the bit.
def item10():
    from mesocontact import loop
    seen = []

    def run(fail_at):
        pair(six=True, tangential=True)
        seen.clear()

        def callback():
            if O.iter == fail_at:
                raise ValueError("probe failure")
            seen.append(O.iter)
        O.engines = O.engines + [loop.runner(callback, 1, "probeFailing")]
        until_touch(1)  # the runner after Newton; the contact's springs load every step
        start = O.iter
        try:
            with Stderr() as err:
                O.run(40, True)
            error = None
        except RuntimeError as e:
            error = str(e)
        return start, error, err.text

    start, error, _ = run(None)
    reference = outcome() + [(O.iter,)]
    fail = start + 10
    _, error, text = run(fail)
    check(error is not None and "'probeFailing' raised at iteration %d" % fail in error and "probe failure" in error,
          "a raising callback stops the run with an error naming the runner, the iteration and the error",
          str(error)[:160])
    check(O.iter == fail + 1, "the failing step was completed (O.iter advanced past it)",
          f"O.iter {O.iter}, failed at {fail}")
    check("probe failure" in text, "the error is printed when it happens", text[:120])
    loop.register("probeFailing", lambda: seen.append(O.iter))  # the fix
    O.run(start + 40 - O.iter, True)
    check(outcome() + [(O.iter,)] == reference,
          "resuming after the fix repeats no step: the run without the failure, to the bit")
    check([e for e in O.engines if isinstance(e, w.PyRunner) and "raise_pending" in e.command] == [],
          "the engine that raised the error is gone")


# All items, or those named on the command line (item1 ... item7), e.g. to show one before a fix:
#   yade -n -x tests/yade/test_reliability.py item2
ITEMS = {f.__name__: f for f in (item1, item2, item3, item4, item5, item6, item7, item8, item9, item10)}
for name in [a for a in sys.argv[1:] if a in ITEMS] or list(ITEMS):
    ITEMS[name]()
finish()
