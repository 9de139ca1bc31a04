"""A calibration from force-displacement cycles: the law's normal parameters k1, kp, kc, phiF
fitted to a force F measured along overlaps delta from a fresh contact (docs/calibration.md,
"From force-displacement cycles"). The model is theory.normal_force_path: quasi-static, without
the viscous term and the non-contact force. Optionally a free offset of the overlap (the law at
delta - shift): an agglomerate's meso-overlap is defined only up to where its surfaces first
touch. What the cycles determine as for e(v): the Jacobian in the logarithms of the free
parameters, then profile-likelihood intervals (cycles_identify)."""
import math
import time
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import least_squares

from .. import checks as _checks
from .. import theory as _theory
from .cycles_identify import _OPEN_END, _coverage, _identify, _profile
from .data import SIGMA_MIN, no_bools
from .fitting import RESTARTS, _bound_text, _nulls, _open_ends
from .problem import _check_result, _from_x, _names, _to_x

CYCLE_PARAMETERS = ("k1", "kp", "kc", "phiF")
CYCLE_STARTS = 3                  # the best grid starts (by their sum of squares) refitted to convergence
# The largest |delta|, |force| and a12 the fit takes (any units): it is scale-free to 1e-150 and 1e150 (measured),
# but its products (stiffness times overlap, squared residuals) leave floating point near 1e-300 and 1e300.
MAGNITUDES = (1e-100, 1e100)


@dataclass
class CycleFit:
    """A calibration on force-displacement cycles (units: those of the data; a12 as delta)."""
    params: dict                  # k1, kp, kc, phiF (fitted or fixed) and shift
    free: list                    # the free names, "shift" last when freed
    a12: float
    interpolation: str
    delta: np.ndarray
    force: np.ndarray
    ci95: dict                    # free name -> [low, high], profile likelihood (the Jacobian's in extra)
    correlation: list             # between the free coordinates (logarithms; kc at 0 and shift linear)
    undetermined: list            # free names the cycles do not fix
    statements: list              # plain sentences on what the cycles do and do not determine
    rms_residual: float           # [force]
    max_residual: float           # [force]
    force_scale: float            # max |F| of the data [force]
    chi2_reduced: float           # with the data's sigma (None without)
    sigma_used: float             # the force error the intervals assume (given or estimated)
    branches: dict                # branch of the law -> number of points, with the fitted parameters
    wall_clock_s: float
    extra: dict = field(default_factory=dict)

    def curve(self, delta=None):
        """The fitted law's force along delta (default: the data's overlaps)."""
        p = self.params
        d = self.delta if delta is None else np.asarray(delta, float)
        return _theory.normal_force_path(d - p["shift"], p["k1"], p["kp"], p["kc"], p["phiF"], self.a12,
                                         self.interpolation)

    def bound(self, n):
        """The 95 % bound the cycles put on an undetermined parameter, in words (the data's units)."""
        floor, top = _OPEN_END[n]
        return _bound_text(self.ci95[n], (self.params["k1"] if floor is None else floor, top), "")

    def to_json(self):
        # An undetermined parameter keeps its number here (studies read these keys as numbers); the reason says what it
        # is.
        return {**{n: self.params[n] for n in CYCLE_PARAMETERS + ("shift",)}, "a12": self.a12,
                "undetermined_reason": {n: f"undetermined by the cycles: {self.bound(n)}; the value is "
                                           f"the fit's point, one "
                                        "of many that fit as well" for n in self.undetermined},
                "k2Interpolation": self.interpolation, "free": self.free, "ci95": _open_ends(self.ci95),
                "correlation": {"names": self.free, "matrix": _nulls(self.correlation)},
                "undetermined": self.undetermined,
                "statements": self.statements, "rms_residual": self.rms_residual, "max_residual": self.max_residual,
                "force_scale": self.force_scale, "rms_relative": self.rms_residual / self.force_scale,
                "max_relative": self.max_residual / self.force_scale, "chi2_reduced": self.chi2_reduced,
                "sigma_used": self.sigma_used, "branches": self.branches, "n_points": int(len(self.delta)),
                "wall_clock_s": self.wall_clock_s, **self.extra}

    def report(self):
        s = self.force_scale
        lines = [f"{len(self.delta)} points, free: {', '.join(self.free)}; residual rms {self.rms_residual / s:.3g}, "
                 f"max {self.max_residual / s:.3g} of max |F| = {s:.4g}"
                 + (f", reduced chi2 {self.chi2_reduced:.3g}" if self.chi2_reduced is not None else "")
                 + f"; {self.wall_clock_s:.2f} s"]
        for n in CYCLE_PARAMETERS + ("shift",):
            if n in self.undetermined:
                lines.append(f"  {n:5s} = undetermined: {self.bound(n)} (95 %)")
            elif n in self.free:
                lo, hi = self.ci95[n]
                lines.append(f"  {n:5s} = {self.params[n]:.6g}   95 %: [{lo:.4g}, {hi:.4g}]")
            else:
                lines.append(f"  {n:5s} = {self.params[n]:.6g}   (fixed)")
        if self.undetermined:
            lines.append("  (the curve uses the fit's point for "
                         + ", ".join(f"{n} = {self.params[n]:.4g}" for n in self.undetermined)
                         + ": one of many that fit as well)")
        lines.append("  branches: " + ", ".join(f"{k} {v}" for k, v in self.branches.items()))
        lines += ["  " + t for t in self.statements]
        return "\n".join(lines)


def _checked(delta, force, a12, free, values, sigma, interpolation, shift):
    """The inputs checked: (delta, force, weights, free names, values with the fixed ones).
    Raises ValueError naming what is wrong."""
    for name, x in (("delta", delta), ("force", force), ("sigma", sigma)):
        no_bools(name, x)
    d, F = _checks.finite_array("delta", delta), _checks.finite_array("force", force)
    if d.shape != F.shape:
        raise ValueError(f"delta and force must have the same length (got {len(d)} and {len(F)})")
    if not d.size:
        raise ValueError("delta and force are empty: there are no points to fit")
    _checks.positive("a12", a12)
    lo, hi = MAGNITUDES
    for name, x in (("delta", d), ("force", F), ("a12", np.array([a12]))):
        big = float(np.max(np.abs(x)))
        if big > hi or 0 < big < lo:
            what = f"a12 = {a12!r}" if name == "a12" else f"{name}: the largest |{name}| = {big!r}"
            raise ValueError(f"{what} is outside the range the fit computes in ({lo:g} to {hi:g}): rescale the units "
                             "(any consistent units do, a12 in those of delta)")
    if interpolation not in _theory.K2_INTERPOLATIONS:
        raise ValueError(f"interpolation = {interpolation!r} is invalid: must be one of {_theory.K2_INTERPOLATIONS}")
    if not isinstance(shift, bool):
        raise ValueError(f"shift = {shift!r} is invalid: must be True or False")
    free = _names("free", free, CYCLE_PARAMETERS)
    free = list(CYCLE_PARAMETERS) if free is None else free
    for n in free:
        if n not in CYCLE_PARAMETERS:
            raise ValueError(f"free parameter {n!r} is unknown: must be among {CYCLE_PARAMETERS}"
                             + (" (the overlap's offset is freed by shift=True)" if n == "shift" else ""))
    if len(set(free)) != len(free):
        raise ValueError(f"free = {free}: a parameter is named twice")
    if shift:
        free.append("shift")
    if not free:
        raise ValueError("free is empty: name a parameter to fit (or shift=True)")
    if values is not None and not hasattr(values, "keys"):
        raise TypeError(f"values = {values!r:.80} is invalid: must be a dict of parameter values")
    values = dict(values or {})
    for n in values:
        if n not in CYCLE_PARAMETERS + ("shift",):
            raise ValueError(f"value given for unknown parameter {n!r}: must be among {CYCLE_PARAMETERS + ('shift',)}")
    values.setdefault("shift", 0.0)
    for n, check in (("k1", _checks.positive), ("kc", _checks.nonnegative)):
        if n in values:
            check(n, values[n])
    if not (_checks.is_number(values["shift"]) and math.isfinite(values["shift"])):
        raise ValueError(f"shift = {values['shift']!r} is invalid: must be a finite number")
    if "phiF" in values and not (_checks.is_number(values["phiF"]) and 0 < values["phiF"] <= 1):
        raise ValueError(f"phiF = {values['phiF']!r} is invalid: must lie in (0, 1]")
    if "kp" in values and not (_checks.is_number(values["kp"]) and math.isfinite(values["kp"])
                               and values["kp"] >= values.get("k1", 0.0) and values["kp"] > 0):
        raise ValueError(f"kp = {values['kp']!r} is invalid: must be a finite number >= k1")
    missing = [n for n in CYCLE_PARAMETERS if n not in free and n not in values]
    if missing:
        raise ValueError(f"no value for {', '.join(missing)}: a parameter that is not free needs one")
    if not np.max(d - values["shift"]) > 0:
        raise ValueError(f"delta: no overlap is > 0 (after the shift {values['shift']!r}): there is no contact to fit")
    if len(d) <= len(free):
        raise ValueError(f"delta: {len(d)} points cannot fix {len(free)} free parameters ({', '.join(free)}): "
                         "more points are needed than free parameters")
    overlaps = len(np.unique(d))
    if overlaps < len(free):
        raise ValueError(f"delta: {overlaps} distinct overlap(s) ({d[0]!r}{', ...' if overlaps > 1 else ''}) cannot "
                         f"determine {len(free)} free parameters ({', '.join(free)}): F(delta) needs "
                         f"a range of overlaps")
    scale = float(np.max(np.abs(F)))
    if not scale > 0:
        raise ValueError("force: every value is 0, there is no contact force to fit")
    if not np.max(F) > 0:  # a fresh contact's first loading pushes (k1 delta > 0) whatever the parameters
        raise ValueError(f"force: no value is > 0 (the largest is {float(np.max(F))!r}): the law's force is repulsive "
                         "(> 0) on its first loading; if compression is negative in these data, pass -force")
    if np.all(F == F[0]):
        raise ValueError(f"force: all {len(F)} values are {F[0]!r}: a constant force carries no stiffness to fit "
                         "(a wrong column?)")
    if sigma is None:
        w = np.full(len(d), 1.0 / scale)
    else:
        if np.ndim(sigma) == 0 and not _checks.is_number(sigma):
            raise ValueError(f"sigma = {sigma!r} is invalid: must be a number or one per point")
        s = (np.broadcast_to(np.asarray(sigma, float), d.shape) if np.ndim(sigma) == 0
             else _checks.finite_array("sigma", sigma))
        if s.shape != d.shape:
            raise ValueError(f"sigma must be one number or one per point ({len(s)} for {len(d)} points)")
        bad = np.flatnonzero(~(np.isfinite(s) & (s > 0)))
        if bad.size:
            raise ValueError(f"sigma[{bad[0]}] = {s[bad[0]]!r} is invalid: must be a finite number > 0")
        bad = np.flatnonzero(s < SIGMA_MIN * scale)
        if bad.size:
            raise ValueError(f"sigma[{bad[0]}] = {s[bad[0]]!r} is invalid: must be >= {SIGMA_MIN:g} of the largest "
                             f"|force| ({scale!r}): the force is known to its rounding at best, and a smaller error "
                             f"overflows the weights")
        w = 1.0 / s
    return d, F, w, free, values


def _guesses(d, F, a12, values):
    """Starting values from the data where none is given: k1 the steep end of the secants F/delta
    on the first loading (new maxima of delta), kc the steep end of -F/delta in tension, kp and
    phiF on a grid (eta = 1, 4, 16; deltaMax^p 0.3, 1 and 3 times the largest overlap)."""
    x = d - values["shift"]
    top = float(np.max(x))
    big = x > 0.05 * top
    first = (x >= np.maximum.accumulate(x)) & big & (F > 0)
    if "k1" in values:
        k1 = values["k1"]
    else:
        k1 = float(np.percentile(F[first] / x[first], 90)) if first.any() else float(np.max(np.abs(F))) / top
        k1 = min(k1, values.get("kp", k1))
    tension = big & (F < 0)
    kc = (values["kc"] if "kc" in values
          else float(np.percentile(-F[tension] / x[tension], 90)) if tension.any() else 0.0)
    out = []
    for kp in ((values["kp"],) if "kp" in values else (2 * k1, 5 * k1, 17 * k1)):
        for reach in ((None,) if "phiF" in values else (0.3, 1.0, 3.0)):
            phiF = values["phiF"] if reach is None else min(1.0, max(reach * top * (kp - k1) / (kp * a12), 1e-9))
            out.append(dict(values, k1=k1, kp=kp, kc=kc, phiF=phiF))
    return out


class _Cycles:
    """The least-squares problem: the data, the fixed values, the fit's coordinates (log k1,
    log(kp - k1), log phiF <= 0, kc/k1 >= 0, shift over the largest |delta|) and local solves."""

    def __init__(self, d, F, w, a12, interpolation, free, k1):
        self.d, self.F, self.w, self.a12, self.interpolation, self.free = d, F, w, a12, interpolation, free
        self.kscale = k1  # kc's unit: the start's k1
        self.dscale = float(np.max(np.abs(d)))

    def force(self, p):
        return _theory._force_path(self.d - p["shift"], p["k1"], p["kp"], p["kc"], p["phiF"], self.a12,
                                   self.interpolation, np)[0]

    def to_x(self, n, p):
        # the e(v) fit's coordinates (problem._to_x), with kc over the start's k1; the shift is signed
        return p["shift"] / self.dscale if n == "shift" else _to_x(n, p, {"kc": self.kscale})

    def params(self, names, x, fixed):
        return _from_x(names, x, fixed, {"kc": self.kscale, "shift": self.dscale})

    def residuals(self, names, fixed):
        def fun(x):
            try:
                with np.errstate(all="ignore"):
                    r = (self.force(self.params(names, x, fixed)) - self.F) * self.w
            except (ValueError, OverflowError, ZeroDivisionError):
                r = np.full(len(self.d), np.inf)
            if not np.all(np.isfinite(r)):
                return np.full(len(self.d), 1e3)  # outside floating point: far from any data
            # finite but vast (a trial k of 1e250): the solver's differences stay finite
            return np.clip(r, -1e100, 1e100)
        return fun

    def solve(self, names, fixed, start):
        lo = [0.0 if n == "kc" else -np.inf for n in names]
        hi = [0.0 if n == "phiF" else np.inf for n in names]
        x0 = np.clip([self.to_x(n, start) for n in names], np.array(lo) + 1e-12, np.array(hi) - 1e-12)
        r = least_squares(self.residuals(names, fixed), x0, bounds=(lo, hi), x_scale="jac", method="trf",
                          xtol=1e-10, ftol=1e-12, gtol=1e-12)
        return 2 * r.cost, self.params(names, r.x, fixed)

    def ssr(self, p):
        r = self.residuals([], p)([])
        return float(r @ r)

    def best(self, names, fixed, starts, polished=1):
        """The best local solve from the `polished` starts with the smallest sum of squares."""
        firsts = sorted(starts, key=lambda q: self.ssr(dict(q, **{n: fixed[n] for n in fixed if n not in names})))
        return min((self.solve(names, fixed, q) for q in firsts[:polished]), key=lambda t: t[0])


def fit_cycles(delta, force, a12, free=CYCLE_PARAMETERS, values=None, sigma=None, interpolation="linear", shift=False):
    """Least-squares fit of theory.normal_force_path to a force measured along overlaps from a
    fresh contact (repulsive > 0; any consistent units, a12 in those of delta).

    free: names among CYCLE_PARAMETERS; values: the others' values (required) and starting guesses
    for the free ones (else taken from the data); sigma: the force's standard error (one number
    or one per point), else estimated from the residuals; shift=True frees an offset of the
    overlap (the law at delta - shift; values['shift'] is its start, or a fixed offset).
    Returns a CycleFit; raises ValueError naming what is wrong with the input."""
    t0 = time.time()
    d, F, w, free, values = _checked(delta, force, a12, free, values, sigma, interpolation, shift)
    starts = _guesses(d, F, a12, values)
    pb = _Cycles(d, F, w, a12, interpolation, free, starts[0]["k1"])
    fixed = dict(starts[0])
    for attempt in range(RESTARTS + 1):
        if "shift" in free:  # the law at the start's shift first: a free shift from a poor start runs off the data
            starts = [pb.best(free[:-1], fixed, starts, CYCLE_STARTS)[1]] + starts if len(free) > 1 else starts
        ssr_min, p = pb.best(free, fixed, starts, CYCLE_STARTS)
        _check_result(p, free, "these F(delta)")
        res = pb.force(p) - F
        n, k = len(d), len(free)
        if sigma is None:
            s2, chi2 = ssr_min / (n - k), None
            sigma_used = math.sqrt(s2) * float(np.max(np.abs(F)))
        else:
            s2, chi2, sigma_used = 1.0, ssr_min / (n - k), float(np.median(1 / w))
        if sigma is None and ssr_min < 1e-24 * n:  # rms below 1e-12 of the largest |F|
            raise ValueError("force: the fit passes through every point (to 1e-12 of the largest |F|): without sigma "
                             "the noise, and so any interval, cannot be estimated; give sigma")
        ci, corr, undetermined, statements = _identify(pb, free, p, s2)
        ci_jacobian = _open_ends({m: list(v) for m, v in ci.items()})
        better = _profile(pb, p, ssr_min, s2, ci, undetermined, statements)
        if better is None or attempt == RESTARTS:
            break
        starts = [better] + starts  # a profile refit beat the fit: start again from it
    counts, coverage = _coverage(pb, p)
    scale = float(np.max(np.abs(F)))
    return CycleFit(p, free, a12, interpolation, d, F, ci, corr, [m for m in free if m in undetermined],
                    coverage + statements,
                    float(np.sqrt(np.mean(res ** 2))), float(np.max(np.abs(res))), scale, chi2, sigma_used, counts,
                    time.time() - t0, extra={"ci95_jacobian": ci_jacobian})
