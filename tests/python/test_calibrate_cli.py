"""`scripts/calibrate.py` end to end (ctest gives the YADE launcher): a fit of exact synthetic data
with its YADE check (|Δe| ≤ 1e-3), the files it writes, and the errors for bad input.

    python3 tests/python/test_calibrate_cli.py build/yade-meso"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.join(HERE, "..", "..")
sys.path.insert(0, os.path.join(ROOT, "py"))
from mesocontact import calibrate as cal  # noqa: E402
from mesocontact import theory  # noqa: E402

YADE = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else os.path.join(ROOT, "build", "yade-meso")
R, RHO = 1e-3, 2500.0
TRUTH = dict(k1=100.0, kp=500.0, kc=100.0, phiF=0.05, fa=0.0)


def run(*args):
    return subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "calibrate.py"), *args],
                          capture_output=True, text=True)


class Cli(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp()

    def write(self, name, text):
        path = os.path.join(self.dir, name)
        with open(path, "w") as f:
            f.write(text)
        return path

    def test_fit_with_yade_check(self):
        m_r, a12 = cal.geometry(R, RHO)
        vp = theory.plastic_limit_velocity(100.0, 500.0, 0.05, a12, m_r)
        v = [vp * x for x in (0.03, 0.1, 0.25, 0.4, 0.7, 1.5, 3.0, 5.0)]
        e = cal.Setup(m_r, a12).curve(v, TRUTH)
        # Exact values with a stated error: without sigma an exact fit is refused (no noise to estimate).
        path = self.write("d.csv", "# exact data of eta = 4, beta = 1\nv,e,sigma\n"
                          + "".join(f"{a!r},{b!r},0.01\n" for a, b in zip(v, e)))
        out = os.path.join(self.dir, "out")
        r = run(path, "--radius", repr(R), "--density", repr(RHO), "--k1", "100", "--starts", "5", "--bootstrap", "10",
                "--out", out, "--yade", YADE)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        with open(os.path.join(out, "calibration.json")) as f:
            j = json.load(f)
        for key in ("k1", "kp", "kc", "phiF", "fa", "kca", "adhesion", "ci95", "undetermined", "rms_residual",
                    "yade_check"):
            self.assertIn(key, j)
        for n in ("kp", "kc", "phiF"):
            self.assertAlmostEqual(j[n] / TRUTH[n], 1.0, delta=1e-5, msg=n)
        self.assertEqual(len(j["yade_check"]["points"]), len(v))
        # the pair tests' tolerance: YADE against the closed form to 1e-3 at 2000 steps per contact
        self.assertLessEqual(j["yade_check"]["worst_abs_de"], 1e-3)
        self.assertGreater(os.path.getsize(os.path.join(out, "calibration.png")), 10000)
        self.assertIn("YADE check: worst", r.stdout)

    def test_bad_input_is_named(self):
        bad = self.write("bad.csv", "v,e\n0.1,1.2\n0.2,0.5\n0.3,0.4\n0.4,0.3\n")
        for args, words in (([bad, "--radius", "1e-3", "--density", "2500", "--k1", "100"], "e = 1.2 at point 1"),
                            ([self.write("ok.csv", "v,e\n0.1,0.9\n0.2,0.5\n0.3,0.4\n"), "--radius", "1e-3",
                              "--density", "2500"], "no value for k1"),
                            ([bad, "--radius", "1e-3", "--density", "2500", "--k1", "100", "--starts", "0"],
                             "--starts 0 is invalid"),
                            ([bad, "--radius", "1e-3"], "--density")):
            r = run(*args, "--no-yade-check", "--out", os.path.join(self.dir, "x"))
            self.assertNotEqual(r.returncode, 0, args)
            self.assertIn(words, r.stderr, args)
            self.assertNotIn("Traceback", r.stderr, args)

    def test_refused_before_the_fit(self):
        """A negative radius is named (argparse read it as a missing value), and an --out that is a file
        or a --yade that does not exist are refused before the fit, not after its seconds."""
        import time
        data = self.write("ok.csv", "v,e,sigma\n0.1,0.9,0.01\n0.2,0.5,0.01\n0.3,0.4,0.01\n0.4,0.35,0.01\n")
        afile = self.write("afile", "")
        base = [data, "--density", "2500", "--k1", "100"]
        for args, words in (([*base, "--radius", "-1e-3"], "--radius -0.001 is invalid"),
                            ([*base, "--radius", "1e-3", "--out", afile], "exists and is not a directory"),
                            ([*base, "--radius", "1e-3", "--out", os.path.join(afile, "x")], "cannot be made"),
                            ([*base, "--radius", "1e-3", "--out", os.path.join(self.dir, "y"), "--yade", "/no/yade"],
                             "--yade /no/yade: not an executable")):
            t0 = time.time()
            r = run(*args)
            self.assertEqual(r.returncode, 2, args)
            self.assertIn(words, r.stderr, args)
            self.assertNotIn("fit", r.stdout.lower(), args)  # nothing of the fit was printed
            self.assertLess(time.time() - t0, 5.0, args)


if __name__ == "__main__":
    unittest.main()
