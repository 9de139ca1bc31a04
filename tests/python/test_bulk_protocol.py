"""The bulk sample's protocol (mesocontact.bulk.protocol, pure Python): Appendix F's parameter set
as the paper states it (d0 p_s/kp = 0.02, p_r/p_s = 1e-3, kc/kp = 0.2), stresses given as ratios
or in Pa giving the same protocol, the JSON that travels with the scene giving it back exactly,
and every bad argument refused with its name before any work."""
import math
import unittest

from mesocontact.bulk import protocol as P

# A user's own material in SI units (m, kg, s): 100 um particles of 2500 kg/m^3.
USER = dict(density=2500.0, k1=50.0, kp=250.0, kc=25.0, phiF=0.05, gammaN=1e-6, frictionAngle=0.5,
            kt=50.0, gammaT=2e-7, kr=25.0, gammaR=0.0, muR=0.1, ko=25.0, gammaO=0.0, muO=0.1)


class AppendixF(unittest.TestCase):
    def test_paper_values(self):
        p = P.appendix_f()
        # Written out from the paper (mm, us, mg): d0 = 0.01, kp = 5, d0 p_s/kp = 0.02 -> p_s = 10
        # (1e10 Pa); p_r = 1e-3 p_s; kc/kp = 0.2; mu_r = mu_o = 0.2; gamma_r = gamma_o = 0.1 gamma0.
        self.assertEqual((p.d0, p.kp), (0.01, 5.0))
        self.assertAlmostEqual(p.sinter_stress, 10.0, places=12)
        self.assertAlmostEqual(p.release_stress / p.sinter_stress, 1e-3, places=15)
        self.assertAlmostEqual(p.sintering_ratio(), 0.02, places=15)
        self.assertAlmostEqual(p.material["kc"] / p.kp, 0.2, places=15)
        self.assertEqual((p.material["muR"], p.material["muO"]), (0.2, 0.2))
        self.assertAlmostEqual(p.material["gammaR"] / p.material["gammaN"], 0.1, places=15)
        self.assertAlmostEqual(P.TABLE2["kc"] / P.TABLE2["kp"], 0.5, places=15)
        self.assertEqual(p.speeds(), (2.0, 0.05))

    def test_sinter_override_keeps_the_other_stresses(self):
        p = P.appendix_f(sinter_stress=30.0)
        self.assertEqual(p.sinter_stress, 30.0)
        self.assertEqual((p.release_stress, p.energy_stress), (P.appendix_f().release_stress, 10.0))


class Units(unittest.TestCase):
    def test_ratios_and_pascal_agree(self):
        d0 = 1e-4
        a = P.Protocol.ratios(USER, d0, sinter=0.02, release=1e-3)
        p_s = 0.02 * 250.0 / d0  # 5e4 Pa
        b = P.Protocol.pascal(USER, d0, sinter_pa=p_s, release_pa=1e-3 * p_s)
        self.assertAlmostEqual(a.sinter_stress / p_s, 1.0, places=14)
        self.assertAlmostEqual(b.release_stress / a.release_stress, 1.0, places=14)
        # mm, us, mg: a stress unit is 1e9 Pa
        c = P.Protocol.pascal(P.APPENDIX_F, 0.01, sinter_pa=1e10, pa_per_unit=1e9)
        self.assertAlmostEqual(c.sinter_stress, P.appendix_f().sinter_stress, places=12)

    def test_default_speeds_follow_the_wave_speed(self):
        p = P.Protocol.ratios(USER, 1e-4)
        m = 2500.0 * math.pi * 1e-12 / 6
        c = 1e-4 * math.sqrt(250.0 / m)
        self.assertAlmostEqual(p.speeds()[0] / (0.1 * c), 1.0, places=14)
        self.assertAlmostEqual(p.speeds()[1] / (c / 400), 1.0, places=14)

    def test_json_round_trip_is_exact(self):
        for p in (P.appendix_f(aspect=(2, 1, 1)), P.Protocol.ratios(USER, 1e-4, sinter=0.013, n=500, seed=7)):
            self.assertEqual(P.Protocol.from_json(p.to_json()), p)


class Refusals(unittest.TestCase):
    def refused(self, prefix, **kw):
        args = dict(material=USER, d0=1e-4, sinter_stress=5e4, release_stress=50.0)
        args.update(kw)
        with self.assertRaises((ValueError, TypeError)) as cm:
            P.Protocol(**args)
        self.assertTrue(str(cm.exception).startswith(prefix), f"{prefix!r} does not start {str(cm.exception)!r}")

    def test_each_argument_named(self):
        cases = [("d0 = ", dict(d0=0.0)), ("d0 = ", dict(d0=math.nan)), ("sinter_stress = ", dict(sinter_stress=-1.0)),
                 ("release_stress = ", dict(release_stress=1e5)), ("release_stress = ", dict(release_stress=math.inf)),
                 ("n = ", dict(n=3)), ("n = ", dict(n=10.5)), ("n = ", dict(n=True)), ("rel_std = ", dict(rel_std=0.5)),
                 ("gas_fraction = ", dict(gas_fraction=0.6)), ("aspect = ", dict(aspect=(1, 1))),
                 ("aspect = ", dict(aspect=(1, 1, 100))), ("packing = ", dict(packing="loose")),
                 ("glue = ", dict(glue="none")), ("release_steps = ", dict(release_steps=0)),
                 ("release_steps = ", dict(release_steps=1500)), ("drag = ", dict(drag=(4.0,))),
                 ("drag = ", dict(drag=(-1.0, 1.0))), ("wall_kc_over_kp = ", dict(wall_kc_over_kp=-1.0)),
                 ("wall_mu = ", dict(wall_mu=math.nan)), ("compaction_speed = ", dict(compaction_speed=0.0)),
                 ("packing_stress = ", dict(packing_stress=-2.0)), ("packing_stress = ", dict(packing_stress=5e4)),
                 ("hold_speed = ", dict(hold_speed=math.inf)), ("tol_ke = ", dict(tol_ke=0.0)),
                 ("seed = ", dict(seed=1.5)), ("name = ", dict(name=3)), ("material = ", dict(material=[1, 2])),
                 ("material['kp'] = ", dict(material=dict(USER, kp=0.0))),
                 ("material['density'] = ", dict(material=dict(USER, density=-1.0))),
                 ("material['kc'] = ", dict(material=dict(USER, kc="a"))),
                 ("material = ", dict(material=dict(USER, label=object()))),
                 ("material is invalid: it lacks 'gammaN'",
                  dict(material={k: v for k, v in USER.items() if k != "gammaN"})),
                 ("material['gammaN'] = ", dict(material=dict(USER, gammaN=0.0))),
                 ("distribution = ", dict(distribution="weibull")), ("mixture = ", dict(mixture="glass")),
                 ("mixture[0] is invalid: its number fraction", dict(mixture=((1.5, USER),))),
                 ("mixture[0] is invalid: its material", dict(mixture=((0.5, "glass"),))),
                 ("mixture[0]['kp'] = ", dict(mixture=((0.5, dict(USER, kp=-1.0)),))),
                 ("mixture[1]['gammaN'] = ", dict(mixture=((0.2, USER), (0.2, dict(USER, gammaN=0.0))))),
                 ("mixture is invalid: its fractions add up", dict(mixture=((0.5, USER), (0.5, USER)))),
                 ("mixture is invalid: with n = 8 a kind gets no sphere",
                  dict(n=8, mixture=((0.45, USER), (0.45, USER), (0.09, USER))))]
        for prefix, kw in cases:
            with self.subTest(prefix=prefix, kw=kw):
                self.refused(prefix, **kw)

    def test_mixture_counts_add_up(self):
        # the fractions of n, the largest remainders taking the rest: of 10, 0.4 -> 4, 0.35 -> 3.5, 0.25 -> 2.5;
        # one sphere is left, for the first of the two equal remainders
        p = P.appendix_f(n=10, mixture=((0.35, USER), (0.25, USER)))
        self.assertEqual(p.kind_counts(), [4, 4, 2])
        p = P.appendix_f(n=64, mixture=((0.25, USER),))
        self.assertEqual(p.kind_counts(), [48, 16])

    def test_conversions_named(self):
        for prefix, call in (("sinter = ", lambda: P.Protocol.ratios(USER, 1e-4, sinter=0.0)),
                             ("release = ", lambda: P.Protocol.ratios(USER, 1e-4, release=math.nan)),
                             ("d0 = ", lambda: P.Protocol.ratios(USER, -1.0)),
                             ("sinter_pa = ", lambda: P.Protocol.pascal(USER, 1e-4, sinter_pa=-5.0)),
                             ("pa_per_unit = ", lambda: P.Protocol.pascal(USER, 1e-4, 5e4, pa_per_unit=0.0))):
            with self.subTest(prefix=prefix):
                with self.assertRaises((ValueError, TypeError)) as cm:
                    call()
                self.assertTrue(str(cm.exception).startswith(prefix), str(cm.exception))

    def test_a_value_not_a_view(self):
        mat = dict(USER)
        p = P.Protocol.ratios(mat, 1e-4, aspect=[2, 1, 1])
        mat["kp"] = 1.0
        self.assertEqual((p.material["kp"], p.aspect), (250.0, (2, 1, 1)))
        self.assertEqual(P.Protocol.from_json(p.to_json()), p)


class StudiesBitwise(unittest.TestCase):
    """The protocols the studies pass give the very floats the studies computed before the library
    (the expressions of studies/mesostudies/tablet/sample.py before issue #58, written out)."""

    KP, GAMMA0, D0, SINTER = 5.0, 5e-5, 0.01, 0.02
    OLD_APPENDIX_F = dict(density=2.0, k1=0.5 * KP, kp=KP, kc=0.2 * KP, phiF=0.05, gammaN=GAMMA0,
                          frictionAngle=math.atan(1.0), kt=0.2 * KP, gammaT=0.2 * GAMMA0, kr=0.1 * KP,
                          gammaR=0.1 * GAMMA0, muR=0.2, ko=0.1 * KP, gammaO=0.1 * GAMMA0, muO=0.2)

    def check_paper_scales(self, p):
        sinter_stress = self.SINTER * self.KP / self.D0
        self.assertEqual(p.release_stress, 1e-3 * sinter_stress)
        self.assertEqual(p.packing_stress, 0.1 * sinter_stress)
        self.assertEqual(p.reference_stress, sinter_stress)
        self.assertEqual((p.d0, p.kp, p.speeds(), p.holding_speed()), (0.01, 5.0, (2.0, 0.05), 0.01))
        g = p.material["gammaN"]
        self.assertEqual((p.drag[0] * g, p.drag[1] * g), (4 * self.GAMMA0, self.GAMMA0))
        self.assertEqual((p.wall_kc_over_kp * p.kp, math.atan(p.wall_mu)), (20 * self.KP, math.atan(10.0)))

    def test_tablet(self):
        p = P.appendix_f()
        self.assertEqual(p.material, self.OLD_APPENDIX_F)
        self.assertEqual(p.sinter_stress, self.SINTER * self.KP / self.D0)
        self.check_paper_scales(p)
        deep = P.appendix_f(sinter_stress=0.1 * self.KP / self.D0)  # a deep sample: only p_s changes
        self.assertEqual(deep.sinter_stress, 0.1 * self.KP / self.D0)
        self.check_paper_scales(deep)

    def test_agglomerate(self):
        from mesostudies.agglomerate import primaries
        p = primaries.protocol(1000, 3, (2, 1, 1))
        self.assertEqual(p.material, self.OLD_APPENDIX_F)
        self.check_paper_scales(p)
        self.assertEqual((p.n, p.seed, p.aspect, p.packing, p.glue, p.rel_std),
                         (1000, 3, (2, 1, 1), "frictionless", "sinter", 0.1))


if __name__ == "__main__":
    unittest.main()
