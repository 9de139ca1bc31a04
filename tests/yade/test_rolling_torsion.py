# ctest (inside yade): a sphere on an adhesive wall (box, ScGeom6D), held by fa and kc.
# (a) spinning about the normal, it stops with the constant deceleration a' mu_o level / I;
# (b) rolling, with v' = -a' (a' mu_r level)/(I + m a'^2) (sliding sticks, rolling slips);
# (c) below the limits, a constant applied torque T is balanced at the angle T/(k a'^2) for
#     rolling (kr) and torsion (ko): the spring torques at small angles.
# level = f_n + kc delta; a' = a - delta/2 is the lever arm against a wall ('reduced').
import math

from yade import O, wrapper as w
from mesocontact import pair, params
from harness import failures, finish

r = 1e-3
m = params.sphere_mass(r, 2000)
I = 0.4 * m * r * r
mat = dict(k1=1e3, kp=5e3, kc=1e3, phiF=0.1, fa=2e-3, kca=1e3, adhesion="jumpIn", gammaN=0.1,
           kt=2e3, gammaT=0.05, frictionAngle=math.atan(2.0), kr=200.0, gammaR=0.01, muR=0.05, ko=200.0,
           gammaO=0.01, muO=0.08, phiD=0.9)


def settled():
    s = pair.build_wall(r, 0.05, mat, kind="box", six_d=True, steps_per_contact=200)
    O.engines = O.engines[:-1] + [w.MesoBackgroundDamping(gammaB=0.0, gammaBR=0.0)] + O.engines[-1:]
    O.run(int(150 * s.contact_time / O.dt), True)
    i = O.interactions[s.ids[0], s.ids[1]]
    b = O.bodies[s.ids[1]].state
    assert b.vel.norm() < 1e-8 and isinstance(i.geom, w.ScGeom6D), "not settled on the wall"
    return s, i, b


def level_of(i):
    return i.phys.coulombLevel  # f_h + f_v + kc delta (test_sliding_limit checks it)


def fit_slope(ts, ys):
    n = len(ts)
    mt, my = sum(ts) / n, sum(ys) / n
    return sum((t - mt) * (y - my) for t, y in zip(ts, ys)) / sum((t - mt) ** 2 for t in ts)


def record(fn, steps, every=10):
    ts, ys = [], []
    for k in range(steps):
        O.step()
        if k % every == 0:
            ts.append(O.time)
            ys.append(fn())
    return ts, ys


# (a) spin
s, i, b = settled()
b.angVel = (0, 0, 400.0)  # stops after ~7000 steps
O.run(100, True)  # the torsion spring reaches its limit
lv, arm = level_of(i), r - 0.5 * i.geom.penetrationDepth
ts, ys = record(lambda: b.angVel[2], 3000)
alpha = -fit_slope(ts, ys)
alpha_th = arm * mat["phiD"] * mat["muO"] * lv / I
err = abs(alpha - alpha_th) / alpha_th
ok = err <= 1e-3 and b.angVel[2] > 0
print(("ok   " if ok else "FAIL ")
      + f"spin: deceleration {alpha:.6e} rad/s2, a' mu_o,d level / I = {alpha_th:.6e}, rel. error {err:.1e}",
      flush=True)
if not ok:
    failures.append("spin")

# (b) rolling without sliding
s, i, b = settled()
arm = r - 0.5 * i.geom.penetrationDepth
v0 = 0.05
b.vel = (v0, 0, 0)
b.angVel = (0, v0 / arm, 0)
O.run(300, True)
lv, arm = level_of(i), r - 0.5 * i.geom.penetrationDepth
ts, ys = record(lambda: b.vel[0], 3000)
acc = -fit_slope(ts, ys)
acc_th = arm * (arm * mat["phiD"] * mat["muR"] * lv) / (I + m * arm * arm)
err = abs(acc - acc_th) / acc_th
slip = abs(b.vel[0] - arm * b.angVel[1]) / b.vel[0]
ok = err <= 1e-3 and slip < 1e-3
print(("ok   " if ok else "FAIL ")
      + f"rolling: deceleration {acc:.6e} m/s2, analytic {acc_th:.6e}, rel. error {err:.1e}; "
      f"contact-point slip / v = {slip:.1e}", flush=True)
if not ok:
    failures.append("rolling")

# (c) spring torques at small angles
for label, axis, k_spring, mu in (("rolling", 1, mat["kr"], mat["muR"]), ("torsion", 2, mat["ko"], mat["muO"])):
    s, i, b = settled()
    arm, lv = r - 0.5 * i.geom.penetrationDepth, level_of(i)
    T = 0.3 * arm * mu * lv  # 30 % of the limit torque
    moment = [0.0, 0.0, 0.0]
    moment[axis] = T
    O.engines = O.engines[:-1] + [w.TorqueEngine(ids=[s.ids[1]], moment=moment)] + O.engines[-1:]
    for e in O.engines:
        if isinstance(e, w.MesoBackgroundDamping):
            e.gammaB, e.gammaBR = 0.05, 0.05  # settle the rocking quickly
    O.run(60000, True)
    aa = b.ori.toAxisAngle()
    theta = aa[1] * aa[0][axis]
    arm = r - 0.5 * i.geom.penetrationDepth
    T_spring = k_spring * arm * arm * theta
    err = abs(T_spring - T) / T
    ok = err <= 1e-3 and b.angVel.norm() < 1e-6
    print(("ok   " if ok else "FAIL ")
          + f"{label} spring: angle {theta:.4e} rad under T = {T:.4e} N m; k a'^2 theta = {T_spring:.4e}, "
          f"rel. error {err:.1e}", flush=True)
    if not ok:
        failures.append(label + " spring")
finish()
