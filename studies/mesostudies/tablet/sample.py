"""The agglomerate "tablet" of Luding 2008 / Appendix F of the long paper (run inside ``yade``).

Units are the paper's: 1 mm, 1 us, 1 mg (stiffness 1 = 1e6 N/m, stress 1 = 1e9 Pa). Primary
particles of mean diameter d0 = 0.01, with the full law (adhesion, friction, rolling, torsion)
from the start, are compacted from a gas by six walls (YADE boxes, so that rolling and torsion
act on the walls' ScGeom6D too) driven by YADE's ``TriaxialStressController``, pressure-sintered
at d0 p_s/kp = 0.02, released to p_r/p_s = 1e-3, and saved:

    from mesostudies.tablet import sample
    info = sample.prepare("released.yade.gz")    # or stages.ensure("released", DIR): reuse
    print(info["released"]["solid_fraction"])

While the tablet is compacted and sintered the walls are a smooth, non-adhesive mould
(mould_material); after sintering the two loading walls get the strongly adhesive material of
Luding's tension tests (make_adhesive_walls: kc_wall/kp = 20, mu_wall = 10), and the tests
remove the four lateral walls (uniaxial.make_unconfined).
"""
import json
import math
import os
import random
import time

try:
    from yade import O
    from yade import utils as _utils
    from yade import wrapper as _w
except ImportError as _exc:  # pragma: no cover - outside yade
    raise ImportError("mesostudies.tablet.sample needs YADE: run it inside `yade`") from _exc

from mesocontact import outputs as _outputs
from mesocontact import params as _params
from mesocontact import scene as _scene

D0 = 0.01          # mean primary-particle diameter [mm]
DENSITY = 2.0      # 2000 kg/m^3 in mg/mm^3
KP = 5.0           # limit stiffness [mg/us^2 = 1e6 N/m]
GAMMA0 = 5e-5      # normal viscous damping [mg/us = kg/s]
SINTER = 0.02                    # d0 p_s/kp, the paper's sintering stress
SINTER_STRESS = SINTER * KP / D0
RELEASE_RATIO = 1e-3             # p_r/p_s
COMPACTION_SPEED = 2.0           # largest wall speed while compacting the gas [mm/us], ~c/10
SINTER_SPEED = 0.05              # largest wall speed while sintering and releasing [mm/us]
RELEASE_STEPS = 40000            # steps over which the wall stress is lowered from p_s to p_r
WALLS = ("left", "right", "bottom", "top", "back", "front")  # YADE's aabbWalls order: -x +x -y +y -z +z
# The preparation's options (the factor study of the tested sample, campaigns/tablet/factors.md):
PACKINGS = ("full", "frictionless")  # the law while the gas is compacted: the full law, or without friction,
#                                      rolling, torsion and adhesion (the full law switched on for sintering)
PACKING_RATIO = 0.1                  # the frictionless packing's stress, over p_s
GLUES = ("loading", "all", "sinter")  # the walls made adhesive: the two x walls after sintering, all six after
#                                      sintering, or all six from the start of sintering (the first protocol's)


# Particle parameter sets (MesoMat keywords, the paper's units): Table 2 of Luding 2008 and the
# long paper's Appendix F, which changes kc, the rolling and torsion limits and their dashpots.
MATERIALS = {
    "table2": dict(density=DENSITY, k1=0.5 * KP, kp=KP, kc=0.5 * KP, phiF=0.05, gammaN=GAMMA0,
                   frictionAngle=math.atan(1.0), kt=0.2 * KP, gammaT=0.2 * GAMMA0,
                   kr=0.1 * KP, gammaR=0.05 * GAMMA0, muR=0.1, ko=0.1 * KP, gammaO=0.05 * GAMMA0, muO=0.1),
}
MATERIALS["appendixF"] = dict(MATERIALS["table2"], kc=0.2 * KP, gammaR=0.1 * GAMMA0, muR=0.2,
                              gammaO=0.1 * GAMMA0, muO=0.2)


def particle_material(material="appendixF", **changes):
    """The particles' MesoMat keywords of parameter set ``material`` ('appendixF': Table 2 of
    Luding 2008 with kc/kp = 0.2, mu_r = mu_o = 0.2, gamma_r/gamma0 = gamma_o/gamma0 = 0.1;
    'table2': Luding's reference set); ``changes`` override."""
    if material not in MATERIALS:
        raise ValueError(f"material = {material!r} is invalid: one of {sorted(MATERIALS)}")
    kw = dict(MATERIALS[material], label="particles")
    kw.update(changes)
    return kw


def mould_material(material="appendixF"):
    """The walls while the tablet is made: the particles' normal law without adhesion, friction,
    rolling or torsion resistance (a smooth, non-adhesive mould), imposed unmixed. Frictional
    walls lock the box: spheres wedged at its edges and corners carry the wall stress by
    friction against the neighbouring wall (at N = 216 the stress target was met at solid
    fraction 0.40, coordination 1.2). After sintering the loading walls are made adhesive."""
    return particle_material(material, kc=0.0, frictionAngle=0.0, muR=0.0, muO=0.0, label="walls", dominant=True)


def background_damping(reference="lab"):
    """Luding's viscous background damping, gamma_b/gamma0 = 4, gamma_br/gamma0 = 1, relative to
    the lab frame (preparation) or to the rigid motion of each particle's contacts (the tests)."""
    return _w.MesoBackgroundDamping(gammaB=4 * GAMMA0, gammaBR=GAMMA0, reference=reference, label="background")


def contact_step(r_min):
    """The tablet campaign's base step: t_c/50 of the stiffest, lightest pair (all springs of the
    law resolved), a fraction of a contact's duration. Not the package's time-step rule, which is
    scene.time_step (a fraction of the stability bound each contact is checked against; this
    step is 0.032 of that bound on the unconfined tablet, campaigns/tablet/timestep.md); the
    campaign keeps this one so that its committed runs stay reproducible, and scales it per test
    (campaign.DT_FACTORS, from the convergence study of campaigns/tablet/timestep.md)."""
    m = particle_material()
    m_min = _params.sphere_mass(r_min, DENSITY)
    return _params.resolved_step(m["kp"], m_min, kt=m["kt"], kr=m["kr"], ko=m["ko"], gamma=m["gammaN"])


def engines(controller=None, extra=(), reference="lab"):
    """The engine loop of every tablet run: spheres and boxes, meso law, background damping."""
    loop = [
        _w.ForceResetter(),
        _w.InsertionSortCollider([_w.Bo1_Sphere_Aabb(), _w.Bo1_Box_Aabb()], label="collider"),
        _w.InteractionLoop(
            # The law reads no relative rotation of ScGeom6D (only the bodies' spins): YADE need not compute them.
            [_w.Ig2_Sphere_Sphere_ScGeom6D(updateRotations=False), _w.Ig2_Box_Sphere_ScGeom6D()],
            [_w.Ip2_MesoMat_MesoMat_MesoPhys()],
            [_w.Law2_ScGeom_MesoPhys_Meso(label="law")]),
        background_damping(reference),
    ]
    if controller is not None:
        loop.append(controller)
    loop += list(extra)
    loop.append(_w.NewtonIntegrator(damping=0.0, label="newton"))
    return loop


def _radii(n, rel_std, rng):
    """n radii, Gaussian about d0/2 with relative standard deviation rel_std, cut at 2 sigma."""
    out = []
    while len(out) < n:
        x = rng.gauss(0.0, rel_std)
        if abs(x) <= 2 * rel_std:
            out.append(0.5 * D0 * (1.0 + x))
    return out


def build(n=1728, rel_std=0.05, solid_fraction=0.2, seed=1, material="appendixF", kc_over_kp=None, aspect=(1, 1, 1)):
    """A loose random gas of n spheres in a box of six smooth walls (ids 0-5, spheres after),
    cubic or with sides in the ratios ``aspect`` (x, y, z), particles of parameter set
    ``material`` (kc_over_kp overrides its kc/kp). The Gaussian size distribution is narrow
    (relative std rel_std, cut at 2 sigma) to avoid monodisperse crystallisation."""
    changes = {}
    if kc_over_kp is not None:
        if not (0 <= kc_over_kp < math.inf):
            raise ValueError(f"kc_over_kp = {kc_over_kp} is invalid: must be finite and >= 0")
        changes["kc"] = kc_over_kp * KP
    particles = particle_material(material, **changes)
    if int(n) != n or n < 8:
        raise ValueError(f"n = {n} is invalid: at least 8 particles")
    if not 0 <= rel_std < 0.3:
        raise ValueError(f"rel_std = {rel_std} is invalid: must lie in [0, 0.3)")
    if not 0 < solid_fraction <= 0.3:
        raise ValueError(f"solid_fraction = {solid_fraction} is invalid: the random gas needs (0, 0.3]")
    if not (len(aspect) == 3 and all(isinstance(a, (int, float)) and 0.1 <= a <= 10 for a in aspect)):
        raise ValueError(f"aspect = {aspect!r} is invalid: three side ratios in [0.1, 10]")
    rng = random.Random(seed)
    radii = _radii(int(n), rel_std, rng)
    volume = sum(4.0 / 3.0 * math.pi * r ** 3 for r in radii)
    side = (volume / solid_fraction / (aspect[0] * aspect[1] * aspect[2])) ** (1.0 / 3.0)
    sides = [side * a for a in aspect]
    _scene.reset()
    O.materials.append(_w.MesoMat(**mould_material(material)))
    O.materials.append(_w.MesoMat(**particles))
    thick = 0.5 * D0
    lo, hi = (0.0, 0.0, 0.0), tuple(sides)
    walls = _utils.aabbWalls([lo, hi], thickness=thick, oversizeFactor=1.5, material="walls")
    O.bodies.append(walls)
    # Random sequential placement, largest first (no overlaps; the gas is far from jamming).
    placed = []
    cell = D0 * 1.2
    grid = {}
    for r in sorted(radii, reverse=True):
        for _ in range(100000):
            c = tuple(rng.uniform(r, sides[k] - r) for k in range(3))
            key = tuple(int(x / cell) for x in c)
            near = [placed[j] for dx in (-1, 0, 1) for dy in (-1, 0, 1) for dz in (-1, 0, 1)
                    for j in grid.get((key[0] + dx, key[1] + dy, key[2] + dz), ())]
            if all(sum((c[k] - q[0][k]) ** 2 for k in range(3)) >= (r + q[1]) ** 2 for q in near):
                grid.setdefault(key, []).append(len(placed))
                placed.append((c, r))
                break
        else:
            raise RuntimeError("could not place the random gas; lower solid_fraction")
    O.bodies.append([_utils.sphere(c, r, material="particles") for c, r in placed])
    O.dt = contact_step(min(radii))
    out = {"n": int(n), "radii": (min(radii), max(radii)), "side0": side, "dt": O.dt, "material": material,
           "kc_over_kp": particles["kc"] / KP, "seed": seed, "rel_std": rel_std}
    if tuple(aspect) != (1, 1, 1):
        out["aspect"] = list(aspect)
    return out


def sphere_ids():
    return [b.id for b in O.bodies if b is not None and isinstance(b.shape, _w.Sphere)]


def wall_ids():
    """{'left': id, ...} of the walls still present."""
    return {name: i for i, name in enumerate(WALLS) if i < len(O.bodies) and O.bodies[i] is not None
            and isinstance(O.bodies[i].shape, _w.Box)}


def inner_box():
    """(lo, hi) of the space between the walls present (inner faces)."""
    lo, hi = [None] * 3, [None] * 3
    for name, i in wall_ids().items():
        b = O.bodies[i]
        axis = WALLS.index(name) // 2
        if WALLS.index(name) % 2 == 0:
            lo[axis] = b.state.pos[axis] + b.shape.extents[axis]
        else:
            hi[axis] = b.state.pos[axis] - b.shape.extents[axis]
    return lo, hi


def kinetic_energy():
    """Translational plus rotational kinetic energy of the particles [mg mm^2/us^2 = nJ]."""
    e = 0.0
    for i in sphere_ids():
        s = O.bodies[i].state
        e += 0.5 * s.mass * s.vel.squaredNorm() + 0.5 * sum(s.inertia[k] * s.angVel[k] ** 2 for k in range(3))
    return e


def _lens(r1, r2, d):
    """Volume shared by two overlapping spheres (radii r1, r2, centres d apart)."""
    if d >= r1 + r2:
        return 0.0
    return math.pi * (r1 + r2 - d) ** 2 * (d * d + 2 * d * (r1 + r2) - 3 * (r1 - r2) ** 2) / (12 * d)


def _cap(r, h):
    """Volume of a sphere of radius r beyond a plane at distance h from its centre."""
    t = r - h
    return 0.0 if t <= 0 else math.pi * t * t * (3 * r - t) / 3


def stats():
    """The state of the sample: solid fraction (sphere volume inside the walls' inner box, overlap
    lenses and wall caps subtracted, over the box volume; where the walls are gone, the particles'
    extent), coordination (2 x particle-particle contacts / N), coordination_with_walls,
    rattlers (particles with < 2 mechanical contacts, walls included), wall stresses
    (compressive > 0), kinetic energy and its ratio to energy_scale()."""
    ids = set(sphere_ids())
    lo, hi = inner_box()
    for k in range(3):  # without walls on an axis: the particles' extent
        if lo[k] is None:
            lo[k] = min(O.bodies[i].state.pos[k] - O.bodies[i].shape.radius for i in ids)
        if hi[k] is None:
            hi[k] = max(O.bodies[i].state.pos[k] + O.bodies[i].shape.radius for i in ids)
    vol = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2])
    vs = 0.0
    for i in ids:
        b = O.bodies[i]
        r, x = b.shape.radius, b.state.pos
        vs += 4.0 / 3.0 * math.pi * r ** 3
        for k in range(3):
            vs -= _cap(r, x[k] - lo[k]) + _cap(r, hi[k] - x[k])
    pp = pw = 0
    contacts = dict.fromkeys(ids, 0)
    for I in O.interactions:
        if not I.isReal or I.geom.penetrationDepth <= 0:  # mechanical contacts only
            continue
        for j in (I.id1, I.id2):
            if j in contacts:
                contacts[j] += 1
        if I.id1 in ids and I.id2 in ids:
            pp += 1
            b1, b2 = O.bodies[I.id1], O.bodies[I.id2]
            vs -= _lens(b1.shape.radius, b2.shape.radius, (b1.state.pos - b2.state.pos).norm())
        else:
            pw += 1
    stress = {}
    for name, i in wall_ids().items():
        axis = WALLS.index(name) // 2
        a, b = [k for k in range(3) if k != axis]
        area = (hi[a] - lo[a]) * (hi[b] - lo[b])
        f = O.forces.f(i)[axis]
        stress[name] = (f if WALLS.index(name) % 2 else -f) / area
    ke = kinetic_energy()
    return {"solid_fraction": vs / vol, "coordination": 2.0 * pp / len(ids),
            "coordination_with_walls": (2.0 * pp + pw) / len(ids),
            "rattlers": sum(1 for c in contacts.values() if c < 2), "wall_stress": stress,
            "side": [hi[k] - lo[k] for k in range(3)], "kinetic_energy": ke,
            "kinetic_energy_ratio": ke / energy_scale(len(ids)), "iter": O.iter, "time": O.time}


def _controller(goal, max_vel):
    return _w.TriaxialStressController(
        internalCompaction=False, stressMask=7, goal1=-goal, goal2=-goal, goal3=-goal,
        thickness=0.5 * D0, max_vel=max_vel, stressDamping=0.25, label="triax")


def energy_scale(n):
    """Elastic energy of the sintered sample, the scale of 'static': a contact force p_s d0^2
    on a spring kp stores (p_s d0^2)^2/(2 kp); about 3 contacts per particle."""
    return 3 * n * (SINTER_STRESS * D0 * D0) ** 2 / (2 * KP)


def run_until_static(measure, stage, chunk=2000, max_steps=400000, progress=True):
    """Runs until ``measure()`` -> (static, text, value) says static on two consecutive checks,
    ``chunk`` steps apart; returns (steps, value). The one loop behind every "relax" of the
    tablet and its tests."""
    t0, start, ok, text = time.time(), O.iter, 0, ""
    while O.iter - start < max_steps:
        O.run(chunk, True)
        static, text, value = measure()
        if progress:
            print(f"  {stage}: step {O.iter - start:7d}  {text}  ({time.time() - t0:.0f} s)", flush=True)
        ok = ok + 1 if static else 0
        if ok == 2:
            return O.iter - start, value
    raise RuntimeError(f"{stage}: not static after {max_steps} steps ({text})")


def _relax(goal, tol_stress, tol_ke, stage, progress, max_steps=400000):
    """The stress-controlled walls run until every wall's stress is within tol_stress of the goal
    and the kinetic energy below tol_ke energy_scale(); returns stats() with the goal."""
    def measure():
        s = stats()
        err = max(abs(v / goal - 1.0) for v in s["wall_stress"].values())
        text = (f"max |stress/goal - 1| = {err:.3g}  E_kin/E_ref = {s['kinetic_energy_ratio']:.2e}  "
                f"solid fraction {s['solid_fraction']:.4f}  C {s['coordination']:.2f}")
        return err < tol_stress and s["kinetic_energy_ratio"] < tol_ke, text, s
    steps, s = run_until_static(measure, stage, max_steps=max_steps, progress=progress)
    s["goal"], s["steps"] = goal, steps
    return s


def _set_goal(p):
    triax = [e for e in O.engines if isinstance(e, _w.TriaxialStressController)][0]
    triax.goal1 = triax.goal2 = triax.goal3 = -p  # YADE: tension positive


def _release(goal, steps, progress, chunk=1000):
    """Lowers the walls' stress goal geometrically from the present one to ``goal`` over
    ``steps`` steps. A sudden drop lets the stored elastic energy throw the particles apart:
    released at once, the sintered sample expanded by 14 % in length and lost half its contacts."""
    triax = [e for e in O.engines if isinstance(e, _w.TriaxialStressController)][0]
    start = -triax.goal1
    n = max(1, steps // chunk)
    for k in range(1, n + 1):
        _set_goal(start * (goal / start) ** (k / n))
        O.run(chunk, True)
        if progress and k % 10 == 0:
            s = stats()
            print(f"  release ramp: {k * chunk:7d}/{n * chunk} steps  goal {-triax.goal1:.4g}  "
                  f"solid fraction {s['solid_fraction']:.4f}  C {s['coordination']:.2f}", flush=True)


def save_atomic(path, info):
    """O.save to ``path`` and the description to ``path + '.json'``, each written under a
    temporary name and renamed, the JSON last: a reader that finds the JSON finds both whole."""
    tmp = f"{path[:-len('.yade.gz')]}.tmp-{os.getpid()}-state.yade.gz"  # outputs.sweep knows the pattern
    O.save(tmp)
    os.replace(tmp, path)
    _outputs.write_atomic(path + ".json", json.dumps(info, indent=1))


def make_adhesive_walls(wall_ids):
    """Gives these walls the adhesive law of Luding's tension tests (the particles' law with
    kc_wall/kp = 20, mu_wall = 10, ``dominant``) as a material of their own, "loading walls", so
    that the other walls stay a smooth mould; every contact of these walls adopts it, keeping its
    history (the force stays continuous). Idempotent."""
    mats = [m for m in O.materials if m.label == "loading walls"]
    if mats:
        mat = mats[0]
    else:
        particles = [m for m in O.materials if m.label == "particles"][0]
        keys = [k for k in particle_material() if k != "label"]
        kw = {k: getattr(particles, k) for k in keys}
        kw.update(kc=20 * KP, frictionAngle=math.atan(10.0), dominant=True, label="loading walls")
        mat = _w.MesoMat(**kw)
        O.materials.append(mat)
    _give_material(wall_ids, mat)


def _give_material(ids, mat):
    """Gives the bodies ``ids`` the material ``mat``; each of their contacts adopts it keeping its
    history (overlap, delta_max, springs): the force stays continuous."""
    ip2 = [e for e in O.engines if isinstance(e, _w.InteractionLoop)][0].physDispatcher.functors[0]
    for i in ids:
        O.bodies[i].material = mat
    for I in {(I.id1, I.id2): I for i in ids for I in O.bodies[i].intrs() if I.isReal}.values():
        ip2.adoptMaterials(I)


def set_tensile_stiffness(kc_over_kp):
    """The loaded state with the particles' kc/kp changed (issue E5: does the peak follow the
    contacts' tensile branch?): the "particles" material gets kc = kc_over_kp kp and every
    contact of a sphere adopts it, keeping its history; the loading walls' own kc stays. A
    contact on the tensile branch at this moment changes its force (-kc delta): their number is
    returned with the change. Returns {'kc_over_kp', 'was', 'contacts', 'tensile_fraction'}."""
    if not (isinstance(kc_over_kp, (int, float)) and 0 <= kc_over_kp < math.inf):
        raise ValueError(f"kc_over_kp = {kc_over_kp!r} is invalid: must be a finite number >= 0")
    mat = [m for m in O.materials if m.label == "particles"][0]
    was = mat.kc / KP
    tensile = _scene.branch_fractions().get("tensile", 0.0)
    mat.kc = kc_over_kp * KP
    _give_material(sphere_ids(), mat)
    return {"kc_over_kp": kc_over_kp, "was": was, "contacts": sum(1 for I in O.interactions if I.isReal),
            "tensile_fraction": tensile}


LIMITS = {"locked": dict(frictionAngle=math.atan(1e3), muR=1e3, muO=1e3),   # no sliding, rolling or twisting
          "free": dict(frictionAngle=0.0, muR=0.0, muO=0.0)}               # no resistance to them at all


def set_limits(mode):
    """The loaded state with the particles' Coulomb limits of sliding, rolling and torsion changed
    (issue #47, E7: is the early loss of tension the contacts' re-arrangement?): 'locked' (mu,
    muR, muO = 1000: the springs never slip) or 'free' (all 0: no tangential, rolling or torsion
    force); every sphere's contact adopts it keeping its history. Returns {'limits', 'was'}."""
    if mode not in LIMITS:
        raise ValueError(f"limits = {mode!r} is invalid: one of {sorted(LIMITS)}")
    mat = [m for m in O.materials if m.label == "particles"][0]
    was = {k: getattr(mat, k) for k in LIMITS[mode]}
    for k, v in LIMITS[mode].items():
        setattr(mat, k, v)
    _give_material(sphere_ids(), mat)
    return {"limits": mode, "was": was}


def _switch_particles(label):
    """Gives every sphere the material ``label`` (_give_material)."""
    _give_material(sphere_ids(), [m for m in O.materials if m.label == label][0])


def _wall_contacts(name):
    wid = wall_ids()[name]
    return sum(1 for I in O.bodies[wid].intrs() if I.isReal and I.geom.penetrationDepth > 0)


def _compact(goal, speed, progress, chunk=500, max_steps=200000):
    """Drives the walls in at up to ``speed`` [mm/us], without background drag, until every wall
    first carries 0.9 goal; returns stats() then. The particles meet faster than they stick, so
    the skeleton is formed by the pressure rather than by slow aggregation into clusters."""
    drag = [e for e in O.engines if isinstance(e, _w.MesoBackgroundDamping)][0]
    triax = [e for e in O.engines if isinstance(e, _w.TriaxialStressController)][0]
    gammas, triax.max_vel = (drag.gammaB, drag.gammaBR), speed
    drag.gammaB = drag.gammaBR = 0.0
    start = O.iter
    while True:
        O.run(chunk, True)
        s = stats()
        if progress:
            print(f"  compaction: step {O.iter - start:6d}  smallest wall stress/goal "
                  f"{min(s['wall_stress'].values()) / goal:.3f}  solid fraction {s['solid_fraction']:.4f}", flush=True)
        if min(s["wall_stress"].values()) >= 0.9 * goal:
            break
        if O.iter - start > max_steps:
            raise RuntimeError(f"compaction: the wall stress did not reach {goal:g} in {max_steps} steps")
    drag.gammaB, drag.gammaBR = gammas
    triax.max_vel = SINTER_SPEED
    s["steps"] = O.iter - start
    return s


def prepare(path, n=1728, material="appendixF", kc_over_kp=None, rel_std=0.05, seed=1, tol_stress=0.01,
            tol_ke=1e-4, compaction_speed=COMPACTION_SPEED, release_steps=RELEASE_STEPS, progress=True,
            packing="full", glue="loading", sinter=SINTER, aspect=(1, 1, 1)):
    """Makes the released tablet with the full law (adhesion, friction, rolling, torsion) from
    the start: a gas of the particles is compacted by the six walls (at up to
    ``compaction_speed`` [mm/us], without background drag) until they carry d0 p_s/kp = 0.02,
    sintered at that stress with the lab-frame background drag until static, glued to the two
    x walls (make_adhesive_walls), released to
    p_r/p_s = 1e-3 (the goal lowered geometrically over ``release_steps`` steps) and relaxed.
    Saves the released state to ``path`` (O.save) and its description to ``path + '.json'``
    (both atomically); returns the description.

    ``packing='frictionless'`` compacts the gas without friction, rolling, torsion and adhesion
    (the particles' normal law otherwise) and lets it come to rest at PACKING_RATIO p_s with the
    drag (a dense random packing), then switches the full law on for sintering, each contact
    keeping its history; ``glue='all'`` makes all six walls adhesive after sintering, ``'sinter'``
    before it (the four lateral ones are removed with the unconfined start, uniaxial.make_unconfined).
    ``sinter``: the sintering stress d0 p_s/kp (the paper's 0.02); the packing's and the release's
    stresses stay those of the paper, so that only the sintering depth changes. ``aspect``: the
    box's side ratios (build; the agglomerate study sinters a block of two cubes)."""
    if not (isinstance(sinter, (int, float)) and math.isfinite(sinter) and sinter > 0):
        raise ValueError(f"sinter = {sinter!r} is invalid: the sintering stress d0 p_s/kp must be a positive number")
    p_s = sinter * KP / D0
    if packing not in PACKINGS:
        raise ValueError(f"packing = {packing!r} is invalid: one of {PACKINGS}")
    if glue not in GLUES:
        raise ValueError(f"glue = {glue!r} is invalid: one of {GLUES}")
    t0 = time.time()
    info = {"built": build(n, rel_std=rel_std, seed=seed, material=material, kc_over_kp=kc_over_kp, aspect=aspect)}
    info["built"].update(packing=packing, glue=glue, **({"sinter": sinter} if sinter != SINTER else {}))
    O.engines = engines(_controller(p_s, SINTER_SPEED), reference="lab")
    if packing == "frictionless":  # packed to rest at PACKING_RATIO p_s, then the full law and p_s
        O.materials.append(_w.MesoMat(**particle_material(material, kc=0.0, frictionAngle=0.0, muR=0.0, muO=0.0,
                                                          label="packing")))
        _switch_particles("packing")
        _set_goal(PACKING_RATIO * SINTER_STRESS)
        info["compacted"] = _compact(PACKING_RATIO * SINTER_STRESS, compaction_speed, progress)
        info["packed"] = _relax(PACKING_RATIO * SINTER_STRESS, tol_stress, tol_ke, "packing", progress)
        _switch_particles("particles")
        _set_goal(p_s)
    else:
        info["compacted"] = _compact(p_s, compaction_speed, progress)
    if glue == "sinter":  # sintered against six adhesive walls
        make_adhesive_walls([wall_ids()[w] for w in WALLS])
    info["sintered"] = _relax(p_s, tol_stress, tol_ke, "sintering", progress, max_steps=1000000)
    # The loading walls are glued to the sample where it was sintered against them: released
    # against the smooth mould first, only the few particles still touching at p_r (12 and 16
    # of about 144 per face) held it, and the pull tore it off a wall.
    make_adhesive_walls([wall_ids()[w] for w in (("left", "right") if glue == "loading" else WALLS)])
    info["loading_wall_contacts_sintered"] = {k: _wall_contacts(k) for k in ("left", "right")}
    _release(RELEASE_RATIO * SINTER_STRESS, release_steps, progress)
    info["released"] = _relax(RELEASE_RATIO * SINTER_STRESS, tol_stress, tol_ke, "release", progress)
    info["release_steps"] = release_steps
    info["loading_wall_contacts_released"] = {k: _wall_contacts(k) for k in ("left", "right")}
    info["units"] = "mm, us, mg (stress 1 = 1e9 Pa)"
    info["d0"] = D0
    info["kp"] = KP
    info["wall_clock_s"] = time.time() - t0
    save_atomic(path, info)
    return info
