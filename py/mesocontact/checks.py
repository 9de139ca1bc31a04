"""Argument checks shared by the package's plain-Python and YADE-side helpers: a wrong value is a
ValueError naming the argument and the range it must lie in (plain Python, no YADE)."""
import math
import numbers


def is_number(value):
    """A real number (numpy's included), not a bool: dt=True is a slip, not 1 s."""
    # float and int (numpy's float64 is a float) first: the abstract numbers.Real check is slow, and
    # the closed form's checks run it millions of times in a calibration's fit
    if isinstance(value, float):
        return True
    if isinstance(value, int):
        return not isinstance(value, bool)
    return isinstance(value, numbers.Real)


def positive(name, value):
    if not (is_number(value) and math.isfinite(value) and value > 0):
        raise ValueError(f"{name} = {value!r} is invalid: must be a finite number > 0")


def nonnegative(name, value):
    if not (is_number(value) and math.isfinite(value) and value >= 0):
        raise ValueError(f"{name} = {value!r} is invalid: must be a finite number >= 0")


def positive_or_inf(name, value):
    if not (is_number(value) and value > 0):  # NaN fails too
        raise ValueError(f"{name} = {value!r} is invalid: must be a number > 0 (inf allowed)")


def finite_array(name, value):
    """``value`` as a one-dimensional numpy float array of finite numbers; a ValueError naming
    ``name`` (and the first bad index) otherwise. numpy is imported here, not by the module."""
    import numpy as np
    try:
        a = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{name} is invalid: must be a sequence of numbers") from None
    if a.ndim != 1:
        raise ValueError(f"{name} is invalid: must be a one-dimensional sequence (got shape {a.shape})")
    bad = np.flatnonzero(~np.isfinite(a))
    if bad.size:
        raise ValueError(f"{name}[{bad[0]}] = {a[bad[0]]!r} is invalid: must be finite")
    return a


def vector(name, value, length=3):
    """``value`` as a tuple of ``length`` finite floats (a tuple, list, numpy array or YADE Vector3);
    a TypeError (not a sequence of numbers) or ValueError (length, NaN, inf) naming ``name``."""
    allowed = f"must be a sequence of {length} finite numbers"
    try:
        # a mapping iterates its keys and a set has no order: neither is a vector
        unordered = isinstance(value, (str, bytes, dict, set, frozenset)) or hasattr(value, "keys")
        items = None if unordered else list(value)
    except TypeError:
        items = None
    if items is None:
        raise TypeError(f"{name} = {value!r} is invalid: {allowed}")
    if len(items) != length:
        raise ValueError(f"{name} = {value!r} is invalid: {allowed} (it has {len(items)})")
    for i, x in enumerate(items):
        if not is_number(x):
            raise TypeError(f"{name} = {value!r} is invalid: {allowed} ({name}[{i}] = {x!r})")
        if not math.isfinite(x):
            raise ValueError(f"{name} = {value!r} is invalid: {allowed} ({name}[{i}] = {x!r})")
    return tuple(float(x) for x in items)
