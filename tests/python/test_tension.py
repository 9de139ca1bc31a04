"""mesostudies.agglomerate.tension on an unloading whose tension is known by hand: Luding's triangle
from the first touch (k1 up to the turn, k2 back to zero force), then a plateau -c from there to
delta_touch - 0.25 (a neck drawn beyond the touch), then a force ringing about zero. The work held
beyond the touch is c times the plateau's length below delta_touch (the numbers are binary fractions,
the trapezoids exact, the crossing of delta_touch cut exactly), and the ringing adds nothing to it;
the plateau's mean is -c; a law with no force beyond the touch misses it by the data's rms there over
the peak force (the fit's measure); a law equal to the data carries it all."""
import math
import unittest

from mesostudies.agglomerate import tension


def line(d_from, d_to, force, n=256):
    return [(d_from + (d_to - d_from) * k / n, force(d_from + (d_to - d_from) * k / n)) for k in range(n + 1)]


class Unloadings(unittest.TestCase):
    def setUp(self):
        t, dm, k1, k2, self.c = 1.0, 1.25, 2.0, 8.0, 0.0625
        dz = dm - k1 * (dm - t) / k2          # where the k2 line reaches zero force: 1.1875
        self.end = t - 0.25
        ring = [(self.end - 0.25 * k / 256, 0.01 * math.sin(math.pi * k / 32)) for k in range(257)]  # 4 periods
        strokes = [("touch", [(t, 0.0)]), ("loaded to 0.25 d0", line(t, dm, lambda d: k1 * (d - t))),
                   ("unloaded", line(dm, dz, lambda d: k2 * (d - dz)) + line(dz, self.end, lambda d: -self.c)
                    + [(self.end, 0.0)] + ring)]
        self.rows, self.events, it = [], [], 0
        for what, pts in strokes:
            for d, f in pts:
                self.rows.append((it, d, f))
                it += 1
            self.events.append((what, self.rows[-1][0], self.rows[-1][1], self.rows[-1][2]))
        self.peak = k1 * (dm - t)

    def test_held_beyond_the_touch(self):
        (u,) = tension.unloadings(self.rows, self.events, d0=1.0, band=(-0.2, -0.05))
        self.assertAlmostEqual(u["held_beyond"], self.c * 0.25, places=12)
        self.assertAlmostEqual(u["press_work"], 0.5 * self.peak * 0.25, places=12)
        self.assertAlmostEqual(u["plateau"], -self.c, places=15)
        self.assertAlmostEqual(u["end_d0"], -0.5, places=12)
        self.assertEqual(u["amplitude"], 0.25)

    def test_the_law_against_it(self):
        law = [max(r[2], 0.0) if r[1] >= 1.0 else 0.0 for r in self.rows]  # no force beyond the touch
        none = tension.unloadings(self.rows, self.events, law=law, d0=1.0)[0]
        self.assertEqual((none["law_held_beyond"], none["law_plateau"]), (0.0, 0.0))
        beyond = [r[2] for r in self.rows[self.events[1][1]:] if r[1] < 1.0]
        want = math.sqrt(sum(f * f for f in beyond) / len(beyond)) / self.peak
        self.assertAlmostEqual(none["misfit_beyond"], want, places=12)
        same = tension.unloadings(self.rows, self.events, law=[r[2] for r in self.rows], d0=1.0)[0]
        self.assertEqual((same["law_held_beyond"], same["misfit_beyond"]), (same["held_beyond"], 0.0))
        self.assertIn("| x | 0.25 |", tension.table({"x": ([none], self.peak)}))


if __name__ == "__main__":
    unittest.main()
