"""the fracture faces' roughness (`mesostudies.tablet.roughness`) on lattices whose faces are known:
flat halves 0; a one-layer step over half the face rms 1/2 and a 5-95 % range of 1; a tablet in one
piece refused; a VTK snapshot read back as written."""
import os
import tempfile
import unittest

import numpy as np

from mesostudies.tablet import roughness

R = 0.5  # unit spacing, spheres touching: d0 = 1


def lattice(nx, ny, nz, x0=0.0):
    g = np.array([(x0 + i, j, k) for i in range(nx) for j in range(ny) for k in range(nz)], dtype=float)
    return g, np.full(len(g), R)


def two_halves(step=False):
    left, rl = lattice(5, 6, 6)           # faces at x = 4.5
    right, rr = lattice(5, 6, 6, x0=8.0)  # faces at x = 7.5: gap 3
    if step:  # the left half's last layer removed where y < 3: face at 3.5 there
        keep = ~((left[:, 0] == 4) & (left[:, 1] < 3))
        left, rl = left[keep], rl[keep]
    return np.vstack([left, right]), np.concatenate([rl, rr])


class Roughness(unittest.TestCase):
    def test_flat_faces(self):
        pos, rad = two_halves()
        f = roughness.faces(pos, rad, roughness.torn_halves(pos, rad))
        # 6 x 6 columns less the outermost
        self.assertEqual((f["d0"], f["columns"], f["halves"], f["elsewhere"]), (1.0, 16, [180, 180], 0))
        self.assertTrue(np.all(f["left"] == 4.5) and np.all(f["right"] == 7.5))
        self.assertEqual(roughness.roughness(f["left"]), {"rms": 0.0, "range_5_95": 0.0, "peak_to_valley": 0.0})

    def test_step_of_one_layer(self):
        pos, rad = two_halves(step=True)
        f = roughness.faces(pos, rad, roughness.torn_halves(pos, rad))
        r = roughness.roughness(f["left"])
        self.assertEqual(sorted(set(f["left"])), [3.5, 4.5])
        self.assertAlmostEqual(r["rms"], 0.5, places=12)
        self.assertAlmostEqual(r["range_5_95"], 1.0, places=12)
        self.assertEqual(roughness.roughness(f["right"])["rms"], 0.0)

    def test_loose_sphere_is_elsewhere(self):
        pos, rad = two_halves()
        pos, rad = np.vstack([pos, [[6.0, 2.0, 2.0]]]), np.append(rad, R)
        f = roughness.faces(pos, rad, roughness.torn_halves(pos, rad))
        self.assertEqual((f["halves"], f["elsewhere"]), ([180, 180], 1))

    def test_one_piece_refused(self):
        pos, rad = lattice(10, 6, 6)
        with self.assertRaisesRegex(ValueError, "not torn apart"):
            roughness.torn_halves(pos, rad)
        cut = roughness.planar_cut(pos)  # a flat cut through it: flat faces
        f = roughness.faces(pos, rad, cut)
        self.assertEqual(roughness.roughness(f["left"])["rms"], 0.0)
        self.assertTrue(np.all(f["right"] - f["left"] == 0.0))

    def test_vtk_round_trip(self):
        pos, rad = two_halves(step=True)
        with tempfile.TemporaryDirectory() as d:
            p = os.path.join(d, "s.vtk")
            with open(p, "w") as f:
                f.write(f"# vtk DataFile Version 3.0.\nt\nASCII\n\nDATASET POLYDATA\nPOINTS {len(rad)} double\n")
                f.writelines(f"{x!r} {y!r} {z!r}\n" for x, y, z in pos)
                f.write(f"\nPOINT_DATA {len(rad)}\nSCALARS radius double 1\nLOOKUP_TABLE default\n")
                f.writelines(f"{r!r}\n" for r in rad)
            out = roughness.measure(p, flat=p)
        self.assertAlmostEqual(out["left"]["rms"], 0.5, places=12)
        self.assertEqual((out["right"]["rms"], out["gap_d0"]), (0.0, 3.5))  # gaps of 3 and 4 on half the columns each
        self.assertIn("flat_cut", out)


if __name__ == "__main__":
    unittest.main()
