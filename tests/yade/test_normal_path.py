# ctest (inside yade): a sphere moved against another under displacement control along a cyclic path
# (every branch, the −kc branch twice, separation and a new contact): YADE's hysteretic force is
# `theory.normal_force_path` on the recorded overlaps to 64 ulps of the largest force (measured: 0
# with 'linear', 0.2 ulps with 'sqrt').
#
# Theory.normal_force_path is the law of pkg/core/NormalLaw.hpp. One sphere is
# moved against a fixed one under displacement control (its position set every step; no damping,
# no tangential, rolling or torsion springs, no non-contact adhesion) along a cyclic path: loading
# to 0.6 deltaMax^p, unloading into tension past the pull-off onto the -kc branch, re-loading from
# there beyond the first maximum and past deltaMax^p, unloading on the limit line into tension
# again, re-loading from the -kc branch, separation (delta < 0: YADE ends the interaction) and a
# fresh contact. The hysteretic
# force YADE records is compared with normal_force_path on the overlaps YADE recorded, for both k2
# interpolations.
# Tolerance: 64 ulps of the largest |F|. The two compute the same arithmetic in double precision:
# with 'linear' they agree to the last bit (measured: 0); with 'sqrt' the cubic's closed-form root
# uses cbrt, cos and arccos, whose numpy (vectorised) and libm values differ by an ulp, and its
# Newton step near a double root can amplify that (measured 0.2 ulps here; up to ~110 ulps on
# random paths against a loop transcription of the C++ with Python's libm).
import math

from yade import O, Vector3
from mesocontact import pair, theory
from harness import check, finish

R = 1e-3
TOL = 64 * 2 ** -52
LAW = dict(k1=100.0, kp=500.0, kc=100.0, phiF=0.1, gammaN=0.0, kt=0.0, kr=0.0, ko=0.0, adhesion="none")
# the path's corners in units of deltaMax^p, with samples per leg
CORNERS = (-0.02, 0.6, 0.1, 1.6, 0.5, 0.9, -0.02, 0.3)
PER_LEG = 300


def targets(dmp):
    out = []
    for a, b in zip(CORNERS[:-1], CORNERS[1:]):
        out += [dmp * (a + (b - a) * (k + 1) / PER_LEG) for k in range(PER_LEG)]
    return out


def run(interpolation):
    s = pair.build(R, 1e-3, dict(LAW, k2Interpolation=interpolation), gap=0.05 * R)
    b1, b2 = O.bodies[s.ids[0]], O.bodies[s.ids[1]]
    for b in (b1, b2):
        b.state.blockedDOFs, b.state.vel, b.state.angVel = "xyzXYZ", (0, 0, 0), (0, 0, 0)
    dmp = theory.delta_max_p(LAW["k1"], LAW["kp"], LAW["phiF"], s.a12)
    deltas, forces, branches, other = [], [], [], 0.0
    for d in targets(dmp):
        b2.state.pos = Vector3(b1.state.pos[0] + 2 * R - d, 0, 0)
        O.step()
        i = O.interactions[s.ids[0], s.ids[1]]
        if i is not None and i.isReal:
            deltas.append(i.geom.penetrationDepth)
            forces.append(i.phys.hystereticForce)
            branches.append(i.phys.branch)
            other = max(other, abs(i.phys.adhesiveForce), abs(i.phys.viscousForce))
        else:  # no interaction: apart, no force
            deltas.append(2 * R - (b2.state.pos - b1.state.pos).norm())
            forces.append(0.0)
            branches.append("gone")
    return s, dmp, deltas, forces, branches, other


for interpolation in ("linear", "sqrt"):
    s, dmp, deltas, forces, branches, other = run(interpolation)
    seen = []
    for b in branches:
        if not seen or seen[-1] != b:
            seen.append(b)
    want_seen = ["gone", "loading", "unloading", "tensile", "unloading", "loading", "limit", "unloading", "tensile",
                 "unloading", "loading", "unloading", "tensile", "gone", "loading"]
    check(seen == want_seen, f"{interpolation}: the path passes every branch in order", " -> ".join(seen))
    check(other == 0.0, f"{interpolation}: no adhesive or viscous force", f"largest {other:.3g} N")
    want = theory.normal_force_path(deltas, LAW["k1"], LAW["kp"], LAW["kc"], LAW["phiF"], s.a12, interpolation)
    scale = max(abs(f) for f in forces)
    diffs = [abs(f - w) for f, w in zip(forces, want)]
    k = max(range(len(diffs)), key=diffs.__getitem__)
    check(max(diffs) <= TOL * scale, f"{interpolation}: normal_force_path is YADE's hysteretic force along the path",
          f"largest difference {max(diffs):.3g} N = {max(diffs) / scale:.3g} of max |F| = {scale:.4g} N "
          f"({max(diffs) / scale / 2 ** -52:.1f} ulps; at sample {k}, delta/deltaMax^p = {deltas[k] / dmp:.4g}, "
          f"branch {branches[k]}; {len(deltas)} samples, tolerance {TOL:.3g})")
    check(not math.isnan(scale) and scale > 0, f"{interpolation}: forces recorded", f"max |F| {scale:.4g} N")

finish()
