"""A calibration and how it is made: ``fit`` (validation, multi-start, the Jacobian's and the
profile's intervals, the bootstrap) and its result ``Fit``."""
import math
import time
from dataclasses import dataclass, field

import numpy as np

from .. import theory as _theory
from .data import PARAMETERS, UNITS, Data, Setup
from .identify import (_coverage_statements, _edge_statements, _identify, _kca_response, _kca_statements, _regimes,
                       v_p_edge)
from .problem import _check_result, _count, _multistart, _noise, _Problem, _validated
from .profile import _BOUND_END, PROFILE_CHI2, _bootstrap, _Profile


@dataclass
class Fit:
    """A calibration: the fitted parameters, their intervals and what the data determine."""
    params: dict                  # k1, kp, kc, phiF, fa (fitted or fixed) [SI]: the fit's point, undetermined ones too
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
    radius: float = None          # [m], density [kg/m^3] and against: the collisions the data come from
    density: float = None
    against: str = None
    v_p: float = None             # the fit's plastic-limit speed (Eq. 19) [m/s]
    v_p_edge: list = field(default_factory=list)  # identify.v_p_edge: where v_p lies at the data's edge
    kca_response: dict = None     # d ln p/d ln kca of the free parameters (adhesion with a finite kca)

    def curve(self, v):
        return self.setup.curve(v, self.params)

    def bound(self, n):
        """The 95 % bound the data put on an undetermined parameter, in words with its unit."""
        floor, top = _BOUND_END[n]
        return _bound_text(self.ci95[n], (self.params["k1"] if floor is None else floor, top), UNITS[n])

    def to_json(self):
        p, und = self.params, self.undetermined
        out = {n: None if n in und else p[n] for n in PARAMETERS}  # an undetermined parameter has no value: null
        out.update({
            "undetermined_reason": {n: self._reason(n) for n in und},
            "fit_point": dict(p),  # what the curve, the regimes and the YADE check use, undetermined ones included
            "units": dict(UNITS, v_p="m/s", m_r="kg", a12="m", rms_residual="", sigma_used=""),
            "kca": self.setup.kca if math.isfinite(self.setup.kca) else None,
            "adhesion": self.setup.adhesion, "k2Interpolation": self.setup.interpolation,
            "m_r": self.setup.m_r, "a12": self.setup.a12, "radius": self.radius, "density": self.density,
            "against": self.against, "free": self.free,
            "ci95": _open_ends(self.ci95), "ci95_bootstrap": self.ci95_bootstrap,
            "correlation": {"names": self.free, "matrix": _nulls(self.correlation)},
            "undetermined": self.undetermined, "statements": self.statements,
            "rms_residual": self.rms_residual, "chi2_reduced": self.chi2_reduced,
            "sigma_used": self.sigma_used, "regimes": self.regimes, "n_points": int(len(self.data.v)),
            "v_p": self.v_p, "v_p_edge": self.v_p_edge,
            "starts": self.starts, "wall_clock_s": self.wall_clock_s})
        if self.setup.adhesion != "none":
            out["kca_assumed"] = {"kca": out["kca"], "dln_dln_kca": self.kca_response}
        out.update(self.extra)
        return out

    def _reason(self, n):
        said = [t for t in self.statements if n in t.split(":")[0].split(", ")]  # "kc: ..." and "kp, phiF: ..."
        return f"undetermined by the data: {self.bound(n)}" + ("; " + "; ".join(said) if said else "")

    def report(self):
        s, d = self.setup, self.data
        where = {"particle": "two equal spheres", "wall": "a sphere on a wall"}.get(self.against, "the data's pair")
        lines = [f"{len(d.v)} points from {d.v.min():.4g} to {d.v.max():.4g} m/s, {where} (m_r = {s.m_r:.4g} kg, "
                 f"a12 = {s.a12:.4g} m); adhesion {s.adhesion!r}, k2 rule {s.interpolation!r}",
                 f"free: {', '.join(self.free)}; rms residual of e {self.rms_residual:.3g}"
                 + (f", reduced chi2 {self.chi2_reduced:.3g}" if self.chi2_reduced is not None else "")
                 + f"; {self.starts} starts, {self.wall_clock_s:.2f} s"]
        for n in PARAMETERS:
            if n == "fa" and s.adhesion == "none":
                continue
            u = (" " + UNITS[n]) if UNITS[n] else ""
            if n in self.undetermined:
                lines.append(f"  {n:5s} = undetermined: {self.bound(n)} (95 %)")
            elif n in self.free:
                lo, hi = self.ci95[n]
                b = self.ci95_bootstrap.get(n)
                lines.append(f"  {n:5s} = {self.params[n]:.6g}{u}   95 %: [{lo:.4g}, {hi:.4g}]{u}"
                             + (f"   bootstrap [{b[0]:.4g}, {b[1]:.4g}]{u}" if b else ""))
            else:
                lines.append(f"  {n:5s} = {self.params[n]:.6g}{u}   (fixed)")
        if s.adhesion != "none":
            lines.append(f"  kca   = {s.kca:.6g} N/m   (assumed, not fitted: the fit holds for it, see below)")
        if self.v_p is not None:
            lines.append(f"  v_p   = {self.v_p:.4g} m/s   (the fit's plastic-limit speed, Eq. 19"
                         + (f"; at the data's {' and '.join(e['side'] for e in self.v_p_edge)} edge" if self.v_p_edge
                            else "") + ")")
        if self.undetermined:
            lines.append("  (the curve, the regimes and the YADE check use the fit's point for "
                         + ", ".join(f"{n} = {self.params[n]:.4g}" + (" " + UNITS[n] if UNITS[n] else "")
                                     for n in self.undetermined)
                         + ": one of many that fit as well)")
        lines.append("  regimes: " + ", ".join(f"{k} {v}" for k, v in self.regimes.items()))
        lines += ["  " + t for t in self.statements]
        return "\n".join(lines)


def _bound_text(ci, ends, unit):
    """'at most x N/m', 'at least x', 'between x and y' or 'no bound from the data': the ends of a 95 %
    interval that are not the parameter's own domain ends (``ends``: e.g. 0 and inf, k1 and inf for kp)."""
    lo, hi = ci
    u = (" " + unit) if unit else ""
    floor, top = ends
    has_lo = lo is not None and math.isfinite(lo) and (lo > floor + 1e-12 * abs(floor) if math.isfinite(floor)
                                                       else True)
    has_hi = hi is not None and math.isfinite(hi) and (hi < top - 1e-12 * abs(top) if math.isfinite(top) else True)
    if has_lo and has_hi:
        return f"between {lo:.3g} and {hi:.3g}{u}"
    if has_hi:
        return f"at most {hi:.3g}{u}"
    if has_lo:
        return f"at least {lo:.3g}{u}"
    return "no bound from the data"


def _nulls(matrix):
    """A correlation for JSON: an entry that is not finite (a parameter the data do not move at all) is null."""
    return [[x if math.isfinite(x) else None for x in row] for row in matrix]


def _open_ends(ci):
    """JSON has no infinity: an interval's open end (the data do not bound it) is null."""
    return {n: [x if math.isfinite(x) else None for x in lohi] for n, lohi in ci.items()}


RESTARTS = 3  # a profile refit that beats the fit starts the fit again from it, at most this often


def fit(data, radius, density, against="particle", adhesion="none", kca=math.inf, interpolation="linear",
        free=None, values=None, starts=40, bootstrap=200, seed=0):
    """Least-squares fit of the closed-form e(v) to data (a Data, or (v, e[, sigma])).

    values: the fixed parameters' values and the free ones' starting guesses (k1 is always
    needed: e(v) without adhesion cannot fix it, see the module's docstring); kc defaults to 0,
    fa to 0. free: names among PARAMETERS (default kp, kc, phiF, and fa with adhesion).
    Returns a Fit; raises ValueError naming what is wrong with the input."""
    t0 = time.time()
    starts, bootstrap, seed = _count("starts", starts, 1), _count("bootstrap", bootstrap, 0), _count("seed", seed, 0)
    for attempt in range(RESTARTS + 1):
        data, setup, free, values = _validated(data, radius, density, against, adhesion, kca, interpolation, free,
                                               values)
        pb = _Problem(data, setup, free, values, seed)
        best, p = _multistart(pb, starts)
        _check_result(p, free, "these e(v)")
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
    v_p = _theory.plastic_limit_velocity(p["k1"], p["kp"], p["phiF"], setup.a12, setup.m_r,
                                         p["fa"] if setup.adhesion != "none" else 0.0)
    edges = v_p_edge(data.v, v_p)
    response = (_kca_response(free, p, setup, data, pb.w) if setup.adhesion != "none" and math.isfinite(setup.kca)
                else None)
    statements = (_coverage_statements(setup, p, data, free) + _edge_statements(edges, v_p, undetermined) + statements
                  + _kca_statements(setup, response or {}))
    boot = _bootstrap(pb, best.x, bootstrap) if bootstrap else {}
    return Fit(p, free, setup, data, ci, boot, corr, undetermined, statements, float(np.sqrt(np.mean(res ** 2))), chi2,
               _regimes(setup, p, data), starts, time.time() - t0, sigma_used,
               extra={"ci95_jacobian": _open_ends(ci_jacobian)}, radius=radius, density=density, against=against,
               v_p=v_p, v_p_edge=edges, kca_response=response)
