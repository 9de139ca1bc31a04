"""The agglomerates: a block pressure-sintered as the tablet is, and two spheres carved from it
(inside ``yade``).

The block is sintered as the tablet is (the library's ``bulk.prepare`` with Appendix F's protocol
and the preparation the tablet study chose, ``primaries.protocol``: packed without friction,
sintered against six adhesive walls at d0 p_s/kp = 0.02, released to p_r/p_s = 1e-3) in a box of two
cubes side by side along x. Each cube's centre is the centre of one agglomerate: the particles that
lie wholly within ``radius`` of it (default: the largest sphere that keeps MARGIN = 0.5 d0 from the
block's walls, whose flat faces order the layers next to them) are kept with their contacts and
sintering history, everything else is erased, and the largest connected cluster of each sphere is
what the agglomerate is (particles cut loose by the carving are removed and counted). The two are
relaxed apart, with the background drag in the lab frame, until their kinetic energy is below 1e-12
of the sintered state's elastic energy scale (quiet for collisions at centimetres per second), and
saved with the drag relative to each particle's contacts (as the tablet's tests have it), with their
description:

    from mesostudies.agglomerate import make
    info = make.ensure("results/agglomerate", quick=True)   # made once, then loaded
    print(info["agglomerates"][0]["n"], info["agglomerates"][0]["radius"])

Each agglomerate's radius R is that of the smallest sphere about its centre of mass that holds
all its particles (the outer surface: the first point another body can touch, whatever the
direction); the meso-overlap of two is delta = R1 + R2 - |x1 - x2| of their centres of mass.
"""
import json
import math
import os
import time

from yade import O
from yade import Vector3
from yade import wrapper as _w

from mesocontact.bulk import sample
from mesocontact.bulk import sintering as _sintering
from . import primaries
from .primaries import D0, KP, SCALES

ASPECT = (2, 1, 1)   # two cubes along x
N_FULL = 5400        # about 600 primaries per agglomerate (the released block holds 1.4 per d0^3)
N_QUICK = 600        # about 45 per agglomerate, for the pipeline's test
MARGIN = 0.5         # d0 between a carved sphere and the block's walls: its particles' centres keep 1 d0,
#                      beyond the layer the flat wall orders (with 1 d0 the agglomerates held 419 and 431)


def path(outdir, stage, quick=False):
    return os.path.join(outdir, f"{stage}{'-quick' if quick else ''}.yade.gz")


def _block(outdir, quick, seed, progress):
    """The sintered, released block loaded into O (prepared first if ``outdir`` lacks it)."""
    p = path(outdir, "block", quick)
    n = N_QUICK if quick else N_FULL
    if os.path.exists(p) and os.path.exists(p + ".json"):
        with open(p + ".json") as f:
            info = json.load(f)
        built = info["built"]
        if (built["n"], built["seed"], built.get("aspect")) != (n, seed, list(ASPECT)):
            raise ValueError(f"{p} holds a block of {built['n']} particles, seed {built['seed']}, aspect "
                             f"{built.get('aspect')}: not the one asked for (use another output directory)")
        O.load(p)
        return info
    os.makedirs(outdir, exist_ok=True)
    if progress:
        print(f"preparing the sintered block {p} ({n} particles, sides {ASPECT})", flush=True)
    return _sintering.prepare(p, primaries.protocol(n, seed, ASPECT), progress)


def clusters(ids):
    """The connected clusters of ``ids`` through contacts in overlap, largest first."""
    ids = set(ids)
    links = {i: [] for i in ids}
    for i in ids:
        for inter in O.bodies[i].intrs():
            j = inter.id2 if inter.id1 == i else inter.id1
            if j in ids and inter.isReal and inter.geom.penetrationDepth > 0:
                links[i].append(j)
    seen, out = set(), []
    for i in sorted(ids):
        if i in seen:
            continue
        stack, part = [i], []
        seen.add(i)
        while stack:
            k = stack.pop()
            part.append(k)
            for j in links[k]:
                if j not in seen:
                    seen.add(j)
                    stack.append(j)
        out.append(sorted(part))
    return sorted(out, key=len, reverse=True)


def _mass_weighted(ids, attr):
    m, x = 0.0, Vector3(0, 0, 0)
    for i in ids:
        s = O.bodies[i].state
        m += s.mass
        x += s.mass * getattr(s, attr)
    return x / m, m


def centre_of_mass(ids):
    """(centre of mass, mass) of the bodies ``ids``."""
    return _mass_weighted(ids, "pos")


def velocity(ids):
    """The velocity of the centre of mass of ``ids``."""
    return _mass_weighted(ids, "vel")[0]


def meso_overlap(members, radii):
    """delta = R1 + R2 - |x1 - x2| of two agglomerates' centres of mass (the module's definition)."""
    c = [centre_of_mass(m)[0] for m in members]
    return radii[0] + radii[1] - (c[0] - c[1]).norm()


def joining(first, second):
    """The contacts in overlap that join a body of ``first`` to one of ``second``: (interaction,
    whether its id2 is the body of ``second``)."""
    other = set(second)
    for i in first:
        for inter in O.bodies[i].intrs():
            j = inter.id2 if inter.id1 == i else inter.id1
            if j in other and inter.isReal and inter.geom.penetrationDepth > 0:
                yield inter, inter.id2 == j


def contacts_between(first, second):
    """How many contacts in overlap join a body of ``first`` to one of ``second``."""
    return sum(1 for _ in joining(first, second))


X_AXIS = (1.0, 0.0, 0.0)


def axis_frame(axis):
    """An orthonormal frame (axis, t1, t2) as rows; x's is the identity, so that x's arithmetic is
    exactly the coordinates' own."""
    import numpy as np
    n = np.array(axis, dtype=float)
    n /= np.linalg.norm(n)
    if tuple(n) == X_AXIS:
        return np.eye(3)
    t1 = np.cross(n, [0.0, 0.0, 1.0] if abs(n[2]) < 0.9 else [1.0, 0.0, 0.0])
    t1 /= np.linalg.norm(t1)
    return np.array([n, t1, np.cross(n, t1)])


def touch_shift(first, second, axis=X_AXIS):
    """How far ``second`` must move along ``axis`` towards ``first`` until a particle of one first
    touches a particle of the other (the agglomerates' surfaces, not their outer spheres): the
    smallest, over pairs less than r_i + r_j apart sideways, of their distance along the axis minus
    the distance at which they would touch."""
    import numpy as np
    frame = axis_frame(axis)
    pos = [np.array([list(O.bodies[i].state.pos) for i in ids]) @ frame.T for ids in (first, second)]
    rad = [np.array([O.bodies[i].shape.radius for i in ids]) for ids in (first, second)]
    side = 1.0 if pos[1][:, 0].mean() > pos[0][:, 0].mean() else -1.0
    best = np.inf
    for p, r in zip(pos[0], rad[0]):
        lateral = np.hypot(pos[1][:, 1] - p[1], pos[1][:, 2] - p[2])
        reach = r + rad[1]
        near = lateral < reach
        if near.any():
            gap = side * (pos[1][near, 0] - p[0]) - np.sqrt(reach[near] ** 2 - lateral[near] ** 2)
            best = min(best, float(gap.min()))
    return best


def translate(ids, shift):
    for i in ids:
        O.bodies[i].state.pos += shift
    for e in O.engines:  # a jump the integrator did not make: the collider must sort again, or miss new pairs
        if isinstance(e, _w.InsertionSortCollider):
            e.doSort = True


def move_to_gap(first, second, gap, axis=X_AXIS):
    """Moves ``second`` along ``axis`` so that it touches ``first`` after moving ``gap`` [mm] towards it."""
    n = Vector3(*axis_frame(axis)[0])
    c = [centre_of_mass(m)[0].dot(n) for m in (first, second)]
    side = 1.0 if c[1] > c[0] else -1.0
    translate(second, n * (side * (gap - touch_shift(first, second, axis))))


def place_along(first, second, axis, radii):
    """Moves ``second`` (a translation: its contacts' history stays exact) so that its centre of
    mass lies from ``first``'s along ``axis``, its outer sphere 1 d0 clear of the other's: the two
    then meet with other faces than along x."""
    n = Vector3(*axis_frame(axis)[0])
    c = [centre_of_mass(m)[0] for m in (first, second)]
    translate(second, c[0] + n * (radii[0] + radii[1] + D0) - c[1])


def directions(count, seed=1):
    """``count`` approach directions: x (the pair as carved), then unit vectors drawn uniformly on
    the sphere (numpy's default_rng(seed))."""
    import numpy as np
    rng = np.random.default_rng(seed)
    out = [X_AXIS]
    while len(out) < count:
        v = rng.normal(size=3)
        out.append(tuple(float(x) for x in v / np.linalg.norm(v)))
    return out


def outer_radius(ids, centre):
    return max((O.bodies[i].state.pos - centre).norm() + O.bodies[i].shape.radius for i in ids)


def describe(ids):
    """An agglomerate's state: n, mass, centre of mass, radius R (outer_radius), solid fraction of
    its core (the sphere volume, contact lenses halved, of the particles whose centres lie within
    R - d0, over that sphere's volume), coordination (2 x contacts in overlap / n, its own
    particles), rattlers (particles with fewer than 2 contacts), the mean deltaMax of its
    contacts over their plastic limit."""
    ids = sorted(ids)
    own = set(ids)
    c, m = centre_of_mass(ids)
    radius = outer_radius(ids, c)
    core = radius - D0
    count = dict.fromkeys(ids, 0)
    solid, depth, n_contacts = 0.0, [], 0
    for i in ids:
        b = O.bodies[i]
        inside = (b.state.pos - c).norm() <= core
        if inside:
            solid += 4.0 / 3.0 * math.pi * b.shape.radius ** 3
        for inter in b.intrs():
            j = inter.id2 if inter.id1 == i else inter.id1
            if j not in own or not inter.isReal or inter.geom.penetrationDepth <= 0:
                continue
            count[i] += 1
            if inside:
                other = O.bodies[j]
                solid -= 0.5 * sample.lens_volume(b.shape.radius, other.shape.radius,
                                                  (b.state.pos - other.state.pos).norm())
            if i < j:
                n_contacts += 1
                dmp = inter.phys.deltaMaxP if hasattr(inter.phys, "deltaMaxP") else None
                if dmp:
                    depth.append(inter.phys.deltaMax / dmp)
    return {"n": len(ids), "mass": m, "centre": list(c), "radius": radius, "radius_d0": radius / D0,
            "solid_fraction_core": solid / (4.0 / 3.0 * math.pi * core ** 3),
            "coordination": 2.0 * n_contacts / len(ids), "rattlers": sum(1 for k in count.values() if k < 2),
            "mean_depth": sum(depth) / len(depth) if depth else None}


def _carve(radius, margin):
    """Keeps, about each cube's centre, the largest connected cluster of the particles wholly
    within ``radius``; erases the rest and the walls. Returns (members, carved radius, removed)."""
    lo, hi = sample.inner_box()
    sides = [hi[k] - lo[k] for k in range(3)]
    if radius is None:
        radius = min(sides[0] / 4, sides[1] / 2, sides[2] / 2) - margin * D0
    centres = [Vector3(lo[0] + f * sides[0], lo[1] + sides[1] / 2, lo[2] + sides[2] / 2) for f in (0.25, 0.75)]
    inside = [[i for i in sample.sphere_ids()
               if (O.bodies[i].state.pos - c).norm() + O.bodies[i].shape.radius <= radius] for c in centres]
    members = [clusters(part)[0] for part in inside]
    loose = sum(len(part) for part in inside) - sum(len(m) for m in members)
    keep = set(members[0]) | set(members[1])
    for b in list(O.bodies):
        if b is not None and b.id not in keep:
            O.bodies.erase(b.id)
    return members, radius, loose


def ensure(outdir, quick=False, seed=1, radius=None, progress=True, tol_ke=1e-12, max_steps=400000):
    """The carved, relaxed pair of agglomerates loaded into O (made first, from the block, if
    ``outdir`` lacks it); returns its description ('agglomerates': describe() of each, 'members':
    their ids, 'block': the block's description, 'carve_radius', 'removed_loose')."""
    p = path(outdir, "agglomerates", quick)
    if os.path.exists(p) and os.path.exists(p + ".json"):
        with open(p + ".json") as f:
            info = json.load(f)
        O.load(p)
        return info
    t0 = time.time()
    block = _block(outdir, quick, seed, progress)
    O.step()  # a loaded state's contact geometry (penetrationDepth) is made by a step: carve after one, either way
    members, r_carve, loose = _carve(radius, MARGIN)
    # Quiet enough for the slowest collision: the tablet's "static" (1e-4 of the sintering's
    # elastic energy) leaves the particles a few m/s of vibration; the lab-frame drag takes it out.
    O.engines = sample.engines(SCALES, reference="lab")
    scale = sample.energy_scale(len(members[0]) + len(members[1]), SCALES)

    def measure():
        ke = sample.kinetic_energy() / scale
        return ke < tol_ke, f"E_kin/E_ref = {ke:.2e}", ke
    steps, ke = sample.run_until_static(measure, "carved agglomerates", max_steps=max_steps, progress=progress)
    for e in O.engines:
        if isinstance(e, _w.MesoBackgroundDamping):
            e.reference = "contacts"  # the tests': a part moving as a body is not dragged
    info = {"block": block, "carve_radius": r_carve, "carve_radius_d0": r_carve / D0,
            "removed_loose": loose, "relax_steps": steps, "kinetic_energy_ratio": ke,
            "members": members, "agglomerates": [describe(m) for m in members],
            "definitions": {"radius": "smallest sphere about the centre of mass holding every particle",
                            "delta": "R1 + R2 - |x1 - x2| of the centres of mass"},
            "units": "mm, us, mg", "d0": D0, "kp": KP, "wall_clock_s": time.time() - t0}
    sample.save_atomic(p, info)
    if progress:
        for k, a in enumerate(info["agglomerates"]):
            print(f"agglomerate {k}: {a['n']} particles, R = {a['radius_d0']:.3f} d0, solid fraction "
                  f"{a['solid_fraction_core']:.3f}, coordination {a['coordination']:.2f}, rattlers {a['rattlers']}",
                  flush=True)
    return info
