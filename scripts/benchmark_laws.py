#!/usr/bin/env python3
"""Benchmark of Law2_ScGeom_MesoPhys_Meso against YADE's own laws (issue: speed in bulk).

Runs scripts/benchmark_laws_scene.py inside YADE with 1 and 2 threads on one dense, static packing
under (a) Law2_ScGeom_FrictPhys_CundallStrack, (b) Law2_ScGeom_LudingPhys_Basic, (c) the meso law with
the normal force and adhesion, (d) the meso law with sliding, rolling and torsion on ScGeom6D,
(e) Law2_ScGeom6D_CohFrictPhys_CohesionMoment with rolling and twisting moments.

All scenes live in one YADE process and take turns in short bursts, round after round; ratios are
taken within a round (same machine state) and summarised by their median over all rounds, with the
quartiles. Reports whole-step and InteractionLoop time per contact (YADE's engine timing), the Law2
time and its share of the step (YADE's LawDispatcher, timed in a twin scene where the separate
dispatchers replace the InteractionLoop), -j2 speed-ups, the serial/parallel difference of the
forces, the size of MesoPhys, and with --profile callgrind's instructions per go() call.

usage: scripts/benchmark_laws.py [--yade YADE] [--bodies N] [--steps S] [--rounds R] [--sessions K]
                                 [--laws a,b,...] [--profile] [--json FILE]
"""
import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
ALL = ["cundall-strack", "luding-basic", "meso-normal", "meso-full", "cohesion-moment"]
LETTER = dict(zip(ALL, "abcde"))
ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
ap.add_argument("--yade", default=os.environ.get("YADE", "yade"), help="YADE launcher (default: yade, or $YADE)")
ap.add_argument("--bodies", type=int, default=6000, help="target number of spheres (a hexagonal lattice fills the box)")
ap.add_argument("--steps", type=int, default=40, help="steps per burst")
ap.add_argument("--rounds", type=int, default=15, help="rounds per YADE run; in each, every law runs one burst")
ap.add_argument("--sessions", type=int, default=2, help="YADE runs per thread count, -j1 and -j2 alternating")
ap.add_argument("--laws", default=",".join(ALL), help="comma-separated subset of " + ",".join(ALL))
ap.add_argument("--profile", action="store_true",
                help="only profile: each law under valgrind's callgrind (2000 spheres, -j1): Law2 share of the "
                     "instructions and instructions per go() call, with the hottest functions (slow: minutes)")
ap.add_argument("--json", help="also write the merged measurements to this file")
args = ap.parse_args()
laws = args.laws.split(",")
if any(n not in ALL for n in laws):
    sys.exit(f"benchmark_laws: --laws must be taken from {','.join(ALL)}")
if args.bodies < 100 or args.steps < 5 or args.rounds < 3 or args.sessions < 1:
    sys.exit("benchmark_laws: --bodies must be >= 100, --steps >= 5, --rounds >= 3, --sessions >= 1")
SCENE = os.path.join(here, "benchmark_laws_scene.py")


def quartiles(xs):
    q = statistics.quantiles(xs, n=4, method="inclusive") if len(xs) > 1 else [xs[0]] * 3
    return q[0], q[1], q[2]


def profile():
    """Callgrind instruction counts of each law's go() (deterministic, unlike times on a shared machine)."""
    print("profile (callgrind, 2000 spheres, -j1, 20 + 20 + 1 steps): Law2::go() inclusive instructions")
    symbols = {"cundall-strack": "Law2_ScGeom_FrictPhys_CundallStrack::go(", "luding-basic": "Law2_ScGeom_LudingPhys_Basic::go(",
               "meso-normal": "Law2_ScGeom_MesoPhys_Meso::go(", "meso-full": "Law2_ScGeom_MesoPhys_Meso::go(",
               "cohesion-moment": "Law2_ScGeom6D_CohFrictPhys_CohesionMoment::go("}
    for n in laws:
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "cg.%p")
            cmd = ["valgrind", "--tool=callgrind", "--trace-children=yes", f"--callgrind-out-file={out}", args.yade, "-j1", "-n", "-x",
                   SCENE, os.path.join(tmp, "p.json"), "2000", "20", n, "1"]
            subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            prof = max((os.path.join(tmp, f) for f in os.listdir(tmp) if f.startswith("cg.")), key=os.path.getsize)
            ann = subprocess.run(["callgrind_annotate", "--inclusive=yes", prof], capture_output=True, text=True).stdout
            flat = subprocess.run(["callgrind_annotate", prof], capture_output=True, text=True).stdout
            with open(os.path.join(tmp, "p.json")) as f:
                contacts = json.load(f)["laws"][n]["contacts"]

        def inclusive(symbol):
            best = 0
            for line in ann.splitlines():
                m = re.match(r"\s*([\d,]+) \(", line)
                if m and symbol in line and "thunk" not in line and "=>" not in line:
                    best = max(best, int(m.group(1).replace(",", "")))
            return best
        law, step = inclusive(symbols[n]), inclusive("Scene::moveToNextTimeStep()")
        calls = contacts * 41
        print(f"  {n:16s} Law2 share of the step {law / step:6.1%}; {law / calls:7.0f} instructions per go() call; hottest (self):")
        for line in [ln for ln in flat.splitlines() if re.match(r"\s*[\d,]+ \(", ln)][1:7]:
            m = re.match(r"\s*([\d,]+) \(\s*([\d.]+)%\)\s+\S+:(.*)", line) or re.match(r"\s*([\d,]+) \(\s*([\d.]+)%\)\s+(.*)", line)
            if m:
                print(f"      {int(m.group(1).replace(',', '')) / calls:7.1f} per call  {m.group(3)[:110]}")


if args.profile:
    profile()
    sys.exit(0)

# Measurements merged over the sessions: runs[threads][law] = lists over all rounds.
runs, info = {1: {}, 2: {}}, {}
with tempfile.TemporaryDirectory() as tmp:
    for session in range(args.sessions):
        for threads in (1, 2):
            path = os.path.join(tmp, f"j{threads}.json")
            cmd = [args.yade, f"-j{threads}", "-n", "-x", SCENE, path, str(args.bodies), str(args.steps), ",".join(laws), str(args.rounds), "1"]
            print(f"session {session + 1}/{args.sessions}:", " ".join(cmd), flush=True)
            subprocess.run(cmd, check=True, stdout=sys.stdout, stderr=subprocess.DEVNULL)
            with open(path) as f:
                r = json.load(f)
            info = {k: r[k] for k in ("bodies", "steps", "mesoPhys_bytes", "frictPhys_bytes")}
            for n, L in r["laws"].items():
                M = runs[threads].setdefault(n, {"contacts": L["contacts"], "forces": L["forces"]})
                for key in ("step_ns", "interaction_loop_ns", "law2_ns", "split_step_ns"):
                    M.setdefault(key, []).extend(L[key])

r1, r2 = runs[1], runs[2]
rounds_total = len(r1[laws[0]]["step_ns"])
print(f"\n{info['bodies']} spheres, {r1[laws[0]]['contacts']} contacts; {rounds_total} rounds of {info['steps']} steps per law and thread "
      f"count; MesoPhys {info['mesoPhys_bytes']} bytes (FrictPhys {info['frictPhys_bytes']})")
print("medians over the rounds, per contact; Law2 = YADE's LawDispatcher, share = of the step with separate dispatchers")
for threads, r in runs.items():
    print(f"\n-j{threads}: {'law':20s} {'step':>9s} {'InteractionLoop':>16s} {'Law2':>9s} {'Law2 share':>10s}  step/(a), quartiles")
    for n in laws:
        L, c = r[n], r[n]["contacts"]
        share = statistics.median(a / b for a, b in zip(L["law2_ns"], L["split_step_ns"]))
        line = (f"      ({LETTER[n]}) {n:16s} {statistics.median(L['step_ns']) / c:6.1f} ns {statistics.median(L['interaction_loop_ns']) / c:13.1f} ns "
                f"{statistics.median(L['law2_ns']) / c:6.1f} ns {share:9.1%}")
        if "cundall-strack" in r:
            q = quartiles([x / y for x, y in zip(L["step_ns"], r["cundall-strack"]["step_ns"])])
            line += f"  {q[1]:.3f} [{q[0]:.3f}, {q[2]:.3f}]"
        print(line)


def paired(r, num, den):
    """Quartiles of the per-round ratio of whole-step times num/den."""
    return quartiles([x / y for x, y in zip(r[num]["step_ns"], r[den]["step_ns"])])


if all(n in laws for n in ALL):
    print("\ncriteria (whole-step time; median of the per-round ratios [quartiles]):")
    for threads, r in runs.items():
        ca, cb, de = paired(r, "meso-normal", "cundall-strack"), paired(r, "meso-normal", "luding-basic"), paired(r, "meso-full", "cohesion-moment")
        print(f"  -j{threads}: (c)/(a) = {ca[1]:.3f} [{ca[0]:.3f}, {ca[2]:.3f}] (<= 1.10: {'yes' if ca[1] <= 1.10 else 'NO'}); "
              f"(c)/(b) = {cb[1]:.3f} [{cb[0]:.3f}, {cb[2]:.3f}] (< 1: {'yes' if cb[1] < 1 else 'NO'}); "
              f"(d)/(e) = {de[1]:.3f} [{de[0]:.3f}, {de[2]:.3f}] (<= 1.0: {'yes' if de[1] <= 1.0 else 'NO'})")
    # speed-up(x)/speed-up(y) = [x/y at -j1]/[x/y at -j2]: the within-round ratios cancel the machine's state.
    print("  -j2 speed-ups relative to each other (ratio of the paired medians at -j1 and -j2; >= 1: at least as good):")
    for x, y in (("meso-normal", "cundall-strack"), ("meso-normal", "cohesion-moment"), ("meso-full", "cundall-strack"), ("meso-full", "cohesion-moment")):
        rel = paired(r1, x, y)[1] / paired(r2, x, y)[1]
        print(f"      speed-up ({LETTER[x]}) / speed-up ({LETTER[y]}) = {rel:.3f} ({'yes' if rel >= 1 else 'NO'})")

print("\n-j2 speed-up (ratio of the median whole steps) and serial/parallel difference of the forces and torques on the bodies:")
for n in laws:
    s = statistics.median(r1[n]["step_ns"]) / statistics.median(r2[n]["step_ns"])
    f1, f2 = r1[n]["forces"], r2[n]["forces"]
    diff = []
    for part in (slice(0, 3), slice(3, 6)):  # forces, then torques, each against its own scale
        scale = max(max(abs(a) for a in p[part]) for p in f1) or 1.0
        diff.append(max(max(abs(a - b) for a, b in zip(p[part], q[part])) for p, q in zip(f1, f2)) / scale)
    print(f"  ({LETTER[n]}) {n:16s} speed-up {s:.3f}; max |F(-j2) - F(-j1)| / max |F| = {diff[0]:.1e}, same for torques {diff[1]:.1e}")
if args.json:
    for r in runs.values():
        for L in r.values():
            L.pop("forces")
    with open(args.json, "w") as f:
        json.dump({"info": info, "runs": runs}, f)
