# ctest (plain Python): a packing on an adhesive box with every mechanism on (most contacts sliding
# at the dynamic limit), run with `-j1` and `-j2`: every contact's history, springs and forces
# bitwise identical, forces and torques on the bodies and every energy term equal to summation order
# (it found that YADE's `EnergyTracker` loses shares when threads meet a new energy name at once:
# the law now registers its names under a lock before adding to them); and the same without
# `ScGeom6D`'s relative rotations (`updateRotations=False`): identical; and the contact-relative
# drag on free spheres, its reference gathered by the law on both threads: forces and torques equal
# to summation order.
#
# The meso law under YADE's OpenMP gives what it gives serially. Runs
# tests/openmp/scene.py with -j1 and -j2 (argv[1]: the YADE launcher) and checks that every
# contact's history, springs and forces are bitwise identical (a contact's update does not depend
# on the order of contacts), and that the forces and torques summed on the bodies and the energy
# differ by no more than summation order allows. Also runs -j1 without ScGeom6D's relative rotations
# (Ig2_Sphere_Sphere_ScGeom6D.updateRotations=False): the law does not read them, nothing changes.
import json
import os
import subprocess
import sys
import tempfile

launcher = sys.argv[1]
scene = os.path.join(os.path.dirname(os.path.abspath(__file__)), "scene.py")
reports = {}
with tempfile.TemporaryDirectory() as tmp:
    for run, (threads, extra) in {1: (1, []), 2: (2, []), "norot": (1, ["norot"]), "drag1": (1, ["drag"]),
                                  "drag2": (2, ["drag"])}.items():
        out = os.path.join(tmp, f"{run}.json")
        subprocess.run([launcher, f"-j{threads}", "-n", "-x", scene, out] + extra, check=True,
                       stdout=subprocess.DEVNULL)
        with open(out) as f:
            reports[run] = json.load(f)
r1, r2 = reports[1], reports[2]
failures = []
# The law reads no relative rotation of ScGeom6D: without them (updateRotations=False) all is the same.
same = all(r1[k] == reports["norot"][k] for k in ("contacts", "forces", "energy"))
print(f"Ig2_Sphere_Sphere_ScGeom6D(updateRotations=False): identical results: {same}", flush=True)
if not same:
    failures.append("results depend on ScGeom6D's relative rotations")
if r2["threads"] != 2:
    failures.append(f"the -j2 run used {r2['threads']} threads")
# The drag on free spheres (3 steps; the blocked ones above get none): its reference gathered by
# the law on both threads, summed per thread, gives the -j1 forces to rounding.
d1, d2 = reports["drag1"], reports["drag2"]
drag_energy = d1["energy"].get("mesoBackground", 0)
print(f"drag on free spheres: the law's sums used in {d1['law_sum_steps']} (-j1) and {d2['law_sum_steps']} (-j2) of 3 "
      f"steps; mesoBackground {drag_energy:.3e}", flush=True)
if not (d1["law_sum_steps"] == d2["law_sum_steps"] == 2 and drag_energy > 0 and d2["threads"] == 2):
    failures.append("the drag did not act, or not from the law's sums, in the free run")


def compare_bodies(a, b, label):
    """Forces and torques on the bodies of two runs: equal to summation order (1e-13 of the largest)."""
    for part, name in ((slice(0, 3), "forces"), (slice(3, 6), "torques")):
        scale = max(max(abs(x) for x in f[part]) for f in a["forces"])
        diff = max(max(abs(x - y) for x, y in zip(f[part], g[part])) for f, g in zip(a["forces"], b["forces"]))
        print(f"{label}{name}: max |(-j2) - (-j1)| = {diff / scale:.1e} of the largest", flush=True)
        if not diff <= 1e-13 * scale:
            failures.append(f"{label}{name} differ by {diff / scale:.1e} of the largest")


compare_bodies(d1, d2, "drag run ")
if r1["contacts"] != r2["contacts"]:
    differ = [k for k in r1["contacts"] if r1["contacts"][k] != r2["contacts"].get(k)]
    failures.append(f"per-contact state differs in {len(differ)} of {len(r1['contacts'])} contacts (e.g. {differ[:3]})")
compare_bodies(r1, r2, "")
# Each energy term sums ~contacts x steps = 1.3e6 increments in an order that depends on the threads:
# rounding may differ by ~1.3e6 x 1.1e-16 = 1.4e-10 of the summed magnitudes, which exceed a term by
# up to a few times where its increments cancel (dissipation against storage): 1e-9 of the term
# itself bounds what order can do. A share lost to a race is a whole contact-step's increment:
# orders of magnitude more (YADE's EnergyTracker race, without the law's lock, cost 7e-8 to 2.5e-4
# of some terms, in about one run in sixteen: it needs both threads at a new name at once).
for k in sorted(r1["energy"]):
    e1 = r1["energy"][k]
    d = abs(e1 - r2["energy"].get(k, float("nan")))
    print(f"energy {k:14s} {e1: .6e}; |(-j2) - (-j1)| = {d / abs(e1) if e1 else d:.1e} of the term", flush=True)
    if not d <= 1e-9 * abs(e1):
        failures.append(f"energy {k} differs by {d:.1e} (the term is {e1:.3e})")
print(f"{len(r1['contacts'])} contacts, {r1['slipping']} sliding at the dynamic limit", flush=True)
if r1["slipping"] == 0:
    failures.append("no contact slides: the scene does not exercise the Coulomb limits")
if failures:
    print("FAILED:", "; ".join(failures))
    sys.exit(1)
print("all passed")
