"""Agglomerates carved out of a sintered bulk sample, and placed against each other (inside ``yade``).

From a sample of ``bulk.prepare`` (released, its walls still in place), ``carve`` keeps about
each given centre the particles that lie wholly within ``radius`` of it, with their contacts and
sintering history; everything else (and the walls) is erased, and the largest connected cluster
of each sphere is the agglomerate (particles cut loose are removed and counted). ``carve_pair``
carves two, about the centres of the two halves of the box along x (a box of two cubes, protocol
aspect (2, 1, 1), gives two equal spheres); ``relax`` brings the carved agglomerates to rest::

    from mesocontact.bulk import agglomerate
    O.load("released.yade.gz"); O.step()          # a step makes the contacts' geometry
    members, radius, loose = agglomerate.carve_pair(margin=0.5)
    agglomerate.relax(members)                    # lab-frame drag until E_kin < 1e-12 of the scale
    print([agglomerate.describe(m) for m in members])

An agglomerate is a list of body ids. Its radius R is that of the smallest sphere about its
centre of mass that holds all its particles (``outer_radius``: the first point another body can
touch, whatever the direction); the meso-overlap of two is delta = R1 + R2 - |x1 - x2| of their
centres of mass (``meso_overlap``). ``touch_shift``, ``move_to_gap`` and ``place_along`` move one
agglomerate against another by a translation (its contacts' history stays exact), along any
axis (``directions``: x, then directions drawn on the sphere). Lengths in units of d0 come from a
Protocol: the ``protocol`` argument, else the scene's (``bulk.sample.current()``). ``Watched``
reads two agglomerates every few steps (a collision's watcher) without checking them each time.
"""
import math
import numbers

try:
    from yade import O
    from yade import Vector3
    from yade import wrapper as _w
except ImportError as _exc:  # pragma: no cover - outside yade
    raise ImportError("mesocontact.bulk.agglomerate needs YADE: run it inside `yade`") from _exc

from .. import checks as _checks
from . import sample

X_AXIS = (1.0, 0.0, 0.0)


def _ids(name, ids):
    """``ids`` as a list, each an id of a body in the scene: a TypeError (not a sequence of
    integers) or ValueError (empty, or no such body) naming ``name``."""
    if isinstance(ids, (str, bytes, dict)):
        raise TypeError(f"{name} = {ids!r} is invalid: a sequence of body ids")
    try:
        items = list(ids)
    except TypeError:
        raise TypeError(f"{name} = {ids!r} is invalid: a sequence of body ids") from None
    if not items:
        raise ValueError(f"{name} = {ids!r} is invalid: at least one body id")
    n = len(O.bodies)
    for i in items:
        if isinstance(i, bool) or not isinstance(i, numbers.Integral):
            raise TypeError(f"{name} is invalid: body ids are integers ({i!r})")
        if not 0 <= i < n:
            raise ValueError(f"{name} is invalid: no body {i} in the scene")
    return items


def _bodies(name, ids):
    """The bodies ``ids`` (checked as _ids does, and present: none erased)."""
    items = _ids(name, ids)
    bodies = [O.bodies[i] for i in items]
    for i, b in zip(items, bodies):
        if b is None:
            raise ValueError(f"{name} is invalid: body {i} was erased")
    return bodies


def _members(name, members, count=None):
    """A sequence of agglomerates (each a sequence of body ids), ``count`` of them if given."""
    if isinstance(members, (str, bytes, dict)) or not hasattr(members, "__len__"):
        raise TypeError(f"{name} = {members!r} is invalid: a sequence of agglomerates (lists of body ids)")
    if count is not None and len(members) != count:
        raise ValueError(f"{name} is invalid: {count} agglomerates, not {len(members)}")
    if not len(members):
        raise ValueError(f"{name} is invalid: at least one agglomerate")
    for k, m in enumerate(members):
        for i, b in zip(m, _bodies(f"{name}[{k}]", m)):
            if b.isClump or b.isClumpMember:  # a clump moves as one rigid body: its primaries cannot be driven
                raise ValueError(f"{name}[{k}] is invalid: body {i} is a clump or one of its members; an "
                                 "agglomerate's primaries must move freely (O.bodies.releaseFromClump first)")


def _radii(name, radii, count):
    if isinstance(radii, (str, bytes, dict)) or not hasattr(radii, "__len__") or len(radii) != count:
        raise ValueError(f"{name} = {radii!r} is invalid: {count} radii")
    for k, r in enumerate(radii):
        _checks.positive(f"{name}[{k}]", r)


def _axis(axis):
    v = _checks.vector("axis", axis)
    if not any(v):
        raise ValueError(f"axis = {axis!r} is invalid: a nonzero vector")


def _whole(name, value, least=1):
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < least:
        raise ValueError(f"{name} = {value!r} is invalid: an integer >= {least}")


def clusters(ids):
    """The connected clusters of ``ids`` through contacts in overlap, largest first."""
    _ids("ids", ids)
    return _clusters(ids)


def _clusters(ids):
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


def _mass_weighted(bodies, attr):
    m, x = 0.0, Vector3(0, 0, 0)
    for b in bodies:
        s = b.state
        m += s.mass
        x += s.mass * getattr(s, attr)
    return x / m, m


def centre_of_mass(ids):
    """(centre of mass, mass) of the bodies ``ids``."""
    return _mass_weighted(_bodies("ids", ids), "pos")


def velocity(ids):
    """The velocity of the centre of mass of ``ids``."""
    return _mass_weighted(_bodies("ids", ids), "vel")[0]


def check_pair(members, radii):
    """Two agglomerates of bodies present and their two radii, checked before any work: a
    TypeError or ValueError naming ``members`` or ``radii``."""
    _members("members", members, 2)
    _radii("radii", radii, 2)


def meso_overlap(members, radii):
    """delta = R1 + R2 - |x1 - x2| of two agglomerates' centres of mass."""
    check_pair(members, radii)
    return _overlap([centre_of_mass(m)[0] for m in members], radii)


def _overlap(centres, radii):
    return radii[0] + radii[1] - (centres[0] - centres[1]).norm()


def joining(first, second):
    """The contacts in overlap that join a body of ``first`` to one of ``second``: an iterator of
    (interaction, whether its id2 is the body of ``second``)."""
    return _joining(_bodies("first", first), set(_ids("second", second)))


def _joining(first_bodies, other):
    """The contacts in overlap joining one of ``first_bodies`` to a body whose id is in ``other``."""
    for b in first_bodies:
        i = b.id
        for inter in b.intrs():
            j = inter.id2 if inter.id1 == i else inter.id1
            if j in other and inter.isReal and inter.geom.penetrationDepth > 0:
                yield inter, inter.id2 == j


class Watched:
    """Two agglomerates (``members``, ``radii``), checked once, read every few steps by a watcher
    (a collision's): centre_of_mass, velocity, meso_overlap and joining with the module functions'
    arithmetic, in the same order, without checking every id again at each call (in a collision's
    watcher the checks cost as much as the reading). The bodies must stay in the scene."""

    def __init__(self, members, radii):
        check_pair(members, radii)
        self.bodies = [[O.bodies[i] for i in m] for m in members]
        self.radii = list(radii)
        self._second = set(members[1])

    def centre_of_mass(self, k):
        """(centre of mass, mass) of agglomerate k (0 or 1)."""
        return _mass_weighted(self.bodies[k], "pos")

    def velocity(self, k):
        return _mass_weighted(self.bodies[k], "vel")[0]

    def meso_overlap(self):
        return _overlap([self.centre_of_mass(k)[0] for k in (0, 1)], self.radii)

    def joining(self):
        """As joining(first, second): (interaction, whether its id2 is the second's body)."""
        return _joining(self.bodies[0], self._second)


def contacts_between(first, second):
    """How many contacts in overlap join a body of ``first`` to one of ``second``."""
    return sum(1 for _ in joining(first, second))


def axis_frame(axis):
    """An orthonormal frame (axis, t1, t2) as rows; x's is the identity, so that x's arithmetic is
    exactly the coordinates' own."""
    _axis(axis)
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
    the distance at which they would touch (inf if no pair ever meets)."""
    _bodies("first", first)
    _bodies("second", second)
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
    """Moves the bodies ``ids`` by ``shift`` (a jump, not a motion: velocities and contacts' history
    stay), and has the collider sort again."""
    _bodies("ids", ids)
    _checks.vector("shift", shift)
    if not isinstance(shift, Vector3):
        shift = Vector3(*shift)
    for i in ids:
        O.bodies[i].state.pos += shift
    for e in O.engines:  # a jump the integrator did not make: the collider must sort again, or miss new pairs
        if isinstance(e, _w.InsertionSortCollider):
            e.doSort = True


def move_to_gap(first, second, gap, axis=X_AXIS):
    """Moves ``second`` along ``axis`` so that it touches ``first`` after moving ``gap`` (a length,
    the scene's units) towards it."""
    _bodies("first", first)
    _bodies("second", second)
    _checks.nonnegative("gap", gap)
    n = Vector3(*axis_frame(axis)[0])
    c = [centre_of_mass(m)[0].dot(n) for m in (first, second)]
    side = 1.0 if c[1] > c[0] else -1.0
    shift = touch_shift(first, second, axis)
    if not math.isfinite(shift):
        raise ValueError(f"second is invalid: seen along axis = {tuple(axis)!r} it never meets first")
    translate(second, n * (side * (gap - shift)))


def place_along(first, second, axis, radii, clearance=1.0, protocol=None):
    """Moves ``second`` (a translation: its contacts' history stays exact) so that its centre of
    mass lies from ``first``'s along ``axis``, its outer sphere (radii: R of each) ``clearance`` d0
    clear of the other's: the two then meet with other faces than along x."""
    _bodies("first", first)
    _bodies("second", second)
    _axis(axis)
    _radii("radii", radii, 2)
    _checks.nonnegative("clearance", clearance)
    d0 = sample.resolve(protocol).d0
    n = Vector3(*axis_frame(axis)[0])
    c = [centre_of_mass(m)[0] for m in (first, second)]
    translate(second, c[0] + n * (radii[0] + radii[1] + clearance * d0) - c[1])


def directions(count, seed=1):
    """``count`` approach directions: x (the pair as carved), then unit vectors drawn uniformly on
    the sphere (numpy's default_rng(seed))."""
    _whole("count", count)
    _whole("seed", seed, 0)
    import numpy as np
    rng = np.random.default_rng(seed)
    out = [X_AXIS]
    while len(out) < count:
        v = rng.normal(size=3)
        out.append(tuple(float(x) for x in v / np.linalg.norm(v)))
    return out


def outer_radius(ids, centre):
    """The radius of the smallest sphere about ``centre`` that holds every particle of ``ids``."""
    bodies = _bodies("ids", ids)
    _checks.vector("centre", centre)
    if not isinstance(centre, Vector3):
        centre = Vector3(*centre)
    return max((b.state.pos - centre).norm() + b.shape.radius for b in bodies)


def describe(ids, protocol=None):
    """An agglomerate's state: n, mass, centre of mass, radius R (outer_radius), solid fraction of
    its core (the sphere volume, contact lenses halved, of the particles whose centres lie within
    R - d0, over that sphere's volume), coordination (2 x contacts in overlap / n, its own
    particles), rattlers (particles with fewer than 2 contacts), the mean deltaMax of its
    contacts over their plastic limit."""
    _bodies("ids", ids)
    d0 = sample.resolve(protocol).d0
    ids = sorted(ids)
    own = set(ids)
    c, m = centre_of_mass(ids)
    radius = outer_radius(ids, c)
    core = radius - d0
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
    return {"n": len(ids), "mass": m, "centre": list(c), "radius": radius, "radius_d0": radius / d0,
            "solid_fraction_core": solid / (4.0 / 3.0 * math.pi * core ** 3) if core > 0 else None,
            "coordination": 2.0 * n_contacts / len(ids), "rattlers": sum(1 for k in count.values() if k < 2),
            "mean_depth": sum(depth) / len(depth) if depth else None}


def carve(centres, radius):
    """Keeps, about each of ``centres``, the largest connected cluster (contacts in overlap) of the
    particles wholly within ``radius`` of it; erases every other body (the walls too). Run it a
    step after loading a saved sample (the contacts' geometry is made by a step). Returns
    (members: the agglomerates' ids, one list per centre; how many particles the carving cut loose)."""
    if isinstance(centres, (str, bytes, dict)) or not hasattr(centres, "__len__") or not len(centres):
        raise ValueError(f"centres = {centres!r} is invalid: a sequence of points")
    for k, c in enumerate(centres):
        _checks.vector(f"centres[{k}]", c)
    _checks.positive("radius", radius)
    centres = [c if isinstance(c, Vector3) else Vector3(*c) for c in centres]
    inside = [[i for i in sample.sphere_ids()
               if (O.bodies[i].state.pos - c).norm() + O.bodies[i].shape.radius <= radius] for c in centres]
    for k, part in enumerate(inside):
        if not part:
            raise ValueError(f"radius = {radius!r} is invalid: no particle lies wholly within it of centres[{k}]")
    members = [_clusters(part)[0] for part in inside]
    loose = sum(len(part) for part in inside) - sum(len(m) for m in members)
    keep = set().union(*members)
    for b in list(O.bodies):
        if b is not None and b.id not in keep:
            O.bodies.erase(b.id)
    return members, loose


def carve_pair(radius=None, margin=0.5, protocol=None):
    """Two agglomerates carved (``carve``) about the centres of the two halves, along x, of the
    walls' inner box; ``radius`` defaults to the largest sphere that keeps ``margin`` d0 from the
    walls (their flat faces order the layers next to them). Returns (members, radius, loose)."""
    if radius is not None:
        _checks.positive("radius", radius)
    _checks.nonnegative("margin", margin)
    d0 = sample.resolve(protocol).d0
    lo, hi = sample.inner_box()
    if any(x is None for x in lo + hi):
        raise ValueError("this scene has not all six walls: carve_pair carves from a sample of bulk.prepare "
                         "(or pass centres and radius to carve)")
    sides = [hi[k] - lo[k] for k in range(3)]
    if radius is None:
        radius = min(sides[0] / 4, sides[1] / 2, sides[2] / 2) - margin * d0
        if not radius > 0:
            raise ValueError(f"margin = {margin!r} is invalid: it leaves no sphere in the box")
    centres = [Vector3(lo[0] + f * sides[0], lo[1] + sides[1] / 2, lo[2] + sides[2] / 2) for f in (0.25, 0.75)]
    members, loose = carve(centres, radius)
    return members, radius, loose


def relax(members, tol_ke=1e-12, max_steps=400000, progress=True, protocol=None):
    """Relaxes the carved agglomerates with the background drag in the lab frame until their
    kinetic energy is below ``tol_ke`` of the energy scale (bulk.sample.energy_scale of their
    particles), then sets the drag relative to each particle's contacts (as the tests have it: a
    part moving as a body is not dragged). The sintered sample's 'static' (1e-4) leaves the
    particles vibrating faster than a slow collision; 1e-12 is quiet at centimetres per second.
    Returns (steps, E_kin/E_ref)."""
    _members("members", members)
    _checks.positive("tol_ke", tol_ke)
    _whole("max_steps", max_steps)
    p = sample.resolve(protocol)
    O.engines = sample.engines(p, reference="lab")
    scale = sample.energy_scale(sum(len(m) for m in members), p)

    def measure():
        ke = sample.kinetic_energy() / scale
        return ke < tol_ke, f"E_kin/E_ref = {ke:.2e}", ke
    steps, ke = sample.run_until_static(measure, "carved agglomerates", max_steps=max_steps, progress=progress)
    for e in O.engines:
        if isinstance(e, _w.MesoBackgroundDamping):
            e.reference = "contacts"  # the tests': a part moving as a body is not dragged
    return steps, ke
