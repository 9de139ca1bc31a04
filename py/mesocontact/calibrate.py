"""Calibration: the law's normal parameters from measured restitution e(v) (plain Python with
numpy and scipy; no YADE). docs/calibration.md explains the method and what it showed.

    from mesocontact import calibrate
    d = calibrate.load_data("drops.csv")                       # columns v, e[, sigma] (SI)
    f = calibrate.fit(d, radius=1e-3, density=2500, values=dict(k1=100))
    print(f.report())

The closed form (theory.pair_collision, every regime, both adhesion modes and k2 rules) makes a
fit a least-squares problem of a few parameters: milliseconds per evaluation, seconds per fit
with its intervals. e(v) depends on k1, kp, kc, phiF, fa (and kca, m_r, a12) only through five
dimensionless groups (eta, beta, kca/k1, fa/(k1 phiF a12) and v/v_p, docs/model.md §2), so some
parameter sets are undetermined by any e(v) data; the fit finds which from the Jacobian, in the
logarithms of the free parameters, and says so.
"""
import csv
import math
import time
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import brentq, least_squares

from . import checks as _checks
from . import params as _params
from . import theory as _theory

PARAMETERS = ("k1", "kp", "kc", "phiF", "fa")
AGAINST = ("particle", "wall")
Z95 = 1.959963984540054           # two-sided 95 % quantile of the normal distribution
UNDETERMINED_FACTOR = 10.0        # a 95 % interval reaching beyond this factor either way: not determined
PROFILE_CHI2 = 3.841458820694124  # chi2 quantile (1 degree of freedom, 95 %): the profile interval's threshold
PROFILE_GRID = 8                  # points of each profile scan from the fit to UNDETERMINED_FACTOR (1.33x apart)
EXPLORE_NFEV = 5                  # the wider search follows each start this many steps ...
EXPLORE_KEPT = 2                  # ... and refits the best this many to convergence
PROFILE_STARTS = 6                # random starts at the factor's value (the fit's and the scan's besides)
MUTATIONS = (0.01, 100.0)  # factors on the scan neighbour's values, one parameter at a time
SCREEN_CANDIDATES = 300           # grid starts whose sum of squares is evaluated (the best refitted) ...
SCREEN_POLISHED = 10              # ... in the fit itself (the profile's wider search refits fit()'s `starts` of them)
NULL_RCOND = 1e-7                 # singular values below this fraction of the largest: a direction the data cannot see


class DataError(ValueError):
    """Restitution data that cannot be fitted (the message names the problem and the row)."""


@dataclass
class Data:
    v: np.ndarray                 # approach speeds v_inf [m/s]
    e: np.ndarray                 # restitution (0: the pair stuck)
    sigma: np.ndarray = None      # standard errors of e, or None (then estimated from the residuals)
    source: str = ""


def check_data(v, e, sigma=None, source="data"):
    """Data with every value checked: v > 0 and finite, 0 <= e <= 1, sigma > 0."""
    v, e = np.asarray(v, float), np.asarray(e, float)
    if v.shape != e.shape or v.ndim != 1:
        raise DataError(f"{source}: v and e must be two lists of the same length (got {v.shape} and {e.shape})")
    if len(v) == 0:
        raise DataError(f"{source}: no data points")
    for name, x, ok, need in (("v", v, lambda a: np.isfinite(a) & (a > 0), "a finite speed > 0 [m/s] (the approach speed)"),
                              ("e", e, lambda a: np.isfinite(a) & (a >= 0) & (a <= 1), "in [0, 1] (e = 0: the pair stuck)")):
        bad = np.flatnonzero(~ok(x))
        if bad.size:
            raise DataError(f"{source}: {name} = {x[bad[0]]!r} at point {bad[0] + 1} is invalid: must be {need}")
    if sigma is not None:
        sigma = np.asarray(sigma, float)
        if sigma.shape != v.shape:
            raise DataError(f"{source}: sigma must have one value per point ({sigma.shape} for {v.shape})")
        bad = np.flatnonzero(~(np.isfinite(sigma) & (sigma > 0)))
        if bad.size:
            raise DataError(f"{source}: sigma = {sigma[bad[0]]!r} at point {bad[0] + 1} is invalid: must be a finite number > 0")
    return Data(v, e, sigma, source)


def load_data(path):
    """Reads a CSV file with a header naming the columns v, e and optionally sigma (SI units;
    lines starting with # are comments)."""
    try:  # utf-8-sig: a spreadsheet's "CSV UTF-8" starts with a byte-order mark
        with open(path, newline="", encoding="utf-8-sig") as f:
            lines = [ln for ln in f if ln.strip() and not ln.lstrip().startswith("#")]
    except UnicodeDecodeError as e:
        raise DataError(f"{path}: not a text CSV file (byte {e.start} is not UTF-8)") from None
    if not lines:
        raise DataError(f"{path}: no header and no data")
    reader = csv.reader(lines)
    header = [h.strip() for h in next(reader)]
    twice = sorted({h for h in header if header.count(h) > 1})
    if twice:
        raise DataError(f"{path}: column {twice[0]!r} appears {header.count(twice[0])} times in the header {header}")
    for need in ("v", "e"):
        if need not in header:
            raise DataError(f"{path}: column {need!r} is missing (the header is {header}; needed: v, e and optionally sigma)")
    cols = {name: [] for name in header}
    for n, row in enumerate(reader, start=2):
        if len(row) != len(header):
            raise DataError(f"{path}: data row {n - 1} has {len(row)} values for {len(header)} columns")
        for name, x in zip(header, row):
            try:
                cols[name].append(float(x))
            except ValueError:
                raise DataError(f"{path}: data row {n - 1}: {name} = {x.strip()!r} is not a number") from None
    return check_data(cols["v"], cols["e"], cols.get("sigma"), source=str(path))


def geometry(radius, density, against="particle"):
    """(m_r, a12) of the collision the data come from: two equal spheres ('particle': m_r = m/2,
    a12 = radius) or a sphere on a wall ('wall': m_r = m, a12 = 2 radius)."""
    if against not in AGAINST:
        raise ValueError(f"against = {against!r} is invalid: must be one of {AGAINST}")
    m = _params.sphere_mass(radius, density)
    if against == "particle":
        return _params.reduced_mass(m, m), _params.reduced_radius(radius, radius)
    return _params.reduced_mass(m), _params.reduced_radius(radius)


@dataclass
class Setup:
    """What the data's collisions share: geometry and the law's fixed choices."""
    m_r: float
    a12: float
    adhesion: str = "none"
    kca: float = math.inf
    interpolation: str = "linear"

    def outcome(self, v, p):
        return _theory.pair_collision(v, p["k1"], p["kp"], p["kc"], p["phiF"], self.a12, self.m_r,
                                      p["fa"] if self.adhesion != "none" else 0.0, self.kca,
                                      self.adhesion, self.interpolation)

    def curve(self, v, p):
        return np.array([self.outcome(float(x), p).e for x in np.atleast_1d(v)])


# --- the fit's coordinates: unconstrained where possible, bounded where 0 is a value -----------

def _to_x(name, p, scale):
    """The fit coordinate of a parameter (a start outside the domain, e.g. kp <= k1 after k1
    was moved, is put just inside it)."""
    if name == "k1":
        return math.log(p["k1"])
    if name == "kp":
        return math.log(max(p["kp"] - p["k1"], 1e-9 * p["k1"]))
    if name == "phiF":
        return math.log(min(max(p["phiF"], 1e-12), 1.0))
    return max(p[name], 0.0) / scale[name]  # kc, fa: linear, >= 0


def _from_x(names, x, fixed, scale):
    p = dict(fixed)
    x = [float(xi) for xi in x]  # Python floats: the theory's range checks raise instead of numpy warning
    for name, xi in zip(names, x):
        if name not in ("kp",):
            p[name] = math.exp(xi) if name in ("k1", "phiF") else xi * scale[name]
    if "kp" in names:
        p["kp"] = p["k1"] + math.exp(x[names.index("kp")])
    return p


def _bounds(names):
    lo = [-np.inf if n in ("k1", "kp", "phiF") else 0.0 for n in names]
    hi = [0.0 if n == "phiF" else np.inf for n in names]
    return lo, hi


@dataclass
class Fit:
    """A calibration: the fitted parameters, their intervals and what the data determine."""
    params: dict                  # k1, kp, kc, phiF, fa (fitted or fixed) [SI]
    free: list
    setup: Setup
    data: Data
    ci95: dict                    # free parameter -> [low, high], profile likelihood (the Jacobian's in extra)
    ci95_bootstrap: dict          # free parameter -> [low, high], 2.5/97.5 percentiles over resampled data
    correlation: list             # between the logarithms of the free parameters (a tiny ridge keeps it finite)
    undetermined: list            # free parameters the data do not fix
    statements: list              # plain sentences on what the data do and do not determine
    rms_residual: float
    chi2_reduced: float           # with the data's sigma (None without)
    regimes: dict                 # regime -> number of data points (with the fitted parameters)
    starts: int
    wall_clock_s: float
    sigma_used: float             # the e error the intervals assume (given or estimated)
    extra: dict = field(default_factory=dict)

    def curve(self, v):
        return self.setup.curve(v, self.params)

    def to_json(self):
        p = self.params
        return {"k1": p["k1"], "kp": p["kp"], "kc": p["kc"], "phiF": p["phiF"], "fa": p["fa"],
                "kca": self.setup.kca if math.isfinite(self.setup.kca) else None,
                "adhesion": self.setup.adhesion, "k2Interpolation": self.setup.interpolation,
                "m_r": self.setup.m_r, "a12": self.setup.a12, "free": self.free,
                "ci95": _open_ends(self.ci95), "ci95_bootstrap": self.ci95_bootstrap,
                "correlation": {"names": self.free, "matrix": self.correlation},
                "undetermined": self.undetermined, "statements": self.statements,
                "rms_residual": self.rms_residual, "chi2_reduced": self.chi2_reduced,
                "sigma_used": self.sigma_used, "regimes": self.regimes, "n_points": int(len(self.data.v)),
                "starts": self.starts, "wall_clock_s": self.wall_clock_s, **self.extra}

    def report(self):
        lines = [f"{len(self.data.v)} points, free: {', '.join(self.free)}; rms residual {self.rms_residual:.3g}"
                 + (f", reduced chi2 {self.chi2_reduced:.3g}" if self.chi2_reduced is not None else "")
                 + f"; {self.starts} starts, {self.wall_clock_s:.2f} s"]
        for n in PARAMETERS:
            if n == "fa" and self.setup.adhesion == "none":
                continue
            if n in self.free:
                lo, hi = self.ci95[n]
                b = self.ci95_bootstrap.get(n)
                lines.append(f"  {n:5s} = {self.params[n]:.6g}   95 %: [{lo:.4g}, {hi:.4g}]"
                             + (f"  bootstrap [{b[0]:.4g}, {b[1]:.4g}]" if b else "")
                             + ("   UNDETERMINED" if n in self.undetermined else ""))
            else:
                lines.append(f"  {n:5s} = {self.params[n]:.6g}   (fixed)")
        lines.append("  regimes: " + ", ".join(f"{k} {v}" for k, v in self.regimes.items()))
        lines += ["  " + s for s in self.statements]
        return "\n".join(lines)


def _scale(name, k1, m_r, v):
    """The natural size of kc (k1) and of fa (alpha = 1 at the median speed, Eq. 27c)."""
    return k1 if name == "kc" else _params.fa_from_alpha(1.0, k1, m_r, float(np.median(v)))


def _phiF_for(v_p, k1, eta, m_r, a12):
    """phiF that puts the plastic limit at v_p (Eq. 19 with fa = 0: v_p = sqrt(k1/m_r) (1 + eta)/eta phiF a12)."""
    return v_p / (math.sqrt(k1 / m_r) * (1 + eta) / eta * a12)


def _open_ends(ci):
    """JSON has no infinity: an interval's open end (the data do not bound it) is null."""
    return {n: [x if math.isfinite(x) else None for x in lohi] for n, lohi in ci.items()}


def _residuals(names, fixed, scale, setup, data, w, seen=None):
    """The weighted residuals as a function of the free parameters' solver variables; with `seen`
    a list, every evaluation's (sum of squares, parameters) is appended to it."""
    def fun(x):
        try:
            p = _from_x(names, x, fixed, scale)
            r = (setup.curve(data.v, p) - data.e) * w
        except (ValueError, OverflowError):  # outside the law's domain (e.g. an impact beyond floating point): far from any data
            return np.full(len(data.v), 10.0) * w
        if seen is not None:
            seen.append((float(r @ r), p))
        return r
    return fun


def _starts(names, given, setup, data, n, rng):
    """Starting points: the given values, then draws from grids of the dimensionless groups
    (eta, beta, v_p over the data's range, the adhesivity alpha at the median speed)."""
    k1 = given["k1"]
    out = [dict(given)]
    etas, betas = (0.5, 2.0, 8.0, 30.0, 100.0), (0.0, 0.2, 1.0, 4.0)
    vps = np.geomspace(data.v.min() / 3, 3 * data.v.max(), 5)
    alphas = (0.0, 0.03, 0.1, 0.3, 1.0)
    for _ in range(n - 1):
        p = dict(given)
        if "k1" in names:
            p["k1"] = k1 * 10 ** rng.uniform(-1, 1)
        eta = rng.choice(etas) if "kp" in names else (p["kp"] - p["k1"]) / p["k1"]
        if "kp" in names:
            p["kp"] = p["k1"] * (1 + eta)
        if "kc" in names:
            p["kc"] = p["k1"] * rng.choice(betas)
        if "phiF" in names:
            v_p = rng.choice(vps)
            p["phiF"] = min(1.0, _phiF_for(v_p, p["k1"], max(eta, 1e-12), setup.m_r, setup.a12))
        if "fa" in names:
            p["fa"] = rng.choice(alphas) * _scale("fa", p["k1"], setup.m_r, data.v)
        out.append(p)
    return out


def _grid_starts(names, given, setup, data, rng, n=SCREEN_CANDIDATES):
    """Candidate starts on grids of the dimensionless groups (beta, v_p over the data's range and
    beyond, the adhesivity alpha, eta; k1 by factors 3), the other parameters as given; a random
    subset of n when the product is larger. The e(v) surface is flat wherever every point sticks
    or every point rebounds alike, so a local solver started in the wrong regime stays there: the
    candidates are screened by their sum of squares and the best refitted."""
    k1s = [given["k1"] * f for f in (1 / 3, 1.0, 3.0)] if "k1" in names else [given["k1"]]
    etas = (0.5, 2.0, 8.0, 30.0, 100.0) if "kp" in names else (None,)
    betas = (0.0, 0.03, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0) if "kc" in names else (None,)
    vps = np.geomspace(data.v.min() / 3, 3 * data.v.max(), 6) if "phiF" in names else (None,)
    alphas = (0.0, 0.003, 0.01, 0.03, 0.1, 0.3, 1.0) if "fa" in names else (None,)
    combos = [(a, b, c, d, e) for a in k1s for b in etas for c in betas for d in vps for e in alphas]
    if len(combos) > n:
        combos = [combos[i] for i in sorted(rng.choice(len(combos), n, replace=False))]
    out = []
    for k1, eta, beta, v_p, alpha in combos:
        q = dict(given, k1=k1)
        if eta is None:  # kp fixed (or the profiled parameter)
            q["kp"] = given["kp"]
        else:
            q["kp"] = k1 * (1 + eta)
        eta_q = max(q["kp"] / k1 - 1, 1e-12)
        if beta is not None:
            q["kc"] = beta * k1
        if v_p is not None:
            q["phiF"] = min(1.0, _phiF_for(v_p, k1, eta_q, setup.m_r, setup.a12))
        if alpha is not None:
            q["fa"] = alpha * _scale("fa", k1, setup.m_r, data.v)
        out.append(q)
    return out


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


def _identify(names, p, setup, data, w, s2):
    """Covariance of the log parameters, 95 % intervals, correlation, the undetermined and why."""
    J, at_zero = _log_jacobian(names, p, setup, data, w)
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
    C = np.linalg.inv(J.T @ J + ridge * np.eye(len(names)))
    d = np.sqrt(np.diag(C))
    corr = (C / np.outer(d, d)).tolist()
    ci, undetermined = {}, []
    for i, n in enumerate(names):
        if at_zero[i]:  # d/d(value/scale): the interval's upper end from the linear sd
            scale = _scale(n, p["k1"], setup.m_r, data.v)
            ci[n] = [0.0, float(Z95 * sd[i] * scale) if math.isfinite(sd[i]) else math.inf]
            if not math.isfinite(sd[i]):
                undetermined.append(n)
            continue
        f = math.exp(Z95 * sd[i]) if sd[i] < 700 else math.inf
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
    # the weak directions: where moving the log parameters changes e by less than the noise over
    # the interval factor
    weak = [k for k in range(len(sv)) if sv[k] == 0 or math.sqrt(s2) / sv[k] * Z95 > math.log(UNDETERMINED_FACTOR)]
    for k in weak:
        v = Vt[k]
        involved = [(names[i], v[i]) for i in range(len(names)) if abs(v[i]) > 0.05 * np.abs(v).max()]
        if len(involved) < 2:
            continue
        ref = max(involved, key=lambda t: abs(t[1]))[1]
        moves = ", ".join(f"{n} x lambda^{c / ref:+.2f}" for n, c in involved)
        statements.append(f"{', '.join(n for n, _ in involved)}: the data fix only a combination; e(v) stays the same "
                          f"(to the noise) along {moves}; fix one of them")
    return ci, corr, undetermined, statements


# a side of a parameter's interval that the data leave open
_BOUND_END = {"k1": (0.0, math.inf), "kp": (None, math.inf), "kc": (0.0, math.inf), "phiF": (0.0, 1.0), "fa": (0.0, math.inf)}


def _profile_values(m, p, setup, data):
    """(side, value) pairs the profile test tries: the value divided and multiplied by
    UNDETERMINED_FACTOR (kp through eta; phiF capped at 1; a parameter at 0 tried at a tenth of
    its natural scale: beta = 0.1, alpha = 0.1 at the median speed)."""
    f = UNDETERMINED_FACTOR
    if m == "kp":
        eta = p["kp"] / p["k1"] - 1
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
        return lambda t: p["k1"] * (1 + e0 * (e1 / e0) ** t)
    if p[m] <= 0:
        return lambda t: t * moved
    return lambda t: p[m] * (moved / p[m]) ** t


def _path_fraction(m, p, moved, x):
    """The inverse of _path: the fraction t at which the path from the fit to `moved` reaches x
    (beyond 1 past `moved`, negative on the other side of the fit)."""
    if m == "kp":
        e0, e1, e = p["kp"] / p["k1"] - 1, moved / p["k1"] - 1, x / p["k1"] - 1
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


def _validated(data, radius, density, against, adhesion, kca, interpolation, free, values):
    """The fit's inputs checked, with the defaults filled in: (Data, Setup, free names, values).
    Raises ValueError (DataError for the data) naming what is wrong."""
    if not isinstance(data, Data):
        data = check_data(*data)
    m_r, a12 = geometry(radius, density, against)
    if adhesion not in _theory.ADHESION_MODES:
        raise ValueError(f"adhesion = {adhesion!r} is invalid: must be one of {_theory.ADHESION_MODES}")
    setup = Setup(m_r, a12, adhesion, kca, interpolation)
    free = list(free if free is not None else (("kp", "kc", "phiF") + (("fa",) if adhesion != "none" else ())))
    for n in free:
        if n not in PARAMETERS:
            raise ValueError(f"free parameter {n!r} is unknown: must be among {PARAMETERS}")
    if len(set(free)) != len(free):
        raise ValueError(f"free = {free}: a parameter is named twice")
    if adhesion == "none" and "fa" in free:
        raise ValueError("free parameter 'fa' needs adhesion 'reversible' or 'jumpIn' (with adhesion 'none' fa does nothing)")
    if adhesion != "none" and not (_checks.is_number(kca) and kca > 0):
        raise ValueError(f"kca = {kca!r} is invalid: must be > 0 with adhesion {adhesion!r} (inf allowed for 'jumpIn')")
    if adhesion == "reversible" and not math.isfinite(kca):
        raise ValueError("kca = inf is invalid with adhesion 'reversible': the pull-in range fa/kca needs a finite kca")
    values = dict(values or {})
    for n in values:
        if n not in PARAMETERS:
            raise ValueError(f"value given for unknown parameter {n!r}: must be among {PARAMETERS}")
    values.setdefault("kc", 0.0)
    values.setdefault("fa", 0.0)
    missing = [n for n in PARAMETERS if n not in values and n not in free]
    if "k1" not in values:
        missing = ["k1"] + [n for n in missing if n != "k1"]
    if missing:
        raise ValueError(f"no value for {', '.join(missing)}: fixed parameters need a value (k1 also when free, as its "
                         "starting guess; e(v) alone cannot fix the stiffness scale)")
    if len(data.v) < len(free):
        raise DataError(f"{data.source}: {len(data.v)} points cannot fix {len(free)} free parameters ({', '.join(free)})")
    values.setdefault("kp", values["k1"] * 5.0)
    values.setdefault("phiF", 0.1)
    _theory.check_law(values["k1"], values["kp"], values["phiF"], a12)
    if values["kp"] == values["k1"] and "kp" in free:
        values["kp"] = values["k1"] * 1.5
    speeds = len(np.unique(data.v))
    if speeds < len(free):
        raise DataError(f"{data.source}: {speeds} distinct speed(s) cannot determine {len(free)} free parameters ({', '.join(free)}): "
                        "measure at more speeds or fix some (free=...)")
    return data, setup, free, values


class _Problem:
    """One least-squares problem: the data, the law's setup, the free names and the values of the
    others; local solves from given starts. Every evaluation on the data is kept in ``seen`` as
    (sum of squares, parameters): a point under the profile threshold lies inside every interval.
    Two random streams: ``rng`` (the random starts, the bootstrap) and ``grid_rng`` (the grid's
    subsets), so the random starts stay those of the seed whatever the grid draws."""

    def __init__(self, data, setup, free, values, seed):
        self.data, self.setup, self.free, self.values = data, setup, free, values
        self.scale = {n: _scale(n, values["k1"], setup.m_r, data.v) for n in ("kc", "fa")}
        self.w = 1.0 / data.sigma if data.sigma is not None else np.ones(len(data.v))
        self.fixed = {n: values[n] for n in PARAMETERS}
        self.rng = np.random.default_rng(seed)
        self.grid_rng = np.random.default_rng([seed, 1])
        self.seen = []

    def params(self, names, x, fix):
        return _from_x(names, x, fix, self.scale)

    def solve(self, names, fix, x0, max_nfev=None, data=None, w=None):
        """A local least-squares solve (on resampled ``data`` with weights ``w`` for the bootstrap)."""
        on_data = data is None
        fun = _residuals(names, fix, self.scale, self.setup, self.data if on_data else data, self.w if on_data else w,
                         self.seen if on_data else None)
        return least_squares(fun, x0, bounds=_bounds(names), x_scale="jac", method="trf", xtol=1e-12, ftol=1e-12, gtol=1e-12,
                             max_nfev=max_nfev)

    def best_of(self, names, fix, starts_p, explore=False):
        """The best refit from the starts; with explore, each start is first followed for
        EXPLORE_NFEV steps only and the best EXPLORE_KEPT of those are refitted to convergence
        (many starts end on the same plateau; only which basin a start reaches matters)."""
        lo, hi = _bounds(names)
        xs = [np.clip([_to_x(n, p0, self.scale) for n in names], np.array(lo) + 1e-12, np.array(hi) - 1e-12) for p0 in starts_p]
        if explore and len(xs) > EXPLORE_KEPT:
            short = sorted((self.solve(names, fix, x0, EXPLORE_NFEV) for x0 in xs), key=lambda r: r.cost)
            xs = [r.x for r in short[:EXPLORE_KEPT]]
        best = None
        for x0 in xs:
            r = self.solve(names, fix, x0)
            if best is None or r.cost < best.cost:
                best = r
        return best

    def ssr_of(self, names, fix, q):
        """The sum of squares at the values q (no solve)."""
        x = np.array([_to_x(n, q, self.scale) for n in names])
        return float(np.sum(_residuals(names, fix, self.scale, self.setup, self.data, self.w, self.seen)(x) ** 2))

    def grid(self, names, fix):
        """The grid starts (_grid_starts), best sum of squares first."""
        return sorted(_grid_starts(names, fix, self.setup, self.data, self.grid_rng), key=lambda q: self.ssr_of(names, fix, q))


def _multistart(pb, starts):
    """The best local fit from the given values, `starts` - 1 random starts on grids of the
    dimensionless groups and the SCREEN_POLISHED best grid starts: (least_squares result, parameters)."""
    grid = pb.grid(pb.free, pb.fixed)
    best = pb.best_of(pb.free, pb.fixed, _starts(pb.free, pb.values, pb.setup, pb.data, starts, pb.rng) + grid[:SCREEN_POLISHED])
    return best, pb.params(pb.free, best.x, pb.fixed)


def _noise(data, res, k):
    """(noise variance s2 the intervals use, reduced chi2 or None, the sigma used): the data's sigma
    when given, else the residuals' variance (n - k degrees of freedom)."""
    n = len(data.v)
    if data.sigma is not None:
        return 1.0, float(np.sum((res / data.sigma) ** 2) / max(n - k, 1)), float(np.median(data.sigma))
    if n <= k or float(np.sum(res ** 2)) < 1e-24 * n:
        raise DataError(f"{data.source}: the fit passes through every point ({n} points, {k} free parameters): without a sigma "
                        "column the noise, and so any interval, cannot be estimated; give sigma or more points")
    s2 = float(np.sum(res ** 2) / max(n - k, 1))
    return s2, None, math.sqrt(s2)


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
    return {m: [float(np.percentile(samples[:, i], 2.5)), float(np.percentile(samples[:, i], 97.5))] for i, m in enumerate(pb.free)}


RESTARTS = 3  # a profile refit that beats the fit starts the fit again from it, at most this often


def fit(data, radius, density, against="particle", adhesion="none", kca=math.inf, interpolation="linear",
        free=None, values=None, starts=40, bootstrap=200, seed=0):
    """Least-squares fit of the closed-form e(v) to data (a Data, or (v, e[, sigma])).

    values: the fixed parameters' values and the free ones' starting guesses (k1 is always
    needed: e(v) without adhesion cannot fix it, see the module's docstring); kc defaults to 0,
    fa to 0. free: names among PARAMETERS (default kp, kc, phiF, and fa with adhesion).
    Returns a Fit; raises ValueError naming what is wrong with the input."""
    t0 = time.time()
    for attempt in range(RESTARTS + 1):
        data, setup, free, values = _validated(data, radius, density, against, adhesion, kca, interpolation, free, values)
        pb = _Problem(data, setup, free, values, seed)
        best, p = _multistart(pb, starts)
        res = setup.curve(data.v, p) - data.e
        s2, chi2, sigma_used = _noise(data, res, len(free))
        ci, corr, undetermined, statements = _identify(free, p, setup, data, pb.w, s2)
        ci_jacobian = {m: list(v) for m, v in ci.items()}
        profile = _Profile(pb, p, 2 * best.cost, s2, ci, undetermined, starts)  # least_squares' cost is SSR/2
        profile.run()
        if profile.better[1] is None or attempt == RESTARTS:
            break
        values = dict(values, **{m: profile.better[1][m] for m in free})  # start again from the better fit
    for m, sides in profile.open_sides.items():
        statements.append(f"{m}: set to {' or '.join(sides)} with the others refitted it fits as well (in brackets: "
                          f"the growth of the sum of squares in noise^2; 95 % threshold {PROFILE_CHI2:.2f})")
    undetermined = [m for m in free if m in undetermined]
    statements = _coverage_statements(setup, p, data, free) + statements
    boot = _bootstrap(pb, best.x, bootstrap) if bootstrap else {}
    return Fit(p, free, setup, data, ci, boot, corr, undetermined, statements, float(np.sqrt(np.mean(res ** 2))), chi2,
               _regimes(setup, p, data), starts, time.time() - t0, sigma_used,
               extra={"ci95_jacobian": _open_ends(ci_jacobian)})


# --- the law's parameters from other common inputs -------------------------------------------

def from_groups(eta, beta, phiF, v_p, radius, density, against="particle"):
    """k1, kp, kc, phiF that give plasticity eta, adhesivity beta, plasticity depth phiF and the
    plastic-limit speed v_p (Eq. 19 with fa = 0) for the collision of `against`."""
    _theory.check_groups(eta, beta)
    _checks.positive("eta", eta)
    _checks.positive("v_p", v_p)
    if not (_checks.is_number(phiF) and 0 < phiF <= 1):
        raise ValueError(f"phiF = {phiF!r} is invalid: must lie in (0, 1]")
    m_r, a12 = geometry(radius, density, against)
    k1 = m_r * (_phiF_for(v_p, 1.0, eta, 1.0, a12) / phiF) ** 2  # _phiF_for scales as 1/sqrt(k1/m_r)
    return {"k1": k1, "kp": (1 + eta) * k1, "kc": beta * k1, "phiF": phiF}


def contact_duration(chi, eta, beta, interpolation="linear"):
    """Time with positive overlap of a head-on collision below v_p (fa = 0), in units of
    sqrt(m_r/k1) (theory.contact_duration in the law's own units: k1 = m_r = a12 = 1). Raises
    ValueError if the pair sticks."""
    if not 0 < chi <= 1:
        raise ValueError(f"chi = {chi!r} is invalid: must lie in (0, 1] (below v_p)")
    if _theory.en_squared(chi, eta, beta, interpolation) <= 0:
        raise ValueError(f"chi = {chi!r} with eta = {eta!r}, beta = {beta!r}: the pair sticks, the contact does not end")
    phiF = 0.5 if eta > 0 else 1.0  # any: chi carries the scale
    v = _theory.impact_velocity_for_chi(chi, 1.0, 1.0 + eta, phiF, 1.0, 1.0)
    return _theory.contact_duration(v, 1.0, 1.0 + eta, beta, phiF, 1.0, 1.0, interpolation=interpolation)


def from_restitution_and_contact_time(e, t_c, v, eta, beta, radius, density, against="particle",
                                      interpolation="linear"):
    """k1, kp, kc, phiF for a restitution e at the approach speed v (below v_p, fa = 0) with the
    contact lasting t_c (time with positive overlap), for given eta and beta (what MercuryDPM's
    users set from e and t_c for a linear spring). The speed is placed on the decreasing branch of
    e(chi) below the sticking window."""
    _checks.positive("t_c", t_c)
    _checks.positive("v", v)
    _checks.positive("eta", eta)
    if not (_checks.is_number(e) and 0 < e < 1):
        raise ValueError(f"e = {e!r} is invalid: must lie in (0, 1)")
    e_min = _theory.restitution_fa0(1.0, eta, beta, interpolation)
    # the branch from chi = 0 (e = 1) down to the first chi where e = 0 or chi = 1
    hi = 1.0
    if beta > 0 and eta > 0:
        try:
            hi = min(1.0, _theory.chi_c_b(eta, beta))
        except ValueError:
            pass
    if e < _theory.restitution_fa0(hi, eta, beta, interpolation):
        raise ValueError(f"e = {e!r} is invalid with eta = {eta!r}, beta = {beta!r}: below v_p e stays above "
                         f"{max(e_min, _theory.restitution_fa0(hi, eta, beta, interpolation)):.4g}")
    lo = 0.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if _theory.restitution_fa0(mid, eta, beta, interpolation) > e:
            lo = mid
        else:
            hi = mid
    chi = 0.5 * (lo + hi)
    m_r, a12 = geometry(radius, density, against)
    k1 = m_r * (contact_duration(chi, eta, beta, interpolation) / t_c) ** 2
    phiF = _phiF_for(v / chi, k1, eta, m_r, a12)
    if not 0 < phiF <= 1:
        raise ValueError(f"t_c = {t_c!r} and v = {v!r} need phiF = {phiF:.4g}, outside (0, 1]: the overlap would exceed "
                         "the particle's size")
    return {"k1": k1, "kp": (1 + eta) * k1, "kc": beta * k1, "phiF": phiF, "chi": chi}


# --- the fit run through YADE, and its picture -------------------------------------------------

def material(params, adhesion="none", kca=math.inf, interpolation="linear", density=2000.0):
    """The MesoMat attributes of a calibration (a dict for MesoMat(**...) or pair.build)."""
    m = {"k1": params["k1"], "kp": params["kp"], "kc": params["kc"], "phiF": params["phiF"],
         "adhesion": adhesion, "k2Interpolation": interpolation, "density": density}
    if adhesion != "none":
        m["fa"] = params["fa"]
        if math.isfinite(kca):
            m["kca"] = kca
    return m


def yade_check(fitted, velocities, radius, density, against="particle", progress=True):
    """Pair collisions in YADE (inside ``yade``) with the fitted parameters at the given speeds:
    a list of (v, e_yade, e_fitted_curve). fitted: calibration.json's dict."""
    from . import pair  # needs YADE
    kca = fitted["kca"] if fitted.get("kca") is not None else math.inf
    mat = material(fitted, fitted["adhesion"], kca, fitted["k2Interpolation"], density)
    setup = Setup(*geometry(radius, density, against), fitted["adhesion"], kca, fitted["k2Interpolation"])
    out = []
    for i, v in enumerate(velocities):
        s = pair.build(radius, float(v), dict(mat)) if against == "particle" else \
            pair.build_wall(radius, float(v), dict(mat), wall_material=dict(mat))
        r = pair.collide(s, max_contact_times=15)
        e_fit = float(setup.curve(float(v), fitted)[0])
        out.append((float(v), float(r.e), e_fit))
        if progress:
            print(f"  YADE check {i + 1}/{len(velocities)}: v = {v:.4g} m/s  e_yade = {r.e:.5f}  e_fit = {e_fit:.5f}", flush=True)
    return out


def plot(fit, path, yade_points=None, truth=None):
    """Data with error bars, the fitted curve, the YADE collisions, the regimes shaded."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from . import outputs as _out
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
    txt = ", ".join(f"{n} = {p[n]:.3g}" for n in PARAMETERS if n != "fa" or fit.setup.adhesion != "none")
    mode = "no adhesion" if fit.setup.adhesion == "none" else f"adhesion {fit.setup.adhesion!r}"
    ax.set_title(f"{mode}; free: {', '.join(fit.free)}\n{txt} (N/m, N)", fontsize=9)
    ax.legend(fontsize=8, loc="best")
    fig.tight_layout()
    _out.savefig_atomic(fig, path, dpi=120)
    plt.close(fig)
