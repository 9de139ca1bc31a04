# ctest (inside yade): the bulk sample's mould made of facets (Protocol(walls="facets"): one large
# triangle per face) instead of YADE boxes. The same gas compacted in either mould follows the same
# path to rounding (a flat facet and a box's face are the same plane to the law, and the stress
# controller reads a facet's plane where it reads a box's centre less its half thickness); the
# facet-walled sample reaches every stage's target, is unconfined, pulled through a tension cycle
# and pressed in a die of facets, and is drawn with its walls.
import os
import tempfile
import types

from yade import O, Vector3, utils
from yade import wrapper as w

from mesocontact import bulk, mpi
from mesocontact.bulk import pictures, sample, sintering, uniaxial
from harness import check, die_start, finish

USER = dict(density=2500.0, k1=125.0, kp=250.0, kc=25.0, phiF=0.05, gammaN=1.25e-5, frictionAngle=0.5,
            kt=50.0, gammaT=2.5e-6, kr=25.0, gammaR=1.25e-6, muR=0.1, ko=25.0, gammaO=1.25e-6, muO=0.1)
D0 = 1e-4
out = tempfile.mkdtemp(prefix="bulk-facets-")
p = bulk.Protocol.ratios(USER, D0, sinter=0.02, n=64, seed=3, release_steps=4000, packing="frictionless",
                         walls="facets")

# 1. The same gas, compacted 4000 steps in boxes and in facets with the smooth mould (68 wall
# contacts at the end), then 2000 steps with all six walls glued (the adhesive walls' law: kc,
# friction, rolling and torsion at the walls): the spheres and the walls stay together to rounding.
# Measured 8e-14 d0 (positions) and 2e-14 d0 (faces) after the first part; a wall placed or read a
# hair off (the controller's thickness, a facet's plane) moves them apart by 7e-2 d0, far more than
# the 1e-10 d0 allowed.
paths = {}
for walls in ("boxes", "facets"):
    q = p.replace(walls=walls)
    sample.build(q)
    O.engines = sample.engines(q, sintering.controller(q, q.sinter_stress), reference="lab")
    if walls == "facets":
        check(all(isinstance(O.bodies[i].shape, w.Facet) for i in range(6)) and sorted(sample.wall_ids().values())
              == list(range(6)), "facets: six walls, a Facet each, ids 0-5")
    for part in ("mould", "glued"):
        if part == "glued":
            sample.make_adhesive_walls(list(range(6)), q)
        O.run(4000 if part == "mould" else 2000, True)
        paths[walls, part] = ([O.bodies[i].state.pos for i in sample.sphere_ids()], sample.inner_box(),
                              [O.forces.f(i) for i in range(6)], [O.forces.t(i) for i in range(6)],
                              sum(1 for i in O.interactions if i.isReal and i.id1 < 6 and i.geom.penetrationDepth > 0))
for part in ("mould", "glued"):
    (pb, box_b, fb, tb, nb), (pf, box_f, ff, tf, nf) = paths["boxes", part], paths["facets", part]
    gap = max((a - b).norm() for a, b in zip(pb, pf)) / D0
    faces = max(abs(a - b) for x, y in zip(box_b, box_f) for a, b in zip(x, y)) / D0
    force = max((a - b).norm() for a, b in zip(fb, ff)) / max(a.norm() for a in fb)
    check(nb == nf > 30 and gap < 1e-10 and faces < 1e-10 and force < 1e-9,
          f"{part}: the same spheres, faces and wall forces in facets as in boxes, to rounding",
          f"{nf} wall contacts, positions {gap:.1e} d0, faces {faces:.1e} d0, wall forces {force:.1e}")

# 2. Prepared in facets: every stage meets its targets; the protocol travels with the scene.
path = os.path.join(out, "released.yade.gz")
info = bulk.prepare(path, p, progress=False)
p_s = 0.02 * 250.0 / D0
e_ref = 3 * 64 * (p_s * D0 * D0) ** 2 / (2 * 250.0)
# (the stages' own stopping rule: a stage that never met it would have raised)
for stage, goal in (("packed", p_s * 0.1), ("sintered", p_s), ("released", p_s * 1e-3)):
    s = info[stage]
    worst = max(abs(v / goal - 1.0) for v in s["wall_stress"].values())
    check(len(s["wall_stress"]) == 6 and worst < 0.01 and s["kinetic_energy"] < 1e-4 * e_ref,
          f"facets, {stage}: six walls each within 1 % of its goal, at rest",
          f"|stress/goal - 1| <= {worst:.2e}, E_kin/E_ref = {s['kinetic_energy'] / e_ref:.2e}")
sf = info["released"]["solid_fraction"]
check(info["built"].get("walls") == "facets" and 0.45 < sf < 0.75 and info["released"]["coordination"] > 3,
      "facets, released: described as such, a dense, connected packing",
      f"solid fraction {sf:.3f}, coordination {info['released']['coordination']:.2f}")
O.reset()
O.load(path)
check(sample.current() == p and bulk.Protocol.from_json(p.to_json()).walls == "facets",
      "the facet protocol comes back from the saved scene")
# Drawn with its six facets: each as its face, so the frame is the sample's (a facet's triangle
# reaches three faces' widths beyond it).
lo, hi = sample.inner_box()
win = pictures.window(margin=1.0, d0=D0)
check(win[1] - win[0] <= hi[0] - lo[0] + 2.5 * D0 + 1e-12 * D0,
      "drawn with its six facets: the frame holds the sample, its faces and the margin only",
      f"{(win[1] - win[0]) / D0:.3f} d0 for a sample {(hi[0] - lo[0]) / D0:.3f} d0 long")
# A box added by a tool (pair_cycles.Wall adds one) still meets the spheres in a facet-walled scene.
ball = O.bodies[sample.sphere_ids()[0]]
c = ball.state.pos + Vector3(ball.shape.radius, 0, 0)
probe = O.bodies.append(utils.box(c, (0.1 * D0, 0.1 * D0, 0.1 * D0), fixed=True, material="walls"))
O.step()
check(O.interactions.has(probe, ball.id) and O.interactions[probe, ball.id].isReal,
      "a box added to a facet-walled scene makes its contact (the box functors stay)")
O.bodies.erase(probe)
try:  # MPI hands only boxes to the master: refused before any work
    mpi.split_slabs(types.SimpleNamespace(numThreads=2, rank=0), keep=False)
    refused = "no exception"
except ValueError as e:
    refused = str(e)
check("walls='facets'" in refused and not getattr(O, "splitted", False), "split_slabs refuses a facet-walled scene",
      refused)
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
# the bound of yade.bulk_user's pull through boxes: the walls' work summed first order in dt
check(abs(bal["residual_over_gross"]) < 2e-3, "energy balance through facets: the walls' work is the energy change",
      f"(dE - W)/gross = {bal['residual_over_gross']:.2e}")
png = os.path.join(out, "facets.png")
win = pictures.window(margin=1.0, d0=D0)
left = O.bodies[walls["left"]].state.pos[0]
check(abs(win[0] - (left - 0.25 * D0 - D0)) < 1e-12 * D0, "drawn: the window holds the left facet, a quarter d0 thick")
pictures.png(png, "facets", win=win, d0=D0)
check(os.path.getsize(png) > 10000, "a picture of the sample between its facets")

# 4. The die: the four lateral facets stay, the x facets press by 0.05 d0.
before, lateral, die = die_start(path)
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
