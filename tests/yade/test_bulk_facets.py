# ctest (inside yade): the bulk sample's mould made of facets (Protocol(walls="facets"): one large
# triangle per face) instead of YADE boxes. The same gas compacted in either mould follows the same
# path to rounding (a flat facet and a box's face are the same plane to the law, and the stress
# controller reads a facet's plane where it reads a box's centre less its half thickness); the
# facet-walled sample reaches every stage's target, is unconfined, pulled through a tension cycle
# and pressed in a die of facets, and is drawn with its walls.
import os
import tempfile

from yade import O
from yade import wrapper as w
from mesocontact import bulk
from mesocontact.bulk import pictures, sample, sintering, uniaxial
from harness import check, finish

USER = dict(density=2500.0, k1=125.0, kp=250.0, kc=25.0, phiF=0.05, gammaN=1.25e-5, frictionAngle=0.5,
            kt=50.0, gammaT=2.5e-6, kr=25.0, gammaR=1.25e-6, muR=0.1, ko=25.0, gammaO=1.25e-6, muO=0.1)
D0 = 1e-4
out = tempfile.mkdtemp(prefix="bulk-facets-")
p = bulk.Protocol.ratios(USER, D0, sinter=0.02, n=64, seed=3, release_steps=4000, packing="frictionless",
                         walls="facets")

# 1. The same gas, compacted 4000 steps in boxes and in facets (about 65 wall contacts at the end):
# the spheres and the walls stay together to rounding. Measured 7e-14 d0 (positions) and 2e-14 d0
# (faces); a wall placed or read a hair off (the controller's thickness, a facet's plane) moves
# them apart by far more than the 1e-10 d0 allowed.
paths = {}
for walls in ("boxes", "facets"):
    q = p.replace(walls=walls)
    sample.build(q)
    O.engines = sample.engines(q, sintering.controller(q, q.sinter_stress), reference="lab")
    if walls == "facets":
        check(all(isinstance(O.bodies[i].shape, w.Facet) for i in range(6)) and sorted(sample.wall_ids().values())
              == list(range(6)), "facets: six walls, a Facet each, ids 0-5")
    O.run(4000, True)
    paths[walls] = ([O.bodies[i].state.pos for i in sample.sphere_ids()], sample.inner_box(),
                    [O.forces.f(i) for i in range(6)],
                    sum(1 for i in O.interactions if i.isReal and i.id1 < 6 and i.geom.penetrationDepth > 0))
(pb, box_b, fb, nb), (pf, box_f, ff, nf) = paths["boxes"], paths["facets"]
gap = max((a - b).norm() for a, b in zip(pb, pf)) / D0
faces = max(abs(a - b) for x, y in zip(box_b, box_f) for a, b in zip(x, y)) / D0
force = max((a - b).norm() for a, b in zip(fb, ff)) / max(a.norm() for a in fb)
check(nb == nf > 30 and gap < 1e-10 and faces < 1e-10 and force < 1e-9,
      "compacted in facets as in boxes: the same spheres, faces and wall forces to rounding",
      f"{nf} wall contacts, positions {gap:.1e} d0, faces {faces:.1e} d0, wall forces {force:.1e}")

# 2. Prepared in facets: every stage meets its targets; the protocol travels with the scene.
path = os.path.join(out, "released.yade.gz")
info = bulk.prepare(path, p, progress=False)
p_s = 0.02 * 250.0 / D0
e_ref = 3 * 64 * (p_s * D0 * D0) ** 2 / (2 * 250.0)
for stage, goal in (("packed", p_s * 0.1), ("sintered", p_s), ("released", p_s * 1e-3)):
    s = info[stage]
    worst = max(abs(v / goal - 1.0) for v in s["wall_stress"].values())
    check(len(s["wall_stress"]) == 6 and worst < 0.01 and s["kinetic_energy"] < 1e-4 * e_ref,
          f"facets, {stage}: every wall within 1 % of its goal, at rest",
          f"|stress/goal - 1| <= {worst:.2e}, E_kin/E_ref = {s['kinetic_energy'] / e_ref:.2e}")
sf = info["released"]["solid_fraction"]
check(info["built"].get("walls") == "facets" and 0.45 < sf < 0.75 and info["released"]["coordination"] > 3,
      "facets, released: described as such, a dense, connected packing",
      f"solid fraction {sf:.3f}, coordination {info['released']['coordination']:.2f}")
O.reset()
O.load(path)
check(sample.current() == p and bulk.Protocol.from_json(p.to_json()).walls == "facets",
      "the facet protocol comes back from the saved scene")
check('"walls"' not in p.replace(walls="boxes").to_json(), "a box mould's protocol is saved as before (no walls key)")

# 3. Unconfined and one tension cycle of 0.05 d0 through the two facets left.
uniaxial.make_unconfined(progress=False)
walls = sample.wall_ids()
check(sorted(walls) == ["left", "right"] and all(isinstance(O.bodies[i].shape, w.Facet) for i in walls.values()),
      "unconfined: the two x facets are left")
t = uniaxial.Test(progress=False)
t.track_energy()
faces = []
t.cycles("tension", 0.05, n_cycles=1, period=40.0, on_record=lambda test, row: faces.append(
    O.bodies[walls["right"]].state.pos[0] - O.bodies[walls["left"]].state.pos[0]))
stretch = max(faces) - t.L0
check(abs(stretch - 0.05 * D0) < 1e-3 * 0.05 * D0 and abs(t.rows[-1][1]) < 1e-9,
      "the facets' planes move apart by 0.05 d0 and come back", f"{stretch:.6e} m")
check(min(r[2] for r in t.rows) < 0, "the sample glued to the facets resists tension (F < 0)")
bal = t.energy_balance()
check(abs(bal["residual_over_gross"]) < 2e-3, "energy balance through facets (as through boxes)",
      f"(dE - W)/gross = {bal['residual_over_gross']:.2e}")
png = os.path.join(out, "facets.png")
win = pictures.window(margin=1.0, d0=D0)
left = O.bodies[walls["left"]].state.pos[0]
check(abs(win[0] - (left - 0.25 * D0 - D0)) < 1e-12 * D0, "drawn: the window holds the left facet, a quarter d0 thick")
pictures.png(png, "facets", win=win, d0=D0)
check(os.path.getsize(png) > 10000, "a picture of the sample between its facets")

# 4. The die: the four lateral facets stay, the x facets press by 0.05 d0.
O.reset()
O.load(path)
before = {k: tuple(O.bodies[i].state.pos) for k, i in sample.wall_ids().items()}
uniaxial.make_confined(progress=False)
lateral = {k: i for k, i in sample.wall_ids().items() if k not in ("left", "right")}
die = uniaxial.Test(progress=False)
s0 = sample.stats()["wall_stress"]
die.compress(p.speeds()[1], until=0.05, every=2)
s1 = sample.stats()["wall_stress"]
check(sorted(lateral) == ["back", "bottom", "front", "top"]
      and all(tuple(O.bodies[i].state.pos) == before[k] for k, i in lateral.items())
      and all(s1[k] > 2 * s0[k] > 0 for k in lateral), "die of facets: the side facets stay put and carry more stress",
      ", ".join(f"{k} {s0[k]:.3g} -> {s1[k]:.3g} Pa" for k in sorted(lateral)))
try:
    p.replace(walls="cylinder")
    check(False, "Protocol refuses walls")
except ValueError as e:
    check("walls" in str(e), "Protocol refuses walls", str(e))
finish()
