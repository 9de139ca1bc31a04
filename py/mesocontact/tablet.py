"""The agglomerate "tablet" of Luding 2008 / Appendix F of the long paper (run inside ``yade``).

Units are the paper's: 1 mm, 1 us, 1 mg (stiffness 1 = 1e6 N/m, stress 1 = 1e9 Pa). Primary
particles of mean diameter d0 = 0.01 in a box of six walls (YADE boxes, so that rolling and
torsion act on the walls' ScGeom6D too) are pressure-sintered with YADE's
``TriaxialStressController`` at d0 p_s/kp = 0.02, released to p_r/p_s = 1e-3, and saved:

    from mesocontact import tablet
    info = tablet.prepare("tablet.yade.gz")      # or tablet.released("tablet.yade.gz"): reuse
    print(info["released"]["solid_fraction"])

All six walls carry the strongly adhesive wall material of Luding's tension tests (a ``dominant``
MesoMat, kc_wall/kp = 20, mu_wall = 10), so the two loading walls of every later test hold the
sample from the start; the four lateral walls are removed by the tests.
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
    raise ImportError("mesocontact.tablet needs YADE: run it inside `yade`") from _exc

from . import params as _params

D0 = 0.01          # mean primary-particle diameter [mm]
DENSITY = 2.0      # 2000 kg/m^3 in mg/mm^3
KP = 5.0           # limit stiffness [mg/us^2 = 1e6 N/m]
GAMMA0 = 5e-5      # normal viscous damping [mg/us = kg/s]
SINTER_STRESS = 0.02 * KP / D0   # d0 p_s/kp = 0.02
RELEASE_RATIO = 1e-3             # p_r/p_s
PACKING_RATIO = 1e-1             # stress of the frictionless, non-adhesive packing stage, over p_s
WALLS = ("left", "right", "bottom", "top", "back", "front")  # YADE's aabbWalls order: -x +x -y +y -z +z


def particle_material(**changes):
    """Table 2 of Luding 2008 with the changes of Appendix F (kc/kp = 0.2, mu_r = mu_o = 0.2,
    gamma_r/gamma0 = gamma_o/gamma0 = 0.1) as MesoMat keywords; ``changes`` override."""
    kw = dict(density=DENSITY, k1=0.5 * KP, kp=KP, kc=0.2 * KP, phiF=0.05, gammaN=GAMMA0,
              frictionAngle=math.atan(1.0), kt=0.2 * KP, gammaT=0.2 * GAMMA0,
              kr=0.1 * KP, gammaR=0.1 * GAMMA0, muR=0.2, ko=0.1 * KP, gammaO=0.1 * GAMMA0, muO=0.2,
              label="particles")
    kw.update(changes)
    return kw


def wall_material(**changes):
    """The loading walls of Luding's tension tests: the particles' law with kc_wall/kp = 20 and
    mu_wall = 10, imposed unmixed on wall contacts (``dominant``)."""
    kw = particle_material(kc=20 * KP, frictionAngle=math.atan(10.0), label="walls", dominant=True)
    kw.update(changes)
    return kw


def background_damping():
    """Luding's viscous background damping, gamma_b/gamma0 = 4, gamma_br/gamma0 = 1."""
    return _w.MesoBackgroundDamping(gammaB=4 * GAMMA0, gammaBR=GAMMA0, label="background")


def time_step(r_min):
    """t_c/50 of the stiffest, lightest pair (all springs of the law resolved)."""
    m = particle_material()
    m_min = _params.sphere_mass(r_min, DENSITY)
    return _params.time_step(m["kp"], m_min, kt=m["kt"], kr=m["kr"], ko=m["ko"], gamma=m["gammaN"])


def engines(controller=None, extra=()):
    """The engine loop of every tablet run: spheres and boxes, meso law, background damping."""
    loop = [
        _w.ForceResetter(),
        _w.InsertionSortCollider([_w.Bo1_Sphere_Aabb(), _w.Bo1_Box_Aabb()], label="collider"),
        _w.InteractionLoop(
            # The law reads no relative rotation of ScGeom6D (only the bodies' spins): YADE need not compute them.
            [_w.Ig2_Sphere_Sphere_ScGeom6D(updateRotations=False), _w.Ig2_Box_Sphere_ScGeom6D()],
            [_w.Ip2_MesoMat_MesoMat_MesoPhys()],
            [_w.Law2_ScGeom_MesoPhys_Meso(label="law")]),
        background_damping(),
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


def build(n=1728, rel_std=0.05, solid_fraction=0.2, seed=1):
    """A loose random gas of n spheres in a cubic box of six adhesive walls (ids 0-5, spheres
    after). The Gaussian size distribution is narrow (relative std rel_std, cut at 2 sigma) to
    avoid monodisperse crystallisation."""
    if int(n) != n or n < 8:
        raise ValueError(f"n = {n} is invalid: at least 8 particles")
    if not 0 <= rel_std < 0.3:
        raise ValueError(f"rel_std = {rel_std} is invalid: must lie in [0, 0.3)")
    if not 0 < solid_fraction <= 0.3:
        raise ValueError(f"solid_fraction = {solid_fraction} is invalid: the random gas needs (0, 0.3]")
    rng = random.Random(seed)
    radii = _radii(int(n), rel_std, rng)
    volume = sum(4.0 / 3.0 * math.pi * r ** 3 for r in radii)
    side = (volume / solid_fraction) ** (1.0 / 3.0)
    O.reset()
    O.materials.append(_w.MesoMat(**wall_material()))
    O.materials.append(_w.MesoMat(**particle_material()))
    thick = 0.5 * D0
    lo, hi = (0.0, 0.0, 0.0), (side, side, side)
    walls = _utils.aabbWalls([lo, hi], thickness=thick, oversizeFactor=1.5, material="walls")
    O.bodies.append(walls)
    # Random sequential placement, largest first (no overlaps; the gas is far from jamming).
    placed = []
    cell = D0 * 1.2
    grid = {}
    for r in sorted(radii, reverse=True):
        for _ in range(100000):
            c = tuple(rng.uniform(r, side - r) for _ in range(3))
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
    O.dt = time_step(min(radii))
    return {"n": int(n), "radii": (min(radii), max(radii)), "side0": side, "dt": O.dt}


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


def stats():
    """Solid fraction (sphere volume over the walls' inner box, or the particles' extent where
    the walls are gone; overlaps counted twice), mean
    coordination number (particle contacts per particle, walls excluded, and with walls), wall
    stresses (compressive > 0), kinetic energy."""
    ids = set(sphere_ids())
    lo, hi = inner_box()
    for k in range(3):  # without walls on an axis: the particles' extent
        if lo[k] is None:
            lo[k] = min(O.bodies[i].state.pos[k] - O.bodies[i].shape.radius for i in ids)
        if hi[k] is None:
            hi[k] = max(O.bodies[i].state.pos[k] + O.bodies[i].shape.radius for i in ids)
    vol = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2])
    vs = sum(4.0 / 3.0 * math.pi * O.bodies[i].shape.radius ** 3 for i in ids)
    pp = pw = 0
    for I in O.interactions:
        if not I.isReal or I.geom.penetrationDepth <= 0:  # mechanical contacts only
            continue
        if I.id1 in ids and I.id2 in ids:
            pp += 1
        else:
            pw += 1
    stress = {}
    for name, i in wall_ids().items():
        axis = WALLS.index(name) // 2
        a, b = [k for k in range(3) if k != axis]
        area = (hi[a] - lo[a]) * (hi[b] - lo[b])
        f = O.forces.f(i)[axis]
        stress[name] = (f if WALLS.index(name) % 2 else -f) / area
    return {"solid_fraction": vs / vol, "coordination": 2.0 * pp / len(ids),
            "coordination_with_walls": (2.0 * pp + pw) / len(ids), "wall_stress": stress,
            "side": [hi[k] - lo[k] for k in range(3)], "kinetic_energy": kinetic_energy(),
            "iter": O.iter, "time": O.time}


def _controller(goal):
    return _w.TriaxialStressController(
        internalCompaction=False, stressMask=7, goal1=-goal, goal2=-goal, goal3=-goal,
        thickness=0.5 * D0, max_vel=0.05, stressDamping=0.25, label="triax")


def energy_scale(n):
    """Elastic energy of the sintered sample, the scale of 'static': a contact force p_s d0^2
    on a spring kp stores (p_s d0^2)^2/(2 kp); about 3 contacts per particle."""
    return 3 * n * (SINTER_STRESS * D0 * D0) ** 2 / (2 * KP)


def _relax(goal, max_steps, tol_stress, tol_ke, chunk, progress, stage):
    """Runs the stress-controlled walls until the sample is static: every wall's stress within
    tol_stress of the goal and the kinetic energy below tol_ke energy_scale(). Returns (steps,
    stats())."""
    e_ref = energy_scale(len(sphere_ids()))
    t0, start, ok = time.time(), O.iter, 0
    while O.iter - start < max_steps:
        O.run(chunk, True)
        s = stats()
        err = max(abs(v / goal - 1.0) for v in s["wall_stress"].values())
        ke = s["kinetic_energy"] / e_ref
        if progress:
            print(f"  {stage}: step {O.iter - start:7d}  max |stress/goal - 1| = {err:.3g}  "
                  f"E_kin/E_ref = {ke:.2e}  solid fraction {s['solid_fraction']:.4f}  "
                  f"({time.time() - t0:.0f} s)", flush=True)
        ok = ok + 1 if (err < tol_stress and ke < tol_ke) else 0
        if ok == 2:  # static on two consecutive checks
            return O.iter - start, s
    raise RuntimeError(f"{stage}: not static after {max_steps} steps (stress error {err:.3g}, "
                       f"E_kin/E_ref {ke:.3g})")


def _set_goal(p):
    triax = [e for e in O.engines if isinstance(e, _w.TriaxialStressController)][0]
    triax.goal1 = triax.goal2 = triax.goal3 = -p  # YADE: tension positive


def _set_packing_law(packing):
    """Frictionless, non-adhesive contacts (packing=True) or the full law (False). Existing
    contacts are remade by the Ip2 with the new parameters, without history."""
    for m in O.materials:
        full = wall_material() if m.label == "walls" else particle_material()
        if packing:
            m.kc, m.frictionAngle, m.muR, m.muO = 0.0, 0.0, 0.0, 0.0
        else:
            m.kc, m.frictionAngle, m.muR, m.muO = full["kc"], full["frictionAngle"], full["muR"], full["muO"]
    for I in O.interactions:
        I.phys = None


def prepare(path, n=1728, rel_std=0.05, seed=1, tol_stress=0.01, tol_ke=1e-4,
            max_steps=400000, progress=True):
    """Builds, pressure-sinters at d0 p_s/kp = 0.02 and releases to p_r/p_s = 1e-3 a tablet of n
    particles, saves the released state to ``path`` (O.save) and its description to
    ``path + '.json'``; returns that description."""
    t0 = time.time()
    info = {"built": build(n, rel_std=rel_std, seed=seed)}
    # A random gas of adhesive, frictional particles aggregates into loose clusters; pack it
    # first without adhesion and friction (the usual way to a dense random packing), at a low
    # stress, then switch the full law on (new contacts, no history) and sinter.
    _set_packing_law(True)
    p_pack = PACKING_RATIO * SINTER_STRESS
    O.engines = engines(_controller(p_pack))
    _, info["packed"] = _relax(p_pack, max_steps, tol_stress, tol_ke, 2000, progress, "packing")
    info["packed"]["goal"] = p_pack
    _set_packing_law(False)
    _set_goal(SINTER_STRESS)
    _, sinter = _relax(SINTER_STRESS, max_steps, tol_stress, tol_ke, 2000, progress, "sintering")
    sinter["goal"] = SINTER_STRESS
    info["sintered"] = sinter
    p_r = RELEASE_RATIO * SINTER_STRESS
    _set_goal(p_r)
    _, released = _relax(p_r, max_steps, tol_stress, tol_ke, 2000, progress, "release")
    released["goal"] = p_r
    info["released"] = released
    info["units"] = "mm, us, mg (stress 1 = 1e9 Pa)"
    info["d0"] = D0
    info["kp"] = KP
    info["wall_clock_s"] = time.time() - t0
    O.save(path)
    with open(path + ".json", "w") as f:
        json.dump(info, f, indent=1)
    return info


def released(path, progress=True, **prepare_kw):
    """The released state at ``path``: loaded if the file exists, prepared and saved otherwise.
    Returns its description (the JSON written by prepare())."""
    if os.path.exists(path) and os.path.exists(path + ".json"):
        O.load(path)
        with open(path + ".json") as f:
            return json.load(f)
    if progress:
        print(f"preparing the released tablet {path}", flush=True)
    return prepare(path, progress=progress, **prepare_kw)
