"""Closed-form theory of the meso-particle contact model (Singh, Magnanimo & Luding).

Equation numbers are those of the long paper ("A contact model for sticking of adhesive
meso-particles"); see docs/model.md §6. Plain Python (math only): importable anywhere;
normal_force_path alone imports numpy, when called.

Two layers:
- dimensionless forms for fa = 0 (Eqs. 32-40, Appendix A, C, D) in terms of the plasticity
  eta = (kp - k1)/k1, the adhesivity beta = kc/k1 and the scaled velocity chi = v_i/v_p;
- the dimensional restitution of a pair with non-contact adhesion (Eqs. 16-25), in SI units.
"""
import functools
import math
from dataclasses import dataclass

from .checks import finite_array, is_number, nonnegative, positive, positive_or_inf

ADHESION_MODES = ("none", "reversible", "jumpIn")
K2_INTERPOLATIONS = ("linear", "sqrt")


def _in_range(f):
    """Arguments inside the domain whose result leaves floating point (e.g. v_i = 1e300) raise
    ValueError naming them, not OverflowError or a NaN."""
    names = f.__code__.co_varnames[:f.__code__.co_argcount]

    @functools.wraps(f)
    def checked(*args, **kw):
        def fail(why):
            given = ", ".join(f"{n}={v!r}" for n, v in list(zip(names, args)) + list(kw.items()))
            raise ValueError(f"{names[0]}: arguments ({given}) out of floating-point range: {why}") from None
        try:
            r = f(*args, **kw)
        except (OverflowError, ZeroDivisionError) as e:
            fail(e)
        except ValueError as e:  # math's "math domain error" names nothing; the checks' own messages stay
            if str(e) == "math domain error":
                fail(e)
            raise
        if isinstance(r, float):  # the common case first: a calibration's fit calls these millions of times
            if math.isnan(r):
                fail("the result is NaN")
        elif hasattr(r, "__dataclass_fields__") and any(
                isinstance(v, float) and math.isnan(v) for v in (getattr(r, k) for k in r.__dataclass_fields__)):
            fail("the result is NaN")
        return r
    return checked


def check_groups(eta, beta=0.0, interpolation="linear"):
    nonnegative("eta", eta)
    nonnegative("beta", beta)
    if interpolation not in K2_INTERPOLATIONS:
        raise ValueError(f"interpolation = {interpolation!r} is invalid: must be one of {K2_INTERPOLATIONS}")


def check_law(k1, kp, phiF, a12):
    positive("k1", k1)
    if not (is_number(kp) and math.isfinite(kp) and kp >= k1):
        raise ValueError(f"kp = {kp!r} is invalid: must be a finite number >= k1")
    if not (is_number(phiF) and 0 < phiF <= 1):
        raise ValueError(f"phiF = {phiF!r} is invalid: must lie in (0, 1]")
    positive("a12", a12)


# --- fa = 0, dimensionless: eta = (kp - k1)/k1, beta = kc/k1, chi = v_i/v_p (Eq. 27) -------

@_in_range
def k2_over_k1(chi, eta, interpolation="linear"):
    """k2(deltaMax)/k1 at chi = deltaMax/deltaMax^p (Eq. 29; Eq. D.1 for 'sqrt'), capped at 1 + eta."""
    nonnegative("chi", chi)
    check_groups(eta, 0.0, interpolation)
    x = min(chi, 1.0)
    return 1.0 + eta * (math.sqrt(x) if interpolation == "sqrt" else x)


# --- fa = 0: restitution, sticking window, sticking overlap -------------------------------

@_in_range
def en_squared(chi, eta, beta, interpolation="linear"):
    """Signed e_n^2 for fa = 0 (argument of the roots of Eqs. 32 and 33); negative means sticking."""
    nonnegative("chi", chi)
    check_groups(eta, beta, interpolation)
    if chi <= 1.0:
        r = k2_over_k1(chi, eta, interpolation)  # k2/k1
        # E_f/E_i = k1/k2 - kc (k2 - k1)^2/(k1 k2 (k2 + kc))  (Eq. 21 with fa = 0)
        return 1.0 / r - beta * (r - 1.0) ** 2 / (r * (r + beta))
    return 1.0 - (1.0 - en_squared(1.0, eta, beta, interpolation)) / chi ** 2


@_in_range
def restitution_fa0(chi, eta, beta, interpolation="linear"):
    """e(chi) for fa = 0: Eq. 32 (chi <= 1) and Eq. 33 (chi > 1); 0 where the pair sticks."""
    return math.sqrt(max(en_squared(chi, eta, beta, interpolation), 0.0))


@_in_range
def low_velocity_restitution(chi, eta):
    """Small-chi approximation e ~ 1 - eta chi/2 (Fig. 6); only for eta chi/2 < 1 (beyond it the
    line is negative and the approximation meaningless)."""
    nonnegative("chi", chi)
    check_groups(eta)
    if not 0.5 * eta * chi < 1:
        raise ValueError(f"chi = {chi!r} is invalid with eta = {eta!r}: the small-chi line needs eta chi/2 < 1")
    return 1.0 - 0.5 * eta * chi


@_in_range
def chi_c_b(eta, beta):
    """Lower end of the sticking window, Eq. 34 (requires beta > 0)."""
    positive("eta", eta)
    positive("beta", beta)
    return (1.0 + math.sqrt(1.0 + 4.0 * beta * (1.0 + beta))) / (2.0 * beta * eta)


@_in_range
def chi_c_c(eta, beta):
    """Upper end of the sticking window, Eq. 37."""
    check_groups(eta, beta)
    return math.sqrt(1.0 - 1.0 / (1.0 + eta) + beta * eta ** 2 / ((1.0 + eta) * (1.0 + beta + eta)))


@_in_range
def beta_star(eta):
    """Smallest adhesivity for which pairs can stick, Eq. 40b (eta > 1)."""
    check_groups(eta)
    if not eta > 1:
        raise ValueError(f"eta = {eta!r} is invalid: beta* exists only for eta > 1")
    return 1.0 / (eta - 1.0)


@_in_range
def sticking_overlap(chi, eta, beta, interpolation="linear"):
    """delta_c/deltaMax^p of a sticking pair, Eqs. 36 and 38: (chi/sqrt(beta)) sqrt(-e_n^2).

    The overlap where the kinetic energy vanishes on the -kc branch (the lower turning point of
    the oscillation that follows). Raises ValueError where the pair does not stick.
    """
    positive("beta", beta)
    e2 = en_squared(chi, eta, beta, interpolation)
    if e2 > 0:
        raise ValueError(f"chi = {chi!r}: the pair rebounds (e = {math.sqrt(e2):.6g}), no sticking overlap")
    return chi / math.sqrt(beta) * math.sqrt(-e2)


@_in_range
def max_sticking_overlap(eta, beta):
    """delta_c(chi = 1)/deltaMax^p, Eq. 39 (where the pair sticks at chi = 1: beta eta^2 >= 1 + eta + beta)."""
    check_groups(eta, beta)
    positive("beta", beta)
    if beta * eta ** 2 < 1.0 + eta + beta:
        raise ValueError(f"beta = {beta!r} is invalid with eta = {eta!r}: the pair does not stick at chi = 1 (needs "
                         f"beta eta^2 >= 1 + eta + beta)")
    return math.sqrt((beta * eta ** 2 - (1.0 + eta + beta)) / (beta * (1.0 + eta) * (1.0 + eta + beta)))


@_in_range
def restitution_asymptote(chi, eta, beta=0.0, interpolation="linear"):
    """Large-chi (chi <= 1, eta chi >> 1) asymptotes: (eta chi)^-1/2 (C.2), sqrt(1/(eta chi) - beta)
    (C.3); for 'sqrt' interpolation sqrt(eta)^-1 chi^-1/4-type decay (D.2)."""
    positive("chi", chi)
    check_groups(eta, beta, interpolation)
    positive("eta", eta)
    if interpolation == "sqrt":
        return 1.0 / math.sqrt(eta * math.sqrt(chi))
    return math.sqrt(max(1.0 / (eta * chi) - beta, 0.0))


@_in_range
def widened_kp(k1, kp, phiF, phiF_new):
    """Appendix A, Eq. A.3: limit stiffness kp' for a wider plastic range phiF' > phiF that keeps
    the low-overlap behaviour."""
    check_law(k1, kp, phiF, 1.0)
    if not (is_number(phiF_new) and 0 < phiF_new <= 1):
        raise ValueError(f"phiF_new = {phiF_new!r} is invalid: must lie in (0, 1]")
    A = (kp - k1) ** 2 / kp
    B = phiF_new / phiF
    h = 0.5 * A * B
    return k1 + h + math.sqrt(h * h + k1 * A * B)


# --- dimensional: a pair with non-contact adhesion ----------------------------------------

@dataclass(frozen=True)
class PairOutcome:
    """Result of the closed-form collision of a pair (SI units)."""
    e: float            # restitution v_f,inf / v_i,inf (0 if the pair stays bound)
    en: float           # contact part e_n = v_f/v_i (0 if it sticks in contact)
    eps_in: float       # pull-in factor v_i/v_i,inf (Eq. 17b; 1 for jump-in)
    eps_out: float      # pull-off factor v_f,inf/v_f (Eq. 18b; 0 if bound)
    v_contact: float    # relative velocity at first touch v_i [m/s]
    delta_max: float    # largest overlap: Eq. 20b below v_p, along the limit branch beyond (max_overlap) [m]
    v_p: float          # plastic-limit velocity, Eq. 19 [m/s]
    E_f: float          # kinetic energy at the end of contact, Eqs. 21/23e [J] (<= 0: sticks)
    regime: str         # 'sticking-contact', 'sticking-noncontact', 'rebound'
    plastic_limit: bool  # the limit branch was reached (v_i >= v_p)


@_in_range
def delta_max_p(k1, kp, phiF, a12):
    """Limit overlap kp/(kp - k1) phiF a12, Eq. 10 [m] (inf when kp == k1)."""
    check_law(k1, kp, phiF, a12)
    return math.inf if kp == k1 else kp / (kp - k1) * phiF * a12


@_in_range
def tensile_range(delta_max, k1, kp, kc, phiF, a12, interpolation="linear"):
    """How far a contact that reached ``delta_max`` opens from its force-free overlap delta0
    before its k2 line meets the tensile limit -kc delta (Eqs. 7-9): delta0 - delta_min =
    delta0 kc/(k2 + kc) [m]; beyond delta_max^p, delta0 = phiF a12 and k2 = kp (Eq. 11). It grows
    with delta_max up to max_tensile_range: no sintering depth stretches it further."""
    nonnegative("delta_max", delta_max)
    nonnegative("kc", kc)
    dmp = delta_max_p(k1, kp, phiF, a12)
    if delta_max >= dmp:
        return phiF * a12 * kc / (kp + kc)
    k2 = k1 * k2_over_k1(delta_max / dmp, (kp - k1) / k1, interpolation)
    return (1.0 - k1 / k2) * delta_max * kc / (k2 + kc)


def largest_pull(k2, kc, delta0):
    """The most tensile force a contact reaches when pulled apart slowly from its present history:
    where its k2 line k2 (delta - delta0) meets the tensile limit -kc delta, at delta = k2 delta0/(k2
    + kc), the pull kc k2 delta0/(k2 + kc) [N] (0 without a tensile limit or plastic history).
    Works elementwise on numbers; no check (the law's own values)."""
    return kc * k2 * delta0 / (k2 + kc) if kc > 0 and delta0 > 0 else 0.0


def normal_force_path(delta, k1, kp, kc, phiF, a12, interpolation="linear"):
    """The hysteretic normal force (> 0 repulsive) along the overlaps ``delta`` (a sequence, any
    consistent units; the force in those of k1 times delta), from a fresh contact: docs/model.md §3
    as pkg/core/NormalLaw.hpp computes it, the same arithmetic (no viscous term, no non-contact
    adhesion: quasi-static and fa = 0). Returns a numpy array.

    The history is deltaMax alone: each sample first raises it to delta (loading: k1 delta, the
    limit branch kp (delta - phiF a12) beyond deltaMax^p), then lowers it to the deltaMax whose k2
    line passes through (delta, -kc delta) if its own line lies below the tensile limit there (the
    force is then -kc delta); delta <= 0 ends the contact (force 0, deltaMax 0). Each sample's
    update is a clamp of deltaMax to [lo, hi] (lo = delta, hi = that deltaMax), and clamps compose
    to clamps, so the history is a prefix scan in log2(n) vectorised steps, not a loop."""
    import numpy as np  # theory itself stays plain Python: only this function needs numpy
    check_law(k1, kp, phiF, a12)
    nonnegative("kc", kc)
    if interpolation not in K2_INTERPOLATIONS:
        raise ValueError(f"interpolation = {interpolation!r} is invalid: must be one of {K2_INTERPOLATIONS}")
    d = finite_array("delta", delta)
    f = _force_path(d, k1, kp, kc, phiF, a12, interpolation, np)[0]
    if not np.all(np.isfinite(f)):
        raise ValueError(f"normal_force_path: arguments (k1={k1!r}, kp={kp!r}, kc={kc!r}, phiF={phiF!r}, a12={a12!r}) "
                         "out of floating-point range: the force is not finite")
    return f


def _force_path(d, k1, kp, kc, phiF, a12, interpolation, np):
    """normal_force_path on checked arguments (d a float array): (force, deltaMax after each
    sample, whether the sample is on the tensile limit, 1/deltaMax^p)."""
    touch = d > 0
    inv = (kp - k1) / (kp * phiF * a12) if kp > k1 else 0.0  # as MesoParams.cpp's pairGeometry
    lo = np.where(touch, d, 0.0)
    hi = np.where(touch, np.inf, 0.0)
    if inv > 0:
        through = _deltamax_through(d[touch], k1, kp, kc, inv, interpolation, np)
        hi[touch] = np.where(through * inv < 1, through, np.inf)  # beyond deltaMax^p the limit line is one line
    a, b = lo.copy(), hi.copy()  # prefix composition: clamp(., a[i], b[i]) = the updates of samples 0..i
    s = 1
    while s < len(d):
        a[s:], b[s:] = np.clip(a[:-s], a[s:], b[s:]), np.clip(b[:-s], a[s:], b[s:])
        s *= 2
    dm = a  # clamp(0, a, b) = a, as a >= 0
    before = np.concatenate(([0.0], dm[:-1]))
    tensile = touch & (hi < np.maximum(before, d))
    x = dm * inv
    k2 = np.where(x >= 1, kp, k1 + (kp - k1) * (np.sqrt(np.minimum(x, 1.0)) if interpolation == "sqrt" else x))
    with np.errstate(divide="ignore", invalid="ignore"):  # k2 > 0; 0 x inf where kp == k1 is discarded
        d0 = np.where(x >= 1, (1 - k1 / kp) * (1 / inv if inv > 0 else 0.0), (1 - k1 / k2) * dm)
    f = np.where(tensile, -kc * d, k2 * (d - d0))
    f[~touch] = 0.0
    return f, dm, tensile, inv


def _deltamax_through(delta, k1, kp, kc, inv, interpolation, np):
    """deltaMaxThrough of NormalLaw.hpp, elementwise on delta > 0: the deltaMax whose k2 line passes
    through (delta, -kc delta), the root of (k2(dm) - k1) dm = (k2(dm) + kc) delta in closed form
    (a quadratic for 'linear', a cubic in sqrt(dm) for 'sqrt'), unrestricted to dm < deltaMax^p."""
    dmp = 1 / inv
    x = delta * inv
    q = (k1 + kc) / (kp - k1)
    if interpolation == "linear":
        return dmp * (0.5 * x + np.sqrt(0.25 * x * x + q * x))
    P, Q = -x, -q * x  # s^3 + P s + Q = 0 with dm = deltaMax^p s^2
    D = 0.25 * Q * Q + P * P * P / 27
    r = np.sqrt(np.maximum(D, 0.0))
    with np.errstate(invalid="ignore"):  # each formula evaluated where the other is used too
        cardano = np.cbrt(-0.5 * Q + r) + np.cbrt(-0.5 * Q - r)
        trig = 2 * np.sqrt(-P / 3) * np.cos(np.arccos(1.5 * Q / P * np.sqrt(-3 / P)) / 3)
    s = np.where(D >= 0, cardano, trig)
    s = s - (s * s * s + P * s + Q) / (3 * s * s + P)  # one Newton step polishes rounding
    return dmp * s * s


@_in_range
def max_tensile_range(kp, kc, phiF, a12):
    """The supremum of tensile_range over delta_max: phiF a12 kc/(kp + kc) [m], reached on the
    limit branch (delta_max >= delta_max^p)."""
    nonnegative("kc", kc)
    positive("kp", kp)
    if not (is_number(phiF) and 0 < phiF <= 1):
        raise ValueError(f"phiF = {phiF!r} is invalid: must lie in (0, 1]")
    positive("a12", a12)
    return phiF * a12 * kc / (kp + kc)


@_in_range
def plastic_limit_velocity(k1, kp, phiF, a12, m_r, fa=0.0):
    """v_p of Eq. 19: 1/2 m_r v_p^2 = 1/2 k1 dmp^2 - fa dmp [m/s]."""
    positive("m_r", m_r)
    nonnegative("fa", fa)
    dmp = delta_max_p(k1, kp, phiF, a12)
    return math.sqrt(max(dmp * (k1 * dmp - 2.0 * fa), 0.0) / m_r)


@_in_range
def pair_collision(v_inf, k1, kp, kc, phiF, a12, m_r, fa=0.0, kca=math.inf, adhesion="none",
                   interpolation="linear"):
    """Closed-form outcome of a head-on collision without viscosity (Eqs. 16-25, 17b, 18b).

    v_inf: approach speed before any force acts [m/s]; stiffnesses in N/m, a12 [m], m_r [kg],
    fa [N]. adhesion: 'none', 'reversible' (pull-in and pull-off along -kca delta - fa) or
    'jumpIn' (no pull-in; -fa from first touch; pull-off tail after contact).
    """
    positive("v_inf", v_inf)
    positive("m_r", m_r)
    check_law(k1, kp, phiF, a12)
    nonnegative("kc", kc)
    nonnegative("fa", fa)
    positive_or_inf("kca", kca)
    if adhesion not in ADHESION_MODES:
        raise ValueError(f"adhesion = {adhesion!r} is invalid: must be one of {ADHESION_MODES}")
    if interpolation not in K2_INTERPOLATIONS:
        raise ValueError(f"interpolation = {interpolation!r} is invalid: must be one of {K2_INTERPOLATIONS}")
    if adhesion == "none":
        fa = 0.0
    if fa > 0 and not kca > 0:
        raise ValueError(f"kca = {kca!r} is invalid: must be > 0 when fa > 0")
    tail = fa * fa / kca if fa > 0 else 0.0  # 2 x energy of the non-contact tail, fa^2/kca [J]

    v_i = math.sqrt(v_inf ** 2 + tail / m_r) if adhesion == "reversible" else v_inf  # Eq. 17
    E_i = 0.5 * m_r * v_i ** 2
    d_max = max_overlap(v_i, k1, kp, phiF, a12, m_r, fa)  # Eq. 20b below v_p
    dmp = delta_max_p(k1, kp, phiF, a12)
    v_p = plastic_limit_velocity(k1, kp, phiF, a12, m_r, fa)
    limit = d_max >= dmp
    if not limit:
        k2 = k1 * k2_over_k1(d_max / dmp if math.isfinite(dmp) else 0.0, (kp - k1) / k1, interpolation)
        E_f = (k1 / k2 - kc * (k2 - k1) ** 2 / (k1 * k2 * (k2 + kc))) * 0.5 * k1 * d_max ** 2 - fa * d_max  # Eq. 21
    else:
        E_diss = (1.0 - k1 / kp + kc * (kp - k1) ** 2 / (k1 * kp * (kp + kc))) * 0.5 * k1 * dmp ** 2  # Eq. 23e
        E_f = E_i - E_diss
    if E_f <= 0:
        return PairOutcome(0.0, 0.0, v_i / v_inf, 0.0, v_i, d_max, v_p, E_f, "sticking-contact", limit)
    v_f = math.sqrt(2.0 * E_f / m_r)
    v_f_inf2 = v_f ** 2 - tail / m_r  # Eq. 18: the pull-off tail acts in both adhesive modes
    if v_f_inf2 <= 0:
        return PairOutcome(0.0, v_f / v_i, v_i / v_inf, 0.0, v_i, d_max, v_p, E_f, "sticking-noncontact", limit)
    v_f_inf = math.sqrt(v_f_inf2)
    return PairOutcome(v_f_inf / v_inf, v_f / v_i, v_i / v_inf, v_f_inf / v_f, v_i, d_max, v_p, E_f, "rebound", limit)


@_in_range
def max_overlap(v_i, k1, kp, phiF, a12, m_r, fa=0.0):
    """Largest overlap of a head-on collision with contact speed v_i, without viscosity [m]:
    Eq. 20b on the loading branch k1; beyond deltaMax^p along the limit branch kp (delta - phiF a12)."""
    nonnegative("v_i", v_i)
    check_law(k1, kp, phiF, a12)
    positive("m_r", m_r)
    nonnegative("fa", fa)
    E_i = 0.5 * m_r * v_i ** 2
    d = (fa + math.sqrt(fa * fa + k1 * m_r * v_i ** 2)) / k1  # Eq. 20b: 1/2 k1 d^2 - fa d = E_i
    dmp = delta_max_p(k1, kp, phiF, a12)
    if d <= dmp:
        return d
    d0p = phiF * a12  # kp/2 u^2 - fa u = R with u = delta - phiF a12
    R = E_i - 0.5 * k1 * dmp ** 2 + 0.5 * kp * (dmp - d0p) ** 2 + fa * d0p
    return d0p + (fa + math.sqrt(fa * fa + 2.0 * kp * R)) / kp


@_in_range
def impact_velocity_for_chi(chi, k1, kp, phiF, a12, m_r, fa=0.0):
    """Approach speed at contact v_i that reaches deltaMax = chi deltaMax^p (inverse of Eq. 20b) [m/s]."""
    nonnegative("chi", chi)
    positive("m_r", m_r)
    nonnegative("fa", fa)
    dmp = delta_max_p(k1, kp, phiF, a12)
    d = chi * dmp
    v = math.sqrt(max(d * (k1 * d - 2.0 * fa), 0.0) / m_r)
    if math.isinf(v) and math.isfinite(dmp):
        raise ValueError(f"chi = {chi!r}: the speed for it is out of floating-point range (deltaMax^p = {dmp!r} m)")
    return v


# --- the duration of a contact -------------------------------------------------------------

def _time_to(delta, v, k, b, m, target):
    """Earliest t > 0 at which delta(t) = target under m delta'' = b - k delta (one linear branch
    of the law; k < 0 on the tensile branch, whose pull weakens towards delta = 0), or None if the
    motion turns back first. Exact: harmonic (k > 0), hyperbolic (k < 0), parabolic (k = 0)."""
    if k > 0:
        w = math.sqrt(k / m)
        u0, ut = delta - b / k, target - b / k
        amp = math.hypot(u0, v / w)
        if abs(ut) > amp:
            return None
        phase = math.atan2(v / w, u0)  # u(t) = amp cos(w t - phase)
        c = math.acos(ut / amp) if amp > 0 else 0.0
        ts = [(phase + s * c + 2 * math.pi * n) / w for s in (1, -1) for n in (-1, 0, 1)]
        t = min((t for t in ts if t > 0), default=None)
        turn = ((phase % math.pi) or math.pi) / w  # the first zero of the velocity
        return t if t is not None and t <= turn else None
    if k < 0:
        kap = math.sqrt(-k / m)
        u0, ut = delta - b / k, target - b / k
        A, B = 0.5 * (u0 + v / kap), 0.5 * (u0 - v / kap)  # u(t) = A x + B/x, x = exp(kap t)
        if A == 0:
            xs = [B / ut] if ut != 0 else []
        else:
            disc = ut * ut - 4 * A * B
            xs = [] if disc < 0 else [(ut + s * math.sqrt(disc)) / (2 * A) for s in (1, -1)]
        x = min((x for x in xs if x > 1), default=None)
        if x is None or (A * B > 0 and 1 < math.sqrt(B / A) < x):  # turned back before arriving
            return None
        return math.log(x) / kap
    a = b / m
    if a == 0:
        return (target - delta) / v if v != 0 and (target - delta) / v > 0 else None
    disc = v * v + 2 * a * (target - delta)
    if disc < 0:
        return None
    t = min((t for t in ((-v + s * math.sqrt(disc)) / a for s in (1, -1)) if t > 0), default=None)
    return t if t is not None and (t <= -v / a or -v / a <= 0) else None


@_in_range
def contact_duration(v_inf, k1, kp, kc, phiF, a12, m_r, fa=0.0, kca=math.inf, adhesion="none",
                     interpolation="linear"):
    """How long the overlap of a head-on collision without viscosity stays positive, from the
    first touch to the separation of the surfaces [s]; inf if the pair sticks in contact.

    The law's branches are linear, so each phase is an exact arc: loading along k1 (and the limit
    branch kp beyond deltaMax^p) to deltaMax, un-loading along k2 to deltaMin = k2 delta0/(k2 + kc)
    (harmonic), then the tensile branch -kc delta to delta = 0 (hyperbolic: its pull weakens
    towards the surface; parabolic for kc = 0). fa pulls with a constant force throughout the
    contact (both adhesive modes); reversible adhesion speeds the approach up (Eq. 17)."""
    out = pair_collision(v_inf, k1, kp, kc, phiF, a12, m_r, fa, kca, adhesion, interpolation)
    if out.regime == "sticking-contact":
        return math.inf
    fa = fa if adhesion != "none" else 0.0
    dmp, d0p = delta_max_p(k1, kp, phiF, a12), phiF * a12
    v = out.v_contact
    hit = _time_to(0.0, v, k1, fa, m_r, dmp) if math.isfinite(dmp) else None
    if hit is None:  # the peak on the loading branch k1 (harmonic about fa/k1)
        w, u = math.sqrt(k1 / m_r), -fa / k1
        t = math.atan2(v / w, u) / w
        d_max = fa / k1 + math.hypot(u, v / w)
        f_max = k1 * d_max
    else:  # on to the peak along the limit branch kp (delta - phiF a12), harmonic about d0p + fa/kp
        v = math.sqrt(max(v * v - (k1 * dmp * dmp - 2 * fa * dmp) / m_r, 0.0))
        w, u = math.sqrt(kp / m_r), dmp - d0p - fa / kp
        t = hit + math.atan2(v / w, u) / w
        d_max = d0p + fa / kp + math.hypot(u, v / w)
        f_max = kp * (d_max - d0p)
    k2 = k1 * k2_over_k1(min(d_max / dmp, 1.0) if math.isfinite(dmp) else 0.0, (kp - k1) / k1, interpolation)
    delta0 = d_max - f_max / k2
    d_min = k2 * delta0 / (k2 + kc)
    # un-loading along k2 from rest at deltaMax to deltaMin: harmonic about delta0 + fa/k2
    w2, c2 = math.sqrt(k2 / m_r), delta0 + fa / k2
    ratio = (d_min - c2) / (d_max - c2)
    if ratio < -1:
        return math.inf  # turns back above deltaMin: held in contact
    t += math.acos(min(1.0, ratio)) / w2
    v = -w2 * math.sqrt(max((d_max - c2) ** 2 - (d_min - c2) ** 2, 0.0))
    rest = _time_to(d_min, v, -kc, fa, m_r, 0.0) if d_min > 0 else 0.0  # tensile branch: m delta'' = kc delta + fa
    return t + rest if rest is not None else math.inf
