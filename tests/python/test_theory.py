"""the closed form against the reference values of `docs/model.md` §6 and against an independent
numerical integration of the force law written here from `docs/model.md` §3-4; the tensile range
against bisection on the unloading line, growing with δmax up to its bound; every function refuses
arguments outside its domain, naming them; `normal_force_path` against a loop transcription of
`NormalLaw.hpp` on random paths (the same bits with 'linear')."""
import math
import unittest

from mesocontact import params, theory


def integrate_collision(v_inf, k1, kp, kc, phiF, a12, m_r, fa=0.0, kca=math.inf, adhesion="none", steps=40000):
    """Velocity-Verlet integration of the head-on collision (reference written independently of
    the C++ core: the -kc reset is found by bisection). Returns e, or 0 if still bound."""
    dmp = kp / (kp - k1) * phiF * a12
    da = -fa / kca if fa > 0 else 0.0

    def k2_of(dm):
        return kp if dm >= dmp else k1 + (kp - k1) * dm / dmp

    st = {"dm": 0.0, "touched": False}

    def force(d):
        f = 0.0
        if d > 0:
            if d > st["dm"]:
                st["dm"] = d
            k2 = k2_of(st["dm"])
            d0 = phiF * a12 if st["dm"] >= dmp else (1 - k1 / k2) * st["dm"]
            f = k2 * (d - d0)
            if f < -kc * d:
                lo, hi = d, st["dm"]  # (k2(x) - k1) x - (k2(x) + kc) d changes sign in [d, dm]
                for _ in range(200):
                    mid = 0.5 * (lo + hi)
                    if (k2_of(mid) - k1) * mid - (k2_of(mid) + kc) * d > 0:
                        hi = mid
                    else:
                        lo = mid
                st["dm"] = 0.5 * (lo + hi)
                f = -kc * d
        else:
            st["dm"] = 0.0
        if adhesion != "none" and fa > 0:
            if adhesion == "jumpIn" and not st["touched"]:
                if d > 0:
                    st["touched"] = True
            if adhesion == "reversible" or st["touched"]:
                f += -fa if d > 0 else (-kca * d - fa if d > da else 0.0)
        return f

    t_c = math.pi * math.sqrt(m_r / kp)
    dt = t_c / 2000
    d, v = da - 2 * v_inf * dt, v_inf  # v = d(delta)/dt
    a = -force(d) / m_r
    for _ in range(steps * 5):
        v_half = v + 0.5 * dt * a
        d += dt * v_half
        a = -force(d) / m_r
        v = v_half + 0.5 * dt * a
        if d < da and v < 0:
            return -v / v_inf
    return 0.0


class ReferenceValues(unittest.TestCase):
    """docs/model.md §6, eta = 4, beta = 1."""

    def test_sticking_window(self):
        self.assertAlmostEqual(theory.chi_c_b(4, 1), 0.5, places=12)
        self.assertAlmostEqual(theory.chi_c_c(4, 1), math.sqrt(4 / 3), places=12)
        self.assertAlmostEqual(theory.beta_star(4), 1 / 3, places=12)
        self.assertAlmostEqual(theory.max_sticking_overlap(4, 1), math.sqrt(1 / 3), places=12)

    def test_quoted_restitution(self):
        self.assertAlmostEqual(theory.restitution_fa0(0.34, 4, 1), 0.4364, delta=5e-5)
        self.assertAlmostEqual(theory.restitution_fa0(1.37, 4, 1), 0.5382, delta=5e-5)

    def test_window_edges_and_continuity(self):
        self.assertAlmostEqual(theory.en_squared(theory.chi_c_b(4, 1), 4, 1), 0.0, places=12)
        self.assertAlmostEqual(theory.en_squared(theory.chi_c_c(4, 1), 4, 1), 0.0, places=12)
        for eta, beta in ((4, 1), (50, 0.1), (5, 0)):
            lo = theory.en_squared(1 - 1e-9, eta, beta)
            hi = theory.en_squared(1 + 1e-9, eta, beta)
            self.assertAlmostEqual(lo, hi, places=7)
        self.assertAlmostEqual(theory.sticking_overlap(1.0, 4, 1), theory.max_sticking_overlap(4, 1), places=12)
        with self.assertRaises(ValueError):
            theory.sticking_overlap(0.3, 4, 1)

    def test_no_sticking_below_beta_star(self):
        b = theory.beta_star(4)
        self.assertGreater(theory.en_squared(1.0, 4, 0.9 * b), 0)
        self.assertLess(theory.en_squared(1.0, 4, 1.1 * b), 0)

    def test_asymptotes(self):
        self.assertAlmostEqual(theory.restitution_fa0(1.0, 500, 0) * math.sqrt(500), 1.0, delta=2e-3)  # C.2
        self.assertAlmostEqual(theory.low_velocity_restitution(1e-4, 4), theory.restitution_fa0(1e-4, 4, 1), delta=1e-7)

    def test_widened_kp(self):
        self.assertAlmostEqual(theory.widened_kp(100, 500, 0.1, 0.1), 500, places=9)  # B = 1 gives kp back
        self.assertGreater(theory.widened_kp(100, 500, 0.05, 0.5), 500)

    def test_widened_kp_keeps_small_overlaps(self):
        # Appendix A's purpose, checked from the force law itself: below the old deltaMax^p the
        # tuned model's k2(deltaMax) = k1 + (kp' - k1) deltaMax/deltaMax^p' (Eq. 9) equals the
        # reference's, so every collision that stays below it ends alike (Eq. 21)
        a12, m_r = 1.1e-3, 5.6e-6
        for k1, kp, phi, phi2 in ((100, 500, 0.1, 0.5), (10, 1e4, 0.02, 0.9), (1e3, 1.5e3, 0.3, 0.31)):
            kp2 = theory.widened_kp(k1, kp, phi, phi2)
            slope = (kp - k1) / theory.delta_max_p(k1, kp, phi, a12)
            slope2 = (kp2 - k1) / theory.delta_max_p(k1, kp2, phi2, a12)
            self.assertAlmostEqual(slope2 / slope, 1.0, places=12)
            v = 0.9 * theory.plastic_limit_velocity(k1, kp, phi, a12, m_r)
            e1 = theory.pair_collision(v, k1, kp, 0.3 * k1, phi, a12, m_r).e
            e2 = theory.pair_collision(v, k1, kp2, 0.3 * k1, phi2, a12, m_r).e
            self.assertAlmostEqual(e1, e2, places=12)

    def test_asymptote_validity(self):
        # (eta chi)^-1/2 is sqrt(1 + 1/(eta chi)) below e1 = (1 + eta chi)^-1/2: within 5 % for
        # eta chi >= 1/(1.05^2 - 1) = 9.756; the sqrt rule's (eta sqrt chi)^-1/2 likewise
        edge = 1.0 / (1.05 ** 2 - 1.0)
        for eta in (50.0, 500.0):
            chi = edge / eta
            self.assertAlmostEqual(theory.restitution_asymptote(chi, eta) / theory.restitution_fa0(chi, eta, 0), 1.05,
                                   places=9)
            chi_s = (edge / eta) ** 2
            self.assertAlmostEqual(theory.restitution_asymptote(chi_s, eta, 0.0, "sqrt")
                                   / theory.restitution_fa0(chi_s, eta, 0, "sqrt"), 1.05, places=9)


class TimeStep(unittest.TestCase):
    def test_binding_stiffness(self):
        m = params.sphere_mass(1e-3, 2000)
        base = params.resolved_step(1e3, m, steps_per_contact=1)
        self.assertAlmostEqual(base, params.contact_time(1e3, m / 2), places=15)  # normal: pi sqrt(m_r/kp)
        self.assertAlmostEqual(params.resolved_step(1e3, m, kt=1e3 / 3.5 * 0.99, steps_per_contact=1), base, places=15)
        self.assertLess(params.resolved_step(1e3, m, kt=1e3, steps_per_contact=1), base)   # sliding binds
        # rolling binds (2.5 kr/m > kp/m_r)
        self.assertLess(params.resolved_step(1e3, m, kr=1e3, steps_per_contact=1), base)
        self.assertLess(params.resolved_step(1e3, m, ko=1e3, steps_per_contact=1), base)   # torsion binds
        self.assertAlmostEqual(params.resolved_step(1e3, m, steps_per_contact=50), base / 50, places=15)
        with self.assertRaisesRegex(ValueError, "^kt"):
            params.resolved_step(1e3, m, kt=-1)

    def test_reduced_mass_of_the_pair(self):
        """The pair drivers' step: the half period of kp with the pair's own reduced mass (a sphere
        on a wall: its mass) over steps_per_contact, to rounding."""
        m = params.sphere_mass(1e-3, 2000)
        for m_r in (m, m / 3, 0.5 * m):
            dt = params.resolved_step(1e3, m, m_r=m_r, steps_per_contact=2000)
            self.assertLess(abs(dt / (params.contact_time(1e3, m_r) / 2000) - 1), 4e-16)
        self.assertEqual(params.resolved_step(1e3, m, m_r=0.5 * m), params.resolved_step(1e3, m))
        with self.assertRaisesRegex(ValueError, "^m_r"):
            params.resolved_step(1e3, m, m_r=0.0)


class DimensionalForm(unittest.TestCase):
    r = 1.1e-3
    m_r = params.sphere_mass(1.1e-3, 2000) / 2

    def test_matches_dimensionless_for_fa0(self):
        for chi in (0.05, 0.34, 0.7, 1.0, 1.37, 3.0):
            v = theory.impact_velocity_for_chi(chi, 100, 500, 0.1, self.r, self.m_r)
            out = theory.pair_collision(v, 100, 500, 100, 0.1, self.r, self.m_r)
            self.assertAlmostEqual(out.e, theory.restitution_fa0(chi, 4, 1), places=10)

    def test_against_independent_integration(self):
        fa_small = params.fa_from_alpha(0.042, 100, self.m_r, 0.01)
        fa_large = params.fa_from_alpha(0.42, 100, self.m_r, 0.01)
        cases = [(0.3, 0.0, "none"), (1.5, 0.0, "none"), (0.2, fa_small, "jumpIn"), (1.3, fa_large, "jumpIn"),
                 (0.1, fa_large, "reversible"), (2.0, fa_small, "reversible")]
        for zeta, fa, mode in cases:
            v = zeta * theory.plastic_limit_velocity(100, 500, 0.1, self.r, self.m_r, fa)
            closed = theory.pair_collision(v, 100, 500, 100, 0.1, self.r, self.m_r, fa=fa, kca=100, adhesion=mode)
            numeric = integrate_collision(v, 100, 500, 100, 0.1, self.r, self.m_r, fa=fa, kca=100, adhesion=mode)
            self.assertAlmostEqual(closed.e, numeric, delta=1e-3, msg=f"{zeta} {fa} {mode}")

    def test_bad_input_names_parameter(self):
        for kw, name in ((dict(kp=50), "kp"), (dict(adhesion="glue"), "adhesion"), (dict(v_inf=float("nan")), "v_inf"),
                         (dict(fa=1e-3, kca=0, adhesion="reversible"), "kca")):
            args = dict(v_inf=0.1, k1=100, kp=500, kc=100, phiF=0.1, a12=self.r, m_r=self.m_r)
            args.update(kw)
            with self.assertRaisesRegex(ValueError, "^" + name):
                theory.pair_collision(**args)


if __name__ == "__main__":
    unittest.main()


class OutsideTheDomain(unittest.TestCase):
    """Every public function raises ValueError naming the argument outside its domain, instead of
    returning a number (issue #14 item 9: e.g. restitution_fa0(0.5, -0.5, 0) gave 1.155)."""

    inf, nan = math.inf, math.nan
    calls = [
        ("eta", theory.restitution_fa0, (0.5, -0.5, 0)),
        ("beta", theory.restitution_fa0, (0.5, 2.0, -1)),
        ("chi", theory.restitution_fa0, (nan, 2.0, 0)),
        ("interpolation", theory.k2_over_k1, (0.5, 2.0, "cubic")),
        ("interpolation", theory.en_squared, (0.5, 2.0, 0.1, "cubic")),
        ("chi", theory.k2_over_k1, (-0.1, 2.0)),
        ("chi", theory.low_velocity_restitution, (10, 4)),
        ("eta", theory.low_velocity_restitution, (0.1, -1)),
        ("eta", theory.chi_c_c, (-1, 0.5)),
        ("beta", theory.chi_c_c, (2, nan)),
        ("eta", theory.beta_star, (nan,)),
        ("beta", theory.max_sticking_overlap, (2.0, 0.1)),  # does not stick at chi = 1
        ("chi", theory.restitution_asymptote, (0, 2.0)),
        ("interpolation", theory.restitution_asymptote, (0.5, 2.0, 0.0, "cubic")),
        ("phiF_new", theory.widened_kp, (100, 500, 0.1, 0)),
        ("kp", theory.widened_kp, (100, 50, 0.1, 0.2)),
        ("phiF", theory.delta_max_p, (100, 500, 1.5, 1e-3)),
        ("a12", theory.delta_max_p, (100, 500, 0.1, -1e-3)),
        ("m_r", theory.plastic_limit_velocity, (100, 500, 0.1, 1e-3, 0)),
        ("fa", theory.plastic_limit_velocity, (100, 500, 0.1, 1e-3, 1e-6, -1)),
        ("kp", theory.pair_collision, (0.1, 100, inf, 0, 0.1, 1e-3, 1e-6)),
        ("kp", theory.pair_collision, (0.1, 100, nan, 0, 0.1, 1e-3, 1e-6)),
        ("phiF", theory.pair_collision, (0.1, 100, 500, 0, 0, 1e-3, 1e-6)),
        ("kca", theory.pair_collision, (0.1, 100, 500, 0, 0.1, 1e-3, 1e-6, 1e-4, nan, "reversible")),
        ("chi", theory.impact_velocity_for_chi, (-1, 100, 500, 0.1, 1e-3, 1e-6)),
        ("m1", params.reduced_mass, (-1, 2)),
        ("m2", params.reduced_mass, (1, nan)),
        ("a1", params.reduced_radius, (0, 1)),
        ("v_i", params.fa_from_alpha, (0.4, 100, 1e-6, -1)),
        ("steps_per_contact", params.resolved_step, (500, 1e-6), {"steps_per_contact": -50}),
        ("k", params.contact_time, (True, 1.0)),  # a bool is a slip, not 1
        ("radius", params.sphere_mass, (1e-300, 2000)),  # the mass underflows to 0
        ("radius", params.sphere_mass, (1e200, 1e200)),  # and overflows
        # results out of range: the call with
        ("resolved_step(kp=1e+308, m_min=1e-12)", params.resolved_step, (1e308, 1e-12)),
        # its arguments named, not 0 or inf
        ("reduced_mass(m1=1e-320, m2=1e-320)", params.reduced_mass, (1e-320, 1e-320)),
        ("contact_time(k=1e-320, m_r=1e+300)", params.contact_time, (1e-320, 1e300)),
        ("chi", theory.impact_velocity_for_chi, (1e308, 100, 500, 0.1, 1e-3, 1e-6)),
    ]

    def test_numpy_numbers_are_numbers(self):
        import numpy as np
        self.assertEqual(params.contact_time(np.float32(100), np.int64(1)), params.contact_time(100.0, 1.0))

    def test_each_call_names_its_argument(self):
        for name, f, args, *kw in self.calls:
            with self.subTest(f=f.__name__, args=args):
                with self.assertRaises(ValueError) as c:
                    f(*args, **(kw[0] if kw else {}))
                self.assertTrue(str(c.exception).startswith(name), str(c.exception))

    def test_inside_the_domain_still_answers(self):
        self.assertAlmostEqual(theory.low_velocity_restitution(0.1, 4), 0.8)
        self.assertAlmostEqual(theory.max_sticking_overlap(9.0, 0.5) ** 2,
                               (0.5 * 81 - 10.5) / (0.5 * 10 * 10.5))
        self.assertEqual(params.reduced_mass(2.0), 2.0)  # against a wall


class MaxOverlap(unittest.TestCase):
    """theory.max_overlap against the work integral of the loading force, summed here."""

    def test_work_integral(self):
        k1, kp, phiF, a12, m_r = 100.0, 500.0, 0.1, 1e-3, 4e-6
        dmp = kp / (kp - k1) * phiF * a12
        for fa in (0.0, 2e-5):
            for v in (0.05, 0.3, 1.0):  # below and above v_p
                def work(d, n=20000):
                    h, w = d / n, 0.0
                    for j in range(n):
                        x = (j + 0.5) * h
                        w += h * ((k1 * x if x <= dmp else kp * (x - phiF * a12)) - fa)
                    return w
                E = 0.5 * m_r * v * v
                d = theory.max_overlap(v, k1, kp, phiF, a12, m_r, fa)
                self.assertAlmostEqual(work(d) / E, 1.0, delta=1e-6, msg=f"v {v}, fa {fa}")


class TensileRange(unittest.TestCase):
    """theory.tensile_range against the force-free and tensile-limit overlaps found by bisection on
    the unloading line written here from docs/model.md §3 (the tablet's brittleness, docs/tablet)."""

    k1, kp, kc, phiF, a12 = 0.5, 1.0, 0.2, 0.05, 0.5  # Appendix F's ratios, a12 = d0/2 with d0 = 1

    def by_bisection(self, dm, interpolation):
        dmp = self.kp / (self.kp - self.k1) * self.phiF * self.a12
        x = min(dm / dmp, 1.0)
        k2 = self.k1 + (self.kp - self.k1) * (math.sqrt(x) if interpolation == "sqrt" else x)
        # the unloading line: through (dm, k1 dm) below dmp, the limit branch kp (d - phiF a12) beyond it
        if dm >= dmp:
            line = lambda d: self.kp * (d - self.phiF * self.a12)  # noqa: E731
        else:
            line = lambda d: k2 * (d - dm) + self.k1 * dm  # noqa: E731

        def root(g):
            lo, hi = 0.0, dm
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                lo, hi = (mid, hi) if g(mid) < 0 else (lo, mid)
            return 0.5 * (lo + hi)
        return root(line) - root(lambda d: line(d) + self.kc * d)

    def test_against_bisection(self):
        for interpolation in ("linear", "sqrt"):
            for dm in (0.001, 0.0217, 0.04, 0.05, 0.08, 0.3):
                r = theory.tensile_range(dm, self.k1, self.kp, self.kc, self.phiF, self.a12, interpolation)
                self.assertAlmostEqual(r, self.by_bisection(dm, interpolation), delta=1e-12,
                                       msg=f"{interpolation}, delta_max {dm}")

    def test_bounded_by_the_limit_branch(self):
        # grows with delta_max and saturates at phiF a12 kc/(kp + kc) from delta_max^p = 0.05 on
        bound = theory.max_tensile_range(self.kp, self.kc, self.phiF, self.a12)
        self.assertAlmostEqual(bound, 0.05 * 0.5 * 0.2 / 1.2, delta=1e-15)
        for interpolation in ("linear", "sqrt"):
            r = [theory.tensile_range(0.001 * j, self.k1, self.kp, self.kc, self.phiF, self.a12, interpolation)
                 for j in range(1, 101)]
            self.assertTrue(all(a < b for a, b in zip(r[:49], r[1:50])), interpolation)
            self.assertTrue(all(abs(x - bound) < 1e-15 for x in r[49:]), interpolation)

    def test_bad_input_names_parameter(self):
        for args, name in (((-1.0, 1, 2, 0.2, 0.05, 0.5), "delta_max"), ((0.01, 1, 2, -0.2, 0.05, 0.5), "kc")):
            with self.assertRaisesRegex(ValueError, name):
                theory.tensile_range(*args)
        with self.assertRaisesRegex(ValueError, "phiF"):
            theory.max_tensile_range(1.0, 0.2, 0.0, 0.5)


def force_path_loop(delta, k1, kp, kc, phiF, a12, interpolation="linear"):
    """normal_force_path as a loop over the samples, transcribed from pkg/core/NormalLaw.hpp
    (hystereticForce, setUnloadingLine, deltaMaxThrough) with Python's math."""
    inv = (kp - k1) / (kp * phiF * a12) if kp > k1 else 0.0
    dmp = 1 / inv if inv > 0 else math.inf

    def k2_of(dm):
        x = dm * inv
        return kp if x >= 1 else k1 + (kp - k1) * (math.sqrt(x) if interpolation == "sqrt" else x)

    def line(dm):  # (deltaMax, delta0) of the k2 line of dm
        return dm, (1 - k1 / kp) * dmp if dm * inv >= 1 else (1 - k1 / k2_of(dm)) * dm

    def through(d):
        x, q = d * inv, (k1 + kc) / (kp - k1)
        if interpolation == "linear":
            return dmp * (0.5 * x + math.sqrt(0.25 * x * x + q * x))
        P, Q = -x, -q * x
        D = 0.25 * Q * Q + P * P * P / 27
        if D >= 0:
            r = math.sqrt(D)
            s = math.copysign(abs(-0.5 * Q + r) ** (1 / 3), -0.5 * Q + r) + math.copysign(abs(-0.5 * Q - r) ** (1 / 3),
                                                                                          -0.5 * Q - r)
        else:
            s = 2 * math.sqrt(-P / 3) * math.cos(math.acos(1.5 * Q / P * math.sqrt(-3 / P)) / 3)
        s -= (s * s * s + P * s + Q) / (3 * s * s + P)
        return dmp * s * s

    dm = d0 = 0.0
    out = []
    for d in delta:
        if d <= 0:
            dm = d0 = 0.0
            out.append(0.0)
            continue
        if d > dm:
            dm, d0 = line(d)
        f = k2_of(dm) * (d - d0)
        if f < -kc * d:
            dm, d0 = line(through(d))
            f = -kc * d
        out.append(f)
    return out


class NormalForcePath(unittest.TestCase):
    """theory.normal_force_path (the YADE comparison is yade.normal_path)."""
    law = (100.0, 500.0, 100.0, 0.1, 1e-3)  # k1, kp, kc, phiF, a12: deltaMax^p = 1.25e-4 m

    def test_against_a_loop_on_random_paths(self):
        import numpy as np
        rng = np.random.default_rng(1)
        worst = {"linear": 0.0, "sqrt": 0.0}
        for _ in range(100):
            k1 = 10 ** rng.uniform(1, 3)
            kp, kc, phiF = k1 * (1 + 10 ** rng.uniform(-1, 2)), k1 * rng.choice([0, 0.1, 1, 5]), rng.uniform(0.01, 1)
            dmp = theory.delta_max_p(k1, kp, phiF, 1e-3)
            d = np.clip(np.cumsum(rng.normal(0, 0.05 * dmp, 400)) + rng.uniform(0, dmp), -0.3 * dmp, 3 * dmp)
            for interp in worst:
                got = theory.normal_force_path(d, k1, kp, kc, phiF, 1e-3, interp)
                want = np.array(force_path_loop(d, k1, kp, kc, phiF, 1e-3, interp))
                worst[interp] = max(worst[interp], float(np.max(np.abs(got - want)) / np.max(np.abs(want))))
        self.assertEqual(worst["linear"], 0.0)  # the same operations: the same bits
        self.assertLess(worst["sqrt"], 1e-12)   # numpy's cos/arccos/cbrt against libm's

    def test_branches(self):
        k1, kp, kc, phiF, a12 = self.law
        dmp = theory.delta_max_p(k1, kp, phiF, a12)
        up = [0.2 * dmp, 0.6 * dmp]
        f = theory.normal_force_path(up + [0.5 * dmp, 0.05 * dmp, 0.0, 0.3 * dmp, 2 * dmp, 1.9 * dmp], *self.law)
        k2 = k1 + (kp - k1) * 0.6
        self.assertAlmostEqual(f[0], k1 * 0.2 * dmp, delta=1e-15)           # loading k1 delta
        self.assertAlmostEqual(f[2] - f[1], -k2 * 0.1 * dmp, delta=1e-15)   # unloading along k2
        self.assertEqual(f[3], -kc * 0.05 * dmp)                            # the tensile limit
        self.assertEqual(f[4], 0.0)
        self.assertAlmostEqual(f[5], k1 * 0.3 * dmp, delta=1e-15)           # delta <= 0 ended the contact
        self.assertAlmostEqual(f[6], kp * (2 * dmp - phiF * a12), delta=1e-15)  # the limit branch
        self.assertAlmostEqual(f[6] - f[7], kp * 0.1 * dmp, delta=1e-15)

    def test_reloading_from_the_tensile_branch(self):
        """Down the -kc branch the contact forgets: re-loaded, it follows the k2 line through its
        last tensile point and joins k1 delta at that line's deltaMax, below the first maximum."""
        k1, kp, kc, phiF, a12 = self.law
        dmp = theory.delta_max_p(k1, kp, phiF, a12)
        d = [0.6 * dmp, 0.1 * dmp, 0.2 * dmp, 0.5 * dmp]
        f = theory.normal_force_path(d, *self.law)
        # the quadratic's root
        dm = 0.1 * dmp * 0.5 + math.sqrt((0.1 * dmp) ** 2 / 4 + (k1 + kc) * dmp / (kp - k1) * 0.1 * dmp)
        self.assertTrue(0.2 * dmp < dm < 0.5 * dmp)
        self.assertAlmostEqual(f[3], k1 * 0.5 * dmp, delta=1e-15)  # back on k1 delta before the first maximum 0.6
        k2 = k1 + (kp - k1) * dm / dmp
        self.assertAlmostEqual(f[2], k2 * (0.2 * dmp - (1 - k1 / k2) * dm), delta=1e-15)
        self.assertAlmostEqual(theory.normal_force_path(d[:2], *self.law)[1], -kc * 0.1 * dmp, delta=1e-18)

    def test_largest_pull(self):
        """Unloading slowly from deltaMax, the most tensile force is largest_pull's."""
        import numpy as np
        k1, kp, kc, phiF, a12 = self.law
        dmp = theory.delta_max_p(k1, kp, phiF, a12)
        for dm in (0.3 * dmp, 0.8 * dmp, 1.5 * dmp):
            step = dm / 200000
            d = np.concatenate([np.linspace(0, dm, 50)[1:], np.linspace(dm, 0, 200001)[1:]])
            f = theory.normal_force_path(d, *self.law)
            k2 = kp if dm >= dmp else k1 + (kp - k1) * dm / dmp
            d0 = phiF * a12 if dm >= dmp else (1 - k1 / k2) * dm
            self.assertAlmostEqual(-f.min(), theory.largest_pull(k2, kc, d0), delta=(kp + kc) * step)  # sampled kink

    def test_elastic_and_no_tension(self):
        import numpy as np
        d = np.array([1e-4, 3e-4, 1e-4, 2e-4])
        np.testing.assert_array_equal(theory.normal_force_path(d, 100.0, 100.0, 0.0, 0.1, 1e-3), 100.0 * d)
        f = theory.normal_force_path([1e-4, 1e-6, 5e-5], 100.0, 500.0, 0.0, 0.1, 1e-3)
        self.assertEqual(f[1], 0.0)  # kc = 0: the tensile limit is zero force
        self.assertEqual(len(theory.normal_force_path([], *self.law)), 0)

    def test_bad_input_names_argument(self):
        k1, kp, kc, phiF, a12 = self.law
        for args, kw, name in (((([1e-4, math.nan]), k1, kp, kc, phiF, a12), {}, r"delta\[1\]"),
                               ((([[1e-4]]), k1, kp, kc, phiF, a12), {}, "delta"),
                               ((("ab",), k1, kp, kc, phiF, a12), {}, "delta"),
                               (([1e-4], 0.0, kp, kc, phiF, a12), {}, "k1"),
                               (([1e-4], k1, 50.0, kc, phiF, a12), {}, "kp"),
                               (([1e-4], k1, kp, -1.0, phiF, a12), {}, "kc"),
                               (([1e-4], k1, kp, kc, 1.5, a12), {}, "phiF"),
                               (([1e-4], k1, kp, kc, phiF, -1.0), {}, "a12"),
                               (([1e-4], k1, kp, kc, phiF, a12), {"interpolation": "cubic"}, "interpolation")):
            with self.assertRaisesRegex(ValueError, name):
                theory.normal_force_path(*args, **kw)
