"""A sintered bulk sample of any MesoMat, made in a box of six walls (inside ``yade``).

The stages: a random gas of the particles in a box of six walls (YADE boxes, or a facet each:
Protocol.walls; either with ScGeom6D, so that rolling and torsion act at the walls too),
compacted by YADE's ``TriaxialStressController`` to the sintering stress p_s, sintered there
with the full law until static, the loading walls (or all) made adhesive, released slowly to p_r
and relaxed; then saved with its description::

    from mesocontact import bulk
    from mesocontact.bulk import protocol
    p = protocol.Protocol.ratios(my_material, d0=1e-4, sinter=0.02, n=500)
    info = bulk.prepare("released.yade.gz", p)        # saved, described, progress lines
    print(info["released"]["solid_fraction"], info["released"]["coordination"])

While the sample is made the walls are a smooth, non-adhesive mould: frictional walls lock the
box (spheres wedged at its edges carry the stress by friction: at N = 216 the target was met
at solid fraction 0.40, coordination 1.2). The protocol travels with the scene (O.tags), so
``current()`` knows it after ``O.load``. Wall ids 0-5 are left, right, bottom, top, back, front.
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
    raise ImportError("mesocontact.bulk.sample needs YADE: run it inside `yade`") from _exc

from .. import outputs as _outputs
from .. import params as _params
from .. import scene as _scene
from .protocol import TAG, Protocol

WALLS = ("left", "right", "bottom", "top", "back", "front")  # YADE's aabbWalls order: -x +x -y +y -z +z


def current():
    """The Protocol the scene in O was made with (read from O.tags); a ValueError if it has none."""
    if TAG not in O.tags.keys():
        raise ValueError("this scene has no bulk protocol: make it with bulk.prepare (or bulk.sample.build), "
                         "or pass protocol=")
    return Protocol.from_json(O.tags[TAG])


def resolve(protocol):
    """``protocol`` (a Protocol), or, when None, the scene's (current())."""
    if protocol is None:
        return current()
    if not isinstance(protocol, Protocol):
        raise TypeError(f"protocol = {protocol!r} is invalid: a mesocontact.bulk.protocol.Protocol")
    return protocol


def particle_material(protocol, label="particles", **changes):
    """The particles' MesoMat keywords with this label; ``changes`` override."""
    return dict(protocol.material, label=label, **changes)


def without_adhesion(protocol):
    """The keywords that switch the particles' adhesion off: kc, and the non-contact fa where the
    material has one (``protocol``: a Protocol, or one material's keywords)."""
    material = protocol if isinstance(protocol, dict) else protocol.material
    return dict(kc=0.0, **({"fa": 0.0} if material.get("fa", 0.0) > 0 else {}))


def mould_material(protocol):
    """The walls while the sample is made: the particles' normal law without adhesion, friction,
    rolling or torsion (a smooth, non-adhesive mould), imposed unmixed."""
    return particle_material(protocol, **without_adhesion(protocol), frictionAngle=0.0, muR=0.0, muO=0.0,
                             label="walls", dominant=True)


def background_damping(protocol, reference="lab"):
    """Viscous background drag gamma_b, gamma_br (protocol.drag times gammaN), relative to the lab
    (preparation) or to the rigid motion of each particle's contacts (the tests)."""
    g = protocol.material["gammaN"]
    return _w.MesoBackgroundDamping(gammaB=protocol.drag[0] * g, gammaBR=protocol.drag[1] * g,
                                    reference=reference, label="background")


def contact_step(protocol, r_min):
    """t_c/50 of the stiffest, lightest pair (every spring of the law resolved; in a mixture the
    smallest over its materials)."""
    steps = []
    for _, _, m in protocol.materials():
        m_min = _params.sphere_mass(r_min, m["density"])
        steps.append(_params.resolved_step(m["kp"], m_min, kt=m.get("kt", 0.0), kr=m.get("kr", 0.0),
                                           ko=m.get("ko", 0.0), gamma=m["gammaN"]))
    return min(steps)


def _wall_functors(protocol):
    """([Bo1], [Ig2]) of the protocol's walls: YADE's box functors, and with facet walls the plugin's
    facet geometry too (boxes stay for the tools that add a box of their own: pair_cycles.Wall)."""
    bo1, ig2 = [_w.Bo1_Box_Aabb()], [_w.Ig2_Box_Sphere_ScGeom6D()]
    if resolve(protocol).walls == "facets":
        bo1.append(_w.Bo1_Facet_Aabb())
        ig2.append(_w.Ig2_Facet_Sphere_MesoScGeom6D())
    return bo1, ig2


def engines(protocol, controller=None, extra=(), reference="lab"):
    """The engine loop of a bulk sample: spheres and walls (boxes or facets), the meso law,
    background drag."""
    bo1, ig2 = _wall_functors(protocol)
    loop = [
        _w.ForceResetter(),
        _w.InsertionSortCollider([_w.Bo1_Sphere_Aabb()] + bo1, label="collider"),
        _w.InteractionLoop(
            # The law reads no relative rotation of ScGeom6D (only the bodies' spins): YADE need not compute them.
            [_w.Ig2_Sphere_Sphere_ScGeom6D(updateRotations=False)] + ig2,
            [_w.Ip2_MesoMat_MesoMat_MesoPhys()],
            [_w.Law2_ScGeom_MesoPhys_Meso(label="law")]),
        background_damping(protocol, reference),
    ]
    if controller is not None:
        loop.append(controller)
    loop += list(extra)
    loop.append(_w.NewtonIntegrator(damping=0.0, label="newton"))
    return loop


def _radii(n, d0, rel_std, rng, distribution="gaussian"):
    """n radii about d0/2 with relative standard deviation rel_std: Gaussian, cut at 2 sigma;
    uniform (half-width sqrt(3) rel_std); lognormal with mean d0/2 and that spread before its
    logarithm is cut at 2 sigma. The cuts narrow the spread: to 0.88 of rel_std (Gaussian;
    lognormal 0.88 to 0.86 for rel_std 0.1 to 0.29), and lower the lognormal mean by 0.1 to 0.9 %."""
    out = []
    if distribution == "uniform":
        h = math.sqrt(3.0) * rel_std
        return [0.5 * d0 * (1.0 + rng.uniform(-h, h)) for _ in range(n)]
    s = math.sqrt(math.log(1.0 + rel_std * rel_std))
    while len(out) < n:
        if distribution == "lognormal":
            z = rng.gauss(0.0, 1.0)
            if abs(z) <= 2:
                out.append(0.5 * d0 * math.exp(s * z - 0.5 * s * s))
            continue
        x = rng.gauss(0.0, rel_std)
        if abs(x) <= 2 * rel_std:
            out.append(0.5 * d0 * (1.0 + x))
    return out


def _place(radii, sides, cell, rng):
    """Random sequential placement, largest first, without overlaps (the gas is far from jamming)."""
    placed, grid = [], {}
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
            raise RuntimeError("could not place the random gas; lower gas_fraction")
    return placed


def _kinds(p):
    """Each sphere's material label: 'particles' alone, or a mixture's kinds in their numbers
    (Protocol.kind_counts), shuffled by their own generator so that the radii and places are those
    of the same seed without a mixture."""
    if not p.mixture:
        return ["particles"] * p.n
    out = [label for (label, _, _), c in zip(p.materials(), p.kind_counts()) for _ in range(c)]
    random.Random(p.seed + 104729).shuffle(out)
    return out


def build(protocol):
    """A loose random gas of the protocol's n spheres in a box of six smooth walls (ids 0-5,
    spheres after), sides in the ratios protocol.aspect; the scene carries the protocol
    (O.tags). Returns its description."""
    p = resolve(protocol)
    rng = random.Random(p.seed)
    radii = _radii(p.n, p.d0, p.rel_std, rng, p.distribution)
    volume = sum(4.0 / 3.0 * math.pi * r ** 3 for r in radii)
    aspect = p.aspect
    side = (volume / p.gas_fraction / (aspect[0] * aspect[1] * aspect[2])) ** (1.0 / 3.0)
    sides = [side * a for a in aspect]
    materials = [_w.MesoMat(**mould_material(p))] + [_w.MesoMat(**dict(m, label=label))  # refused before the reset
                                                     for label, _, m in p.materials()]
    _scene.reset()
    O.tags[TAG] = p.to_json()
    for mat in materials:
        O.materials.append(mat)
    lo, hi = (0.0, 0.0, 0.0), tuple(sides)
    if p.walls == "facets":
        O.bodies.append(facet_walls(lo, hi, "walls"))
    else:
        O.bodies.append(_utils.aabbWalls([lo, hi], thickness=0.5 * p.d0, oversizeFactor=1.5, material="walls"))
    # cells at least a diameter wide, so that the 27 cells about one hold every sphere it can overlap
    # (1.2 d0 holds them for radii up to 0.6 d0: every preparation made so far, rel_std <= 0.1, unchanged)
    placed = _place(radii, sides, max(p.d0 * 1.2, 2.0 * max(radii)), rng)
    O.bodies.append([_utils.sphere(c, r, material=kind) for (c, r), kind in zip(placed, _kinds(p))])
    O.dt = contact_step(p, min(radii))
    out = {"n": p.n, "radii": (min(radii), max(radii)), "side0": side, "dt": O.dt, "material": p.name,
           "kc_over_kp": p.material["kc"] / p.kp, "seed": p.seed, "rel_std": p.rel_std}
    if p.distribution != "gaussian":
        out["distribution"] = p.distribution
    if p.mixture:
        out["mixture"] = {label: sum(1 for i in sphere_ids() if O.bodies[i].material.label == label)
                          for label, _, _ in p.materials()}
    if tuple(aspect) != (1, 1, 1):
        out["aspect"] = list(aspect)
    if p.walls != "boxes":
        out["walls"] = p.walls
    return out


def facet_walls(lo, hi, material):
    """The six faces of the box (lo, hi) as one fixed facet each, in WALLS' order: a triangle in the
    face's plane that holds the face grown to three times its sides about its centre, so that a
    sphere inside the box meets no edge while a test stretches the box or moves the faces."""
    walls = []
    for k, name in enumerate(WALLS):
        axis = k // 2
        a, b = [j for j in range(3) if j != axis]
        plane = lo[axis] if k % 2 == 0 else hi[axis]
        ca, cb = 0.5 * (lo[a] + hi[a]), 0.5 * (lo[b] + hi[b])
        ha, hb = 1.5 * (hi[a] - lo[a]), 1.5 * (hi[b] - lo[b])  # half sides of the grown face
        # the triangle (-2 ha, -hb), (2 ha, -hb), (0, 3 hb) about the centre holds the rectangle |u| <= ha, |v| <= hb
        corners = []
        for u, v in ((-2 * ha, -hb), (2 * ha, -hb), (0.0, 3 * hb)):
            x = [0.0, 0.0, 0.0]
            x[axis], x[a], x[b] = plane, ca + u, cb + v
            corners.append(tuple(x))
        walls.append(_utils.facet(corners, material=material, fixed=True))
    return walls


def sphere_ids():
    return [b.id for b in O.bodies if b is not None and isinstance(b.shape, _w.Sphere)]


def wall_ids():
    """{'left': id, ...} of the walls still present (boxes or facets)."""
    return {name: i for i, name in enumerate(WALLS) if i < len(O.bodies) and O.bodies[i] is not None
            and isinstance(O.bodies[i].shape, (_w.Box, _w.Facet))}


def wall_face(i, name):
    """The coordinate of wall ``name``'s (body ``i``) inner face along its axis: a box's face, a
    facet's plane."""
    b = O.bodies[i]
    axis = WALLS.index(name) // 2
    if isinstance(b.shape, _w.Facet):
        return b.state.pos[axis]
    return b.state.pos[axis] + (1 if WALLS.index(name) % 2 == 0 else -1) * b.shape.extents[axis]


def inner_box():
    """(lo, hi) of the space between the walls present (inner faces; None where a wall is gone)."""
    lo, hi = [None] * 3, [None] * 3
    for name, i in wall_ids().items():
        axis = WALLS.index(name) // 2
        (lo if WALLS.index(name) % 2 == 0 else hi)[axis] = wall_face(i, name)
    return lo, hi


def kinetic_energy():
    """Translational plus rotational kinetic energy of the particles (the scene's energy unit)."""
    e = 0.0
    for i in sphere_ids():
        s = O.bodies[i].state
        e += 0.5 * s.mass * s.vel.squaredNorm() + 0.5 * sum(s.inertia[k] * s.angVel[k] ** 2 for k in range(3))
    return e


def lens_volume(r1, r2, d):
    """Volume shared by two overlapping spheres (radii r1, r2, centres d apart)."""
    if d >= r1 + r2:
        return 0.0
    return math.pi * (r1 + r2 - d) ** 2 * (d * d + 2 * d * (r1 + r2) - 3 * (r1 - r2) ** 2) / (12 * d)


def _cap(r, h):
    """Volume of a sphere of radius r beyond a plane at distance h from its centre."""
    t = r - h
    return 0.0 if t <= 0 else math.pi * t * t * (3 * r - t) / 3


def energy_scale(n, protocol=None):
    """The elastic energy of a sintered sample of n particles, the scale of 'static': a contact
    force p d0^2 (p: protocol.reference_stress) on a spring kp stores (p d0^2)^2/(2 kp), about
    3 contacts per particle."""
    p = resolve(protocol)
    return 3 * n * (p.reference_stress * p.d0 * p.d0) ** 2 / (2 * p.kp)


def _extent(ids):
    """The walls' inner box; on an axis without walls, the particles' extent."""
    lo, hi = inner_box()
    for k in range(3):
        if lo[k] is None:
            lo[k] = min(O.bodies[i].state.pos[k] - O.bodies[i].shape.radius for i in ids)
        if hi[k] is None:
            hi[k] = max(O.bodies[i].state.pos[k] + O.bodies[i].shape.radius for i in ids)
    return lo, hi


def stats(protocol=None):
    """The state of the sample: solid fraction (sphere volume inside the walls' inner box, overlap
    lenses and wall caps subtracted, over the box volume; where the walls are gone, the particles'
    extent), coordination (2 x particle-particle contacts / N), coordination_with_walls,
    rattlers (particles with < 2 mechanical contacts, walls included), wall stresses
    (compressive > 0), side lengths, kinetic energy and its ratio to energy_scale()."""
    protocol = resolve(protocol)
    ids = set(sphere_ids())
    if not ids:
        raise ValueError("stats: the scene holds no particles")
    lo, hi = _extent(ids)
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
    for inter in O.interactions:
        if not inter.isReal or inter.geom.penetrationDepth <= 0:  # mechanical contacts only
            continue
        for j in (inter.id1, inter.id2):
            if j in contacts:
                contacts[j] += 1
        if inter.id1 in ids and inter.id2 in ids:
            pp += 1
            b1, b2 = O.bodies[inter.id1], O.bodies[inter.id2]
            vs -= lens_volume(b1.shape.radius, b2.shape.radius, (b1.state.pos - b2.state.pos).norm())
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
            "kinetic_energy_ratio": ke / energy_scale(len(ids), protocol), "iter": O.iter, "time": O.time}


def run_until_static(measure, stage, chunk=2000, max_steps=400000, progress=True):
    """Runs until ``measure()`` -> (static, text, value) says static on two consecutive checks,
    ``chunk`` steps apart; returns (steps, value). A RuntimeError naming the stage if not static
    after max_steps."""
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


def save_atomic(path, info):
    """O.save to ``path`` and the description to ``path + '.json'``, each written under a
    temporary name and renamed, the JSON last: a reader that finds the JSON finds both whole."""
    tmp = f"{path[:-len('.yade.gz')]}.tmp-{os.getpid()}-state.yade.gz"  # outputs.sweep knows the pattern
    O.save(tmp)
    os.replace(tmp, path)
    _outputs.write_atomic(path + ".json", json.dumps(info, indent=1))


def give_material(ids, mat):
    """Gives the bodies ``ids`` the material ``mat``; each of their contacts adopts it keeping its
    history (overlap, delta_max, springs): the force stays continuous."""
    ip2 = [e for e in O.engines if isinstance(e, _w.InteractionLoop)][0].physDispatcher.functors[0]
    for i in ids:
        O.bodies[i].material = mat
    for inter in {(j.id1, j.id2): j for i in ids for j in O.bodies[i].intrs() if j.isReal}.values():
        ip2.adoptMaterials(inter)


def make_adhesive_walls(wall_ids, protocol=None):
    """Gives these walls an adhesive law of their own, "loading walls" (the particles' law with
    kc = protocol.wall_kc_over_kp kp and friction coefficient wall_mu, ``dominant``), so that the
    other walls stay a smooth mould; every contact of these walls adopts it, keeping its history.
    Idempotent."""
    mats = [m for m in O.materials if m.label == "loading walls"]
    if mats:
        mat = mats[0]
    else:
        p = resolve(protocol)
        particles = [m for m in O.materials if m.label == "particles"][0]
        kw = {k: getattr(particles, k) for k in p.material if k != "label"}
        kw.update(kc=p.wall_kc_over_kp * p.kp, frictionAngle=math.atan(p.wall_mu), dominant=True,
                  label="loading walls")
        mat = _w.MesoMat(**kw)
        O.materials.append(mat)
    give_material(wall_ids, mat)
