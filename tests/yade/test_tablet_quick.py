# ctest (inside yade): the tablet campaign in quick mode (216 particles, one cycle) checks the
# protocol: stress targets, unconfined set-up, adhesive walls, cycles back to zero strain,
# finite forces, tension re-loading with positive slope, snapshots, where the pull breaks.
import glob
import json
import math
import os
import sys
import tempfile

from yade import O, utils
from yade import wrapper as w
from mesocontact import campaign, snapshots, tablet, uniaxial

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what, flush=True)
    if not ok:
        failures.append(what)


# 1. The see-through measure on known pictures: a ring of 12 touching spheres (seen along y)
#    encloses a hole; a filled disk of spheres has none.
O.reset()
r = 0.5 * tablet.D0
R = r / math.sin(math.pi / 12)
O.bodies.append([utils.sphere((R * math.cos(2 * math.pi * k / 12), 0, R * math.sin(2 * math.pi * k / 12)), r)
                 for k in range(12)])
hole = snapshots.see_through_holes(pixel=tablet.D0 / 40)
inner = (R - r) ** 2 * math.pi / tablet.D0 ** 2  # the inscribed disk lies inside the hole
check(inner < hole < 1.2 * math.pi * R ** 2 / tablet.D0 ** 2, f"ring of spheres: hole {hole:.3f} d0^2 (> inscribed disk {inner:.3f})")
O.bodies.append(utils.sphere((0, 0.02, 0), R + 0.5 * r))  # covers the ring
check(snapshots.see_through_holes(pixel=tablet.D0 / 40) == 0, "ring covered by a sphere behind: no hole")

out = tempfile.mkdtemp(prefix="tablet-quick-")

# 2. Preparation: targets reached and static.
path, info = campaign.prepare(out, quick=True)
for stage, goal in (("sintered", tablet.SINTER_STRESS), ("released", tablet.RELEASE_RATIO * tablet.SINTER_STRESS)):
    s = info[stage]
    err = max(abs(v / goal - 1) for v in s["wall_stress"].values())
    check(err < 0.01, f"{stage}: six wall stresses within 1% of {goal:g} (worst {err:.2e})")
    e_ref = tablet.energy_scale(info["built"]["n"])
    check(s["kinetic_energy"] < 1e-4 * e_ref, f"{stage}: kinetic energy {s['kinetic_energy']:.2e} < 1e-4 x {e_ref:.2e}")
print(f"     sintered: solid fraction {info['sintered']['solid_fraction']:.3f}, Z {info['sintered']['coordination']:.2f}; "
      f"released: {info['released']['solid_fraction']:.3f}, Z {info['released']['coordination']:.2f}")
p_r = 2e-5 * tablet.KP / tablet.D0  # the paper's d0 p_r/kp = 2e-5
check(all(abs(v / p_r - 1) < 0.01 for v in info["released"]["wall_stress"].values()), f"release stress is d0 p_r/kp = 2e-5 (p_r = {p_r:g})")
u = info["unconfined"]
check(u["force_error"] < 1e-4 and u["kinetic_energy_ratio"] < 1e-4,
      f"unconfined start: wall force at p_r A to {u['force_error']:.1e} kp d0, at rest ({u['kinetic_energy_ratio']:.1e})")

# 3. The unconfined test: two walls left, with the adhesive wall law imposed on their contacts.
test = uniaxial.Test(path, progress=False)
check(abs(test.force() - u["target_force"] / (tablet.KP * tablet.D0)) < 1e-4, f"test starts at rest: F/(kp d0) = {test.force():.2e}")
check(len(tablet.wall_ids()) == 2 and set(tablet.wall_ids()) == {"left", "right"}, "lateral walls removed")
wall_contacts = [I for I in O.interactions if I.isReal and test.left in (I.id1, I.id2)]
check(len(wall_contacts) > 0 and all(abs(I.phys.kc - 20 * tablet.KP) < 1e-12 and abs(I.phys.muS - 10) < 1e-12
                                     for I in wall_contacts),
      f"{len(wall_contacts)} wall contacts with kc = 20 kp and mu = 10 (dominant wall material)")
try:
    test.cycles("shear", 0.1)
    check(False, "bad mode rejected")
except ValueError as e:
    check(str(e).startswith("mode"), f"bad mode rejected: {e}")

# 4. Cycles in tension and compression.
for mode in ("tension", "compression"):
    amps = (0.05, 0.2)
    summary = campaign.cyclic(mode, out, amps, quick=True, progress=False)
    for amp in amps:
        name = f"{mode}-Dx{amp:g}-fast"
        run = summary["runs"][name]
        check(abs(run["final_Dx"]) < 1e-9, f"{name}: back to zero strain (Dx = {run['final_Dx']:.1e})")
        check(abs(run["max_abs_Dx"] / amp - 1) < 1e-3, f"{name}: amplitude reached ({run['max_abs_Dx']:.5f})")
        rows = [tuple(map(float, line.split(","))) for line in open(os.path.join(out, name + ".csv")).read().split("\n")[1:] if line]
        check(all(math.isfinite(x) for r in rows for x in r), f"{name}: {len(rows)} finite records")
        peak = max(range(len(rows)), key=lambda k: abs(rows[k][1]))
        if mode == "tension":
            check(min(r[2] for r in rows[:peak + 1]) < 0, f"{name}: tensile force on the way out")
            back = rows[peak:]  # the return: compression coordinate u = -Dx grows
            u = [-r[1] for r in back]
            f = [r[2] for r in back]
            mu, mf = sum(u) / len(u), sum(f) / len(f)
            slope = sum((a - mu) * (b - mf) for a, b in zip(u, f)) / sum((a - mu) ** 2 for a in u)
            check(slope > 0, f"{name}: re-loading branch slope dF/du = {slope:.3g} > 0")
        else:
            check(max(r[2] for r in rows[:peak + 1]) > 0, f"{name}: compressive force on the way in")
    check(os.path.exists(os.path.join(out, ("fig16" if mode == "tension" else "fig18") + "-quick.png")), f"{mode}: figure written")

# 5. The monotonic pull: snapshots, the first see-through gap and the last contact chain.
pull = campaign.pull(out, quick=True, progress=False)
check(pull["last_contact_Dx"] is not None, f"pull: the last contact chain breaks at Dx = {pull['last_contact_Dx']}")
check(pull["first_gap_Dx"] is not None and pull["first_gap_Dx"] <= (pull["last_contact_Dx"] or 0),
      f"pull: first gap at Dx = {pull['first_gap_Dx']} before the break")
pngs = sorted(glob.glob(os.path.join(out, "fig17-quick-0*.png")))
vtks = sorted(glob.glob(os.path.join(out, "fig17-quick-spheres-*.vtk")))
check(len(pngs) == len(campaign.FIG17_DX) == len(vtks), f"pull: {len(pngs)} PNG and {len(vtks)} VTK snapshots")
check(open(vtks[-1]).readline().startswith("# vtk DataFile"), "VTK snapshot is legacy VTK")
check(all(os.path.getsize(p) > 10000 for p in pngs), "PNG snapshots are pictures")

if failures:
    print(f"{len(failures)} FAILED: {failures}")
    sys.exit(1)
print("all passed")
