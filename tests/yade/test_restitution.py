# ctest (inside yade): YADE pair collisions against the closed form (`docs/model.md` §6), |Δe| ≤
# 1e-3, over all four regimes: eta = 4, beta = 1 and three parameter sets of our own (unequal radii,
# unlike materials); fa > 0 in both adhesion modes; both k2 interpolations; sticking overlaps
# against Eqs. 36/38 within 1e-3 δmax^p.
import math

from mesocontact import pair, params, theory
from harness import failures, finish

TOL_E = 1e-3
TOL_DC = 1e-3  # in units of deltaMax^p
worst, regimes = 0.0, set()


def hm(x, y):
    return 0.0 if x == 0 or y == 0 else 2 * x * y / (x + y)


def sweep(label, zetas, mat, r1, r2=None, mat2=None, density=2000.0, density2=None):
    global worst
    r2 = r2 or r1
    mat2 = mat2 or mat
    d2 = density2 or density
    m_r = params.reduced_mass(params.sphere_mass(r1, density), params.sphere_mass(r2, d2))
    a12 = params.reduced_radius(r1, r2)
    k = {n: hm(mat.get(n, 0.0), mat2.get(n, 0.0)) for n in ("k1", "kp", "kc", "fa", "kca")}
    phiF = 0.5 * (mat["phiF"] + mat2["phiF"])
    mode = mat.get("adhesion", "none")
    interp = mat.get("k2Interpolation", "linear")
    v_p = theory.plastic_limit_velocity(k["k1"], k["kp"], phiF, a12, m_r, k["fa"])
    first_rebound = math.inf
    for zeta in zetas:
        v = zeta * v_p
        m1 = dict(mat, density=density)
        m2 = dict(mat2, density=d2) if (mat2 is not mat or d2 != density) else None
        s = pair.build(r1, v, m1, radius2=r2, material2=m2)
        res = pair.collide(s, max_contact_times=15)
        th = theory.pair_collision(v, k["k1"], k["kp"], k["kc"], phiF, a12, m_r, fa=k["fa"],
                                   kca=k["kca"] or math.inf, adhesion=mode, interpolation=interp)
        err = abs(res.e - th.e)
        worst = max(worst, err)
        ok = err <= TOL_E and res.stuck == (th.e == 0)
        line = f"{label:28s} zeta={zeta:6.3f} e_sim={res.e:.6f} e_th={th.e:.6f} |de|={err:.1e} {th.regime}"
        if th.e > 0:
            first_rebound = min(first_rebound, zeta)
            regimes.add("second rebound" if th.plastic_limit else "rebound")
        else:
            regimes.add("high-velocity sticking" if zeta > first_rebound else "low-velocity sticking")
        if res.stuck and k["fa"] == 0 and th.regime == "sticking-contact":
            eta, beta = (k["kp"] - k["k1"]) / k["k1"], k["kc"] / k["k1"]
            dmp = theory.delta_max_p(k["k1"], k["kp"], phiF, a12)
            chi = th.delta_max / dmp if not th.plastic_limit else v / v_p
            dc_th = theory.sticking_overlap(chi, eta, beta, interp)
            dc_err = abs(res.final_overlap / dmp - dc_th)
            ok = ok and dc_err <= TOL_DC
            line += f" delta_c/dmp sim={res.final_overlap / dmp:.6f} th={dc_th:.6f} err={dc_err:.1e}"
        print(("ok   " if ok else "FAIL ") + line, flush=True)
        if not ok:
            failures.append(line)


paper = dict(k1=100.0, kp=500.0, kc=100.0, phiF=0.1)
r = 1.1e-3
m_r = params.sphere_mass(r, 2000) / 2
window = [0.1, 0.34, 0.45, 0.6, 0.9, 1.0, 1.1, 1.3, 2.5]  # in zeta = v/v_p (= chi for fa = 0)
sweep("eta4 beta1 linear", window, paper, r)
sweep("eta4 beta1 sqrt", window, dict(paper, k2Interpolation="sqrt"), r)
for alpha in (0.042, 0.42):  # Fig. 5: fa from alpha at v_i = 0.01 m/s; kca = kc
    fa = params.fa_from_alpha(alpha, 100, m_r, 0.01)
    for mode in ("jumpIn", "reversible"):
        sweep(f"eta4 beta1 {mode} a={alpha}", [0.003, 0.02, 0.2, 0.6, 1.2, 3.0],
              dict(paper, fa=fa, kca=100.0, adhesion=mode), r)
# Own sets: unequal radii and densities; stiffer and more plastic; unlike materials with sqrt.
own1 = dict(k1=1e3, kp=1e4, kc=500.0, phiF=0.05)  # eta = 9, beta = 0.5 > beta* = 1/8
sweep("own1 eta9 unequal radii", [0.05, 0.3, 0.6, 1.0, 1.5, 4.0], own1, 1e-3, r2=2.5e-3, density=2500.0,
      density2=1500.0)
own2 = dict(k1=50.0, kp=200.0, kc=30.0, phiF=0.2, fa=2e-5, kca=40.0, adhesion="reversible")
sweep("own2 eta3 reversible", [0.01, 0.1, 0.4, 0.8, 1.1, 2.0], own2, 2e-3, r2=1e-3)
own3a = dict(k1=200.0, kp=4000.0, kc=100.0, phiF=0.08, fa=1e-4, kca=200.0, adhesion="jumpIn", k2Interpolation="sqrt")
own3b = dict(k1=300.0, kp=5000.0, kc=60.0, phiF=0.12, fa=2e-4, kca=300.0, adhesion="jumpIn", k2Interpolation="sqrt")
sweep("own3 unlike sqrt jumpIn", [0.005, 0.05, 0.3, 0.8, 1.5, 5.0], own3a, 1.5e-3, r2=1e-3, mat2=own3b)

print(f"worst |de| = {worst:.2e}; regimes seen: {sorted(regimes)}")
needed = {"low-velocity sticking", "rebound", "high-velocity sticking", "second rebound"}
if not needed <= regimes:
    failures.append(f"regimes not covered: {needed - regimes}")
finish()
