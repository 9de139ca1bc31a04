# ctest (inside yade): the agglomerate study's pipeline on small agglomerates (about 35 primaries
# each, 90 s; `studies/scripts/agglomerate.py all --quick`): the carved radius recomputed, one
# connected cluster each, `move_to_gap` against brute-force surface distances, the cycles' turning
# points and one row per iteration, the fit's residual recomputed from the CSV with the law's a12,
# collisions that keep the momentum and lose kinetic energy (it failed with 7.5 times the start's
# before the carved pair was relaxed to 1e-12 of the energy scale), and the meso-particle pair in
# YADE against the closed form (1e-4); the wall cycles' turning points; a drawn approach direction:
# the placement against brute-force surface distances along it, the momentum in all three
# components, e = e_speed cos(deflection); the same direction followed to its end (bonds, the
# final gap, the spin's share); the sticking speed of the tension taken as adhesion; the
# library's agglomerate calls (`bulk.agglomerate`, `bulk.pair_cycles`, `bulk.collisions`) refuse bad
# arguments, naming them, and leave the scene as it was; a pull apart saved on the way and loaded again
# (Pair.pull_apart's checkpoint) gives the study's rows, every one.
import json
import math
import os
import tempfile

import numpy as np
from yade import O, Vector3
from mesocontact.bulk import agglomerate, pair_cycles
from mesocontact.bulk.collisions import Collision
from mesostudies.agglomerate import compare, make, study
from mesostudies.agglomerate.primaries import D0, SCALES
from harness import FirstSaveKept, check, finish

pair_cycles.PROGRESS_EVERY = 2.0  # the long strokes' progress lines, in the log (a full run prints one a minute)

out = tempfile.mkdtemp(prefix="agglomerate-")
study.main(["all", "--quick", "--out", out])
d = os.path.join(out, "quick")

# 1. The carved pair: two connected agglomerates, R the outer sphere about the centre of mass.
info = make.ensure(d, quick=True, progress=False)
check(info["block"]["built"].get("aspect") == [2, 1, 1], "the block is two cubes",
      str(info["block"]["built"].get("aspect")))
for k, (ids, a) in enumerate(zip(info["members"], info["agglomerates"])):
    pos = np.array([list(O.bodies[i].state.pos) for i in ids])
    rad = np.array([O.bodies[i].shape.radius for i in ids])
    mass = np.array([O.bodies[i].state.mass for i in ids])
    c = (mass[:, None] * pos).sum(0) / mass.sum()
    r_out = float((np.linalg.norm(pos - c, axis=1) + rad).max())
    check(len(ids) >= 20, f"agglomerate {k}: {len(ids)} primaries")
    check(abs(r_out - a["radius"]) < 1e-12 * a["radius"],
          f"agglomerate {k}: R = {a['radius'] / D0:.4f} d0 is the outer sphere about the centre of mass",
          f"recomputed {r_out / D0:.6f}")
    check(a["radius"] <= info["carve_radius"] * 1.01 + 0.01 * D0,
          f"agglomerate {k}: within the carved sphere (grown by relaxing at most 1 %)")

O.step()  # the loaded state's contact geometry
for k, ids in enumerate(info["members"]):
    check(len(agglomerate.clusters(ids)) == 1, f"agglomerate {k}: one connected cluster")

# 2. move_to_gap: the surfaces (not the outer spheres) are gap apart along x: brute force over all pairs.
A, B = info["members"]
gap = 0.05 * D0
agglomerate.move_to_gap(A, B, gap)
pa = np.array([list(O.bodies[i].state.pos) for i in A])
pb = np.array([list(O.bodies[i].state.pos) for i in B])
ra = np.array([O.bodies[i].shape.radius for i in A])
rb = np.array([O.bodies[i].shape.radius for i in B])
side = 1.0 if pb[:, 0].mean() > pa[:, 0].mean() else -1.0


def surface_gap(t):
    """The smallest surface distance of any pair with B moved t towards A along x."""
    q = pb - np.array([side * t, 0, 0])
    return float((np.linalg.norm(pa[:, None, :] - q[None, :, :], axis=2) - ra[:, None] - rb[None, :]).min())


check(surface_gap(0.0) > 0 and abs(surface_gap(gap)) < 1e-9 * D0,
      "move_to_gap: the surfaces touch after moving the gap",
      f"gap {surface_gap(0.0) / D0:.4f} d0 apart, {surface_gap(gap) / D0:.2e} d0 after moving {gap / D0} d0")

# 2b. Another approach direction: placed beside the first along it, then gap apart along it.
n = np.array(agglomerate.directions(3, study.DIRECTION_SEED)[2])
check(abs(np.linalg.norm(n) - 1) < 1e-15, "agglomerate.directions: unit vectors")
agglomerate.place_along(A, B, tuple(n), [a["radius"] for a in info["agglomerates"]], protocol=SCALES)
agglomerate.move_to_gap(A, B, gap, tuple(n))
pa = np.array([list(O.bodies[i].state.pos) for i in A])
pb = np.array([list(O.bodies[i].state.pos) for i in B])


def surface_gap_n(t):
    q = pb - t * n
    return float((np.linalg.norm(pa[:, None, :] - q[None, :, :], axis=2) - ra[:, None] - rb[None, :]).min())


check((pb.mean(0) - pa.mean(0)) @ n > 0 and surface_gap_n(0.0) > 0 and abs(surface_gap_n(gap)) < 1e-9 * D0,
      "place_along, move_to_gap along a drawn direction: the surfaces touch after moving the gap along it",
      f"{surface_gap_n(0.0) / D0:.4f} d0 apart, {surface_gap_n(gap) / D0:.2e} d0 after moving {gap / D0} d0")

# 3. The cycles: turning points where asked, force > 0 at each loaded turn, caps rigid.
cyc = study._cycle_runs(d)
check(list(cyc) == ["cycles-v2.5"], "quick: one cycle run (no rate check)", str(list(cyc)))
run = cyc["cycles-v2.5"]
touch = run["touch_delta_mm"]
loaded = [e for e in run["events"] if e[0].startswith("loaded to")]
check(len(loaded) == len(study.AMPLITUDES[True]), "one loaded turn per amplitude")
for e, a in zip(loaded, study.AMPLITUDES[True]):
    over = (e[2] - touch) / D0 - a
    # the stroke stops at the first check past the target: delta moves about 2 v dt check (1e-4 d0) between checks
    check(0 <= over < 1e-3 and e[3] > 0,
          f"loaded to {a} d0: delta - delta_touch = {(e[2] - touch) / D0:.4f} d0, F = {e[3]:.3e} > 0")
unloaded = [e for e in run["events"] if e[0] == "unloaded"]
check(all(-0.21 < (e[2] - touch) / D0 <= -0.2 for e in unloaded), "each unloading turns 0.2 d0 below the first touch")
rows = [tuple(float(x) for x in line.split(","))
        for line in open(os.path.join(d, "cycles-v2.5.csv")).read().split("\n")[1:] if line]
check(len({r[0] for r in rows}) == len(rows), f"cycles CSV: {len(rows)} rows, one per iteration")

# 3b. Against a wall: the same turning points, the force on the wall repulsive at each loaded turn.
wrun = study._cycle_runs(d, "wall-cycles-v")
check(list(wrun) == ["wall-cycles-v2.5"], "quick: one wall cycle run", str(list(wrun)))
wr = wrun["wall-cycles-v2.5"]
wloaded = [e for e in wr["events"] if e[0].startswith("loaded to")]
for e, a in zip(wloaded, study.AMPLITUDES[True]):
    over = (e[2] - wr["touch_delta_mm"]) / D0 - a
    # one cap moves: delta moves about v dt check between checks
    check(0 <= over < 1e-3 and e[3] > 0, f"wall, loaded to {a} d0: {over:.2e} d0 beyond, F = {e[3]:.3e} > 0")
check(len(wloaded) == len(study.AMPLITUDES[True]) and wr["grip_particles"][0] > 0,
      "wall: one loaded turn per amplitude, one cap")

# 4. The fit's residual recomputed from the CSV and the fitted law (compare.law_curve: units, shift, a12).
summary = json.load(open(os.path.join(d, "agglomerate-vs-meso.json")))
fit = summary["fit"]
a12 = compare.geometry(info)[0]
law = compare.law_curve(fit, rows, a12)
res = np.array([r[2] for r in rows]) - np.array(law)
scale = max(abs(r[2]) for r in rows)
rms = float(np.sqrt(np.mean(res ** 2))) / scale
check(abs(rms - fit["rms_relative"]) < 1e-6 * fit["rms_relative"],
      f"fit residual {fit['rms_relative']:.4f} of the force scale, recomputed {rms:.4f}")
check(abs(fit["a12"] - a12) < 1e-15 * a12, "the fit used the law's a12 = 2 R1 R2/(R1 + R2)")

# 5. Collisions: no external force (momentum kept), energy lost, e in [0, 1]; meso pair = closed form.
hits = json.load(open(os.path.join(d, "collisions.json")))
for h in hits:
    check(h["touched"] and 0 <= h["e"] <= 1 and h["contact_time"] > 0,
          f"collision at {h['v_rel_m_s']} m/s: e = {h['e']:.4f}, contact time {h['contact_time']:.3g} us")
    crow = np.loadtxt(os.path.join(d, f"collision-v{h['v_rel_m_s']:g}.csv"), delimiter=",", skiprows=1)
    check(h["press_d0"] > 0 and abs(h["largest_normal_force"] - crow[:, 5].max()) == 0
          and abs(h["press_d0"] - (crow[:, 2].max() - crow[crow[:, 5] > 0][0, 2]) / D0) < 1e-12,
          f"collision at {h['v_rel_m_s']} m/s: press {h['press_d0']:.2e} d0 and largest force from its "
          f"{len(crow)} rows")
vis = summary["meso_viscous"]
k0 = summary["speeds"].index(vis["fitted_at_m_s"])
check(abs(vis["e_at_fit"] - summary["e_agglomerate"][k0]) < 1e-3 and vis["e_meso"][k0] == vis["e_at_fit"],
      f"gammaN = {vis['gammaN']:.4g} kg/s fitted: the viscous pair's e {vis['e_at_fit']:.4f} at "
      f"{vis['fitted_at_m_s']} m/s against the agglomerates' {summary['e_agglomerate'][k0]:.4f}")
for v, em, et in zip(summary["speeds"], summary["e_meso"], summary["e_theory"]):
    check(abs(em - et) < 1e-4, f"meso pair at {v} m/s: e = {em:.6f} (YADE) against {et:.6f} (closed form)")
info = make.ensure(d, quick=True, progress=False)
c = Collision(info["members"], [g["radius"] for g in info["agglomerates"]], protocol=SCALES)
masses = [sum(O.bodies[i].state.mass for i in m) for m in info["members"]]
v = 1.0 / 1e3
r = c.run(v, progress=False)
p = sum(O.bodies[i].state.mass * O.bodies[i].state.vel[0] for m in info["members"] for i in m)
s = 1.0 if agglomerate.centre_of_mass(info["members"][1])[0][0] > agglomerate.centre_of_mass(info["members"][0])[0][0] \
    else -1.0
p0 = s * 0.5 * v * (masses[0] - masses[1])
check(abs(p - p0) < 1e-9 * sum(masses) * v, "collision: momentum along x kept (no external force)",
      f"{p:.6e} against {p0:.6e}")
ke = sum(0.5 * O.bodies[i].state.mass * O.bodies[i].state.vel.squaredNorm() for m in info["members"] for i in m)
ke0 = 0.5 * sum(masses) * (0.5 * v) ** 2
check(ke < ke0 and math.isfinite(ke), f"collision: kinetic energy {ke / ke0:.3f} of the start's")
shares = r["energy_over_impact"]
check(abs(sum(shares.values()) - 1) < 1e-3,
      "collision: the impact's energy accounted for (centres of mass, internal motion, "
      "stored and dissipated by the law)", ", ".join(f"{k} {v:.4f}" for k, v in shares.items()))

# 6. A collision along a drawn direction: momentum kept in all three components; e, the speed ratio
# and the deflection agree (e = e_speed cos(deflection)).
info = make.ensure(d, quick=True, progress=False)
n = agglomerate.directions(2, study.DIRECTION_SEED)[1]
c = Collision(info["members"], [g["radius"] for g in info["agglomerates"]], axis=n, protocol=SCALES)
r = c.run(v, progress=False)
p = sum((O.bodies[i].state.vel * O.bodies[i].state.mass for m in info["members"] for i in m), Vector3(0, 0, 0))
p0 = Vector3(*n) * (0.5 * v * (masses[0] - masses[1]))
check((p - p0).norm() < 1e-9 * sum(masses) * v, "collision along a drawn direction: momentum kept", f"{p} against {p0}")
if not r["stuck"]:
    check(abs(r["e_speed"] * math.cos(math.radians(r["deflection_deg"])) - r["e"]) < 1e-12,
          f"e = {r['e']:.4f} is the speed ratio {r['e_speed']:.4f} times cos({r['deflection_deg']:.1f} deg)")

# 6b. The same direction faster, followed to its end (issue #59's ensemble): the run goes on until the
# fragments' surfaces are `follow` presses apart; the bonds counted before are each agglomerate's own
# contacts in overlap (describe's coordination x n / 2, counted there independently); spin takes a share.
info = make.ensure(d, quick=True, progress=False)
bonds0 = sum(round(g["coordination"] * g["n"] / 2) for g in info["agglomerates"])
c = Collision(info["members"], [g["radius"] for g in info["agglomerates"]], axis=n, protocol=SCALES)
r = c.run(10.0 / 1e3, progress=False, follow=3.0)
bonds_now = sum(round(agglomerate.describe(m, protocol=SCALES)["coordination"] * len(m) / 2) for m in info["members"])
check(r["bonds_before"] == bonds0 and bonds_now >= r["bonds_before"] - r["bonds_broken"],
      f"followed: {r['bonds_before']} bonds before (describe: {bonds0}), {r['bonds_broken']} broken; describe "
      f"counts {bonds_now} now, at least the survivors")
if not r["stuck"]:
    check(r["final_gap_over_press"] > 3.0 and r["time"] > 0,
          f"followed: the fragments end {r['final_gap_over_press']:.2f} presses apart (> 3)")
    # a glancing impact along a drawn direction sets the pair spinning; what the rigid motion keeps is at
    # most the impact's energy
    check(r["spin_energy_share"] > 0.01 and r["e_rigid"] <= 1,
          f"followed: e_rigid {r['e_rigid']:.3f}, the spins' share {r['spin_energy_share']:.3f} of the impact's energy")

# 7. The cycles' tension as a non-contact force: the pair sticks below the stated speed, not above.
from mesocontact import theory  # noqa: E402
for ad in summary["adhesion"]:
    a12, m_r = compare.geometry(info)[:2]

    def e_at(x):
        return theory.pair_collision(x, fit["k1"], fit["kp"], fit["kc"], fit["phiF"], a12, m_r, fa=ad["fa_N"],
                                     kca=ad["kca_N_m"],
                                     adhesion="jumpIn").e
    vs = ad["sticks_below_m_s"]
    check(e_at(0.99 * vs) == 0 and e_at(1.01 * vs) > 0,
          f"after {ad['after_d0']} d0: the pair sticks below {vs:.3g} m/s and rebounds above")

# 8. The library's agglomerate calls refuse bad arguments, naming them, before any work: the scene unchanged.
info = make.ensure(d, quick=True, progress=False)
A, B = info["members"]
radii = [g["radius"] for g in info["agglomerates"]]
before = (len(O.engines), [tuple(O.bodies[i].state.pos) for i in A + B])
bad = (("ids", agglomerate.centre_of_mass, ([],), {}), ("ids", agglomerate.clusters, ([10 ** 9],), {}),
       ("axis", agglomerate.move_to_gap, (A, B, 0.0), {"axis": (0, 0, 0)}),
       ("gap", agglomerate.move_to_gap, (A, B, -1.0), {}), ("count", agglomerate.directions, (0,), {}),
       ("radii", agglomerate.place_along, (A, B, (1, 0, 0), [1.0]), {"protocol": SCALES}),
       ("radius", agglomerate.carve, ([(0, 0, 0)], math.nan), {}),
       ("tol_ke", agglomerate.relax, ([A, B],), {"tol_ke": -1.0, "protocol": SCALES}),
       ("protocol", agglomerate.describe, (A,), {"protocol": "appendixF"}),
       ("grip", pair_cycles.Pair, ([A, B], radii), {"grip": 1.5, "protocol": SCALES}),
       ("material", pair_cycles.Wall, ([A, B], radii[0]), {"material": "glass", "protocol": SCALES}),
       ("members", Collision, ([A], radii), {"protocol": SCALES}),
       ("axis", Collision, ([A, B], radii), {"axis": (math.inf, 0, 0), "protocol": SCALES}))
for name, call, args, kw in bad:
    try:
        call(*args, **kw)
        refused = "no exception"
    except (TypeError, ValueError) as e:
        refused = str(e)
    check(refused.startswith(name), f"{call.__name__}: a bad {name} refused, naming it", refused)
check(before == (len(O.engines), [tuple(O.bodies[i].state.pos) for i in A + B]),
      "the refused calls left the scene as it was")

# 9. The library's one call (bulk.coarse.coarse_grain) on the same pair: with the study's cap speed and
# amplitudes its cycles are the study's cycles-v2.5 (the same state and code: every row equal), its
# collisions along x the study's at the same speeds, and the scene is given back as it was; the
# verdicts follow from the e's and the tolerance; bad arguments are refused, naming them.
from mesocontact.bulk import coarse  # noqa: E402
info = make.ensure(d, quick=True, progress=False)
A, B = info["members"]
radii = [g["radius"] for g in info["agglomerates"]]
start = [tuple(O.bodies[i].state.pos) for i in A + B]
for name, kw in (("speeds", {"speeds": []}), ("speeds[0]", {"speeds": [-1.0]}), ("directions", {"directions": 0}),
                 ("amplitudes[0]", {"amplitudes": (0.0,)}), ("tolerance", {"tolerance": math.nan}),
                 ("cap_speed", {"cap_speed": -1.0}), ("out", {"out": 3})):
    try:
        coarse.coarse_grain([A, B], radii, **{"speeds": [1e-3], **kw}, protocol=SCALES, progress=False)
        refused = "no exception"
    except (TypeError, ValueError) as e:
        refused = str(e)
    check(refused.startswith(name), f"coarse_grain: a bad {name} refused, naming it", refused)
cg_out = os.path.join(out, "coarse")
speeds = study.SPEEDS[True][:2]
cg = coarse.coarse_grain([A, B], radii, [v / 1e3 for v in speeds], directions=1, amplitudes=study.AMPLITUDES[True],
                         cap_speed=study.CAP_SPEED, out=cg_out, protocol=SCALES, progress=False)
check([tuple(O.bodies[i].state.pos) for i in A + B] == start, "coarse_grain: the scene given back as it was")
study_rows = [tuple(float(x) for x in line.split(","))
              for line in open(os.path.join(d, "cycles-v2.5.csv")).read().split("\n")[1:] if line]
f_scale = max(abs(r[2]) for r in study_rows)
same = all(abs(a[1] - b[1]) <= 1e-12 * abs(b[1]) and abs(a[2] - b[2]) <= 1e-9 * f_scale
           for a, b in zip(cg.cycle_rows, study_rows))
check(len(cg.cycle_rows) == len(study_rows) and same,
      f"coarse_grain: its cycles are the study's ({len(cg.cycle_rows)} rows against {len(study_rows)})")
with open(os.path.join(d, "collisions.json")) as f:
    study_e = {h["v_rel_m_s"]: h["e"] for h in json.load(f)}
for v, row in zip(speeds, cg.e_agglomerates):
    check(abs(row[0] - study_e[v]) < 1e-6,
          f"coarse_grain: e at {v} m/s along x {row[0]:.6f}, the study's {study_e[v]:.6f}")
holds = [abs(sum(r) / len(r) - e) <= 0.1 and max(b) <= 0.01 for r, e, b in zip(cg.e_agglomerates, cg.e_meso, cg.broken)]
with open(os.path.join(cg_out, "coarse-grained.json")) as f:
    js = json.load(f)
check(js["holds"] == holds and cg.holds() == holds and js["material"]["k1"] == cg.fit.params["k1"],
      f"coarse_grain: the verdicts {holds} follow from the e's; the JSON holds them and the material")
check(all(os.path.getsize(os.path.join(cg_out, f)) > 1000 for f in ("cycles.csv", "coarse-grained.png")),
      "coarse_grain: cycles.csv and coarse-grained.png written")

# 10. A pull apart saved on the way (Pair.pull_apart's checkpoint, as the hours-long pulls of issue #59 run),
# on the agglomerate against the wall (its quick pull holds on for 380000 steps; the pair's parts in 10):
# one cycle of 0.05 d0 and a pull to 0.6 d0 below the touch, run whole, then with a save every quarter of
# the pull, going on from each file as loaded: the same to rounding as the whole run (a load renews the
# collider's order of new contacts; here none form, and it is the same bit for bit); then the pull
# loaded from its first save (Pair.load, as a new process would), saving on: every row and event the
# saved run's, bit for bit; the checkpoint's files are removed at the end; a bad path is refused.


def wall_pull(**kw):
    info = make.ensure(d, quick=True, progress=False)
    w = pair_cycles.Wall(info["members"], info["agglomerates"][0]["radius"], progress=False, protocol=SCALES)
    return w, w.cycles((0.05,), study.CAP_SPEED, max_pull=0.6, **kw)


whole, rows = wall_pull()
pull_steps = whole.events[-1][1] - whole.events[-2][1]
ck, kept = os.path.join(out, "pull.checkpoint.yade.gz"), os.path.join(out, "kept.yade.gz")
with FirstSaveKept(pair_cycles.Wall, kept) as first:
    saved, rows_saved = wall_pull(checkpoint=ck, checkpoint_steps=max(1, pull_steps // 4))
saves = first.steps
check(len(saves) >= 3 and rows_saved == rows and saved.events == whole.events,
      f"checkpoint: {len(saves)} saves in a pull of {pull_steps} steps ({whole.events[-1][0]}), every one of "
      f"{len(rows)} rows and the events as in the whole run")
check(not os.path.exists(ck) and not os.path.exists(ck + ".json"), "checkpoint: its files removed at the end")
resumed = pair_cycles.Wall.load(kept)
check(O.iter == saves[0] and len(resumed.rows) < len(rows), f"checkpoint: loaded at step {O.iter}, the first save")
again = resumed.pull_apart(study.CAP_SPEED, max_pull=0.6, checkpoint=ck, checkpoint_steps=max(1, pull_steps // 4))
check(again == rows_saved and resumed.events == saved.events,
      f"checkpoint: the pull loaded from its first save ends with the saved run's {len(again)} rows and events")
for bad in ("pull.xml", 3):
    try:
        resumed.save(bad)
        refused = "no exception"
    except ValueError as e:
        refused = str(e)
    check(refused.startswith("path"), f"save: a bad path {bad!r} refused, naming it", refused)

for f in ("cycles.png", "wall-cycles.png", "restitution.png", "agglomerate-vs-meso.json"):
    check(os.path.getsize(os.path.join(d, f)) > 1000, f"{f} written")
check(all(k in summary for k in ("fit", "speeds", "e_agglomerate", "e_meso", "e_theory", "fragmented")), "summary keys")
finish()
