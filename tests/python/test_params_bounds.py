"""params' results are materials MesoMat takes (issue #57, the fuzz): a result outside MesoMat's
[1e-100, 1e100] is refused naming the inputs, not returned for MesoMat to refuse later."""
import unittest

from mesocontact import params

BASE = dict(radius=1e-3, impact_speed=0.5, restitution=0.6, contact_time=6e-4, kc_over_kp=0.2, kca=100.0)


class Bounds(unittest.TestCase):
    def test_material_from_fa_too_small(self):
        with self.assertRaisesRegex(ValueError, r"fa = 1e-300.*outside the \[1e-100, 1e100\]"):
            params.material_from(density=71117.7, phiF=0.96, fa=1e-300, **BASE)

    def test_material_from_density_out_of_range(self):
        with self.assertRaisesRegex(ValueError, r"^density = 1.7e\+308 is invalid"):
            params.material_from(density=1.7e308, phiF=0.1, fa=1e-4, **BASE)

    def test_scale_material_result_out_of_range(self):
        with self.assertRaisesRegex(ValueError, r"density_factor = 1e-300: they give k1"):
            params.scale_material(dict(k1=100.0, kp=500.0, density=2000.0), 2.32, 1e-300)

    def test_in_range_passes(self):
        out = params.scale_material(dict(k1=100.0, kp=500.0, density=2000.0), 2.0)
        self.assertAlmostEqual(out["density"], 2000.0)


if __name__ == "__main__":
    unittest.main()
