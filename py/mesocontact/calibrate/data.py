"""The data a calibration fits and the collisions they come from: restitution e(v) read and checked,
the pair's geometry, the law's fixed choices (plain Python)."""
import csv
import math
from dataclasses import dataclass

import numpy as np

from .. import params as _params
from .. import theory as _theory

PARAMETERS = ("k1", "kp", "kc", "phiF", "fa")
AGAINST = ("particle", "wall")
# SI units of the fitted parameters
UNITS = {"k1": "N/m", "kp": "N/m", "kc": "N/m", "phiF": "", "fa": "N", "kca": "N/m"}
SIGMA_MIN = 1e-15                 # a restitution's error below this is below e's rounding (and its weight overflows)


class DataError(ValueError):
    """Restitution data that cannot be fitted (the message names the problem and the row)."""


@dataclass
class Data:
    v: np.ndarray                 # approach speeds v_inf [m/s]
    e: np.ndarray                 # restitution (0: the pair stuck)
    sigma: np.ndarray = None      # standard errors of e, or None (then estimated from the residuals)
    source: str = ""


def no_bools(name, value, error=ValueError):
    """Refuses a bool among the numbers of ``value`` (a number or a sequence), naming it: numpy
    reads True as 1.0, a speed or an overlap of 1, which is a slip, not a measurement."""
    if isinstance(value, np.ndarray):
        if value.dtype.kind == "b" and value.size:
            raise error(f"{name}[0] = {value.flat[0]!r} is invalid: a bool, not a number")
        if value.dtype.kind != "O":
            return
        value = value.ravel().tolist()
    if isinstance(value, (bool, np.bool_)):
        raise error(f"{name} = {value!r} is invalid: a bool, not a number")
    if isinstance(value, (list, tuple)):
        for i, x in enumerate(value):
            if isinstance(x, (bool, np.bool_)):
                raise error(f"{name}[{i}] = {x!r} is invalid: a bool, not a number")


def _floats(name, value, source):
    no_bools(name, value, DataError)
    try:
        return np.asarray(value, float)
    except (TypeError, ValueError):
        raise DataError(f"{source}: {name} is invalid: must be a sequence of numbers (got {value!r:.80})") from None


def check_data(v, e, sigma=None, source="data"):
    """Data with every value checked: v > 0 and finite, 0 <= e <= 1, sigma >= SIGMA_MIN."""
    v, e = _floats("v", v, source), _floats("e", e, source)
    if v.shape != e.shape or v.ndim != 1:
        raise DataError(f"{source}: v and e must be two lists of the same length (got {v.shape} and {e.shape})")
    if len(v) == 0:
        raise DataError(f"{source}: no data points")
    for name, x, ok, need in (("v", v, lambda a: np.isfinite(a) & (a > 0),
                               "a finite speed > 0 [m/s] (the approach speed)"),
                              ("e", e, lambda a: np.isfinite(a) & (a >= 0) & (a <= 1),
                               "in [0, 1] (e = 0: the pair stuck)")):
        bad = np.flatnonzero(~ok(x))
        if bad.size:
            raise DataError(f"{source}: {name} = {x[bad[0]]!r} at point {bad[0] + 1} is invalid: must be {need}")
    if sigma is not None:
        sigma = _floats("sigma", sigma, source)
        if sigma.shape != v.shape:
            raise DataError(f"{source}: sigma must have one value per point ({sigma.shape} for {v.shape})")
        bad = np.flatnonzero(~(np.isfinite(sigma) & (sigma > 0)))
        if bad.size:
            raise DataError(f"{source}: sigma = {sigma[bad[0]]!r} at point {bad[0] + 1} is invalid: must be "
                            f"a finite number > 0")
        bad = np.flatnonzero(sigma < SIGMA_MIN)
        if bad.size:
            raise DataError(f"{source}: sigma = {sigma[bad[0]]!r} at point {bad[0] + 1} is invalid: must "
                            f"be >= {SIGMA_MIN:g} "
                            "(e is known to its rounding at best; a smaller error overflows the fit's weights)")
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
            raise DataError(f"{path}: column {need!r} is missing (the header is {header}; needed: v, e "
                            f"and optionally sigma)")
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
