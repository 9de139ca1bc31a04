# Clumps of MesoMat spheres (rigid dumbbells and triplets) dropped on a floor and onto each other
# (about 15 s; --quick: a few s).  yade -n -x examples/clumps.py [--quick]
# The law acts between the member spheres of different clumps and between members and the floor;
# YADE sums the members' forces on the clump. Checks that every clump stays rigid (members keep
# their distances), that the pile comes to rest above the floor, and prints the contacts per clump.
import math
import random
import sys

from yade import O, plot, utils
from yade import wrapper as w
from mesocontact import scene

quick = "--quick" in sys.argv[1:]
N, R, RHO, K1, KP = (12, 0.5e-3, 2000.0, 1000.0, 5000.0) if quick else (60, 0.5e-3, 2000.0, 1000.0, 5000.0)
mat = w.MesoMat(k1=K1, kp=KP, kc=0.5 * KP, phiF=0.05, fa=2e-5, kca=200.0, adhesion="jumpIn", gammaN=2e-3,
                density=RHO, frictionAngle=math.atan(0.5), kt=0.2 * K1, gammaT=2e-5)
O.materials.append(mat)
O.bodies.append(utils.box((0, 0, -R), (60 * R, 60 * R, R), material=mat, fixed=True))  # wide: nothing falls off
rnd = random.Random(5)
clumps = []
for c in range(N):
    x, y, z = rnd.uniform(-6 * R, 6 * R), rnd.uniform(-6 * R, 6 * R), 3 * R + 3.5 * R * c
    shape = [(0, 0, 0), (1.6 * R, 0, 0)] if c % 2 else [(0, 0, 0), (1.6 * R, 0, 0), (0.8 * R, 1.4 * R, 0)]
    cid, mids = O.bodies.appendClumped([utils.sphere((x + dx, y + dy, z + dz), R, material=mat)
                                        for dx, dy, dz in shape])
    O.bodies[cid].state.angVel = (rnd.uniform(-50, 50), rnd.uniform(-50, 50), 0)
    clumps.append((cid, mids))
O.engines = [
    w.ForceResetter(),
    w.InsertionSortCollider([w.Bo1_Sphere_Aabb(), w.Bo1_Box_Aabb()]),
    w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom(), w.Ig2_Box_Sphere_ScGeom()],
                      [w.Ip2_MesoMat_MesoMat_MesoPhys()], [w.Law2_ScGeom_MesoPhys_Meso()]),
    w.MesoBackgroundDamping(gammaB=2e-5, gammaBR=2e-5, reference="lab"),  # air drag: terminal speed about 1 m/s
    w.NewtonIntegrator(damping=0, gravity=(0, 0, -9.81)),
    w.PyRunner(iterPeriod=200, command="plot.addData(t=O.time, Ek=utils.kineticEnergy())"),
]
scene.set_detection()
O.dt = scene.time_step(safety=0.05)  # clump members count as spheres of their material
plot.plots = {"t": ("Ek",)}
gaps0 = {cid: [(O.bodies[a].state.pos - O.bodies[b].state.pos).norm() for a in mids for b in mids if a < b]
         for cid, mids in clumps}
t_end = math.sqrt(2 * (3.5 * R * N + 3 * R) / 9.81) + 0.4  # the fall, then time to settle
O.run(int(t_end / O.dt), True)
drift = max(abs((O.bodies[a].state.pos - O.bodies[b].state.pos).norm() - g)
            for cid, mids in clumps for (a, b), g in zip([(a, b) for a in mids for b in mids if a < b], gaps0[cid]))
ek = utils.kineticEnergy()
lowest = min(O.bodies[m].state.pos[2] for _, mids in clumps for m in mids)
member_of = {m: cid for cid, mids in clumps for m in mids}
touch = {cid: 0 for cid, _ in clumps}
for i in O.interactions:
    if i.isReal and i.geom.penetrationDepth > 0:
        for b in (i.id1, i.id2):
            if b in member_of:
                touch[member_of[b]] += 1
mass = sum(O.bodies[cid].state.mass for cid, _ in clumps)
print(f"{N} clumps after {O.time:.3f} s: kinetic energy {ek:.2e} J (m g R of the pile: {mass * 9.81 * R:.2e} J), "
      f"lowest sphere centre {lowest / R:.3f} R above the floor, contacts per clump "
      f"{sum(touch.values()) / N:.1f}, member distances kept to {drift:.1e} m")
ok = drift < 1e-12 and 0.9 * R < lowest < 1.01 * R and ek < 1e-2 * mass * 9.81 * R
print("clumps: " + ("ok" if ok else "FAILED"))
sys.exit(0 if ok else 1)
