"""the tension branch's table (`mesostudies.tablet.experiments`, plain Python) on a made-up campaign
tree whose numbers are worked by hand: E1's spread and cycle-2 ratio, E2's F(0.2)/F_peak, crack
plane and row choice (`python.tablet_docs` checks the committed
`campaigns/tablet/branch/experiments.md` against the module)."""
import json
import os
import tempfile
import unittest

from mesostudies.tablet import experiments


def _write(path, obj):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(obj if isinstance(obj, str) else json.dumps(obj))


class Experiments(unittest.TestCase):
    def test_made_up_tree(self):
        with tempfile.TemporaryDirectory() as t:
            _write(os.path.join(t, "chosen", "tension-Dx0.2-P480.json"),
                   {"peaks": [-0.06, -0.02, -0.018, -0.016], "amplitude": 0.2, "period_crossings": 480, "L0": 0.116,
                    "steps_per_cycle": 4})
            # the first cycle (steps 10-13) turns back at Dx 0.2 with F -0.015; the next cycle reaches 0.2 again
            _write(os.path.join(t, "chosen", "tension-Dx0.2-P480.csv"),
                   "iter,Dx,F\n10,0.0,0.0\n11,0.1,-0.06\n12,0.2,-0.015\n13,0.1,0.01\n14,0.2,-0.02\n")
            _write(os.path.join(t, "chosen", "compression-Dx0.2-P120.json"), {"peaks": [1.0]})  # not tension: left out
            row = {"packing": "frictionless", "glue": "sinter", "rel_std": 0.1, "drag": "contacts", "L0": 0.115 * 1.01,
                   "peak_tension": 0.05, "peak_Dx": 0.03, "first_gap_Dx_by_area": {"1": 1.2}, "last_chain_Dx": 6.0,
                   "weakest_at_marks": {"0.81": {"from_left_d0": 9.0, "from_right_d0": 3.5}}}
            pull = os.path.join("{}", "pull-contacts", "pull-contacts.json")
            rows = [dict(row, sinter=0.02, seed=2, pull=pull.format("frictionless-sinter-std0.1-seed2")),
                    dict(row, sinter=0.1, seed=1, pull=pull.format("frictionless-sinter-std0.1-sinter0.1")),
                    dict(row, glue="loading", sinter=0.02, seed=1, pull=pull.format("frictionless-loading-std0.1"))]
            _write(os.path.join(t, "factors", "factors.json"), rows)
            csv = "iter,Dx,F_over_kp_d0\n1,0.0,0.0\n2,0.1,-0.05\n3,0.19,-0.03\n4,0.21,-0.02\n"
            for name in ("frictionless-sinter-std0.1-seed2", "frictionless-sinter-std0.1-sinter0.1"):
                _write(os.path.join(t, "factors", name, "pull-contacts", "pull-contacts.csv"), csv)
            one, two = experiments.e1(t), experiments.e2(t)
        self.assertEqual(len(one), 1)
        # cycles 2-4: mean -0.018, spread (-0.016 - -0.02) / 0.018 = 2/9; cycle 2 / first = 1/3
        self.assertAlmostEqual(one[0]["later_spread"], 2 / 9, places=12)
        self.assertAlmostEqual(one[0]["second_over_first"], 1 / 3, places=12)
        self.assertAlmostEqual(one[0]["turnaround_over_first"], 0.25, places=12)
        self.assertAlmostEqual(one[0]["later_spread_of_first"], 0.004 / 0.06, places=12)
        # the loading-glue row left out
        self.assertEqual([(r["sinter"], r["seed"]) for r in two], [(0.02, 2), (0.1, 1)])
        # the first record at or past Dx 0.2 holds -0.02: 0.02 / 0.05
        self.assertAlmostEqual(two[0]["F02_over_peak"], 0.4, places=12)
        self.assertEqual(two[0]["crack_from_wall_d0"], 3.5)
        self.assertAlmostEqual(two[0]["L0_vs_paper"], 0.01, places=12)
        self.assertIsNone(two[0]["affine_peak_Dx"])
        self.assertEqual(two[1]["folder"], "frictionless-sinter-std0.1-sinter0.1")

    def test_variants_and_profiles(self):
        with tempfile.TemporaryDirectory() as t:
            e1 = {"peaks": [-0.06, -0.02], "amplitude": 0.1, "period_crossings": 480, "L0": 0.116, "steps_per_cycle": 4}
            _write(os.path.join(t, "chosen", "tension-Dx0.1-P480.json"), e1)
            # the first pull peaks at Dx 0.05 (-0.06), turns back at 0.1 with -0.03
            _write(os.path.join(t, "chosen", "tension-Dx0.1-P480.csv"),
                   "iter,Dx,F\n10,0.0,0.0\n11,0.05,-0.06\n12,0.1,-0.03\n13,0.05,0.01\n14,0.1,-0.02\n")
            # back to the start's force: strokes end at iters 12 (out), 14 (back at Dx 0.04), 16, 18 (Dx 0.05)
            _write(os.path.join(t, "variants", "tested", "force-return-tension-Dx0.1-P480.json"),
                   dict(e1, peaks=[-0.05, -0.04], turns=[[12, 0.1, -0.02], [14, 0.04, 0.0], [16, 0.1, -0.03],
                                                         [18, 0.05, 0.0]]))
            _write(os.path.join(t, "variants", "tested", "force-return-tension-Dx0.1-P480.csv"),
                   "iter,Dx,F\n10,0.0,0.0\n11,0.06,-0.05\n12,0.1,-0.02\n13,0.07,-0.01\n14,0.04,0.0\n")
            records = [{"Dx": 0.0, "measured": {"tensile": 0.0, "open": 0.0}, "affine": {"tensile": 0.0, "open": 0.0},
                        "max_strain_over_affine": None, "at_d0": None},
                       {"Dx": 0.03, "measured": {"tensile": 0.02, "open": 0.1},
                        "affine": {"tensile": 0.3, "open": 0.05},
                        "max_strain_over_affine": 1.5, "at_d0": 4.0},
                       {"Dx": 0.06, "measured": {"tensile": 0.01, "open": 0.2}, "affine": {"tensile": 0.4, "open": 0.1},
                        "max_strain_over_affine": 2.5, "at_d0": 4.0}]
            _write(os.path.join(t, "profile", "tested", "profile.json"),
                   {"peak_F": -0.05, "peak_Dx": 0.028, "localization_first_Dx": {"2": 0.04}, "records": records,
                    "protocol": {"packing": "frictionless"}})
            _write(os.path.join(t, "profile", "tested", "profile.csv"),
                   "iter,Dx,F\n1,0.0,0.0\n2,0.19,-0.03\n3,0.2,-0.01\n")
            # E4: the same pull through grips, listed after the walls' pull of its sample
            _write(os.path.join(t, "profile", "tested-grips1", "profile.json"),
                   {"peak_F": -0.05, "peak_Dx": 0.028, "localization_first_Dx": {"2": 0.04}, "records": records,
                    "protocol": {"packing": "frictionless"},
                    "grips": {"thickness_d0": 1.0, "left": 9, "right": 8, "free": 40},
                    "L0": 0.1})
            _write(os.path.join(t, "profile", "tested-grips1", "profile.csv"), "iter,Dx,F\n1,0.0,0.0\n2,0.2,-0.02\n")
            one = experiments.e1(t)
            three, five_six = experiments.e3(t), experiments.e56(t, one)
        self.assertEqual(one[0]["first_peak_Dx"], 0.05)
        self.assertAlmostEqual(one[0]["turnaround_over_first"], 0.5, places=12)
        (v,) = five_six
        self.assertEqual((v["variant"], v["first_peak_Dx"], v["returns_at_Dx"]), ("force-return", 0.06, [0.04, 0.05]))
        self.assertAlmostEqual(v["turnaround_over_first"], 0.4, places=12)  # the out stroke ends at -0.02
        self.assertEqual(v["E1"]["first_peak"], -0.06)
        p, g = three
        self.assertEqual((p["loading"], g["loading"], g["sample"]),
                         ("walls", "grips 1 d0 (9 + 8 of 57 particles; free 0.80 of L0)", "tested-grips1"))
        self.assertAlmostEqual(g["F02_over_peak"], 0.4, places=12)
        # L0 = 10 d0, grips of 1 d0: 8 d0 free; the recorded 1.5 at the peak is 1.2 of the free part's even
        # stretch, and "2x the free part's" is 2.5 recorded: first and for good at Dx 0.06 (2.5 >= 2.5)
        self.assertAlmostEqual(g["strain_at_peak"], 1.2, places=12)
        self.assertEqual(g["strain_2x_from_Dx"], 0.06)
        self.assertEqual((p["sinter"], p["seed"], p["record_Dx"], p["max_tensile_affine"]), (0.02, 1, 0.03, 0.4))
        self.assertAlmostEqual(p["F02_over_peak"], 0.2, places=12)
        self.assertEqual((p["strain_at_peak"], p["strain_2x_from_Dx"]), (1.5, 0.06))

    def test_contact_pull_ratio(self):
        # a contact's largest pull kc k2 d0/(k2 + kc), kc 0.5 against 0.2 (over kp): k2 = kp: (0.5/1.5)/(0.2/1.2) = 2;
        # k2 = k1 = kp/2: (0.25/1)/(0.1/0.7) = 1.75
        lo, hi = experiments.pull_ratio(0.5)
        self.assertAlmostEqual(lo, 1.75, places=12)
        self.assertAlmostEqual(hi, 2.0, places=12)


if __name__ == "__main__":
    unittest.main()
