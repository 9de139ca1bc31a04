"""Figs. 5 and 6 of the short paper ("Sticking of adhesive particles in elasto-plastic
collisions"): e against the approach speed v_i^inf with jump-in adhesion (the non-contact
stiffness is kc there: kca = kc). YADE pair collisions over the closed form, inside ``yade``."""
import os
import time

from mesocontact import theory
from .appendix import collide_pair, log_grid, plot_live
from .common import (
    DENSITY, PAPER, RADIUS, fig_note, pair_reduced_mass, plt, print_progress, save_figure,
    write_csv,
)

SHORT = dict(k1=100.0, kp=500.0, kc=100.0, phiF=PAPER["phiF"])
FA = 5e-7  # N, Fig. 5


def _e_theory(v, mat, fa):
    return theory.pair_collision(v, mat["k1"], mat["kp"], mat["kc"], mat["phiF"], RADIUS, pair_reduced_mass(), fa=fa,
                                 kca=mat["kc"], adhesion="jumpIn" if fa > 0 else "none").e


def _run(tag, curves, t0):
    """curves: (label, mat, fa, speeds) -> rows (label, fa, v, e_yade, e_theory, stuck)."""
    rows, n = [], sum(len(c[3]) for c in curves)
    for label, mat, fa, speeds in curves:
        m = dict(mat, density=DENSITY, fa=fa, kca=mat["kc"], adhesion="jumpIn" if fa > 0 else "none")
        for v in speeds:
            r = collide_pair(m, v, max_contact_times=15)
            rows.append((label, fa, v, r.e, _e_theory(v, mat, fa), int(r.stuck)))
            plot_live(v=v, e_yade=r.e, e_theory=rows[-1][4])
            print_progress(tag, len(rows), n, t0)
    return rows


def _plot(ax, curves, rows, colors, grid):
    for (label, mat, fa, _), color, marker in zip(curves, colors, "sodv^>"):
        ax.plot(grid, [_e_theory(v, mat, fa) for v in grid], "-", color=color, lw=1, label=f"theory, {label}")
        pts = [(r[2], r[3]) for r in rows if r[0] == label]
        ax.plot(*zip(*pts), marker, mfc="none", color=color, ms=4, label=f"YADE, {label}")
    ax.set_xscale("log")
    ax.set_xlabel("approach speed v_i^∞ [m/s]")
    ax.set_ylabel("coefficient of restitution e")


HEADER = ["curve", "fa_N", "v_inf_m_s", "e_yade", "e_theory", "stuck"]
PARAM_LINE = (f"k1 = 100, kc = kca = 100 N/m, φf = {PAPER['phiF']:g}, a = {RADIUS * 1e3:g} mm, "
              f"ρ = {DENSITY:g} kg/m³, jump-in")


def short_fig5(outdir, quick=False):
    """Irreversible elastic-adhesive (kp = k1) against elasto-plastic adhesive (kp = 5 k1) spheres,
    fa = 5e-7 N: one low-velocity sticking limit, a second sticking regime only with plasticity."""
    t0 = time.time()
    speeds = [1e-4, 0.1, 2.0] if quick else log_grid(1e-5, 3.0, 23)
    v_fa = FA / (pair_reduced_mass() * SHORT["kc"]) ** 0.5  # Eq. 19 of the short paper
    curves = [("elastic-adhesive (kp = k1)", dict(SHORT, kp=SHORT["k1"]), FA, speeds),
              ("elasto-plastic adhesive (kp = 5 k1)", SHORT, FA, speeds)]
    rows = _run("short fig5", curves, t0)
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    _plot(ax, curves, rows, ("tab:blue", "tab:red"), log_grid(1e-5, 3.0, 600))
    ax.axvline(v_fa, color="0.5", lw=0.6, ls=":")
    ax.text(v_fa * 1.1, 0.05, f"v_f^a = {v_fa:.2g} m/s", fontsize=7, color="0.3")
    ax.set_ylim(-0.02, 1.05)
    ax.set_title(f"Short paper, Fig. 5: f_a = {FA:g} N")
    ax.legend(fontsize=7, loc="center left")
    fig_note(fig, PARAM_LINE)
    save_figure(fig, outdir, "short_fig5_elastic_vs_plastic")
    write_csv(os.path.join(outdir, "short_fig5_elastic_vs_plastic.csv"), HEADER, rows)
    return dict(figure="short 5", collisions=len(rows), worst_abs_e_error=max(abs(r[3] - r[4]) for r in rows),
                v_fa=v_fa)


def _low_sticking_edge(mat, fa, lo=1e-9, hi=3.0):
    """The speed below which the pair sticks (the low-velocity limit v_f^a), by bisection on the
    closed form between lo (stuck) and the first rebound above it; None if it rebounds at lo."""
    if _e_theory(lo, mat, fa) > 0:
        return None
    grid = log_grid(lo, hi, 400)
    up = next((v for v in grid if _e_theory(v, mat, fa) > 0), None)
    if up is None:
        return hi  # stuck over the whole range
    a = grid[grid.index(up) - 1]
    for _ in range(100):
        mid = (a * up) ** 0.5
        a, up = (mid, up) if _e_theory(mid, mat, fa) == 0 else (a, mid)
    return up


def short_fig6(outdir, quick=False, fas=(0.0, 5e-9, 5e-7, 5e-5, 5e-3, 0.1)):
    """e against v_i^inf for several fa (elasto-plastic, kp = 5 k1), chosen so that each sentence of
    the paper can be read off the plotted range 1e-5 to 3 m/s: the low-velocity sticking limit v_f^a
    grows with fa; 0.1 N holds the pair at every plotted speed; 5e-9 N lies on the fa = 0 curve
    (within 1 %) over the whole range, its own sticking limit far below it."""
    t0 = time.time()
    fas = (0.0, 5e-9, 0.1) if quick else fas
    speeds = [1e-3, 0.1] if quick else log_grid(1e-5, 3.0, 15)
    curves = [(f"f_a = {fa:g} N", SHORT, fa, speeds) for fa in fas]
    rows = _run("short fig6", curves, t0)
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    _plot(ax, curves, rows, ("k", "tab:cyan", "tab:green", "tab:orange", "tab:red", "tab:purple"),
          log_grid(1e-5, 3.0, 600))
    ax.set_ylim(-0.02, 1.05)
    ax.set_title("Short paper, Fig. 6: the strength of the non-contact adhesion")
    ax.legend(fontsize=6, loc="center left", ncol=2)
    fig_note(fig, "kp = 500 N/m; " + PARAM_LINE)
    save_figure(fig, outdir, "short_fig6_adhesion_strength")
    write_csv(os.path.join(outdir, "short_fig6_adhesion_strength.csv"), HEADER, rows)
    grid = log_grid(1e-5, 3.0, 600)
    summary = []
    for fa in fas:
        on_fa0 = max(abs(_e_theory(v, SHORT, fa) - _e_theory(v, SHORT, 0.0)) / max(_e_theory(v, SHORT, 0.0), 1e-300)
                     for v in grid if _e_theory(v, SHORT, 0.0) > 0)
        stuck_yade = [r[2] for r in rows if r[1] == fa and r[5]]
        summary.append(dict(fa=fa, v_f_a=_low_sticking_edge(SHORT, fa), e_at_3=_e_theory(3.0, SHORT, fa),
                            sticks_at_every_plotted_speed=all(_e_theory(v, SHORT, fa) == 0 for v in grid),
                            largest_relative_departure_from_fa0=on_fa0, yade_stuck_speeds=len(stuck_yade)))
    return dict(figure="short 6", collisions=len(rows), worst_abs_e_error=max(abs(r[3] - r[4]) for r in rows),
                curves=summary)
