"""results are whole or absent: `outputs.Bundle` commits a directory by one rename; 12 writers killed
at random moments (SIGKILL, SIGTERM) each leave the old bundle or the new one, never a mix."""
import json
import os
import random
import signal
import subprocess
import sys
import tempfile
import textwrap
import time
import unittest

from mesocontact import outputs

# A writer that rewrites one bundle over and over, slowly (so that kills land mid-write).
WRITER = textwrap.dedent("""
    import sys, time
    sys.path.insert(0, sys.argv[2])
    from mesocontact import outputs
    k = 0
    while True:
        k += 1
        with outputs.Bundle(sys.argv[1]) as b:
            for name in ("run.csv", "run.json", "fig.png"):
                with open(b.path(name), "w") as f:
                    for j in range(200):
                        f.write(f"{k},{j}\\n")
                        f.flush()
                        time.sleep(0.0001)
""")
# A writer committed over an older bundle and sent SIGTERM right before or right after the call
# that puts the new bundle under the name: the moments where a two-step replacement (old aside,
# new in, old removed) loses the old bundle or leaves it behind.
TERM_AT_SWAP = textwrap.dedent("""
    import os, signal, sys
    sys.path.insert(0, sys.argv[2])
    from mesocontact import outputs
    final, when = sys.argv[1], sys.argv[3]
    def bundle(k):
        with outputs.Bundle(final) as b:
            b.write_text("k.txt", str(k))
    bundle(1)
    def hooked(call):
        def f(src, dst, *a):
            if os.path.abspath(dst) != os.path.abspath(final):
                return call(src, dst, *a)
            if when == "before":
                os.kill(os.getpid(), signal.SIGTERM)
            r = call(src, dst, *a)
            os.kill(os.getpid(), signal.SIGTERM)
            return r
        return f
    outputs.os.rename = hooked(os.rename)
    if hasattr(outputs, "_exchange"):
        outputs._exchange = hooked(outputs._exchange)
    bundle(2)
""")
PY = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "py")


class BundleTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="outputs-")

    def test_commit_and_discard(self):
        final = os.path.join(self.dir, "runs", "a")
        with outputs.Bundle(final) as b:
            b.write_json("a.json", {"x": 1})
            b.write_text("a.csv", "iter\n1\n")
        self.assertTrue(outputs.complete(final))
        with self.assertRaises(ZeroDivisionError):
            with outputs.Bundle(final) as b:
                b.write_text("a.csv", "half")
                1 / 0
        with open(os.path.join(final, "a.csv")) as f:
            self.assertEqual(f.read(), "iter\n1\n")  # the old one stays
        self.assertEqual(outputs.problems(self.dir), [])
        with open(os.path.join(final, "a.csv"), "a") as f:  # tampering shows
            f.write("2\n")
        self.assertFalse(outputs.complete(final))
        self.assertEqual(len(outputs.problems(self.dir)), 1)

    def test_killed_writers_leave_whole_bundles(self):
        final = os.path.join(self.dir, "fig")
        rng = random.Random(3)
        script = os.path.join(self.dir, "writer.py")
        with open(script, "w") as f:
            f.write(WRITER)
        for trial in range(12):
            proc = subprocess.Popen([sys.executable, script, final, PY])
            time.sleep(rng.uniform(0.15, 0.6))
            proc.send_signal(signal.SIGKILL if trial % 2 else signal.SIGTERM)
            proc.wait()
            if os.path.exists(final):
                self.assertTrue(outputs.complete(final), f"trial {trial}")
                rows = set()
                for name in ("run.csv", "run.json", "fig.png"):
                    with open(os.path.join(final, name)) as f:
                        rows |= {line.split(",")[0] for line in f.read().split()}
                self.assertEqual(len(rows), 1, f"trial {trial}: files of different commits {rows}")
            left = outputs.problems(self.dir, ignore_running=False)
            if trial % 2 == 0:  # SIGTERM: the writer removed its temporary directory itself
                self.assertEqual(left, [], f"trial {trial}")
            outputs.sweep(self.dir)  # SIGKILL: the next job removes it
            self.assertEqual(outputs.problems(self.dir, ignore_running=False), [], f"trial {trial}")
        self.assertTrue(os.path.exists(final))

    def test_term_at_the_swap_leaves_one_whole_bundle(self):
        script = os.path.join(self.dir, "term.py")
        with open(script, "w") as f:
            f.write(TERM_AT_SWAP)
        for when, expect in (("before", "1"), ("after", "2")):
            final = os.path.join(self.dir, when)
            rc = subprocess.run([sys.executable, script, final, PY, when]).returncode
            self.assertEqual(rc, -signal.SIGTERM, when)
            self.assertTrue(outputs.complete(final), when)
            with open(os.path.join(final, "k.txt")) as f:
                self.assertEqual(f.read(), expect, when)
            self.assertEqual(outputs.problems(self.dir, ignore_running=False), [], when)

    def test_manifest_lists_exactly_the_files(self):
        final = os.path.join(self.dir, "b")
        with outputs.Bundle(final) as b:
            b.write_text("x.csv", "1\n")
        with open(os.path.join(final, outputs.MANIFEST)) as f:
            manifest = json.load(f)
        self.assertEqual(sorted(manifest), ["x.csv"])
        open(os.path.join(final, "stray.png"), "w").close()
        self.assertFalse(outputs.complete(final))


if __name__ == "__main__":
    unittest.main()
