"""Inputs a user can reach in calibrate and params that used to fail with numpy's, Python's or
scipy's own error (naming nothing), or to give a silent result: each is now a ValueError or
TypeError that names the parameter and the value (issue #57, "Silent or unclear" 6)."""
import math
import unittest
import warnings

import numpy as np

from mesocontact import calibrate as cal
from mesocontact import params, theory

A12 = 1e-3
DMP = theory.delta_max_p(100.0, 500.0, 0.1, A12)
D = np.concatenate([np.linspace(a, b, 20, endpoint=False)
                    for a, b in zip((0, 0.6, 0.1, 1.6), (0.6, 0.1, 1.6, 0.3))]) * DMP
F = (theory.normal_force_path(D, 100.0, 500.0, 100.0, 0.1, A12)
     * (1 + 0.01 * np.random.default_rng(0).standard_normal(len(D))))
NOT_NAMED = (OverflowError, ZeroDivisionError, FloatingPointError, np.linalg.LinAlgError)


class Named(unittest.TestCase):
    def refused(self, f, cases, error=ValueError):
        """Each (arguments, pattern): f(**arguments) raises `error` matching the pattern (the name
        and the value), not an error that names nothing."""
        for kw, pattern in cases:
            with self.subTest(**{k: (repr(v) if np.ndim(v) == 0 else f"array of {np.size(v)}") for k, v in kw.items()}):
                try:
                    f(**kw)
                except NOT_NAMED as e:
                    self.fail(f"{type(e).__name__}: {e}")
                except (ValueError, TypeError) as e:
                    self.assertIsInstance(e, error)
                    self.assertRegex(str(e), pattern)
                else:
                    self.fail("accepted")


class FitCycles(Named):
    def test_empty_equal_negative_and_bools(self):
        n = len(D)

        def fit(**kw):
            cal.fit_cycles(**dict(dict(delta=D, force=F, a12=A12), **kw))
        self.refused(fit, (
            # was numpy's "zero-size array"
            (dict(delta=[], force=[]), "delta and force are empty"),
            # "math domain error"
            (dict(delta=np.full(n, 1e-4)), r"delta: 1 distinct overlap\(s\) \(0\.0001\) cannot determine 4"),
            (dict(delta=np.full(n, 1e-4), force=np.full(n, 1.0)), r"delta: 1 distinct overlap"),
            (dict(delta=np.full(n, 1e-4), force=-np.abs(F), sigma=0.1), r"delta: 1 distinct overlap"),
            # was a silent fit
            (dict(force=-np.abs(F)), r"force: no value is > 0 \(the largest is -.*pass -force"),
            (dict(force=np.full(n, 2.0)), r"force: all 80 values are 2\.0: a constant force"),      # was a silent fit
            (dict(delta=-D), "delta: no overlap is > 0"),
            (dict(delta=[True, False] * (n // 2)), r"delta\[0\] = True is invalid: a bool"),          # was read as 1.0
            (dict(delta=np.ones(n, bool)), r"delta\[0\] = True is invalid: a bool"),
            (dict(delta=[0.0] * 5 + [True] + list(D[6:])), r"delta\[5\] = True is invalid: a bool"),
            (dict(force=[*F[:3], np.bool_(False), *F[4:]]), r"force\[3\] = (np\.)?False.* is invalid: a bool"),
            (dict(sigma=True), "sigma = True is invalid: a bool"),
            (dict(a12=True), "a12 = True"),
        ))
        self.refused(fit, ((dict(free="k1"), r"free = 'k1' is invalid: must be a list of names, e\.g\. free=\['k1'\]"),
                           (dict(values=3), "values = 3 is invalid: must be a dict")), TypeError)
        # was numpy's "could not convert string to float"
        self.refused(fit, ((dict(sigma="x"), "sigma = 'x' is invalid"),))

    def test_extreme_magnitudes(self):
        def fit(**kw):
            cal.fit_cycles(**dict(dict(delta=D, force=F, a12=A12), **kw))
        self.refused(fit, (  # were ZeroDivisionError, OverflowError, scipy's "x0 is infeasible", SVD did not converge
            (dict(delta=D * 1e300, a12=A12 * 1e300), r"delta: the largest \|delta\| = .*e\+296 is outside .*rescale"),
            (dict(delta=D * 1e-300, a12=A12 * 1e-300), r"delta: the largest \|delta\| = .*e-304 is outside"),
            (dict(force=F * 1e-300), r"force: the largest \|force\| = .*e-30\d is outside"),
            (dict(force=F * 1e300), r"force: the largest \|force\| = .*e\+29\d is outside"),
            (dict(a12=1e300), r"a12 = 1e\+300 is outside"),
            (dict(sigma=1e-300), r"sigma\[0\] = 1e-300 is invalid: must be >= 1e-15 of the largest \|force\|"),
        ))
        # inside the range the fit is scale-free: the same fit in other units
        f = cal.fit_cycles(D * 1e90, F * 1e-90, A12 * 1e90, sigma=0.01 * np.max(F) * 1e-90)
        g = cal.fit_cycles(D, F, A12, sigma=0.01 * np.max(F))
        self.assertAlmostEqual(f.params["k1"] / (g.params["k1"] * 1e-180), 1.0, places=5)


class MaterialFrom(Named):
    BASE = dict(radius=1e-3, density=2000.0, impact_speed=0.1, restitution=0.5, contact_time=1e-4, phiF=0.1)

    def test_extreme_contact_times_and_speeds(self):
        def make(**kw):
            params.material_from(**dict(self.BASE, **kw))
        self.refused(make, (
            # was "math domain error"
            (dict(contact_time=1e300), r"contact_time = 1e\+300 is out of range .*1e-605 N/m"),
            (dict(contact_time=1e-300), r"contact_time = 1e-300 is out of range .*1e\+595 N/m"),  # was an OverflowError
            (dict(impact_speed=1e300), r"impact_speed = 1e\+300, contact_time = 0\.0001.*cannot be computed"),
            (dict(radius2=1e300), r"radius2 = 1e\+300: "),                                       # named 'radius'
            (dict(interpolation="cubic"), "interpolation = 'cubic'"),
            (dict(density=1e-300), "density = 1e-300"),                                          # a subnormal mass
        ))


class Fit(Named):
    V = np.geomspace(0.005, 0.3, 8)
    E = cal.Setup(*cal.geometry(1e-3, 2500.0)).curve(V, dict(k1=100.0, kp=500.0, kc=100.0, phiF=0.05, fa=0.0))
    DATA = cal.check_data(V, E, np.full(8, 0.01))

    def test_values_and_options(self):
        def fit(**kw):
            cal.fit(**dict(dict(data=self.DATA, radius=1e-3, density=2500.0, values=dict(k1=100.0), starts=1,
                                bootstrap=0), **kw))
        v = dict(k1=100.0)
        self.refused(fit, (
            (dict(values=dict(v, kc=math.nan)), "kc = nan is invalid"),          # was scipy's "x0 is infeasible"
            # was "array must not contain infs or NaNs"
            (dict(values=dict(v, kc=math.inf)), "kc = inf is invalid"),
            (dict(values=dict(v, kc=-1.0)), "kc = -1.0 is invalid"),             # was silently started at 0
            (dict(values=dict(v, kc=True)), "kc = True is invalid"),
            (dict(values=dict(v, kc="x")), "kc = 'x' is invalid"),               # was "'>' not supported"
            (dict(values=dict(v, fa=math.nan)), "fa = nan is invalid"),          # was returned as fa = nan
            (dict(values=dict(v, fa=None)), "fa = None is invalid"),
            (dict(values=dict(k1="x")), "k1 = 'x' is invalid"),                  # was "can't multiply sequence"
            (dict(values=dict(k1=1e-300)), r"v = .* at point 1: the collision with the starting values \(k1 = 1e-300"),
            (dict(starts=True), "starts = True is invalid: must be an integer >= 1"),  # was a fit with 1 start
            # was "'float' object cannot be interpreted"
            (dict(starts=2.0), "starts = 2.0 is invalid"),
            (dict(bootstrap=-1), "bootstrap = -1 is invalid: must be an integer >= 0"),
            (dict(bootstrap=None), "bootstrap = None is invalid"),
            # was "object of type 'NoneType' has no len()"
            (dict(seed=None), "seed = None is invalid"),
            (dict(seed=0.5), "seed = 0.5 is invalid"),
            (dict(kca=math.nan), "kca = nan is invalid"),
            (dict(interpolation="cubic"), "interpolation = 'cubic' is invalid"),
            (dict(data=(self.V * 1e300, self.E, np.full(8, 0.01))), r"v = 5\.0*4?e\+297 at point 1: the collision"),
            (dict(data=(self.V, self.E, np.full(8, 1e-300))),
             r"sigma = 1e-300 at point 1 is invalid: must be >= 1e-15"),
        ))
        self.refused(fit, ((dict(free="kp"), r"free = 'kp' is invalid: must be a list of names"),
                           (dict(data=3), "data = 3 is invalid"), (dict(values=3), "values = 3 is invalid")), TypeError)

    def test_data(self):
        self.refused(lambda **kw: cal.check_data(**kw), (
            (dict(v=[True, 0.2, 0.3], e=[0.5, 0.5, 0.4]), r"v\[0\] = True is invalid: a bool"),  # was read as 1 m/s
            (dict(v=[0.1, 0.2, 0.3], e=[0.5, False, 0.4]), r"e\[1\] = False is invalid: a bool"),
            (dict(v=np.ones(3, bool), e=[0.5, 0.5, 0.4]), r"v\[0\] = True is invalid: a bool"),
            (dict(v=[0.1, 0.2, 0.3], e=[0.5, 0.5, 0.4], sigma=[0.1, True, 0.1]), r"sigma\[1\] = True"),
            (dict(v=["x", 0.2], e=[0.5, 0.5]), r"data: v is invalid: must be a sequence of numbers"),  # numpy's message
            (dict(v=[0.1, 0.2], e=[0.5, 0.5], sigma=[1e-300, 0.1]), r"sigma = 1e-300 at point 1 is invalid"),
        ), cal.DataError)


class Helpers(Named):
    def test_groups_and_contact_time(self):
        base = dict(eta=4.0, beta=1.0, phiF=0.05, v_p=0.3, radius=1e-3, density=2500.0)
        self.refused(lambda **kw: cal.from_groups(**dict(base, **kw)), (
            (dict(phiF=1e-300), r"from_groups\(.*phiF=1e-300.*out of floating-point range"),   # was an OverflowError
            (dict(v_p=1e300), r"from_groups\(.*v_p=1e\+300.*out of floating-point range"),     # was an OverflowError
            (dict(v_p=1e-300), r"from_groups\(.*v_p=1e-300.*k1 = 0\.0 N/m is out of floating"),  # was k1 = 0 returned
            (dict(eta=1e-300), r"from_groups\(.*eta=1e-300.*k1 = 0\.0 N/m"),
        ))
        base = dict(e=0.7, t_c=2e-4, v=0.05, eta=4.0, beta=1.0, radius=1e-3, density=2500.0)
        self.refused(lambda **kw: cal.from_restitution_and_contact_time(**dict(base, **kw)), (
            # was a ZeroDivisionError
            (dict(t_c=1e300), r"t_c = 1e\+300.*k1 = .* 0\.0 N/m is out of floating-point range"),
            (dict(t_c=1e-300), r"t_c=1e-300.*out of floating-point range"),    # was an OverflowError
        ))
        self.refused(lambda **kw: cal.contact_duration(**dict(dict(chi=0.3, eta=4.0, beta=1.0), **kw)), (
            (dict(chi="x"), "chi = 'x' is invalid"),                           # was "'<' not supported"
            # was inf: a rebounding pair's contact never ending
            (dict(beta=1e-300), r"beta = 1e-300: the pair rebounds .* not finite"),
        ))

    def test_material(self):
        p = dict(k1=100.0, kp=500.0, kc=10.0, phiF=0.1, fa=0.0)
        self.refused(lambda **kw: cal.material(**dict(dict(params=p), **kw)), (
            (dict(adhesion="glue"), "adhesion = 'glue' is invalid"),        # was put in the material as given
            (dict(adhesion=math.nan), "adhesion = nan is invalid"),
            (dict(kca=math.nan, adhesion="jumpIn"), "kca = nan is invalid"),
            (dict(density=True), "density = True is invalid"),
            (dict(density="x"), "density = 'x' is invalid"),
            (dict(params=dict(p, phiF=2.0)), "phiF = 2.0 is invalid"),
            (dict(params=dict(p, fa=1e-6)), r"fa = 1e-06 N > 0 with adhesion 'none'"),  # was dropped silently
        ))
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            self.assertEqual(cal.material(p, "jumpIn", 50.0, "sqrt", 2500.0)["kca"], 50.0)  # the old positional call
        with self.assertRaisesRegex(TypeError, "params = 3 is invalid"):
            cal.material(3)


if __name__ == "__main__":
    unittest.main()
