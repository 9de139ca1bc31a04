"""What force-displacement cycles determine (for cycles.fit_cycles): the Jacobian in the
logarithms of the free parameters (kc at 0 and the overlap's offset linear), the branches of the
law the cycles cover, in words, and profile-likelihood intervals."""
import math

import numpy as np
from scipy.optimize import brentq

from .. import theory as _theory
from .identify import UNDETERMINED_FACTOR, Z95, _combinations, _log_covariance
from .profile import PROFILE_CHI2, PROFILE_GRID

# the value an open side of an interval takes (None: k1)
_OPEN_END = {"k1": (0.0, math.inf), "kp": (None, math.inf), "kc": (0.0, math.inf), "phiF": (0.0, 1.0),
             "shift": (-math.inf, math.inf)}


def _jacobian(pb, names, p):
    """d residual / d coordinate: log of each parameter (central differences; one-sided at kp = k1
    and phiF = 1); kc at 0 per kc/k1 and shift per largest |delta|, linear. Also which are linear."""
    h, cols, linear = 1e-5, [], []
    for n in names:
        lo, hi = dict(p), dict(p)
        if n == "shift" or (n == "kc" and p["kc"] <= 0):
            unit = pb.dscale if n == "shift" else pb.kscale
            lo[n], hi[n] = p[n] - (h * unit if n == "shift" else 0.0), p[n] + h * unit
            linear.append(True)
        else:
            lo[n], hi[n] = p[n] * math.exp(-h), p[n] * math.exp(h)
            if n == "kp" and lo[n] <= p["k1"]:
                lo[n] = p[n]
            if n == "phiF" and hi[n] > 1:
                hi[n] = p[n]
            linear.append(False)
        step = (math.log(hi[n] / lo[n]) if not linear[-1]
                else (hi[n] - lo[n]) / (pb.dscale if n == "shift" else pb.kscale))
        # a value so small that the step does not move it (a subnormal) has no derivative: the data do not see it
        cols.append((pb.force(hi) - pb.force(lo)) * pb.w / step if step else np.zeros(len(pb.d)))
    return np.array(cols).T, linear


def _identify(pb, names, p, s2):
    """The Jacobian's intervals, correlation, the undetermined and the combinations the cycles fix."""
    J, linear = _jacobian(pb, names, p)
    sd, corr, sv, Vt = _log_covariance(J, s2)
    ci, undetermined = {}, []
    for i, n in enumerate(names):
        if linear[i]:
            unit = pb.dscale if n == "shift" else pb.kscale
            half = Z95 * sd[i] * unit if math.isfinite(sd[i]) else math.inf
            ci[n] = [p[n] - half if n == "shift" else 0.0, p[n] + half]
            if not (math.isfinite(half) and (n == "kc" or Z95 * sd[i] < 1)):  # shift: within the overlaps' size
                undetermined.append(n)
            continue
        f = math.exp(Z95 * sd[i]) if Z95 * sd[i] < 700 else math.inf  # exp overflows past 709
        ci[n] = [max(p[n] / f, p["k1"]) if n == "kp" else p[n] / f, min(p[n] * f, 1.0) if n == "phiF" else p[n] * f]
        if not f < UNDETERMINED_FACTOR:
            undetermined.append(n)
    colnorm = np.linalg.norm(J, axis=0)
    statements = [f"{n}: F(delta) does not depend on it along these cycles (no point where it acts)"
                  for i, n in enumerate(names) if colnorm[i] <= 1e-9 * max(colnorm.max(), 1e-300)]
    return ci, corr, undetermined, statements + _combinations(names, sv, Vt, s2, "F(delta)")


def _branches(pb, p):
    """(points per branch of the law, largest deltaMax, deltaMax^p) with the parameters p."""
    x = pb.d - p["shift"]
    _, dm, tensile, inv = _theory._force_path(x, p["k1"], p["kp"], p["kc"], p["phiF"], pb.a12, pb.interpolation, np)
    on_max = (x > 0) & (x == dm) & ~tensile
    limit = on_max & (dm * inv >= 1)
    counts = {"loading": int(np.sum(on_max & ~limit)), "limit": int(np.sum(limit)),
              "unloading": int(np.sum((x > 0) & ~on_max & ~tensile)), "tensile": int(np.sum(tensile)),
              "apart": int(np.sum(x <= 0))}
    return counts, float(np.max(dm)), (1 / inv if inv > 0 else math.inf)


def _coverage(pb, p):
    """What the cycles cover with the fitted parameters, in words."""
    counts, dm, dmp = _branches(pb, p)
    out = []
    if counts["tensile"] == 0:
        out.append("no point on the tensile branch -kc delta: the cycles do not see kc")
    if counts["unloading"] + counts["tensile"] == 0:
        out.append("no un- or re-loading point: kp and phiF are not seen")
    elif dm < dmp:
        comb = "(kp - k1)^2/(kp phiF)" if pb.interpolation == "linear" else "(kp - k1)^2/(kp phiF) (k2 with sqrt)"
        out.append(f"largest deltaMax {dm:.4g} below deltaMax^p = {dmp:.4g} (chi = {dm / dmp:.3g}): the limit branch "
                   f"is not seen, kp and phiF act only through k2(deltaMax), i.e. through {comb}")
    return counts, out


def _moves(m, p, pb):
    """(side, value at the profile's far end, path t -> value from the fit (t = 0) to it (t = 1),
    the path's inverse): by UNDETERMINED_FACTOR either way, geometric (kp through eta; phiF capped
    at 1); linear for shift (by the largest |delta|), for kc at 0 (up to k1/10) and for kp at k1
    (eta = 0 to rounding, where no factor moves it: up to 2 k1)."""
    f, v = UNDETERMINED_FACTOR, p[m]
    at_k1 = m == "kp" and not v / p["k1"] - 1 > 1e-12
    if m == "shift" or (m == "kc" and v <= 1e-12 * pb.kscale) or at_k1:
        ends = ([(0, v - pb.dscale), (1, v + pb.dscale)] if m == "shift"
                else [(1, 2 * p["k1"] if at_k1 else 0.1 * pb.kscale)])
        return [(k, e, lambda t, e=e: v + t * (e - v), lambda x, e=e: (x - v) / (e - v)) for k, e in ends]
    k1 = p["k1"]
    g, g_inv = ((lambda x: x / k1 - 1), (lambda y: k1 * (1 + y))) if m == "kp" else ((lambda x: x), (lambda y: y))
    y = g(v)
    ends = [(0, g_inv(y / f))] + ([(1, min(v * f, 1.0) if m == "phiF" else g_inv(y * f))] if m != "phiF" or v < 1
                                  else [])
    return [(k, e, lambda t, e=e: g_inv(y * (g(e) / y) ** t),
             lambda x, e=e: math.log(g(x) / y) / math.log(g(e) / y) if g(x) > 0 else math.inf) for k, e in ends]


def _profile(pb, p, ssr_min, s2, ci, undetermined, statements):
    """Profile-likelihood ends: where the sum of squares, the others refitted, has grown by
    PROFILE_CHI2 noise^2. Each side is searched outward from the Jacobian's end (or from 1/8 of
    the way to _moves' value) doubling the distance, each point refitted from the last
    (continuation), up to _moves' value, where a side still under the threshold is open; the
    crossing is then solved to 0.1 % of its distance from the fit. Returns the best fit seen if
    it beats p by 0.01 noise^2, else None."""
    better = [ssr_min - 0.01 * s2, None]

    def refit(m, value, seeds):
        fixed = dict(p, **{m: value})
        others = [n for n in pb.free if n != m]
        ssr, q = (pb.best(others, fixed, [dict(s, **{m: value}) for s in seeds], len(seeds)) if others
                  else (pb.ssr(fixed), fixed))
        if ssr < better[0]:
            better[:] = [ssr, q]
        return (ssr - ssr_min) / s2, q

    for m in pb.free:
        for k, moved, path, fraction in _moves(m, p, pb):
            t = fraction(ci[m][k]) if math.isfinite(ci[m][k]) else math.inf
            t = t if 0 < t < 1 else 1 / PROFILE_GRID
            prev, t_prev, seeds = p, 0.0, [p]
            while True:
                growth, q = refit(m, path(t), seeds)
                if growth > PROFILE_CHI2 or t >= 1:
                    break
                prev, t_prev, seeds, t = q, t, [q], min(2 * t, 1.0)
            if growth <= PROFILE_CHI2:
                end = _OPEN_END[m][k]
                ci[m][k] = p["k1"] if end is None else end
                if m not in undetermined:
                    undetermined.append(m)
                growth = round(growth, 2) + 0.0  # no "-0.00"
                statements.append(f"{m}: set to {moved:.4g} with the others refitted it fits as well ({growth:+.2f} "
                                  f"noise^2; 95 % threshold {PROFILE_CHI2:.2f})")
                continue
            rise = lambda t: refit(m, path(t), [prev])[0] - PROFILE_CHI2  # noqa: E731
            try:
                ci[m][k] = path(brentq(rise, t_prev, t, xtol=1e-12, rtol=1e-3))
            except ValueError:  # no sign change between the two refits: the crossing point itself
                ci[m][k] = path(t)
    return better[1]
