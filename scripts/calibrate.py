#!/usr/bin/python3
# The law's normal parameters from measured restitution data (docs/calibration.md):
#   python3 scripts/calibrate.py DATA.csv --radius R --density RHO --k1 K1 [--against particle|wall]
#       [--adhesion none|reversible|jumpIn] [--kca KCA] [--free kp,kc,phiF[,fa]] [--out DIR]
# DATA.csv: a header naming v, e and optionally sigma (SI units, # comments). Prints the fit and
# writes DIR/calibration.json and DIR/calibration.png; then runs the fitted parameters through
# YADE pair collisions at the data's speeds (--no-yade-check skips it, --yade names the launcher).
# --against names the collision the data come from: one material gives another e(v) on a wall
# (twice the reduced radius) than between two particles.
import argparse
import json
import math
import os
import shutil
import subprocess
import sys

# Inside YADE (yade -x, yade-batch) __file__ names YADE's own launcher; argv[0] names this script.
SCRIPT = os.path.abspath(sys.argv[0] if os.path.basename(sys.argv[0]) == "calibrate.py" else __file__)
HERE = os.path.dirname(SCRIPT)
sys.path.insert(0, os.path.join(HERE, "..", "py"))


def _need_scipy():
    """The fit needs numpy and scipy (Debian: python3-numpy, python3-scipy); an interpreter
    without them hands over to Debian's /usr/bin/python3 when that one has them."""
    import importlib.util
    if importlib.util.find_spec("numpy") is None or importlib.util.find_spec("scipy") is None:
        deb = "/usr/bin/python3"
        if os.path.realpath(sys.executable) != os.path.realpath(deb) and os.path.exists(deb) and \
                subprocess.run([deb, "-c", "import numpy, scipy"], capture_output=True).returncode == 0:
            print(f"(numpy/scipy missing in {sys.executable}; running under {deb})", flush=True)
            os.execv(deb, [deb] + sys.argv)
        sys.exit("calibrate.py needs numpy and scipy: install Debian's python3-numpy and python3-scipy")


def _launcher(given):
    if given:
        return given
    tree = os.path.join(HERE, "..", "build", "yade-meso")
    if os.path.exists(tree):
        return os.path.abspath(tree)
    found = shutil.which("yade")
    if not found:
        sys.exit("no YADE launcher found: pass --yade PATH or --no-yade-check")
    return found


def parse(argv):
    from mesocontact import calibrate as cal
    p = argparse.ArgumentParser(prog="python3 scripts/calibrate.py",
                                description="Fit k1, kp, kc, phiF, fa of the meso-particle law to "
                                            "restitution data e(v).")
    p.add_argument("data", help="CSV with columns v, e [, sigma] (SI units; # comments)")
    p.add_argument("--radius", type=float, required=True, help="particle radius [m]")
    p.add_argument("--density", type=float, required=True, help="particle density [kg/m^3]")
    p.add_argument("--against", choices=cal.AGAINST, default="particle",
                   help="the collision the data come from: particle, two equal spheres (a12 = R, m_r = m/2); wall, a "
                        "sphere on a wall (a12 = 2R, m_r = m). One material gives different e(v) in the two: the wall "
                        "contact has twice the reduced radius (and mass), so its v_p is sqrt(2) times the pair's and "
                        "e_pair(v) = e_wall(sqrt(2) v) without adhesion (docs/calibration.md)")
    p.add_argument("--adhesion", choices=("none", "reversible", "jumpIn"), default="none")
    p.add_argument("--interpolation", choices=("linear", "sqrt"), default="linear", help="k2(deltaMax) rule")
    p.add_argument("--free", default=None, help="comma-separated free parameters among k1,kp,kc,phiF,fa "
                   "(default kp,kc,phiF, and fa with adhesion)")
    for n, what in (("k1", "loading stiffness [N/m] (always needed: fixed, or the start when free)"),
                    ("kp", "limit stiffness [N/m]"), ("kc", "tensile stiffness [N/m] (default 0 when fixed)"),
                    ("phiF", "plasticity depth"), ("fa", "non-contact force [N] (default 0 when fixed)")):
        p.add_argument("--" + n, type=float, default=None, help=what)
    p.add_argument("--kca", type=float, default=math.inf,
                   help="stiffness of the non-contact force [N/m]: assumed, not fitted; the fitted fa (and kc, kp) "
                        "follow it, and the report says how much")
    p.add_argument("--starts", type=int, default=40, help="starting points of the fit")
    p.add_argument("--bootstrap", type=int, default=200, help="bootstrap resamples (0: none)")
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--out", default="results/calibration", help="output directory")
    p.add_argument("--yade", default=None, help="YADE launcher for the check (default: the build tree's, else yade)")
    p.add_argument("--no-yade-check", action="store_true", help="skip the YADE pair collisions")
    # synthetic studies: a JSON of the true parameters, drawn
    p.add_argument("--truth", default=None, help=argparse.SUPPRESS)
    p.add_argument("--yade-check", default=None, help=argparse.SUPPRESS)  # internal: run inside YADE on this JSON
    # "--radius -1e-3": argparse takes a negative number for an option unless it looks like one of its
    # own; join such values to their option, so that the value is refused by name below, not read as missing.
    argv = list(argv)
    for k in range(len(argv) - 1):
        if argv[k] is not None and argv[k + 1] is not None and argv[k].startswith("--") and "=" not in argv[k] \
                and argv[k + 1].startswith("-") and _is_number(argv[k + 1]):
            argv[k], argv[k + 1] = argv[k] + "=" + argv[k + 1], None
    a = p.parse_args([x for x in argv if x is not None])
    for n in ("starts", "bootstrap"):
        if getattr(a, n) < (1 if n == "starts" else 0):
            p.error(f"--{n} {getattr(a, n)} is invalid: must be >= {1 if n == 'starts' else 0}")
    for n, what in (("radius", "a particle radius [m]"), ("density", "a density [kg/m^3]")):
        v = getattr(a, n)
        if not (math.isfinite(v) and v > 0):
            p.error(f"--{n} {v!r} is invalid: must be {what}, finite and > 0")
    # The output folder and the YADE launcher are checked now, not after a fit of seconds to minutes.
    if os.path.exists(a.out) and not os.path.isdir(a.out):
        p.error(f"--out {a.out}: exists and is not a directory")
    try:
        os.makedirs(a.out, exist_ok=True)
    except OSError as e:
        p.error(f"--out {a.out}: cannot be made ({e.strerror})")
    if not a.no_yade_check and a.yade is not None and not (os.access(a.yade, os.X_OK) or shutil.which(a.yade)):
        p.error(f"--yade {a.yade}: not an executable (or pass --no-yade-check)")
    return a


def _is_number(text):
    try:
        float(text)
        return True
    except ValueError:
        return False


def yade_side(path):
    """Inside YADE: the collisions at the data's speeds, written next to the calibration."""
    from mesocontact import calibrate as cal
    with open(path) as f:
        job = json.load(f)
    pts = cal.yade_check(job["fit"], job["velocities"], job["radius"], job["density"], job["against"])
    from mesocontact import outputs
    outputs.write_atomic(job["result"], json.dumps(pts))


def main(argv):
    if "--yade-check" in argv:  # inside YADE (numpy from Debian's python there)
        return yade_side(argv[argv.index("--yade-check") + 1])
    _need_scipy()
    from mesocontact import calibrate as cal
    from mesocontact import outputs
    a = parse(argv)
    try:
        data = cal.load_data(a.data)
        values = {n: getattr(a, n) for n in cal.PARAMETERS if getattr(a, n) is not None}
        free = a.free.split(",") if a.free else None
        fit = cal.fit(data, a.radius, a.density, a.against, a.adhesion, a.kca, a.interpolation, free=free,
                      values=values, starts=a.starts, bootstrap=a.bootstrap, seed=a.seed)
    except (ValueError, OSError) as e:
        sys.exit(f"calibrate.py: {e}")
    print(fit.report(), flush=True)
    os.makedirs(a.out, exist_ok=True)
    result = fit.to_json()
    result.update(data=os.path.abspath(a.data), radius=a.radius, density=a.density, against=a.against)
    pts = None
    if not a.no_yade_check:
        job = os.path.join(a.out, "yade-check-job.json")
        out = os.path.join(a.out, "yade-check-points.json")
        outputs.write_atomic(job, json.dumps({"fit": result, "velocities": [float(v) for v in data.v],
                                              "radius": a.radius,
                                              "density": a.density, "against": a.against, "result": out}))
        yade = _launcher(a.yade)
        print(f"YADE check: {len(data.v)} pair collisions ({yade})", flush=True)
        env = {k: v for k, v in os.environ.items() if k != "YADE_BATCH"}  # the check is not a batch job
        r = subprocess.run([yade, "-j1", "-n", "-x", SCRIPT, "--yade-check", job], env=env)
        if r.returncode != 0 or not os.path.exists(out):
            sys.exit(f"calibrate.py: the YADE check failed (exit code {r.returncode})")
        with open(out) as f:
            pts = json.load(f)
        os.remove(job)
        os.remove(out)
        worst = max(abs(y - c) for _, y, c in pts)
        result["yade_check"] = {"points": [{"v": v, "e_yade": y, "e_fit": c} for v, y, c in pts], "worst_abs_de": worst}
        print(f"YADE check: worst |e_yade - e_fit| = {worst:.2e} over {len(pts)} collisions", flush=True)
    truth = None
    if a.truth:
        with open(a.truth) as f:
            truth = json.load(f)
        result["truth"] = truth
    outputs.write_atomic(os.path.join(a.out, "calibration.json"), json.dumps(result, indent=1))
    cal.plot(fit, os.path.join(a.out, "calibration.png"), pts, truth)
    print(f"wrote {os.path.join(a.out, 'calibration.json')} and calibration.png", flush=True)


def batch_argv(argv):
    """Under yade-batch (YADE_BATCH set; this script then runs inside YADE) the options come from
    the table's line: columns data (the CSV), radius, density and any other option, underscores
    for dashes, e.g. no_yade_check=True."""
    if not os.environ.get("YADE_BATCH") or "--yade-check" in argv:
        return argv
    from mesocontact import batch
    return batch.argv(argv, positional="data", data=None, radius=None, density=None, against=None, adhesion=None,
                      interpolation=None, free=None, k1=None, kp=None, kc=None, phiF=None, fa=None, kca=None,
                      starts=None,
                      bootstrap=None, seed=None, out=None, yade=None, no_yade_check=False)


main(batch_argv(sys.argv[1:]))
