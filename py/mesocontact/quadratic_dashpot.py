"""Closed form of a head-on collision with the quadratic dashpot (MesoMat.gammaN2; docs/model.md §5).

The normal law with gammaN = 0, kc = 0, fa = 0 and the dashpot force gammaN2 |v| v in contact: with
u = v^2 along the overlap x, m_r v dv/dx = -F_h(x) -/+ gammaN2 u is linear in u on every linear
branch of the hysteretic force F_h = k (x - r), so each branch has an exact solution, and the turning
point is a Lambert W (w0_plus_one). Loading k1 x (and the limit branch kp (x - phiF a12) beyond deltaMax^p),
unloading along k2(deltaMax) to its force-free overlap delta0, then the dashpot alone out to x = 0
(the hysteretic force is 0 there without kc). With a = 2 gammaN2/m_r, on a branch entered at
y_s = x_s - r with u_s:
  loading    u(y)/C = (u_s/C + a y_s - 1) exp(-a (y - y_s)) - a y + 1,  C = k m_r/(2 gammaN2^2),
             u = 0 at a y = 1 + W0((u_s/C + a y_s - 1) exp(a y_s - 1));
  unloading  u(delta0) = C2 (1 - (1 + b) exp(-b)),  b = a (deltaMax - delta0),  C2 with k2;
  outward    u(0) = u(delta0) exp(-a delta0).
Plain Python (math only).
"""
import math
from dataclasses import dataclass

from .checks import positive
from .theory import check_law, delta_max_p, k2_over_k1, K2_INTERPOLATIONS


@dataclass
class QuadraticOutcome:
    e: float            # restitution v_out/v_in
    delta_max: float    # largest overlap [m]
    delta0: float       # force-free overlap of the unloading line [m]
    v_at_delta0: float  # speed where the hysteretic force ends [m/s]
    plastic_limit: bool  # the limit branch was reached


# W0 about its branch point in p = sqrt(2 (1 + e q)): W0 = -1 + p - p^2/3 + 11/72 p^3 - ... (Corless et al. 1996)
_BRANCH_SERIES = (1.0, -1.0 / 3.0, 11.0 / 72.0, -43.0 / 540.0, 769.0 / 17280.0, -221.0 / 8505.0, 680863.0 / 43545600.0)


def w0_plus_one(t):
    """1 + W0(q) with q = (t - 1)/e, from t = 1 + e q >= 0, to full relative precision also near the
    branch point q = -1/e (t = 0), where W0 = -1: there both t and 1 + W0 are small, and the
    collision's turning point is 1 + W0 over a. It solves f(y) = y e^y - expm1(y) = t for y = 1 + W0."""
    if not t >= 0:
        raise ValueError(f"t = {t!r}: W0 needs 1 + e q >= 0")
    if t == 0:
        return 0.0
    if t < 1e-4:  # the series (7 terms: truncated at p^8 ~ 1e-15 of p)
        p = math.sqrt(2.0 * t)
        y = sum(c * p ** (k + 1) for k, c in enumerate(_BRANCH_SERIES))
    else:
        q = (t - 1.0) / math.e
        if t < 0.3:
            w = -1.0 + math.sqrt(2.0 * t) * (1.0 - math.sqrt(2.0 * t) / 3.0)
        else:
            w = math.log1p(q) if q < 3.0 else math.log(q) - math.log(math.log(q))
        for _ in range(60):  # Halley on w e^w = q
            ew = math.exp(w)
            f = w * ew - q
            step = f / (ew * (w + 1.0) - (w + 2.0) * f / (2.0 * w + 2.0))
            w -= step
            if abs(step) <= 4e-16 * (1.0 + abs(w)):
                break
        y = 1.0 + w
    for _ in range(2):  # Newton on f(y) = t itself: q = (t - 1)/e has lost t's last digits near the branch point
        y -= (_f(y) - t) / (y * math.exp(y))
    return y


def _series(b, weight):
    """sum over n >= 2 of weight(n) b^n/n!, for |b| < 0.5 (where the closed forms below cancel)."""
    total, term, n = 0.0, b, 1
    while True:
        n += 1
        term *= b / n
        add = weight(n) * term
        total += add
        if abs(add) <= 1e-17 * abs(total) or n > 60:
            return total


def _f(b):
    """b e^b - expm1(b) = sum (n - 1) b^n/n!; f(-b) = 1 - (1 + b) e^-b."""
    return _series(b, lambda n: n - 1) if abs(b) < 0.5 else b * math.exp(b) - math.expm1(b)


def _g(d):
    """e^-d - 1 + d = sum (-d)^n/n!."""
    return _series(-d, lambda n: 1) if abs(d) < 0.5 else math.expm1(-d) + d


def _turn(s_s, b_s):
    """a y where u = 0 on a loading branch entered at a y_s = b_s with u_s/C = s_s:
    1 + e q = 1 + (s_s + b_s - 1) e^b_s = s_s e^b_s + f(b_s)."""
    return w0_plus_one(s_s * math.exp(b_s) + _f(b_s))


def _loading_u(s_s, b_s, b):
    """u/C at a y = b on a loading branch entered at a y_s = b_s with u_s/C = s_s:
    (s_s + b_s - 1) e^-(b - b_s) - b + 1 = s_s e^-d + b_s expm1(-d) - g(d), d = b - b_s."""
    d = b - b_s
    return s_s * math.exp(-d) + b_s * math.expm1(-d) - _g(d)


def restitution(v_i, k1, kp, phiF, a12, m_r, gammaN2, interpolation="linear"):
    """e of a head-on pair with contact speed v_i [m/s] and the quadratic dashpot gammaN2 [kg/m]
    alone (gammaN = kc = fa = 0): the closed form of the module's docstring."""
    positive("v_i", v_i)
    positive("m_r", m_r)
    positive("gammaN2", gammaN2)
    check_law(k1, kp, phiF, a12)
    if interpolation not in K2_INTERPOLATIONS:
        raise ValueError(f"interpolation = {interpolation!r} is invalid: must be one of {K2_INTERPOLATIONS}")
    a = 2.0 * gammaN2 / m_r
    dmp = delta_max_p(k1, kp, phiF, a12)
    c1 = k1 * m_r / (2.0 * gammaN2 ** 2) if gammaN2 > 1e-150 else math.inf
    if not math.isfinite(c1 * kp / k1):
        raise ValueError(f"gammaN2 = {gammaN2!r} is too small for this closed form (its scale k m_r/(2 gammaN2^2) "
                         "leaves floating point): use theory.pair_collision, the limit gammaN2 -> 0")
    x_max = _turn(v_i * v_i / c1, 0.0) / a
    limit = x_max > dmp
    if limit:  # on to the limit branch kp (x - phiF a12) from dmp, where u is the k1 branch's
        u_p = c1 * _loading_u(v_i * v_i / c1, 0.0, a * dmp)
        d0p = phiF * a12
        cp = kp * m_r / (2.0 * gammaN2 ** 2)
        x_max = d0p + _turn(u_p / cp, a * (dmp - d0p)) / a
        k2, delta0 = kp, d0p
    else:
        k2 = k1 * k2_over_k1(x_max / dmp if math.isfinite(dmp) else 0.0, (kp - k1) / k1, interpolation)
        delta0 = (1.0 - k1 / k2) * x_max
    u0 = k2 * m_r / (2.0 * gammaN2 ** 2) * _f(-a * (x_max - delta0))
    v_out = math.sqrt(u0 * math.exp(-a * delta0))
    return QuadraticOutcome(v_out / v_i, x_max, delta0, math.sqrt(u0), limit)
