"""the tablet's pages: the generated ones (`campaigns/tablet`: `chosen/summary.md`, `summary.md`,
`chosen/statements.md`, `branch/experiments.md`, `repeats/verdicts.txt`) are what their scripts write
from the committed files; `docs/tablet/README.md` quotes no number that those pages, `chosen/peaks.md`
and `factors/factors.md` do not hold (every result on it computed by a script: a number typed by hand is
caught, numbers inside commands are not results), `docs/tablet/branch.md` only numbers of
`experiments.md` and `factors.md`; and each picture the prose shows (`docs/tablet/pictures`) is the
campaign's own file, byte for byte."""
import os
import re
import unittest

from mesostudies.tablet import statements, summary

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
DOCS = os.path.join(ROOT, "campaigns", "tablet")
PROSE = os.path.join(ROOT, "docs", "tablet")
CHOSEN = os.path.join(DOCS, "chosen")
# docs/tablet/pictures/<name>: the campaign file it shows
PICTURES = {**{f"{n}.png": os.path.join("chosen", f"{n}.png")
               for n in ("fig16", "fig17", "fig17-snapshots", "fig18", "fig19", "fig19-snapshots")},
            "pull-contacts-sinter0.1.png": os.path.join("factors", "frictionless-sinter-std0.1-sinter0.1",
                                                        "pull-contacts",
                                                        "pull-contacts.png"),
            "timestep-x1-pull.png": os.path.join("timestep", "timestep-x1-pull.png")}
NUMBER = re.compile(r"\d+(?:\.\d+)?")


def _read(*path):
    with open(os.path.join(DOCS, *path), encoding="utf-8") as f:
        return f.read()


def _prose(name):
    with open(os.path.join(PROSE, name), encoding="utf-8") as f:
        return f.read()


def missing_numbers(text, generated):
    """The numbers of ``text`` (outside `code`: commands and names) that ``generated`` does not hold."""
    have = set(NUMBER.findall(generated))
    return sorted(set(NUMBER.findall(re.sub(r"`[^`]*`", "", text))) - have, key=float)


class TabletDocs(unittest.TestCase):
    def test_summary_is_generated(self):
        self.assertEqual(summary.summary(CHOSEN), _read("chosen", "summary.md"),
                         "chosen/summary.md differs from what python3 -m mesostudies.tablet.summary writes")

    def test_statements_are_generated(self):
        self.assertEqual(statements.markdown(statements.statements(CHOSEN), "campaigns/tablet/chosen"),
                         _read("chosen", "statements.md"),
                         "chosen/statements.md differs from what python3 -m mesostudies.tablet.statements writes")

    def generated(self):
        return "".join(_read(*p) for p in (("chosen", "summary.md"), ("chosen", "statements.md"),
                                           ("chosen", "peaks.md"), ("factors", "factors.md"),
                                           ("branch", "experiments.md"), ("repeats", "verdicts.txt")))

    def test_repeats_verdicts_are_generated(self):
        """repeats/verdicts.txt is what studies/scripts/tablet_repeats.py prints from that folder alone."""
        import subprocess
        import sys
        import tempfile
        with tempfile.TemporaryDirectory() as tmp:
            env = dict(os.environ, REPEATS=os.path.join(tmp, "repeats"),
                       PYTHONPATH=os.pathsep.join(os.path.join(ROOT, x) for x in ("py", "studies")))
            out = subprocess.run([sys.executable, os.path.join(ROOT, "studies", "scripts", "tablet_repeats.py"), "all"],
                                 cwd=ROOT, env=env, capture_output=True, text=True, check=True).stdout
        self.assertEqual(out, _read("repeats", "verdicts.txt"),
                         "repeats/verdicts.txt differs from what tablet_repeats.py all prints")

    def test_readme_quotes_generated_numbers(self):
        self.assertEqual(missing_numbers(_prose("README.md"), self.generated()), [],
                         "numbers on docs/tablet/README.md found in no generated page")

    def test_branch_quotes_generated_numbers(self):
        generated = _read("branch", "experiments.md") + _read("factors", "factors.md")
        self.assertEqual(missing_numbers(_prose("branch.md"), generated), [],
                         "numbers on docs/tablet/branch.md found in neither experiments.md nor factors.md")

    def test_experiments_are_generated(self):
        from mesostudies.tablet import experiments
        one = experiments.e1(DOCS)
        self.assertEqual(experiments.markdown(one, experiments.e2(DOCS), "campaigns/tablet", experiments.e3(DOCS),
                                              experiments.e56(DOCS, one)),
                         _read("branch", "experiments.md"),
                         "branch/experiments.md differs from what python3 -m mesostudies.tablet.experiments writes")

    def test_pictures_are_the_campaigns(self):
        self.assertEqual(sorted(os.listdir(os.path.join(PROSE, "pictures"))), sorted(PICTURES))
        for name, source in PICTURES.items():
            with open(os.path.join(PROSE, "pictures", name), "rb") as a, open(os.path.join(DOCS, source), "rb") as b:
                self.assertEqual(a.read(), b.read(), f"docs/tablet/pictures/{name} is not campaigns/tablet/{source}")

    def test_the_check_can_fail(self):
        # a result typed by hand into the page is caught; the same number inside a command is not a result
        text = _prose("README.md")
        self.assertEqual(missing_numbers(text + "\nthe peak at Dx = 0.0313\n", self.generated()), ["0.0313"])
        self.assertEqual(missing_numbers(text + "\n`--until 0.0313`\n", self.generated()), [])


if __name__ == "__main__":
    unittest.main()
