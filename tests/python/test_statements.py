"""mesocontact.tablet.statements on the committed campaign of docs/tablet: one row per statement of
Appendix F, numbers read from the files (checked here against the files directly)."""
import json
import os
import unittest

from mesocontact.tablet import statements

DOCS = os.path.join(os.path.dirname(__file__), "..", "..", "docs", "tablet")


class TestStatements(unittest.TestCase):
    def test_committed_campaign(self):
        items = statements.statements(DOCS)
        self.assertEqual(len(items), 27)
        self.assertTrue(all(s["verdict"] in ("✓", "◐", "✗", "–") for s in items))
        with open(os.path.join(DOCS, "tension-Dx0.2-P480.json")) as f:
            L0 = json.load(f)["L0"]
        first = items[0]
        self.assertIn(f"{L0:.5f}", first["project"])
        expect = "✓" if abs(L0 / 0.115 - 1) <= 0.01 else ("◐" if abs(L0 / 0.115 - 1) <= 0.05 else "✗")
        self.assertEqual(first["verdict"], expect)
        with open(os.path.join(DOCS, "fig17.json")) as f:
            last = json.load(f)["last_contact_Dx"]
        row = next(s for s in items if s["paper"].startswith("the contact is lost only at Dx ~ 8"))
        self.assertEqual(row["project"], f"Dx = {last:.2f}")
        self.assertEqual(row["verdict"], "✓" if 6 <= last <= 10 else "✗")
        row = next(s for s in items if s["paper"].startswith("the contact surface has developed a roughness"))
        self.assertEqual(row["verdict"], "–")  # no roughness.json there

    def test_roughness_of_the_chosen_campaign(self):
        chosen = os.path.join(DOCS, "chosen")
        items = statements.statements(chosen)
        with open(os.path.join(chosen, "roughness.json")) as f:
            rough = json.load(f)
        ranges = [rough[s]["range_5_95"] for s in ("left", "right")]
        flat = max(rough["flat_cut"][s]["range_5_95"] for s in ("left", "right"))
        row = next(s for s in items if s["paper"].startswith("the contact surface has developed a roughness"))
        self.assertIn(f"range {ranges[0]:.1f} and {ranges[1]:.1f} d0", row["project"])
        self.assertEqual(row["verdict"], "✓" if min(ranges) >= 2 and min(ranges) >= 2 * flat else
                         ("◐" if min(ranges) >= 1 else "✗"))


if __name__ == "__main__":
    unittest.main()
