"""What the data determine: the Jacobian in the logarithms of the free parameters, its intervals,
the directions the data cannot see, and the regimes the data cover, in words."""
import math

import numpy as np

from .. import theory as _theory
from .data import Setup
from .problem import _scale

Z95 = 1.959963984540054           # two-sided 95 % quantile of the normal distribution
UNDETERMINED_FACTOR = 10.0        # a 95 % interval reaching beyond this factor either way: not determined
NULL_RCOND = 1e-7                 # singular values below this fraction of the largest: a direction the data cannot see
# v_p at the data's edge: fewer than EDGE_POINTS points faster than v_p (slower than it) while v_p lies
# below EDGE_FACTOR times the fastest speed (above the slowest over EDGE_FACTOR): one point, or the
# trend towards the last one, sets v_p, and the curve beyond it is the closed form's, not the data's.
EDGE_POINTS = 2
EDGE_FACTOR = 2.0


def _log_jacobian(names, p, setup, data, w):
    """d residual / d log(parameter) for each free parameter (central differences; a parameter at
    0 gets d/d(value) times a natural scale instead, flagged)."""
    cols, at_zero = [], []
    for n in names:
        h = 1e-5
        if p[n] > 0:
            pl, ph = dict(p), dict(p)
            pl[n], ph[n] = p[n] * math.exp(-h), p[n] * math.exp(h)
            if n == "kp" and pl[n] <= p["k1"]:
                pl[n] = p[n]
                cols.append((setup.curve(data.v, ph) - setup.curve(data.v, pl)) * w / h)
            elif n == "phiF" and ph[n] > 1:
                ph[n] = p[n]
                cols.append((setup.curve(data.v, ph) - setup.curve(data.v, pl)) * w / h)
            else:
                cols.append((setup.curve(data.v, ph) - setup.curve(data.v, pl)) * w / (2 * h))
            at_zero.append(False)
        else:
            scale = _scale(n, p["k1"], setup.m_r, data.v)
            ph = dict(p)
            ph[n] = h * scale
            cols.append((setup.curve(data.v, ph) - setup.curve(data.v, p)) * w / h)
            at_zero.append(True)
    return np.array(cols).T, at_zero


def _log_covariance(J, s2):
    """From the Jacobian J of the residuals in the fit's log coordinates and the noise variance s2:
    the standard deviations (inf along a direction the data cannot see), the correlation (a tiny
    ridge keeps it finite), the singular values and the right singular vectors."""
    U, sv, Vt = np.linalg.svd(J, full_matrices=False)
    null = sv < NULL_RCOND * max(sv.max(), 1e-300)
    # var(log p_i) = s2 sum_k V_ki^2 / sv_k^2; a null direction makes it infinite for the
    # parameters it involves
    with np.errstate(divide="ignore", invalid="ignore"):  # 0 x inf in the branch np.where discards
        inv = np.where(null, np.inf, 1.0 / np.where(null, 1.0, sv) ** 2)
        terms = np.where(Vt ** 2 > 1e-6, Vt ** 2 * inv[:, None], np.where(null[:, None], 0.0, Vt ** 2 * inv[:, None]))
    var = s2 * terms.sum(axis=0)
    sd = np.sqrt(var)
    ridge = 1e-12 * max(float(np.max(sv)) ** 2, 1e-300)
    C = np.linalg.inv(J.T @ J + ridge * np.eye(J.shape[1]))
    d = np.sqrt(np.diag(C))
    corr = (C / np.outer(d, d)).tolist()
    return sd, corr, sv, Vt


def _combinations(names, sv, Vt, s2, what):
    """Plain sentences on the weak directions: where moving the log parameters changes the data's
    model (``what``, e.g. "e(v)") by less than the noise over the interval factor."""
    statements = []
    weak = [k for k in range(len(sv)) if sv[k] == 0 or math.sqrt(s2) / sv[k] * Z95 > math.log(UNDETERMINED_FACTOR)]
    for k in weak:
        v = Vt[k]
        involved = [(names[i], v[i]) for i in range(len(names)) if abs(v[i]) > 0.05 * np.abs(v).max()]
        if len(involved) < 2:
            continue
        ref = max(involved, key=lambda t: abs(t[1]))[1]
        moves = ", ".join(f"{n} x lambda^{c / ref:+.2f}" for n, c in involved)
        statements.append(f"{', '.join(n for n, _ in involved)}: the data fix only a combination; {what} stays "
                          f"the same (to the noise) along {moves}; fix one of them")
    return statements


def _identify(names, p, setup, data, w, s2):
    """Covariance of the log parameters, 95 % intervals, correlation, the undetermined and why."""
    J, at_zero = _log_jacobian(names, p, setup, data, w)
    sd, corr, sv, Vt = _log_covariance(J, s2)
    ci, undetermined = {}, []
    for i, n in enumerate(names):
        if at_zero[i]:  # d/d(value/scale): the interval's upper end from the linear sd
            scale = _scale(n, p["k1"], setup.m_r, data.v)
            ci[n] = [0.0, float(Z95 * sd[i] * scale) if math.isfinite(sd[i]) else math.inf]
            if not math.isfinite(sd[i]):
                undetermined.append(n)
            continue
        f = math.exp(Z95 * sd[i]) if Z95 * sd[i] < 700 else math.inf  # exp overflows past 709
        lo, hi = p[n] / f, p[n] * f
        if n == "kp":
            lo = max(lo, p["k1"])
        if n == "phiF":
            hi = min(hi, 1.0)
        ci[n] = [lo, hi]
        if not f < UNDETERMINED_FACTOR:
            undetermined.append(n)
    statements = []
    colnorm = np.linalg.norm(J, axis=0)
    for i, n in enumerate(names):
        if n in undetermined and colnorm[i] <= 1e-6 * max(colnorm.max(), 1e-300):
            statements.append(f"{n}: e(v) does not depend on it at the data's speeds (no point where it acts)")
    statements += _combinations(names, sv, Vt, s2, "e(v)")
    return ci, corr, undetermined, statements


def _regimes(setup, p, data):
    counts = {}
    for v in data.v:
        o = setup.outcome(float(v), p)
        key = ("sticking" if o.e == 0 else "rebound") + (" beyond v_p" if o.plastic_limit else " below v_p")
        counts[key] = counts.get(key, 0) + 1
    return counts


def _coverage_statements(setup, p, data, free):
    """Which regimes the data miss, in words (the Jacobian says what that costs)."""
    v_p = _theory.plastic_limit_velocity(p["k1"], p["kp"], p["phiF"], setup.a12, setup.m_r,
                                         p["fa"] if setup.adhesion != "none" else 0.0)
    out = []
    if data.v.max() < v_p:
        out.append(f"all points below v_p = {v_p:.4g} m/s: kp and phiF act only through eta chi = eta v/v_p "
                   "(Eq. 32), and the limit branch is not seen")
    if data.v.min() > v_p:
        out.append(f"all points beyond v_p = {v_p:.4g} m/s: e^2 = 1 - (1 - e_p^2) (v_p/v)^2 (Eq. 33) fixes "
                   "one combination of eta, beta and v_p")
    if setup.adhesion != "none" and "fa" in free:
        p0 = dict(p, fa=0.0)
        de = np.abs(setup.curve(data.v, p) - setup.curve(data.v, p0))
        if not np.any(de > 0.01):
            out.append("no point where the non-contact force changes e by more than 0.01: "
                       "fa needs slower collisions")
    return out


def v_p_edge(v, v_p):
    """Where v_p lies at the edge of the speeds v: a list of {"side": "fast" or "slow", "points":
    the data points beyond v_p on that side, "speed": the fastest (slowest) speed}, empty when
    v_p has EDGE_POINTS or more points on each side or lies far outside the data (EDGE_FACTOR)."""
    v = np.asarray(v, float)
    faster, slower = int(np.sum(v > v_p)), int(np.sum(v < v_p))
    out = []
    if faster < EDGE_POINTS and v_p < EDGE_FACTOR * v.max():
        out.append({"side": "fast", "points": faster, "speed": float(v.max())})
    if slower < EDGE_POINTS and v_p > v.min() / EDGE_FACTOR:
        out.append({"side": "slow", "points": slower, "speed": float(v.min())})
    return out


def _edge_statements(edges, v_p, undetermined=()):
    """v_p_edge's edges in words; v_p is the fit's point when a parameter it depends on is undetermined."""
    loose = [n for n in undetermined if n in ("k1", "kp", "phiF", "fa")]
    out = []
    for e in edges:
        n, speed = e["points"], e["speed"]
        if e["side"] == "fast":
            out.append(f"v_p = {v_p:.4g} m/s lies at the fast edge of the data: {n} point{'' if n == 1 else 's'} "
                       f"faster than it (fewer than {EDGE_POINTS}; the fastest at {speed:.4g} m/s), so "
                       + ("one point sets v_p" if n == 1 else "the trend towards the fastest points alone sets v_p")
                       + "; beyond v_p the fitted e(v) climbs back towards 1 (Eq. 33), which the data do not show: "
                       f"use the curve only up to {speed:.4g} m/s, or measure faster")
        else:
            out.append(f"v_p = {v_p:.4g} m/s lies at the slow edge of the data: {n} point{'' if n == 1 else 's'} "
                       f"slower than it (fewer than {EDGE_POINTS}; the slowest at {speed:.4g} m/s), so e(v) below "
                       f"v_p (Eq. 32) rests on "
                       + ("one point" if n == 1 else "no point")
                       + f": use the curve only down to {speed:.4g} m/s, or measure slower")
    if loose and out:
        out[-1] += f" ({', '.join(loose)} undetermined: this v_p is the fit's point's, one of many that fit as well)"
    return out


def _kca_response(names, p, setup, data, w):
    """How the fit moves with the assumed kca (kca is not fitted): d ln(parameter)/d ln(kca) of the
    refitted free parameters, linearised at the fit (the least-squares response of the Jacobian
    in the log coordinates, the directions the data cannot see left out). Parameters at 0 are
    left out too (no logarithm)."""
    J, at_zero = _log_jacobian(names, p, setup, data, w)
    h = 1e-5
    moved = [Setup(setup.m_r, setup.a12, setup.adhesion, setup.kca * math.exp(s * h), setup.interpolation)
             for s in (-1, 1)]
    j = (moved[1].curve(data.v, p) - moved[0].curve(data.v, p)) * w / (2 * h)
    dx = -np.linalg.lstsq(J, j, rcond=NULL_RCOND)[0]
    return {n: float(dx[i]) for i, n in enumerate(names) if not at_zero[i]}


def _kca_statements(setup, response):
    """What the assumed kca does to the fit, in words (adhesion only)."""
    if setup.adhesion == "none":
        return []
    if not math.isfinite(setup.kca):
        return ["kca = inf is assumed, not fitted (--kca): no pull-off tail; a finite kca adds the tail's energy "
                "fa^2/(2 kca) to what e(v) sees, and the fit then gives another fa"]
    moves = [(n, s) for n, s in response.items() if abs(s) > 0.01]
    head = (f"kca = {setup.kca:.4g} N/m is assumed, not fitted (--kca), and the fit holds for it: e(v) sees the "
            "non-contact force through fa in contact and the pull-off tail's energy fa^2/(2 kca), so what the data fix "
            "is fa together with kca")
    if not moves:
        return [head + "; at these speeds the fit hardly moves with kca (every d ln p/d ln kca below 0.01)"]
    # x2, not x10: the slopes change along a decade of kca (measured: x2.5 predicted, x1.98 refitted)
    return [head + "; assuming kca x2 moves the fit to " + ", ".join(f"{n} x{2 ** s:.3g}" for n, s in moves)
            + " (" + ", ".join(f"d ln {n}/d ln kca = {s:+.3f}" for n, s in moves)
            + ", linearised at the fit; refit with another kca for a larger change)"]
