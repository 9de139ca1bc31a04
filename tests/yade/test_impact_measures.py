# ctest (inside yade): bulk.impact against motions built by hand (a few seconds). Two clusters of
# spheres are given a rigid motion, v_i = V + w x (x_i - c) and every sphere's own spin w:
# rigid() recovers V and w (to rounding: 1e-12 of |w|), and its rotational energy, 0.5 w.I w,
# equals the particles' kinetic energy minus the centre's 0.5 M V^2, summed sphere by sphere
# (no inertia tensor involved). spin_measures' e_contact against the contact point's velocities
# written out (V + w x (p - c) of each cluster), e_rigid against the energies summed the same way,
# and a spin that vanishes leaves e_contact the centres' normal restitution. bonds() and broken():
# two touching spheres make one bond, which breaks when they are moved apart and a step is taken. A
# followed head-on collision of two single meso-particles: e is the closed form's, e_contact = e_rigid = e.
# A clump is refused as an agglomerate. closest_approach (fragments moving on rigidly): a passing
# sphere's smallest gap, an aimed one's touch, a spinning dumbbell sweeping a sphere, each by hand.
# agglomerate.Watched (what a collision reads every few steps) equals the module functions bit for bit.
import numpy as np
from yade import O, Vector3, utils
from yade import wrapper as w
from mesocontact.bulk import impact
from harness import check, finish

rng = np.random.default_rng(7)


def cluster(centre, n=12):
    ids = []
    for _ in range(n):
        x = np.asarray(centre) + rng.uniform(-1.0, 1.0, 3)
        ids.append(O.bodies.append(utils.sphere(tuple(x), rng.uniform(0.2, 0.4))))
    return ids


def give(ids, V, W):
    """A rigid motion about the cluster's centre of mass: v_i = V + W x (x_i - c), spin W."""
    m = np.array([O.bodies[i].state.mass for i in ids])
    x = np.array([list(O.bodies[i].state.pos) for i in ids])
    c = m @ x / m.sum()
    for i, xi in zip(ids, x):
        O.bodies[i].state.vel = Vector3(*(np.asarray(V) + np.cross(W, xi - c)))
        O.bodies[i].state.angVel = Vector3(*W)
    return c


def kinetic(ids):
    return sum(0.5 * O.bodies[i].state.mass * O.bodies[i].state.vel.squaredNorm()
               + 0.5 * O.bodies[i].state.inertia[0] * O.bodies[i].state.angVel.squaredNorm() for i in ids)


O.reset()
A, B = cluster((0, 0, 0)), cluster((3, 0.5, 0))
VA, WA = np.array([0.1, -0.2, 0.05]), np.array([0.3, -1.1, 0.7])
VB, WB = np.array([-0.4, 0.1, 0.0]), np.array([2.0, 0.4, -0.9])
cA, cB = give(A, VA, WA), give(B, VB, WB)
for ids, V, W, name in ((A, VA, WA, "A"), (B, VB, WB, "B")):
    mass, c, vc, wr, inertia = impact.rigid(ids)
    check(np.linalg.norm(vc - V) < 1e-12 * np.linalg.norm(V) and np.linalg.norm(wr - W) < 1e-12 * np.linalg.norm(W),
          f"rigid({name}): the built motion recovered", f"V off by {np.linalg.norm(vc - V):.1e}, "
          f"w off by {np.linalg.norm(wr - W):.1e} of |w| = {np.linalg.norm(W):.3f}")
    rot = kinetic(ids) - 0.5 * mass * V.dot(V)
    check(abs(0.5 * wr @ inertia @ wr - rot) < 1e-12 * rot,
          f"rigid({name}): 0.5 w.I w is the particles' kinetic energy about the centre",
          f"{0.5 * wr @ inertia @ wr:.12g} against {rot:.12g}")

p, n = np.array([1.5, 0.2, 0.1]), np.array([1.0, 0.3, -0.2])
dv0 = np.array([-0.8, 0.1, 0.05])
r = impact.spin_measures(A, B, tuple(n), tuple(p), tuple(dv0))
un = n / np.linalg.norm(n)
at = (VB + np.cross(WB, p - cB)) - (VA + np.cross(WA, p - cA))
check(abs(r["e_contact"] - (-at.dot(un) / dv0.dot(un))) < 1e-12,
      "e_contact: the contact point's normal velocity after over before", f"{r['e_contact']:.12f}")
mA, mB = (sum(O.bodies[i].state.mass for i in ids) for ids in (A, B))
mu = mA * mB / (mA + mB)
spin = kinetic(A) - 0.5 * mA * VA.dot(VA) + kinetic(B) - 0.5 * mB * VB.dot(VB)
rel = VB - VA
want = np.sqrt((0.5 * mu * rel.dot(rel) + spin) / (0.5 * mu * dv0.dot(dv0)))
share = spin / (0.5 * mu * dv0.dot(dv0))
check(abs(r["e_rigid"] - want) < 1e-12 * want and abs(r["spin_energy_share"] - share) < 1e-12 * share,
      "e_rigid: the rigid motion's energy after (summed sphere by sphere) over the impact's", f"{r['e_rigid']:.12f}")
give(A, VA, (0, 0, 0))
give(B, VB, (0, 0, 0))
r = impact.spin_measures(A, B, tuple(n), tuple(p), tuple(dv0))
check(abs(r["e_contact"] + rel.dot(un) / dv0.dot(un)) < 1e-12 and r["spin_energy_share"] < 1e-24,
      "without spin e_contact is the centres' normal restitution", f"{r['e_contact']:.12f} against "
      f"{-rel.dot(un) / dv0.dot(un):.12f}, spin's share {r['spin_energy_share']:.1e}")

O.reset()
O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb()]),
             w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom()], [w.Ip2_FrictMat_FrictMat_FrictPhys()],
                               [w.Law2_ScGeom_FrictPhys_CundallStrack()]),
             w.NewtonIntegrator()]
a = O.bodies.append(utils.sphere((0, 0, 0), 1.0))
b = O.bodies.append(utils.sphere((1.9, 0, 0), 1.0))
c = O.bodies.append(utils.sphere((10, 0, 0), 1.0))
O.dt = 1e-6
O.step()
bonds = impact.bonds([[a, c], [b]]) | impact.bonds([[a, b, c]])
check(bonds == {(a, b)}, "bonds: only the touching pair of one agglomerate", str(bonds))
check(impact.broken(bonds) == [], "broken: none while they touch")

# agglomerate.Watched (a collision's watcher: checked once) gives the module functions' values, bit for bit
from mesocontact.bulk import agglomerate  # noqa: E402
d = O.bodies.append(utils.sphere((0.5, 1.7, 0), 0.9))  # touches a (b touches a already)
O.bodies[b].state.vel, O.bodies[d].state.vel = Vector3(0.3, -0.1, 0.2), Vector3(-0.5, 0.4, 0.0)
O.step()
first, second = [a, c], [b, d]
watched = agglomerate.Watched([first, second], [1.5, 1.6])
pairs = [(i.id1, i.id2, on) for i, on in watched.joining()]
check(pairs == [(i.id1, i.id2, on) for i, on in agglomerate.joining(first, second)] and len(pairs) == 2,
      "Watched.joining: the same contacts as joining, in the same order", str(pairs))
check(watched.meso_overlap() == agglomerate.meso_overlap([first, second], [1.5, 1.6])
      and all(watched.velocity(k) == agglomerate.velocity(m)
              and watched.centre_of_mass(k) == agglomerate.centre_of_mass(m) for k, m in enumerate((first, second))),
      "Watched: meso_overlap, velocity and centre_of_mass equal the module functions'")
try:
    agglomerate.Watched([first, [b, 99]], [1.5, 1.6])
    refused = ""
except ValueError as exc:
    refused = str(exc)
check("members[1]" in refused, "Watched refuses a body that is not in the scene, naming members", refused)
O.bodies[b].state.pos = Vector3(2.5, 0, 0)
O.step()
check(impact.broken(bonds) == [(a, b)], "broken: the pair moved apart", str(impact.broken(bonds)))

# A followed collision of two single meso-particles head-on (bulk.collisions with follow): e of the
# centres is the closed form's (the pair's discretisation: 2000 steps per contact, equal to 6 digits here;
# 1e-3 allowed), and with no spin and the contact on the line of centres e_contact and e_rigid are e.
from mesocontact import pair, theory  # noqa: E402
from mesocontact.bulk import protocol  # noqa: E402
from mesocontact.bulk.collisions import Collision  # noqa: E402
mat = dict(density=2500.0, k1=1e3, kp=5e3, kc=1e3, phiF=0.1, gammaN=0.0, frictionAngle=0.0)
R, v = 1e-3, 0.05
pair.build(R, v, material=mat)
prot = protocol.Protocol.ratios(dict(mat, gammaN=1e-9), d0=2 * R, sinter=0.02)  # only its d0 and kp are read
r = Collision([[0], [1]], [R, R], protocol=prot).run(v, follow=3.0, progress=False)
m = 2500.0 * 4.0 / 3.0 * np.pi * R ** 3
want = theory.pair_collision(v, 1e3, 5e3, 1e3, 0.1, R, m / 2).e
check(abs(r["e"] - want) < 1e-3 and abs(r["e_contact"] - r["e"]) < 1e-9 and abs(r["e_rigid"] - r["e"]) < 1e-9,
      f"followed head-on pair: e {r['e']:.6f} (closed form {want:.6f}), e_contact {r['e_contact']:.6f}, "
      f"e_rigid {r['e_rigid']:.6f}")
check(r["final_gap_over_press"] > 3.0 and r["recontacts"] == 0 and r["bonds_before"] == 0,
      f"followed head-on pair: {r['final_gap_over_press']:.2f} presses apart, no re-contact, no bonds")
# receding head-on without spin: the closest the two will come is where they are now
check(r["recontact_ahead"] is False and abs(r["closest_gap_ahead_over_press"] / r["final_gap_over_press"] - 1) < 1e-12,
      "followed head-on pair: no re-contact ahead, the closest gap ahead is the final gap")

# A clump is refused as an agglomerate (its primaries move as one rigid body: cycles and collisions
# need them free), naming the argument; free spheres are taken.
from mesocontact.bulk import agglomerate  # noqa: E402
O.reset()
clump = O.bodies.appendClumped([utils.sphere((0, 0, 0), 1.0), utils.sphere((1.5, 0, 0), 1.0)])
free = O.bodies.append([utils.sphere((5, 0, 0), 1.0), utils.sphere((6.5, 0, 0), 1.0)])
try:
    agglomerate.check_pair([clump[1], free], [2.0, 2.0])
    refused = "no exception"
except ValueError as e:
    refused = str(e)
check(refused.startswith("members[0] is invalid") and "clump" in refused, "a clump refused as an agglomerate", refused)
# closest_approach: fragments moving on rigidly. (a) A sphere passing another at 3 between centres:
# the smallest gap 1, at t = 10, then the bounding spheres part for good; sampled in steps of 0.05
# r (a gap quadratic in t about its minimum: off by (0.05)^2/6 at most). (b) Aimed 0.5 off the
# line of centres: they touch when the centres are 2 apart, at t = 10 - sqrt(3.75), found within
# a step. (c) A dumbbell (spheres of 0.5 at +-2) spinning at 1 rad/s about its axis of symmetry's
# normal z sweeps a sphere of 0.5 at rest at (0, 2.8): its arm touches it where the centres are 1
# apart, sin(phi) = (4 + 7.84 - 1)/(2 x 2 x 2.8), at t = phi; not spinning, it never does.
O.reset()
a = O.bodies.append(utils.sphere((0, 0, 0), 1.0))
b = O.bodies.append(utils.sphere((10, 3, 0), 1.0))
O.bodies[b].state.vel = Vector3(-1, 0, 0)
g, t, parted = impact.closest_approach([a], [b], max_time=100.0)
check(abs(g - 1.0) < 1e-3 and abs(t - 10.0) < 0.05 and parted, "closest_approach: a passing sphere's smallest gap",
      f"gap {g:.6f} at t = {t:.4f}, parted {parted}")
O.bodies[b].state.pos = Vector3(1.5, 0, 0)  # overlapping now: touching at t = 0, whatever comes
g, t, parted = impact.closest_approach([a], [b], max_time=100.0)
check(abs(g + 0.5) < 1e-12 and t == 0.0 and not parted, "closest_approach: fragments touching now", f"gap {g:.3f}")
O.bodies[b].state.pos = Vector3(10, 0.5, 0)
g, t, parted = impact.closest_approach([a], [b], max_time=100.0)
check(g <= 0 and 0 <= t - (10 - 3.75 ** 0.5) <= 0.05 and not parted, "closest_approach: an aimed sphere touches",
      f"gap {g:.2e} at t = {t:.4f} (touch at {10 - 3.75 ** 0.5:.4f})")
O.reset()
arm = [O.bodies.append(utils.sphere((x, 0, 0), 0.5)) for x in (-2.0, 2.0)]
ball = O.bodies.append(utils.sphere((0, 2.8, 0), 0.5))
give(arm, (0, 0, 0), (0, 0, 1.0))
g, t, parted = impact.closest_approach(arm, [ball], max_time=10.0)
phi = np.arcsin((4 + 2.8 ** 2 - 1) / (2 * 2 * 2.8))
check(g <= 0 and 0 <= t - phi <= 0.0101 and not parted, "closest_approach: a spinning dumbbell's arm sweeps a sphere",
      f"touch at t = {t:.4f} (phi = {phi:.4f})")
give(arm, (0, 0, 0), (0, 0, 0.0))
g, t, parted = impact.closest_approach(arm, [ball], max_time=10.0)
check(abs(g - (np.hypot(2, 2.8) - 1)) < 1e-12, "closest_approach: the same dumbbell at rest never touches",
      f"gap {g:.6f}")
finish()
