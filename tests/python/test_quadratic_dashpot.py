"""The quadratic dashpot's closed form (`mesocontact.quadratic_dashpot`) against an independent
integration in time of the head-on pair, written here from docs/model.md §3 and §5, below and beyond
the plastic limit; its Lambert W against the definition; its limit gammaN2 -> 0 against the
closed form without viscosity; its refusals."""
import math
import unittest

from mesocontact import quadratic_dashpot as qd, theory

K1, KP, PHIF, A12, M = 1e5, 5e5, 0.1, 1e-3, 1e-3  # v_p = 1.25 m/s


def integrate(v, c, n, kp=KP, sqrt=False):
    """e of the pair by classical Runge-Kutta in time, n steps per pi sqrt(m/k1), phase by phase so
    that every phase is smooth (loading on k1, on the limit branch, unloading on the k2 line to its
    force-free overlap, the dashpot alone to x = 0); each phase ends where its step is cut, by
    bisection, to meet the phase's end. Fourth order then."""
    dt = math.pi * math.sqrt(M / K1) / n
    dmp = kp / (kp - K1) * PHIF * A12 if kp > K1 else math.inf

    def step(x, u, h, acc):
        a1 = acc(x, u)
        a2 = acc(x + 0.5 * h * u, u + 0.5 * h * a1)
        a3 = acc(x + 0.5 * h * (u + 0.5 * h * a1), u + 0.5 * h * a2)
        a4 = acc(x + h * (u + 0.5 * h * a2), u + h * a3)
        return x + h * (u + h / 6 * (a1 + a2 + a3)), u + h / 6 * (a1 + 2 * a2 + 2 * a3 + a4)

    def phase(x, u, acc, ended):
        while True:
            xn, un = step(x, u, dt, acc)
            if not ended(xn, un):
                x, u = xn, un
                continue
            lo, hi = 0.0, dt
            for _ in range(100):
                mid = 0.5 * (lo + hi)
                lo, hi = (lo, mid) if ended(*step(x, u, mid, acc)) else (mid, hi)
            return step(x, u, hi, acc)

    x, u = phase(0.0, v, lambda x, u: -(K1 * x + c * u * u) / M, lambda x, u: u <= 0 or x >= dmp)
    if u > 0:  # on along the limit branch kp (x - phiF a12)
        x, u = phase(x, u, lambda x, u: -(kp * (x - PHIF * A12) + c * u * u) / M, lambda x, u: u <= 0)
    k2 = kp if x >= dmp else K1 + (kp - K1) * (math.sqrt(x / dmp) if sqrt else x / dmp)
    d0 = PHIF * A12 if x >= dmp else (1 - K1 / k2) * x
    x, u = phase(x, 0.0, lambda x, u: -(k2 * (x - d0) - c * u * u) / M, lambda x, u: x <= d0)
    x, u = phase(x, u, lambda x, u: c * u * u / M, lambda x, u: x <= 0)
    return -u / v


def f(y):
    """y e^y - expm1(y) = 1 + (y - 1) e^y, by its power series near 0 (sum (n - 1) y^n/n!)."""
    if abs(y) >= 0.5:
        return 1.0 + (y - 1.0) * math.exp(y)
    total, term = 0.0, y
    for n in range(2, 40):
        term *= y / n
        total += (n - 1) * term
    return total


class LambertW(unittest.TestCase):
    def test_values(self):
        self.assertEqual(qd.w0_plus_one(0.0), 0.0)  # t = 1 + e q = 0: the branch point, W0 = -1
        self.assertEqual(qd.w0_plus_one(1.0), 1.0)  # q = 0
        self.assertAlmostEqual(qd.w0_plus_one(1.0 + math.e * math.e), 2.0, places=15)  # q = e
        self.assertAlmostEqual(qd.w0_plus_one(1.0 + math.e), 1.5671432904097838, places=15)  # the omega constant

    def test_definition(self):
        # y = 1 + W0 solves (y - 1) e^(y - 1) = q, i.e. f(y) = 1 + e q = t: to rounding, in relative terms,
        # on both sides of the series' (1e-4) and the first guess's (0.3) switches
        for t in (1e-300, 1e-14, 1e-9, 1e-6, 9.9e-5, 1.01e-4, 1e-3, 0.29, 0.31, 0.9, 3.0, 30.0, 1e4, 1e12):
            y = qd.w0_plus_one(t)
            self.assertLess(abs(f(y) - t), 4e-16 * t * (1 + y), t)
            self.assertGreater(y, 0.0)

    def test_refuses(self):
        with self.assertRaisesRegex(ValueError, "t = "):
            qd.w0_plus_one(-1e-9)


class Restitution(unittest.TestCase):
    def test_against_integration(self):
        v_p = theory.plastic_limit_velocity(K1, KP, PHIF, A12, M)
        for c in (0.05, 1.0, 10.0):  # a dmp = 2 c dmp/m: 0.013 to 2.5
            for chi in (0.3, 0.9, 2.0, 6.0):
                r = qd.restitution(chi * v_p, K1, KP, PHIF, A12, M, c)
                e1, e2 = integrate(chi * v_p, c, 1000), integrate(chi * v_p, c, 2000)
                # fourth order: e2's own error is about |e1 - e2|/15, below 1e-11 here
                self.assertLess(abs(e1 - e2), 1.5e-10)
                self.assertAlmostEqual(r.e, e2, delta=2e-11, msg=(c, chi))
                self.assertLess(r.e, theory.pair_collision(chi * v_p, K1, KP, 0.0, PHIF, A12, M).e)

    def test_limit_without_damping(self):
        v_p = theory.plastic_limit_velocity(K1, KP, PHIF, A12, M)
        for chi in (0.3, 0.9, 2.0):
            e0 = theory.pair_collision(chi * v_p, K1, KP, 0.0, PHIF, A12, M).e
            # e - e0 is first order in gammaN2: its slope settles, to 1e-5 of itself from 1e-5 to 1e-7 kg/m
            slope = [(qd.restitution(chi * v_p, K1, KP, PHIF, A12, M, c).e - e0) / c for c in (1e-5, 1e-6, 1e-7)]
            self.assertLess(slope[0], 0.0)
            self.assertAlmostEqual(slope[1], slope[0], delta=1e-5 * abs(slope[0]))
            self.assertAlmostEqual(slope[2], slope[1], delta=1e-5 * abs(slope[0]))

    def test_elastic_falls_with_speed(self):
        # kp = k1: no plasticity; the dashpot's share grows with the speed, unlike a linear dashpot's
        speeds = (0.1, 1.0, 10.0)
        es = [qd.restitution(v, K1, K1, PHIF, A12, M, 1.0).e for v in speeds]
        self.assertGreater(es[0], es[1])
        self.assertGreater(es[1], es[2])
        for v, e in zip(speeds, es):
            self.assertAlmostEqual(e, integrate(v, 1.0, 2000, kp=K1), delta=2e-11, msg=v)

    def test_sqrt_interpolation(self):
        # k2(deltaMax) by Eq. D.1: the closed form reads it at deltaMax; the reference with the same rule
        v_p = theory.plastic_limit_velocity(K1, KP, PHIF, A12, M)
        for chi in (0.3, 0.9):
            r = qd.restitution(chi * v_p, K1, KP, PHIF, A12, M, 1.0, interpolation="sqrt")
            self.assertAlmostEqual(r.e, integrate(chi * v_p, 1.0, 2000, sqrt=True), delta=2e-11, msg=chi)
            self.assertNotAlmostEqual(r.e, qd.restitution(chi * v_p, K1, KP, PHIF, A12, M, 1.0).e, delta=1e-3)

    def test_refuses(self):
        for kw, name in ((dict(gammaN2=0.0), "gammaN2"), (dict(gammaN2=-1.0), "gammaN2"),
                         (dict(gammaN2=1e-160), "gammaN2"), (dict(gammaN2=1e-300), "gammaN2"), (dict(v_i=0.0), "v_i"),
                         (dict(m_r=0.0), "m_r"), (dict(interpolation="cubic"), "interpolation")):
            args = dict(v_i=1.0, k1=K1, kp=KP, phiF=PHIF, a12=A12, m_r=M, gammaN2=1.0)
            args.update(kw)
            with self.assertRaisesRegex(ValueError, name):
                qd.restitution(**args)


if __name__ == "__main__":
    unittest.main()
