"""the library and the studies apart (plain Python, no YADE): no module of `py/mesocontact` and no
library script in `scripts/` imports `mesostudies` (read from the sources, and seen in `sys.modules`
after importing every plain-Python module); the tablet and the agglomerate study import neither each
other nor any private name of another module (only the figures, which redraw the tablet's runs, use
the tablet study); the moved modules' old paths are gone and nothing hooks the import system,
`campaign.__all__` names exactly what it imports and nothing private, and a study's module still
runs with `python3 -m` from the source tree."""
import ast
import importlib
import json
import os
import pathlib
import subprocess
import sys
import tempfile
import unittest

ROOT = pathlib.Path(__file__).resolve().parents[2]
LIBRARY = ROOT / "py" / "mesocontact"
DOCS = ROOT / "campaigns" / "tablet" / "chosen"
# the library's modules that need no YADE (the rest import yade at the top)
PLAIN = ("theory", "params", "checks", "outputs", "scene_names", "calibrate", "bulk", "bulk.protocol", "jobs")
STUDIES = ROOT / "studies" / "mesostudies"
# what a study package may import of the others: nothing, but the figures redraw the tablet's runs
MAY_USE = {d.name: ({"tablet"} if d.name == "figures" else set())
           for d in STUDIES.iterdir() if (d / "__init__.py").exists()}


def imported_names(path):
    """Every module a source file imports (absolute names; relative ones resolved in the library)."""
    names = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            names.update(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom):
            names.add(node.module or "" if node.level == 0 else "mesocontact." + (node.module or ""))
    return names


def resolved_imports(path):
    """(module, names) of each import of a study's source file, relative imports resolved."""
    package = ".".join(path.relative_to(ROOT / "studies").with_suffix("").parts[:-1])
    out = []
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            out += [(a.name, []) for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = package.split(".")[:len(package.split(".")) - node.level + 1] if node.level else []
            module = ".".join(base + ([node.module] if node.module else []))
            out.append((module, [a.name for a in node.names]))
    return out


def private_attributes(path):
    """``alias._name`` uses where alias is an imported module (a private name used across modules)."""
    tree = ast.parse(path.read_text())
    aliases = {a.asname or a.name for n in ast.walk(tree) if isinstance(n, (ast.Import, ast.ImportFrom))
               for a in n.names}
    return sorted({f"{n.value.id}.{n.attr}" for n in ast.walk(tree) if isinstance(n, ast.Attribute)
                   and isinstance(n.value, ast.Name) and n.value.id in aliases and n.attr.startswith("_")
                   and not n.attr.startswith("__")})


class Layout(unittest.TestCase):
    def test_no_study_imports_another_nor_a_private_name(self):
        self.assertGreaterEqual(len(MAY_USE), 3)
        bad = {}
        for study, allowed in MAY_USE.items():
            for f in (STUDIES / study).rglob("*.py"):
                for module, names in resolved_imports(f):
                    parts = module.split(".")
                    if parts[0] == "mesostudies" and len(parts) > 1 and parts[1] != study and parts[1] not in allowed \
                            and parts[1] != "manifest":
                        bad.setdefault(str(f.relative_to(ROOT)), []).append(module)
                    bad_names = [n for n in names if n.startswith("_") and not n.startswith("__")]
                    if bad_names:
                        bad.setdefault(str(f.relative_to(ROOT)), []).append(f"{module}: {bad_names}")
                used = private_attributes(f)
                if used:
                    bad.setdefault(str(f.relative_to(ROOT)), []).extend(used)
        self.assertEqual(bad, {})

    def test_the_library_scripts_import_no_study(self):
        found = {f.name: sorted(n for n in imported_names(f) if n.split(".")[0] == "mesostudies")
                 for f in (ROOT / "scripts").glob("*.py")}
        self.assertEqual({f: n for f, n in found.items() if n}, {})
        self.assertGreater(len(found), 5)

    def test_the_library_imports_no_study(self):
        found = {str(f.relative_to(ROOT)): sorted(n for n in imported_names(f) if n.split(".")[0] == "mesostudies")
                 for f in LIBRARY.rglob("*.py")}
        self.assertEqual({f: n for f, n in found.items() if n}, {})
        self.assertGreater(len(found), 15)
        before = set(sys.modules)
        for name in PLAIN:
            importlib.import_module("mesocontact." + name)
        self.assertEqual([m for m in set(sys.modules) - before if m.startswith("mesostudies")], [])

    def test_no_old_paths_and_no_import_hooks(self):
        for old in ("mesocontact.tablet", "mesocontact.figures", "mesocontact.campaign", "mesocontact.statements"):
            with self.assertRaises(ImportError, msg=old):
                importlib.import_module(old)
        import mesocontact  # noqa: F401
        self.assertEqual([f for f in sys.meta_path if type(f).__module__.startswith(("mesocontact", "mesostudies"))],
                         [])

    def test_each_package_exports_what_it_names(self):
        for name in ("mesostudies.tablet.campaign",):
            spec = importlib.util.find_spec(name)
            tree = ast.parse(pathlib.Path(spec.origin).read_text())
            exported = next(ast.literal_eval(n.value) for n in tree.body
                            if isinstance(n, ast.Assign) and getattr(n.targets[0], "id", "") == "__all__")
            self.assertEqual([e for e in exported if e.startswith("_")], [], name)
            bound = {a.asname or a.name for n in tree.body if isinstance(n, ast.ImportFrom) for a in n.names}
            self.assertEqual(sorted(set(exported) - bound), [], name)
            self.assertEqual(sorted(bound - set(exported)), [], name)

    def test_a_study_runs_as_a_script(self):
        with tempfile.TemporaryDirectory() as top:
            d = os.path.join(top, "chosen")  # beside ../factors and ../branch, which the statements' reasons read
            os.mkdir(d)
            os.symlink(DOCS.parent / "factors", os.path.join(top, "factors"))
            os.symlink(DOCS.parent / "branch", os.path.join(top, "branch"))
            for f in os.listdir(DOCS):
                if f.endswith((".json", ".csv")) and not f.endswith("-branches.csv") and f != "statements.json":
                    os.symlink(DOCS / f, os.path.join(d, f))
            env = dict(os.environ, PYTHONPATH=f"{ROOT / 'py'}:{ROOT / 'studies'}")
            r = subprocess.run([sys.executable, "-m", "mesostudies.tablet.statements", d], env=env, capture_output=True,
                               text=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            with open(os.path.join(d, "statements.json")) as f, open(DOCS / "statements.json") as g:
                self.assertEqual(json.load(f), json.load(g))


if __name__ == "__main__":
    unittest.main()
