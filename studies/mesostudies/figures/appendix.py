"""Figs. 9-15 of the long paper (adhesivity, Appendix A-E): YADE pair collisions over the closed
form, inside ``yade``. Each function writes CSV + PNG into outdir and returns a summary dict
(the worst |e_YADE - e_theory|, the number of collisions, what the figure must show)."""
import math
import os
import time

from mesocontact import loop as _loop
from mesocontact import pair, theory
from .common import (
    DENSITY, PAPER, RADIUS, fig_note, pair_reduced_mass, plt, print_progress, save_figure,
    write_csv,
)

K1 = PAPER["k1"]
PHI_F = PAPER["phiF"]


def _mat(eta, beta, **kw):
    return dict(k1=K1, kp=K1 * (1.0 + eta), kc=beta * K1, phiF=PHI_F, density=DENSITY, **kw)


def _speed(chi, mat):
    return theory.impact_velocity_for_chi(chi, mat["k1"], mat["kp"], mat["phiF"], RADIUS, pair_reduced_mass())


def collide_pair(mat, v, **kw):
    return pair.collide(pair.build(RADIUS, v, mat), **kw)


def _finish_sweep(fig, ax, outdir, stem, rows, title, note, ylabel="e", legend_size=7, legend_loc="lower left"):
    """What every e(chi) figure ends with: log chi axis, labels, legend, the parameters under the
    plot, PNG and the sweep's CSV."""
    ax.set_xscale("log")
    ax.set_xlabel("χ = v_i / v_p")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.legend(fontsize=legend_size, loc=legend_loc)
    fig_note(fig, note)
    save_figure(fig, outdir, stem)
    write_csv(os.path.join(outdir, stem + ".csv"), SWEEP_HEADER, rows)


def log_grid(lo, hi, n):
    return [lo * (hi / lo) ** (i / (n - 1)) for i in range(n)]


def _sweep(tag, curves, t0, rows, interpolation="linear"):
    """curves: (label, eta, beta, chis); YADE e at each chi against restitution_fa0. Appends
    (label, eta, beta, chi, v, e_yade, e_theory, stuck) rows; returns {label: [(chi, e_yade)]}."""
    n, k, out = sum(len(c[3]) for c in curves), 0, {}
    for label, eta, beta, chis in curves:
        mat = _mat(eta, beta, k2Interpolation=interpolation)
        for chi in chis:
            v = _speed(chi, mat)
            r = collide_pair(mat, v, max_contact_times=15)
            e_th = theory.restitution_fa0(chi, eta, beta, interpolation)
            rows.append((label, eta, beta, chi, v, r.e, e_th, int(r.stuck)))
            plot_live(chi=chi, v=v, e_yade=r.e, e_theory=e_th)
            out.setdefault(label, []).append((chi, r.e))
            k += 1
            print_progress(tag, k, n, t0)
    return out


def plot_live(**point):
    """Each collision also goes to yade.plot (plot.plot() in the shell shows e as it comes)."""
    from yade import plot
    if not plot.plots:
        plot.plots = {"chi": ("e_yade", "e_theory")} if "chi" in point else {"v": ("e_yade", "e_theory")}
    plot.addData(**point)


def _worst(rows, i_sim=5, i_th=6):
    return max(abs(r[i_sim] - r[i_th]) for r in rows)


SWEEP_HEADER = ["curve", "eta", "beta", "chi", "v_i_m_s", "e_yade", "e_theory", "stuck"]
PARAM_LINE = f"k1 = {K1:g} N/m, φf = {PHI_F:g}, a = {RADIUS * 1e3:g} mm, ρ = {DENSITY:g} kg/m³, f_a = 0, γ0 = 0"


def fig9(outdir, quick=False, phiF_tuned=0.5):
    """e(chi) for beta/beta* = 1/3, 1, 3 at eta = 4, and the tuned plastic model of Appendix A
    (phiF' = 0.5, kp' of Eq. A.3) for beta = beta*/3 on the reference chi axis."""
    eta, t0, rows = 4.0, time.time(), []
    bs = theory.beta_star(eta)
    chis = [0.1, 0.7, 1.5] if quick else [0.02, 0.05, 0.1, 0.2, 0.3, 0.45, 0.6, 0.75, 0.9, 0.95, 1.05, 1.1, 1.3, 1.6,
                                          2.0, 3.0, 5.0]
    curves = [(f"β/β* = {name}", eta, f * bs, chis) for name, f in (("1/3", 1 / 3), ("1", 1), ("3", 3))]
    sim = _sweep("fig9", curves, t0, rows)
    ref = _mat(eta, bs / 3)
    kp_t = theory.widened_kp(K1, ref["kp"], PHI_F, phiF_tuned)
    tuned = dict(ref, kp=kp_t, phiF=phiF_tuned)
    m_r = pair_reduced_mass()

    def e_tuned(chi):
        return theory.pair_collision(_speed(chi, ref), K1, kp_t, ref["kc"], phiF_tuned, RADIUS, m_r).e

    tuned_sim = []
    for chi in ([0.5, 3.0] if quick else [0.3, 0.7, 1.5, 3.0, 5.0]):
        r = collide_pair(tuned, _speed(chi, ref), max_contact_times=15)
        rows.append(("tuned", (kp_t - K1) / K1, ref["kc"] / K1, chi, _speed(chi, ref), r.e, e_tuned(chi), int(r.stuck)))
        tuned_sim.append((chi, r.e))
    grid = log_grid(0.01, 6.0, 500)
    same = max(abs(e_tuned(c) - theory.restitution_fa0(c, eta, bs / 3)) for c in grid if c <= 1)
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for (label, _, beta, _), color, (cin, cout) in zip(curves, ("tab:red", "tab:green", "tab:blue"),
                                                       (("r", "m"), ("g", "k"), ("b", "c"))):
        ax.plot(grid, [theory.restitution_fa0(c, eta, beta) for c in grid], "-", color=color, lw=1,
                label=f"Eqs. 32/33, {label} (β = {beta:.3g})")
        pts = sim[label]
        ax.plot([c for c, _ in pts if c <= 1], [e for c, e in pts if c <= 1], "o", mfc="none", color=cin)
        ax.plot([c for c, _ in pts if c > 1], [e for c, e in pts if c > 1], "s", mfc="none", color=cout)
    ax.plot(grid, [e_tuned(c) for c in grid], "r--", lw=1.2,
            label=f"tuned: φf' = {phiF_tuned:g}, kp' = {kp_t:.4g} N/m (Eq. A.3)")
    ax.plot(*zip(*tuned_sim), "rv", mfc="none", label="YADE, tuned")
    ax.plot([], [], "ko", mfc="none", label="YADE (circles χ ≤ 1, squares χ > 1)")
    _finish_sweep(fig, ax, outdir, "fig9_adhesivity", rows, f"Fig. 9: adhesivity around β* = {bs:.4g} (η = 4)",
                  f"kp = {ref['kp']:g} N/m, kc = β k1; " + PARAM_LINE, "coefficient of restitution e", 6.5)
    return dict(figure="long 9", collisions=len(rows), worst_abs_e_error=_worst(rows), kp_tuned=kp_t,
                tuned_equals_reference_below_chi1=same)


def fig10(outdir, quick=False, phiF_tuned=0.5, chis=(0.5, 1.0, 2.5)):
    """The force law with phiF and with phiF' (kp' of Eq. A.3): YADE loops at the same impact
    speeds for both, the branches k1, kp, kp', -kc drawn from the closed form."""
    eta, beta = 4.0, 1.0 / 9.0
    ref = _mat(eta, beta)
    kp_t = theory.widened_kp(K1, ref["kp"], PHI_F, phiF_tuned)
    tuned = dict(ref, kp=kp_t, phiF=phiF_tuned)
    dmp = theory.delta_max_p(K1, ref["kp"], PHI_F, RADIUS)
    m_r, rows, summary_rows = pair_reduced_mass(), [], []
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for chi, lw in zip(chis[:1] if quick else chis, (0.8, 1.0, 1.2)):
        v = _speed(chi, ref)
        for mat, style, name in ((ref, "k-", "reference"), (tuned, "r--", "tuned")):
            r = collide_pair(mat, v, max_contact_times=8, record=True, settle_contact_times=1)
            e_th = theory.pair_collision(v, K1, mat["kp"], mat["kc"], mat["phiF"], RADIUS, m_r).e
            summary_rows.append((name, chi, v, r.e, e_th, int(r.stuck)))
            tr = [t for t in r.trace if t[1] > 0]
            ax.plot([t[1] / dmp for t in tr], [t[2] * 1e3 for t in tr], style, lw=lw,
                    label=f"YADE {name}, χ = {chi:g}" + (" (sticks)" if r.stuck else f" (e = {r.e:.3f})"))
            rows += [(name, chi) + t for t in r.trace[::20]]  # every 20th step
            print(f"[fig10] {name} chi = {chi}: e = {r.e:.4f} (theory {e_th:.4f})", flush=True)
    x = [0, 3.2 * dmp]
    ax.plot([xi / dmp for xi in x], [K1 * xi * 1e3 for xi in x], "g:", lw=0.8, label="k1 δ")
    ax.plot([PHI_F * RADIUS / dmp, x[1] / dmp], [0, ref["kp"] * (x[1] - PHI_F * RADIUS) * 1e3], "b:", lw=0.8,
            label=f"kp (δ − φf a12), kp = {ref['kp']:g}")
    ax.plot([phiF_tuned * RADIUS / dmp, x[1] / dmp], [0, kp_t * (x[1] - phiF_tuned * RADIUS) * 1e3], "r:", lw=0.8,
            label=f"kp' (δ − φf' a12), kp' = {kp_t:.4g}")
    ax.plot([0, x[1] / dmp], [0, -ref["kc"] * x[1] * 1e3], "m:", lw=0.8, label="−kc δ")
    ax.set_xlim(0, 3.2)
    top = max(max(r[4] for r in rows), K1 * 3.2 * dmp)
    ax.set_ylim(-ref["kc"] * 3.2 * dmp * 1.1e3, 1.08e3 * top)
    ax.set_xlabel("δ / δ_max^p (reference)")
    ax.set_ylabel("hysteretic force f [mN]")
    ax.set_title(f"Fig. 10: force law with φf = {PHI_F:g} and φf' = {phiF_tuned:g} (Appendix A)")
    ax.legend(fontsize=6.5, loc="upper left")
    fig_note(fig, f"η = 4, β = 1/9 (kc = {ref['kc']:.4g} N/m); " + PARAM_LINE)
    save_figure(fig, outdir, "fig10_tuned_force_law")
    write_csv(os.path.join(outdir, "fig10_tuned_force_law.csv"),
              ["model", "chi", "time_s", "overlap_m", "hysteretic_force_N", "total_force_N"], rows)
    return dict(figure="long 10", collisions=len(summary_rows), kp_tuned=kp_t,
                worst_abs_e_error=max(abs(r[3] - r[4]) for r in summary_rows),
                loops=[dict(model=m, chi=c, e_yade=e, e_theory=et, stuck=s) for m, c, _, e, et, s in summary_rows])


def fig11(outdir, quick=False, gamma0=5e-3, kcs=(10.0, 100.0 / 3.0, 100.0), chi=1.0):
    """chi = 1, eta = 4, kc below, at and above beta* k1, with and without viscosity gamma0:
    force against overlap and delta/deltaMax^p against time."""
    eta = 4.0
    kcs = kcs[1:2] if quick else kcs
    dmp = theory.delta_max_p(K1, K1 * (1 + eta), PHI_F, RADIUS)
    fig, axes = plt.subplots(len(kcs), 2, figsize=(9, 3.0 * len(kcs)), squeeze=False)
    rows, cases = [], []
    for (axf, axt), kc, tag in zip(axes, kcs, ("ab", "cd", "ef")):
        beta = kc / K1
        for g, color, name in ((0.0, "tab:blue", "γ0 = 0"), (gamma0, "tab:red", f"γ0 = {gamma0:g} kg/s")):
            mat = _mat(eta, beta, gammaN=g)
            r = collide_pair(mat, _speed(chi, mat), max_contact_times=10 if quick else 30, record=True,
                             settle_contact_times=4 if quick else 8)
            e2 = theory.en_squared(chi, eta, beta)
            dc = theory.sticking_overlap(chi, eta, beta) if e2 <= 0 else None
            cases.append(dict(kc=kc, beta=beta, gamma0=g, stuck=r.stuck, e_yade=r.e, e_theory=math.sqrt(max(e2, 0)),
                              final_overlap_over_dmp=r.final_overlap / dmp if r.stuck else None,
                              delta_c_over_dmp_eq36_38=dc))
            tr = r.trace[::5]
            axf.plot([t[1] / dmp for t in tr if t[1] > 0], [t[3] * 1e3 for t in tr if t[1] > 0], "-", color=color,
                     lw=0.8, label=name)
            axt.plot([t[0] * 1e3 for t in tr], [t[1] / dmp for t in tr], "-", color=color, lw=0.8,
                     label=name + (": sticks" if r.stuck else f": e = {r.e:.4f}"))
            rows += [(kc, g) + t for t in r.trace[::50]]  # the CSV: every 50th step (the plot: every 5th)
            print(f"[fig11] kc = {kc:.4g}, gamma0 = {g:g}: " + (f"stuck at {r.final_overlap / dmp:.4f} dmp"
                                                                if r.stuck else f"e = {r.e:.5f}"), flush=True)
        rel = "<" if beta < theory.beta_star(eta) - 1e-9 else ">" if beta > theory.beta_star(eta) + 1e-9 else "="
        axf.set_title(f"({tag[0]}) kc = {kc:.4g} N/m, β {rel} β*", fontsize=9)
        axt.set_title(f"({tag[1]}) kc = {kc:.4g} N/m", fontsize=9)
        axf.set_xlabel("δ / δ_max^p")
        axf.set_ylabel("contact force f [mN]")
        axt.set_xlabel("t [ms]")
        axt.set_ylabel("δ / δ_max^p")
        axt.axhline(0, color="0.6", lw=0.5)
        axf.legend(fontsize=7)
        axt.legend(fontsize=7, loc="upper right")
    fig_note(fig, f"χ = {chi:g}, η = 4, β* = 1/3; " + PARAM_LINE.replace(", γ0 = 0", ""))
    fig.suptitle("Fig. 11: viscosity at χ = 1 for β below, at and above β*")
    save_figure(fig, outdir, "fig11_viscosity")
    write_csv(os.path.join(outdir, "fig11_viscosity.csv"),
              ["kc_N_m", "gamma0_kg_s", "time_s", "overlap_m", "hysteretic_force_N", "total_force_N"], rows)
    return dict(figure="long 11", collisions=len(cases), cases=cases,
                note="no closed form with viscosity: the viscous runs are compared with the non-viscous closed form")


def _within(grid, exact, approx, tol=0.05):
    """Smallest chi of the grid from which on approx stays within tol of exact (None if nowhere)."""
    ok = [abs(approx(c) / exact(c) - 1.0) <= tol if exact(c) > 0 else False for c in grid]
    for i in range(len(grid)):
        if all(ok[i:]):
            return grid[i]
    return None


def fig12(outdir, quick=False, etas=(5.0, 50.0, 500.0)):
    """log-log e(chi <= 1) for beta = 0 and eta = 5, 50, 500 with the asymptote (eta chi)^-1/2 (C.2)."""
    t0, rows = time.time(), []
    chis = [0.01, 0.3] if quick else log_grid(0.001, 1.0, 10)
    curves = [(f"η = {eta:g}", eta, 0.0, chis) for eta in etas]
    sim = _sweep("fig12", curves, t0, rows)
    grid = log_grid(0.001, 1.0, 300)
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    holds = {}
    for (label, eta, _, _), color in zip(curves, ("tab:red", "tab:green", "tab:blue")):
        ax.plot(grid, [theory.restitution_fa0(c, eta, 0.0) for c in grid], "-", color=color, lw=0.8, alpha=0.6)
        ax.plot(grid, [theory.restitution_asymptote(c, eta) for c in grid], "--", color=color, lw=1.2,
                label=f"(ηχ)^−1/2, {label} (Eq. C.2)")
        ax.plot(*zip(*sim[label]), "o", mfc="none", color=color, label=f"YADE, {label}")
        holds[label] = _within(grid, lambda c: theory.restitution_fa0(c, eta, 0.0),
                               lambda c: theory.restitution_asymptote(c, eta))
    ax.plot([], [], "k-", lw=0.8, alpha=0.6, label="Eq. 32 (thin)")
    ax.set_yscale("log")
    ax.set_ylim(0.03, 1.5)
    _finish_sweep(fig, ax, outdir, "fig12_asymptote_eta", rows, "Fig. 12: β = 0, large plasticity η",
                  "kp = k1 (1 + η), kc = 0; " + PARAM_LINE)
    return dict(figure="long 12", collisions=len(rows), worst_abs_e_error=_worst(rows),
                asymptote_within_5pct_from_chi=holds)


def fig13(outdir, quick=False, betas=(0.01, 0.1, 1.0), eta=50.0):
    """log-log e(chi <= 1) at eta = 50 for beta = 0.01, 0.1, 1 with sqrt(1/(eta chi) - beta) (C.3)
    and the chi^-1/4, chi^-1/2 guides."""
    t0, rows = time.time(), []
    chis = [0.003, 0.3] if quick else log_grid(0.001, 1.0, 10)
    curves = [(f"β = {b:g}", eta, b, chis) for b in betas]
    sim = _sweep("fig13", curves, t0, rows)
    grid = log_grid(0.001, 1.0, 300)
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    holds = {}
    for (label, _, b, _), color in zip(curves, ("tab:red", "tab:green", "tab:blue")):
        ax.plot(grid, [theory.restitution_fa0(c, eta, b) or float("nan") for c in grid], "-", color=color, lw=0.8,
                alpha=0.6)
        ax.plot(grid, [theory.restitution_asymptote(c, eta, b) or float("nan") for c in grid], "--", color=color,
                lw=1.2, label=f"sqrt(1/(ηχ) − β), {label} (Eq. C.3)")
        pts = sim[label]
        ax.plot([c for c, e in pts if e > 0], [e for c, e in pts if e > 0], "o", mfc="none", color=color,
                label=f"YADE, {label}")
        stuck = [c for c, e in pts if e == 0]
        if stuck:
            ax.plot(stuck, [0.012 * 1.1 ** len(holds)] * len(stuck), "x", color=color, label=f"YADE sticks, {label}")
        holds[label] = _within(grid, lambda c: theory.restitution_fa0(c, eta, b),
                               lambda c: theory.restitution_asymptote(c, eta, b))
    c0 = 0.02  # the guide's anchor: the weakest adhesion's closed form
    e0 = theory.restitution_fa0(c0, eta, betas[0])
    ax.plot(grid, [e0 * (c / c0) ** -0.25 for c in grid], "k-", lw=0.8, label="∝ χ^−1/4")
    ax.plot(grid, [(eta * c) ** -0.5 for c in grid], "m-", lw=0.8, label="(ηχ)^−1/2")
    ax.set_yscale("log")
    ax.set_ylim(0.01, 1.5)
    _finish_sweep(fig, ax, outdir, "fig13_asymptote_beta", rows, f"Fig. 13: adhesivity β at η = {eta:g}",
                  f"kp = {K1 * (1 + eta):g} N/m, kc = β k1; " + PARAM_LINE, "e (× at the bottom: the pair sticks)", 6.5)
    return dict(figure="long 13", collisions=len(rows), worst_abs_e_error=_worst(rows),
                asymptote_within_5pct_from_chi=holds)


def fig14(outdir, quick=False, eta=50.0):
    """Linear (Eq. 9) against square-root (Eq. D.1) k2 interpolation, eta = 50, beta = 0, with
    the asymptotes (eta chi)^-1/2 and (eta sqrt(chi))^-1/2 (D.2)."""
    t0, rows = time.time(), []
    chis = [0.01, 0.5] if quick else log_grid(0.001, 1.0, 10)
    sim = _sweep("fig14 linear", [("linear", eta, 0.0, chis)], t0, rows)
    sim.update(_sweep("fig14 sqrt", [("sqrt", eta, 0.0, chis)], t0, rows, interpolation="sqrt"))
    grid = log_grid(0.001, 1.0, 300)
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    holds = {}
    for interp, color, asym in (("linear", "tab:red", "(ηχ)^−1/2 (C.2)"), ("sqrt", "tab:blue", "(η√χ)^−1/2 (D.2)")):
        ax.plot(grid, [theory.restitution_fa0(c, eta, 0.0, interp) for c in grid], "-", color=color, lw=0.8, alpha=0.6)
        ax.plot(grid, [theory.restitution_asymptote(c, eta, 0.0, interp) for c in grid], "--", color=color, lw=1.2,
                label=f"{interp}: {asym}")
        ax.plot(*zip(*sim[interp]), "o", mfc="none", color=color, label=f"YADE, {interp} k2")
        holds[interp] = _within(grid, lambda c: theory.restitution_fa0(c, eta, 0.0, interp),
                                lambda c: theory.restitution_asymptote(c, eta, 0.0, interp))
    ax.plot([], [], "k-", lw=0.8, alpha=0.6, label="Eq. 32 with Eq. 9 / D.1 (thin)")
    ax.set_ylim(0, 1.05)
    _finish_sweep(fig, ax, outdir, "fig14_interpolation", rows, f"Fig. 14: k2 interpolation, η = {eta:g}, β = 0",
                  f"kp = {K1 * (1 + eta):g} N/m, kc = 0; " + PARAM_LINE, legend_loc="upper right")
    return dict(figure="long 14", collisions=len(rows), worst_abs_e_error=_worst(rows),
                asymptote_within_5pct_from_chi=holds)


def _branch_potential(branch, f, k1, k2, kc):
    """The paper's plastic "potential" of Fig. 15(a, c): the energy of the branch the contact is on,
    each branch counted from its own zero: loading f^2/(2 k1), un-/re-loading (and the limit line)
    f^2/(2 k2), the tensile limit -f^2/(2 kc) (attractive: negative), none out of contact."""
    if branch == "loading":
        return f * f / (2 * k1)
    if branch in ("unloading", "limit"):
        return f * f / (2 * k2)
    if branch == "tensile":
        return -f * f / (2 * kc) if kc > 0 else 0.0
    return 0.0


def fig15(outdir, quick=False, chis=(0.34, 0.69)):
    """The paper's four panels (eta = 4, beta = 1), from YADE's collision: (a, c) kinetic energy and
    the plastic "potential" (the energy of the contact's current branch, negative on the -kc branch,
    _branch_potential), (b, d) kinetic and the available (elastic) energy, what the contact would give
    back along its k2 line ('mesoElastic'); the times where the overlap passes the closed form's
    delta0, deltaMin (and deltaC, where the pair sticks) marked. The energy balance (kinetic + stored
    + dissipated = E0) is checked on every sample."""
    from yade import O
    eta, beta = 4.0, 1.0
    mat = _mat(eta, beta)
    fig, axes = plt.subplots(2, len(chis), figsize=(5.2 * len(chis), 6.6), squeeze=False)
    rows, cases = [], []
    for col, chi in enumerate(chis):
        v = _speed(chi, mat)
        s = pair.build(RADIUS, v, mat, track_energy=True)
        e0 = 0.5 * s.m_r * v ** 2  # no force acts before contact: the kinetic energy is exact
        t_load = math.pi * math.sqrt(s.m_r / K1)
        samples = []
        sampler = _loop.runner(lambda: samples.append(_sample(s)), 1 if quick else 20, "fig15Sampler")
        O.engines = O.engines + [sampler]
        O.run(int((3 if quick else 6) * t_load / O.dt), True)
        kc = mat["kc"]
        potential = [_branch_potential(x[7], x[8], K1, x[9], kc) for x in samples]
        worst = max(abs(x[5] - e0) for x in samples) / e0
        # closed form of this collision (fa = 0): deltaMax (Eq. 20b), k2, delta0, deltaMin, deltaC
        d_max = theory.max_overlap(v, K1, mat["kp"], PHI_F, s.a12, s.m_r)
        k2 = K1 * theory.k2_over_k1(chi, eta)
        d0 = (1 - K1 / k2) * d_max
        d_min = k2 * d0 / (k2 + kc)
        sticks = theory.en_squared(chi, eta, kc / K1) <= 0
        marks = [("δ0", d0), ("δmin", d_min)] + (
            [("δc", theory.sticking_overlap(chi, eta, kc / K1) * theory.delta_max_p(K1, mat["kp"], PHI_F, s.a12))]
            if sticks else [])
        ms = [x[0] * 1e3 for x in samples]
        state = "sticks" if sticks else f"rebounds, e = {theory.restitution_fa0(chi, eta, beta):.3f}"
        first_below = {}
        unloading = False
        for x in samples:  # the first time the overlap falls to delta0 and deltaMin after deltaMax
            unloading = unloading or x[7] in ("unloading", "tensile")
            for name, d in marks[:2]:
                if unloading and name not in first_below and x[6] <= d:
                    first_below[name] = x[0] * 1e3
        delta_c_yade = None
        if sticks:  # deltaC: the lower turning point after deltaMin, where the stuck pair first comes to rest
            after = [x for x in samples if x[0] * 1e3 >= first_below.get("δmin", 0.0)]
            k = next((n for n in range(1, len(after) - 1) if after[n][6] <= after[n - 1][6]
                      and after[n][6] < after[n + 1][6]), None)
            if k is not None:
                first_below["δc"] = after[k][0] * 1e3
                delta_c_yade = after[k][6]
        for row, (label, values, color) in enumerate((("plastic “potential” (current branch)", potential, "tab:red"),
                                                      ("available elastic (mesoElastic, along k2)",
                                                       [x[2] for x in samples], "tab:blue"))):
            ax = axes[row][col]
            ax.plot(ms, [x[1] / e0 for x in samples], "k-", lw=1, label="kinetic")
            ax.plot(ms, [y / e0 for y in values], "-", color=color, lw=1.2, label=label)
            ax.axhline(0, color="0.6", lw=0.5)
            # above the panel; delta0 and deltaMin lie close together
            for n, (name, t) in enumerate(first_below.items()):
                ax.axvline(t, color="0.5", lw=0.6, ls=":")
                ax.text(t, 1.01, (name + " ") if n == 0 else (" " + name), fontsize=7, color="0.3",
                        ha="right" if n == 0 else "left", va="bottom", transform=ax.get_xaxis_transform())
            panel = "abcd"[2 * col + row]
            ax.set_title(f"({panel}) χ = {chi:g}: {state}", fontsize=9, pad=11)
            ax.set_xlabel("t [ms]")
            ax.set_ylabel("energy / E_kin(0)")
            ax.set_xlim(0, min(ms[-1], 1.6 * t_load * 1e3))  # the contact and a few oscillations of a stuck pair
            ax.legend(fontsize=6.5, loc="upper right")
        low = min(potential) / e0
        cases.append(dict(chi=chi, worst_abs_sum_error_over_E0=worst, samples=len(samples), sticks=sticks,
                          min_plastic_potential_over_E0=low, min_available_over_E0=min(x[2] for x in samples) / e0,
                          overlap_marks_ms=first_below, delta_c_closed_form=marks[2][1] if sticks else None,
                          delta_c_yade=delta_c_yade,
                          plastic_potential_after_stick_over_E0=(potential[-1] / e0) if sticks else None))
        rows += [(chi,) + x[:7] + (x[8], p) for x, p in zip(samples, potential)]
        print(f"[fig15] chi = {chi}: {len(samples)} samples, worst |sum - E0|/E0 = {worst:.2e}, lowest plastic "
              f"potential {low:.3f} E0",
              flush=True)
    fig_note(fig, "η = 4, β = 1; " + PARAM_LINE)
    fig.suptitle("Fig. 15: kinetic and potential energies of one collision (YADE)")
    save_figure(fig, outdir, "fig15_energies")
    write_csv(os.path.join(outdir, "fig15_energies.csv"),
              ["chi", "time_s", "kinetic_J", "mesoElastic_J", "mesoPlastic_J", "mesoAdhesive_J", "total_J",
               "overlap_m",
               "hystereticForce_N", "plastic_potential_J"], rows)
    return dict(figure="long 15", collisions=len(cases), cases=cases,
                worst_abs_sum_error_over_E0=max(c["worst_abs_sum_error_over_E0"] for c in cases))


def _sample(s):
    """fig15: one row of the collision's energies and contact state, taken inside YADE's loop (one O.run)."""
    from yade import O
    en = {k: O.energy[k] for k in O.energy.keys()}
    i = O.interactions[s.ids[0], s.ids[1]] if O.interactions.has(s.ids[0], s.ids[1]) else None
    real = i is not None and i.isReal
    return (O.time, en.get("kinetic", 0.0), en.get("mesoElastic", 0.0), en.get("mesoPlastic", 0.0),
            en.get("mesoAdhesive", 0.0), O.energy.total(), pair.overlap(s),
            i.phys.branch if real else "apart", i.phys.hystereticForce if real else 0.0,
            i.phys.k2 if real else K1)
