# ctest (inside yade): oblique sphere-wall impacts against the analytic stick and slide limits,
# and a rigid rotation of a stuck pair without spurious tangential force or torque.
#
# Elastic normal law (kp = k1, no adhesion, no damping) and kt = 2/7 k1: the tangential spring,
# which drags translation and rotation (effective mass 2/7 m), then oscillates at the normal
# frequency, so |f_t|/f_n stays constant during the impact:
# - stick (mu >= (kt/k1)(v_t/v_n)): the contact-point tangential velocity is exactly reversed;
# - slide (v_t >> v_n): the tangential impulse is mu (1 + e_n) m v_n with e_n = 1.
import math

from yade import O, Vector3
from mesocontact import pair, params
from harness import failures, finish

r, k1 = 1e-3, 1e4
m = params.sphere_mass(r, 2000)
kt = 2.0 / 7.0 * k1


def impact(vn, vt, mu):
    mat = dict(k1=k1, kp=k1, kc=0.0, phiF=0.5, kt=kt, frictionAngle=math.atan(mu))
    s = pair.build_wall(r, vn, mat, kind="box", tangential_velocity=(vt, 0, 0), steps_per_contact=4000)
    res = pair.collide(s, max_contact_times=5)
    b = O.bodies[s.ids[1]].state
    return res, b.vel, b.angVel


# stick: ratio (kt/k1)(vt/vn) = 2/7 * 1 < mu = 0.5
vn, vt = 0.02, 0.02
res, vel, w = impact(vn, vt, 0.5)
vc = vel[0] - r * w[1]  # contact-point velocity along x (w about y; contact point below the centre)
err_stick = abs(vc - (-vt)) / vt
ok = not res.stuck and err_stick <= 1e-3 and abs(res.e - 1) < 1e-3
print(("ok   " if ok else "FAIL ")
      + f"stick: contact-point velocity {vt:.4f} -> {vc:.6f} (analytic {-vt}), rel. error "
        f"{err_stick:.1e}; e_n = {res.e:.6f}")
if not ok:
    failures.append("stick")

# slide: vt = 20 vn, mu = 0.1 -> slides throughout; impulse mu (1 + 1) m vn
vn, vt, mu = 0.02, 0.4, 0.1
res, vel, w = impact(vn, vt, mu)
dv = vt - vel[0]
dv_th = mu * 2 * vn
err_slide = abs(dv - dv_th) / dv_th
dw_th = dv_th * m * r / (0.4 * m * r * r)  # spin-up by the same impulse at arm a (a - delta/2 ~ a)
err_spin = abs(w[1] - dw_th) / dw_th  # friction below the centre spins it up about +y
ok = err_slide <= 1e-3 and err_spin <= 2e-3
print(("ok   " if ok else "FAIL ")
      + f"slide: tangential velocity loss {dv:.6e} (analytic mu (1+e) v_n = {dv_th:.6e}), rel. error {err_slide:.1e}; "
      f"spin-up rel. error {err_spin:.1e}")
if not ok:
    failures.append("slide")

# rigid rotation of a stuck sphere-sphere pair held by adhesion (ScGeom6D: all mechanisms on).
# Rolling and torsion see w1 - w2 = 0 exactly. Sliding sees only a physical effect: the
# centrifugal force stretches the contact, the orbital angular velocity then lags the spin
# (angular momentum), and the contact slides a little; over one radian that force grows as w^2.
# A kinematic error (a spring not following the frame, a wrong arm) would not fall with w.
from yade import wrapper as wr  # noqa: E402

mat = dict(k1=1e3, kp=5e3, kc=1e3, phiF=0.1, fa=1e-3, kca=1e3, adhesion="jumpIn", gammaN=0.1, kt=400.0, gammaT=0.02,
           kr=200.0, gammaR=0.01, muR=0.2, ko=200.0, gammaO=0.01, muO=0.2, frictionAngle=0.5)


def rigid_rotation(steps_per_contact, rate):
    s = pair.build(r, 0.05, mat, steps_per_contact=steps_per_contact)
    f = O.engines[2].geomDispatcher.functors[0]
    O.engines[2].geomDispatcher.functors = [
        wr.Ig2_Sphere_Sphere_ScGeom6D(interactionDetectionFactor=f.interactionDetectionFactor)]
    O.run(int(100 * s.contact_time / O.dt), True)
    i = O.interactions[s.ids[0], s.ids[1]]
    b1, b2 = O.bodies[s.ids[0]].state, O.bodies[s.ids[1]].state
    at_rest = b1.vel.norm() + b2.vel.norm() < 1e-8 and i.isReal and isinstance(i.geom, wr.ScGeom6D)
    level = i.phys.coulombLevel  # f_h + f_v + kc delta (test_sliding_limit checks it)
    omega = Vector3(0.3, -0.5, 0.8) * rate  # rad/s, about an axis oblique to the normal
    c = 0.5 * (b1.pos + b2.pos)
    for b in (b1, b2):
        b.angVel = omega
        b.vel = omega.cross(b.pos - c)
    worst = [0.0, 0.0, 0.0]
    for _ in range(int(1.0 / (omega.norm() * O.dt))):  # one radian
        O.step()
        worst = [max(worst[0], i.phys.shearForce.norm()), max(worst[1], i.phys.rollingForce.norm()),
                 max(worst[2], abs(i.phys.torsionForce))]
    return at_rest, level, worst


at_rest, level, fast = rigid_rotation(400, 20.0)
_, _, slow = rigid_rotation(400, 10.0)
_, _, fine = rigid_rotation(800, 20.0)
ratio = fast[0] / slow[0] if slow[0] > 0 else math.inf
ok = at_rest and fast[0] <= 1e-3 * level and fast[1] == 0 and fast[2] == 0 and ratio > 3.5 \
    and abs(fine[0] - fast[0]) <= 0.05 * fast[0]
print(("ok   " if ok else "FAIL ")
      + f"rigid rotation by 1 rad of a stuck pair (at rest before: {at_rest}): max |f_t| = {fast[0]:.2e} N = "
      f"{fast[0] / level:.1e} of the Coulomb level at |w| = {Vector3(0.3, -0.5, 0.8).norm() * 20:.1f} rad/s; "
      f"{slow[0]:.2e} N at half the rate (ratio {ratio:.2f}, centrifugal ~ w^2), {fine[0]:.2e} N with dt/2; "
      f"max |f_r| = {fast[1]:.1e}, |f_o| = {fast[2]:.1e}")
if not ok:
    failures.append("rigid rotation")
finish()
