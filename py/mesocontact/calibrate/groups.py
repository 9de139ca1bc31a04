"""The law's parameters from other common inputs: dimensionless groups, a restitution with a
contact time, and the MesoMat attributes of a calibration."""
import math

from .. import checks as _checks
from .. import theory as _theory
from .data import geometry
from .problem import _phiF_for


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


def material(params, adhesion="none", kca=math.inf, interpolation="linear", density=2000.0):
    """The MesoMat attributes of a calibration (a dict for MesoMat(**...) or pair.build)."""
    m = {"k1": params["k1"], "kp": params["kp"], "kc": params["kc"], "phiF": params["phiF"],
         "adhesion": adhesion, "k2Interpolation": interpolation, "density": density}
    if adhesion != "none":
        m["fa"] = params["fa"]
        if math.isfinite(kca):
            m["kca"] = kca
    return m
