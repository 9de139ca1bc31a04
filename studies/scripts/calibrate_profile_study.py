#!/usr/bin/python3
# The profile intervals on a multi-modal calibration problem (issue #32 item 11): jump-in
# adhesion, 7 speeds from 0.3 to 4 v_p, 2 % noise (the truth kp = 500, kc = 100, phiF = 0.1,
# fa = 2e-4 N, kca = 200 N/m, k1 = 100 N/m fixed), fitted for each noise draw; a draw counts
# where the truth fits within the 95 % threshold (chi2 of the truth - chi2 of the best fit < 3.84, all
# parameters at the truth, none refitted: so the truth lies inside every true profile interval)
# and it is a miss when a reported interval does not hold the truth.
#   python3 studies/scripts/calibrate_profile_study.py [--draws 12] [--out FILE.json] \
#       [--compare OLD_MODULE.py|OLD_PACKAGE_DIR | --compare-rev REV]
import argparse
import importlib.util
import json
import os
import re
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "py"))  # the library
import numpy as np  # noqa: E402
from mesocontact import calibrate, outputs, theory  # noqa: E402

ap = argparse.ArgumentParser(prog="calibrate_profile_study.py")
ap.add_argument("--draws", type=int, default=12)
ap.add_argument("--starts", type=int, default=10)
ap.add_argument("--out", default=None)
ap.add_argument("--compare", default=None,
                help="another version of mesocontact's calibrate (its module file, or its package "
                     "directory) on the same draws")
ap.add_argument("--compare-rev", default=None, help="the same, calibrate as it was at this git revision")
a = ap.parse_args()


def _git(*args):
    return subprocess.run(["git", "-C", HERE, *args], check=True, capture_output=True, text=True).stdout


def load_compared(files):
    """A package `calibrate_compared` from {file name: text} (a single module becomes its
    __init__), its imports of the rest of mesocontact made absolute."""
    pkg = os.path.join(tempfile.mkdtemp(prefix="calibrate-compared-"), "calibrate_compared")
    os.mkdir(pkg)
    up = r"\." if "__init__.py" in files and len(files) == 1 else r"\.\."  # the level that leaves calibrate
    for name, text in files.items():
        text = re.sub(r"^(\s*)from " + up + r"(\w*) import",
                      lambda m: f"{m.group(1)}from mesocontact{'.' + m.group(2) if m.group(2) else ''} import", text,
                      flags=re.M)
        with open(os.path.join(pkg, name), "w") as f:
            f.write(text)
    spec = importlib.util.spec_from_file_location("calibrate_compared", os.path.join(pkg, "__init__.py"),
                                                  submodule_search_locations=[pkg])
    module = importlib.util.module_from_spec(spec)
    sys.modules["calibrate_compared"] = module
    spec.loader.exec_module(module)
    return module


compared = None
if a.compare_rev:  # the module of that revision (one file before the package split, a package after)
    kind = subprocess.run(["git", "-C", HERE, "cat-file", "-t", f"{a.compare_rev}:py/mesocontact/calibrate"],
                          capture_output=True, text=True).stdout.strip()
    names = (_git("ls-tree", "--name-only", f"{a.compare_rev}:py/mesocontact/calibrate").split() if kind == "tree"
             else [])
    compared = {f: _git("show", f"{a.compare_rev}:py/mesocontact/calibrate/{f}") for f in names if f.endswith(".py")} \
        or {"__init__.py": _git("show", f"{a.compare_rev}:py/mesocontact/calibrate.py")}
elif a.compare:
    compared = ({f: open(os.path.join(a.compare, f)).read() for f in os.listdir(a.compare) if f.endswith(".py")}
                if os.path.isdir(a.compare) else {"__init__.py": open(a.compare).read()})
R, RHO, KCA = 1e-3, 2500.0, 200.0
TRUTH = dict(k1=100.0, kp=500.0, kc=100.0, phiF=0.1, fa=2e-4)
versions = {"this": calibrate}
if compared:
    versions["compared"] = load_compared(compared)
m_r, a12 = calibrate.geometry(R, RHO)
v_p = theory.plastic_limit_velocity(TRUTH["k1"], TRUTH["kp"], TRUTH["phiF"], a12, m_r, TRUTH["fa"])
v = np.geomspace(0.3 * v_p, 4 * v_p, 7)
setup = calibrate.Setup(m_r, a12, "jumpIn", KCA)
e0 = setup.curve(v, TRUTH)
rows = []
for seed in range(a.draws):
    noise = 0.02 * np.maximum(e0, 0.1)
    e = np.where(e0 > 0, np.clip(e0 + noise * np.random.default_rng(seed).standard_normal(len(v)), 0, 1), 0)
    sigma = np.maximum(noise, 1e-3)
    row = {"seed": seed}
    for name, mod in versions.items():
        t0 = time.time()
        f = mod.fit((v, e, sigma), R, RHO, adhesion="jumpIn", kca=KCA, values=dict(k1=100.0), starts=a.starts,
                    bootstrap=0)
        chi2 = lambda p: float(np.sum(((setup.curve(v, p) - e) / sigma) ** 2))  # noqa: E731
        row["chi2_truth"] = chi2(TRUTH)
        row[name] = {"chi2_fit": chi2(f.params), "delta_chi2_truth": chi2(TRUTH) - chi2(f.params), "ci95": f.ci95,
                     "params": f.params,
                     "outside": [n for n in f.free if not f.ci95[n][0] <= TRUTH[n] <= f.ci95[n][1]],
                     "seconds": time.time() - t0}
        print(f"draw {seed} {name:8s}: truth at +{row[name]['delta_chi2_truth']:.2f}, outside {row[name]['outside']}, "
              f"{row[name]['seconds']:.0f} s", flush=True)
    rows.append(row)
summary = {}
for name in versions:
    # the premise against the best fit any version found
    inside = [r for r in rows if r["chi2_truth"] - min(r[n]["chi2_fit"] for n in versions) < calibrate.PROFILE_CHI2]
    summary[name] = {"draws": len(rows), "truth_within_threshold": len(inside),
                     "of_those_missed": sum(1 for r in inside if r[name]["outside"]),
                     "missed_anywhere": sum(1 for r in rows if r[name]["outside"]),
                     "median_seconds": float(np.median([r[name]["seconds"] for r in rows]))}
    print(name, summary[name], flush=True)
if a.out:
    outputs.write_atomic(a.out, json.dumps({"command": "python3 studies/scripts/calibrate_profile_study.py "
                                                       + " ".join(sys.argv[1:]),
                                            "truth": TRUTH, "summary": summary, "draws": rows}, indent=1,
                                           default=float))
