"""The cycle measures of mesostudies.tablet.measures on cycles whose answers are known in closed form."""
import math
import unittest

from mesostudies.tablet import measures


def ellipse(n, amp, k, b, cycles=1):
    """Dx = amp (1 - cos t)/2, F = -k Dx - b sin t (tension): a loop of area pi b amp / 2."""
    rows = []
    for i in range(n * cycles + 1):
        t = 2 * math.pi * i / n
        dx = 0.5 * amp * (1 - math.cos(t))
        rows.append((i, dx, -k * dx - b * math.sin(t)))
    return rows


def one_contact(n, amp, k1, k2, mode="tension"):
    """Loading with k1 to amp, unloading with k2 > k1: the force is zero at Dx = amp (1 - k1/k2)."""
    s = -1 if mode == "tension" else 1
    rows = []
    for i in range(n + 1):
        up = i <= n // 2
        dx = amp * (i / (n // 2) if up else (n - i) / (n - n // 2))
        f = k1 * dx if up else k1 * amp - k2 * (amp - dx)
        rows.append((i, s * dx, s * f))
    return rows


class TestMeasures(unittest.TestCase):
    def test_ellipse_area(self):
        # trapezoids on a smooth closed curve: error ~ (2 pi / n)^2 / 12 of the area; 1e-3 at n = 400
        c = measures.cycle_measures(ellipse(400, 0.2, 0.3, 0.01, cycles=4), 400, "tension")
        self.assertEqual(len(c), 4)
        for m in c:
            self.assertAlmostEqual(m["loop"] / (math.pi * 0.01 * 0.2 / 2), 1.0, delta=1e-3)

    def test_elastic_cycle(self):
        c = measures.cycle_measures(ellipse(400, 0.2, 0.3, 0.0), 400, "tension")[0]
        self.assertLess(c["loop"], 1e-15)
        self.assertEqual(c["set"], 0.0)
        self.assertAlmostEqual(c["elastic"], 0.5 * 0.3 * 0.2 * 0.2, delta=1e-12)  # force swing k amp
        self.assertAlmostEqual(c["peak"], -0.3 * 0.2, delta=1e-12)

    def test_set_of_one_contact(self):
        for mode in ("tension", "compression"):
            for k1, k2 in ((1.0, 2.0), (1.0, 4.0), (2.0, 2.5)):
                c = measures.cycle_measures(one_contact(200, 0.3, k1, k2, mode), 200, mode)[0]
                self.assertAlmostEqual(c["set"], 1 - k1 / k2, delta=1e-9, msg=f"{mode} k1={k1} k2={k2}")
                # the triangle (0, 0), (amp, k1 amp), (0, (k1 - k2) amp), closed along Dx = 0: amp^2 (k2 - k1)/2
                self.assertAlmostEqual(c["loop"], 0.5 * 0.3 ** 2 * (k2 - k1), delta=1e-9)

    def test_set_from_the_starting_force(self):
        # the one-contact cycle shifted by f0 (the release stress): the same set, measured from f0
        for mode in ("tension", "compression"):
            rows = [(i, dx, f + 0.003) for i, dx, f in one_contact(200, 0.3, 1.0, 2.0, mode)]
            c = measures.cycle_measures(rows, 200, mode)[0]
            self.assertAlmostEqual(c["set"], 0.5, delta=1e-9)
            shift = 0.003 / (2.0 * 0.3)  # measured from zero instead, the set moves by f0/(k2 amp)
            self.assertAlmostEqual(measures.permanent_set(rows, mode), 0.5 + (shift if mode == "tension" else -shift),
                                   delta=1e-9)

    def test_split(self):
        rows = [(100 + i, 0.0, 0.0) for i in range(41)]
        parts = measures.split_cycles(rows, 10)
        self.assertEqual([len(p) for p in parts], [11, 11, 11, 11])
        self.assertEqual(parts[1][0][0], 110)
        with self.assertRaises(ValueError):
            measures.split_cycles(rows, 0)


if __name__ == "__main__":
    unittest.main()
