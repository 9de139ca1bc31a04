"""theory.contact_duration against an independent integration of the law, and
params.material_from: parameters from a restitution, a contact time and the other measurable
quantities, recovered exactly from the closed form of known materials."""
import math
import unittest

from mesocontact import params, theory

R, RHO = 1.1e-3, 2000.0
M_R = params.sphere_mass(R, RHO) / 2
A12 = R


def integrated_duration(v_inf, k1, kp, kc, phiF, a12, m_r, fa, kca, adhesion, steps=50000):
    """Velocity Verlet on the normal law as the model states it (loading k1 up to the limit
    branch kp (delta - phiF a12), un-/re-loading k2 through (deltaMax, f(deltaMax)), the tensile
    limit -kc delta, a constant -fa in contact), started at first touch; the time to delta = 0."""
    v = theory.pair_collision(v_inf, k1, kp, kc, phiF, a12, m_r, fa, kca, adhesion).v_contact
    fa = fa if adhesion != "none" else 0.0
    dmp = kp / (kp - k1) * phiF * a12

    def force(d, dmax):
        upper = k1 * d if d < dmp else kp * (d - phiF * a12)
        if d >= dmax:
            return upper
        k2 = k1 + (kp - k1) * min(dmax / dmp, 1.0)
        fmax = k1 * dmax if dmax < dmp else kp * (dmax - phiF * a12)
        return max(k2 * (d - dmax) + fmax, -kc * d)

    dt = 4 * math.pi * math.sqrt(m_r / k1) / steps
    d, dmax, t = 0.0, 0.0, 0.0
    a = (fa - force(d, dmax)) / m_r
    while t < 100 * steps * dt:
        v += 0.5 * dt * a
        d += dt * v
        dmax = max(dmax, d)
        a = (fa - force(d, dmax)) / m_r
        v += 0.5 * dt * a
        t += dt
        if d <= 0:
            return t, dt
    return math.inf, dt


class ContactDuration(unittest.TestCase):
    def test_against_integration(self):
        # below and beyond the plastic limit, with and without the tensile branch and fa
        for v in (0.05, 0.5, 5.0):
            for kc in (0.0, 100.0):
                for fa, mode in ((0.0, "none"), (1e-5, "jumpIn"), (1e-5, "reversible")):
                    with self.subTest(v=v, kc=kc, adhesion=mode):
                        t = theory.contact_duration(v, 100.0, 500.0, kc, 0.1, A12, M_R, fa, 100.0, mode)
                        ref, dt = integrated_duration(v, 100.0, 500.0, kc, 0.1, A12, M_R, fa, 100.0, mode)
                        if math.isinf(ref):  # held in contact (kc = 100 sticks at 0.5 m/s)
                            self.assertEqual(t, math.inf)
                            continue
                        # the event lies within one step of the integration; its error is O(dt^2)
                        self.assertLess(abs(t - ref), 2 * dt, f"{t} vs {ref}")

    def test_elastic_half_period(self):
        # kp -> k1 (no plasticity), no adhesion: pi sqrt(m_r/k1) exactly
        t = theory.contact_duration(0.1, 100.0, 100.0 * (1 + 1e-12), 0.0, 0.1, A12, M_R)
        self.assertAlmostEqual(t / (math.pi * math.sqrt(M_R / 100.0)), 1.0, places=9)

    def test_sticking_is_infinite(self):
        # eta = 4, beta = kc/k1 = 5 sticks at chi = 1 (Eq. 39's condition beta eta^2 >= 1 + eta + beta)
        v = theory.impact_velocity_for_chi(1.0, 100.0, 500.0, 0.1, A12, M_R)
        self.assertEqual(theory.contact_duration(v, 100.0, 500.0, 500.0, 0.1, A12, M_R), math.inf)


class MaterialFrom(unittest.TestCase):
    TRUE = dict(k1=100.0, kp=500.0, kc=100.0, phiF=0.1, fa=2e-4, kca=100.0)

    def measured(self, v, adhesion="jumpIn", radius2=R, **law):
        p = dict(self.TRUE, **law)
        m_r = params.reduced_mass(params.sphere_mass(R, RHO),
                                  math.inf if math.isinf(radius2) else params.sphere_mass(radius2, RHO))
        a12 = params.reduced_radius(R, radius2)
        args = (v, p["k1"], p["kp"], p["kc"], p["phiF"], a12, m_r, p["fa"], p["kca"], adhesion)
        return theory.pair_collision(*args), theory.contact_duration(*args), a12

    def test_round_trip(self):
        for v, adhesion, radius2 in ((0.05, "jumpIn", R), (0.8, "jumpIn", R), (2.0, "reversible", R),
                                     (0.05, "jumpIn", math.inf)):
            with self.subTest(v=v, adhesion=adhesion, radius2=radius2):
                o, t, a12 = self.measured(v, adhesion, radius2)
                pull_off = 500.0 * 100.0 / 600.0 * 0.1 * a12  # kp kc/(kp + kc) phiF a12
                for kc_kw in (dict(kc_over_kp=0.2), dict(pull_off_force=pull_off)):
                    got = params.material_from(R, RHO, v, o.e, t, plastic_overlap=0.1 * a12, fa=2e-4, kca=100.0,
                                               adhesion=adhesion, radius2=radius2, limit=o.plastic_limit, **kc_kw)
                    for k in ("k1", "kp", "kc"):
                        self.assertAlmostEqual(got[k] / self.TRUE[k], 1.0, places=9, msg=f"{k} from {kc_kw}")
                    self.assertEqual(got["adhesion"], adhesion)

    def test_two_materials_named(self):
        # beyond the plastic limit one e and one contact time also fit a material that stays below it
        o, t, a12 = self.measured(0.8)
        self.assertTrue(o.plastic_limit)
        with self.assertRaisesRegex(ValueError,
                                    r"2 materials reproduce.*beyond the plastic limit.*below the "
                                    r"plastic limit.*limit=True"):
            params.material_from(R, RHO, 0.8, o.e, t, phiF=0.1, kc_over_kp=0.2, fa=2e-4, kca=100.0)
        other = params.material_from(R, RHO, 0.8, o.e, t, phiF=0.1, kc_over_kp=0.2, fa=2e-4, kca=100.0, limit=False)
        self.assertGreater(other["k1"], 120.0)  # the other fit: a stiffer k1, a softer kp
        args = (0.8, other["k1"], other["kp"], other["kc"], 0.1, a12, M_R, 2e-4, 100.0, "jumpIn")
        self.assertAlmostEqual(theory.pair_collision(*args).e, o.e, places=9)
        self.assertAlmostEqual(theory.contact_duration(*args) / t, 1.0, places=9)

    def test_report_says_what_kp_costs(self):
        m = params.material_from(radius=0.5e-3, density=2000, impact_speed=0.2, restitution=0.5, contact_time=1e-5,
                                 phiF=0.1)
        mass = 2000 * 4 / 3 * math.pi * 0.5e-3 ** 3  # equal spheres: m_r = m/2
        dt = 2 * math.sqrt(0.5 * mass / m["kp"])
        self.assertAlmostEqual(m.stable_step / dt, 1.0, places=12)
        self.assertIn(f"kp/k1 = {m['kp'] / m['k1']:.3g}", m.report)
        self.assertIn(f"{dt:.3g} s", m.report)
        self.assertEqual(set(m),
                         {"k1", "kp", "kc", "phiF", "fa", "kca", "adhesion", "k2Interpolation", "gammaN", "density"})

    def test_bad_input_named(self):
        o, t, _ = self.measured(0.05)
        base = dict(radius=R, density=RHO, impact_speed=0.05, restitution=o.e, contact_time=t, phiF=0.1)
        for key, value, pattern in (("restitution", 1.0, "restitution"), ("restitution", 0.0, "restitution"),
                                    ("contact_time", -1.0, "contact_time"), ("density", float("nan"), "density"),
                                    ("phiF", 2.0, "phiF"), ("pull_off_force", -1.0, "pull_off_force"),
                                    ("limit", "yes", "limit"), ("adhesion", "glue", "adhesion")):
            with self.subTest(key=key):
                with self.assertRaisesRegex(ValueError, pattern):
                    params.material_from(**dict(base, **{key: value}))
        with self.assertRaisesRegex(ValueError, "phiF, plastic_overlap"):
            params.material_from(**dict(base, plastic_overlap=1e-5))
        # a contact far too short for e = 0.5 at 0.2 m/s: the message gives the e those materials reach and what to
        # relax
        with self.assertRaisesRegex(ValueError,
                                    r"give e in \[0\.\d+, 1\] at this speed .*relax restitution or contact_time"):
            params.material_from(radius=0.5e-3, density=2000, impact_speed=0.2, restitution=0.5, contact_time=1e-7,
                                 phiF=0.1)
        # what MesoMat refuses (fa without a mode) is refused here too, before the fit
        with self.assertRaisesRegex(ValueError, "^adhesion = 'none' is invalid with fa > 0"):
            params.material_from(**dict(base, fa=1e-6, adhesion="none"))
        # a contact far too short for any k1 and kp with this e
        with self.assertRaisesRegex(ValueError, "contact_time"):
            params.material_from(**dict(base, contact_time=t * 1e-9))


if __name__ == "__main__":
    unittest.main()
