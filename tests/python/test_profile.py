"""mesostudies.tablet.profile's plain parts (issue #47, E3): the affine branches of contacts, the
local strains between slabs and the localization factor, against values worked by hand."""
import unittest

import numpy as np

from mesostudies.tablet import profile


class AffineBranches(unittest.TestCase):
    def test_one_contact_through_its_branches(self):
        # delta 1, delta0 0.5, k2 2, kc 1, l 1, along x: the overlap is 1 - eps. The k2 line meets
        # -kc delta at delta* = k2 delta0 / (k2 + kc) = 1/3 (eps 2/3); the contact opens at eps 1.
        c = [np.array([x]) for x in (1.0, 0.5, 2.0, 1.0, 1.0, 1.0)]
        for eps, branch in ((0.0, "line"), (0.66, "line"), (0.67, "tensile"), (0.99, "tensile"),
                            (1.01, "open")):
            got = profile.affine_branches(*c, eps)
            self.assertEqual(got[branch], 1.0, (eps, got))
            self.assertEqual(sum(got.values()), 1.0)

    def test_normals_open_later(self):
        # the same contact at nx^2 = 1/4 opens four times later; the two together split evenly
        c = [np.array([1.0, 1.0]), np.array([0.5, 0.5]), np.array([2.0, 2.0]), np.array([1.0, 1.0]),
             np.array([1.0, 1.0]), np.array([1.0, 0.25])]
        self.assertEqual(profile.affine_branches(*c, 1.01), {"line": 0.5, "tensile": 0.0, "open": 0.5})
        self.assertEqual(profile.affine_branches(*c, 3.0), {"line": 0.0, "tensile": 0.5, "open": 0.5})


class Strains(unittest.TestCase):
    def test_even_stretch_is_affine(self):
        x = np.array([0.5, 1.5, 2.5, 3.5])
        s = profile.local_strains(x, 0.01 * (x - 2.0))
        np.testing.assert_allclose(s, 0.01, rtol=1e-12)
        self.assertAlmostEqual(profile.localization(s, 0.01)[0], 1.0, places=12)

    def test_a_crack_between_two_slabs(self):
        # all the stretch (0.3) between the second and third slab, centres 1 apart: strain 0.3 there,
        # against an affine 0.1 over three gaps
        s = profile.local_strains([0.5, 1.5, 2.5, 3.5], [0.0, 0.0, 0.3, 0.3])
        np.testing.assert_allclose(s, [0.0, 0.3, 0.0], atol=1e-15)
        factor, where = profile.localization(s, 0.1)
        self.assertAlmostEqual(factor, 3.0, places=12)
        self.assertEqual(where, 1)

    def test_persistent_localization(self):
        # a first crossing at 0.001 (noise over a tiny affine strain) that falls back, then for good from 0.03
        recs = [{"Dx": 0.0, "max_strain_over_affine": None}, {"Dx": 0.001, "max_strain_over_affine": 3.0},
                {"Dx": 0.01, "max_strain_over_affine": 1.2}, {"Dx": 0.03, "max_strain_over_affine": 2.0},
                {"Dx": 0.05, "max_strain_over_affine": 2.5}]
        self.assertEqual(profile.persistent_from(recs, 2.0), 0.03)
        self.assertIsNone(profile.persistent_from(recs, 3.0))


if __name__ == "__main__":
    unittest.main()
