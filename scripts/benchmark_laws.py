#!/usr/bin/env python3
"""Benchmark of Law2_ScGeom_MesoPhys_Meso against YADE's own laws (issue: speed in bulk).

Runs scripts/benchmark_laws_scene.py inside YADE with 1 and 2 threads on one dense, static packing
under (a) Law2_ScGeom_FrictPhys_CundallStrack, (b) Law2_ScGeom_LudingPhys_Basic, (c) the meso law with
the normal force and adhesion, (d) the meso law with sliding, rolling and torsion on ScGeom6D as the
README sets it up (Ig2_Sphere_Sphere_ScGeom6D(updateRotations=False): the law reads no relative
rotation), (d') the same with YADE's default Ig2 (which computes the rotations all the same), and
(e) Law2_ScGeom6D_CohFrictPhys_CohesionMoment with rolling and twisting moments.

All scenes live in one YADE process and take turns in short bursts, round after round; ratios are
taken within a round (same machine state) and summarised by their median over all rounds, with the
quartiles. Reports whole-step and InteractionLoop time per contact (YADE's engine timing), the Law2
time and its share of the step (YADE's LawDispatcher, timed in a twin scene where the separate
dispatchers replace the InteractionLoop), -j2 speed-ups, the serial/parallel difference of the
forces, the size of MesoPhys, and with --profile callgrind's instructions per go() call.

usage: scripts/benchmark_laws.py [--yade YADE] [--bodies N] [--steps S] [--rounds R] [--sessions K]
                                 [--laws a,b,...] [--profile] [--json FILE] [--merge FILE ...]
Several runs' measurements (--json) can be pooled with --merge (with --sessions 0: no new run).
"""
import argparse
import json
import os
import random
import re
import statistics
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
ALL = ["cundall-strack", "luding-basic", "meso-normal", "meso-full", "meso-full-rotations", "cohesion-moment"]
LETTER = dict(zip(ALL, ["a", "b", "c", "d", "d'", "e"]))
ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
ap.add_argument("--yade", default=os.environ.get("YADE", "yade"), help="YADE launcher (default: yade, or $YADE)")
ap.add_argument("--bodies", type=int, default=6000, help="target number of spheres (a hexagonal lattice fills the box)")
ap.add_argument("--steps", type=int, default=60, help="timed steps per burst")
ap.add_argument("--rounds", type=int, default=15, help="rounds per YADE run; in each, every law runs one burst")
ap.add_argument("--sessions", type=int, default=2, help="YADE runs per thread count, -j1 and -j2 alternating")
ap.add_argument("--laws", default=",".join(ALL), help="comma-separated subset of " + ",".join(ALL))
ap.add_argument("--profile", action="store_true",
                help="only profile: each law under valgrind's callgrind (2000 spheres, -j1): Law2 share of the "
                     "instructions and instructions per go() call, with the hottest functions (slow: minutes)")
ap.add_argument("--json", help="also write this invocation's measurements (all its sessions) to this file")
ap.add_argument("--merge", nargs="+", default=[], help="pool the rounds of earlier runs' --json files with this run's")
args = ap.parse_args()
laws = args.laws.split(",")
if any(n not in ALL for n in laws):
    sys.exit(f"benchmark_laws: --laws must be taken from {','.join(ALL)}")
if (args.bodies < 100 or args.steps < 5 or args.rounds < 3 or args.sessions < 0
        or (args.sessions == 0 and not args.merge)):
    sys.exit("benchmark_laws: --bodies must be >= 100, --steps >= 5, --rounds >= 3, --sessions >= 1 "
             "(0 only with --merge)")
SCENE = os.path.join(here, "benchmark_laws_scene.py")
PAIRS = (("meso-normal", "cundall-strack"), ("meso-full", "cohesion-moment"),
         ("meso-full-rotations", "cohesion-moment"),
         ("meso-normal", "cohesion-moment"), ("meso-full", "cundall-strack"))
PROFILE_BODIES, PROFILE_STEPS = 2000, 30


def quartiles(xs):
    q = statistics.quantiles(xs, n=4, method="inclusive") if len(xs) > 1 else [xs[0]] * 3
    return q[0], q[1], q[2]


def profile():
    """Callgrind instruction counts (deterministic, unlike times on a shared machine), collected
    inside the time steps only (not YADE's start-up): whole step and Law2::go() per contact, and
    what go() spends in its callees."""
    print(f"profile (callgrind instructions, {PROFILE_BODIES} spheres, -j1, all time steps):")
    symbols = {"cundall-strack": "Law2_ScGeom_FrictPhys_CundallStrack::go(",
               "luding-basic": "Law2_ScGeom_LudingPhys_Basic::go(",
               "meso-normal": "Law2_ScGeom_MesoPhys_Meso::go(", "meso-full": "Law2_ScGeom_MesoPhys_Meso::go(",
               "meso-full-rotations": "Law2_ScGeom_MesoPhys_Meso::go(",
               "cohesion-moment": "Law2_ScGeom6D_CohFrictPhys_CohesionMoment::go("}
    for n in laws:
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "cg.%p")
            # Only the time steps are collected (not YADE's start-up nor building the scene); the first step,
            # which creates the contacts, is among them, diluted over all.
            cmd = ["valgrind", "--tool=callgrind", "--trace-children=yes", "--collect-atstart=no",
                   "--toggle-collect=yade::Scene::moveToNextTimeStep()", f"--callgrind-out-file={out}", args.yade,
                   "-j1", "-n", "-x",
                   SCENE, os.path.join(tmp, "p.json"), str(PROFILE_BODIES), str(PROFILE_STEPS), n, "1"]
            subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            prof = max((os.path.join(tmp, f) for f in os.listdir(tmp) if f.startswith("cg.")), key=os.path.getsize)
            tree = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--tree=calling", prof],
                                  capture_output=True, text=True).stdout
            with open(os.path.join(tmp, "p.json")) as f:
                contacts = json.load(f)["laws"][n]["contacts"]
        total = int(re.search(r"([\d,]+) \(100.0%\)\s+PROGRAM TOTALS", tree).group(1).replace(",", ""))
        # The blocks of go() in the calling tree (callgrind splits a function by the files its inlined code
        # comes from): the largest inclusive count is go()'s, the callee lines are summed over the blocks.
        lines = tree.splitlines()
        star = re.compile(r"\s*([\d,]+) \([\s\d.]+%\)\s+\*\s+\S*:(yade::)?" + re.escape(symbols[n]))
        callee = re.compile(r"\s*([\d,]+) \([\s\d.]+%\)\s+>\s+\S*?:(.*?)\(.*\((\d[\d,]*)x\)")
        law, callees = 0, {}
        for i, ln in enumerate(lines):
            m = star.match(ln)
            if not m or "thunk" in ln:
                continue
            law = max(law, int(m.group(1).replace(",", "")))
            for c in lines[i + 1:]:
                mc = callee.match(c)
                if not mc:
                    break
                cost, count = callees.get(mc.group(2), (0, 0))
                callees[mc.group(2)] = (cost + int(mc.group(1).replace(",", "")),
                                        count + int(mc.group(3).replace(",", "")))
        calls = max(int(m.group(1).replace(",", "")) for m in
                    (re.search(r"\((\d[\d,]*)x\)", ln) for ln in lines if symbols[n] in ln and ">" in ln
                     and "thunk" not in ln) if m)
        steps = calls / contacts
        print(f"  {'(' + LETTER[n] + ')':4s} {n:19s} step {total / calls:6.0f} per contact; Law2::go() "
              f"{law / calls:5.0f} per call ({law / total:5.1%} of the step); in go():")
        for name, (cost, count) in sorted(callees.items(), key=lambda kv: -kv[1][0]):
            print(f"      {cost / calls:6.0f}  {name[-60:]} ({count / calls:.1f} per call)")
        print(f"      ({steps:.0f} steps)")


if args.profile:
    profile()
    sys.exit(0)

# per round, as the scene writes them
KEYS = ("step_ns", "interaction_loop_ns", "law2_ns", "split_step_ns", "serial_loop_ns")
# Measurements merged over the sessions: runs[threads][law] = lists over all rounds.
runs, info = {1: {}, 2: {}}, {}
with tempfile.TemporaryDirectory() as tmp:
    for session in range(args.sessions):
        for threads in (1, 2):
            path = os.path.join(tmp, f"j{threads}.json")
            cmd = [args.yade, f"-j{threads}", "-n", "-x", SCENE, path, str(args.bodies), str(args.steps),
                   ",".join(laws), str(args.rounds), "1"]
            print(f"session {session + 1}/{args.sessions}:", " ".join(cmd), flush=True)
            subprocess.run(cmd, check=True, stdout=sys.stdout, stderr=subprocess.DEVNULL)
            with open(path) as f:
                r = json.load(f)
            info = {k: r[k] for k in ("bodies", "steps", "mesoPhys_bytes", "mesoTangentialPhys_bytes",
                                      "frictPhys_bytes")}
            for n, L in r["laws"].items():
                M = runs[threads].setdefault(n, {"contacts": L["contacts"], "forces": L["forces"]})
                for key in KEYS:
                    M.setdefault(key, []).extend(L[key])

# this invocation's own measurements only, so that pooling them later counts nothing twice
if args.json and args.sessions:
    with open(args.json, "w") as f:
        json.dump({"info": info,
                   "runs": {t: {n: {k: v for k, v in L.items() if k != "forces"} for n, L in r.items()}
                            for t, r in runs.items()}}, f)
for path in args.merge:
    with open(path) as f:
        old = json.load(f)
    info = info or old["info"]
    if (old["info"]["bodies"], old["info"]["steps"]) != (info["bodies"], info["steps"]):
        sys.exit(f"benchmark_laws: {path} was measured on another scene (bodies, steps): not pooled")
    for threads in (1, 2):
        for n in laws:
            L = old["runs"][str(threads)].get(n)
            if L is None:
                sys.exit(f"benchmark_laws: {path} has no measurements of {n}")
            M = runs[threads].setdefault(n, {"contacts": L["contacts"]})
            for key in KEYS:
                M.setdefault(key, []).extend(L[key])
    print(f"pooled with {path}")

r1, r2 = runs[1], runs[2]
rounds_total = len(r1[laws[0]]["step_ns"])
print(f"\n{info['bodies']} spheres, {r1[laws[0]]['contacts']} contacts; {rounds_total} rounds of {info['steps']} steps "
      f"per law and thread count;\ncontact physics: MesoPhys {info['mesoPhys_bytes']} bytes, MesoTangentialPhys "
      f"{info['mesoTangentialPhys_bytes']} (FrictPhys {info['frictPhys_bytes']})")
print("medians over the rounds, per contact; Law2 = YADE's LawDispatcher, share = of the step with separate "
      "dispatchers")
for threads, r in runs.items():
    print(f"\n-j{threads}: {'law':20s} {'step':>9s} {'fastest':>9s} {'InteractionLoop':>16s} {'Law2':>9s} "
          f"{'Law2 share':>10s}  step/(a), quartiles")
    for n in laws:
        L, c = r[n], r[n]["contacts"]
        share = statistics.median(a / b for a, b in zip(L["law2_ns"], L["split_step_ns"]))
        line = (f"      {'(' + LETTER[n] + ')':4s} {n:19s} {statistics.median(L['step_ns']) / c:6.1f} ns "
                f"{min(L['step_ns']) / c:6.1f} ns {statistics.median(L['interaction_loop_ns']) / c:13.1f} ns "
                f"{statistics.median(L['law2_ns']) / c:6.1f} ns {share:9.1%}")
        if "cundall-strack" in r:
            q = quartiles([x / y for x, y in zip(L["step_ns"], r["cundall-strack"]["step_ns"])])
            line += f"  {q[1]:.3f} [{q[0]:.3f}, {q[2]:.3f}]"
        print(line)


def paired(r, num, den):
    """Quartiles of the per-round ratio of whole-step times num/den."""
    return quartiles([x / y for x, y in zip(r[num]["step_ns"], r[den]["step_ns"])])


def fastest(r, num, den):
    """Ratio of the fastest bursts: noise only ever slows a burst down."""
    return min(r[num]["step_ns"]) / min(r[den]["step_ns"])


def bootstrap_relative(r1, r2, x, y, samples=2000):
    """90 % interval of [median x/y at -j1] / [median x/y at -j2], the rounds of each thread count resampled."""
    rng = random.Random(7)
    a = [p / q for p, q in zip(r1[x]["step_ns"], r1[y]["step_ns"])]
    b = [p / q for p, q in zip(r2[x]["step_ns"], r2[y]["step_ns"])]
    est = sorted(statistics.median(rng.choices(a, k=len(a))) / statistics.median(rng.choices(b, k=len(b)))
                 for _ in range(samples))
    return est[int(0.05 * samples)], est[int(0.95 * samples) - 1]


def verdict(ok):
    return "yes" if ok else "NO"


CRITERIA = ((("meso-normal", "cundall-strack"), 1.10, False), (("meso-normal", "luding-basic"), 1.0, True),
            (("meso-full", "cohesion-moment"), 1.0, False), (("meso-full-rotations", "cohesion-moment"), 1.0, False))
present = [(xy, b, s) for xy, b, s in CRITERIA if all(n in laws for n in xy)]
if present:
    print("\ncriteria (whole-step time): median of the per-round ratios [quartiles]; ratio of the fastest bursts")
    for threads, r in runs.items():
        for (x, y), bound, strict in present:
            q, f = paired(r, x, y), fastest(r, x, y)
            ok = (lambda v: v < bound) if strict else (lambda v: v <= bound)
            print(f"  -j{threads}: ({LETTER[x]})/({LETTER[y]}) = {q[1]:.3f} [{q[0]:.3f}, {q[2]:.3f}]; {f:.3f}   "
                  f"({'<' if strict else '<='} {bound}: {verdict(ok(q[1]))}; {verdict(ok(f))})")
pairs = [(x, y) for x, y in PAIRS if x in laws and y in laws]
if pairs:
    # speed-up(x)/speed-up(y) = [x/y at -j1]/[x/y at -j2]: the within-round ratios cancel the machine's state.
    print("  -j2 speed-ups relative to each other (>= 1: at least as good), from the paired medians [90 "
          "% bootstrap interval")
    print("  over the rounds] and from the fastest bursts:")
    for x, y in pairs:
        rel = paired(r1, x, y)[1] / paired(r2, x, y)[1]
        lo, hi = bootstrap_relative(r1, r2, x, y)
        relf = fastest(r1, x, y) / fastest(r2, x, y)
        print(f"      speed-up ({LETTER[x]}) / speed-up ({LETTER[y]}) = {rel:.3f} [{lo:.3f}, {hi:.3f}]; {relf:.3f}   "
              f"({verdict(rel >= 1)}; {verdict(relf >= 1)})")

print("\nInteractionLoop speed-up with 2 threads, measured inside the -j2 runs: each burst against its neighbour "
      "with a")
print("one-thread InteractionLoop (median of the per-round ratios [quartiles]); and each law's against the "
      "others', paired by round:")
loop_speedup = {n: [a / b for a, b in zip(r2[n]["serial_loop_ns"], r2[n]["interaction_loop_ns"])] for n in laws}
for n in laws:
    q = quartiles(loop_speedup[n])
    print(f"  {'(' + LETTER[n] + ')':4s} {n:19s} {q[1]:.3f} [{q[0]:.3f}, {q[2]:.3f}]")
for x, y in PAIRS:
    if x in laws and y in laws:
        q = quartiles([a / b for a, b in zip(loop_speedup[x], loop_speedup[y])])
        print(f"      ({LETTER[x]}) / ({LETTER[y]}) = {q[1]:.3f} [{q[0]:.3f}, {q[2]:.3f}] ({verdict(q[1] >= 1)})")

print("\n-j2 speed-up (ratio of the median whole steps; of the fastest) and serial/parallel difference of the forces "
      "and torques on the bodies:")
for n in laws:
    s = statistics.median(r1[n]["step_ns"]) / statistics.median(r2[n]["step_ns"])
    sf = min(r1[n]["step_ns"]) / min(r2[n]["step_ns"])
    if "forces" not in r1[n]:  # measured in no run of this invocation
        print(f"  {'(' + LETTER[n] + ')':4s} {n:19s} speed-up {s:.3f}; {sf:.3f}")
        continue
    f1, f2 = r1[n]["forces"], r2[n]["forces"]
    diff = []
    for part in (slice(0, 3), slice(3, 6)):  # forces, then torques, each against its own scale
        scale = max(max(abs(a) for a in p[part]) for p in f1) or 1.0
        diff.append(max(max(abs(a - b) for a, b in zip(p[part], q[part])) for p, q in zip(f1, f2)) / scale)
    print(f"  {'(' + LETTER[n] + ')':4s} {n:19s} speed-up {s:.3f}; {sf:.3f}; max |F(-j2) - F(-j1)| / max "
          f"|F| = {diff[0]:.1e}, same for torques {diff[1]:.1e}")
