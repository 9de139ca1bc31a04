"""mesostudies.agglomerate.tension on two unloadings whose tension is known by hand, one after the
other on one pair (delta_touch = 1, d0 = 1):

1. pressed 0.125 along k1, back along a k2 line to zero force, then held at -c1 to 0.125 beyond the
   touch: its misfit against a law with no force beyond the touch is measured against the run's
   largest force (the second press's), not its own;
2. from there, pressed 0.25 along k1 (no force until the faces meet again), back along k2 to zero
   force, then a tension -c + s (delta - 1) to 0.25 beyond the touch, then a force ringing about
   zero.

The work held beyond the touch is the integral of the tension there (the numbers are binary
fractions and the pieces straight, so the trapezoids and the cut at the touch, interpolated on the
sloped piece, are exact), the ringing adding nothing; the plateau is the tension's mean over the band;
a law equal to the data carries it all."""
import math
import unittest

from mesostudies.agglomerate import tension


def line(d_from, d_to, force, n=256):
    return [(d_from + (d_to - d_from) * k / n, force(d_from + (d_to - d_from) * k / n)) for k in range(n + 1)]


class Unloadings(unittest.TestCase):
    def setUp(self):
        t, k1, k2 = 1.0, 2.0, 8.0
        self.c1, self.c, self.s = 0.03125, 0.0625, 0.125
        dm1, dm = t + 0.125, t + 0.25
        dz1, dz = dm1 - k1 * (dm1 - t) / k2, dm - k1 * (dm - t) / k2
        self.end = t - 0.25
        ring = [(self.end - 0.25 * k / 256, 0.01 * math.sin(math.pi * k / 32)) for k in range(257)]  # 4 periods
        strokes = [("touch", [(t, 0.0)]),
                   ("loaded to 0.125 d0", line(t, dm1, lambda d: k1 * (d - t))),
                   ("unloaded", line(dm1, dz1, lambda d: k2 * (d - dz1)) + line(dz1, t - 0.125, lambda d: -self.c1)),
                   ("loaded to 0.25 d0", line(t - 0.125, t, lambda d: 0.0) + line(t, dm, lambda d: k1 * (d - t))),
                   ("unloaded", line(dm, dz, lambda d: k2 * (d - dz))
                    + line(dz, self.end, lambda d: -self.c + self.s * (d - t)) + [(self.end, 0.0)] + ring)]
        self.rows, self.events, it = [], [], 0
        for what, pts in strokes:
            for d, f in pts:
                self.rows.append((it, d, f))
                it += 1
            self.events.append((what, self.rows[-1][0], self.rows[-1][1], self.rows[-1][2]))
        self.peak, self.step = k1 * (dm - t), (dz - self.end) / 256

    def test_held_beyond_the_touch(self):
        first, second = tension.unloadings(self.rows, self.events, d0=1.0, band=(-0.2, -0.05))
        self.assertAlmostEqual(first["held_beyond"], self.c1 * 0.125, places=12)
        self.assertAlmostEqual(first["plateau"], -self.c1, places=15)
        # beyond the touch the tension is c - s (delta - 1) over 0.25: c 0.25 + s 0.25^2/2
        self.assertAlmostEqual(second["held_beyond"], self.c * 0.25 + self.s * 0.25 ** 2 / 2, places=12)
        self.assertAlmostEqual(second["press_work"], 0.5 * self.peak * 0.25, places=12)
        # the band's mean of -c + s (delta - 1): -c - s 0.125, to a grid step of the band's ends
        self.assertLess(abs(second["plateau"] - (-self.c - self.s * 0.125)), self.s * self.step)
        self.assertAlmostEqual(second["end_d0"], -0.5, places=12)
        self.assertEqual((first["amplitude"], second["amplitude"]), (0.125, 0.25))

    def test_the_law_against_it(self):
        law = [max(r[2], 0.0) if r[1] >= 1.0 else 0.0 for r in self.rows]  # no force beyond the touch
        first, second = tension.unloadings(self.rows, self.events, law=law, d0=1.0)
        self.assertEqual((second["law_held_beyond"], second["law_plateau"]), (0.0, 0.0))
        start = self.events[1][1]  # the first unloading: against the run's largest force, the second press's
        beyond = [r[2] for r in self.rows[start:self.events[2][1] + 1] if r[1] < 1.0]
        want = math.sqrt(sum(f * f for f in beyond) / len(beyond)) / self.peak
        self.assertAlmostEqual(first["misfit_beyond"], want, places=12)
        same = tension.unloadings(self.rows, self.events, law=[r[2] for r in self.rows], d0=1.0)[1]
        self.assertEqual((same["law_held_beyond"], same["misfit_beyond"]), (same["held_beyond"], 0.0))
        table = tension.table({"x": ([first, second], self.peak)}).split("\n")
        self.assertEqual(len(table), 4)
        # held (c 0.25 + s 0.25^2/2)/(peak 0.25/2) = 0.3125, plateau (-c - s 0.125)/peak = -0.15625
        self.assertTrue(table[3].startswith("| x | 0.25 | +0.312 | -0.156 | +0.0e+00, +0.0e+00 |"), table[3])


if __name__ == "__main__":
    unittest.main()
