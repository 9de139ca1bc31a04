"""every folder of `campaigns/` with a `CAMPAIGN.json` holds exactly the files it lists (size and
SHA-256) and says which commits and command made them; the check finds a changed, a missing and an
unlisted file."""
import json
import os
import pathlib
import shutil
import tempfile
import unittest

from mesostudies import manifest

ROOT = pathlib.Path(__file__).resolve().parents[2] / "campaigns"


class Campaigns(unittest.TestCase):
    def test_every_campaign_is_its_manifest(self):
        folders = sorted(p.parent for p in ROOT.rglob(manifest.NAME))
        self.assertGreaterEqual(len(folders), 5)
        for folder in folders:
            self.assertEqual(manifest.check(folder), [], str(folder))
            with open(folder / manifest.NAME) as f:
                m = json.load(f)
            self.assertTrue(m["commit"] and m["command"] and m["date"] and m["machine"], str(folder))
        # every data file of campaigns/ belongs to one campaign
        data = [p for p in ROOT.rglob("*") if p.is_file() and p.name not in (manifest.NAME, "README.md")]
        self.assertEqual([str(p) for p in data if not any(f in p.parents for f in folders)], [])

    def test_the_check_can_fail(self):
        with tempfile.TemporaryDirectory() as d:
            for name in ("a.csv", "b.json"):
                with open(os.path.join(d, name), "w") as f:
                    f.write(name)
            manifest.write(d, "abc1234", "made by hand")
            self.assertEqual(manifest.check(d), [])
            with open(os.path.join(d, "a.csv"), "a") as f:
                f.write("x")
            os.remove(os.path.join(d, "b.json"))
            shutil.copy(os.path.join(d, "a.csv"), os.path.join(d, "c.png"))
            self.assertEqual(manifest.check(d), ["missing b.json", "unlisted c.png", "changed a.csv"])
            with self.assertRaises(ValueError):
                manifest.write(d, "", "no commit")


if __name__ == "__main__":
    unittest.main()
