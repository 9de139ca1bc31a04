"""The agglomerate study's page: campaigns/agglomerate/summary.md is what its report writes from the
committed summary, and the results section of docs/agglomerate.md quotes no number that page does
not hold; the ensemble page's verdict and choices tables are its campaign's ensemble.md's."""
import json
import os
import re
import unittest

from mesostudies.agglomerate import report

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")
RESULTS = os.path.join(ROOT, "campaigns", "agglomerate")
NUMBER = re.compile(r"\d+(?:\.\d+)?(?:e[+-]\d+)?")


class AgglomerateDocs(unittest.TestCase):
    def test_summary_is_generated(self):
        with open(os.path.join(RESULTS, "agglomerate-vs-meso.json")) as f:
            s = json.load(f)
        with open(os.path.join(RESULTS, "summary.md")) as f:
            self.assertEqual(report.markdown(s), f.read(),
                             "summary.md differs from what mesostudies.agglomerate.report writes")

    def test_results_quote_the_summary(self):
        with open(os.path.join(ROOT, "docs", "agglomerate.md")) as f:
            text = f.read()
        results = text[text.index("## Results"):text.index("## Commands and cost")]
        with open(os.path.join(RESULTS, "summary.md")) as f:
            have = set(NUMBER.findall(f.read()))
        missing = sorted(set(NUMBER.findall(re.sub(r"`[^`]*`", "", results))) - have)
        self.assertEqual(missing, [], "numbers in docs/agglomerate.md's results found nowhere in summary.md")

    def test_ensemble_verdict_quotes_its_campaign(self):
        """The ensemble page's verdict and choices tables are its campaign's ensemble.md's, row for row."""
        with open(os.path.join(ROOT, "docs", "agglomerate-ensemble.md")) as f:
            text = f.read()
        quoted = text[text.index("## The verdict"):text.index("## Which speeds inform")]
        quoted += text[text.index("## What the fit's choices do"):text.index("## What the agglomerates do")]
        rows = [line for line in quoted.splitlines() if line.startswith("|")]
        with open(os.path.join(ROOT, "campaigns", "agglomerate-ensemble", "ensemble.md")) as f:
            have = set(f.read().splitlines())
        self.assertGreater(len(rows), 15)
        self.assertEqual([r for r in rows if r not in have], [], "table rows not in the campaign's ensemble.md")


if __name__ == "__main__":
    unittest.main()
