"""`yade-batch` with the build-tree launcher runs `scripts/pair_batch.py` once per table line: each job
writes its JSON and YADE agrees with the closed form (1e-3, the pair tests' tolerance); a table with
a column the script does not know fails that job, naming the column;
`examples/impact-velocity.table` runs as the README runs it (both sticking regimes and the rebound).

    python3 tests/python/test_batch.py build/yade-meso"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
YADE = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else os.path.join(ROOT, "build", "yade-meso")


def batch(table_text, d):
    table = os.path.join(d, "jobs.table")
    with open(table, "w") as f:
        f.write(table_text)
    return subprocess.run(["yade-batch", "--executable", YADE, "-j", "2", "--nice", "0", "--log",
                           os.path.join(d, "job-@.log"),
                           table, os.path.join(ROOT, "scripts", "pair_batch.py")], cwd=d, capture_output=True,
                          text=True,
                          timeout=600)


class Batch(unittest.TestCase):
    def test_table_lines_run_and_agree_with_theory(self):
        d = tempfile.mkdtemp()
        out = os.path.join(d, "res")
        r = batch("description  kp    kc   phiF  v     against     out\n"
                  f"rebound      500   100  0.05  0.02  'particle'  '{out}'\n"
                  f"plastic-wall 5100  5    0.02  0.04  'wall'      '{out}'\n", d)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        for name in ("rebound", "plastic-wall"):
            with open(os.path.join(out, name + ".json")) as f:
                j = json.load(f)
            self.assertLessEqual(abs(j["e_yade"] - j["e_theory"]), 1e-3, name)
            self.assertGreater(j["e_theory"], 0, name)
        self.assertIn("kp=5100", j["params"])

    def test_shipped_impact_table(self):
        # examples/impact-velocity.table as the README runs it: every line a job, each meets theory
        d = tempfile.mkdtemp()
        with open(os.path.join(ROOT, "examples", "impact-velocity.table")) as f:
            text = f.read()
        r = batch(text, d)
        self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
        names = [line.split()[0] for line in text.splitlines() if line.startswith("v-")]
        regimes = set()
        for name in names:
            with open(os.path.join(d, "results", "batch", name + ".json")) as f:
                j = json.load(f)
            self.assertLessEqual(abs(j["e_yade"] - j["e_theory"]), 1e-3, name)
            regimes.add(j["regime"])
        self.assertEqual(len(names), 5)
        self.assertEqual(regimes, {"rebound", "sticking-contact", "sticking-noncontact"})  # both sticking regimes

    def test_unknown_column_is_named(self):
        d = tempfile.mkdtemp()
        batch("description  kq\nbad  1\n", d)
        with open(os.path.join(d, "job-bad.log")) as f:
            log = f.read()
        self.assertIn("kq", log)
        self.assertFalse(os.path.exists(os.path.join(d, "results", "batch", "bad.json")))

    def test_shared_description_is_refused(self):
        # two lines with one description would write one set of files: both jobs stop, naming the lines
        d = tempfile.mkdtemp()
        batch("description  kp\ntwin  500\ntwin  600\n", d)
        with open(os.path.join(d, "job-twin.log")) as f:
            log = f.read()
        self.assertIn("lines 2, 3 share the description 'twin'", log)
        self.assertFalse(os.path.exists(os.path.join(d, "results", "batch", "twin.json")))


if __name__ == "__main__":
    unittest.main()
