"""the studies' jobs (issue #58 item 4): one record shape, `mesocontact.jobs` (plain Python), for the
tablet, the agglomerate and the figures; each registry ordered, refusing a second job of one name
and naming the known jobs for an unknown one; an unknown job's cost is an error, not 0 h, and the
tablet's plan refuses a table line with one before any work (through `build/yade-meso`); each
study declares its registry in the module at its top, which no module of its package imports, and
every committed yade-batch table names registered jobs only."""
import argparse
import ast
import os
import pathlib
import subprocess
import tempfile
import unittest

from mesocontact.jobs import Job, Registry

ROOT = pathlib.Path(__file__).resolve().parents[2]
STUDIES = ROOT / "studies" / "mesostudies"
# each study's registry module (at the top of its package) and the yade-batch column naming its job
REGISTRIES = {"tablet": ("cli", "figure"), "agglomerate": ("study", "job"), "figures": ("atlas", None)}
LAUNCHER = pathlib.Path(os.environ.get("YADE_MESO", ROOT / "build" / "yade-meso"))


def run(*args, **kw):
    return f"ran {args} {kw}"


class Shape(unittest.TestCase):
    def test_a_job_is_a_checked_record(self):
        job = Job("pull", run, "the pull to rupture.", cost=len)
        self.assertEqual((job.name, job.function, job.description, job.cost),
                         ("pull", run, "the pull to rupture.", len))
        for bad, says in ((dict(name=""), "name"), (dict(name="two words"), "name"), (dict(name="--quick"), "name"),
                          (dict(function=None), "function"), (dict(description=""), "description"),
                          (dict(description="two\nlines"), "description"), (dict(cost=3), "cost")):
            with self.assertRaises(ValueError, msg=bad) as e:
                Job(**dict(dict(name="pull", function=run, description="d."), **bad))
            self.assertIn(says, str(e.exception))

    def test_ordered_refuses_duplicates_names_the_known(self):
        jobs = Registry([Job("prepare", run, "p."), Job("fig16", run, "t."), Job("all", run, "a.")])
        self.assertEqual((list(jobs), jobs.names(), len(jobs)), (["prepare", "fig16", "all"],
                                                                 ("prepare", "fig16", "all"), 3))
        self.assertTrue("fig16" in jobs and "fig61" not in jobs and ["unhashable"] not in jobs)
        self.assertIs(jobs.get("fig16").function, run)
        with self.assertRaises(ValueError) as e:
            jobs.get("fig61")
        self.assertEqual(str(e.exception), "job 'fig61' is unknown: one of prepare, fig16, all")
        with self.assertRaises(ValueError) as e:
            Registry([Job("prepare", run, "p."), Job("prepare", print, "again.")])
        self.assertIn("'prepare'", str(e.exception))
        for bad in ([], [("prepare", run, "p.")]):
            with self.assertRaises(ValueError):
                Registry(bad)

    def test_an_unknown_jobs_cost_is_an_error_not_zero(self):
        jobs = Registry([Job("prepare", run, "minutes."), Job("fig17", run, "hours.", cost=lambda cells: 7)],
                        what="figure")
        self.assertEqual((jobs.cost("fig17", {}), jobs.cost("prepare", {})), (7, None))
        with self.assertRaises(ValueError) as e:
            jobs.cost("fig61", {})
        self.assertIn("figure 'fig61' is unknown", str(e.exception))

    def test_describe_and_choices(self):
        jobs = Registry([Job("a", run, "short."), Job("longer", run, "word " * 40)])
        lines = jobs.describe(width=60).splitlines()
        self.assertEqual(lines[0], "  a       short.")
        self.assertTrue(lines[1].startswith("  longer  word ") and len(lines) > 3
                        and all(ln.startswith(" " * 10 + "word") and len(ln) <= 60 for ln in lines[2:]), lines)
        p = argparse.ArgumentParser()
        p.add_argument("job", choices=jobs)  # a registry is argparse's choices as it stands
        self.assertEqual(p.parse_args(["longer"]).job, "longer")


def registered(study):
    """The job names a study's registry module declares (read from its source: no YADE here)."""
    module = REGISTRIES[study][0]
    tree = ast.parse((STUDIES / study / f"{module}.py").read_text())
    calls = [n.value for n in tree.body if isinstance(n, ast.Assign) and getattr(n.targets[0], "id", "") == "JOBS"]
    assert len(calls) == 1 and isinstance(calls[0], ast.Call) and calls[0].func.id == "Registry", study
    return [ast.literal_eval(j.args[0]) for j in calls[0].args[0].elts
            if isinstance(j, ast.Call) and j.func.id == "Job"]


def imports(path):
    """Every module a study's file imports, relative imports resolved (``from . import x``: x too)."""
    package = ".".join(path.relative_to(ROOT / "studies").with_suffix("").parts[:-1]).split(".")
    out = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            out.update(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = ".".join((package[:len(package) - node.level + 1] if node.level else [])
                            + ([node.module] if node.module else []))
            out.add(base)
            out.update(f"{base}.{a.name}" for a in node.names)
    return out


class Studies(unittest.TestCase):
    def test_each_registry_sits_above_its_jobs(self):
        for study, (module, _) in REGISTRIES.items():
            self.assertGreater(len(registered(study)), 5, study)
            registry = f"mesostudies.{study}.{module}"
            importers = sorted(str(f.relative_to(ROOT)) for f in (STUDIES / study).rglob("*.py")
                               if f.stem != module and registry in imports(f))
            self.assertEqual(importers, [], f"{registry} is imported by modules of its own study")
        # the tablet's campaign lies below the jobs its command line dispatches to: it imports none of them
        above = {f"mesostudies.tablet.{m}" for m in ("affine", "profile", "slaved", "cli")}
        upward = {str(f.relative_to(ROOT)): sorted(imports(f) & above)
                  for f in (STUDIES / "tablet" / "campaign").glob("*.py")}
        self.assertEqual({f: ms for f, ms in upward.items() if ms}, {})
        self.assertEqual(registered("tablet")[-1], "slaved")  # the last job added, carried over

    def test_the_tables_name_registered_jobs(self):
        known = {s: set(registered(s)) for s in REGISTRIES}
        unknown = []
        for table in sorted((ROOT / "studies" / "batch").glob("*.table")):
            rows = [ln.split() for ln in table.read_text().splitlines() if ln.strip() and not ln.startswith("#")]
            head = rows[0]
            for row in rows[1:]:
                cells = dict(zip(head, (c.strip("'\"") for c in row)))
                if "figure" in cells:
                    name, study = cells["figure"], "tablet"
                elif "job" in cells:
                    name, study = cells["job"], "agglomerate"
                else:
                    name, study = f"{cells.get('paper', 'long')}-{cells['number']}", "figures"
                if name not in known[study]:
                    unknown.append(f"{table.name}: {cells.get('description')}: {name}")
        self.assertEqual(unknown, [])


class TabletPlan(unittest.TestCase):
    def test_an_unknown_job_is_refused_before_any_work(self):
        if not os.access(LAUNCHER, os.X_OK):
            self.skipTest(f"no build-tree launcher at {LAUNCHER} (set YADE_MESO)")
        with tempfile.TemporaryDirectory() as t:
            table = os.path.join(t, "typo.table")
            with open(table, "w") as f:
                f.write("description  figure  amplitudes\npull  'fig17'  None\ntypo  'fig61'  '0.2'\n")
            out = os.path.join(t, "out")
            p = subprocess.run([str(LAUNCHER), "-j1", "-n", "-x", str(ROOT / "studies" / "scripts" / "tablet_plan.py"),
                                table, "--out", out], capture_output=True, text=True, timeout=120, cwd=t)
            text = p.stdout + p.stderr
            self.assertNotEqual(p.returncode, 0, text)
            self.assertIn("line typo: job 'fig61' is unknown: one of prepare,", text)
            self.assertFalse(os.path.exists(out), "the sample's preparation started before the table was checked")


if __name__ == "__main__":
    unittest.main()
