# ctest (inside yade): a sphere-wall collision reproduces the sphere-sphere restitution curve
# (closed form with a12 = 2a and the sphere's mass as m_r) to |de| <= 1e-3 in all four regimes,
# for boxes (ScGeom and ScGeom6D), walls and facets, with the wall's own material mixed in.
import math

from mesocontact import pair, params, theory
from harness import failures, finish

worst, regimes = 0.0, set()
r = 1.1e-3
m = params.sphere_mass(r, 2000)
base = dict(k1=100.0, kp=500.0, kc=100.0, phiF=0.1)


def hm(x, y):
    return 0.0 if x == 0 or y == 0 else 2 * x * y / (x + y)


def sweep(label, zetas, mat, kind, six_d=False, wall_mat=None):
    global worst
    w = wall_mat or mat
    k = {n: hm(mat.get(n, 0.0), w.get(n, 0.0)) for n in ("k1", "kp", "kc", "fa", "kca")}
    phiF = 0.5 * (mat["phiF"] + w["phiF"])
    mode = mat.get("adhesion", "none")
    v_p = theory.plastic_limit_velocity(k["k1"], k["kp"], phiF, 2 * r, m, k["fa"])
    first_rebound = math.inf
    for zeta in zetas:
        v = zeta * v_p
        s = pair.build_wall(r, v, mat, wall_material=wall_mat, kind=kind, six_d=six_d)
        res = pair.collide(s, max_contact_times=15)
        th = theory.pair_collision(v, k["k1"], k["kp"], k["kc"], phiF, 2 * r, m, fa=k["fa"],
                                   kca=k["kca"] or math.inf, adhesion=mode)
        err = abs(res.e - th.e)
        worst = max(worst, err)
        if th.e > 0:
            first_rebound = min(first_rebound, zeta)
            regimes.add("second rebound" if th.plastic_limit else "rebound")
        else:
            regimes.add("high-velocity sticking" if zeta > first_rebound else "low-velocity sticking")
        ok = err <= 1e-3 and res.stuck == (th.e == 0)
        line = f"{label:34s} zeta={zeta:6.3f} e_wall={res.e:.6f} e_theory={th.e:.6f} |de|={err:.1e} {th.regime}"
        print(("ok   " if ok else "FAIL ") + line, flush=True)
        if not ok:
            failures.append(line)


fa = params.fa_from_alpha(0.42, 100, m, 0.01)
zetas = [0.003, 0.05, 0.3, 0.7, 1.05, 2.0]
sweep("box, reversible", zetas, dict(base, fa=fa, kca=100.0, adhesion="reversible"), "box")
sweep("box 6D, jumpIn, all mechanisms on", zetas,
      dict(base, fa=fa, kca=100.0, adhesion="jumpIn", kt=40.0, kr=20.0, ko=20.0, muR=0.1, muO=0.1), "box", six_d=True)
sweep("wall, jumpIn", zetas, dict(base, fa=fa, kca=100.0, adhesion="jumpIn"), "wall")
sweep("facet, fa = 0", [0.3, 0.7, 1.05, 2.0], dict(base), "facet")
sweep("box, unlike wall material", [0.1, 0.5, 0.9, 1.5, 3.0], dict(base), "box",
      wall_mat=dict(k1=300.0, kp=2000.0, kc=50.0, phiF=0.2))
# highly plastic (eta = 50, beta = 0.05): the contact lasts many periods of kp, and just below
# the sticking window (chi_c^(b) = 0.42) the pair leaves slowly on the tensile branch
sweep("box, eta = 50, near the window", [0.1, 0.3, 0.34, 0.4, 0.45, 1.5],
      dict(k1=100.0, kp=5100.0, kc=5.0, phiF=0.02), "box")
print(f"worst |de| = {worst:.2e}; regimes seen: {sorted(regimes)}")
needed = {"low-velocity sticking", "rebound", "high-velocity sticking", "second rebound"}
if not needed <= regimes:
    failures.append(f"regimes not covered: {needed - regimes}")
finish()
