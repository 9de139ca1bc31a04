"""A calibration run through YADE (pair collisions at the data's speeds) and its picture."""
import math
import warnings

import numpy as np

from .. import theory as _theory
from .data import PARAMETERS, UNITS, Setup, geometry
from .groups import material


def yade_check(fitted, velocities, radius, density, against="particle", progress=True):
    """Pair collisions in YADE (inside ``yade``) with the fitted parameters at the given speeds:
    a list of (v, e_yade, e_fitted_curve). fitted: calibration.json's dict."""
    from .. import pair  # needs YADE
    kca = fitted["kca"] if fitted.get("kca") is not None else math.inf
    with warnings.catch_warnings():  # the report said which parameters are undetermined; the check runs the fit's point
        warnings.simplefilter("ignore", UserWarning)
        mat = material(fitted, density=density)
    # calibration.json before the fit's point was written: the values themselves
    point = fitted.get("fit_point") or fitted
    setup = Setup(*geometry(radius, density, against), fitted["adhesion"], kca, fitted["k2Interpolation"])
    out = []
    for i, v in enumerate(velocities):
        s = pair.build(radius, float(v), dict(mat)) if against == "particle" else \
            pair.build_wall(radius, float(v), dict(mat), wall_material=dict(mat))
        r = pair.collide(s, max_contact_times=15)
        e_fit = float(setup.curve(float(v), point)[0])
        out.append((float(v), float(r.e), e_fit))
        if progress:
            print(f"  YADE check {i + 1}/{len(velocities)}: v = {v:.4g} m/s  e_yade = {r.e:.5f}  e_fit = {e_fit:.5f}",
                  flush=True)
    return out


def plot(fit, path, yade_points=None, truth=None):
    """Data with error bars, the fitted curve, the YADE collisions, the regimes shaded."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from .. import outputs as _out
    d = fit.data
    vv = np.geomspace(d.v.min() / 3, d.v.max() * 3, 600)
    ee = fit.curve(vv)
    p = fit.params
    v_p = _theory.plastic_limit_velocity(p["k1"], p["kp"], p["phiF"], fit.setup.a12, fit.setup.m_r,
                                         p["fa"] if fit.setup.adhesion != "none" else 0.0)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    stuck = ee == 0
    edges = np.flatnonzero(np.diff(np.r_[0, stuck.astype(int), 0]))
    for a, b in zip(edges[::2], edges[1::2]):
        ax.axvspan(vv[a], vv[b - 1], color="0.85", lw=0, label="sticking" if a == edges[0] else None)
    ax.axvspan(v_p, vv[-1], color="#fde7c8", lw=0, zorder=0, label=f"beyond v_p = {v_p:.3g} m/s")
    ax.plot(vv, ee, "-", color="C0", label="fitted closed form")
    if truth is not None:
        ax.plot(vv, fit.setup.curve(vv, truth), ":", color="k", lw=1, label="true parameters")
    if d.sigma is not None:
        ax.errorbar(d.v, d.e, yerr=d.sigma, fmt="s", ms=4, color="C3", capsize=2, label="data")
    else:
        ax.plot(d.v, d.e, "s", ms=4, color="C3", label="data")
    if yade_points:
        ax.plot([x[0] for x in yade_points], [x[1] for x in yade_points], "o", mfc="none", color="C2", ms=8,
                label="YADE, fitted parameters")
    ax.set_xscale("log")
    ax.set_xlim(vv[0], vv[-1])
    ax.set_ylim(-0.03, 1.03)
    ax.set_xlabel("approach speed v [m/s]")
    ax.set_ylabel("restitution e")
    txt = ", ".join(_title_value(fit, n) for n in PARAMETERS if n != "fa" or fit.setup.adhesion != "none")
    mode = "no adhesion" if fit.setup.adhesion == "none" else \
        f"adhesion {fit.setup.adhesion!r}, kca = {fit.setup.kca:.3g} N/m assumed"
    ax.set_title(f"{mode}; free: {', '.join(fit.free)}\n{txt}", fontsize=9)
    if fit.v_p_edge:  # one point sets v_p: the curve past the data is the closed form's, not the data's
        ax.plot([], [], " ", label=f"v_p at the data's {' and '.join(e['side'] for e in fit.v_p_edge)} edge: "
                "the curve past the data is extrapolated")
    for x in (d.v.min(), d.v.max()):  # the data's range: beyond it the curve is the model's alone
        ax.axvline(x, color="0.5", lw=0.6, ls=":")
    ax.legend(fontsize=8, loc="best")
    fig.tight_layout()
    _out.savefig_atomic(fig, path, dpi=120)
    plt.close(fig)


def _title_value(fit, n):
    """'kp = 500 N/m', or 'kc undetermined (at most 0.0012 N/m)' for a parameter the data do not fix."""
    if n in fit.undetermined:
        b = fit.bound(n)
        return f"{n} undetermined" + ("" if b.startswith("no bound") else f" ({b})")
    return f"{n} = {fit.params[n]:.3g}" + (" " + UNITS[n] if UNITS[n] else "")
