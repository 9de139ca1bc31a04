# Periodic triaxial compression of a cohesive packing with PeriTriaxController (about a minute;
# --quick: a few s).  yade -n -x examples/periodic_triaxial.py [--quick]
# A gas of adhesive, frictional spheres in a periodic cell is compressed isotropically to p0,
# then shortened along z at constant lateral stress p0. Prints and plots (yade.plot) the
# deviatoric stress q = s_zz - (s_xx + s_yy)/2 against the axial strain; checks that the
# isotropic state reached p0 and that the sample carries a deviatoric load.
import math
import sys

from yade import O, pack, plot, utils
from yade import wrapper as w
from mesocontact import params, scene

quick = "--quick" in sys.argv[1:]
N, R, RHO = (150, 0.5e-3, 2000.0) if quick else (300, 0.5e-3, 2000.0)
K1, KP = 100.0, 500.0
P0 = 0.005 * K1 / (2 * R)  # confining stress: overlaps of about half a percent of d
mat = w.MesoMat(k1=K1, kp=KP, kc=0.5 * KP, phiF=0.05, gammaN=2e-4, density=RHO, frictionAngle=math.atan(0.4),
                kt=0.2 * K1, gammaT=4e-5)
O.materials.append(mat)
O.periodic = True
side = (N * 4 / 3 * math.pi * R ** 3 / 0.3) ** (1 / 3)  # a loose gas, solid fraction 0.3
O.cell.hSize = utils.Matrix3(side, 0, 0, 0, side, 0, 0, 0, side)
sp = pack.SpherePack()
sp.makeCloud((0, 0, 0), (side, side, side), rMean=R, rRelFuzz=0.2, num=N, periodic=True, seed=3)
sp.toSimulation(material=mat)
stage = {"name": "isotropic"}


def done_isotropic():
    print(f"isotropic: p = {-sum(tri.stress) / 3:.4g} Pa (goal {P0:.4g}) at iteration {O.iter}", flush=True)
    stage.update(name="shear", iter0=O.iter, eps0=O.cell.trsf[2, 2])

    # z: a strain goal, counted (as PeriTriaxController does) from the start of the isotropic stage
    tri.goal, tri.stressMask = (-P0, -P0, tri.strain[2] - (0.05 if quick else 0.1)), 0b011
    tri.maxStrainRate = (1.0, 1.0, 0.5)  # inertial number about 1e-3: quasi-static
    tri.doneHook = "O.pause()"


def record():

    s = tri.stress
    eps = -math.log(O.cell.trsf[2, 2] / stage.get("eps0", 1.0)) if stage["name"] == "shear" else 0.0
    q = -(s[2] - 0.5 * (s[0] + s[1]))  # stress: the diagonal (compression negative)
    plot.addData(eps_z=eps, q=q, p=-sum(s) / 3, unbalanced=utils.unbalancedForce(), shear=int(stage["name"] == "shear"))


O.engines = [
    w.ForceResetter(),
    w.InsertionSortCollider([w.Bo1_Sphere_Aabb()]),
    w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom()], [w.Ip2_MesoMat_MesoMat_MesoPhys()],
                      [w.Law2_ScGeom_MesoPhys_Meso()]),
    w.PeriTriaxController(goal=(-P0, -P0, -P0), stressMask=0b111, maxUnbalanced=0.05, maxStrainRate=(2.0, 2.0, 2.0),
                          dynCell=True, mass=0.2 * N * params.sphere_mass(R, RHO) / side, doneHook="done_isotropic()"),
    w.NewtonIntegrator(damping=0.3),
    w.PyRunner(iterPeriod=200, command="record()"),
]
tri = O.engines[3]
O.dt = scene.time_step(safety=0.05)
plot.plots = {"eps_z": ("q",), "eps_z ": ("p",)}
O.run(400000 if quick else 2000000, True)
if stage["name"] != "shear":
    print("periodic_triaxial: FAILED: the isotropic stage never reached its goal")
    sys.exit(1)
d = plot.data
shear = [i for i, s in enumerate(d["shear"]) if s]
qmax = max(d["q"][i] for i in shear)
eps_end = d["eps_z"][shear[-1]]
p_iso = d["p"][shear[0]]
print(f"shear: {O.iter - stage['iter0']} steps, axial strain {eps_end:.3f}, peak q = {qmax:.4g} Pa = "
      f"{qmax / P0:.2f} p0")
ok = abs(p_iso / P0 - 1) < 0.1 and qmax > 0.2 * P0
print("periodic_triaxial: " + ("ok" if ok else "FAILED"))
sys.exit(0 if ok else 1)
