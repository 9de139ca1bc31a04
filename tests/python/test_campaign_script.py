"""studies/scripts/tablet_campaign.sh refuses bad options at once (exit 2, the option named),
before the sample's preparation starts (issue #49 item 10): each case here returns in well under
a second, and none reaches yade."""
import os
import subprocess
import tempfile
import unittest

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
SCRIPT = os.path.join(ROOT, "studies", "scripts", "tablet_campaign.sh")


def run(*args):
    with tempfile.TemporaryDirectory() as t:
        env = dict(os.environ, YADE_BATCH_COMMAND="false")
        p = subprocess.run(["bash", SCRIPT, "--yade", "/bin/false", *args], capture_output=True, text=True, timeout=30,
                           env=env, cwd=t)
    return p.returncode, p.stderr


class CampaignScript(unittest.TestCase):
    def test_refused_before_any_work(self):
        table = os.path.join(ROOT, "studies", "batch", "tablet-campaign.table")
        cases = [(("--lanes",), "--lanes needs a value"),
                 (("--lanes", "--out", "x"), "--lanes needs a value"),
                 (("--lanes", "0"), "--lanes 0 is invalid"),
                 (("--table", "/no/such.table"), "no such file"),
                 (("--table", table, "--out", "a'b"), "no quotes"),
                 (("--table", table, "--out", "a\\b"), "no quotes"),
                 (("--table", table, "--out", "a b"), "no quotes"),
                 (("--table", table, "--out", "r/x", "--docs", "r/x/"), "copied onto themselves"),
                 (("--bogus", "1"), "unknown option --bogus")]
        for args, says in cases:
            rc, err = run(*args)
            self.assertEqual(rc, 2, f"{args}: rc {rc}, {err}")
            self.assertIn(says, err, f"{args}")
        rc, err = run("--table", table, "--yade", "/no/yade")
        self.assertEqual((rc, "--yade /no/yade: not an executable" in err), (2, True), err)


if __name__ == "__main__":
    unittest.main()
