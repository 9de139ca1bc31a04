"""docs/tablet: the generated pages are what their scripts write from the committed files, and
README.md quotes no number that those pages do not hold (every result on it computed by a script)."""
import os
import re
import unittest

from mesostudies.tablet import statements, summary

DOCS = os.path.join(os.path.dirname(__file__), "..", "..", "docs", "tablet")
CHOSEN = os.path.join(DOCS, "chosen")
NUMBER = re.compile(r"\d+(?:\.\d+)?")


def _read(*path):
    with open(os.path.join(DOCS, *path), encoding="utf-8") as f:
        return f.read()


def missing_numbers(text, generated):
    """The numbers of ``text`` (outside `code`: commands and names) that ``generated`` does not hold."""
    have = set(NUMBER.findall(generated))
    return sorted(set(NUMBER.findall(re.sub(r"`[^`]*`", "", text))) - have, key=float)


class TabletDocs(unittest.TestCase):
    def test_summary_is_generated(self):
        self.assertEqual(summary.summary(CHOSEN), _read("chosen", "summary.md"),
                         "chosen/summary.md differs from what python3 -m mesostudies.tablet.summary writes")
        self.assertEqual(summary.summary(DOCS), _read("summary.md"), "the first protocol's summary.md")

    def test_statements_are_generated(self):
        self.assertEqual(statements.markdown(statements.statements(CHOSEN), "docs/tablet/chosen"),
                         _read("chosen", "statements.md"),
                         "chosen/statements.md differs from what python3 -m mesostudies.tablet.statements writes")

    def generated(self):
        return "".join(_read(*p) for p in (("chosen", "summary.md"), ("chosen", "statements.md"),
                                           ("chosen", "peaks.md"), ("factors", "factors.md")))

    def test_readme_quotes_generated_numbers(self):
        self.assertEqual(missing_numbers(_read("README.md"), self.generated()), [],
                         "numbers on docs/tablet/README.md found in no generated page")

    def test_the_check_can_fail(self):
        # a result typed by hand into the page is caught; the same number inside a command is not a result
        text = _read("README.md")
        self.assertEqual(missing_numbers(text + "\nthe peak at Dx = 0.0313\n", self.generated()), ["0.0313"])
        self.assertEqual(missing_numbers(text + "\n`--until 0.0313`\n", self.generated()), [])

if __name__ == "__main__":
    unittest.main()
