# ctest (inside yade): scene.time_step, the stable step of the law before any contact exists
# (Ip2_MesoMat_MesoMat_MesoPhys.stableStep, the code that checks each new contact), is the
# integrator's true limit whichever element is the stiffest. A sphere rests on a box under gravity,
# one element at a time much stiffer than the others and kicked (Coulomb limits far away, so the
# element stays elastic): at 0.95 of the step the kinetic energy stays bounded (at most the
# leapfrog's 1/(1 - 0.95^2) = 10.3 of the kick: the velocities are half-step ones), at 1.1 it grows
# without bound. And the case YADE's GlobalStiffnessTimeStepper gets wrong: it sees kn and ks but
# not the rolling and torsion springs, so a spinning sphere with kr = ko = 100 kp blows up at its
# step and stays bounded at scene.time_step. A fixed sphere counts as a wall (it does not move back).
import math

from yade import O, utils
from yade import wrapper as w
from mesocontact import params, scene
from harness import check, finish

R, RHO, G = 1e-3, 2000.0, 50.0
MASS = params.sphere_mass(R, RHO)


def resting(spin=(0, 0, 0), vt=(0, 0, 0), vn=0.0, timestepper=None, **mat):
    scene.reset()
    m = w.MesoMat(density=RHO, **mat)
    O.materials.append(m)
    d0 = MASS * G / mat["k1"]  # the overlap that carries the weight
    box = utils.box((0, 0, -R), (20 * R, 20 * R, R), material=m, fixed=True)
    ball = utils.sphere((0, 0, R - d0), R, material=m)
    O.bodies.append([box, ball])
    ball.state.vel, ball.state.angVel = (vt[0], vt[1], vn), spin
    O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb(), w.Bo1_Box_Aabb()]),
                 w.InteractionLoop([w.Ig2_Box_Sphere_ScGeom6D()], [w.Ip2_MesoMat_MesoMat_MesoPhys()],
                                   [w.Law2_ScGeom_MesoPhys_Meso()])] + ([timestepper] if timestepper else []) + \
                [w.NewtonIntegrator(damping=0, gravity=(0, 0, -G))]


def growth(steps=2000, e0=None):
    """Largest kinetic energy over the run / the kick's (e0: the kinetic energy before any step)."""
    e0 = e0 or utils.kineticEnergy()
    worst = e0
    for _ in range(steps // 50):
        O.run(50, True)
        worst = max(worst, utils.kineticEnergy())
    return worst / e0


base = dict(k1=100.0, kp=100.0, frictionAngle=1.5, muR=10.0, muO=10.0)
cases = {"normal, kp": (dict(base), dict(vn=1e-3)),
         "normal, gamma0 (overdamped)": (dict(base, gammaN=0.5), dict(vn=1e-3)),
         "sliding, kt = 50 kp": (dict(base, kt=5000.0), dict(vt=(1e-3, 0, 0))),
         "rolling, kr = 50 kp": (dict(base, kr=5000.0), dict(spin=(1.0, 0, 0))),
         "torsion, ko = 50 kp": (dict(base, ko=5000.0), dict(spin=(0, 0, 1.0)))}
for name, (mat, kick) in cases.items():
    resting(**kick, **mat)
    dt = scene.time_step(safety=1.0)
    found = {}
    for f in (0.95, 1.1):
        resting(**kick, **mat)
        O.dt = f * dt
        found[f] = growth()
    check(found[0.95] < 11 and found[1.1] > 50, f"{name}: stable at 0.95 of time_step, unstable at 1.1",
          f"dt = {dt:.4e} s, kinetic energy x{found[0.95]:.3g} and x{found[1.1]:.3g}")

# The spinning sphere: rolling and torsion 100 times stiffer than the normal law.
spin = dict(base, kr=1e4, ko=1e4)
resting(spin=(1.0, 0, 1.0),
        timestepper=w.GlobalStiffnessTimeStepper(timestepSafetyCoefficient=0.8, timeStepUpdateInterval=1,
                                                 defaultDt=1e-6), **spin)
e_kick = utils.kineticEnergy()
O.run(5, True)  # the stepper sets O.dt from the contact's kn and ks
dt_gsts = O.dt
O.engines = [e for e in O.engines if not isinstance(e, w.GlobalStiffnessTimeStepper)]
g_gsts = growth(e0=e_kick)
resting(spin=(1.0, 0, 1.0), **spin)
O.dt = scene.time_step(safety=0.8)
g_ours = growth()
check(g_gsts > 50 and g_ours < 11,
      "spinning sphere, kr = ko = 100 kp: GlobalStiffnessTimeStepper's step blows up, time_step's does not",
      f"{dt_gsts:.3e} s: x{g_gsts:.3g}; {O.dt:.3e} s: x{g_ours:.3g}")

# Several materials and sizes: the smallest sphere of the stiffest pair decides; walls count.
scene.reset()
soft, stiff = w.MesoMat(k1=100.0, kp=100.0, density=RHO), w.MesoMat(k1=100.0, kp=400.0, density=RHO)
O.materials.append([soft, stiff])
O.bodies.append([utils.sphere((0, 0, 0), R, material=soft), utils.sphere((0, 0, 3 * R), 0.5 * R, material=stiff),
                 utils.sphere((0, 0, 6 * R), R, material=stiff)])
ip2 = w.Ip2_MesoMat_MesoMat_MesoPhys()
want = min(ip2.stableStep(soft, stiff, R, 0.5 * R), ip2.stableStep(stiff, stiff, 0.5 * R, 0.5 * R))
check(abs(scene.time_step(safety=1.0) - want) < 1e-15 * want, "two materials: the stiff pair of the small spheres",
      f"{scene.time_step(safety=1.0):.4e} s")
scene.reset()  # one sphere on a wall: no sphere-sphere pair exists, the wall's decides
wall = w.MesoMat(k1=100.0, kp=1e4, density=RHO)
O.bodies.append([utils.sphere((0, 0, 0), 0.5 * R, material=stiff),
                 utils.box((0, 0, -3 * R), (5 * R, 5 * R, R), material=wall, fixed=True)])
want = ip2.stableStep(stiff, wall, 0.5 * R, 0.0)
check(abs(scene.time_step(safety=1.0) - want) < 1e-15 * want and want > ip2.stableStep(stiff, stiff, 0.5 * R, 0.5 * R),
      "one sphere on a wall: the sphere-wall bound", f"{scene.time_step(safety=1.0):.4e} s")
# a sphere against a fixed sphere (no other partner): the fixed one counts as a wall (it does not move back)
scene.reset()
O.bodies.append([utils.sphere((0, 0, 0), 0.5 * R, material=stiff),
                 utils.sphere((0, 0, -2 * R), R, material=wall, fixed=True)])
want = ip2.stableStep(stiff, wall, 0.5 * R, 0.0)
got = scene.time_step(safety=1.0)
check(math.isfinite(got) and abs(got - want) < 1e-15 * want,
      "a sphere against a fixed sphere: the sphere-wall bound, not inf",
      f"{got:.4e} s")
for bad, says in ((0.0, "safety"), (-1.0, "safety"), (math.nan, "safety"), (math.inf, "safety"), ("0.5", "safety")):
    try:
        scene.time_step(safety=bad)
        check(False, f"safety = {bad} refused")
    except ValueError as e:
        check(says in str(e), f"safety = {bad} refused, naming it", str(e))
import warnings  # noqa: E402

with warnings.catch_warnings(record=True) as caught:  # an unstable step on purpose: given, with a warning
    warnings.simplefilter("always")
    over = scene.time_step(safety=1.5)
check(abs(over - 1.5 * want) < 1e-15 * over and len(caught) == 1 and "stability bound" in str(caught[0].message),
      "safety = 1.5: 1.5 times the bound, with a warning", str(caught[0].message) if caught else "no warning")
check(abs(scene.time_step() - 0.05 * want) < 1e-15 * want, "the default safety is 0.05, what the examples use")
try:
    ip2.stableStep(soft, soft, -1.0)
    check(False, "stableStep(radius1 = -1) refused")
except Exception as e:
    check("radius1" in str(e), "stableStep(radius1 = -1) refused, naming it", f"{type(e).__name__}: {e}")
finish()
