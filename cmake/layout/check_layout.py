# Run by the build (yade -n -x check_layout.py DIR-OF-meso_layout_probe.so): does the installed
# YADE library lay out the classes the plugin derives from or reads as the headers the plugin is
# compiled against do? Objects are made and filled by the library (its constructors, its Python
# setters, its engines); the probe reads them through the headers. Exits 1 at the first difference,
# naming the class and member. Scalars come first, pointers only once those agree.
import math
import sys

sys.path.insert(0, sys.argv[-1])
import meso_layout_probe as probe  # noqa: E402

from yade import O, Matrix3, Vector3, utils  # noqa: E402
from yade import wrapper as w  # noqa: E402

checked = []


def differ(what, header, library):
    print(f"layout check FAILED: {what}: the headers read {header!r}, the installed library holds {library!r}")
    print("The plugin's headers do not match the installed YADE library: fetch the source of the installed "
          "version (scripts/fetch-yade-source.sh) or adjust the documented difference.")
    sys.exit(1)


def same(what, header, library):
    if isinstance(library, (tuple, list, Vector3)):
        library = tuple(library)
        header = tuple(header)
        ok = len(header) == len(library) and all(same_number(a, b) for a, b in zip(header, library))
    elif isinstance(library, Matrix3):
        library = tuple(tuple(library[i, j] for j in range(3)) for i in range(3))
        ok = all(same_number(a, b) for ra, rb in zip(header, library) for a, b in zip(ra, rb))
    else:
        ok = same_number(header, library)
    if not ok:
        differ(what, header, library)
    checked.append(what)


def same_number(a, b):
    return a == b or (isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b))


# 1. Sizes of the classes, against the blocks the library allocates for them.
sizes = probe.sizes()
for name, size in sorted(sizes.items()):
    # glibc may hand out a freed chunk up to 24 bytes larger than asked; fresh ones fit: the smallest
    # of many is the size the library asked for.
    objs = [getattr(w, name)() for _ in range(64)]
    block = min(probe.usable(o) for o in objs)
    expected = ((size + 8 + 15) // 16) * 16 - 8  # glibc: the smallest chunk holding size + 8, minus 8
    if block != max(expected, 24):
        differ(f"sizeof({name})", f"{size} bytes (a block of {max(expected, 24)})", f"a block of {block} bytes")
    checked.append(f"sizeof({name})")

# 2. Members, each set to a value of its own by the library's setters.
s = w.State()
s.pos, s.vel, s.angVel, s.mass, s.inertia = ((1.5, -2.5, 3.25), (4.5, 5.75, -6.125), (7.5, -8.25, 9.0), 10.375,
                                             (11.5, 12.25, 13.125))
for k, v in probe.state(s).items():
    same(f"State.{k}", v, getattr(s, k))

m = w.FrictMat(density=1234.5, young=6.5e7, frictionAngle=0.321)
for k, v in probe.material(m).items():
    same(f"FrictMat.{k}", v, getattr(m, k))
sh = w.Sphere(radius=0.0123)
same("Sphere.radius", probe.sphere(sh)["radius"], sh.radius)
fa = w.Facet(vertices=[(0.5, -1.25, 0.125), (2.0, 0.75, -0.5), (-1.5, 0.25, 3.0)])
same("Facet.vertices", probe.facet(fa)["vertices"], tuple(tuple(v) for v in fa.vertices))
wa = w.Wall(axis=2, sense=-1)
for k, v in probe.wall(wa).items():
    same(f"Wall.{k}", v, getattr(wa, k))
p = w.FrictPhys(kn=1.25e5, ks=3.5e4, tangensOfFrictionAngle=0.75)
p.normalForce, p.shearForce = (1.0, 2.0, 3.0), (-4.0, 5.0, -6.0)
for k, v in probe.phys(p).items():
    same(f"FrictPhys.{k}", v, getattr(p, k))

# 3. A scene the library runs: bodies, a clump, a real interaction, a periodic cell, energies.
O.reset()
O.periodic = True
O.cell.hSize = Matrix3(0.2, 0.01, 0, 0, 0.3, 0, 0, 0, 0.25)
O.cell.velGrad = Matrix3(0, 0.5, 0, 0, 0, 0, 0, 0, -0.25)
O.materials.append([w.FrictMat(), w.FrictMat(), w.FrictMat()])
mat = O.materials.append(w.FrictMat(density=2000, young=1e6, frictionAngle=0.4))
for k, v in probe.material(O.materials[mat]).items():
    same(f"FrictMat.{k} (in O.materials)", v, getattr(O.materials[mat], k))
ids = O.bodies.append([utils.sphere((0.05 + 0.01 * i, 0.05, 0.05), 0.006, material=mat) for i in range(4)])
clump, members = O.bodies.appendClumped([utils.sphere((0.1, 0.15, 0.1), 0.005, material=mat),
                                         utils.sphere((0.11, 0.15, 0.1), 0.005, material=mat)])
O.bodies[ids[0]].state.vel = (0.3, 0, 0)
O.trackEnergy = True
O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb()]),
             w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom()], [w.Ip2_FrictMat_FrictMat_FrictPhys()],
                               [w.Law2_ScGeom_FrictPhys_CundallStrack()]),
             w.NewtonIntegrator(damping=0.1)]
O.dt = 1.2345e-6
O.run(7, True)
sc = probe.scene()
same("Scene.dt", sc["dt"], O.dt)
same("Scene.iter", sc["iter"], O.iter)
same("Scene.isPeriodic", sc["isPeriodic"], O.periodic)
same("Scene.trackEnergy", sc["trackEnergy"], O.trackEnergy)
for b in (O.bodies[ids[0]], O.bodies[members[1]], O.bodies[clump]):
    hb = probe.body(b)
    same(f"Body.id (#{b.id})", hb["id"], b.id)
    same(f"Body.clumpId (#{b.id})", hb["clumpId"], b.clumpId)
    same(f"Body.isDynamic (#{b.id})", hb["isDynamic"], b.dynamic)
    same(f"Body.isClumpMember (#{b.id})", hb["isClumpMember"], b.isClumpMember)
    same(f"Body.state (#{b.id})", hb["state"], probe.address(b.state))
    same(f"Body.shape (#{b.id})", hb["shape"], probe.address(b.shape))
    same(f"Body.material (#{b.id})", hb["material"], probe.address(b.material))
    for k, v in probe.state(b.state).items():
        same(f"State.{k} (#{b.id}, moved by the library)", v, getattr(b.state, k))
real = [i for i in O.interactions if i.isReal]
if not real:
    differ("the probe scene", "a real interaction", "none")
i = real[0]
hi = probe.interaction(i)
for k in ("id1", "id2", "isReal", "cellDist"):
    same(f"Interaction.{k}", hi[k], getattr(i, k))
same("Interaction.geom", hi["geom"], probe.address(i.geom))
same("Interaction.phys", hi["phys"], probe.address(i.phys))
for k, v in probe.geom(i.geom).items():
    same(f"ScGeom.{k}", v, getattr(i.geom, k))
for k, v in probe.phys(i.phys).items():
    same(f"FrictPhys.{k} (set by the library's law)", v, getattr(i.phys, k))
loop = O.engines[2]
same("Functor.scene (an Ip2)", probe.functorScene(loop.physDispatcher.functors[0]), sc["address"])
same("Functor.scene (a Law2)", probe.functorScene(loop.lawDispatcher.functors[0]), sc["address"])
same("Engine.scene", probe.engineScene(O.engines[3]), sc["address"])
# The containers, through these headers' offsets.
O.forces.addF(0, (1.5, -2.5, 0.125))
force0 = O.forces.f(0, sync=True)  # the per-thread forces summed (the contacts of the last step and addF)
c = probe.sceneContainers()
same("Scene.bodies", c["bodies"], len(O.bodies))
same("Scene.interactions", c["interactions"], len(O.interactions))
same("Scene.forces", c["force0"], force0)
same("Scene.energy", c["energyNames"], len(O.energy.keys()))
same("Cell.hSize", c["hSize"], O.cell.hSize)
same("Cell.velGrad", c["velGrad"], O.cell.velGrad)
same("Cell.prevHSize", c["prevHSize"], O.cell.prevHSize)
same("Cell.intrShiftPos", c["intrShiftPos100"], O.cell.hSize * Vector3(1, 0, 0))
same("Cell.intrShiftVel", c["intrShiftVel100"], (O.cell.velGrad * O.cell.prevHSize) * Vector3(1, 0, 0))
print(f"layout check: {len(checked)} sizes and members of the installed YADE agree with the headers")
