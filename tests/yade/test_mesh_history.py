# ctest (inside yade; also run with -j2): a contact keeps its history across a mesh's edges and
# vertices (also run with two threads: `yade.mesh_history_j2`): a sphere pressed onto the limit
# branch and dragged over two coplanar facets, through the vertex of four and along a strip of 120
# feels the force one large facet gives at every step (to 1e-9 of the force), with one contact and
# no warning; a save and load 1.5 R from the facet that made the contact goes on bitwise
# (`MesoPhys.meshFacet`); a belt of facets carries the sphere as one large moving facet; a 174° fold
# crossed and back keeps one contact per face, none missing.
#
# A contact keeps its history across a mesh's edges and
# vertices (issue #57). A sphere is pressed onto the limit branch, partly unloaded, then dragged
# slowly (prescribed x, y velocity; z free under a constant force) over a floor of facets: across the
# diagonal two coplanar facets share (a geom.facetBox floor), and through the vertex four facets
# share. The same drag over one large facet is the reference: the contact force (normal and
# sliding, whose springs hold history too) must follow it step by step, to the rounding of a
# nearest point computed on another facet (1e-9 of the force), with one contact at every step and
# no warning. Before the fix the force jumped 66x the weight at the edge (a fresh contact on the
# loading branch). A save and load after the crossing goes on bitwise (MesoPhys.meshFacet saved).
import math

from yade import O, Vector3, utils
from yade import wrapper as w
from mesocontact import scene
from harness import check, finish, Stderr

R, RHO = 1e-3, 2000.0
MAT = dict(k1=100.0, kp=500.0, kc=100.0, phiF=0.1, gammaN=0.05, kt=50.0, frictionAngle=0.5, density=RHO)
L = 5 * R
PRESS, HOLD = 0.03, 0.01  # [N]: beyond k1 * deltaMaxP = 0.025 N (the limit branch), then unloaded
V_DRAG = 1e-2  # [m/s]: 0.1 R in about 400 steps (quasi-static: the same drag on one large facet is the reference)

diagonal = [[(-L, -L, 0), (L, -L, 0), (L, L, 0)], [(-L, -L, 0), (L, L, 0), (-L, L, 0)]]
four = [[(0, 0, 0), (L, -L, 0), (L, L, 0)], [(0, 0, 0), (L, L, 0), (-L, L, 0)],
        [(0, 0, 0), (-L, L, 0), (-L, -L, 0)], [(0, 0, 0), (-L, -L, 0), (L, -L, 0)]]
large = [[(-4 * L, -4 * L, 0), (4 * L, -4 * L, 0), (0, 4 * L, 0)]]
S = 0.1 * R  # a strip of small squares along x, each split on its diagonal: many hand-overs
strip = [t for k in range(-30, 30) for t in ([(k * S, -S, 0), ((k + 1) * S, -S, 0), ((k + 1) * S, S, 0)],
                                             [(k * S, -S, 0), ((k + 1) * S, S, 0), (k * S, S, 0)])]


def sphere_on(facets, centre, blocked):
    """A fresh scene: ``facets`` (vertex triples, fixed) and a sphere at ``centre`` with ``blocked``
    DOFs, YADE's facet functor replaced by set_detection(), the step 0.2 sqrt(m/kp). Returns the
    facets' ids, the sphere's id and body."""
    scene.reset()
    O.materials.append(w.MesoMat(**MAT))
    ids = [O.bodies.append(utils.facet(v, fixed=True, material=0)) for v in facets]
    ball = O.bodies.append(utils.sphere(centre, R, material=0))
    b = O.bodies[ball]
    b.state.blockedDOFs = blocked
    O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb(), w.Bo1_Facet_Aabb()], verletDist=0),
                 w.InteractionLoop([w.Ig2_Facet_Sphere_ScGeom()], [w.Ip2_MesoMat_MesoMat_MesoPhys()],
                                   [w.Law2_ScGeom_MesoPhys_Meso()]),
                 w.NewtonIntegrator(damping=0)]
    scene.set_detection()
    O.dt = 0.2 * math.sqrt(b.state.mass / MAT["kp"])
    return ids, ball, b


def drag(facets, start, direction, distance, save_at=None):
    """Forces on the sphere's contacts (x, y, z) at every step of the drag, the most facet contacts
    at one step, the facets the contact lay on (meshFacet), and the stderr of the run."""
    ids, ball, b = sphere_on(facets, (start[0], start[1], R), "xyXYZ")
    forces, most, seen = [], 0, set()
    with Stderr() as err:
        O.forces.setPermF(ball, (0, 0, -PRESS))
        O.run(600, True)
        O.forces.setPermF(ball, (0, 0, -HOLD))
        O.run(600, True)
        n = math.hypot(*direction)
        b.state.vel = (V_DRAG * direction[0] / n, V_DRAG * direction[1] / n, 0)
        steps = int(round(distance / V_DRAG / O.dt))
        for k in range(steps):
            if save_at is not None and k == save_at:
                O.saveTmp("mesh")
                O.loadTmp("mesh")
                O.forces.setPermF(ball, (0, 0, -HOLD))  # not saved with the scene
            O.step()
            real = [O.interactions[i, ball] for i in ids if O.interactions.has(i, ball)
                    and O.interactions[i, ball].isReal]
            most = max(most, len(real))
            f = [0.0, 0.0, 0.0]
            for i in real:
                seen.add(i.phys.meshFacet)
                t = i.phys.normalForce + i.phys.shearForce
                f = [f[j] + t[j] for j in range(3)]
            forces.append(f)
    return forces, most, seen, err.text


def largest_step(forces, j):
    return max(abs(forces[k + 1][j] - forces[k][j]) for k in range(len(forces) - 1))


# The strip's save comes when the contact lies 1.5 R from the facet that made it: beyond the
# sphere's bounds, so only the saved meshFacet (not a search from that facet) finds it again.
cases = (("edge (two coplanar facets)", diagonal, (0.1 * R, -0.1 * R), (-1, 1), 0.3 * R * math.sqrt(2), 0.5),
         ("vertex (four facets)", four, (0.2 * R, 0.1 * R), (-2, -1), 0.4 * R * math.sqrt(1.25), 0.5),
         ("strip (120 small facets)", strip, (-1.0 * R, 0.03 * R), (1, 0.02), 2.0 * R, 0.75))
for name, mesh, start, direction, distance, save_fraction in cases:
    f_mesh, most, seen, err = drag(mesh, start, direction, distance)
    f_ref, most_ref, _, err_ref = drag(large, start, direction, distance)
    check(most == 1 and most_ref == 1, f"{name}: one contact at every step", f"at most {most} (large facet {most_ref})")
    check(len(seen - {-1}) >= 1, f"{name}: the contact travelled to another facet (meshFacet)",
          f"{len(seen - {-1})} others")
    gap = max(math.dist(a, c) for a, c in zip(f_mesh, f_ref))
    check(gap <= 1e-9 * PRESS, f"{name}: the force follows the large facet's at every step",
          f"largest difference {gap:.3g} N")
    for j, axis in ((2, "normal (z)"), (0, "sliding (x)")):
        dm, dr = largest_step(f_mesh, j), largest_step(f_ref, j)
        print(f"   {name}: largest one-step change of the {axis} force {dm:.4g} N (one large facet {dr:.4g} N)")
    check("IGeomFunctor returned false" not in err and "WARNING" not in err, f"{name}: no warning", err.strip()[:300])
    # Saved and loaded after the crossing: bitwise the same continuation.
    f_saved, _, _, _ = drag(mesh, start, direction, distance, save_at=int(save_fraction * len(f_mesh)))
    check(f_saved == f_mesh, f"{name}: a save and load after the crossing goes on bitwise",
          f"largest difference {max(math.dist(a, c) for a, c in zip(f_saved, f_mesh)):.3g} N")


def belt(facets):
    """A sphere dragged 0.3 R in x over ``facets`` (from the fixed one onto the other: its contact
    walks), then all but the first moving along y at 1e-3 m/s (a belt) for 2000 steps: its y
    velocity, and whether its contact lies on another facet than the one that made it."""
    ids, ball, b = sphere_on(facets, (-0.1 * R, 0, R), "xXYZ")  # x prescribed, y and z free
    O.forces.setPermF(ball, (0, 0, -HOLD))
    O.run(1200, True)
    b.state.vel = (V_DRAG, 0, 0)
    O.run(int(0.3 * R / V_DRAG / O.dt), True)
    b.state.vel = (0, b.state.vel[1], b.state.vel[2])
    for f in ids[1:]:
        O.bodies[f].state.vel = (0, 1e-3, 0)
    O.run(2000, True)
    i = [i for i in b.intrs() if i.isReal][0]
    return b.state.vel[1], i.phys.meshFacet >= 0


# A contact that walked onto a moving facet moves with it (its velocity, not its first facet's).
half = [[(-4 * L, -4 * L, 0), (0, -4 * L, 0), (0, 4 * L, 0)], [(0, -4 * L, 0), (4 * L, -4 * L, 0), (0, 4 * L, 0)]]
still = [[(-4 * L, -4 * L, -L), (-3.9 * L, -4 * L, -L), (-3.9 * L, -3.9 * L, -L)]]  # a still facet far away
v_walked, walked = belt(half)
v_one, _ = belt(still + large)
check(walked and abs(v_walked - v_one) <= 1e-6 * abs(v_one),
      "a contact walked onto a moving facet is carried as by one large moving facet",
      f"y velocity {v_walked:.9g} m/s (one large facet {v_one:.9g} m/s)")


def fold(first, degrees=3.0):
    """A sphere dragged across a shallow concave fold (two facets at 180 - 2 x degrees, as the
    segments of a round die) and back: steps with two contacts lying on one facet, steps where a
    facet's interior is overlapped with no contact on it, the stderr."""
    t = math.tan(math.radians(degrees))
    tris = [[(0, -L, 0), (0, L, 0), (-L, 0, L * t)], [(0, L, 0), (0, -L, 0), (L, 0, L * t)]]
    tris = tris if first == 0 else tris[::-1]
    ids, ball, b = sphere_on(tris, (-0.3 * R, 0, R + 0.3 * R * t + 1e-6), "xyXYZ")
    doubled = uncovered = 0
    with Stderr() as err:
        O.forces.setPermF(ball, (0, 0, -PRESS))
        O.run(600, True)
        O.forces.setPermF(ball, (0, 0, -HOLD))
        O.run(600, True)
        n = int(0.6 * R / V_DRAG / O.dt)
        for k in range(2 * n):
            b.state.vel = (V_DRAG if k < n else -V_DRAG, 0, 0)
            c = Vector3(b.state.pos)  # where the step's contacts are computed (before the motion)
            O.step()
            on = [i.phys.meshFacet if i.phys.meshFacet >= 0 else i.id1
                  for i in (O.interactions[f, ball] for f in ids if O.interactions.has(f, ball)) if i.isReal]
            doubled += len(on) != len(set(on))
            for f, tri in zip(ids, tris):  # the centre over the facet's interior, overlapping it
                a, u, v = (Vector3(*x) for x in tri)
                nrm = (u - a).cross(v - a)
                nrm.normalize()
                q = c - nrm * nrm.dot(c - a)
                inside = all(((y - x).cross(q - x)).dot(nrm) > 1e-9 * R * R for x, y in ((a, u), (u, v), (v, a)))
                if inside and R - abs(nrm.dot(c - a)) > 1e-3 * R and f not in on:
                    uncovered += 1
                    print(f"   facet {f} overlapped {(R - abs(nrm.dot(c - a))) / R:.4g} R without a contact at "
                          f"step {k} of {2 * n}")
    return doubled, uncovered, err.text


for first in (0, 1):
    doubled, uncovered, err = fold(first)
    check(doubled == 0 and uncovered == 0,
          f"a shallow concave fold crossed and back (facet {first} of the smaller id): one contact per facet, "
          "none missing",
          f"{doubled} steps with two contacts on one facet, {uncovered} with a facet overlapped and no contact")
finish()
