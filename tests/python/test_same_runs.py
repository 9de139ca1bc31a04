"""`studies/scripts/tablet_same_runs.py`: two copies of campaign files agree when only their clocks
differ; a changed CSV byte or JSON entry that is not a clock is reported."""
import importlib.util
import json
import os
import shutil
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
_spec = importlib.util.spec_from_file_location("same_runs",
                                               os.path.join(HERE, "..", "..", "studies", "scripts",
                                                            "tablet_same_runs.py"))
same_runs = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(same_runs)

RUN = {"peaks": [-0.06, -0.039], "wall_clock_s": 386.2, "ms_per_step": 1.63, "L0": 0.11606,
       "runs": {"x": {"ms_per_step": 2.0, "steps": 948416}}}


class SameRuns(unittest.TestCase):
    def setUp(self):
        self.a, self.b = tempfile.mkdtemp(), tempfile.mkdtemp()
        for d in (self.a, self.b):
            with open(os.path.join(d, "run.csv"), "w") as f:
                f.write("iter,Dx,F\n0,0.0,0.003\n100,0.001,-0.01\n")
            with open(os.path.join(d, "run.json"), "w") as f:
                json.dump(RUN, f)

    def tearDown(self):
        shutil.rmtree(self.a)
        shutil.rmtree(self.b)

    def _json_b(self, **change):
        with open(os.path.join(self.b, "run.json"), "w") as f:
            json.dump(dict(RUN, **change), f)

    def test_clocks_only(self):
        self._json_b(wall_clock_s=640.0, ms_per_step=2.7, runs={"x": {"ms_per_step": 1.5, "steps": 948416}})
        out = same_runs.compare(self.a, self.b)
        self.assertEqual(out["different"], {})
        self.assertEqual((out["csv_identical"], out["json_same_but_clocks"]), (["run.csv"], ["run.json"]))
        self.assertEqual(same_runs.main([self.a, self.b]), 0)

    def test_physics_entry_differs(self):
        self._json_b(peaks=[-0.06, -0.0391])
        self.assertEqual(same_runs.compare(self.a, self.b)["different"], {"run.json": ["/peaks[1]"]})
        self._json_b(runs={"x": {"ms_per_step": 2.0, "steps": 948417}})
        self.assertEqual(same_runs.compare(self.a, self.b)["different"], {"run.json": ["/runs/x/steps"]})
        self.assertEqual(same_runs.main([self.a, self.b]), 1)

    def test_csv_byte_differs(self):
        with open(os.path.join(self.b, "run.csv"), "w") as f:
            f.write("iter,Dx,F\n0,0.0,0.003\n100,0.001,-0.011\n")
        self.assertEqual(same_runs.compare(self.a, self.b)["different"], {"run.csv": "bytes"})

    def test_files_on_one_side(self):
        open(os.path.join(self.a, "extra.json"), "w").write("{}")
        out = same_runs.compare(self.a, self.b)
        self.assertEqual((out["only_in_a"], out["only_in_b"], out["different"]), (["extra.json"], [], {}))


if __name__ == "__main__":
    unittest.main()
