"""mesostudies.tablet.branchplot and studies/scripts/tablet_branches.py on made-up branch files whose means are
known: the plotted rows' means, the cycle cut, and the errors for bad files."""
import os
import subprocess
import sys
import tempfile
import unittest

from mesostudies.tablet import branchplot
from mesocontact.scene_names import BRANCHES

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


def write(text):
    fd, path = tempfile.mkstemp(suffix=".csv")
    with os.fdopen(fd, "w") as f:
        f.write(text)
    return path


def made_up(n=40, period=10):
    """Rows every step; the first half of each cycle all 'loading', the second all 'unloading'."""
    lines = ["iter,Dx," + ",".join(BRANCHES)]
    for i in range(n + 1):
        on = "loading" if (i % period) < period / 2 else "unloading"
        lines.append(f"{1000 + i},{0.01 * (i % period)}," + ",".join("1" if b == on else "0" for b in BRANCHES))
    return "\n".join(lines) + "\n"


class BranchPlot(unittest.TestCase):
    def test_means_and_cycles(self):
        path, png = write(made_up()), tempfile.mktemp(suffix=".png")
        mean = branchplot.plot(path, png, steps_per_cycle=10)
        self.assertAlmostEqual(mean["loading"], 21 / 41)  # steps 0-4, 10-14, ..., 40: 4 * 5 + 1 of 41
        self.assertAlmostEqual(mean["loading"] + mean["unloading"], 1.0)
        self.assertGreater(os.path.getsize(png), 10000)
        one = branchplot.plot(path, png, cycles=1, steps_per_cycle=10)  # steps 0..10: 5 + 1 of 11
        self.assertAlmostEqual(one["loading"], 6 / 11)

    def test_bad_files_are_named(self):
        for text, words in (("iter,Dx,new\n1,0,1\n", "missing"),
                            (made_up().replace("1000,0.0", "1000,abc", 1), "row 2"),
                            (made_up().replace("\n1000,0.0,0,0,0,1", "\n1000,0.0,0,0,0,0.5", 1), "sum to 0.5")):
            path = write(text)
            with self.assertRaises(ValueError) as c:
                branchplot.read(path)
            self.assertIn(path, str(c.exception))
            self.assertIn(words, str(c.exception))

    def test_script(self):
        path, png = write(made_up()), tempfile.mktemp(suffix=".png")
        r = subprocess.run([sys.executable, os.path.join(ROOT, "studies", "scripts", "tablet_branches.py"), path, png,
                            "--period", "10"],
                           capture_output=True, text=True)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("loading 0.512", r.stdout)
        r = subprocess.run([sys.executable, os.path.join(ROOT, "studies", "scripts", "tablet_branches.py"), path, png,
                            "--cycles", "1"],
                           capture_output=True, text=True)
        self.assertNotEqual(r.returncode, 0)
        self.assertIn("--cycles needs --period", r.stderr)


if __name__ == "__main__":
    unittest.main()
