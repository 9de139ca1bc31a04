"""The law's parameters from other common inputs: dimensionless groups, a restitution with a
contact time, and the MesoMat attributes of a calibration."""
import functools
import inspect
import math
import sys
import warnings

from .. import checks as _checks
from .. import theory as _theory
from .data import PARAMETERS, geometry
from .problem import _phiF_for


def _in_floating_point(f):
    """The helper's k1, kp must come out finite and normal (> 0), kc finite, phiF > 0: arguments
    each valid whose result over- or underflows raise ValueError naming them all, instead of an
    OverflowError, a ZeroDivisionError or a silent k1 = 0."""
    @functools.wraps(f)
    def checked(*args, **kw):
        def fail(why):
            given = ", ".join(f"{k}={v!r}" for k, v in inspect.signature(f).bind(*args, **kw).arguments.items())
            raise ValueError(f"{f.__name__}({given}): {why}; the arguments are too extreme together") from None
        try:
            r = f(*args, **kw)
        except (OverflowError, ZeroDivisionError) as e:
            fail(f"out of floating-point range ({e})")
        for n in ("k1", "kp"):
            if not (math.isfinite(r[n]) and r[n] >= sys.float_info.min):
                fail(f"{n} = {r[n]!r} N/m is out of floating-point range")
        if not math.isfinite(r["kc"]):
            fail(f"kc = {r['kc']!r} N/m is out of floating-point range")
        if not r["phiF"] >= sys.float_info.min:
            fail(f"phiF = {r['phiF']!r} is out of floating-point range")
        return r
    return checked


@_in_floating_point
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
    if not (_checks.is_number(chi) and 0 < chi <= 1):
        raise ValueError(f"chi = {chi!r} is invalid: must lie in (0, 1] (below v_p)")
    if _theory.en_squared(chi, eta, beta, interpolation) <= 0:
        raise ValueError(f"chi = {chi!r} with eta = {eta!r}, beta = {beta!r}: the pair sticks, the contact does "
                         "not end")
    phiF = 0.5 if eta > 0 else 1.0  # any: chi carries the scale
    v = _theory.impact_velocity_for_chi(chi, 1.0, 1.0 + eta, phiF, 1.0, 1.0)
    t = _theory.contact_duration(v, 1.0, 1.0 + eta, beta, phiF, 1.0, 1.0, interpolation=interpolation)
    if not math.isfinite(t):  # the pair rebounds (above), so its contact ends: an inf is the closed form's rounding
        e = _theory.restitution_fa0(chi, eta, beta, interpolation)
        raise ValueError(f"chi = {chi!r}, eta = {eta!r}, beta = {beta!r}: the pair rebounds (e = {e:.3g}) but the "
                         "closed-form duration is not finite there: it loses its precision for a pair that barely "
                         "leaves (e near 0) or a tensile branch far weaker than k1 (use beta = 0 for "
                         "beta below about 1e-16)")
    return t


@_in_floating_point
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
    if not (math.isfinite(k1) and k1 >= sys.float_info.min):  # before phiF, which would blame the overlap
        raise ValueError(f"e = {e!r}, t_c = {t_c!r} with eta = {eta!r}, beta = {beta!r}: k1 = m_r "
                         f"(duration/t_c)^2 = {k1!r} N/m is out of floating-point range (chi = {chi:.6g}, "
                         f"m_r = {m_r:.4g} kg)")
    phiF = _phiF_for(v / chi, k1, eta, m_r, a12)
    if not 0 < phiF <= 1:
        raise ValueError(f"t_c = {t_c!r} and v = {v!r} need phiF = {phiF:.4g}, outside (0, 1]: the overlap would "
                         "exceed the particle's size")
    return {"k1": k1, "kp": (1 + eta) * k1, "kc": beta * k1, "phiF": phiF, "chi": chi}


def material(params, adhesion=None, kca=None, interpolation=None, density=None):
    """The MesoMat attributes of a calibration (a dict for MesoMat(**...) or pair.build).

    params: a Fit, calibration.json's dict (scripts/calibrate.py), or a dict of k1, kp, kc, phiF
    and fa. The adhesion mode, kca, the k2 rule and the density default to those the fit was made
    with (for a plain dict of parameters: 'none', inf, 'linear', 2000 kg/m^3). An explicit
    argument that differs from the fit's is used, with a warning: the fitted values hold for the
    fit's, and e(v) with another differs. A parameter the data left undetermined takes the fit's
    point, with a warning. Raises ValueError naming a value MesoMat would refuse."""
    values, known, undetermined = _calibration(params)
    chosen = {}
    for name, given, default in (("adhesion", adhesion, "none"), ("kca", kca, math.inf),
                                 ("interpolation", interpolation, "linear"), ("density", density, 2000.0)):
        fit_value = known.get(name)
        if given is None:
            chosen[name] = default if fit_value is None else fit_value
            continue
        if fit_value is not None and given != fit_value:
            unit = {"kca": " N/m", "density": " kg/m^3"}.get(name, "")
            warnings.warn(f"calibrate.material: {name} = {given!r}{unit} overrides the fit's {fit_value!r}{unit}: the "
                          f"fitted parameters hold for {fit_value!r}, and e(v) with {given!r} differs", UserWarning,
                          stacklevel=2)
        chosen[name] = given
    adhesion, kca, interpolation, density = (chosen["adhesion"], chosen["kca"], chosen["interpolation"],
                                             chosen["density"])
    if adhesion not in _theory.ADHESION_MODES:
        raise ValueError(f"adhesion = {adhesion!r} is invalid: must be one of {_theory.ADHESION_MODES}")
    if interpolation not in _theory.K2_INTERPOLATIONS:
        raise ValueError(f"interpolation = {interpolation!r} is invalid: must be one of {_theory.K2_INTERPOLATIONS}")
    _checks.positive_or_inf("kca", kca)
    _checks.positive("density", density)
    for n in ("k1", "kp", "kc", "phiF"):
        if n not in values:
            raise ValueError(f"params has no {n!r}: must hold k1, kp, kc, phiF (and fa with adhesion)")
    _theory.check_law(values["k1"], values["kp"], values["phiF"], 1.0)
    _checks.nonnegative("kc", values["kc"])
    fa = values.get("fa", 0.0)
    _checks.nonnegative("fa", fa)
    if fa > 0 and adhesion == "none" and "adhesion" not in known:  # dropping fa would change e(v) unnoticed
        raise ValueError(f"fa = {fa!r} N > 0 with adhesion 'none': a plain dict does not say the fit's adhesion; pass "
                         "the Fit itself (calibrate.material(fit)) or adhesion='reversible' or 'jumpIn'")
    if undetermined:
        warnings.warn("calibrate.material: " + ", ".join(f"{n} = {values[n]:.4g}" for n in undetermined)
                      + " taken from the fit's point: the data leave " + ("it" if len(undetermined) == 1 else "them")
                      + " undetermined (any value in the report's range fits as well)", UserWarning, stacklevel=2)
    m = {"k1": values["k1"], "kp": values["kp"], "kc": values["kc"], "phiF": values["phiF"],
         "adhesion": adhesion, "k2Interpolation": interpolation, "density": density}
    if adhesion != "none":
        m["fa"] = fa
        if math.isfinite(kca):
            m["kca"] = kca
    return m


def _calibration(fitted):
    """(parameter values, the fit's own settings among adhesion, kca, interpolation, density,
    the undetermined names) of a Fit, a calibration.json dict or a plain dict of parameters."""
    if hasattr(fitted, "setup") and hasattr(fitted, "params"):  # a Fit
        s = fitted.setup
        known = {"adhesion": s.adhesion, "kca": s.kca, "interpolation": s.interpolation}
        if getattr(fitted, "density", None) is not None:
            known["density"] = fitted.density
        return dict(fitted.params), known, list(fitted.undetermined)
    if not hasattr(fitted, "keys"):
        raise TypeError(f"params = {fitted!r:.80} is invalid: must be a calibrate.Fit, calibration.json's dict or a "
                        "dict of k1, kp, kc, phiF[, fa]")
    known = {}
    if "adhesion" in fitted:
        known["adhesion"] = fitted["adhesion"]
        known["kca"] = math.inf if fitted.get("kca") is None else fitted["kca"]  # JSON has no inf: null
    if "k2Interpolation" in fitted:
        known["interpolation"] = fitted["k2Interpolation"]
    if fitted.get("density") is not None and "adhesion" in fitted:  # calibration.json: the command's density
        known["density"] = fitted["density"]
    point = fitted.get("fit_point") or {}  # calibration.json: an undetermined parameter is null, its fit's point here
    values = {n: point[n] if fitted.get(n) is None and n in point else fitted[n]
              for n in PARAMETERS if n in fitted or n in point}
    return values, known, [n for n in fitted.get("undetermined", []) if n in values]
