"""The least-squares problem: the fit's coordinates, the residuals, the starting points on grids of
the dimensionless groups, the inputs checked, local solves and the multi-start."""
import math
import sys

import numpy as np
from scipy.optimize import least_squares

from .. import checks as _checks
from .. import params as _params
from .. import theory as _theory
from .data import PARAMETERS, Data, DataError, Setup, check_data, geometry

EXPLORE_NFEV = 5                  # the wider search follows each start this many steps ...
EXPLORE_KEPT = 2                  # ... and refits the best this many to convergence
SCREEN_CANDIDATES = 300           # grid starts whose sum of squares is evaluated (the best refitted) ...
SCREEN_POLISHED = 10              # ... in the fit itself (the profile's wider search refits fit()'s `starts` of them)


# --- the fit's coordinates: unconstrained where possible, bounded where 0 is a value -----------

def _to_x(name, p, scale):
    """The fit coordinate of a parameter (a start outside the domain, e.g. kp <= k1 after k1
    was moved, is put just inside it)."""
    # A refit on data no law fits can run k1 to 0 or kp to inf (_exp): the coordinate stays a finite number.
    if name == "k1":
        return min(math.log(max(p["k1"], sys.float_info.min)), 709.0)
    if name == "kp":
        return min(math.log(max(p["kp"] - p["k1"], 1e-9 * p["k1"], sys.float_info.min)), 709.0)
    if name == "phiF":
        return math.log(min(max(p["phiF"], 1e-12), 1.0))
    return min(max(p[name], 0.0) / scale[name], 1e300)  # kc, fa: linear, >= 0


def _from_x(names, x, fixed, scale):
    p = dict(fixed)
    x = [float(xi) for xi in x]  # Python floats: the theory's range checks raise instead of numpy warning
    for name, xi in zip(names, x):
        if name not in ("kp",):
            p[name] = _exp(xi) if name in ("k1", "phiF") else xi * scale[name]
    if "kp" in names:
        p["kp"] = p["k1"] + _exp(x[names.index("kp")])
    return p


def _exp(x):
    """exp, inf beyond floating point instead of math's OverflowError (the residuals then say 'far')."""
    return math.exp(x) if x < 709.0 else math.inf


def _check_result(p, names, what):
    """The fitted parameters must be numbers the law takes: data that no law fits can run the
    solver to a k1 of 0 or an infinite kp. Raises ValueError naming the parameter and its value."""
    for n in names:
        v = p[n]
        ok = math.isfinite(v) and (v >= 0 if n in ("kc", "fa") else True if n == "shift" else v >= sys.float_info.min)
        if not ok:
            raise ValueError(f"{n}: the fit ran it to {v!r}, out of floating point: {what} are not those of the law "
                             "(check the columns, their signs and units)")


def _bounds(names):
    lo = [-np.inf if n in ("k1", "kp", "phiF") else 0.0 for n in names]
    hi = [0.0 if n == "phiF" else np.inf for n in names]
    return lo, hi


def _scale(name, k1, m_r, v):
    """The natural size of kc (k1) and of fa (alpha = 1 at the median speed, Eq. 27c)."""
    return k1 if name == "kc" else _params.fa_from_alpha(1.0, k1, m_r, float(np.median(v)))


def _phiF_for(v_p, k1, eta, m_r, a12):
    """phiF that puts the plastic limit at v_p (Eq. 19 with fa = 0: v_p = sqrt(k1/m_r) (1 + eta)/eta phiF a12)."""
    return v_p / (math.sqrt(k1 / m_r) * (1 + eta) / eta * a12)


def _residuals(names, fixed, scale, setup, data, w, seen=None):
    """The weighted residuals as a function of the free parameters' solver variables; with `seen`
    a list, every evaluation's (sum of squares, parameters) is appended to it."""
    def fun(x):
        try:
            p = _from_x(names, x, fixed, scale)
            r = (setup.curve(data.v, p) - data.e) * w
        # outside the law's domain (e.g. an impact beyond floating point): far from any data
        except (ValueError, OverflowError):
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


def _validated(data, radius, density, against, adhesion, kca, interpolation, free, values):
    """The fit's inputs checked, with the defaults filled in: (Data, Setup, free names, values).
    Raises ValueError (DataError for the data) naming what is wrong."""
    if not isinstance(data, Data):
        if not isinstance(data, (tuple, list)) or len(data) not in (2, 3):
            raise TypeError(f"data = {data!r:.80} is invalid: must be a calibrate.Data or (v, e[, sigma])")
        data = check_data(*data)
    m_r, a12 = geometry(radius, density, against)
    if adhesion not in _theory.ADHESION_MODES:
        raise ValueError(f"adhesion = {adhesion!r} is invalid: must be one of {_theory.ADHESION_MODES}")
    if interpolation not in _theory.K2_INTERPOLATIONS:
        raise ValueError(f"interpolation = {interpolation!r} is invalid: must be one of {_theory.K2_INTERPOLATIONS}")
    _checks.positive_or_inf("kca", kca)
    setup = Setup(m_r, a12, adhesion, kca, interpolation)
    free = _names("free", free, PARAMETERS)
    free = list(free if free is not None else (("kp", "kc", "phiF") + (("fa",) if adhesion != "none" else ())))
    for n in free:
        if n not in PARAMETERS:
            raise ValueError(f"free parameter {n!r} is unknown: must be among {PARAMETERS}")
    if len(set(free)) != len(free):
        raise ValueError(f"free = {free}: a parameter is named twice")
    if adhesion == "none" and "fa" in free:
        raise ValueError("free parameter 'fa' needs adhesion 'reversible' or 'jumpIn' (with adhesion "
                         "'none' fa does nothing)")
    if adhesion != "none" and not (_checks.is_number(kca) and kca > 0):
        raise ValueError(f"kca = {kca!r} is invalid: must be > 0 with adhesion {adhesion!r} (inf allowed for 'jumpIn')")
    if adhesion == "reversible" and not math.isfinite(kca):
        raise ValueError("kca = inf is invalid with adhesion 'reversible': the pull-in range fa/kca needs a finite kca")
    if values is not None and not hasattr(values, "keys"):
        raise TypeError(f"values = {values!r:.80} is invalid: must be a dict of parameter values")
    values = dict(values or {})
    for n in values:
        if n not in PARAMETERS:
            raise ValueError(f"value given for unknown parameter {n!r}: must be among {PARAMETERS}")
    values.setdefault("kc", 0.0)
    values.setdefault("fa", 0.0)
    for n, check in (("k1", _checks.positive), ("kc", _checks.nonnegative), ("fa", _checks.nonnegative)):
        if n in values:
            check(n, values[n])
    missing = [n for n in PARAMETERS if n not in values and n not in free]
    if "k1" not in values:
        missing = ["k1"] + [n for n in missing if n != "k1"]
    if missing:
        raise ValueError(f"no value for {', '.join(missing)}: fixed parameters need a value (k1 also when free, as its "
                         "starting guess; e(v) alone cannot fix the stiffness scale)")
    if len(data.v) < len(free):
        raise DataError(f"{data.source}: {len(data.v)} points cannot fix {len(free)} free parameters "
                        f"({', '.join(free)})")
    values.setdefault("kp", values["k1"] * 5.0)
    values.setdefault("phiF", 0.1)
    _theory.check_law(values["k1"], values["kp"], values["phiF"], a12)
    if values["kp"] == values["k1"] and "kp" in free:
        values["kp"] = values["k1"] * 1.5
    speeds = len(np.unique(data.v))
    if speeds < len(free):
        raise DataError(f"{data.source}: {speeds} distinct speed(s) cannot determine {len(free)} free parameters "
                        f"({', '.join(free)}): "
                        "measure at more speeds or fix some (free=...)")
    for i, v in enumerate(data.v):  # the fit moves from here: a collision outside floating point is named now
        try:
            setup.outcome(float(v), values)
        except ValueError as e:
            raise DataError(f"{data.source}: v = {v!r} at point {i + 1}: the collision with the starting values (k1 = "
                            f"{values['k1']!r} N/m, kp = {values['kp']!r} N/m, phiF = {values['phiF']!r}; "
                            f"m_r = {m_r:.4g} kg, a12 = {a12:.4g} m) cannot be computed: {e}") from None
    return data, setup, free, values


def _names(what, names, allowed):
    """``names`` (None, or an iterable of names) checked for its type: a string would be read letter by letter."""
    if names is None:
        return None
    if isinstance(names, str):
        raise TypeError(f"{what} = {names!r} is invalid: must be a list of names, e.g. {what}={[names]!r}")
    try:
        return list(names)
    except TypeError:
        raise TypeError(f"{what} = {names!r} is invalid: must be a list of names among {allowed}") from None


def _count(name, value, least):
    """An integer option (starts, bootstrap, seed) checked: a float or a bool is a slip."""
    import numbers
    if not (isinstance(value, numbers.Integral) and not isinstance(value, (bool, np.bool_)) and value >= least):
        raise ValueError(f"{name} = {value!r} is invalid: must be an integer >= {least}")
    return int(value)


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
        return least_squares(fun, x0, bounds=_bounds(names), x_scale="jac", method="trf", xtol=1e-12, ftol=1e-12,
                             gtol=1e-12,
                             max_nfev=max_nfev)

    def best_of(self, names, fix, starts_p, explore=False):
        """The best refit from the starts; with explore, each start is first followed for
        EXPLORE_NFEV steps only and the best EXPLORE_KEPT of those are refitted to convergence
        (many starts end on the same plateau; only which basin a start reaches matters)."""
        lo, hi = _bounds(names)
        xs = [np.clip([_to_x(n, p0, self.scale) for n in names], np.array(lo) + 1e-12, np.array(hi) - 1e-12)
              for p0 in starts_p]
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
        return sorted(_grid_starts(names, fix, self.setup, self.data, self.grid_rng),
                      key=lambda q: self.ssr_of(names, fix, q))


def _multistart(pb, starts):
    """The best local fit from the given values, `starts` - 1 random starts on grids of the
    dimensionless groups and the SCREEN_POLISHED best grid starts: (least_squares result, parameters)."""
    grid = pb.grid(pb.free, pb.fixed)
    best = pb.best_of(pb.free, pb.fixed,
                      _starts(pb.free, pb.values, pb.setup, pb.data, starts, pb.rng) + grid[:SCREEN_POLISHED])
    return best, pb.params(pb.free, best.x, pb.fixed)


def _noise(data, res, k):
    """(noise variance s2 the intervals use, reduced chi2 or None, the sigma used): the data's sigma
    when given, else the residuals' variance (n - k degrees of freedom)."""
    n = len(data.v)
    if data.sigma is not None:
        return 1.0, float(np.sum((res / data.sigma) ** 2) / max(n - k, 1)), float(np.median(data.sigma))
    if n <= k or float(np.sum(res ** 2)) < 1e-24 * n:
        raise DataError(f"{data.source}: the fit passes through every point ({n} points, {k} free parameters): without "
                        "a sigma column the noise, and so any interval, cannot be estimated; give sigma or more points")
    s2 = float(np.sum(res ** 2) / max(n - k, 1))
    return s2, None, math.sqrt(s2)
