"""mesostudies.agglomerate.loss against loops whose areas are known by hand: a loading and
unloading on one line loses nothing; Luding's triangle (k1 up to delta_max, k2 back to zero force)
loses k1 dm^2/2 - k2 (dm - d0)^2/2 = (k1/2) dm^2 (1 - k1/k2) exactly, as the trapezoids are exact
on straight lines; a tensile branch's work is its triangle; a dashpot gamma at speed v adds gamma v
per unit of path, which viscous_gamma gives back."""
import unittest

from mesostudies.agglomerate import loss


def line(d_from, d_to, force, n=200):
    return [(d_from + (d_to - d_from) * k / n, force(d_from + (d_to - d_from) * k / n)) for k in range(n + 1)]


def run(strokes):
    """rows (iter, delta, F) and events from strokes [(what, [(delta, F), ...])]: each event at a stroke's end;
    every stroke's points kept (a jump of the force at a turn is a vertical side, of no area)."""
    rows, events, it = [], [], 0
    for what, pts in strokes:
        for d, f in pts:
            rows.append((it, d, f))
            it += 1
        events.append((what, rows[-1][0], rows[-1][1], rows[-1][2]))
    return rows, events


class Loops(unittest.TestCase):
    def test_elastic_line_loses_nothing(self):
        k, a = 3.0, 0.1
        rows, ev = run([("touch", [(0.0, 0.0)]), ("loaded to 0.1 d0", line(0, a, lambda d: k * d)),
                        ("unloaded", line(a, 0, lambda d: k * d))])
        (c,) = loss.loops(rows, ev)
        self.assertAlmostEqual(c["w_in"], 0.5 * k * a * a, places=12)
        self.assertAlmostEqual(c["loss"], 0.0, places=15)
        self.assertEqual(c["tension_work"], 0.0)

    def test_triangle_and_tension(self):
        k1, k2, dm = 2.0, 5.0, 0.2
        d0 = dm * (1 - k1 / k2)          # where the unloading reaches zero force
        kc = 1.5
        rows, ev = run([("touch", [(0.0, 0.0)]), ("loaded to 0.2 d0", line(0, dm, lambda d: k1 * d)),
                        ("unloaded", line(dm, d0, lambda d: k2 * (d - d0))
                         + line(d0, d0 - 0.05, lambda d: -kc * (d0 - d))[1:]),
                        ("apart", line(d0 - 0.05, d0 - 0.05, lambda d: 0.0, n=1))])
        (c,) = loss.loops(rows, ev)
        tension = 0.5 * kc * 0.05 ** 2
        self.assertAlmostEqual(c["loss"], 0.5 * k1 * dm * dm - 0.5 * k2 * (dm - d0) ** 2 + tension, places=12)
        self.assertAlmostEqual(c["tension_work"], tension, places=12)
        p = loss.pull(rows, ev)
        self.assertAlmostEqual(p["largest_tension"], kc * 0.05, places=12)
        self.assertAlmostEqual(p["range_d0"], -(d0 - 0.05) / loss.D0, places=9)
        self.assertEqual(p["ended"], "apart")

    def test_viscous_gamma(self):
        k, a, gamma = 3.0, 0.1, 0.7

        def runs(v):
            return run([("touch", [(0.0, 0.0)]), ("loaded to 0.1 d0", line(0, a, lambda d: k * d + gamma * v)),
                        ("unloaded", line(a, 0, lambda d: k * d - gamma * v))])
        slow, fast = (loss.loops(*runs(v)) for v in (0.5, 2.0))
        self.assertAlmostEqual(loss.viscous_gamma(slow, fast, 0.5, 2.0)[0], gamma, places=9)
        # a fast loop whose loading takes no work (the caps' inertia) gives no gammaN
        rows, ev = run([("touch", [(0.0, 0.0)]), ("loaded to 0.1 d0", line(0, a, lambda d: -1.0)),
                        ("unloaded", line(a, 0, lambda d: k * d))])
        self.assertEqual(loss.viscous_gamma(slow, loss.loops(rows, ev), 0.5, 2.0), [None])

    def test_dissipated(self):
        # Two loops; O.energy's terms at each turn written by hand: each loop's change per term
        # (from the turn before its loading to the unloading after it), the terms' sum over the
        # dissipating ones only, and a term that appears only later counted from zero.
        ev = [("touch", 10, 0.0, 0.0), ("loaded to 0.1 d0", 20, 0.1, 1.0), ("unloaded", 30, -0.2, 0.0),
              ("loaded to 0.2 d0", 40, 0.2, 2.0), ("unloaded", 50, -0.2, 0.0)]
        en = [{"mesoPlastic": 0.0, "mesoElastic": 0.0}, {"mesoPlastic": 1.0, "mesoElastic": 5.0},
              {"mesoPlastic": 1.5, "mesoElastic": 0.5, "mesoSliding": 0.25},
              {"mesoPlastic": 2.0, "mesoElastic": 9.0, "mesoSliding": 0.5},
              {"mesoPlastic": 4.0, "mesoElastic": 1.0, "mesoSliding": 1.25, "mesoViscous": 0.125}]
        a, b = loss.dissipated(ev, en)
        self.assertEqual((a["amplitude"], b["amplitude"]), (0.1, 0.2))
        self.assertEqual((a["mesoPlastic"], a["mesoSliding"], a["mesoElastic"], a["total"]), (1.5, 0.25, 0.5, 1.75))
        self.assertEqual((b["mesoPlastic"], b["mesoSliding"], b["mesoViscous"], b["mesoElastic"], b["total"]),
                         (2.5, 1.0, 0.125, 0.5, 3.625))

    def test_viscous_gamma_dissipated(self):
        # The contacts' extra dissipation over the slow run's path and the relative speeds' difference,
        # by hand; the drag (not among the contacts' terms) is left out; a fast loop whose loading took
        # no work by the caps' reading gives None; a loop of another amplitude is skipped.
        slow_l = [{"amplitude": 0.1, "path": 0.5, "w_in": 1.0}, {"amplitude": 0.2, "path": 2.0, "w_in": 1.0}]
        fast_l = [{"amplitude": 0.1, "path": 9.0, "w_in": -1.0}, {"amplitude": 0.2, "path": 9.0, "w_in": 1.0}]
        slow_d = [{"total": 1.0}, {"total": 3.0, "mesoBackground": 1.0}]
        fast_d = [{"total": 5.0}, {"total": 7.0, "mesoBackground": 4.0}]
        self.assertEqual(loss.viscous_gamma_dissipated(slow_l, slow_d, fast_l, fast_d, 1.0, 3.0), [None, 1.0])
        other = [{"amplitude": 0.3, "path": 9.0, "w_in": 1.0}]
        self.assertEqual(loss.viscous_gamma_dissipated(slow_l[:1], slow_d[:1], other, fast_d[:1], 1.0, 3.0), [])

    def test_extra_loss_points(self):
        # The same loops: (v_slow, v_fast, extra loss over the slow path, amplitude), None where loading took no work.
        slow_l = [{"amplitude": 0.1, "path": 0.5, "w_in": 1.0}, {"amplitude": 0.2, "path": 2.0, "w_in": 1.0}]
        fast_l = [{"amplitude": 0.1, "path": 9.0, "w_in": -1.0}, {"amplitude": 0.2, "path": 9.0, "w_in": 1.0}]
        slow_d, fast_d = [{"total": 1.0}, {"total": 3.0}], [{"total": 5.0}, {"total": 7.0}]
        self.assertEqual(loss.extra_loss_points(slow_l, slow_d, fast_l, fast_d, 1.0, 3.0), [None, (1.0, 3.0, 2.0, 0.2)])

    def test_rate_dashpots(self):
        # Points made from gammaN = 2, gammaN2 = 0.5 exactly: y = 2 (v - 1) + 0.5 (v^2 - 1) at v = 2, 3, 5
        # (6.5/2 ... by hand: 3.5, 8, 20) give both back and zero residuals; None is skipped.
        pts = [(1.0, 2.0, 3.5), None, (1.0, 3.0, 8.0), (1.0, 5.0, 20.0)]
        g1, g2, res = loss.rate_dashpots(pts)
        self.assertAlmostEqual(g1, 2.0, places=12)
        self.assertAlmostEqual(g2, 0.5, places=12)
        self.assertTrue(all(abs(r) < 1e-12 for r in res))
        # Points that would need a negative gammaN (y = v^2 - 1 - 0.5 (v - 1)): the bound, gammaN = 0, and the
        # least squares of gammaN2 alone: sum (v^2-1) y / sum (v^2-1)^2 with v^2 - 1 = 3, 8, 24 and y = 2.5, 7, 21
        pts = [(1.0, 2.0, 2.5), (1.0, 3.0, 7.0), (1.0, 5.0, 21.0)]
        g1, g2, _ = loss.rate_dashpots(pts)
        self.assertEqual(g1, 0.0)
        self.assertAlmostEqual(g2, (3 * 2.5 + 8 * 7 + 24 * 21) / (9 + 64 + 576), places=12)
        # relative=True: each point's columns and y over |y| (y' = 1), the 2x2 normal equations solved by hand
        # for y = 3.6, 8, 20 (dv = 1, 2, 4; d(v^2) = 3, 8, 24); the residuals are y - fit, unweighted
        pts = [(1.0, 2.0, 3.6), (1.0, 3.0, 8.0), (1.0, 5.0, 20.0)]
        a = [1 / 3.6, 2 / 8, 4 / 20]
        b = [3 / 3.6, 8 / 8, 24 / 20]
        saa, sbb, sab = sum(x * x for x in a), sum(x * x for x in b), sum(x * y for x, y in zip(a, b))
        det = saa * sbb - sab * sab
        g1, g2, res = loss.rate_dashpots(pts, relative=True)
        self.assertAlmostEqual(g1, (sum(a) * sbb - sum(b) * sab) / det, places=12)
        self.assertAlmostEqual(g2, (saa * sum(b) - sab * sum(a)) / det, places=12)
        self.assertAlmostEqual(res[0], 3.6 - g1 * 1 - g2 * 3, places=12)
        self.assertNotAlmostEqual(g1, loss.rate_dashpots(pts)[0], places=3)   # the weights matter here
        with self.assertRaisesRegex(ValueError, "y = 0"):
            loss.rate_dashpots([(1.0, 2.0, 0.0), (1.0, 3.0, 8.0)], relative=True)
        # One pair of speeds, however many points, fixes only gammaN dv + gammaN2 d(v^2): refused
        for pts in ([(1.0, 2.0, 3.5), None], [(1.25, 80.0, 0.25), (1.25, 80.0, 0.43)]):
            with self.assertRaisesRegex(ValueError, "two pairs"):
                loss.rate_dashpots(pts)

    def test_caps_work(self):
        # A constant F = 2 over a loading of 10 steps and an unloading of 10 steps, caps at speed 0.5
        # each, dt 0.1: the caps approach by 2 x 0.5 x 0.1 x 10 = 1 and part by as much, so the loop's
        # work is 2 x 1 - 2 x 1 = 0 whatever delta does. With F = 3 on the way in (rows 0-9) the loading
        # takes 0.1 x (9 x 3 + 2.5) = 2.95 (the last interval's trapezoid is (3 + 2)/2): the loop 0.95.
        ev = [("touch", 0, 0.0, 0.0), ("loaded to 0.1 d0", 10, 0.0, 0.0), ("unloaded", 20, 0.0, 0.0)]
        rows = [(i, 0.3 * (i % 3), 2.0) for i in range(21)]   # delta wanders: it must not enter
        self.assertAlmostEqual(loss.caps_work(rows, ev, 0.5, 0.1)[0], 0.0, places=12)
        rows = [(i, 0.0, 3.0 if i < 10 else 2.0) for i in range(21)]
        self.assertAlmostEqual(loss.caps_work(rows, ev, 0.5, 0.1)[0], 0.95, places=12)


if __name__ == "__main__":
    unittest.main()
