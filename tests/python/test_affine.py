"""the affine tension of a set of contacts (`mesostudies.tablet.affine`, the job `tablet.py affine`;
plain Python) against values worked by hand from the unloading law f = max(k2 (delta - delta0), -kc
delta) (`docs/model.md` §3)."""
import unittest

import numpy as np

from mesostudies.tablet import affine


class Affine(unittest.TestCase):
    def test_one_contact_along_x(self):
        # delta 2, delta0 1.5, k2 10, kc 2, l 100, along x; L0 1000, d0 1: eps = Dx / 1000, the overlap
        # falls by Dx / 10. The k2 line meets -kc delta at delta* = k2 delta0 / (k2 + kc) = 1.25, i.e. Dx = 7.5,
        # force -2.5, wall force -2.5 * 100 / 1000 = -0.25; detachment at delta = 0, Dx = 20.
        args = (np.array([2.0]), np.array([1.5]), np.array([10.0]), np.array([2.0]), np.array([100.0]), np.array([1.0]),
                1000.0, 1.0)
        f = affine.curve(*args, [0.0, 5.0, 7.5, 10.0, 20.0, 25.0])
        # Dx 0: 10 * 0.5 * 100 / 1000; 5: on delta0; 7.5: the tensile limit; 10: -kc * 1; 20: apart
        np.testing.assert_allclose(f, [0.5, 0.0, -0.25, -0.2, 0.0, 0.0], atol=1e-12)
        dx = np.linspace(0, 25, 2501)
        s = affine.summary(dx, affine.curve(*args, dx))
        self.assertAlmostEqual(s["peak_Dx"], 7.5, places=9)
        self.assertAlmostEqual(s["peak_force"], -0.25, places=12)

    def test_normals_and_sum(self):
        # two contacts: one along x, one at 60 degrees (nx^2 = 1/4) opening four times slower and
        # weighing a quarter; their forces add.
        d, d0, k2, kc = np.array([2.0, 2.0]), np.array([1.5, 1.5]), np.array([10.0, 10.0]), np.array([2.0, 2.0])
        l, nx2 = np.array([100.0, 100.0]), np.array([1.0, 0.25])
        f = affine.curve(d, d0, k2, kc, l, nx2, 1000.0, 1.0, [4.0])[0]
        by_hand = (10 * (2 - 0.4 - 1.5) * 100 * 1 + 10 * (2 - 0.1 - 1.5) * 100 * 0.25) / 1000
        self.assertAlmostEqual(f, by_hand, places=12)

    def test_contacts_apart_carry_nothing(self):
        self.assertEqual(list(affine.contact_force(np.array([-1e-9, 0.0]), np.array([0.0, 0.0]), np.array([1.0, 1.0]),
                                                   np.array([1.0, 1.0]))), [0.0, 0.0])


if __name__ == "__main__":
    unittest.main()
