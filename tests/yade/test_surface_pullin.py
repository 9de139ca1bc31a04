# ctest (inside yade): the pull-in at a fixed sphere, a box, a facet and a wall: after
# `set_detection` the interaction starts within one step (V0 dt) of the range's edge and the energy
# of the pull-in (kinetic plus adhesive potential) stays within 1e-4 of the work fa·range/2; YADE's
# facet and wall functors alone miss it and the Ip2 warns once naming the functor to use; no warning
# for pairs that overlapped before the first step; in overlap the facet and wall geometry equals
# YADE's.
#
# The pull-in of reversible adhesion reaches every surface. A sphere drifts
# toward a fixed sphere, a box, a facet and a wall across the adhesion range. After
# scene.set_detection() each interaction starts within one step of the range's edge and the
# sphere's energy follows the closed form of the pull-in (kinetic + adhesive potential constant);
# with YADE's facet and wall functors alone the pull-in is missed and the Ip2 warns, naming the
# functor to use. No warning where nothing was missed (overlap before the first step).
import math

from yade import O, utils
from yade import wrapper as w
from mesocontact import params, scene
from harness import Stderr, check, finish

R, RHO, V0 = 1e-3, 2000.0, 1e-3
FA, KCA = 1e-5, 50.0
RANGE = FA / KCA
MAT = dict(k1=100.0, kp=500.0, kc=100.0, phiF=0.1, fa=FA, kca=KCA, adhesion="reversible", density=RHO)
M = params.sphere_mass(R, RHO)  # the partner is fixed: the moving sphere's mass is the reduced mass
W = FA * RANGE / 2              # the adhesive force's work across the range: fa - kca g from g = range to 0


def surface(kind):
    """The fixed partner with its top face at z = 0."""
    if kind == "sphere":
        return utils.sphere((0, 0, -R), R, fixed=True, material=0)
    if kind == "box":
        return utils.box((0, 0, -R), (5 * R, 5 * R, R), fixed=True, material=0)
    if kind == "facet":
        return utils.facet([(-5 * R, -5 * R, 0), (5 * R, -5 * R, 0), (0, 5 * R, 0)], fixed=True, material=0)
    return utils.wall(0, axis=2, sense=0, material=0)


def drift(kind, detect, start_gap=1.5 * RANGE):
    scene.reset()
    O.materials.append(w.MesoMat(**MAT))
    wall = O.bodies.append(surface(kind))
    ball = O.bodies.append(utils.sphere((0, 0, R + start_gap), R, material=0))
    O.bodies[ball].state.vel = (0, 0, -V0)
    O.engines = [w.ForceResetter(),
                 w.InsertionSortCollider([w.Bo1_Sphere_Aabb(), w.Bo1_Box_Aabb(), w.Bo1_Facet_Aabb(), w.Bo1_Wall_Aabb()],
                                         verletDist=0),
                 w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom(), w.Ig2_Box_Sphere_ScGeom(),
                                    w.Ig2_Facet_Sphere_ScGeom(),
                                    w.Ig2_Wall_Sphere_ScGeom()],
                                   [w.Ip2_MesoMat_MesoMat_MesoPhys()], [w.Law2_ScGeom_MesoPhys_Meso()]),
                 w.NewtonIntegrator(damping=0)]
    if detect:
        scene.set_detection()
    O.dt = 1e-6  # 200 steps across the range at V0; the adhesive spring's omega dt = 2.4e-3
    b = O.bodies[ball]
    out = {"start_gap": None, "worst": 0.0,
           "functors": [type(f).__name__ for f in O.engines[2].geomDispatcher.functors]}
    with Stderr() as err:
        gap_before = b.state.pos[2] - R
        out["v_contact"] = None
        for _ in range(int(3 * (abs(start_gap) + RANGE) / V0 / O.dt)):
            # The interaction loop sees the positions at the start of the step: the gap it acts on.
            seen = b.state.pos[2] - R
            O.step()
            gap = b.state.pos[2] - R
            if out["start_gap"] is None and O.interactions.has(wall, ball) and O.interactions[wall, ball].isReal:
                out["start_gap"] = seen
            if gap <= 0 and out["v_contact"] is None:
                out["v_contact"] = -b.state.vel[2]
            if out["v_contact"] is not None and out["start_gap"] is not None:
                break
            if 0 < gap < RANGE:
                # Leapfrog: the velocity of the half step between the two positions.
                g = 0.5 * (gap + gap_before)
                energy = 0.5 * M * b.state.vel[2] ** 2 - 0.5 * KCA * max(0.0, RANGE - g) ** 2
                out["worst"] = max(out["worst"], abs(energy - 0.5 * M * V0 ** 2) / W)
            gap_before = gap
    out["stderr"] = err.text
    return out


factor = None
for kind in ("sphere", "box", "facet", "wall"):
    r = drift(kind, True)
    # The interaction starts on the first step whose loop sees a gap inside the range (up to V0 dt below it).
    check(r["start_gap"] is not None and RANGE - 1.01 * V0 * O.dt < r["start_gap"] <= RANGE,
          f"{kind}: after set_detection the interaction starts at the range's edge",
          f"gap {r['start_gap']:.6e} m, range {RANGE:.6e} m, V0 dt {V0 * O.dt:.1e} m" if r["start_gap"] is not None
          else "never")
    # Energy: 1/2 m v^2 - kca (range - g)^2 / 2 = 1/2 m v0^2 to the leapfrog's (omega dt)^2 ~ 6e-6 of W.
    check(r["worst"] < 1e-4, f"{kind}: the pull-in follows the closed form (energy constant)",
          f"worst |dE|/W = {r['worst']:.1e}, v on touching {r['v_contact']:.6e} m/s "
          f"(closed form {math.sqrt(V0 ** 2 + 2 * W / M):.6e})")
    check("WARNING" not in r["stderr"], f"{kind}: no warning when nothing was missed", r["stderr"].strip()[:200])
    if kind in ("facet", "wall"):
        check(f"Ig2_{kind.capitalize()}_Sphere_MesoScGeom" in r["functors"],
              f"{kind}: set_detection put this package's functor in place", str(r["functors"]))
    if kind == "wall":
        # The recorded velocity is the half step after touching: off by at most what fa adds in two steps.
        v_c = math.sqrt(V0 ** 2 + FA ** 2 / (KCA * M))
        check(r["v_contact"] is not None and abs(r["v_contact"] - v_c) <= 2 * FA / M * O.dt,
              "sphere-wall pull-in reaches v_c = sqrt(v0^2 + fa^2/(kca m)) on touching",
              f"{r['v_contact']:.6e} m/s against {v_c:.6e} (bound {2 * FA / M * O.dt:.1e})")

for kind in ("facet", "wall"):
    r = drift(kind, False)
    check(r["start_gap"] is not None and r["start_gap"] <= 0,
          f"{kind}: YADE's functor alone makes the contact only in overlap",
          f"gap {r['start_gap']}")
    check(f"Ig2_{kind.capitalize()}_Sphere_MesoScGeom" in r["stderr"] and "missed" in r["stderr"],
          f"{kind}: the Ip2 warns once, naming the functor to use", r["stderr"].strip()[:300])
    check(r["stderr"].count("WARNING") == 1, f"{kind}: one warning", str(r["stderr"].count("WARNING")))

r = drift("wall", False, start_gap=-0.2 * RANGE)  # in overlap before the first step: nothing missed
check("WARNING" not in r["stderr"], "no warning for a pair that overlapped before the first step",
      r["stderr"].strip()[:200])

# In contact the facet and wall geometry equals YADE's (shrinkFactor 0).
for kind, yade_f, meso_f in (("facet", w.Ig2_Facet_Sphere_ScGeom, w.Ig2_Facet_Sphere_MesoScGeom),
                             ("wall", w.Ig2_Wall_Sphere_ScGeom, w.Ig2_Wall_Sphere_MesoScGeom)):
    geoms = []
    for f in (yade_f, meso_f):
        scene.reset()
        O.materials.append(w.MesoMat(k1=100.0, kp=500.0, density=RHO))
        O.bodies.append(surface(kind))
        O.bodies.append(utils.sphere((0.3 * R, -0.2 * R, 0.9 * R), R, material=0))
        O.engines = [w.ForceResetter(),
                     w.InsertionSortCollider([w.Bo1_Sphere_Aabb(), w.Bo1_Facet_Aabb(), w.Bo1_Wall_Aabb()]),
                     w.InteractionLoop([f()], [w.Ip2_MesoMat_MesoMat_MesoPhys()], [w.Law2_ScGeom_MesoPhys_Meso()]),
                     w.NewtonIntegrator(damping=0)]
        O.dt = 1e-7
        O.step()
        g = O.interactions[0, 1].geom
        geoms.append((g.penetrationDepth, tuple(g.normal), tuple(g.contactPoint)))
    # To rounding: positions carry ~1e-19 m of it, the normal ~1e-15 (a difference of positions over R).
    dn = max(abs(a - b) for a, b in zip(geoms[0][1], geoms[1][1]))
    dp = max(abs(a - b) for a, b in zip(geoms[0][2], geoms[1][2]))
    check(abs(geoms[0][0] - geoms[1][0]) < 1e-15 * R and dn < 1e-12 and dp < 1e-12 * R,
          f"{kind}: in overlap the geometry equals YADE's",
          f"overlap {geoms[0][0]:.6e} / {geoms[1][0]:.6e}, |dn| {dn:.1e}, |dC| {dp:.1e} m")

scene.reset()
O.materials.append(w.MesoMat(**MAT))
O.bodies.append([utils.sphere((0, 0, 0), R, material=0)])
O.engines = [w.InsertionSortCollider([w.Bo1_Sphere_Aabb()]),
             w.InteractionLoop([w.Ig2_Facet_Sphere_ScGeom(shrinkFactor=0.1)], [], [])]
try:
    scene.set_detection()
    check(False, "a shrinkFactor the replacement lacks is refused")
except ValueError as e:
    check("shrinkFactor" in str(e), "a shrinkFactor the replacement lacks is refused, naming it", str(e))
finish()
