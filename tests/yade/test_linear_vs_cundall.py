# ctest (inside yade): the meso law reduced to a linear spring (kp = k1, kc = 0, fa = 0,
# gammaN = 0) reproduces, to relative 1e-9, the trajectories of the same multi-sphere scene
# under YADE's Law2_ScGeom_FrictPhys_CundallStrack with the same normal stiffness (and no
# friction): proof that the plugin reads YADE's geometry and applies forces as YADE does.
import random

from yade import *
from yade import utils
from harness import check, finish

K, R, RHO = 2e3, 1e-3, 2500.0


def scene(meso):
    O.reset()
    if meso:
        mat = MesoMat(k1=K, kp=K, kc=0.0, phiF=0.5, density=RHO, frictionAngle=0.0)
        ip2, law = Ip2_MesoMat_MesoMat_MesoPhys(), Law2_ScGeom_MesoPhys_Meso()
    else:  # Ip2_FrictMat_FrictMat_FrictPhys: kn = E R for equal radii
        mat = FrictMat(young=K / R, poisson=0.3, density=RHO, frictionAngle=0.0)
        ip2, law = Ip2_FrictMat_FrictMat_FrictPhys(), Law2_ScGeom_FrictPhys_CundallStrack()
    O.materials.append(mat)
    rnd = random.Random(7)
    for i in range(3):
        for j in range(3):
            for k in range(3):
                b = utils.sphere((i * 2.1 * R + rnd.uniform(-0.1, 0.1) * R, j * 2.1 * R, k * 2.1 * R), R, material=mat)
                O.bodies.append(b)
                b.state.vel = tuple(rnd.uniform(-0.05, 0.05) for _ in range(3))
    O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [ip2], [law]),
                 NewtonIntegrator(damping=0.0, gravity=(0, 0, -9.81))]
    O.dt = 0.02 * 3.14159 * (utils.sphere((0, 0, 0), R, material=mat).state.mass / 2 / K) ** 0.5


def trajectory(meso, checkpoints):
    scene(meso)
    out, contacts = [], 0
    for n in checkpoints:
        while O.iter < n:
            O.step()
        contacts += O.interactions.countReal()
        out.append([(tuple(b.state.pos), tuple(b.state.vel), tuple(b.state.angVel)) for b in O.bodies])
    return out, contacts


checkpoints = list(range(50, 8001, 50))
ref, n_ref = trajectory(False, checkpoints)
mes, n_mes = trajectory(True, checkpoints)
worst_pos = worst_vel = 0.0
for a_step, b_step in zip(ref, mes):
    for (pa, va, wa), (pb, vb, wb) in zip(a_step, b_step):
        worst_pos = max(worst_pos, max(abs(x - y) for x, y in zip(pa, pb)) / R)
        worst_vel = max(worst_vel, max(abs(x - y) for x, y in zip(va, vb)) / 0.05)
        worst_vel = max(worst_vel, max(abs(x) for x in wb))  # no torque: the normal force passes the centres
check(n_ref > 0 and n_ref == n_mes, "the scene has contacts, the same under both laws",
      f"contacts summed over checkpoints: CundallStrack {n_ref}, meso {n_mes}")
check(worst_pos <= 1e-9 and worst_vel <= 1e-9, "trajectories equal to CundallStrack's",
      f"max position difference / radius = {worst_pos:.2e}; max velocity difference / v0 = {worst_vel:.2e}")
finish()
