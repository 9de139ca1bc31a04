# ctest (inside yade, run from the build tree): the command lines check their values before any work
# starts (issue #14 item 18): each bad value ends the script with an error naming the option, within
# seconds, and leaves nothing behind; `figure.py` refuses unknown figures and papers; --help prints
# the usage.
import os
import subprocess
import tempfile
import time

import mesocontact  # noqa: E402  (the source tree's package: the scripts lie beside it)
from harness import failures, finish

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(mesocontact.__file__))))
# the library's scripts, and the studies' (the tablet's jobs behind tablet.py, the figures)
where = {name: (os.path.join(ROOT, "studies", "scripts") if name.startswith(("tablet", "figure"))
                else os.path.join(ROOT, "scripts"))
         for name in ("pair_batch.py", "tablet.py", "tablet_report.py", "tablet_restore.py", "figure.py")}
launcher = os.path.abspath("yade-meso")  # ctest runs this from the build directory


def run(script, *args):
    t0 = time.time()
    p = subprocess.run([launcher, "-j1", "-n", "-x", os.path.join(where[script], script), *args], capture_output=True,
                       text=True,
                       timeout=120)
    return p.returncode, p.stdout + p.stderr, time.time() - t0


tmp = tempfile.mkdtemp(prefix="cli-")
out = os.path.join(tmp, "out")
cases = [
    ("fig16", ["--amplitudes", "inf"], "--amplitudes"),
    ("fig16", ["--amplitudes", "abc"], "--amplitudes"),
    ("fig16", ["--amplitudes", "-0.1"], "--amplitudes"),
    ("fig18", ["--quick", "--amplitudes", "10"], "--amplitudes"),  # the quick sample is about 6 d0 long
    ("fig16", ["--periods", "1e-6"], "--periods"),
    ("fig16", ["--periods", "nan"], "--periods"),
    ("fig17", ["--speed", "0"], "--speed"),
    ("prepare", ["--kc-over-kp", "-1"], "--kc-over-kp"),
    ("prepare", ["--n", "3"], "--n"),
    ("fig16", ["--mpi", "1"], "--mpi"),
    ("fig16", ["--mpi", "3"], "--mpi"),  # not started by mpiexec -n 3
    ("rates", ["--mpi", "3"], "--mpi"),  # only fig16, fig17 and fig18 run under yade.mpy
    ("fig19", ["--mpi", "3"], "--mpi"),
    ("fig17", ["--mpi", "3"], "--mpi"),  # not started by mpiexec -n 3
    ("fig17", ["--until", "0"], "--until"),
    ("affine", ["--sinter", "0"], "--sinter"),
    ("fig17", ["--sinter", "0.1"], "--sinter"),  # the pull runs on the campaign's sample only: not ignored silently
]
for job, args, option in cases:
    script = f"tablet.py {job}"
    rc, text, secs = run("tablet.py", job, *args, "--out", out)
    ok = rc != 0 and option in text and secs < 60 and not os.path.exists(os.path.join(out, "released.yade.gz"))
    last = [line for line in text.splitlines() if option in line][-1:] or text.splitlines()[-1:]
    print(("ok   " if ok else "FAIL ") + f"{script} {' '.join(args)}: rc {rc}, {secs:.0f} s: {last[0] if last else ''}",
          flush=True)
    if not ok:
        failures.append(f"{script} {' '.join(args)}")
# An --out that cannot be written fails at once.
blocker = os.path.join(tmp, "file")
open(blocker, "w").close()
rc, text, secs = run("tablet.py", "fig16", "--out", os.path.join(blocker, "sub"))
ok = rc != 0 and "--out" in text and "not writable" in text
print(("ok   " if ok else "FAIL ") + f"unwritable --out: rc {rc}, {secs:.0f} s", flush=True)
if not ok:
    failures.append("unwritable --out")
# --help prints the usage and runs nothing (it used to create a folder "--help" and run the job).
os.chdir(tmp)
rc, text, secs = run("figure.py", "--help")
ok = rc == 0 and "usage" in text and not os.path.exists(os.path.join(tmp, "--help")) and "[atlas]" not in text
print(("ok   " if ok else "FAIL ")
      + f"figure.py --help: rc {rc}, {secs:.0f} s, folder '--help': {os.path.exists('--help')}", flush=True)
if not ok:
    failures.append("figure.py --help")
# Every script without argparse honours --help too (pair_batch.py used to run a job), and the two
# that take positional arguments refuse a wrong count with their usage.
for script in ("pair_batch.py", "tablet.py", "tablet_report.py", "tablet_restore.py"):
    rc, text, secs = run(script, "--help")
    ok = rc == 0 and "yade" in text and not os.path.exists(os.path.join(tmp, "results")) and secs < 60
    print(("ok   " if ok else "FAIL ") + f"{script} --help: rc {rc}, {secs:.0f} s", flush=True)
    if not ok:
        failures.append(f"{script} --help")
rc, text, secs = run("tablet_report.py", "onlyone")
ok = rc == 2 and "expected 2 argument(s)" in text
print(("ok   " if ok else "FAIL ") + f"tablet_report.py with one argument: rc {rc}", flush=True)
if not ok:
    failures.append("tablet_report.py onlyone")
# The atlas refuses what it does not have, naming it, before any collision.
for args, says in ((["4"], "figure 4 of the long paper"), (["7", "--paper", "short"], "figure 7 of the short paper"),
                   ([], "give a figure number or --all"), (["5", "--all"], "give a figure number or --all"),
                   (["5", "--paper", "mid"], "--paper")):
    rc, text, secs = run("figure.py", *args, "--out", out)
    ok = rc != 0 and says in text and "[atlas]" not in text and secs < 60
    print(("ok   " if ok else "FAIL ") + f"figure.py {' '.join(args)}: rc {rc}, {secs:.0f} s: {says!r} in the message",
          flush=True)
    if not ok:
        failures.append(f"figure.py {' '.join(args)}")
# An output path that is a file: named at once, no traceback (issue #49 item 10).
afile = os.path.join(tmp, "a-file")
open(afile, "w").close()
for script, args, says in (("figure.py", ["5", "--out", afile], "--out " + afile + ": exists and is not a directory"),
                           ("tablet_restore.py", [os.path.join(ROOT, "campaigns", "tablet", "chosen"), afile],
                            "a file, not a directory")):
    rc, text, secs = run(script, *args)
    ok = rc != 0 and says in text and "Traceback" not in text and "[atlas]" not in text
    print(("ok   " if ok else "FAIL ") + f"{script} with a file for its output: rc {rc}: {says!r} in the message",
          flush=True)
    if not ok:
        failures.append(f"{script} output file")

finish()
