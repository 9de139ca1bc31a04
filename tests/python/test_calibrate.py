"""`mesocontact.calibrate`: the fit returns the truth from exact data to 1e-5 and holds it in its
intervals from noisy data; the undetermined parameters are named for data that lack a regime; bad
data and arguments are refused naming the problem; the contact duration and the other helpers
against an independent integration of the force law."""
import math
import os
import tempfile
import unittest

import numpy as np

from mesocontact import calibrate as cal
from mesocontact import theory

R, RHO = 1e-3, 2500.0
M_R, A12 = cal.geometry(R, RHO)
TRUTH = dict(k1=100.0, kp=500.0, kc=100.0, phiF=0.05, fa=0.0)  # eta = 4, beta = 1: a sticking window


def speeds(truth, lo, hi, n, adhesion="none"):
    vp = theory.plastic_limit_velocity(truth["k1"], truth["kp"], truth["phiF"], A12, M_R,
                                       truth["fa"] if adhesion != "none" else 0.0)
    return np.geomspace(lo * vp, hi * vp, n)


def data(truth, v, noise=0.0, seed=0, adhesion="none", kca=math.inf):
    e0 = cal.Setup(M_R, A12, adhesion, kca).curve(v, truth)
    sigma = np.maximum(noise * np.maximum(e0, 0.1), 1e-3)
    e = np.where(e0 > 0,
                 np.clip(e0 + noise * np.maximum(e0, 0.1) * np.random.default_rng(seed).standard_normal(len(v)), 0, 1),
                 0)
    return cal.check_data(v, e, sigma)


class Fits(unittest.TestCase):
    def test_noise_free_data_give_the_truth(self):
        # 12 points over all regimes; the solver's tolerances are 1e-12, the data exact: the fit
        # must find the parameters to far better than any interval (1e-5 relative)
        f = cal.fit(data(TRUTH, speeds(TRUTH, 0.02, 5, 12)), R, RHO, values=dict(k1=100.0), starts=10, bootstrap=0)
        for n in ("kp", "kc", "phiF"):
            self.assertAlmostEqual(f.params[n] / TRUTH[n], 1.0, delta=1e-5, msg=n)
        self.assertLess(f.rms_residual, 1e-7)
        self.assertEqual(f.undetermined, [])

    def test_noisy_data_inside_the_intervals(self):
        # 2 % noise, one fixed draw: the truth inside both 95 % intervals (a draw's 1 - 0.95^6
        # chance of a miss is why the coverage over many draws is in docs/calibration.md)
        f = cal.fit(data(TRUTH, speeds(TRUTH, 0.02, 5, 20), 0.02, seed=3), R, RHO, values=dict(k1=100.0),
                    starts=10, bootstrap=40)
        for n in ("kp", "kc", "phiF"):
            lo, hi = f.ci95[n]
            self.assertTrue(lo <= TRUTH[n] <= hi, f"{n}: {TRUTH[n]} outside {lo, hi}")
            self.assertLess(hi / lo, 1.5, n)  # determined: a narrow interval
        self.assertIsNotNone(f.chi2_reduced)

    def test_reversible_adhesion_fits_fa(self):
        truth = dict(k1=100.0, kp=500.0, kc=20.0, phiF=0.05, fa=2e-4)
        v = speeds(truth, 0.005, 5, 16, "reversible")
        f = cal.fit(data(truth, v, adhesion="reversible", kca=100.0), R, RHO, adhesion="reversible", kca=100.0,
                    values=dict(k1=100.0, fa=1e-4), starts=10, bootstrap=0)
        for n in ("kp", "kc", "phiF", "fa"):
            self.assertAlmostEqual(f.params[n] / truth[n], 1.0, delta=1e-5, msg=n)


class Identifiability(unittest.TestCase):
    def test_stiffness_scale_is_undetermined_without_adhesion(self):
        # e(v) depends on eta, beta, v_p only: k1 -> lambda k1 with phiF -> phiF/sqrt(lambda) is invisible
        f = cal.fit(data(TRUTH, speeds(TRUTH, 0.02, 5, 12)), R, RHO, free=["k1", "kp", "kc", "phiF"],
                    values=dict(k1=100.0), starts=10, bootstrap=0)
        self.assertEqual(sorted(f.undetermined), ["k1", "kc", "kp", "phiF"])
        self.assertTrue(any("combination" in s and "phiF x lambda^-0.50" in s for s in f.statements), f.statements)

    def test_points_only_beyond_vp(self):
        f = cal.fit(data(TRUTH, speeds(TRUTH, 1.2, 5, 12), 0.01), R, RHO, values=dict(k1=100.0), starts=10, bootstrap=0)
        self.assertTrue(f.undetermined)
        self.assertTrue(any("beyond v_p" in s for s in f.statements), f.statements)

    def test_points_only_below_the_window(self):
        # Eq. 32 sees kp and phiF only through eta chi: one of them is free along the ridge
        f = cal.fit(data(TRUTH, speeds(TRUTH, 0.02, 0.45, 12), 0.01), R, RHO, values=dict(k1=100.0), starts=10,
                    bootstrap=0)
        self.assertTrue({"kp", "phiF"} & set(f.undetermined), f.undetermined)

    def test_no_low_speed_points_leave_fa_undetermined(self):
        truth = dict(k1=100.0, kp=500.0, kc=20.0, phiF=0.05, fa=2e-4)
        v = speeds(truth, 0.5, 5, 16, "reversible")
        f = cal.fit(data(truth, v, 0.02, adhesion="reversible", kca=100.0), R, RHO, adhesion="reversible", kca=100.0,
                    values=dict(k1=100.0, fa=1e-4), starts=10, bootstrap=0)
        self.assertIn("fa", f.undetermined)

    def test_profile_interval_holds_a_second_branch(self):
        # Issue #32 item 11. Jump-in, 7 speeds from 0.3 to 4 v_p, 2 % noise: the best fit is
        # kp = 292, kc = 3100 (beta = 31), and the truth (kp = 500, kc = 100: another branch of a
        # multi-modal fit, reached from neither the optimum nor random starts) fits the data within
        # delta chi2 = 0.10 of it, so every 95 % profile interval must hold it. Refitted from the
        # optimum and its neighbour alone the profile gave kp [231, 358], phiF [0.065, 0.088].
        truth = dict(k1=100.0, kp=500.0, kc=100.0, phiF=0.1, fa=2e-4)
        d = data(truth, speeds(truth, 0.3, 4, 7, "jumpIn"), 0.02, seed=0, adhesion="jumpIn", kca=200.0)
        f = cal.fit(d, R, RHO, adhesion="jumpIn", kca=200.0, values=dict(k1=100.0), starts=10, bootstrap=0)
        setup = cal.Setup(M_R, A12, "jumpIn", 200.0)

        def chi2(p):
            return float(np.sum(((setup.curve(d.v, p) - d.e) / d.sigma) ** 2))
        self.assertLess(chi2(truth) - chi2(f.params), cal.PROFILE_CHI2)  # the premise, computed here
        for n in f.free:
            lo, hi = f.ci95[n]
            self.assertTrue(lo <= truth[n] <= hi, f"{n}: {truth[n]} outside {lo, hi}")

    def test_profile_intervals_hold_every_point_under_the_threshold(self):
        # Issue #32 item 11, two draws of studies/scripts/calibrate_profile_study.py (its noise model) where
        # the previous search still missed the truth: draw 7, truth at delta chi2 = 0.48, phiF
        # [0.065, 0.082]; draw 6, truth at 3.05, kp [229, 379] and phiF [0.063, 0.072]. In draw 7 the
        # solver had already evaluated points under the threshold with phiF up to 0.12 (a point under
        # the threshold lies inside every interval by definition); in draw 6 none had kp near 500, and
        # the scan of kp reaches the truth's branch by keeping v_p (phiF (1 + eta)/eta) as kp moves.
        truth = dict(k1=100.0, kp=500.0, kc=100.0, phiF=0.1, fa=2e-4)
        setup = cal.Setup(M_R, A12, "jumpIn", 200.0)
        v_p = theory.plastic_limit_velocity(100.0, 500.0, 0.1, A12, M_R, 2e-4)
        v = np.geomspace(0.3 * v_p, 4 * v_p, 7)
        e0 = setup.curve(v, truth)
        noise = 0.02 * np.maximum(e0, 0.1)
        for seed in (7, 6):
            e = np.where(e0 > 0, np.clip(e0 + noise * np.random.default_rng(seed).standard_normal(len(v)), 0, 1), 0)
            sigma = np.maximum(noise, 1e-3)
            f = cal.fit((v, e, sigma), R, RHO, adhesion="jumpIn", kca=200.0, values=dict(k1=100.0), starts=10,
                        bootstrap=0)
            chi2 = lambda p: float(np.sum(((setup.curve(v, p) - e) / sigma) ** 2))  # noqa: E731
            self.assertLess(chi2(truth) - chi2(f.params), cal.PROFILE_CHI2)  # the premise, computed here
            for n in f.free:
                lo, hi = f.ci95[n]
                self.assertTrue(lo <= truth[n] <= hi, f"draw {seed}, {n}: {truth[n]} outside {lo, hi}")


class BadInput(unittest.TestCase):
    def csv(self, text):
        fd, path = tempfile.mkstemp(suffix=".csv")
        with os.fdopen(fd, "w") as f:
            f.write(text)
        self.addCleanup(os.remove, path)
        return path

    def test_data_errors_name_the_problem(self):
        for text, words in (("v,e\n0.1,1.2\n0.2,0.5\n", ["e = 1.2", "point 1"]),
                            ("v,e\n-0.1,0.5\n0.2,0.5\n", ["v = -0.1", "point 1"]),
                            ("v,sigma\n0.1,0.01\n", ["column 'e' is missing"]),
                            ("v,e\n0.1,abc\n", ["e = 'abc' is not a number"]),
                            ("v,e,sigma\n0.1,0.5,0\n", ["sigma = 0.0", "must be a finite number > 0"]),
                            ("v,e\n0.1\n", ["1 values for 2 columns"]),
                            ("# only a comment\n", ["no header"])):
            with self.assertRaises(cal.DataError) as c:
                cal.load_data(self.csv(text))
            for w in words:
                self.assertIn(w, str(c.exception), text)

    def test_files_people_have(self):
        # a spreadsheet's "CSV UTF-8" (a byte-order mark), a duplicated column, a binary file
        self.assertEqual(list(cal.load_data(self.csv("\ufeffv,e\n0.1,0.8\n0.2,0.7\n")).v), [0.1, 0.2])
        with self.assertRaisesRegex(cal.DataError, "column 'e' appears 2 times"):
            cal.load_data(self.csv("v,e,e\n0.1,0.8,0.7\n"))
        fd, path = tempfile.mkstemp(suffix=".csv")
        with os.fdopen(fd, "wb") as f:
            f.write(b"\x89PNG\r\n\x1a\n\xff\xfe")
        self.addCleanup(os.remove, path)
        with self.assertRaisesRegex(cal.DataError, path.replace(".", "\\.") + ": not a text CSV file"):
            cal.load_data(path)

    def test_data_that_cannot_determine_the_fit(self):
        start = dict(k1=100.0, kp=500.0, kc=50.0, phiF=0.1)
        with self.assertRaisesRegex(cal.DataError, "1 distinct speed.*3 free parameters"):  # four identical rows
            cal.fit(cal.check_data([0.1] * 4, [0.5] * 4), 1e-3, 2000, values=start)
        with self.assertRaisesRegex(cal.DataError, "passes through every point"):  # no sigma, no spread
            cal.fit(cal.check_data([0.05, 0.1, 0.2], [0.9, 0.8, 0.7]), 1e-3, 2000, values=start, bootstrap=0)

    def test_comments_and_sigma_are_read(self):
        d = cal.load_data(self.csv("# drop tests\nv,e,sigma\n0.1,0.8,0.01\n# a note\n0.2,0.7,0.02\n"))
        self.assertEqual(list(d.v), [0.1, 0.2])
        self.assertEqual(list(d.sigma), [0.01, 0.02])

    def test_fit_arguments_are_checked(self):
        d = data(TRUTH, speeds(TRUTH, 0.02, 5, 6))
        cases = ((dict(values={}), "no value for k1"),
                 (dict(values=dict(k1=100.0), free=["kp", "bogus"]), "'bogus' is unknown"),
                 (dict(values=dict(k1=100.0), free=["fa"]), "needs adhesion"),
                 (dict(values=dict(k1=100.0), adhesion="reversible"), "kca = inf is invalid"),
                 (dict(values=dict(k1=100.0, phiF=2.0), free=["kp"]), "phiF = 2.0"),
                 (dict(values=dict(k1=100.0), against="ceiling"), "against = 'ceiling'"))
        for kw, words in cases:
            with self.assertRaises(ValueError) as c:
                cal.fit(d, R, RHO, starts=1, bootstrap=0, **kw)
            self.assertIn(words, str(c.exception), kw)
        with self.assertRaises(cal.DataError) as c:
            cal.fit(data(TRUTH, speeds(TRUTH, 0.02, 5, 2)), R, RHO, values=dict(k1=100.0), starts=1, bootstrap=0)
        self.assertIn("2 points cannot fix 3 free parameters", str(c.exception))


def overlap_duration(k1, kp, kc, phiF, a12, m_r, v, steps=200000):
    """Time with positive overlap of a head-on collision, by velocity Verlet of the force law
    written here from docs/model.md §3 (k2 linear in deltaMax, the -kc branch with deltaMax reset)."""
    dmp = kp / (kp - k1) * phiF * a12
    t_guess = math.pi * math.sqrt(m_r / k1) * 4
    dt = t_guess / steps
    d, u, dm, t = 0.0, v, 0.0, 0.0

    def force(d, dm):
        dm = max(dm, d)
        k2 = kp if dm >= dmp else k1 + (kp - k1) * dm / dmp
        f = k2 * (d - (1 - k1 / k2) * dm)
        if f < -kc * d:  # on the tensile branch; the reset of deltaMax keeps the branch (its value unused here)
            f = -kc * d
        return f, dm

    f, dm = force(d, dm)
    while True:
        u -= 0.5 * dt * f / m_r
        d += dt * u
        t += dt
        if d <= 0:
            return t - d / u  # back to the crossing (d <= 0, u < 0)
        f, dm = force(d, dm)
        u -= 0.5 * dt * f / m_r


class Helpers(unittest.TestCase):
    def test_from_groups(self):
        p = cal.from_groups(4.0, 1.0, 0.05, 0.3, R, RHO)
        self.assertAlmostEqual(p["kp"] / p["k1"] - 1, 4.0, places=12)
        self.assertAlmostEqual(p["kc"] / p["k1"], 1.0, places=12)
        self.assertAlmostEqual(theory.plastic_limit_velocity(p["k1"], p["kp"], p["phiF"], A12, M_R), 0.3, places=12)

    def test_contact_duration_against_integration(self):
        # below v_p (chi = 0.3, 0.45) with beta = 0 and 1: the closed form against velocity Verlet
        # (2e5 steps over four contact times: error O(dt) from the crossing, < 1e-4 relative)
        for kc in (0.0, 100.0):
            for chi in (0.3, 0.45):
                v = theory.impact_velocity_for_chi(chi, 100.0, 500.0, 0.05, A12, M_R)
                t_num = overlap_duration(100.0, 500.0, kc, 0.05, A12, M_R, v)
                t_cf = cal.contact_duration(chi, 4.0, kc / 100.0) * math.sqrt(M_R / 100.0)
                self.assertAlmostEqual(t_cf / t_num, 1.0, delta=1e-4, msg=(kc, chi))

    def test_from_restitution_and_contact_time(self):
        t_c = 2e-4
        p = cal.from_restitution_and_contact_time(0.7, t_c, 0.05, 4.0, 1.0, R, RHO)
        setup = cal.Setup(M_R, A12)
        self.assertAlmostEqual(float(setup.curve(0.05, dict(p, fa=0.0))[0]), 0.7, places=9)
        dmp = theory.delta_max_p(p["k1"], p["kp"], p["phiF"], A12)
        chi = theory.max_overlap(0.05, p["k1"], p["kp"], p["phiF"], A12, M_R) / dmp
        self.assertAlmostEqual(cal.contact_duration(chi, 4.0, 1.0) * math.sqrt(M_R / p["k1"]) / t_c, 1.0, places=9)
        with self.assertRaises(ValueError):
            # without adhesion e(chi <= 1) stays above 1/sqrt(1 + eta) = 0.447
            cal.from_restitution_and_contact_time(0.3, t_c, 0.05, 4.0, 0.0, R, RHO)


if __name__ == "__main__":
    unittest.main()
