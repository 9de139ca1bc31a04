"""What the e(v) calibration reports besides its numbers (issue #57, "A YADE user's third hour"):
v_p at the data's edge, the assumed kca that fa follows, an undetermined parameter printed as
such (terminal, JSON, picture), SI units, calibrate.material taking the fit's choices, and the
wall/pair difference the docs state for --against."""
import json
import math
import os
import re
import tempfile
import unittest
import warnings

import numpy as np

from mesocontact import calibrate as cal
from mesocontact import theory
from mesocontact.calibrate import verify
from mesocontact.calibrate.problem import _Problem, _validated

R, RHO = 1e-3, 2500.0
M_R, A12 = cal.geometry(R, RHO)
TRUTH = dict(k1=100.0, kp=500.0, kc=100.0, phiF=0.05, fa=0.0)  # eta = 4, beta = 1
V_P = theory.plastic_limit_velocity(100.0, 500.0, 0.05, A12, M_R)
# 4.9 um adhesive spheres dropped on a plate (the user): jump-in adhesion, v_p near 89 m/s
SMALL_R, SMALL_RHO = 2.45e-6, 1500.0
SMALL = dict(k1=8000.0, kp=40000.0, kc=800.0, phiF=0.05, fa=3e-5)  # kca = 2000 N/m


def exact(truth, lo, hi, n=12, speeds=None):
    """Exact e(v) of the truth at n speeds from lo to hi times v_p (or at `speeds` times v_p), with sigma 0.01."""
    v = np.geomspace(lo * V_P, hi * V_P, n) if speeds is None else np.asarray(speeds) * V_P
    return cal.check_data(v, cal.Setup(M_R, A12).curve(v, truth), np.full(len(v), 0.01))


def small_spheres(seed=1):
    """2 % noise on the jump-in set at 12 speeds from 0.5 to 100 m/s (stuck below about 3 m/s, the
    fastest beyond v_p)."""
    m_r, a12 = cal.geometry(SMALL_R, SMALL_RHO, "wall")
    v = np.geomspace(0.5, 100.0, 12)
    e0 = cal.Setup(m_r, a12, "jumpIn", 2000.0).curve(v, SMALL)
    sigma = 0.02 * np.maximum(e0, 0.1)
    e = np.where(e0 > 0, np.clip(e0 + sigma * np.random.default_rng(seed).standard_normal(len(v)), 0, 1), 0)
    return cal.check_data(v, e, sigma)


class Edge(unittest.TestCase):
    def test_the_definition(self):
        # fewer than EDGE_POINTS (2) points beyond v_p on one side, v_p within EDGE_FACTOR (2) of that end
        v = [1.0, 2.0, 3.0, 4.0, 5.0]
        for v_p, sides in ((4.5, [("fast", 1)]), (3.5, []), (6.0, [("fast", 0)]), (9.9, [("fast", 0)]), (10.5, []),
                           (1.5, [("slow", 1)]), (0.6, [("slow", 0)]), (0.4, []), (2.5, [])):
            got = [(e["side"], e["points"]) for e in cal.v_p_edge(v, v_p)]
            self.assertEqual(got, sides, v_p)
        self.assertEqual([e["side"] for e in cal.v_p_edge([1.0, 2.0], 1.5)], ["fast", "slow"])

    def test_one_point_beyond_v_p_is_said(self):
        # 12 speeds, the fastest alone beyond v_p: it alone sets v_p (the truth comes back, v_p with it)
        speeds = (0.02, 0.05, 0.1, 0.2, 0.3, 0.4, 0.55, 0.7, 0.8, 0.9, 0.95, 1.6)
        f = cal.fit(exact(TRUTH, 0, 0, speeds=speeds), R, RHO, values=dict(k1=100.0), starts=5, bootstrap=0)
        self.assertAlmostEqual(f.v_p / V_P, 1.0, delta=1e-5)
        self.assertEqual(f.v_p_edge, [{"side": "fast", "points": 1, "speed": float(f.data.v.max())}])
        said = [s for s in f.statements if "fast edge" in s]
        self.assertEqual(len(said), 1, f.statements)
        self.assertIn("1 point faster than it", said[0])
        self.assertIn("climbs back towards 1", said[0])
        self.assertIn("at the data's fast edge", f.report())
        j = json.loads(json.dumps(f.to_json(), allow_nan=False))
        self.assertEqual(j["v_p_edge"][0]["side"], "fast")
        self.assertAlmostEqual(j["v_p"], f.v_p)
        self.assertIn(said[0], j["statements"])

    def test_data_well_beyond_v_p_are_not_at_the_edge(self):
        f = cal.fit(exact(TRUTH, 0.02, 5.0), R, RHO, values=dict(k1=100.0), starts=5, bootstrap=0)
        self.assertEqual(f.v_p_edge, [])
        self.assertFalse([s for s in f.statements if "edge" in s], f.statements)


class Undetermined(unittest.TestCase):
    def test_printed_as_undetermined_with_its_bound(self):
        # only rebounds below the sticking window: kp and phiF move along a ridge (test_calibrate)
        rng = np.random.default_rng(0)
        d = exact(TRUTH, 0.02, 0.45)
        d = cal.check_data(d.v, np.clip(d.e + 0.01 * rng.standard_normal(len(d.v)), 0, 1), d.sigma)
        f = cal.fit(d, R, RHO, values=dict(k1=100.0), starts=10, bootstrap=0)
        self.assertTrue({"kp", "phiF"} & set(f.undetermined), f.undetermined)
        text = f.report()
        for n in f.undetermined:
            line = next(x for x in text.splitlines() if x.startswith(f"  {n:5s} ="))
            self.assertRegex(line, rf"^  {n}\s+= undetermined: ", line)
            self.assertNotIn(f"{f.params[n]:.6g}", line)  # the fit's point is not printed as the value
            self.assertIn(f.bound(n), line)
            title = verify._title_value(f, n)
            self.assertTrue(title.startswith(f"{n} undetermined"), title)
            self.assertNotIn(f"{f.params[n]:.3g}", title.split("(")[0])
        self.assertIn("use the fit's point for", text)
        j = json.loads(json.dumps(f.to_json(), allow_nan=False))
        for n in f.undetermined:
            self.assertIsNone(j[n])
            self.assertTrue(j["undetermined_reason"][n].startswith("undetermined by the data: "),
                            j["undetermined_reason"])
            self.assertEqual(j["fit_point"][n], f.params[n])
        self.assertEqual(j["undetermined"], f.undetermined)  # the keys readers had stay
        for n in set(f.free) - set(f.undetermined):
            self.assertEqual(j[n], f.params[n])
        with tempfile.TemporaryDirectory() as tmp:  # the picture is drawn with the words in its title
            verify.plot(f, os.path.join(tmp, "c.png"))
            self.assertGreater(os.path.getsize(os.path.join(tmp, "c.png")), 10000)

    def test_bound_words(self):
        from mesocontact.calibrate.fitting import _bound_text
        self.assertEqual(_bound_text([0.0, 1.2e-3], (0.0, math.inf), "N/m"), "at most 0.0012 N/m")
        self.assertEqual(_bound_text([0.02, 1.0], (0.0, 1.0), ""), "at least 0.02")
        self.assertEqual(_bound_text([100.0, None], (100.0, math.inf), "N/m"), "no bound from the data")
        self.assertEqual(_bound_text([1.0, 3.0], (0.0, math.inf), "N"), "between 1 and 3 N")

    def test_cycles_report(self):
        from tests.python.test_calibrate_cycles import NO_TENSION, TRUTH as T, cycles
        d, F = cycles(NO_TENSION, noise=0.01, seed=6)
        f = cal.fit_cycles(d, F, 1e-3, free=("k1", "kc"), values=dict(kp=T["kp"], phiF=T["phiF"]))
        self.assertEqual(f.undetermined, ["kc"])
        line = next(x for x in f.report().splitlines() if x.startswith("  kc "))
        self.assertEqual(line, "  kc    = undetermined: no bound from the data (95 %)")
        j = f.to_json()
        self.assertEqual(j["kc"], f.params["kc"])  # kept a number: the agglomerate study reads it
        self.assertIn("kc", j["undetermined_reason"])


class UnitsKcaMaterial(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.data = small_spheres()
        cls.fit = cal.fit(cls.data, SMALL_R, SMALL_RHO, against="wall", adhesion="jumpIn", kca=2000.0,
                          values=dict(k1=8000.0, fa=1.5e-5), starts=5, bootstrap=0)

    def test_units_on_every_quantity(self):
        text = self.fit.report()
        lines = text.splitlines()
        self.assertRegex(lines[0], r"from \S+ to \S+ m/s, a sphere on a wall \(m_r = \S+ kg, a12 = \S+ m\)")
        self.assertIn(" s", lines[1].split(";")[-1])
        for n, unit in (("k1", "N/m"), ("kp", "N/m"), ("kc", "N/m"), ("fa", "N"), ("kca", "N/m"), ("v_p", "m/s")):
            line = next(x for x in lines if x.startswith(f"  {n:5s} ="))
            if "undetermined" not in line:
                self.assertRegex(line, rf"= \S+ {re.escape(unit)}\b", line)
        j = self.fit.to_json()
        self.assertEqual(j["units"]["fa"], "N")
        self.assertEqual(j["units"]["v_p"], "m/s")

    def test_kca_assumed_and_what_fa_does_with_it(self):
        f = self.fit
        said = [s for s in f.statements if s.startswith("kca = 2000 N/m is assumed, not fitted")]
        self.assertEqual(len(said), 1, f.statements)
        self.assertIn("fa x", said[0])
        self.assertIn("(assumed, not fitted", f.report())
        slope = f.kca_response["fa"]
        self.assertGreater(slope, 0.05)  # a stiffer tail, a shorter one: a larger fa makes up for it
        self.assertEqual(f.to_json()["kca_assumed"]["dln_dln_kca"]["fa"], slope)
        # the linearised response against a refit from the fit's point with kca 10 % larger
        data, setup, free, values = _validated(self.data, SMALL_R, SMALL_RHO, "wall", "jumpIn", 2200.0, "linear", None,
                                               dict(f.params))
        pb = _Problem(data, setup, free, values, 0)
        q = pb.params(free, pb.best_of(free, pb.fixed, [f.params]).x, pb.fixed)
        self.assertAlmostEqual(math.log(q["fa"] / f.params["fa"]) / math.log(1.1), slope, delta=0.15 * abs(slope))

    def test_material_takes_the_fits_choices(self):
        f = self.fit
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # nothing to warn about: no override, nothing undetermined here
            self.assertEqual(f.undetermined, [])
            m = cal.material(f)
            self.assertEqual((m["adhesion"], m["kca"], m["k2Interpolation"], m["density"], m["fa"]),
                             ("jumpIn", 2000.0, "linear", SMALL_RHO, f.params["fa"]))
            self.assertEqual(cal.material(f, adhesion="jumpIn", kca=2000.0), m)  # the same values: no warning
            j = json.loads(json.dumps(dict(f.to_json(), density=SMALL_RHO), allow_nan=False))
            self.assertEqual(cal.material(j), m)  # calibration.json's dict
        with self.assertWarnsRegex(UserWarning, r"kca = 500\.0 N/m overrides the fit's 2000\.0 N/m"):
            self.assertEqual(cal.material(f, kca=500.0)["kca"], 500.0)  # an explicit override is used, and said
        with self.assertWarnsRegex(UserWarning, r"adhesion = 'none' overrides the fit's 'jumpIn'"):
            self.assertNotIn("fa", cal.material(f, adhesion="none"))
        j = dict(json.loads(json.dumps(f.to_json())), kc=None, undetermined=["kc"])  # a null parameter: the fit's point
        with self.assertWarnsRegex(UserWarning, "kc = .* taken from the fit's point"):
            self.assertEqual(cal.material(j)["kc"], f.params["kc"])


class WallAndPair(unittest.TestCase):
    def test_one_material_two_curves(self):
        # docs/calibration.md (--against): the wall contact has twice a12 and twice m_r, so v_p is
        # sqrt(2) times the pair's and, without adhesion, e_pair(v) = e_wall(sqrt(2) v)
        pair, wall = cal.Setup(*cal.geometry(R, RHO, "particle")), cal.Setup(*cal.geometry(R, RHO, "wall"))
        self.assertAlmostEqual(wall.a12 / pair.a12, 2.0, places=14)
        v = np.geomspace(0.02, 5, 30) * V_P
        np.testing.assert_allclose(pair.curve(v, TRUTH), wall.curve(math.sqrt(2) * v, TRUTH), rtol=1e-12, atol=1e-14)
        self.assertGreater(np.max(np.abs(pair.curve(v, TRUTH) - wall.curve(v, TRUTH))), 0.1)  # not the same e(v)


if __name__ == "__main__":
    unittest.main()
