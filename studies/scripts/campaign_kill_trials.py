#!/usr/bin/env python3
"""The tablet campaign stopped at random moments (issue #14): in each trial two quick jobs share
one output directory (run concurrently), one of them is killed (SIGTERM or SIGKILL, at a random
time), the other finishes; then every file in the directory is checked: each result bundle is
complete (its manifest's SHA-256 sums), each saved stage has its description and loads, and no
leftover of a stopped job remains once the next job has started (outputs.sweep).

    python3 studies/scripts/campaign_kill_trials.py [YADE] [--trials 10] [--seed 1] [--out FILE.json]

YADE defaults to the build-tree launcher build/yade-meso. Plain Python (it starts YADE jobs).
"""
import argparse
import json
import os
import random
import shutil
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.dirname(HERE)), "py"))
from mesocontact import outputs  # noqa: E402  (plain Python)

JOBS = [["fig16", "--quick", "--amplitudes", "0.05,0.2"], ["fig18", "--quick", "--amplitudes", "0.05,0.2"],
        ["fig17", "--quick", "--speed", "0.0075"], ["rates", "--quick", "--periods", "30,120"]]


def start(yade, job, out):
    cmd = [yade, "-j1", "-n", "-x", os.path.join(HERE, "tablet.py"), *job, "--out", out]
    return subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)


def stage_problems(out):
    found = []
    for parent, _, files in os.walk(out):
        for f in files:
            if f.endswith(".yade.gz") and ".tmp-" not in f and f + ".json" not in files:
                found.append(f"state without its description: {os.path.join(parent, f)}")
            if f.endswith(".yade.gz.json"):
                try:
                    with open(os.path.join(parent, f)) as fh:
                        json.load(fh)
                except ValueError:
                    found.append(f"unreadable description: {os.path.join(parent, f)}")
    return found


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("yade", nargs="?", default=os.path.join(os.path.dirname(HERE), "build", "yade-meso"))
    ap.add_argument("--trials", type=int, default=10)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--out", default=None)
    a = ap.parse_args()
    rng = random.Random(a.seed)
    base = tempfile.mkdtemp(prefix="kill-trials-")
    template = os.path.join(base, "prepared")  # the cached stages, made once (not killed)
    subprocess.run([a.yade, "-j1", "-n", "-x", os.path.join(HERE, "tablet.py"), "prepare", "--quick", "--out",
                    template],
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    trials = []
    for k in range(a.trials):
        # A fresh directory each trial: every third one empty (the kill lands in the preparation),
        # the others with the stages (it lands in the runs and figures).
        out = os.path.join(base, f"trial{k}")
        os.makedirs(out)
        empty = k % 3 == 0
        if not empty:
            for f in os.listdir(template):
                if f.endswith((".yade.gz", ".yade.gz.json")):
                    shutil.copy(os.path.join(template, f), out)
        victim, other = rng.sample(JOBS, 2)
        sig = signal.SIGKILL if k % 2 else signal.SIGTERM
        delay = rng.uniform(2.0, 40.0 if empty else 15.0)
        t0 = time.time()
        p1, p2 = start(a.yade, victim, out), start(a.yade, other, out)
        try:
            p1.wait(timeout=delay)
            killed = False  # finished before its moment
        except subprocess.TimeoutExpired:
            os.killpg(p1.pid, sig)
            p1.wait()
            killed = True
        rc2 = p2.wait(timeout=3600)
        before = outputs.problems(out, ignore_running=False) + stage_problems(out)
        # The next job clears what a killed one left (hidden temporary files of dead processes).
        outputs.sweep(out)
        after = outputs.problems(out, ignore_running=False) + stage_problems(out)
        bundles = sum(1 for parent, _, files in os.walk(out) if outputs.MANIFEST in files)
        trials.append({"trial": k, "from": "empty" if empty else "stages", "killed": " ".join(victim[:1]),
                       "signal": signal.Signals(sig).name, "at_s": round(delay, 1),
                       "killed_before_end": killed, "other": " ".join(other[:1]), "other_rc": rc2, "bundles": bundles,
                       "problems_before_sweep": before, "problems_after_sweep": after,
                       "wall_s": round(time.time() - t0, 1)})
        print(json.dumps(trials[-1]), flush=True)
    summary = {"command": "python3 studies/scripts/campaign_kill_trials.py " + " ".join(sys.argv[1:]), "trials": trials,
               "killed": sum(t["killed_before_end"] for t in trials),
               "other_job_failed": sum(t["other_rc"] != 0 for t in trials),
               "problems_after_sweep": sum(len(t["problems_after_sweep"]) for t in trials),
               "incomplete_results_before_sweep": sum(sum("incomplete" in p or "without" in p or "unreadable" in p
                                                          for p in t["problems_before_sweep"]) for t in trials)}
    print(json.dumps({k: v for k, v in summary.items() if k != "trials"}, indent=1))
    if a.out:
        outputs.write_atomic(a.out, json.dumps(summary, indent=1))
    ok = (summary["problems_after_sweep"] == 0 and summary["incomplete_results_before_sweep"] == 0
          and summary["other_job_failed"] == 0)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
