# ctest (inside yade): `MesoBackgroundDamping` relative to the contacts: no drag force or torque on
# a rigidly moving cluster or a layer moving with its wall (the lab-frame drag on them as a
# control), −γ_b w on a fluctuation, every body's drag against the reference motion written out
# independently, decay of velocity and spin fluctuations at γ_b/m and γ_br a²/I (the leapfrog
# factor), bad attributes rejected. Every check runs with the reference gathered by the law
# (`sumInLaw`, from the second step) and the drag equals the engine's own pass bitwise; a periodic
# lattice moving with the cell under a velocity gradient feels no drag (a neighbour across the
# boundary is its image: without the shift the boundary layer got 8 % of γ_b |∇v| L).
#
# MesoBackgroundDamping relative to the contacts damps fluctuations only.
# - a cluster moving as a rigid body (translation + rotation), and a layer moving with a wall,
#   feel no drag force or torque (to rounding), while the lab-frame drag on them is -gamma_b v;
# - a particle with a velocity fluctuation w among rigidly moving neighbours feels -gamma_b w,
#   and every body gets exactly the drag of the reference written out here independently;
# - a body without contacts feels nothing; bad attributes are rejected naming the attribute;
# - fluctuations decay at the rate gamma_b/m (gamma_br a^2/I for spin): the leapfrog factor
#   (1 - gamma dt/m)^N, within 1e-3 (the sandwich's contact force across the line of centres
#   stays below 1e-4 of the drag).
import math

import numpy as np
from yade import O, Matrix3, Vector3, utils
from yade import wrapper as w
from harness import check, finish


R, GB, GBR = 0.005, 2e-4, 5e-5  # the tablet's units: mm, us, mg
MAT = dict(density=2.0, k1=2.5, kp=5.0, kc=1.0, phiF=0.05, gammaN=5e-5, frictionAngle=0.5, kt=1.0, gammaT=1e-5,
           kr=0.5, gammaR=5e-6, muR=0.2, ko=0.5, gammaO=5e-6, muO=0.2)


def scene(positions, velocities, spins, reference, gamma_b, walls=(), mat=MAT, steps=1, sum_in_law=True):
    """Spheres (and boxes given as (centre, extents, velocity)), ``steps`` steps without
    NewtonIntegrator: the bodies stay put and O.forces holds the contact forces plus the drag (from
    the second step on, the drag's reference comes from the law's sums unless sum_in_law is off)."""
    O.reset()
    O.materials.append(w.MesoMat(**mat))
    ids = O.bodies.append([utils.sphere(tuple(x), R) for x in positions])
    for b, v, s in zip(ids, velocities, spins):
        O.bodies[b].state.vel = Vector3(*v)
        O.bodies[b].state.angVel = Vector3(*s)
    wall_ids = []
    for c, e, v in walls:
        wid = O.bodies.append(utils.box(c, e, fixed=True))
        O.bodies[wid].state.vel = Vector3(*v)
        wall_ids.append(wid)
    O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb(), w.Bo1_Box_Aabb()], verletDist=0),
                 w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom6D(), w.Ig2_Box_Sphere_ScGeom6D()],
                                   [w.Ip2_MesoMat_MesoMat_MesoPhys()], [w.Law2_ScGeom_MesoPhys_Meso()]),
                 w.MesoBackgroundDamping(gammaB=gamma_b, gammaBR=GBR if gamma_b else 0.0, reference=reference,
                                         sumInLaw=sum_in_law, label="drag")]
    O.dt = 1e-5
    for _ in range(steps - 1):
        O.step()
    # Without NewtonIntegrator YADE's forces add up over the steps: keep the last step's share.
    before = {b: (O.forces.f(b), O.forces.t(b)) for b in ids} if steps > 1 else {}
    O.step()
    for b, (f, t) in before.items():
        O.forces.addF(b, -f)
        O.forces.addT(b, -t)
    return ids, wall_ids


def drag(positions, velocities, spins, reference, walls=(), sum_in_law=True):
    """The drag force and torque on each sphere at the second step (the first whose reference the
    law can gather): the steps with the drag minus the same steps without."""
    out = []
    for g in (GB, 0.0):
        ids, _ = scene(positions, velocities, spins, reference, g, walls, steps=2, sum_in_law=sum_in_law)
        if g and reference == "contacts":
            used = O.engines[-1].lawSumSteps
            check(used == (1 if sum_in_law else 0), f"the reference came from the law's sums in {used} of 2 steps "
                  f"(sumInLaw={sum_in_law}: the first step sums in the engine)")
        out.append((np.array([list(O.forces.f(i)) for i in ids]), np.array([list(O.forces.t(i)) for i in ids])))
    return out[0][0] - out[1][0], out[0][1] - out[1][1]


# A 3x3x3 lattice of overlapping spheres (spacing 1.98 R), moving as a rigid body.
pos = np.array([(i, j, k) for i in range(3) for j in range(3) for k in range(3)], float) * 1.98 * R
centre = pos.mean(axis=0)
V, W = np.array([0.3, -0.2, 0.1]), np.array([20.0, -35.0, 50.0])  # mm/us, 1/us
vel = V + np.cross(W, pos - centre)
spin = np.tile(W, (len(pos), 1))
v_scale = np.abs(vel).max()
f, t = drag(pos, vel, spin, "contacts")
check(np.abs(f).max() <= 1e-12 * GB * v_scale,
      f"rigid cluster, drag vs contacts: |F| <= {np.abs(f).max():.1e} (gamma_b v = {GB * v_scale:.1e})")
check(np.abs(t).max() <= 1e-12 * GBR * R * R * np.abs(W).max(),
      f"rigid cluster, drag vs contacts: |T| <= {np.abs(t).max():.1e} (gamma_br a^2 "
      f"w = {GBR * R * R * np.abs(W).max():.1e})")
f, t = drag(pos, vel, spin, "lab")
check(np.abs(f + GB * vel).max() <= 1e-12 * GB * v_scale
      and np.abs(t + GBR * R * R * spin).max() <= 1e-12 * GBR * R * R * 50,
      "rigid cluster, lab-frame drag: F = -gamma_b v, T = -gamma_br a^2 w (the measurement sees a drag)")

# One particle (the centre, 13) with a fluctuation among the rigidly moving rest; the drag on
# every sphere against an independent evaluation of the reference motion of its contacts.
vel2, spin2 = vel.copy(), spin.copy()
fluct, fluct_w = np.array([0.05, 0.02, -0.04]), np.array([7.0, 0.0, -3.0])
vel2[13] += fluct
spin2[13] += fluct_w
f, t = drag(pos, vel2, spin2, "contacts")
check(np.abs(f[13] + GB * fluct).max() <= 1e-12 * GB * v_scale
      and np.abs(t[13] + GBR * R * R * fluct_w).max() <= 1e-12 * GBR * R * R * 50,
      f"fluctuating particle among rigid neighbours: F = -gamma_b w ({f[13]}), T = -gamma_br a^2 w_fluct")
worst = 0.0
for i in range(len(pos)):
    nb = [j for j in range(len(pos)) if j != i and np.linalg.norm(pos[i] - pos[j]) < 2 * R]
    w_ref = spin2[nb].mean(axis=0)
    v_ref = vel2[nb].mean(axis=0) + np.cross(w_ref, pos[i] - pos[nb].mean(axis=0))
    worst = max(worst, np.abs(f[i] + GB * (vel2[i] - v_ref)).max() / (GB * v_scale),
                np.abs(t[i] + GBR * R * R * (spin2[i] - w_ref)).max() / (GBR * R * R * 50))
check(worst <= 1e-12, f"every sphere: drag = -gamma (v - v_ref) of its contacts' rigid motion (worst {worst:.1e})")

# The law's sums against the engine's own pass (sumInLaw=False): the same arithmetic in the same
# order on one thread, so the drag is bitwise the same.
f_own, t_own = drag(pos, vel2, spin2, "contacts", sum_in_law=False)
check(np.array_equal(f, f_own) and np.array_equal(t, t_own),
      f"law's sums and the engine's pass give bitwise the same drag (largest difference {np.abs(f - f_own).max():.1e})")

# A layer of spheres resting on a wall and moving with it, and one sphere on its own.
layer = np.array([(i, 0.0, k) for i in range(3) for k in range(3)]) * 1.98 * R + np.array([0, R * 0.99, 0])
U = np.array([0.1, 0.0, -0.05])
wall = ((0.02, -0.5 * R, 0.02), (0.05, 0.5 * R, 0.05), tuple(U))
free = np.array([[0.0, 0.1, 0.0]])
f, t = drag(np.vstack([layer, free]), np.vstack([np.tile(U, (9, 1)), [[0.2, 0.1, 0.3]]]), np.zeros((10, 3)), "contacts",
            walls=(wall,))
check(np.abs(f[:9]).max() <= 1e-12 * GB * 0.1 and np.abs(t[:9]).max() <= 1e-12 * GBR * R * R,
      f"layer moving with its wall: no drag (|F| <= {np.abs(f[:9]).max():.1e})")
check(np.abs(f[9]).max() == 0 and np.abs(t[9]).max() == 0, "a sphere without contacts: no drag")
f_own, t_own = drag(np.vstack([layer, free]), np.vstack([np.tile(U, (9, 1)), [[0.2, 0.1, 0.3]]]), np.zeros((10, 3)),
                    "contacts",
                    walls=(wall,), sum_in_law=False)
check(np.array_equal(f, f_own) and np.array_equal(t, t_own),
      "with a wall: law's sums and the engine's pass bitwise the same")


# A periodic simple-cubic lattice (4^3, spacing 1.98 R) moving affinely with the cell under a
# velocity gradient: every sphere sees its six neighbours symmetrically, those across the
# boundary as images (velocity shifted by the cell), so the contacts' rigid motion at its centre
# is its own affine velocity and no sphere feels a drag. Summing the raw positions and velocities
# of the neighbours across the boundary (the error this checks) gives the boundary layer a drag
# of order gamma_b |grad v| L.
def periodic_drag(sum_in_law):
    out = []
    for g in (GB, 0.0):
        O.reset()
        O.periodic = True
        n, a = 4, 1.98 * R
        O.cell.setBox(n * a, n * a, n * a)
        grad = np.array([[0.0, 2.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, -1.0]])  # 1/us
        O.cell.velGrad = Matrix3(*grad.flatten())
        O.materials.append(w.MesoMat(**MAT))
        xs = [np.array((i + 0.5, j + 0.5, k + 0.5)) * a for i in range(n) for j in range(n) for k in range(n)]
        ids = O.bodies.append([utils.sphere(tuple(x), R) for x in xs])  # at rest: Newton's first step adds grad x
        O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb()], verletDist=0),
                     w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom6D()], [w.Ip2_MesoMat_MesoMat_MesoPhys()],
                                       [w.Law2_ScGeom_MesoPhys_Meso()]),
                     w.MesoBackgroundDamping(gammaB=g, gammaBR=GBR if g else 0.0, reference="contacts",
                                             sumInLaw=sum_in_law),
                     # it also updates the cell's velocity gradient, which the images' velocity uses
                     w.NewtonIntegrator(damping=0)]
        O.dt = 1e-5
        O.step()
        O.step()
        # velocities lead positions by half a step in the leapfrog: grad v dt/2 apart from grad x
        affine = max((O.bodies[b].state.vel - O.cell.velGrad * O.bodies[b].state.pos).norm() for b in ids)
        half = np.abs(grad).max() * max(O.bodies[b].state.vel.norm() for b in ids) * O.dt
        if g:
            check(affine <= half,
                  f"periodic lattice: every sphere at its affine velocity (within {affine:.1e} <= {half:.1e})")
            check(all(len(O.bodies[b].intrs()) == 6 for b in ids), "periodic lattice: six contacts per sphere")
        out.append(np.array([list(O.forces.f(b)) for b in ids]))
    return out[0] - out[1], GB * np.abs(grad).max() * n * a


for law in (True, False):
    f, scale = periodic_drag(law)
    check(np.abs(f).max() <= 1e-12 * scale, f"periodic lattice moving with the cell (sumInLaw={law}): no drag "
          f"(|F| <= {np.abs(f).max():.1e}; gamma_b |grad v| L = {scale:.1e})")


# Bad attributes are rejected, naming them: in the constructor and on assignment (where the
# engine keeps its previous value).
for attr, value in (("gammaB", -1.0), ("gammaB", math.inf), ("gammaBR", math.nan), ("reference", "walls")):
    try:
        w.MesoBackgroundDamping(**{attr: value})
        check(False, f"{attr} = {value!r} rejected by the constructor")
    except ValueError as e:
        check(attr in str(e) and "invalid" in str(e), f"{attr} = {value!r} rejected by the constructor: {e}")
    engine = w.MesoBackgroundDamping(gammaB=1.0, gammaBR=2.0, reference="contacts")
    try:
        setattr(engine, attr, value)
        check(False, f"{attr} = {value!r} rejected on assignment")
    except ValueError as e:
        kept = (engine.gammaB, engine.gammaBR, engine.reference) == (1.0, 2.0, "contacts")
        check(attr in str(e) and kept, f"{attr} = {value!r} rejected on assignment, the engine unchanged: {e}")

# Decay: a sphere held between two fixed spheres (overlap 1e-9 mm, no tangential mechanisms)
# moving across the line of centres and spinning about it, among neighbours at rest.
smooth = dict(MAT, kc=0.0, frictionAngle=0.0, kt=0.0, gammaT=0.0, kr=0.0, gammaR=0.0, muR=0.0, ko=0.0, gammaO=0.0,
              muO=0.0, gammaN=0.0)
gap = 2 * R - 1e-9
ids, _ = scene([(-gap, 0, 0), (0, 0, 0), (gap, 0, 0)], [(0, 0, 0), (0, 1e-4, 0), (0, 0, 0)],
               [(0, 0, 0), (30.0, 0, 0), (0, 0, 0)],
               "contacts", GB, mat=smooth)
for i in (ids[0], ids[2]):
    O.bodies[i].state.blockedDOFs = "xyzXYZ"
O.engines = O.engines + [w.NewtonIntegrator(damping=0)]
b = O.bodies[ids[1]].state
O.step()  # counted from the first step with NewtonIntegrator on
v0, w0 = b.vel[1], b.angVel[0]
n = 1000
O.run(n, True)
m, inertia = b.mass, b.inertia[0]
expect_v, expect_w = v0 * (1 - GB * O.dt / m) ** n, w0 * (1 - GBR * R * R * O.dt / inertia) ** n
rate_v = -math.log(b.vel[1] / v0) / (n * O.dt)
check(abs(b.vel[1] / expect_v - 1) < 1e-3,
      f"velocity fluctuation decays at gamma_b/m: rate {rate_v:.5g} (gamma_b/m = {GB / m:.5g}), "
      f"v/v_leapfrog - 1 = {b.vel[1] / expect_v - 1:.1e}")
check(abs(b.angVel[0] / expect_w - 1) < 1e-3,
      f"spin fluctuation decays at gamma_br a^2/I: w/w_leapfrog - 1 = {b.angVel[0] / expect_w - 1:.1e}")
check(b.vel[1] / v0 < 0.5, f"and it did decay (v/v0 = {b.vel[1] / v0:.3f})")

finish()
