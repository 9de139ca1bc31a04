# ctest (inside yade): MesoMat bodies among FrictMat bodies. MesoMat is a FrictMat, so with
# YADE's own Ip2_FrictMat_FrictMat_FrictPhys and CundallStrack beside this plugin's pair in the
# InteractionLoop, MesoMat-MesoMat contacts get the meso law and MesoMat-FrictMat contacts
# YADE's linear law from young, poisson and frictionAngle (which MesoMat carries for that).
# Without them YADE aborts the process at the first such contact (its dispatch error is thrown
# inside its OpenMP loop), which the README's "Mixed materials" warns of.
import math

from yade import O, utils
from yade import wrapper as w
from harness import check, finish

O.reset()
meso = O.materials.append(w.MesoMat(k1=100.0, kp=500.0, density=2000.0, young=1e6, poisson=0.3, frictionAngle=0.3))
frict = O.materials.append(w.FrictMat(young=1e6, poisson=0.3, density=2000.0, frictionAngle=0.3))
a = 1e-3
O.bodies.append([utils.sphere((0, 0, 0), a, material=meso), utils.sphere((2 * a + 5e-7, 0, 0), a, material=frict),
                 utils.sphere((-2 * a - 5e-7, 0, 0), a, material=meso)])
O.bodies[1].state.vel = (-0.05, 0, 0)
O.bodies[2].state.vel = (0.05, 0, 0)
O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb()]),
             w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom()],
                               [w.Ip2_MesoMat_MesoMat_MesoPhys(), w.Ip2_FrictMat_FrictMat_FrictPhys()],
                               [w.Law2_ScGeom_MesoPhys_Meso(), w.Law2_ScGeom_FrictPhys_CundallStrack()]),
             w.NewtonIntegrator(damping=0)]
O.dt = 1e-6
O.run(200, True)
mm, mf = O.interactions[0, 2], O.interactions[0, 1]
check(type(mm.phys).__name__ == "MesoPhys" and mm.phys.kp == 500.0, "MesoMat-MesoMat: the meso law",
      type(mm.phys).__name__)
# Ip2_FrictMat_FrictMat_FrictPhys: kn = 2 E1 r1 E2 r2/(E1 r1 + E2 r2) = E a for equal E and radii
d = mf.geom.penetrationDepth
check(type(mf.phys).__name__ == "FrictPhys" and abs(mf.phys.kn / (1e6 * a) - 1) < 1e-12
      and abs(mf.phys.normalForce.norm() / (mf.phys.kn * d) - 1) < 1e-9,
      "MesoMat-FrictMat: YADE's linear law from young",
      f"kn {mf.phys.kn:.6g} (E a = {1e6 * a:g}), |F|/(kn delta) - 1 = "
      f"{mf.phys.normalForce.norm() / (mf.phys.kn * d) - 1:.1e}")
check(all(math.isfinite(x) for b in O.bodies for x in b.state.pos), "the run stays finite")
finish()
