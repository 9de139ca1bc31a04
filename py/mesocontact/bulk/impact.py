"""What a collision of two agglomerates did beyond their centres' rebound (inside ``yade``): the
rigid motion of a fragment (its spin included), restitution measured with that spin, and the
bonds (contacts in overlap) that broke.

A fragment is a list of body ids. Its rigid motion is that of a rigid body with the same mass,
centre of mass, linear and angular momentum: the inertia tensor about the centre of mass sums
each sphere's own inertia and m (|r|^2 I - r r^T); omega = I^-1 L. Two restitution measures
count the spin:

- ``e_contact``: the normal relative velocity at the contact point, omega x r included, after
  over before (the point and the normal are the collision's: the mean contact point and the
  direction of the normal forces' impulse). A glancing slide that sets the agglomerates spinning
  loses the normal velocity at the contact, not only the centres';
- ``e_rigid``: sqrt(the rigid motion's kinetic energy after (the centres' relative motion and the
  two spins) / the impact's kinetic energy): the share of the energy given back to rigid motion,
  whatever its direction.

``bonds(members)`` is the set of contacts in overlap within each agglomerate (id pairs);
``broken(before)``: those of them no longer in overlap. ``closest_approach``: whether two parted
fragments moving on rigidly would touch again (a slow collision's fragments part by little).
"""
try:
    from yade import O
except ImportError as _exc:  # pragma: no cover - outside yade
    raise ImportError("mesocontact.bulk.impact needs YADE: run it inside `yade`") from _exc

from .. import checks as _checks


def rigid(ids):
    """(mass, centre of mass, velocity, angular velocity omega, inertia tensor) of the bodies
    ``ids`` moving as one rigid body with their momenta (numpy arrays)."""
    import numpy as np
    s = [O.bodies[i].state for i in ids]
    m = np.array([b.mass for b in s])
    x = np.array([list(b.pos) for b in s])
    v = np.array([list(b.vel) for b in s])
    w = np.array([list(b.angVel) for b in s])
    own = np.array([b.inertia[0] for b in s])  # spheres: isotropic
    mass = m.sum()
    c, vc = m @ x / mass, m @ v / mass
    r, u = x - c, v - vc
    L = (m[:, None] * np.cross(r, u)).sum(axis=0) + (own[:, None] * w).sum(axis=0)
    inertia = (np.eye(3) * ((m * (r * r).sum(axis=1)).sum() + own.sum())
               - (m[:, None, None] * r[:, :, None] * r[:, None, :]).sum(axis=0))
    return mass, c, vc, np.linalg.solve(inertia, L), inertia


def spin_measures(first, second, normal, point, dv_before, impact_energy=None):
    """e_contact and e_rigid (see the module) of the fragments ``first`` and ``second`` (ids) after
    a collision that began with the relative velocity ``dv_before`` (second's minus first's) and no
    spin; ``point``: the contact point, ``normal``: the direction of the normal impulse
    (3-sequences); ``impact_energy``: the impact's kinetic energy of relative motion (default: 0.5
    mu |dv_before|^2 with the fragments' reduced mass; give the whole agglomerates' when mass broke
    off). Also the spins' share of the impact's energy and the two angular velocities."""
    import numpy as np
    n = np.asarray(normal, dtype=float)
    n /= np.linalg.norm(n)
    p = np.asarray(point, dtype=float)
    dv0 = np.asarray(dv_before, dtype=float)
    parts = [rigid(ids) for ids in (first, second)]
    at = [vc + np.cross(w, p - c) for _, c, vc, w, _ in parts]
    mu = parts[0][0] * parts[1][0] / (parts[0][0] + parts[1][0])
    rel = parts[1][2] - parts[0][2]
    spin = sum(0.5 * w @ inertia @ w for _, _, _, w, inertia in parts)
    impact = 0.5 * mu * dv0.dot(dv0) if impact_energy is None else float(impact_energy)
    return {"e_contact": float(-(at[1] - at[0]).dot(n) / dv0.dot(n)),
            "e_rigid": float(np.sqrt(max(0.5 * mu * rel.dot(rel) + spin, 0.0) / impact)),
            "spin_energy_share": float(spin / impact),
            "spin": [[float(x) for x in part[3]] for part in parts]}


def bonds(members):
    """The contacts in overlap within each agglomerate of ``members``: a set of (id1, id2)."""
    out = set()
    for m in members:
        own = set(m)
        for i in m:
            for inter in O.bodies[i].intrs():
                if (inter.id1 == i and inter.id2 in own and inter.isReal
                        and inter.geom.penetrationDepth > 0):
                    out.add((inter.id1, inter.id2))
    return out


def broken(before):
    """Of the bonds ``before`` (id pairs), those no longer in overlap."""
    out = []
    for i, j in before:
        inter = O.interactions[i, j] if O.interactions.has(i, j) else None  # erased: no longer even near
        if inter is None or not inter.isReal or inter.geom.penetrationDepth <= 0:
            out.append((i, j))
    return out


def _rotation(axis_angle):
    """The rotation matrix of the rotation vector ``axis_angle`` (Rodrigues)."""
    import numpy as np
    a = float(np.linalg.norm(axis_angle))
    if a == 0.0:
        return np.eye(3)
    k = axis_angle / a
    K = np.array([[0.0, -k[2], k[1]], [k[2], 0.0, -k[0]], [-k[1], k[0], 0.0]])
    return np.eye(3) + np.sin(a) * K + (1.0 - np.cos(a)) * K @ K


def closest_approach(first, second, max_time, resolution=0.05):
    """Whether two fragments (ids) that move on as rigid bodies from now would touch again: each
    torque-free (its momentum and angular momentum kept, omega = I(t)^-1 L as the body turns), no
    force between them. Followed until their bounding spheres (about each centre of mass, through
    its farthest surface) part for good, or ``max_time``; a step moves no surface point more than
    ``resolution`` of the smallest radius. Returns (smallest surface gap, its time, whether the
    bounding spheres parted): a gap <= 0 is a re-contact ahead."""
    import numpy as np
    _checks.positive("max_time", max_time)
    _checks.positive("resolution", resolution)
    parts = []
    for ids in (first, second):
        mass, c, vc, w, inertia = rigid(ids)
        x = np.array([list(O.bodies[i].state.pos) for i in ids]) - c
        rad = np.array([O.bodies[i].shape.radius for i in ids])
        parts.append({"c": c, "v": vc, "L": inertia @ w, "I0": inertia, "x0": x, "r": rad, "Q": np.eye(3),
                      "R": float((np.linalg.norm(x, axis=1) + rad).max())})
    reach = parts[0]["R"] + parts[1]["R"]
    u = parts[1]["v"] - parts[0]["v"]

    def gap(t):
        pos = [p["c"] + p["v"] * t + p["x0"] @ p["Q"].T for p in parts]
        return float((np.linalg.norm(pos[0][:, None, :] - pos[1][None, :, :], axis=2)
                      - parts[0]["r"][:, None] - parts[1]["r"][None, :]).min())

    def omega(p):
        return np.linalg.solve(p["Q"] @ p["I0"] @ p["Q"].T, p["L"])

    r_min = min(float(p["r"].min()) for p in parts)
    t, best = 0.0, (gap(0.0), 0.0)
    if best[0] <= 0:  # touching already
        return best[0], 0.0, False
    while t < max_time:
        d = parts[1]["c"] + parts[1]["v"] * t - parts[0]["c"] - parts[0]["v"] * t
        if np.linalg.norm(d) > reach and d.dot(u) >= 0:  # apart and receding: never again
            return best[0], best[1], True
        ws = [omega(p) for p in parts]
        speed = float(np.linalg.norm(u)) + sum(float(np.linalg.norm(w)) * p["R"] for w, p in zip(ws, parts))
        dt = min(resolution * r_min / speed if speed > 0 else max_time, max_time - t)
        for w, p in zip(ws, parts):
            p["Q"] = _rotation(w * dt) @ p["Q"]
        t += dt
        g = gap(t)
        if g < best[0]:
            best = (g, t)
        if g <= 0:
            return best[0], best[1], False
    return best[0], best[1], False
