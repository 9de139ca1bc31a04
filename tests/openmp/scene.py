# Inside yade (-j1 or -j2): a dense packing on an adhesive box with every mechanism of the meso law
# on (adhesion, viscosity, sliding, rolling, torsion with slip) and the contact-relative drag, moved kinematically so
# that forces do not feed back into the motion. Writes the per-contact state, the forces and torques on the
# bodies and the energy to the JSON file in argv[1]; tests/openmp/compare.py compares thread counts
# and geometry settings.
import json
import random
import sys

from yade import O, pack, utils, wrapper as w

R = 1e-3
# argv[2] == "norot": the sphere-sphere ScGeom6D without its relative rotations, which the law does not read.
rotations = not (len(sys.argv) > 2 and sys.argv[2] == "norot")
# argv[2] == "drag": the spheres free, 3 steps: the drag acts (on free bodies only), its reference
# from the law's sums in the last two, and the forces differ between thread counts by rounding alone.
free = len(sys.argv) > 2 and sys.argv[2] == "drag"
mat = w.MesoMat(k1=1e4, kp=5e4, kc=1e4, phiF=0.05, gammaN=1e-4, fa=1e-4, kca=1e3, adhesion="jumpIn", frictionAngle=0.05,
                phiD=0.8, kt=2e4, gammaT=2e-5, kr=1e4, gammaR=5e-6, muR=0.05, ko=1e4, gammaO=5e-6, muO=0.05,
                density=2000)
O.materials.append(mat)
O.bodies.append(pack.regularHexa(pack.inAlignedBox((0, 0, 0), (0.024, 0.024, 0.012)), radius=R, gap=-2e-6,
                                 material=mat))
zmin = min(b.state.pos[2] for b in O.bodies)
O.bodies.append(utils.box((0.012, 0.012, zmin - R - 0.5e-3 + 2e-6), (0.02, 0.02, 0.5e-3), fixed=True, material=mat))
rnd = random.Random(7)
for b in O.bodies:
    if isinstance(b.shape, w.Sphere):
        b.state.blockedDOFs = "" if free else "xyzXYZ"
        # Large enough that some contacts slip, roll and twist beyond their Coulomb limits.
        b.state.vel = tuple(rnd.uniform(-2e-3, 2e-3) for _ in range(3))
        b.state.angVel = tuple(rnd.uniform(-5.0, 5.0) for _ in range(3))
O.engines = [w.ForceResetter(),
             w.InsertionSortCollider([w.Bo1_Sphere_Aabb(aabbEnlargeFactor=1.01), w.Bo1_Box_Aabb()],
                                     verletDist=0.05 * R),
             w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom6D(interactionDetectionFactor=1.01,
                                                             updateRotations=rotations),
                                w.Ig2_Box_Sphere_ScGeom6D()],
                               [w.Ip2_MesoMat_MesoMat_MesoPhys()], [w.Law2_ScGeom_MesoPhys_Meso()]),
             # The drag relative to the contacts, its reference gathered by the law on every thread
             # (comparable to the contact forces and torques: gamma_b v ~ 0.01 N, gamma_br a^2 w ~ 2e-5 N m).
             w.MesoBackgroundDamping(gammaB=5.0, gammaBR=4.0, reference="contacts", label="drag"),
             w.NewtonIntegrator(damping=0, gravity=(0, 0, 0))]
O.dt = 2e-7
O.trackEnergy = True
O.run(3 if free else 300, True)
contacts = {}
for i in O.interactions:
    if i.isReal:
        p = i.phys
        contacts[f"{i.id1}-{i.id2}"] = [p.deltaMax, p.delta0, p.touched, *p.slidingSpring, *p.rollingSpring,
                                        p.torsionSpring,
                                        *p.shearForce, *p.rollingForce, p.torsionForce, *p.normalForce]
report = {"threads": O.numThreads, "contacts": contacts, "law_sum_steps": O.engines[3].lawSumSteps,
          "forces": [tuple(O.forces.f(b.id)) + tuple(O.forces.t(b.id)) for b in O.bodies],
          "energy": {k: O.energy[k] for k in O.energy.keys()},
          "slipping": sum(1 for i in O.interactions if i.isReal and i.phys.shearForce.norm() > 0
                          and abs(i.phys.shearForce.norm()
                                  - mat.phiD * i.phys.muS * (i.phys.hystereticForce + i.phys.viscousForce
                                                             + i.phys.kc * i.geom.penetrationDepth))
                          < 1e-9 * i.phys.shearForce.norm())}
with open(sys.argv[1], "w") as f:
    json.dump(report, f)
