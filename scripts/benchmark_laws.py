#!/usr/bin/env python3
"""Benchmark of Law2_ScGeom_MesoPhys_Meso against YADE's own laws (issue: speed in bulk).

Runs scripts/benchmark_laws_scene.py inside YADE with 1 and 2 threads: one dense, static packing timed under
(a) Law2_ScGeom_FrictPhys_CundallStrack, (b) Law2_ScGeom_LudingPhys_Basic, (c) the meso law with
the normal force and adhesion, (d) the meso law with sliding, rolling and torsion on ScGeom6D,
(e) Law2_ScGeom6D_CohFrictPhys_CohesionMoment with rolling and twisting moments. Prints whole-step
and Law2 times per contact (YADE's engine timing; the Law2 time from YADE's separate LawDispatcher
engine on the same scene), ratios within each run, -j2 speed-ups, and the serial/parallel
difference of the final positions.

usage: scripts/benchmark_laws.py [--yade YADE] [--bodies N] [--steps S]
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
ap.add_argument("--yade", default=os.environ.get("YADE", "yade"), help="YADE launcher (default: yade; build/yade-meso for the build tree)")
ap.add_argument("--bodies", type=int, default=6000)
ap.add_argument("--steps", type=int, default=300)
ap.add_argument("--rounds", type=int, default=3, help="rounds in which the laws take turns; each law keeps its best")
ap.add_argument("--profile", action="store_true",
                help="also run each law under valgrind's callgrind (20 steps, 2000 spheres) for the Law2 share of the "
                     "instructions and the instructions per go() call (slow: minutes)")
args = ap.parse_args()
if args.bodies < 100 or args.steps < 10:
    sys.exit("benchmark_laws: --bodies must be >= 100 and --steps >= 10")

reports = {}
with tempfile.TemporaryDirectory() as tmp:
    for threads in (1, 2):
        path = os.path.join(tmp, f"j{threads}.json")
        cmd = [args.yade, f"-j{threads}", "-n", "-x", os.path.join(here, "benchmark_laws_scene.py"), path, str(args.bodies), str(args.steps),
               "cundall-strack,luding-basic,meso-normal,meso-full,cohesion-moment", str(args.rounds)]
        print("running:", " ".join(cmd), flush=True)
        subprocess.run(cmd, check=True, stdout=sys.stdout, stderr=subprocess.DEVNULL)
        with open(path) as f:
            reports[threads] = json.load(f)

r1, r2 = reports[1], reports[2]
names = list(r1["laws"])
print(f"\n{r1['bodies']} spheres, {r1['steps']} steps per law; MesoPhys {r1['mesoPhys_bytes']} bytes (FrictPhys {r1['frictPhys_bytes']})")
for threads, r in reports.items():
    base = r["laws"]["cundall-strack"]
    print(f"\n-j{threads}: {'law':16s} {'contacts':>8s} {'step/contact':>13s} {'InteractionLoop/contact':>24s} {'step vs (a)':>11s}")
    for n in names:
        L = r["laws"][n]
        c = max(L["contacts"], 1)
        print(f"      {n:16s} {L['contacts']:8d} {L['step_ns'] / c:10.1f} ns {L['interaction_loop_ns'] / c:21.1f} ns "
              f"{L['step_ns'] / base['step_ns']:10.3f}")
print("\ncriteria (whole-step time, ratios within one run):")
for threads, r in reports.items():
    L = r["laws"]
    c_a = L["meso-normal"]["step_ns"] / L["cundall-strack"]["step_ns"]
    c_b = L["meso-normal"]["step_ns"] / L["luding-basic"]["step_ns"]
    d_e = L["meso-full"]["step_ns"] / L["cohesion-moment"]["step_ns"]
    print(f"  -j{threads}: (c)/(a) = {c_a:.3f} (<= 1.10: {'yes' if c_a <= 1.10 else 'NO'}); (c)/(b) = {c_b:.3f} (< 1: {'yes' if c_b < 1 else 'NO'}); "
          f"(d)/(e) = {d_e:.3f} (<= 1.0: {'yes' if d_e <= 1.0 else 'NO'})")
print("\n-j2 speed-up (whole step) and serial/parallel difference of the forces and torques on the bodies:")
for n in names:
    s = r1["laws"][n]["step_ns"] / r2["laws"][n]["step_ns"]
    f1, f2 = r1["laws"][n]["positions"], r2["laws"][n]["positions"]
    scale = max(max(abs(a) for a in p[:3]) for p in f1) or 1.0
    df = max(max(abs(a - b) for a, b in zip(p, q)) for p, q in zip(f1, f2))
    print(f"  {n:16s} speed-up {s:.3f}; max |F(-j2) - F(-j1)| / max |F| = {df / scale:.1e}")

LAW_SYMBOL = {"cundall-strack": "Law2_ScGeom_FrictPhys_CundallStrack::go(", "luding-basic": "Law2_ScGeom_LudingPhys_Basic::go(",
              "meso-normal": "Law2_ScGeom_MesoPhys_Meso::go(", "meso-full": "Law2_ScGeom_MesoPhys_Meso::go(",
              "cohesion-moment": "Law2_ScGeom6D_CohFrictPhys_CohesionMoment::go("}
if args.profile:
    print("\nprofile (callgrind instruction counts, 2000 spheres, 20 steps, -j1): Law2::go() inclusive")
    with tempfile.TemporaryDirectory() as tmp:
        for n in names:
            out = os.path.join(tmp, "cg.%p")
            cmd = ["valgrind", "--tool=callgrind", "--trace-children=yes", f"--callgrind-out-file={out}", args.yade, "-j1", "-n", "-x",
                   os.path.join(here, "benchmark_laws_scene.py"), os.path.join(tmp, "p.json"), "2000", "20", n, "1"]
            subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            prof = max((os.path.join(tmp, f) for f in os.listdir(tmp) if f.startswith("cg.")), key=os.path.getsize)
            ann = subprocess.run(["callgrind_annotate", "--inclusive=yes", prof], capture_output=True, text=True).stdout
            with open(os.path.join(tmp, "p.json")) as f:
                contacts = json.load(f)["laws"][n]["contacts"]

            def inclusive(symbol):
                best = 0
                for line in ann.splitlines():
                    m = re.match(r"\s*([\d,]+) \(", line)
                    if m and symbol in line and "thunk" not in line and "=>" not in line:
                        best = max(best, int(m.group(1).replace(",", "")))
                return best
            law, step = inclusive(LAW_SYMBOL[n]), inclusive("Scene::moveToNextTimeStep()")
            for f in os.listdir(tmp):
                if f.startswith("cg."):
                    os.remove(os.path.join(tmp, f))
            print(f"  {n:16s} Law2 share of the step {law / step:6.1%}; {law / (contacts * 41):7.0f} instructions per go() call")
