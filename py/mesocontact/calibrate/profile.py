"""Profile-likelihood intervals (each end where the sum of squares, the others refitted, has grown
by the 95 % threshold) and the bootstrap."""
import math

import numpy as np
from scipy.optimize import brentq

from .data import Data
from .identify import UNDETERMINED_FACTOR
from .problem import _residuals, _scale, _starts

PROFILE_CHI2 = 3.841458820694124  # chi2 quantile (1 degree of freedom, 95 %): the profile interval's threshold
PROFILE_GRID = 8                  # points of each profile scan from the fit to UNDETERMINED_FACTOR (1.33x apart)
PROFILE_STARTS = 6                # random starts at the factor's value (the fit's and the scan's besides)
MUTATIONS = (0.01, 100.0)  # factors on the scan neighbour's values, one parameter at a time

# a side of a parameter's interval that the data leave open
_BOUND_END = {"k1": (0.0, math.inf), "kp": (None, math.inf), "kc": (0.0, math.inf), "phiF": (0.0, 1.0),
              "fa": (0.0, math.inf)}


def _profile_values(m, p, setup, data):
    """(side, value) pairs the profile test tries: the value divided and multiplied by
    UNDETERMINED_FACTOR (kp through eta; phiF capped at 1; a parameter at 0 tried at a tenth of
    its natural scale: beta = 0.1, alpha = 0.1 at the median speed)."""
    f = UNDETERMINED_FACTOR
    if m == "kp":
        eta = p["kp"] / p["k1"] - 1
        if not eta > 1e-12:  # kp at k1 to rounding: no factor moves eta = 0; tried at eta = 1
            return [(1, 2 * p["k1"])]
        return [(-1, p["k1"] * (1 + eta / f)), (1, p["k1"] * (1 + eta * f))]
    if m in ("kc", "fa") and p[m] <= 1e-12 * _scale(m, p["k1"], setup.m_r, data.v):
        return [(1, 0.1 * _scale(m, p["k1"], setup.m_r, data.v))]
    out = [(-1, p[m] / f)]
    if m != "phiF" or p[m] < 1.0:
        out.append((1, min(p[m] * f, 1.0) if m == "phiF" else p[m] * f))
    return out


def _path(m, p, moved):
    """The parameter's value a fraction t of the way from its fit to `moved`: geometric (kp
    through eta), linear from 0 for a parameter at 0."""
    if m == "kp":
        e0, e1 = p["kp"] / p["k1"] - 1, moved / p["k1"] - 1
        if not e0 > 1e-12:  # from eta = 0: linear in eta
            return lambda t: p["k1"] * (1 + t * e1)
        return lambda t: p["k1"] * (1 + e0 * (e1 / e0) ** t)
    if p[m] <= 0:
        return lambda t: t * moved
    return lambda t: p[m] * (moved / p[m]) ** t


def _path_fraction(m, p, moved, x):
    """The inverse of _path: the fraction t at which the path from the fit to `moved` reaches x
    (beyond 1 past `moved`, negative on the other side of the fit)."""
    if m == "kp":
        e0, e1, e = p["kp"] / p["k1"] - 1, moved / p["k1"] - 1, x / p["k1"] - 1
        if not e0 > 1e-12:
            return e / e1
        return math.log(e / e0) / math.log(e1 / e0) if e > 0 else -math.inf
    if p[m] <= 0:
        return x / moved
    return math.log(x / p[m]) / math.log(moved / p[m]) if x > 0 else -math.inf


def _same_v_p(m, q, value):
    """q with m set to value and the plastic limit velocity v_p kept (Eq. 19 with fa = 0: v_p is
    proportional to phiF (1 + eta)/eta), or None where no such point exists: moving kp or phiF
    alone moves v_p, and the data see v_p, so a branch of equally good fits runs along it."""
    g = lambda kp: kp / (kp - q["k1"])  # noqa: E731  (1 + eta)/eta
    out = dict(q)
    out[m] = value
    if m == "kp" and value > q["k1"] and q["kp"] > q["k1"]:
        out["phiF"] = min(1.0, q["phiF"] * g(q["kp"]) / g(value))
        return out
    if m == "phiF" and value > 0 and q["kp"] > q["k1"]:
        g_new = g(q["kp"]) * q["phiF"] / value
        if g_new > 1:
            out["kp"] = q["k1"] * (1 + 1 / (g_new - 1))
            return out
    return None


class _Profile:
    """Profile-likelihood intervals. The Jacobian is local: a ridge of equally good fits that
    ends at a kink (a point crossing v_p or the sticking window) looks determined there, and near
    kinks its linear intervals are too narrow. So each end is where the sum of squares, the others
    refitted, has grown by PROFILE_CHI2 noise^2 (chi2 of one degree of freedom at 95 %), searched
    up to UNDETERMINED_FACTOR either way; a side still inside the threshold there is open and the
    parameter undetermined. run() fills ci (begun as the Jacobian's), undetermined and open_sides,
    and sets better to (sum of squares, parameters) when a refit beat the fit."""

    def __init__(self, pb, p, ssr_min, s2, ci, undetermined, starts):
        self.pb, self.p, self.ssr_min, self.s2, self.starts = pb, p, ssr_min, s2, starts
        self.ci, self.undetermined = ci, undetermined
        self.open_sides, self.bounded, self.sides = {}, set(), {}
        self.better = (ssr_min * (1 - 1e-9) - 1e-300, None)

    def refit(self, m, value, seeds, search, near=-1):
        """(growth of the sum of squares in noise^2, the refitted values) with m fixed at value:
        the others refitted from the seeds (the fit, the scan's neighbours), each also moved along
        constant v_p for kp and phiF; with search >= 1 also from the seed `near` moved by decades
        one parameter at a time, and with search > 1 from the best `search` grid starts (another
        branch of a multi-modal problem)."""
        pb, p = self.pb, self.p
        fix = dict(p)
        fix[m] = value
        others = [x for x in pb.free if x != m]
        if not others:
            ssr = float(np.sum(_residuals([], fix, pb.scale, pb.setup, pb.data, pb.w)(np.array([])) ** 2))
            return (ssr - self.ssr_min) / self.s2, fix
        firsts = []
        for q in seeds:
            first = dict(q)
            first[m] = value
            if m == "k1":  # the same groups at the new stiffness scale: the ridge's direction
                for x in ("kp", "kc"):
                    if x in others:
                        first[x] = q[x] * value / q["k1"]
                if "phiF" in others:
                    first["phiF"] = min(1.0, q["phiF"] * math.sqrt(q["k1"] / value))
            firsts.append(first)
            along = _same_v_p(m, q, value) if m in ("kp", "phiF") else None
            if along is not None and all(x in others or along[x] == q[x] for x in ("kp", "phiF") if x != m):
                firsts.append(along)
        if search:
            for x in others:
                for f in MUTATIONS:
                    q = dict(firsts[near])
                    q[x] = q[x] * f if q[x] > 0 else f * 1e-2 * _scale(x, q["k1"], pb.setup.m_r, pb.data.v)
                    if x == "phiF":
                        q[x] = min(q[x], 1.0)
                    firsts.append(q)
            if search > 1:
                firsts += pb.grid(others, fix)[:search]
        r = pb.best_of(others, fix, firsts, explore=bool(search))
        q = pb.params(others, r.x, fix)
        if 2 * r.cost < self.better[0]:
            self.better = (2 * r.cost, q)
        return (2 * r.cost - self.ssr_min) / self.s2, q

    def scan(self, m, k, moved):
        """Side k of m's profile at PROFILE_GRID points out to `moved` (continuation from the
        neighbour; the wider search and PROFILE_STARTS random starts at `moved`, and the wider
        search again beyond the outermost point under the threshold: a second valley there moves
        the end out); then the end (conclude)."""
        p, pb = self.p, self.pb
        path = _path(m, p, moved)
        scan, prev = [(0.0, 0.0, p)], p
        for i in range(1, PROFILE_GRID + 1):
            t = i / PROFILE_GRID
            if i < PROFILE_GRID:
                delta, prev = self.refit(m, path(t), [p, prev], 0)
            else:  # a fit stuck on a plateau, where every point is under the threshold, finds its way off here
                random_starts = _starts([x for x in pb.free if x != m], dict(p, **{m: moved}), pb.setup, pb.data,
                                        PROFILE_STARTS, pb.rng)[1:]
                delta, prev = self.refit(m, moved, [p, prev] + random_starts, self.starts, near=1)
            scan.append([t, delta, prev])
        outer = max(j for j, row in enumerate(scan) if row[1] <= PROFILE_CHI2)
        for j in range(PROFILE_GRID - 1, outer, -1):
            seeds = [p, scan[j][2]] + ([scan[j + 1][2]] if j < PROFILE_GRID else [])
            delta, q = self.refit(m, path(scan[j][0]), seeds, self.starts)
            if delta < scan[j][1]:
                scan[j][1:] = [delta, q]
        self.sides[m, k] = (moved, path, scan)
        self.conclude(m, k)

    def seen_beyond(self, m, k, x):
        """The farthest evaluation under the threshold beyond x on side k of m's profile:
        (fraction of the path, growth in noise^2, parameters), or None."""
        moved = self.sides[m, k][0]
        t_x, lim, far = _path_fraction(m, self.p, moved, x), self.ssr_min + PROFILE_CHI2 * self.s2, None
        for ssr, q in self.pb.seen:
            if ssr <= lim:
                t = _path_fraction(m, self.p, moved, q[m])
                if t > t_x and (far is None or t > far[0]):
                    far = (t, (ssr - self.ssr_min) / self.s2, q)
        return far

    def _undetermined(self, m):
        if m not in self.undetermined:
            self.undetermined.append(m)

    def conclude(self, m, k):
        """Side k of m's interval from its scan: open (the parameter undetermined) where the scan
        stays under the threshold out to the factor's value, else the outermost crossing. The
        farthest evaluation under the threshold joins the scan first, and the scan goes on from it."""
        p, ci = self.p, self.ci
        moved, path, scan = self.sides[m, k]
        self.bounded.discard((m, k))
        far = self.seen_beyond(m, k, path(max(row[0] for row in scan if row[1] <= PROFILE_CHI2)))
        if far is not None and far[0] >= 1:  # under the threshold beyond the factor's value
            scan.append([far[0], far[1], far[2]])
        elif far is not None:
            prev = far[2]
            for row in (r for r in scan if r[0] > far[0]):  # continuation out from it
                delta, q = self.refit(m, path(row[0]), [p, prev, row[2]], 0)
                if delta < row[1]:
                    row[1:] = [delta, q]
                prev = row[2]
                if row[1] > PROFILE_CHI2:
                    break
            scan.append([far[0], far[1], far[2]])
            scan.sort(key=lambda row: row[0])
        if scan[-1][1] <= PROFILE_CHI2:
            end = _BOUND_END[m][k]
            ci[m][k] = p["k1"] if end is None else end
            self._undetermined(m)
            self.open_sides.setdefault(m, []).append(f"{path(scan[-1][0]):.4g} (+{scan[-1][1]:.2f})")
            return
        if not self.refit(m, p[m], [p], 0)[0] < PROFILE_CHI2:
            # the fit itself is not below the threshold (no spread to measure): nothing bounds this side
            ci[m][k] = _BOUND_END[m][k] if _BOUND_END[m][k] is not None else p["k1"]
            self._undetermined(m)
            return
        i = max(j for j, row in enumerate(scan) if row[1] <= PROFILE_CHI2)
        (t_lo, _, q_lo), (t_hi, _, q_hi) = scan[i], scan[i + 1]
        rise = lambda t: self.refit(m, path(t), [p, q_lo, q_hi], 0)[0] - PROFILE_CHI2  # noqa: E731
        ci[m][k] = path(brentq(rise, t_lo, t_hi, xtol=1e-4)) if rise(t_lo) < 0 < rise(t_hi) else path(t_hi)
        self.bounded.add((m, k))

    def run(self):
        for m in self.pb.free:
            for side, moved in _profile_values(m, self.p, self.pb.setup, self.pb.data):
                self.scan(m, 0 if side < 0 else 1, moved)
        # A point evaluated on the data (by any fit, scan or search, for any parameter) lies inside
        # every interval when its sum of squares is under the threshold: the profile at its values is
        # at most that. An end that such a point contradicts is searched again from it.
        for m, k in sorted(self.bounded):
            if self.seen_beyond(m, k, self.ci[m][k]) is not None:
                self.conclude(m, k)
        best_seen = min(self.pb.seen, key=lambda e: e[0])
        if best_seen[0] < self.better[0]:
            self.better = best_seen
        for m in self.undetermined:  # an undetermined parameter has no finite interval where the profile found no end
            for k in (0, 1):
                if (m, k) not in self.bounded:
                    self.ci[m][k] = _BOUND_END[m][k] if _BOUND_END[m][k] is not None else self.p["k1"]


def _bootstrap(pb, x, n_resamples):
    """2.5/97.5 percentiles of each free parameter over refits (from x) on the data resampled with replacement."""
    n, samples = len(pb.data.v), []
    for _ in range(n_resamples):
        idx = pb.rng.integers(0, n, n)
        d = Data(pb.data.v[idx], pb.data.e[idx], None if pb.data.sigma is None else pb.data.sigma[idx])
        r = pb.solve(pb.free, pb.fixed, x, data=d, w=pb.w[idx])
        samples.append([pb.params(pb.free, r.x, pb.fixed)[m] for m in pb.free])
    samples = np.array(samples)
    return {m: [float(np.percentile(samples[:, i], 2.5)), float(np.percentile(samples[:, i], 97.5))]
            for i, m in enumerate(pb.free)}
