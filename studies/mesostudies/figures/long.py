"""Figs. 5-8 of the long paper: restitution with and without adhesion, sticking overlap and
force-overlap loops, YADE pair collisions over the closed form (inside ``yade``). Each function
writes a CSV of the simulated points and a PNG with the simulation over the theory, prints
progress, and returns the rows."""
import math
import os
import time

from mesocontact import pair, params, theory
from .common import (
    DENSITY, PAPER, PARAM_NOTE, RADIUS, fig_note, pair_reduced_mass, plt, print_progress,
    save_figure, write_csv,
)


def fig5(outdir, alphas=(0.042, 0.42), zetas=None, kca=100.0):
    """e versus zeta = v_i/v_p with jump-in adhesion, fa from alpha at v_i = 0.01 m/s."""
    zetas = zetas or [0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1.0, 1.1, 1.2, 1.5, 2, 3, 5]
    m_r, a12, rows, t0 = pair_reduced_mass(), RADIUS, [], time.time()
    fig, ax = plt.subplots(figsize=(6, 4.2))
    n = len(alphas) * len(zetas)
    for k, (alpha, color) in enumerate(zip(alphas, ("tab:red", "tab:blue"))):
        fa = params.fa_from_alpha(alpha, PAPER["k1"], m_r, 0.01)
        mat = dict(PAPER, fa=fa, kca=kca, adhesion="jumpIn")
        v_p = theory.plastic_limit_velocity(PAPER["k1"], PAPER["kp"], PAPER["phiF"], a12, m_r, fa)
        grid = [10 ** (math.log10(0.001) + i * (math.log10(10) - math.log10(0.001)) / 600) for i in range(601)]
        th = [theory.pair_collision(z * v_p, PAPER["k1"], PAPER["kp"], PAPER["kc"], PAPER["phiF"], a12, m_r,
                                    fa=fa, kca=kca, adhesion="jumpIn").e for z in grid]
        ax.plot([z for z in grid if z < 1], [e for z, e in zip(grid, th) if z < 1], "-", color=color, lw=1.2,
                label=f"theory Eq. 30, α = {alpha}")
        ax.plot([z for z in grid if z >= 1], [e for z, e in zip(grid, th) if z >= 1], "--", color=color, lw=1.2,
                label=f"theory Eq. 31, α = {alpha}")
        sim = []
        for j, z in enumerate(zetas):
            s = pair.build(RADIUS, z * v_p, dict(mat, density=DENSITY))
            r = pair.collide(s, max_contact_times=15)
            e_th = theory.pair_collision(z * v_p, PAPER["k1"], PAPER["kp"], PAPER["kc"], PAPER["phiF"], a12, m_r,
                                         fa=fa, kca=kca, adhesion="jumpIn").e
            rows.append((alpha, fa, z, z * v_p, r.e, e_th, int(r.stuck)))
            sim.append((z, r.e))
            print_progress("fig5", k * len(zetas) + j + 1, n, t0)
        ax.plot(*zip(*sim), "o" if k == 0 else "s", mfc="none", color=color, label=f"YADE, α = {alpha}")
    ax.set_xscale("log")
    ax.set_xlabel("ζ = v_i / v_p")
    ax.set_ylabel("coefficient of restitution e")
    ax.set_title("Fig. 5: jump-in adhesion, η = 4, β = 1")
    ax.legend(fontsize=7, loc="lower left", bbox_to_anchor=(0.0, 0.08))
    fig_note(fig, PARAM_NOTE + f", φf = {PAPER['phiF']:g}, kca = {kca:g} N/m, f_a from α at v_i = 0.01 m/s")
    save_figure(fig, outdir, "fig5_restitution_adhesive")
    write_csv(os.path.join(outdir, "fig5_restitution_adhesive.csv"),
              ["alpha", "fa_N", "zeta", "v_inf_m_s", "e_yade", "e_theory", "stuck"], rows)
    return rows


def _finish_fa0(fig, ax, outdir, stem, ylabel, title):
    """Labels, legend, the parameter note (f_a = 0) and the file of a panel over χ."""
    ax.set_xlabel("χ = v_i / v_p")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.legend()
    fig_note(fig, PARAM_NOTE + f", φf = {PAPER['phiF']:g}, f_a = 0")
    save_figure(fig, outdir, stem)


def fig6_fig8(outdir, chis=None):
    """Fig. 6: e(chi) for fa = 0, eta = 4, beta = 1; Fig. 8: sticking overlap delta_c/deltaMax^p."""
    chis = chis or [0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.34, 0.45, 0.5, 0.55, 0.6, 0.7, 0.8, 0.9, 1.0,
                    1.05, 1.1, 1.15, 1.2, 1.37, 1.6, 2, 3, 5, 10]
    m_r, a12, rows, t0 = pair_reduced_mass(), RADIUS, [], time.time()
    eta, beta = 4.0, 1.0
    dmp = theory.delta_max_p(PAPER["k1"], PAPER["kp"], PAPER["phiF"], a12)
    for j, chi in enumerate(chis):
        v = theory.impact_velocity_for_chi(chi, PAPER["k1"], PAPER["kp"], PAPER["phiF"], a12, m_r)
        s = pair.build(RADIUS, v, dict(PAPER, density=DENSITY))
        r = pair.collide(s, max_contact_times=15)
        e_th = theory.restitution_fa0(chi, eta, beta)
        dc_th = theory.sticking_overlap(chi, eta, beta) if e_th == 0 else float("nan")
        rows.append((chi, v, r.e, e_th, int(r.stuck), r.final_overlap / dmp if r.stuck else float("nan"), dc_th))
        print_progress("fig6/8", j + 1, len(chis), t0)
    grid = [10 ** (-3 + i * 4.0 / 800) for i in range(801)]
    fig, ax = plt.subplots(figsize=(6, 4.2))
    ax.plot([c for c in grid if c <= 1], [theory.restitution_fa0(c, eta, beta) for c in grid if c <= 1], "r-",
            label="Eq. 32")
    ax.plot([c for c in grid if c > 1], [theory.restitution_fa0(c, eta, beta) for c in grid if c > 1], "b--",
            label="Eq. 33")
    ax.plot([c for c in grid if c < 0.3], [theory.low_velocity_restitution(c, eta) for c in grid if c < 0.3], "k-",
            lw=0.6, label="1 − ηχ/2")
    ax.plot([r[0] for r in rows], [r[2] for r in rows], "ko", mfc="none", label="YADE")
    ax.set_xscale("log")
    _finish_fa0(fig, ax, outdir, "fig6_restitution", "e", "Fig. 6: f_a = 0, η = 4, β = 1")

    lo, hi = theory.chi_c_b(eta, beta), theory.chi_c_c(eta, beta)
    fig, ax = plt.subplots(figsize=(6, 4.2))
    g = [lo + (hi - lo) * (1e-9 + (1 - 2e-9) * i / 400) for i in range(401)]  # inside the window
    ax.plot([c for c in g if c <= 1], [theory.sticking_overlap(c, eta, beta) for c in g if c <= 1], "r-",
            label="Eq. 36")
    ax.plot([c for c in g if c > 1], [theory.sticking_overlap(c, eta, beta) for c in g if c > 1], "b-", label="Eq. 38")
    stuck = [(r[0], r[5]) for r in rows if r[4]]
    if stuck:
        ax.plot(*zip(*stuck), "ko", mfc="none", label="YADE")
    _finish_fa0(fig, ax, outdir, "fig8_sticking_overlap", "δ_c / δ_max^p", "Fig. 8: sticking overlap, η = 4, β = 1")
    write_csv(os.path.join(outdir, "fig6_restitution.csv"),
              ["chi", "v_inf_m_s", "e_yade", "e_theory", "stuck", "delta_c_over_dmp_yade", "delta_c_over_dmp_theory"],
              rows)
    return rows


def fig7(outdir, chis=(0.34, 0.69, 1.1, 1.37), phiF=0.05):
    """Force-overlap loops of single collisions (eta = 4, beta = 1, phiF = 0.05)."""
    m_r, a12 = pair_reduced_mass(), RADIUS
    mat = dict(PAPER, phiF=phiF, density=DENSITY)
    dmp = theory.delta_max_p(PAPER["k1"], PAPER["kp"], phiF, a12)
    fig, axes = plt.subplots(2, 2, figsize=(8, 6.4))
    rows = []
    for ax, chi, tag in zip(axes.flat, chis, "abcd"):
        v = theory.impact_velocity_for_chi(chi, PAPER["k1"], PAPER["kp"], phiF, a12, m_r)
        s = pair.build(RADIUS, v, mat)
        r = pair.collide(s, max_contact_times=6, record=True, settle_contact_times=2)
        tr = [t for t in r.trace if t[1] > 0]
        ax.plot([t[1] * 1e6 for t in tr], [t[2] * 1e3 for t in tr], "k-", lw=1, label="YADE")
        dmax = max(t[1] for t in tr)
        x = [0, max(dmax, dmp) * 1.05]
        ax.plot([xi * 1e6 for xi in x], [PAPER["k1"] * xi * 1e3 for xi in x], "g:", lw=0.8, label="k1 δ")
        ax.plot([xi * 1e6 for xi in x], [-PAPER["kc"] * xi * 1e3 for xi in x], "m:", lw=0.8, label="−kc δ")
        ax.plot([phiF * a12 * 1e6, x[1] * 1e6], [0, PAPER["kp"] * (x[1] - phiF * a12) * 1e3], "b:", lw=0.8,
                label="kp (δ − φf a12)")
        ax.set_title(f"({tag}) χ = {chi}: " + ("sticks" if r.stuck else f"e = {r.e:.3f}"), fontsize=9)
        ax.set_xlabel("δ [µm]")
        ax.set_ylabel("f [mN]")
        ax.set_ylim(-PAPER["kc"] * dmax * 1.3e3,
                    PAPER["kp"] * max(dmax - phiF * a12, 0) * 1.2e3 + PAPER["k1"] * dmax * 1.2e3)
        rows += [(chi, t[0], t[1], t[2], t[3]) for t in r.trace[::10]]  # every 10th step
        print(f"[fig7] chi = {chi}: {'stuck' if r.stuck else 'e = %.4f' % r.e}", flush=True)
    axes.flat[0].legend(fontsize=7)
    fig.suptitle("Fig. 7: force–overlap loops, η = 4, β = 1, φf = 0.05")
    fig_note(fig, PARAM_NOTE + f", φf = {phiF:g}, f_a = 0")
    save_figure(fig, outdir, "fig7_force_overlap")
    write_csv(os.path.join(outdir, "fig7_force_overlap.csv"),
              ["chi", "time_s", "overlap_m", "hysteretic_force_N", "total_force_N"], rows)
    return rows
