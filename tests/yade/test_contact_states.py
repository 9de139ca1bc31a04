# ctest (inside yade): the contact states a user can see (issue #33 item 7). A head-on collision
# beyond the plastic limit with the tensile branch and reversible adhesion passes every branch in
# the order the law prescribes (nonContact pull-in, loading k1, limit kp, unloading k2, tensile
# -kc delta, nonContact pull-off, gone); MesoPhys.dict() holds the meso state and the pair's
# parameters; scene.branch_fractions() sums to 1; scene.export_contacts() writes a legacy VTK file
# with every field of scene.VTK_CONTACT_FIELDS, one value per contact.
import math
import os
import tempfile

from yade import O
from mesocontact import pair, scene, theory
from harness import check, finish

law = dict(k1=100, kp=500, kc=100, phiF=0.1, fa=1e-5, kca=100, adhesion="reversible")
R = 1e-3
# a speed beyond the plastic limit, so that the limit branch is reached
s0 = pair.build(R, 0.1, law, steps_per_contact=4000)
v_p = theory.plastic_limit_velocity(100, 500, 0.1, s0.a12, s0.m_r, 1e-5)
s = pair.build(R, 2 * v_p, law, steps_per_contact=4000)
seen = []
for _ in range(400000):
    O.step()
    i = O.interactions[s.ids[0], s.ids[1]]
    b = i.phys.branch if i is not None and i.isReal else "gone"
    if not seen or seen[-1] != b:
        seen.append(b)
    if b == "gone" and "tensile" in seen:
        break
# real from the pull-in on
want = ["gone", "nonContact", "loading", "limit", "unloading", "tensile", "nonContact", "gone"]
got = [b for b in seen if b != "apart"]
check(got == want, "a collision beyond the plastic limit passes every branch in order", " -> ".join(seen))

s = pair.build(R, 0.5 * v_p, law, steps_per_contact=4000)
while True:
    O.step()
    i = O.interactions[s.ids[0], s.ids[1]]
    if i is not None and i.isReal and i.phys.branch == "unloading":
        break
d = i.phys.dict()
need = {"kn", "normalForce", "deltaMax", "delta0", "k2", "branch", "hystereticForce", "adhesiveForce", "viscousForce",
        "k1", "kp", "kc", "phiF", "fa", "kca", "adhesion", "touched"}
check(need <= set(d) and d["branch"] == "unloading" and d["k2"] == i.phys.k2 and d["kp"] == 500,
      "MesoPhys.dict() holds the meso state and the pair's parameters", f"missing {sorted(need - set(d))}")
f = scene.branch_fractions()
check(abs(sum(f.values()) - 1) < 1e-15 and f["unloading"] == 1.0, "branch_fractions: one contact, unloading", str(f))
with tempfile.TemporaryDirectory() as tmp:
    name = scene.export_contacts(os.path.join(tmp, "contacts"))
    text = open(name).read() if name else ""
    fields = [k for k in scene.VTK_CONTACT_FIELDS if f"\n{k} " in text or f"SCALARS {k} " in text
              or f"VECTORS {k} " in text]
    check(name is not None and text.startswith("# vtk DataFile") and "CELL_DATA 1" in text
          and len(fields) == len(scene.VTK_CONTACT_FIELDS),
          "export_contacts: a legacy VTK file with every field, one cell", f"{os.path.basename(name or '')}: {fields}")


# Against a box and a facet, whose body positions lie 50 radii below and a third of the facet away:
# each contact is drawn from the sphere's centre to its contact point (within the radius), and the
# file is numbered O.iter, so that a second export at the same step overwrites it.
def vtk_points(path):
    words = open(path).read().split("POINTS ")[1].split("\n")
    n = int(words[0].split()[0])
    return [tuple(float(x) for x in ln.split()) for ln in words[1:1 + n]]


for kind in ("box", "facet"):
    s = pair.build_wall(R, 0.05, dict(law, fa=0.0, adhesion="none"), kind=kind, steps_per_contact=400)
    while not any(i.isReal and i.geom.penetrationDepth > 0 for i in O.interactions):
        O.step()
    ball = O.bodies[s.ids[1]]
    with tempfile.TemporaryDirectory() as tmp:
        name = scene.export_contacts(os.path.join(tmp, "c"))
        again = scene.export_contacts(os.path.join(tmp, "c"))
        ends = vtk_points(name)
        far = max(math.dist(p, ball.state.pos) for p in ends)
        check(name == again and name.endswith(f"-intrs-{O.iter:08d}.vtk") and len(os.listdir(tmp)) == 1,
              f"export_contacts ({kind}): numbered O.iter, a second export overwrites", os.listdir(tmp))
        check(len(ends) == 2 and far <= R, f"export_contacts ({kind}): the line ends within the sphere",
              f"farthest end {far / R:.3g} R from its centre (the {kind}'s body: "
              f"{math.dist(O.bodies[s.ids[0]].state.pos, ball.state.pos) / R:.3g} R)")
finish()
