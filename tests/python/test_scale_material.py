"""params.scale_material: a calibrated material for s times larger (r times denser) particles keeps
e(v) at every approach speed, and what it changes (overlaps, forces, times) goes as the law's
similarity says (lengths x s, times x s, forces x r s^2); checked with the closed form."""
import math
import unittest

from mesocontact import params, theory

RADIUS, DENSITY = 2.45e-6, 1500.0
MATERIALS = {  # both adhesion modes, both k2 rules, with and without the tensile branch
    "jumpIn": dict(k1=50.0, kp=250.0, kc=5.0, phiF=0.66, fa=4e-6, kca=50.0, adhesion="jumpIn", k2Interpolation="linear",
                   density=DENSITY),
    "reversible-sqrt": dict(k1=50.0, kp=400.0, kc=20.0, phiF=0.3, fa=2e-6, kca=80.0, adhesion="reversible",
                            k2Interpolation="sqrt", density=DENSITY),
    "none": dict(k1=50.0, kp=250.0, kc=50.0, phiF=0.2, adhesion="none", k2Interpolation="linear", density=DENSITY),
}


def law(mat, radius, against):
    """The closed form's keyword arguments for `mat` on spheres of `radius` (pair or wall)."""
    m = params.sphere_mass(radius, mat["density"])
    m_r = m if against == "wall" else params.reduced_mass(m, m)
    a12 = params.reduced_radius(radius) if against == "wall" else params.reduced_radius(radius, radius)
    return dict(k1=mat["k1"], kp=mat["kp"], kc=mat["kc"], phiF=mat["phiF"], a12=a12, m_r=m_r,
                fa=mat.get("fa", 0.0) if mat["adhesion"] != "none" else 0.0, kca=mat.get("kca", math.inf),
                adhesion=mat["adhesion"], interpolation=mat["k2Interpolation"])


def v_p(p):
    return theory.plastic_limit_velocity(p["k1"], p["kp"], p["phiF"], p["a12"], p["m_r"], p["fa"])


def largest_overlap(v_contact, p):
    return theory.max_overlap(v_contact, p["k1"], p["kp"], p["phiF"], p["a12"], p["m_r"], p["fa"])


def pull_off(p):
    return p["kp"] * p["kc"] / (p["kp"] + p["kc"]) * p["phiF"] * p["a12"]


class ScaleMaterial(unittest.TestCase):
    def test_restitution_kept_and_the_rest_scaled(self):
        for name, mat in MATERIALS.items():
            for against in ("particle", "wall"):
                for s, r in ((20.0, 1.0), (0.1, 1.0), (7.0, 3.0)):
                    with self.subTest(material=name, against=against, s=s, r=r):
                        big = params.scale_material(mat, s, r)
                        small, large = law(mat, RADIUS, against), law(big, RADIUS * s, against)
                        self.assertAlmostEqual(v_p(large) / v_p(small), 1.0, places=12)
                        regimes = set()
                        # every regime (not at v_p itself: a kink)
                        for x in (0.01, 0.03, 0.1, 0.3, 0.6, 0.9, 1.2, 3.0, 10.0):
                            v = x * v_p(small)
                            a, b = theory.pair_collision(v, **small), theory.pair_collision(v, **large)
                            regimes.add(a.regime)
                            self.assertEqual(a.regime, b.regime, v)
                            self.assertAlmostEqual(b.e, a.e, delta=1e-12, msg=v)
                            t_a, t_b = theory.contact_duration(v, **small), theory.contact_duration(v, **large)
                            if math.isfinite(t_a):
                                self.assertAlmostEqual(t_b / (s * t_a), 1.0, places=9, msg=v)  # times x s
                            else:
                                self.assertEqual(t_b, math.inf)
                            ratio = largest_overlap(b.v_contact, large) / largest_overlap(a.v_contact, small)
                            self.assertAlmostEqual(ratio / s, 1.0, places=9, msg=v)  # lengths x s
                        self.assertGreater(len(regimes), 1, regimes)  # the speeds cross at least one regime boundary
                        # forces x r s^2
                        self.assertAlmostEqual(pull_off(large) / (r * s * s * pull_off(small)), 1.0, places=12)
                        if mat["adhesion"] != "none":
                            self.assertAlmostEqual(big["fa"] / (r * s * s * mat["fa"]), 1.0, places=12)
                            self.assertAlmostEqual((big["fa"] / big["kca"]) / (s * mat["fa"] / mat["kca"]), 1.0,
                                                   places=12)
                        step = 2 * math.sqrt(large["m_r"] / large["kp"]) / (2 * math.sqrt(small["m_r"] / small["kp"]))
                        self.assertAlmostEqual(step / s, 1.0, places=12)  # the stable step x s

    def test_what_it_does_to_each_attribute(self):
        mat = dict(MATERIALS["jumpIn"], gammaN=1e-6, gammaN2=3e-5,
                   kt=10.0, gammaT=1e-7, kr=5.0, gammaR=1e-8, ko=5.0, gammaO=1e-8,
                   muR=0.1, muO=0.1, phiD=0.8, frictionAngle=0.5, young=1e9, poisson=0.3, dominant=False, label="a")
        big = params.scale_material(mat, 10.0, 2.0)
        for k in ("k1", "kp", "kc", "kca", "kt", "kr", "ko"):
            self.assertAlmostEqual(big[k] / mat[k], 20.0, places=12, msg=k)
        for k in ("fa", "gammaN", "gammaN2", "gammaT", "gammaR", "gammaO"):
            self.assertAlmostEqual(big[k] / mat[k], 200.0, places=12, msg=k)
        for k in ("density", "young"):
            self.assertAlmostEqual(big[k] / mat[k], 2.0, places=12, msg=k)
        for k in ("phiF", "muR", "muO", "phiD", "frictionAngle", "poisson", "adhesion", "k2Interpolation", "dominant",
                  "label"):
            self.assertEqual(big[k], mat[k], k)

    def test_a_material_from_material_from_and_a_mesomat_like_object(self):
        m = params.material_from(radius=0.5e-3, density=2000, impact_speed=0.2, restitution=0.5, contact_time=1e-5,
                                 phiF=0.1)
        self.assertAlmostEqual(params.scale_material(m, 3.0)["kp"] / m["kp"], 3.0, places=12)

        class Mat:  # YADE's Serializable.dict(): the id is O.materials', not the material's
            def dict(self):
                return dict(MATERIALS["none"], id=4)
        out = params.scale_material(Mat(), 2.0)
        self.assertNotIn("id", out)
        self.assertEqual(out["k1"], 100.0)

    def test_bad_input_named(self):
        mat = MATERIALS["none"]
        for args, pattern in (((mat, 0.0), "radius_factor = 0.0"), ((mat, math.nan), "radius_factor = nan"),
                              ((mat, True), "radius_factor = True"), ((mat, 2.0, -1.0), "density_factor = -1.0"),
                              ((dict(mat, k3=1.0), 2.0), r"material\['k3'\]"),
                              ((dict(mat, k1=math.inf), 2.0), r"material\['k1'\] = inf"),
                              ((dict(mat, k1="x"), 2.0), r"material\['k1'\] = 'x'"),
                              ((dict(mat, k1=1e10), 1e300), r"material\['k1'\].*out of floating-point range"),
                              ((dict(mat, kc=1e-300), 1e-300), r"material\['kc'\].*out of floating-point range")):
            with self.subTest(args=args[1:]):
                with self.assertRaisesRegex(ValueError, pattern):
                    params.scale_material(*args)
        with self.assertRaisesRegex(TypeError, "material = 3"):
            params.scale_material(3, 2.0)


if __name__ == "__main__":
    unittest.main()
