# Adhesive, frictional particles poured into a box under gravity (about 30 s; --quick: a few s).
#   yade -n -x examples/deposition.py [--quick]
# Shows: a MesoMat with friction, rolling and torsion; the walls as boxes of the same material;
# the detection range set from the adhesion (scene.set_detection); the time step from every
# stiffness and dashpot (scene.time_step); yade.plot fed while it runs (plot.plot() in the
# shell shows the kinetic energy and the coordination). Ends by checking that the bed is at rest.
import math
import sys

from yade import O, pack, plot, utils
from yade import wrapper as w
from mesocontact import params, scene

quick = "--quick" in sys.argv[1:]
N, R, RHO = (60, 0.5e-3, 2000.0) if quick else (400, 0.5e-3, 2000.0)
mass = params.sphere_mass(R, RHO)
mat = w.MesoMat(k1=50.0, kp=250.0, kc=50.0, phiF=0.05, fa=5e-6, kca=25.0, adhesion="jumpIn",
                gammaN=2e-4, density=RHO, frictionAngle=math.atan(0.5), kt=10.0, gammaT=5e-5,
                kr=2.0, gammaR=1e-5, muR=0.1, ko=2.0, gammaO=1e-5, muO=0.1)
O.materials.append(mat)
L = 10 * R * (N / 60) ** (1 / 3)  # box side, a few particle layers deep at the end
sp = pack.SpherePack()
sp.makeCloud((0, 0, 2 * R), (L, L, 6 * L), rMean=R, rRelFuzz=0.2, num=N, seed=1)
sp.toSimulation(material=mat)
walls = [utils.box(c, h, material=mat, fixed=True) for c, h in (
    ((L / 2, L / 2, -R), (L, L, R)), ((-R, L / 2, 3 * L), (R, L, 4 * L)), ((L + R, L / 2, 3 * L), (R, L, 4 * L)),
    ((L / 2, -R, 3 * L), (L, R, 4 * L)), ((L / 2, L + R, 3 * L), (L, R, 4 * L)))]
O.bodies.append(walls)
O.engines = [
    w.ForceResetter(),
    w.InsertionSortCollider([w.Bo1_Sphere_Aabb(), w.Bo1_Box_Aabb()]),
    w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom6D(updateRotations=False), w.Ig2_Box_Sphere_ScGeom6D()],
                      [w.Ip2_MesoMat_MesoMat_MesoPhys()], [w.Law2_ScGeom_MesoPhys_Meso()]),
    w.NewtonIntegrator(damping=0, gravity=(0, 0, -9.81)),
    w.PyRunner(iterPeriod=500, command="report()"),
]
print(f"detection factor {scene.set_detection():.5f} for the adhesion range {scene.adhesion_range():.2e} m")
O.dt = scene.time_step(safety=0.05)  # kp with gamma0, sliding, rolling and torsion, sphere-sphere and sphere-wall
spheres = [b for b in O.bodies if isinstance(b.shape, w.Sphere)]


def coordination():
    n = sum(1 for i in O.interactions if i.isReal and i.geom.penetrationDepth > 0
            and isinstance(O.bodies[i.id1].shape, w.Sphere) and isinstance(O.bodies[i.id2].shape, w.Sphere))
    return 2.0 * n / len(spheres)


def report():
    ek = sum(0.5 * b.state.mass * b.state.vel.squaredNorm() for b in spheres)
    plot.addData(t=O.time, Ek=ek, Z=coordination())
    if O.iter % 5000 == 0:
        print(f"t = {O.time:.3f} s: E_kin = {ek:.3e} J, coordination {coordination():.2f}", flush=True)


plot.plots = {"t": ("Ek",), "t ": ("Z",)}
t_fall = math.sqrt(2 * 6 * L / 9.81)
O.run(int(3 * t_fall / O.dt), True)
ek = sum(0.5 * b.state.mass * b.state.vel.squaredNorm() for b in spheres)
top = max(b.state.pos[2] for b in spheres)
inside = all(-R <= b.state.pos[0] <= L + R and -R <= b.state.pos[1] <= L + R and b.state.pos[2] > 0 for b in spheres)
print(f"after {O.time:.3f} s: E_kin = {ek:.2e} J (mg R of one sphere: {mass * 9.81 * R:.2e} J), "
      f"bed height {top / (2 * R):.1f} d, coordination {coordination():.2f}")
ok = inside and ek < N * mass * 9.81 * R * 1e-2 and coordination() > 2.0
print("deposition: " + ("ok" if ok else "FAILED: the bed is not at rest in the box"))
sys.exit(0 if ok else 1)
