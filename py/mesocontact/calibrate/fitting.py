"""A calibration and how it is made: ``fit`` (validation, multi-start, the Jacobian's and the
profile's intervals, the bootstrap) and its result ``Fit``."""
import math
import time
from dataclasses import dataclass, field

import numpy as np

from .data import PARAMETERS, Data, Setup
from .identify import _coverage_statements, _identify, _regimes
from .problem import _multistart, _noise, _Problem, _validated
from .profile import PROFILE_CHI2, _bootstrap, _Profile


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
