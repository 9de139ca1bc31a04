"""The package's layers as a newcomer meets them (plain Python, no YADE): the tablet's modules in
their subpackage, the old import paths giving the same module objects, ``python3 -m`` on an old
path, and the sample's names reached through ``mesocontact.tablet`` refusing clearly without YADE."""
import importlib
import json
import os
import subprocess
import sys
import tempfile
import unittest

import mesocontact
from mesocontact import tablet

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DOCS = os.path.join(ROOT, "docs", "tablet", "chosen")


class Layout(unittest.TestCase):
    def test_old_paths_give_the_moved_modules(self):
        for name in ("measures", "statements", "branchplot"):
            old = importlib.import_module("mesocontact." + name)
            new = importlib.import_module("mesocontact.tablet." + name)
            self.assertIs(old, new, name)
            self.assertIs(getattr(mesocontact, name), new, name)
            self.assertEqual(old.__name__, "mesocontact.tablet." + name)
        from mesocontact import measures  # noqa: F401 - the from-import form too
        self.assertIs(measures, tablet.measures)

    def test_unknown_names_are_not_aliased(self):
        with self.assertRaises(ImportError):
            importlib.import_module("mesocontact.campaigns")
        self.assertFalse(hasattr(tablet, "no_such_name"))

    def test_sample_names_need_yade_and_say_so(self):
        if importlib.util.find_spec("yade") is not None:
            self.skipTest("YADE importable here: the sample loads")
        with self.assertRaisesRegex(AttributeError, "tablet.prepare: .*needs YADE"):
            tablet.prepare  # noqa: B018

    def test_old_path_runs_as_a_script(self):
        with tempfile.TemporaryDirectory() as top:
            d = os.path.join(top, "chosen")  # beside ../factors, which the statements' reasons read
            os.mkdir(d)
            os.symlink(os.path.join(DOCS, "..", "factors"), os.path.join(top, "factors"))
            for f in os.listdir(DOCS):
                if f.endswith((".json", ".csv")) and not f.endswith("-branches.csv") and f != "statements.json":
                    os.symlink(os.path.join(DOCS, f), os.path.join(d, f))
            env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "py"))
            for module in ("mesocontact.statements", "mesocontact.tablet.statements"):
                r = subprocess.run([sys.executable, "-m", module, d], env=env, capture_output=True, text=True)
                self.assertEqual(r.returncode, 0, r.stderr)
                with open(os.path.join(d, "statements.json")) as f, open(os.path.join(DOCS, "statements.json")) as g:
                    self.assertEqual(json.load(f), json.load(g), module)
                os.remove(os.path.join(d, "statements.json"))


if __name__ == "__main__":
    unittest.main()
