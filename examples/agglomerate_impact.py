# An adhesive agglomerate hits a wall (about 20 s; --quick: a few s).
#   yade -n -x examples/agglomerate_impact.py [--quick] [--speed V]
# Spheres on a cubic lattice inside a ball, pressed 2 % of a radius into their neighbours, settle
# into one cohesive cluster (drag towards rest while they settle, then none); the cluster flies
# at V onto a box wall of the same material. Prints the fragments (groups of spheres linked by
# contacts), the spheres left on the wall and the centre-of-mass rebound; checks that the cluster
# was whole before the impact and that O.energy accounts for the kinetic energy it started with.
import argparse
import sys

from yade import O, plot, utils
from yade import wrapper as w
from mesocontact import params, scene

a = argparse.ArgumentParser(prog="yade -n -x examples/agglomerate_impact.py")
a.add_argument("--quick", action="store_true")
a.add_argument("--speed", type=float, default=1.0, help="impact speed [m/s] (default 1; 0.3: it bounces off whole)")
a = a.parse_args(sys.argv[1:])
R, RHO, K1, KP = 0.5e-3, 2000.0, 1000.0, 5000.0
n = 2 if a.quick else 3  # ball radius in lattice spacings
mat = w.MesoMat(k1=K1, kp=KP, kc=0.5 * KP, phiF=0.05, gammaN=1e-4, density=RHO, frictionAngle=0.4, kt=0.2 * K1,
                gammaT=2e-5)
O.materials.append(mat)
h = 2 * R * 0.99  # lattice spacing: pressed 1 % of d into each neighbour
z0 = (n + 2) * h
members = [utils.sphere((i * h, j * h, z0 + k * h), R, material=mat)
           for i in range(-n, n + 1) for j in range(-n, n + 1) for k in range(-n, n + 1)
           if i * i + j * j + k * k <= n * (n + 1)]  # no sphere with a single neighbour
ids = O.bodies.append(members)
wall = O.bodies.append(utils.box((0, 0, -R), (20 * R, 20 * R, R), material=mat, fixed=True))
O.engines = [
    w.ForceResetter(),
    w.InsertionSortCollider([w.Bo1_Sphere_Aabb(), w.Bo1_Box_Aabb()]),
    w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom(), w.Ig2_Box_Sphere_ScGeom()],
                      [w.Ip2_MesoMat_MesoMat_MesoPhys()], [w.Law2_ScGeom_MesoPhys_Meso()]),
    w.MesoBackgroundDamping(gammaB=5e-3, reference="lab"),  # relaxation time m/gamma_b about a contact time
    w.NewtonIntegrator(damping=0),
]
scene.set_detection()
mass = params.sphere_mass(R, RHO)
O.dt = scene.time_step(safety=0.05)  # every element of every pair that can meet, walls included
t_c = params.contact_time(K1, mass / 2)


def clusters():
    """Groups of spheres linked by contacts with overlap (union-find)."""
    parent = {i: i for i in ids}

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i
    for i in O.interactions:
        if i.isReal and i.id1 in parent and i.id2 in parent and i.geom.penetrationDepth > 0:
            parent[find(i.id1)] = find(i.id2)
    groups = {}
    for i in ids:
        groups.setdefault(find(i), []).append(i)
    return sorted((len(g) for g in groups.values()), reverse=True)


O.run(int(40 * t_c / O.dt), True)  # settle, with the drag
whole = clusters()
print(f"{len(ids)} spheres settled into clusters of {whole[:5]} (coordination "
      f"{2 * sum(1 for i in O.interactions if i.isReal and i.geom.penetrationDepth > 0) / len(ids):.2f})", flush=True)
O.engines[3].gammaB = 0  # free flight and impact: no drag
for i in ids:
    O.bodies[i].state.vel = (0, 0, -a.speed)
    O.bodies[i].state.angVel = (0, 0, 0)
O.trackEnergy = True
O.run(1, True)
e0 = O.energy.total()
ek0 = sum(0.5 * O.bodies[i].state.mass * O.bodies[i].state.vel.squaredNorm() for i in ids)
worst = [0.0]


def watch():
    worst[0] = max(worst[0], abs(O.energy.total() - e0) / ek0)
    zc = sum(O.bodies[i].state.pos[2] for i in ids) / len(ids)
    vz = sum(O.bodies[i].state.vel[2] for i in ids) / len(ids)
    plot.addData(t=O.time, z_com=zc, vz_com=vz, Ek=O.energy["kinetic"],
                 dissipated=O.energy.total() - O.energy["kinetic"])


O.engines = O.engines + [w.PyRunner(iterPeriod=50, command="watch()")]
plot.plots = {"t": ("vz_com",), "t ": ("Ek", "dissipated")}
O.run(int((z0 / a.speed + 60 * t_c) / O.dt), True)
frags = clusters()
on_wall = {i.id1 if i.id2 == wall else i.id2 for i in O.interactions if i.isReal and wall in (i.id1, i.id2)
           and i.geom.penetrationDepth > 0}
vz = sum(O.bodies[i].state.vel[2] for i in ids) / len(ids)
print(f"after the impact at {a.speed} m/s: fragments {frags[:8]}{' ...' if len(frags) > 8 else ''} "
      f"({len(frags)} in all), {len(on_wall)} spheres on the wall, centre-of-mass rebound {vz / a.speed:+.3f} v")
print(f"energy: kinetic {O.energy['kinetic'] / ek0:.3f} of the impact energy left; "
      f"O.energy.total() kept within {worst[0]:.1e} of it")
ok = whole[0] == len(ids) and worst[0] < 1e-3
print("agglomerate_impact: " + ("ok" if ok else "FAILED"))
sys.exit(0 if ok else 1)
