"""the agglomerate study's comparisons that need no YADE: the wall prediction written out by hand on a
first loading (where it starts, k1 and the rigid wall's 2 k1), the misfit, and the
tension-as-adhesion estimate (fa, the tail, kca, the closed form's e and the sticking speed); four
mutations each fail it; the gammaN scan's worst differences and least of them, on a law written by hand; the ensemble
table's counting (stuck as 0, an unended run left out of e_contact, the sample sd) on rows written by hand, and
the verdict per speed (two standard errors either side of the line, partial ensembles, fragmentation), and
what collect copies into the committed campaign."""
import unittest

from mesocontact import theory
from mesostudies.agglomerate import compare

INFO = {"agglomerates": [{"radius": 0.05, "mass": 6e2}, {"radius": 0.06, "mass": 7e2}]}  # mm, mg
LAW = {"k1": 5e5, "kp": 2e6, "kc": 1e5, "phiF": 0.5, "shift": 3e-6}                     # SI


class WallPrediction(unittest.TestCase):
    def test_first_loading(self):
        # Below the plastic limit (6.7e-5 m here; the path reaches 1e-7 m) a first loading is
        # k1 (delta - start), start = touch_wall + (shift - touch_pair)/2, written out by hand.
        touch_pair, touch_wall = 0.0031, 0.0022                    # mm
        start = touch_wall * 1e-3 + 0.5 * (LAW["shift"] - touch_pair * 1e-3)
        rows = [(i, touch_wall + 2e-6 * i - 2e-5, 0.0) for i in range(80)]   # mm, from before the contact
        p = compare.wall_predictions(LAW, rows, INFO, touch_pair, touch_wall)
        self.assertEqual(set(p), {"same material", "rigid wall"})
        touched = 0
        for r, same, rigid in zip(rows, p["same material"], p["rigid wall"]):
            expect = max(r[1] * 1e-3 - start, 0.0) * LAW["k1"] / compare.FORCE
            touched += expect > 0
            self.assertAlmostEqual(same, expect, delta=1e-9 * abs(expect) + 1e-20)
            self.assertAlmostEqual(rigid, 2 * expect, delta=2e-9 * abs(expect) + 1e-20)
        self.assertGreater(touched, 20)

    def test_wall_a12(self):
        self.assertEqual(compare.wall_a12(INFO), 2 * 0.05e-3)

    def test_misfit(self):
        rows = [(0, 0.0, 2.0), (1, 0.0, -4.0)]
        rms, largest = compare.misfit([3.0, -4.0], rows)
        self.assertAlmostEqual(rms, (0.5 * 0.25 ** 2) ** 0.5)
        self.assertAlmostEqual(largest, 0.25)


class TensionAsAdhesion(unittest.TestCase):
    def test_fa_kca_and_sticking(self):
        plateau, touch = -2e-5, 0.0031                              # study force units, mm
        a = compare.adhesion_consequence(LAW, INFO, plateau, touch, [1e-5, 1e-2])
        fa = 2e-5 * compare.FORCE          # the study force unit in N (1e3 to rounding)
        tail = LAW["shift"] - (touch - 0.2 * 0.01) * 1e-3
        self.assertAlmostEqual(a["fa_N"], fa, delta=1e-15)
        self.assertAlmostEqual(a["tail_m"], tail, delta=1e-18)
        self.assertAlmostEqual(a["kca_N_m"], fa / tail, delta=1e-9 * fa / tail)
        a12, m_r = compare.geometry(INFO)[:2]

        def e(v):
            return theory.pair_collision(v, LAW["k1"], LAW["kp"], LAW["kc"], LAW["phiF"], a12, m_r, fa=fa,
                                         kca=fa / tail,
                                         adhesion="jumpIn").e
        self.assertEqual(a["e_theory"], [e(1e-5 * compare.SPEED), e(1e-2 * compare.SPEED)])  # mm/us in m/s
        v = a["sticks_below_m_s"]
        self.assertEqual(e(0.999 * v), 0.0)
        self.assertGreater(e(1.001 * v), 0.0)

    def test_no_tension_no_estimate(self):
        self.assertIsNone(compare.adhesion_consequence(LAW, INFO, 1e-5, 0.0031, [1e-3]))


if __name__ == "__main__":
    unittest.main()


class GammaScan(unittest.TestCase):
    def test_worst_and_least(self):
        # The law's e replaced by a hand-written e(v, gammaN) = 1 - gammaN - v/1e3 (v in m/s), against
        # two measures' means at three speeds (160 m/s lies beyond the goal and is left out, None is
        # skipped): the worst |difference| and the least of them, worked out by hand.
        from mesostudies.agglomerate import predict
        calls = []

        def fake(params, info, speeds, progress=True, gammaN=0.0):
            calls.append(speeds)
            return [1.0 - gammaN - v for v in speeds]   # speeds in mm/us = m/s / 1e3
        real, compare.meso_collisions = compare.meso_collisions, fake
        try:
            by = {"a": {"e_mean": [0.9, 0.7, None, 0.0]}, "b": {"e_mean": [0.5, 0.5, 0.48, 0.0]}}
            s = predict.gamma_scan(LAW, INFO, [10.0, 20.0, 80.0, 160.0], by, 0.1, factors=(0.0, 1.0, 4.0))
        finally:
            compare.meso_collisions = real
        self.assertEqual(s["speeds"], [10.0, 20.0, 80.0])
        self.assertEqual(calls, [[0.01, 0.02, 0.08]] * 3)
        # gammaN 0: e = 0.99, 0.98, 0.92; 0.1: 0.89, 0.88, 0.82; 0.4: 0.59, 0.58, 0.52
        for row, a, b in zip(s["rows"], (0.28, 0.18, 0.31), (0.49, 0.39, 0.09)):
            self.assertAlmostEqual(row["worst"]["a"], a, places=12)
            self.assertAlmostEqual(row["worst"]["b"], b, places=12)
        self.assertEqual(s["best_factor"], {"a": 1.0, "b": 4.0})


class EnsembleTable(unittest.TestCase):
    """ensemble_report.table on rows written by hand: a stuck run counts 0 in every measure, a run whose
    first impact never ended (no e_contact) is left out of that measure only; mean and sample sd by hand."""

    def row(self, **kw):
        r = {"v_rel_m_s": 1.0, "seed": 1, "direction_index": 1, "stuck": False, "broken_mass_fraction": 0.0,
             "bonds_broken_fraction": 0.0, "recontacts": 0, "e": 0.5, "e_normal": 0.5, "e_contact": 0.5,
             "e_rigid": 0.5}
        r.update(kw)
        return r

    def test_table(self):
        from mesostudies.agglomerate import ensemble_report as er
        rows = [self.row(e_contact=0.9), self.row(seed=2, e_contact=0.6, broken_mass_fraction=-2e-17),
                self.row(direction_index=2, stuck=True, e_contact=None),
                self.row(seed=3, e_contact=None, recontacts=2)]
        s = er.table(rows)[1.0]
        self.assertEqual((s["n"], s["n_blocks"], s["n_directions"], s["stuck"]), (4, 3, 2, 1))
        k = s["e_contact"]                       # 0.9, 0.6 and the stuck 0: mean 0.5, sd sqrt(0.21)
        self.assertEqual(k["n"], 3)
        self.assertAlmostEqual(k["mean"], 0.5, places=15)
        self.assertAlmostEqual(k["sd"], 0.21 ** 0.5, places=15)
        self.assertEqual((k["min"], k["max"]), (0.0, 0.9))
        self.assertEqual(s["e"]["n"], 4)
        self.assertEqual(s["runs_with_recontacts"], 1)
        self.assertIn("| 0.00 % (0.00 %) | 1 |", er.text({1.0: s}))  # the rounding residue reads 0, not -0.00
        self.assertIn("| 1 (0.750) |", er.text({1.0: s}))  # one stuck; the others 0.9, 0.6
        self.assertEqual(s["e_contact_above_1"], 0)
        rows[0]["e_contact"] = 1.2                               # 1.2, 0.6, 0 (stuck): mean 0.6, capped 0.5333
        s = er.table(rows)[1.0]
        self.assertEqual(s["e_contact_above_1"], 1)
        self.assertAlmostEqual(s["e_contact_mean_capped_at_1"], 1.6 / 3, places=15)
        self.assertAlmostEqual(s["e_contact_mean_rebounding"], 0.9, places=15)   # 1.2 and 0.6; the stuck left out

    def test_anova(self):
        """2 blocks x 2 directions, y = block + direction + an interaction (+1, -1; -1, +1): [[1, 3], [1, 7]],
        mean 3; SS blocks 2 ((2-3)^2 + (4-3)^2) = 4, directions 2 ((1-3)^2 + (5-3)^2) = 16, total 24, residual 4;
        one df each: F 1 and 4. The table carries it for a complete grid only."""
        from mesostudies.agglomerate import ensemble_report as er
        a = er.anova_two_way([[1.0, 3.0], [1.0, 7.0]])
        self.assertAlmostEqual(a["F_blocks"], 1.0, places=12)
        self.assertAlmostEqual(a["F_directions"], 4.0, places=12)
        self.assertEqual(a["df"], [1, 1, 1])
        rows = [self.row(seed=b, direction_index=d, e_contact=y) for b, ys in ((1, (1.0, 3.0)), (2, (1.0, 7.0)))
                for d, y in zip((1, 2), ys)]
        self.assertAlmostEqual(er.table(rows)[1.0]["e_contact"]["anova"]["F_directions"], 4.0, places=12)
        self.assertIsNone(er.table(rows[:3])[1.0]["e_contact"]["anova"])

    def test_verdict(self):
        """verdict by hand: two standard errors of the runs, and Student's t (4.303 for 2 df) on the blocks'
        means, either side of the line."""
        from mesostudies.agglomerate import ensemble_report as er
        rows = [self.row(v_rel_m_s=v, seed=s, direction_index=k, e_contact=e0 + (0.01 if s == 2 else 0.0) * (k % 2))
                for v, e0 in ((1.0, 0.8), (10.0, 0.5), (80.0, 0.6)) for s in (1, 2, 3) for k in range(1, 21)]
        rows.append(self.row(v_rel_m_s=0.1, e_contact=0.9))
        tab = er.table(rows)
        vd = er.verdict(tab, {0.1: 0.9, 1.0: 0.85, 10.0: 0.62, 80.0: 0.6})
        by = {r["speed"]: r for r in vd["rows"]}
        self.assertEqual(by[0.01]["state"], "not measured")
        self.assertEqual(by[0.1]["state"], "partial")          # one run: too few, and no standard error
        self.assertEqual(by[0.1]["decides"], "undecided")
        # 1 m/s: 60 values, 10 of them 0.81, the rest 0.8: sd by hand; blocks 0.8, 0.805, 0.8
        sd = (10 * (0.81 - 0.8 - 0.1 / 60) ** 2 + 50 * (0.1 / 60) ** 2) ** 0.5 / 59 ** 0.5
        self.assertAlmostEqual(by[1.0]["se_runs"], sd / 60 ** 0.5, places=12)
        se_b = (2 * (0.005 / 3) ** 2 + (0.01 / 3) ** 2) ** 0.5 / 2 ** 0.5 / 3 ** 0.5
        self.assertAlmostEqual(by[1.0]["se_blocks"], se_b, places=12)
        self.assertEqual((by[1.0]["decides"], by[1.0]["decides_blocks"]), ("met", "met"))         # 0.0483 + 0.0072
        self.assertEqual((by[10.0]["decides"], by[10.0]["decides_blocks"]), ("missed", "missed"))  # 0.1183 - 0.0072
        self.assertEqual(by[80.0]["decides"], "met")
        self.assertEqual([by[v]["state"] for v in (1.0, 10.0, 80.0)], ["within", "beyond", "within"])
        self.assertEqual((vd["goal"], vd["firm"], vd["firm_blocks"]), ("missed", 3, 3))
        self.assertAlmostEqual(vd["fall"]["ensemble"], 0.5 - 0.6, places=12)   # 10 and 80 m/s: both + 0.1/60
        self.assertAlmostEqual(vd["fall"]["predicted"], 0.62 - 0.6, places=12)
        vd = er.verdict(tab, {0.1: 0.9, 1.0: 0.85, 10.0: 0.55, 80.0: 0.6})
        self.assertEqual(vd["goal"], "open")                    # 0.01 unmeasured, 0.1 partial
        near = er.verdict(tab, {0.1: 0.9, 1.0: by[1.0]["mean"] + 0.097, 10.0: 0.5, 80.0: 0.6})["rows"][2]
        self.assertEqual((near["decides"], near["decides_blocks"], near["state"]), ("met", "undecided", "within"))
        # runs: 0.097 + 2 * 0.000485 <= 0.1; blocks: 0.097 + 4.303 * 0.00167 > 0.1
        t = er.verdict(tab, {0.1: 0.9, 1.0: by[1.0]["mean"] + 0.094, 10.0: 0.5, 80.0: 0.6})["rows"][2]
        self.assertEqual(t["decides_blocks"], "undecided")      # 0.094 + 4.303 * 0.00167 > 0.1 (with 2: 0.0973)
        r2 = er.verdict(tab, {0.1: 0.9, 1.0: by[1.0]["mean"] + 0.0993, 10.0: 0.5, 80.0: 0.6})["rows"][2]
        self.assertEqual(r2["decides"], "undecided")            # 0.0993 + 2 * 0.000485 > 0.1 (with 1: 0.0998)
        beyond = er.verdict(tab, {0.1: 0.9, 1.0: by[1.0]["mean"] + 0.102, 10.0: 0.5, 80.0: 0.6})["rows"][2]
        self.assertEqual((beyond["decides"], beyond["decides_blocks"], beyond["state"]),
                         ("missed", "undecided", "beyond"))  # 0.102 - 0.00097 > 0.1; 0.102 - 0.0072 < 0.1
        gap = er.verdict(er.table(rows[:-3] + rows[-2:]), {0.1: 0.9, 1.0: 0.85, 10.0: 0.55, 80.0: 0.6})
        self.assertEqual(gap["rows"][-1]["state"], "partial")   # 3 blocks and 20 directions, but 59 runs
        rows[-2]["broken_mass_fraction"] = 0.02                 # one 80 m/s run fragments (> 1 % broken off)
        frag = er.verdict(er.table(rows), {0.1: 0.9, 1.0: 0.85, 10.0: 0.55, 80.0: 0.6})
        self.assertEqual((frag["rows"][-1]["decides"], frag["rows"][-1]["decides_blocks"], frag["rows"][-1]["state"],
                          frag["goal"]), ("missed", "missed", "beyond", "missed"))
        self.assertIn("| 10 | 60 (3 x 20) |", er.verdict_text(vd))
        # A speed beyond the goal's (160 m/s) gets its own row, measured alike, that does not count: missed by
        # 0.3 there, the goal stays as it was without it ('open': 0.01 m/s unmeasured, 0.1 partial).
        rows[-2]["broken_mass_fraction"] = 0.0
        far = rows + [self.row(v_rel_m_s=160.0, seed=s, direction_index=k, e_contact=0.3) for s in (1, 2, 3)
                      for k in range(1, 21)]
        wide = er.verdict(er.table(far), {0.1: 0.9, 1.0: 0.85, 10.0: 0.55, 80.0: 0.6, 160.0: 0.6})
        self.assertEqual((wide["rows"][-1]["speed"], wide["rows"][-1]["state"], wide["rows"][-1]["decides"]),
                         (160.0, "outside the goal", "missed"))
        self.assertEqual((wide["goal"], wide["firm"]), ("open", 3))
        self.assertIn("| 160 | 60 (3 x 20) |", er.verdict_text(wide))
        self.assertEqual(len(er.verdict(er.table(far), {0.1: 0.9, 1.0: 0.85, 10.0: 0.55, 80.0: 0.6})["rows"]), 8)
        self.assertAlmostEqual(by[1.0]["half_blocks"], 4.303 * se_b, places=12)
        self.assertAlmostEqual(by[1.0]["half_runs"], 2 * sd / 60 ** 0.5, places=12)
        # A run whose first impact never ended (not stuck, no e_contact) is a run but not measured: said so.
        self.assertNotIn(" measured)", er.verdict_text(wide))
        far[-1]["e_contact"] = None
        lone = er.verdict(er.table(far), {0.1: 0.9, 1.0: 0.85, 10.0: 0.55, 80.0: 0.6, 160.0: 0.6})
        self.assertEqual((lone["rows"][-1]["n"], lone["rows"][-1]["n_measured"]), (60, 59))
        self.assertIn("| 160 | 60 (3 x 20; 59 measured) |", er.verdict_text(lone))
        far[-1]["e_rigid"] = None
        self.assertIn("| 160 | 60 (3 x 20; e_contact of 59, e_rigid of 59) |", er.text(er.table(far)))


class Collect(unittest.TestCase):
    """collect copies what the report and the prediction read (finished runs, the collisions, the
    descriptions, every block's pair, an unfinished pull's last save) and leaves out scenes, finished runs'
    saves, logs and runs still going."""

    def test_collect(self):
        import os
        import tempfile
        from mesostudies.agglomerate import collect
        with tempfile.TemporaryDirectory() as src, tempfile.TemporaryDirectory() as dst:
            names = {"block-s1": ["agglomerates.yade.gz", "agglomerates.yade.gz.json", "block.yade.gz",
                                  "block.yade.gz.json", "pull-a0.02-v0.625.csv", "pull-a0.02-v0.625.json",
                                  "pull-a0.1-v0.625.checkpoint.yade.gz", "pull-a0.1-v0.625.checkpoint.yade.gz.json",
                                  "pull-a0.02-v0.625.checkpoint.yade.gz.json",  # a finished pull's save: left out
                                  "energy-cycles-v40.csv", "x.log", "ensemble/d1-v1.json", "ensemble/d1-v1.tmp"],
                     "block-s2": ["agglomerates.yade.gz", "energy-cycles-v10.csv", "energy-cycles-v10.json",
                                  "ensemble/d2-v3.json"]}
            open(os.path.join(src, "block-s1.log"), "w").close()   # a block's log beside the folders
            for block, files in names.items():
                for f in files:
                    os.makedirs(os.path.dirname(os.path.join(src, block, f)), exist_ok=True)
                    open(os.path.join(src, block, f), "w").close()
            self.assertEqual(collect.collect(src, dst), 11)
            got = sorted(os.path.relpath(os.path.join(r, f), dst) for r, _, fs in os.walk(dst) for f in fs)
            self.assertEqual(got, ["block-s1/agglomerates.yade.gz", "block-s1/agglomerates.yade.gz.json",
                                   "block-s1/block.yade.gz.json", "block-s1/ensemble/d1-v1.json",
                                   "block-s1/pull-a0.02-v0.625.csv", "block-s1/pull-a0.02-v0.625.json",
                                   "block-s1/pull-a0.1-v0.625.checkpoint.yade.gz.json",
                                   "block-s2/agglomerates.yade.gz",
                                   "block-s2/energy-cycles-v10.csv", "block-s2/energy-cycles-v10.json",
                                   "block-s2/ensemble/d2-v3.json"])


class PullRange(unittest.TestCase):
    """tension.pull_range on a pull written by hand (d0 = 1): loaded linearly from the touch at 1 to
    1.1 (press work 0.5 * 2 * 0.1**2 = 0.01), back to the touch, then a constant tension of 0.004 from
    the touch to 0.5 beyond it and nothing after: held beyond the touch 0.004 * min(m, 0.5) / 0.01 up to
    each mark m, and the last force at 0.5. An attraction before the touch is not press work."""

    def test_pull_range(self):
        from mesostudies.agglomerate import tension
        k, n = 2.0, 1000
        load = [(i, 1.0 + 0.1 * i / n, k * 0.1 * i / n) for i in range(n + 1)]
        back = [(n + i, 1.1 - 0.1 * i / n, k * (0.1 - 0.1 * i / n)) for i in range(1, n + 1)]
        pull = [(2 * n + i, 1.0 - 2.0 * i / n, -0.004 if 1.0 - 2.0 * i / n > 0.5 else 0.0) for i in range(1, n + 1)]
        events = [["touch", 0, 1.0, 0.0], ["loaded to 0.1 d0", n, 1.1, 0.2], ["unloaded", 2 * n, 1.0, 0.0]]
        before = [(-100 + i, 0.95 + 0.0005 * i, -0.001) for i in range(100)]  # an attraction before the touch
        r = tension.pull_range(before + load + back + pull, events, d0=1.0, marks=(0.2, 0.5, 1.0, 3.0))
        self.assertAlmostEqual(r["press_work"], 0.01, places=12)
        self.assertAlmostEqual(r["reached_d0"], 2.0, places=12)
        self.assertEqual(sorted(r["held_over_press"]), [0.2, 0.5, 1.0])      # 3 d0 not reached
        for m, want in ((0.2, 0.08), (0.5, 0.2), (1.0, 0.2)):
            self.assertAlmostEqual(r["held_over_press"][m], want, delta=1.01 * 0.004 * 0.002 / 0.01)  # two half-rows
        self.assertAlmostEqual(r["last_force_d0"], 0.5, delta=0.0021)  # within a row's step
