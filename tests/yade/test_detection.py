# ctest (inside yade): mesocontact.scene.set_detection makes a hand-built scene see reversible
# adhesion before contact. Two spheres approach across the pull-in range with YADE's default
# detection: no force acts until they touch (the Ip2 warns) and e misses the closed form; after
# set_detection the same scene meets it (|de| <= 1e-3, the pair driver's own tolerance).
# Issue #57 items 1 and 7: a refused margin (inf set every factor to inf) or scene (a Wall.axis
# outside 0..2, on which YADE's Bo1_Wall_Aabb aborts the process; a sphere radius of 0; a
# material's non-finite young or poisson) is named and changes nothing; time_step and
# scene.check refuse the same scenes.
import math
from yade import O, utils
from yade import wrapper as w
from mesocontact import params, scene, theory
from harness import check, finish

R, RHO, V = 1e-3, 2000.0, 0.004
MAT = dict(k1=100.0, kp=500.0, kc=100.0, phiF=0.1, fa=1e-5, kca=50.0, adhesion="reversible", density=RHO)
m_r = params.sphere_mass(R, RHO) / 2
e_theory = theory.pair_collision(V, 100.0, 500.0, 100.0, 0.1, R, m_r, fa=1e-5, kca=50.0, adhesion="reversible").e


def collide(detect):
    scene.reset()
    O.materials.append(w.MesoMat(**MAT))
    gap = 1.5 * MAT["fa"] / MAT["kca"]  # outside the range of the non-contact force
    b1, b2 = utils.sphere((0, 0, 0), R, material=0), utils.sphere((2 * R + gap, 0, 0), R, material=0)
    O.bodies.append([b1, b2])
    b1.state.vel, b2.state.vel = (V / 2, 0, 0), (-V / 2, 0, 0)
    O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb()], verletDist=0),
                 w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom()], [w.Ip2_MesoMat_MesoMat_MesoPhys()],
                                   [w.Law2_ScGeom_MesoPhys_Meso()]),
                 w.NewtonIntegrator(damping=0)]
    factor = scene.set_detection() if detect else 1.0
    O.dt = params.contact_time(500.0, m_r) / 2000
    O.run(int(3 * params.contact_time(100.0, m_r) / O.dt + gap / V / O.dt), True)
    return (b2.state.vel - b1.state.vel)[0] / V, factor


e_default, _ = collide(False)
e_set, factor = collide(True)
RANGE = MAT["fa"] / MAT["kca"]
check(abs(scene.adhesion_range() - RANGE) < 1e-12 * RANGE, "adhesion_range = fa/kca of the scene's material",
      f"{scene.adhesion_range():.3e}")
check(abs(factor - (1 + 1.2 * RANGE / R)) < 1e-12, "set_detection: factor 1 + 1.2 range/a_min", f"{factor}")
check(abs(e_default - e_theory) > 1e-3, "default detection misses the pull-in (e off the closed form)",
      f"e = {e_default:.6f}, theory {e_theory:.6f}")
check(abs(e_set - e_theory) <= 1e-3, "after set_detection e meets the closed form",
      f"e = {e_set:.6f}, theory {e_theory:.6f}")
scene.reset()
O.materials.append(w.MesoMat(k1=100.0, kp=500.0, density=RHO))
O.bodies.append(utils.sphere((0, 0, 0), R, material=0))
O.engines = [w.InsertionSortCollider([w.Bo1_Sphere_Aabb()])]
check(scene.set_detection() == 1.0 and O.engines[0].boundDispatcher.functors[0].aabbEnlargeFactor <= 1.0,
      "no adhesion: engines left alone")
try:
    scene.set_detection(margin=0.5)
    check(False, "margin < 1 refused")
except ValueError as e:
    check("margin" in str(e), "margin < 1 refused, naming it", str(e))


def wall_scene():
    """An adhesive sphere over a wall, with YADE's wall functor (set_detection replaces it)."""
    scene.reset()
    O.materials.append(w.MesoMat(**MAT))
    O.bodies.append([utils.sphere((0, 0, 0), R, material=0), utils.wall(-2 * R, axis=2, material=0)])
    O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb(), w.Bo1_Wall_Aabb()]),
                 w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom(), w.Ig2_Wall_Sphere_ScGeom()],
                                   [w.Ip2_MesoMat_MesoMat_MesoPhys()],
                                   [w.Law2_ScGeom_MesoPhys_Meso()]),
                 w.NewtonIntegrator(damping=0)]


def detection_state():
    """What set_detection changes: the sphere bound's factor, the geometry functors and theirs."""
    return ([f.aabbEnlargeFactor for f in O.engines[1].boundDispatcher.functors if isinstance(f, w.Bo1_Sphere_Aabb)],
            [(type(f).__name__, getattr(f, "interactionDetectionFactor", None))
             for f in O.engines[2].geomDispatcher.functors])


def refused(what, call, error, words, scene_before=None):
    """call() raises error with every one of words in its message, and the detection is as before."""
    before = detection_state() if scene_before is None else scene_before
    try:
        got = call()
        check(False, f"{what} refused", f"accepted: {got!r}, {detection_state()}")
    except error as e:
        check(all(x in str(e) for x in words) and detection_state() == before,
              f"{what}: {error.__name__} naming {', '.join(words)}, "
              "nothing changed",
              str(e) if detection_state() == before else f"{detection_state()} after, {before} before")
    except Exception as e:  # noqa: BLE001 - the wrong kind of error is the finding
        check(False, f"{what}: {error.__name__} naming {', '.join(words)}", f"{type(e).__name__}: {e}")


wall_scene()
for margin in (math.inf, -math.inf, math.nan, -1.0, 0.5, "1.5", True, None):
    refused(f"set_detection(margin={margin!r})", lambda: scene.set_detection(margin=margin), ValueError, ["margin = "])
O.bodies[0].shape.radius = 1e-9  # range/a_min = 200: a finite margin whose factor overflows
refused("set_detection(margin=1e307) with a factor beyond floating point", lambda: scene.set_detection(margin=1e307),
        ValueError,
        ["margin = 1e+307"])
for radius in (0.0, -R, math.nan, math.inf):
    O.bodies[0].shape.radius = radius  # min(radii) = 0 divided by zero; NaN set NaN factors
    refused(f"set_detection with a sphere radius {radius!r}", lambda: scene.set_detection(), ValueError,
            ["body #0", "radius"])
O.bodies[0].shape.radius = R
O.bodies[1].shape.axis = 3  # YADE takes it; its Bo1_Wall_Aabb aborts the process at the first step
for what, call in (("set_detection", lambda: scene.set_detection()), ("time_step", lambda: scene.time_step()),
                   ("check", lambda: scene.check())):
    refused(f"{what} with Wall.axis = 3", call, ValueError, ["body #1", "Wall.axis = 3", "0, 1 or 2"])
O.bodies[1].shape.axis = 2
for name in ("young", "poisson"):
    wall_scene()
    frict = w.FrictMat(young=1e7, poisson=0.3, density=RHO, label="frict")
    setattr(frict, name, math.nan)
    O.bodies.append(utils.sphere((5 * R, 0, 0), R, material=frict))  # not in O.materials: seen through its body
    for what, call in (("set_detection", lambda: scene.set_detection()), ("time_step", lambda: scene.time_step()),
                       ("check", lambda: scene.check())):
        refused(f"{what} with a FrictMat's {name} = nan", call, ValueError, ["FrictMat frict", f"{name} = nan"])
    wall_scene()
    try:  # the plugin refuses it itself; where it takes it, the scene checks must
        O.materials[0].updateAttrs({name: math.inf})
        refused(f"check with a MesoMat's {name} = inf", lambda: scene.check(), ValueError, ["MesoMat", f"{name} = inf"])
    except ValueError as e:
        check(name in str(e), f"MesoMat refuses {name} = inf itself", str(e)[:100])
wall_scene()
before = detection_state()
factor = scene.set_detection()
check(factor > 1 and detection_state() != before and detection_state()[1][1][0] == "Ig2_Wall_Sphere_MesoScGeom",
      "the same scene, valid, is set", f"{detection_state()}")
check(0 < scene.time_step() < math.inf and scene.check() is None, "time_step and check take it")
finish()
