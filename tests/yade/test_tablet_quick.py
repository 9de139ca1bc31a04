# ctest (inside yade): the tablet campaign in quick mode (216 particles, one cycle): the full law
# from the start, stress targets and rest after sintering and release, lateral walls gone, the
# adhesive wall law on the wall contacts with their sintering history kept (and `adoptMaterials`
# refusing a change of k1), drag relative to the contacts, cycles back to zero strain at the set
# amplitude, tension re-loading with positive slope, the first visible crack and the last contact
# chain of the pull, zero mean force on the detached halves, snapshots that are pictures of shaded
# spheres in one frame; the crack measures on known pictures (a ring of spheres, a layer with a
# missing block); the time-step study at 1 and 2 times the campaign's step closes its energy balance
# (the walls' work against kinetic + stored + dissipated energy) within 1e-3.
import glob
import json
import math
import os
import tempfile

import numpy as np
from yade import O, utils
from yade import wrapper as w
from mesocontact import outputs
from mesostudies.tablet import sample as tablet
from mesostudies.tablet import campaign, snapshots, uniaxial
from harness import check, finish


# 1. The crack measures on known pictures (seen from -y). A ring of 12 touching spheres encloses
#    a see-through hole; a sphere behind covers it.
O.reset()
r = 0.5 * tablet.D0
R = r / math.sin(math.pi / 12)
O.bodies.append([utils.sphere((R * math.cos(2 * math.pi * k / 12), 0, R * math.sin(2 * math.pi * k / 12)), r)
                 for k in range(12)])
hole = snapshots.see_through_holes(pixel=tablet.D0 / 40)
inner = (R - r) ** 2 * math.pi / tablet.D0 ** 2  # the inscribed disk lies inside the hole
check(inner < hole < 1.2 * math.pi * R ** 2 / tablet.D0 ** 2,
      f"ring of spheres: hole {hole:.3f} d0^2 (> inscribed disk {inner:.3f})")
O.bodies.append(utils.sphere((0, 0.02, 0), R + 0.5 * r))
check(snapshots.see_through_holes(pixel=tablet.D0 / 40) == 0, "ring covered by a sphere behind: no hole")
# A front layer (square lattice, spacing d0) 5 d0 before a back layer: no crack; with a 3 x 3
# block of the front layer missing, a crack of about 3 x 3 d0^2 (less the neighbours' overhang).
for missing in (False, True):
    O.reset()
    d = tablet.D0
    front = [(i * d, 0.0, k * d) for i in range(12) for k in range(12) if not (missing and 4 <= i <= 6 and 4 <= k <= 6)]
    back = [(i * d, 5 * d, k * d) for i in range(12) for k in range(12)]
    O.bodies.append([utils.sphere(c, r) for c in front + back])
    area = snapshots.visible_gap(pixel=d / 20)
    if missing:  # 9 empty cells and the 28 quarter pores of the touching lattice around them
        expect = 9 + 28 * (1 - math.pi / 4) / 4
        check(abs(area - expect) < 0.3,
              f"front layer with a 3x3 block missing: crack {area:.2f} d0^2 (cells and pores {expect:.2f})")
    else:
        check(area < 1.0, f"whole front layer: largest deep region {area:.2f} d0^2 < 1 (the lattice's pores)")

# The contacts crossing planes x = const (uniaxial.crossing_profile), on a known sample: two
# walls 10 d0 apart (ids 0, 1 as in the tablet) and two chains of ten spheres of radius
# 0.5005 d0, d0 apart, from wall to wall, every contact in overlap; in the second chain the last
# six spheres are shifted by 0.002 d0, which opens the contact between its 4th and 5th sphere
# (centres 3.5 and 4.502 d0 from the left face). With planes 0.25 d0 apart (40), every plane
# crosses two contacts except the four between 3.5 and 4.502 d0, which cross one: the weakest
# is the first of them, 3.625 d0 from the left face, 6.375 from the right; the mean is 1.9.
O.reset()
d, L = tablet.D0, 10 * tablet.D0
O.bodies.append(utils.box((-0.25 * d, 0, 2 * d), (0.25 * d, 5 * d, 5 * d), fixed=True))
O.bodies.append(utils.box((L + 0.25 * d, 0, 2 * d), (0.25 * d, 5 * d, 5 * d), fixed=True))
for z, shift in ((0.0, 0.0), (3 * d, 0.002 * d)):
    O.bodies.append([utils.sphere(((k + 0.5) * d + (shift if k >= 4 else 0.0), 0, z), 0.5005 * d) for k in range(10)])
O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb(), w.Bo1_Box_Aabb()]),
             w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom(), w.Ig2_Box_Sphere_ScGeom()],
                               [w.Ip2_FrictMat_FrictMat_FrictPhys()],
                               [w.Law2_ScGeom_FrictPhys_CundallStrack()]), w.NewtonIntegrator()]
O.dt = 1e-9
O.step()
prof = uniaxial.crossing_profile(spacing=0.25)
expect = [1 if 3.5 < x < 4.502 else 2 for x in prof["x"]]
wk = prof["weakest"]
check(len(prof["x"]) == 40 and prof["count"] == expect and abs(prof["mean"] - 1.9) < 1e-12
      and abs(wk["from_left_d0"] - 3.625) < 1e-9 and abs(wk["from_right_d0"] - 6.375) < 1e-9 and wk["count"] == 1,
      f"crossing profile of two chains, one open: weakest plane {wk}, mean {prof['mean']}")
# Planes nearer than 0.5 d0 to a wall's face cross only the glued wall's contacts: not the weakest.
syn = {"x": [0.125, 0.375, 0.625, 5.0, 9.875], "count": [1, 3, 4, 2, 1], "length_d0": 10.0}
wk = uniaxial.weakest_plane(syn)
check(wk == {"count": 2, "from_left_d0": 5.0, "from_right_d0": 5.0}
      and uniaxial.weakest_plane(syn, margin=0)["count"] == 1,
      f"weakest plane away from the walls' faces: {wk}")

out = tempfile.mkdtemp(prefix="tablet-quick-")

# 2. Preparation: the full law from the start, targets reached and static.
info = campaign.prepare(out, quick=True)
# Stage files that cannot be used are made again, not loaded: a truncated state, a truncated
# description, a state without its description.
from mesostudies.tablet import stages  # noqa: E402

p_unc = stages.path("unconfined", out, quick=True)
for damage in ("truncated state", "truncated JSON", "kc_over_kp as text", "no JSON"):
    if damage == "truncated state":
        data = open(p_unc, "rb").read()
        open(p_unc, "wb").write(data[: len(data) // 2])
    elif damage == "truncated JSON":
        open(p_unc + ".json", "w").write('{"built": {"n": 2')
    elif damage == "kc_over_kp as text":  # it ended in a TypeError without the file's name
        j = json.load(open(p_unc + ".json"))
        j["built"]["kc_over_kp"] = "abc"
        json.dump(j, open(p_unc + ".json", "w"))
    else:
        os.remove(p_unc + ".json")
    again = campaign.prepare(out, quick=True, progress=False)
    check(len(tablet.sphere_ids()) == info["built"]["n"]
          and all(again["built"][k] == info["built"][k] for k in ("n", "material", "kc_over_kp"))
          and os.path.exists(p_unc + ".json"),
          f"stage with a {damage}: made again and loaded")
info = campaign.prepare(out, quick=True)
particles = [m for m in O.materials if m.label == "particles"][0]
check(abs(particles.kc - 0.2 * tablet.KP) < 1e-12 and particles.muR == 0.2 and particles.frictionAngle > 0,
      "particles carry the Appendix F law (kc/kp = 0.2, mu_r = 0.2, friction) from the start")
for stage, goal in (("sintered", tablet.SINTER_STRESS), ("released", tablet.RELEASE_RATIO * tablet.SINTER_STRESS)):
    s = info[stage]
    err = max(abs(v / goal - 1) for v in s["wall_stress"].values())
    check(err < 0.01, f"{stage}: six wall stresses within 1% of {goal:g} (worst {err:.2e})")
    check(s["kinetic_energy_ratio"] < 1e-4, f"{stage}: at rest, E_kin/E_ref = {s['kinetic_energy_ratio']:.1e}")
    check(0.3 < s["solid_fraction"] < 0.74 and s["coordination"] > 2,
          f"{stage}: solid fraction {s['solid_fraction']:.3f}, "
          f"C {s['coordination']:.2f}, with walls {s['coordination_with_walls']:.2f}, rattlers {s['rattlers']}")
p_r = 2e-5 * tablet.KP / tablet.D0  # the paper's d0 p_r/kp = 2e-5
check(all(abs(v / p_r - 1) < 0.01 for v in info["released"]["wall_stress"].values()),
      f"release stress is d0 p_r/kp = 2e-5 (p_r = {p_r:g})")
u = info["unconfined"]
check(u["force_error"] < 1e-4 and u["kinetic_energy_ratio"] < 1e-4,
      f"unconfined start: wall force at p_r A to {u['force_error']:.1e} kp d0, at rest "
      f"({u['kinetic_energy_ratio']:.1e})")

# 3. The unconfined start: two walls, adhesive, whose contacts kept their sintering history.
test = uniaxial.Test(progress=False)
check(abs(test.force() - u["target_force"] / (tablet.KP * tablet.D0)) < 1e-4,
      f"test starts at rest: F/(kp d0) = {test.force():.2e}")
check(set(tablet.wall_ids()) == {"left", "right"}, "lateral walls removed")
drag = [e for e in O.engines if isinstance(e, w.MesoBackgroundDamping)]
check(len(drag) == 1 and drag[0].reference == "contacts", "tests: background drag relative to the contacts")
wall_contacts = [I for I in O.interactions if I.isReal and test.left in (I.id1, I.id2) and I.geom.penetrationDepth > 0]
check(len(wall_contacts) > 0 and all(abs(I.phys.kc - 20 * tablet.KP) < 1e-12 and abs(I.phys.muS - 10) < 1e-12
                                     for I in wall_contacts),
      f"{len(wall_contacts)} wall contacts with kc = 20 kp and mu = 10 (adhesive wall material)")
mould = [m for m in O.materials if m.label == "walls"][0]
check(mould.kc == 0 and mould.frictionAngle == 0, "the other walls' material stays the smooth mould")
kept = sum(1 for I in wall_contacts if I.phys.deltaMax > 1.5 * I.geom.penetrationDepth)
check(kept > len(wall_contacts) // 2,
      f"wall contacts kept their sintering history: {kept}/{len(wall_contacts)} with deltaMax > 1.5 x overlap")
ip2 = [e for e in O.engines if isinstance(e, w.InteractionLoop)][0].physDispatcher.functors[0]
walls_mat = [m for m in O.materials if m.label == "loading walls"][0]
walls_mat.k1 = 0.3 * tablet.KP
try:
    ip2.adoptMaterials(wall_contacts[0])
    check(False, "adoptMaterials refuses a change of k1")
except ValueError as e:
    check("k1" in str(e), f"adoptMaterials refuses a change of k1: {e}")
try:  # a pull that would take forever is refused before it starts (it used to hang)
    test.pull(1e-300, until=9.0)
    check(False, "pull at speed 1e-300 refused")
except ValueError as e:
    check(str(e).startswith("speed = 1e-300 is invalid"), f"pull at speed 1e-300 refused: {e}")
try:
    test.cycles("shear", 0.1)
    check(False, "bad mode rejected")
except ValueError as e:
    check(str(e).startswith("mode"), f"bad mode rejected: {e}")

# 4. Cycles in tension and compression at the campaign's fast period.
summaries = {}
for mode in ("tension", "compression"):
    amps = (0.05, 0.2)
    summary = summaries[mode] = campaign.cyclic(mode, out, amps, quick=True, periods=campaign.PERIODS[mode][:1],
                                                progress=False)
    for amp in amps:
        name = campaign.run_name(mode, amp, campaign.PERIODS[mode][0])
        run = summary["runs"][name]
        check(abs(run["final_Dx"]) < 1e-9, f"{name}: back to zero strain (Dx = {run['final_Dx']:.1e})")
        check(abs(run["max_abs_Dx"] / amp - 1) < 1e-3, f"{name}: amplitude reached ({run['max_abs_Dx']:.5f})")
        rows = campaign.read_csv(os.path.join(campaign.run_dir(out, name, quick=True), name + ".csv"))
        check(all(math.isfinite(x) for r in rows for x in r), f"{name}: {len(rows)} finite records")
        peak = max(range(len(rows)), key=lambda k: abs(rows[k][1]))
        if mode == "tension":
            check(min(r[2] for r in rows[:peak + 1]) < 0, f"{name}: tensile force on the way out ({run['peaks']})")
            back = rows[peak:]  # the return: compression coordinate u = -Dx grows
            uu = np.array([-r[1] for r in back])
            ff = np.array([r[2] for r in back])
            slope = np.polyfit(uu, ff, 1)[0]
            check(slope > 0, f"{name}: re-loading branch slope dF/du = {slope:.3g} > 0")
        else:
            check(max(r[2] for r in rows[:peak + 1]) > 0, f"{name}: compressive force on the way in ({run['peaks']})")
    fig = "fig16" if mode == "tension" else "fig18"
    figdir = os.path.join(campaign.root(out, quick=True), fig)
    check(outputs.complete(figdir) and os.path.exists(os.path.join(figdir, fig + ".png"))
          and all(os.path.exists(os.path.join(figdir, n + ".csv")) for n in summary["runs"]),
          f"{mode}: figure bundle complete, with its runs' CSV")

# 4a. The committed copies give the runs back: report into a docs folder, lose the runs, restore
#     them (each checked against its peaks) and regather the figure without running anything.
import shutil  # noqa: E402
import time  # noqa: E402

docs = tempfile.mkdtemp(prefix="tablet-docs-")
campaign.report(campaign.root(out, quick=True), docs)
runs_dir = os.path.join(campaign.root(out, quick=True), "runs")
before = {n: open(os.path.join(runs_dir, n, n + ".csv")).read() for n in os.listdir(runs_dir)}
shutil.rmtree(runs_dir)
names = campaign.restore(docs, out)
check(sorted(names) == sorted(before) and all(outputs.complete(os.path.join(runs_dir, n)) for n in names)
      and all(open(os.path.join(runs_dir, n, n + ".csv")).read() == before[n] for n in names),
      f"restore: {len(names)} runs from the docs copies, complete and identical")
t0 = time.time()
again = campaign.cyclic("tension", out, (0.05, 0.2), quick=True, periods=campaign.PERIODS["tension"][:1],
                        progress=False)
check(time.time() - t0 < 10 and again["runs"].keys() == summaries["tension"]["runs"].keys()
      and all(again["runs"][n]["peaks"] == summaries["tension"]["runs"][n]["peaks"] for n in again["runs"]),
      f"fig16 regathered from restored runs in {time.time() - t0:.1f} s")
name = campaign.run_name("tension", 0.2, campaign.PERIODS["tension"][0])
with open(os.path.join(docs, name + ".csv"), "a") as f:
    f.write("999999,0.0,-9.0\n")  # a row the run never made: its peaks change
shutil.rmtree(os.path.join(runs_dir, name))
try:
    campaign.restore(docs, out)
    check(False, "restore refuses a CSV that does not give its JSON's peaks")
except ValueError as e:
    check(name in str(e), f"restore refuses a tampered CSV: {e}")

for bad_docs, bad_out, says in ((os.path.join(docs, "missing"), out, "docsdir"), (docs, docs, "outdir")):
    try:
        campaign.restore(bad_docs, bad_out)
        check(False, f"restore refuses {says}")
    except ValueError as e:
        check(str(e).startswith(says), f"restore refuses a missing folder or itself as the target: {e}")

# Every run records the preparation it was made from; a file without it is of the first protocol.
protos = [info["protocol"] for m in summaries for info in summaries[m]["runs"].values()]
check(all(p == campaign.PROTOCOL for p in protos)
      and campaign.protocol_of({}) == {"packing": "full", "glue": "loading", "rel_std": 0.05},
      f"runs record their preparation {protos[0]}")

# 4b. Issue #47's variants on the same sample: cycles back to the start's force (E6) with kc/kp = 0.5
#     given to every contact on the unconfined start (E5).
P = campaign.PERIODS["tension"][0]
var = campaign.cyclic("tension", out, (0.1,), quick=True, periods=(P,), progress=False, returns="force", kc_over_kp=0.5)
name = "kc0.5-force-return-" + campaign.run_name("tension", 0.1, P)
run = var["runs"][name]
rows = campaign.read_csv(os.path.join(campaign.run_dir(out, name, quick=True), name + ".csv"))
(out_it, out_dx, _), (back_it, back_dx, back_f) = run["turns"]
# The turn is checked every quarter record: the walls move 0.1/800 d0 between checks.
check(0.1 <= out_dx <= 0.1 * (1 + 1.01 / 800), f"{name}: turned at the amplitude (Dx = {out_dx:.6f})")
inside = [r for r in rows if out_it < r[0] < back_it]
check(back_f >= rows[0][2] or back_dx <= 0, f"{name}: the return ended at the start's force {rows[0][2]:.3g} "
      f"(F = {back_f:.3g}, Dx = {back_dx:.3g})")
check(inside and all(r[2] < rows[0][2] and r[1] > 0 for r in inside),
      f"{name}: and not before ({len(inside)} records of the return below the start's force, at Dx > 0)")
check(run["peaks"] == [min(r[2] for r in rows if r[0] <= back_it)], f"{name}: the cycle's peak {run['peaks']}")
kcs = {round(I.phys.dict()["kc"] / tablet.KP, 12) for I in O.interactions if I.isReal}
check(run["tensile_stiffness"]["was"] == 0.2 and kcs == {0.5, 20.0},
      f"{name}: kc/kp 0.2 -> {sorted(kcs)} (particles, loading walls)")

# 4c. A run saved on the way (run_cycles' checkpoint, for runs of hours): one killed after its second
#     save (an exception from the save, as a dying process leaves its files) and started again goes on
#     from that save; its CSV is the one of the same run never stopped, byte for byte; against the run
#     without saves of section 4 the same to rounding (a load renews the collider's order of new
#     contacts). The checkpoint's files are gone at the end; a variant with saves is refused.
from mesocontact.bulk import uniaxial  # noqa: E402


class Killed(Exception):
    pass


saves = []
save = uniaxial.Test.save


def dying_save(self, path):
    save(self, path)
    saves.append(O.iter)
    if len(saves) == 2:
        raise Killed()


uniaxial.Test.save = dying_save
try:
    campaign.run_cycles(out, "tension", 0.05, P, quick=True, progress=False, prefix="ck-killed-", checkpoint=True)
    killed = "no exception"
except Killed:
    killed = "killed"
finally:
    uniaxial.Test.save = save
name_k, name_w = ("ck-killed-" + campaign.run_name("tension", 0.05, P),
                  "ck-whole-" + campaign.run_name("tension", 0.05, P))
where_k = campaign.run_dir(out, name_k, quick=True)
ck_file = os.path.join(os.path.dirname(where_k), name_k + ".checkpoint.yade.gz")
check(killed == "killed" and os.path.exists(ck_file + ".json") and not outputs.complete(where_k),
      f"checkpoint: a run killed after its second save (step {saves[-1]}) leaves its save and no result")
info_k, rows_k = campaign.run_cycles(out, "tension", 0.05, P, quick=True, progress=False, prefix="ck-killed-",
                                     checkpoint=True)
info_w, rows_w = campaign.run_cycles(out, "tension", 0.05, P, quick=True, progress=False, prefix="ck-whole-",
                                     checkpoint=True)
csv = [open(os.path.join(campaign.run_dir(out, n, quick=True), n + ".csv")).read() for n in (name_k, name_w)]
plain = campaign.read_csv(os.path.join(campaign.run_dir(out, campaign.run_name("tension", 0.05, P), quick=True),
                                       campaign.run_name("tension", 0.05, P) + ".csv"))
scale = max(abs(r[2]) for r in plain)
off = max(abs(a[2] - b[2]) for a, b in zip(rows_w, plain)) / scale
check(info_k["resumed_at_step"] == saves[-1] and csv[0] == csv[1] and len(rows_w) == len(plain) and off < 1e-9
      and not os.path.exists(ck_file) and not os.path.exists(ck_file + ".json"),
      f"checkpoint: started again, it went on from step {info_k['resumed_at_step']}; its CSV is the unstopped run's, "
      f"byte for byte; the run without saves differs by {off:.1e} of the force scale; the save is gone")
try:
    campaign.run_cycles(out, "tension", 0.05, P, quick=True, progress=False, prefix="ck-", checkpoint=True,
                        kc_over_kp=0.5)
    refused = "no exception"
except ValueError as e:
    refused = str(e)
check(refused.startswith("checkpoint"), "checkpoint: refused for a variant", refused)

# 5. The monotonic pull: snapshots, the first visible crack, the last contact chain, and no
#    force on the walls once the halves are apart (no drag on a half moving with its wall).
# 3x faster: the protocol, not the figure
pull = campaign.pull(out, quick=True, speed=3 * campaign.PULL_SPEED, progress=False)
check(pull["last_contact_Dx"] is not None, f"pull: the last contact chain breaks at Dx = {pull['last_contact_Dx']}")
check(pull["first_gap_Dx"] is not None and pull["first_gap_Dx"] < pull["until"],
      f"pull: first visible crack at Dx = {pull['first_gap_Dx']}")
f_mean, f_rms = pull["mean_force_after_last_contact"], pull["rms_force_after_last_contact"]
# The halves ring about zero (rms up to ~10 % of the peak in this small sample); a drag on
# them would show as a steady mean (the lab-frame drag gave about the peak itself).
check(f_mean is not None and abs(f_mean) < 0.02 * abs(pull["max_tension"]),
      f"pull: detached halves force-free on average: mean F = {f_mean:.2e} (rms {f_rms:.1e}, peak tension "
      f"{pull['max_tension']:.3g})")
g = [pull["first_gap_Dx_by_area"][k] for k in sorted(pull["first_gap_Dx_by_area"], key=float)]
check(len(g) == 3 and g[1] == pull["first_gap_Dx"] and all(x is not None for x in g) and g[0] <= g[1] <= g[2],
      f"pull: the first gap at 0.5, 1 and 2 d0^2 in order: {g}")
p0, pp = pull["planes_at_start"], pull["planes_at_peak"]
check(p0["weakest"]["count"] <= p0["mean"] and pp["weakest"]["count"] <= p0["weakest"]["count"]
      and abs(pp["F"] - pull["max_tension"]) <= 0.05 * abs(pull["max_tension"]),
      f"pull: weakest plane {p0['weakest']} at Dx = 0, {pp['weakest']} near the peak (Dx = {pp['Dx']:.3f})")
fig17 = os.path.join(campaign.root(out, quick=True), "fig17")
check(outputs.complete(fig17), "pull: fig17 bundle complete")
pngs = sorted(glob.glob(os.path.join(fig17, "fig17-0*.png")))
vtks = sorted(glob.glob(os.path.join(fig17, "fig17-spheres-*.vtk")))
check(len(pngs) == len(campaign.FIG17_DX) == len(vtks), f"pull: {len(pngs)} PNG and {len(vtks)} VTK snapshots")
check(open(vtks[-1]).readline().startswith("# vtk DataFile"), "VTK snapshot is legacy VTK")
import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
for p in (pngs[0], pngs[-1]):
    img = mpimg.imread(p)[..., :3]
    coloured = (img.max(axis=2) - img.min(axis=2)) > 0.15  # the spheres; background white, walls grey
    red, blue = (coloured & (img[..., 0] > img[..., 2])).mean(), (coloured & (img[..., 2] > img[..., 0])).mean()
    shades = np.unique(np.round(img[coloured].sum(axis=1), 2)).size
    check(coloured.mean() > 0.05 and red > 0 and shades > 50,
          f"{os.path.basename(p)}: a picture of shaded spheres ({coloured.mean():.0%} coloured, {shades} shades, red "
          f"{red:.0%}, blue {blue:.1%})")
check(len({mpimg.imread(p).shape for p in pngs}) == 1, "pull snapshots share one frame")

# 6. The time-step study: one cycle each way at 1 and 2 times the campaign's step, with the energy
#    balance (the walls' work against the change of kinetic + stored + dissipated energy: the
#    per-step work measure is first order in dt, 4e-5 and 7e-5 of the gross work in tension, 2e-4
#    and 3e-4 in compression here; 1e-3 leaves room, a wall missing from the work gives ~50 %).
ts = campaign.timestep_study(out, quick=True, factors=(1.0, 2.0), runs=("tension", "compression"), progress=False)
rows = {r["factor"]: r for r in ts["rows"]}
check(set(rows) == {1.0, 2.0}
      and all(abs(rows[f][f"{m}_energy_residual"]) < 1e-3 for f in rows for m in ("tension", "compression")),
      "time-step study: energy balance within 1e-3 of the walls' gross work: "
      + ", ".join(f"x{f:g} {m} {rows[f][f'{m}_energy_residual']:.1e}" for f in sorted(rows)
                  for m in ("tension", "compression")))
check(abs(rows[2.0]["dt"] / rows[1.0]["dt"] - 2) < 1e-12
      and set(rows[2.0]["change_vs_1dt"]) == {"tension_peak", "tension_F_at_Dx0", "compression_peak",
                                              "compression_F_at_Dx0"},
      f"time-step study: 2 dt against 1 dt {rows[2.0]['change_vs_1dt']}")

# The campaign's time steps are those the committed study accepts (campaigns/tablet/timestep.json).
with open(os.path.join(os.path.dirname(os.path.abspath(__import__("harness").__file__)), "..", "..", "campaigns",
                       "tablet", "timestep", "timestep.json")) as f:
    accepted = json.load(f)["largest_accepted_factor"]
check(accepted == campaign.DT_FACTORS,
      f"campaign.DT_FACTORS {campaign.DT_FACTORS} = the study's accepted factors {accepted}")

# Fig. 19: compression to large strain (here Dx = 1, a sixth of the quick sample, 3x faster):
# lettered snapshots at the marks, the sample spreading sideways under a compressive force.
big = campaign.large_compression(out, quick=True, until=1.0, speed=3 * campaign.PULL_SPEED, dx_marks=(0.0, 0.5, 1.0),
                                 progress=False)
sn = big["snapshots"]
widths = [0.5 * (x["width_y_d0"] + x["width_z_d0"]) for x in sn]
check(len(sn) == 3 and all(os.path.exists(os.path.join(campaign.root(out, quick=True), "fig19", x["png"])) for x in sn)
      and widths[0] < widths[1] < widths[2] and sn[1]["F"] > 0 and sn[2]["F"] > 0,
      f"fig19: compression to Dx = 1, snapshots at {[round(-x['Dx'], 2) for x in sn]}, widths "
      f"{[round(w, 2) for w in widths]} d0, force {[round(x['F'], 3) for x in sn]}")

# 7. The preparation's options (the factor study): frictionless packing, all six walls glued.
#    The stage cache tells the preparations apart; the full law acts after the packing.
fout = campaign.factor_dir(out, "frictionless", "all")
finfo = campaign.prepare(fout, quick=True, progress=False, packing="frictionless", glue="all")
check(finfo["built"]["packing"] == "frictionless" and finfo["built"]["glue"] == "all",
      f"factor preparation recorded: {finfo['built']['packing']}, {finfo['built']['glue']}")
spheres = [O.bodies[i] for i in tablet.sphere_ids()]
check(all(b.material.label == "particles" for b in spheres),
      "frictionless packing: the full law on every sphere for the tests")
sphere_contacts = [I for I in O.interactions if I.id1 in tablet.sphere_ids() and I.id2 in tablet.sphere_ids()]
check(sphere_contacts
      and all(abs(I.phys.muS - 1.0) < 1e-12 and abs(I.phys.kc - 0.2 * tablet.KP) < 1e-12 for I in sphere_contacts),
      f"frictionless packing: {len(sphere_contacts)} contacts adopted the full law (mu = 1, kc = 0.2 kp)")
# A deeper sintering (d0 p_s/kp = 0.05): sintered at that stress, released to the paper's p_r.
sout = campaign.factor_dir(out, "full", "loading", sinter=0.05)
sinfo = campaign.prepare(sout, quick=True, progress=False, sinter=0.05)
check(sout.endswith("full-loading-sinter0.05") and sinfo["built"]["sinter"] == 0.05
      and abs(sinfo["sintered"]["goal"] / (0.05 * tablet.KP / tablet.D0) - 1) < 1e-12
      and abs(sinfo["released"]["goal"] / (1e-3 * 0.02 * tablet.KP / tablet.D0) - 1) < 1e-12,
      f"deeper sintering: goals {sinfo['sintered']['goal']:.4g} then {sinfo['released']['goal']:.4g} (stress units), "
      f"in {os.path.basename(sout)}")
try:
    campaign.prepare(fout, quick=True, progress=False)
    check(False, "a directory holding another preparation is refused")
except ValueError as e:
    check("frictionless" in str(e), f"a directory holding another preparation is refused: {str(e)[:90]}...")
try:
    tablet.prepare(os.path.join(out, "x.yade.gz"), n=8, packing="loose")
    check(False, "bad packing rejected")
except ValueError as e:
    check(str(e).startswith("packing"), f"bad packing rejected: {e}")
for bad in (0.0, -0.02, float("nan")):
    try:
        tablet.prepare(os.path.join(out, "x.yade.gz"), n=8, sinter=bad)
        check(False, f"bad sinter {bad} rejected")
    except ValueError as e:
        check(str(e).startswith("sinter"), f"bad sinter rejected: {e}")

# 8. Issue #50: a test records each iteration once (it recorded its start twice, explicitly and by
#    its recorder in the next step at the same iter): no CSV written here has two rows at one iter.
tables, repeated = 0, []
for p in sorted(glob.glob(os.path.join(out, "**", "*.csv"), recursive=True)):
    with open(p) as f:
        lines = f.read().split("\n")
    if lines[0].startswith("iter,"):
        tables += 1
        iters = [ln.split(",", 1)[0] for ln in lines[1:] if ln]
        repeated += [f"{os.path.relpath(p, out)} (iter {a})" for a, b in zip(iters, iters[1:]) if a == b]
check(tables >= 20 and not repeated, f"{tables} CSVs with an iter column, one row per iter",
      f"repeated: {repeated[:4]}{' ...' if len(repeated) > 4 else ''}" if repeated else "")

finish()
