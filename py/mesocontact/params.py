"""Parameter helpers for the meso-particle law (plain Python, SI units)."""
import math

from .theory import _nonnegative, _positive, _positive_or_inf


def sphere_mass(radius, density):
    """Mass of a sphere [kg]."""
    _positive("radius", radius)
    _positive("density", density)
    return 4.0 / 3.0 * math.pi * radius ** 3 * density


def reduced_mass(m1, m2=math.inf):
    """m1 m2/(m1 + m2); against a wall (m2 = inf) the sphere's own mass [kg]."""
    _positive("m1", m1)
    _positive_or_inf("m2", m2)
    return m1 if math.isinf(m2) else m1 * m2 / (m1 + m2)


def reduced_radius(a1, a2=math.inf):
    """a12 = 2 a1 a2/(a1 + a2); against a wall (a2 = inf) 2 a1 [m]."""
    _positive("a1", a1)
    _positive_or_inf("a2", a2)
    return 2.0 * a1 if math.isinf(a2) else 2.0 * a1 * a2 / (a1 + a2)


def fa_from_alpha(alpha, k1, m_r, v_i):
    """Non-contact force from the adhesivity alpha = sqrt(fa^2/(k1 m_r v_i^2)) (Eq. 27c) [N]."""
    _nonnegative("alpha", alpha)
    _positive("k1", k1)
    _positive("m_r", m_r)
    _nonnegative("v_i", v_i)
    return alpha * math.sqrt(k1 * m_r) * v_i


def contact_time(k, m_r):
    """Half period pi sqrt(m_r/k) of a linear contact of stiffness k [s]."""
    _positive("k", k)
    _positive("m_r", m_r)
    return math.pi * math.sqrt(m_r / k)


def time_step(kp, m_min, kt=0.0, kr=0.0, ko=0.0, gamma=0.0, steps_per_contact=50):
    """A time step resolving every stiffness of the law for the smallest particle mass m_min [s].

    Highest angular frequencies of a pair of equal spheres (the worst case; a sphere against a
    wall is slower): normal kp/m_r with m_r = m/2; sliding 3.5 kt/m_r (the spring drags
    translation and rotation, I = 2/5 m a^2); rolling and torsion about 2.5 k/m with the lever
    a'12 = a/2 (10 k/m with lever 'a12'; pass 4 kr, 4 ko for that convention). The period of the
    fastest one is resolved by 2 steps_per_contact steps; gamma: the largest dashpot [kg/s].
    """
    _positive("kp", kp)
    _positive("m_min", m_min)
    _positive("steps_per_contact", steps_per_contact)
    for name, v in (("kt", kt), ("kr", kr), ("ko", ko), ("gamma", gamma)):
        _nonnegative(name, v)
    m_r = 0.5 * m_min
    omega2 = max(kp / m_r, 3.5 * kt / m_r, 2.5 * kr / m_min, 2.5 * ko / m_min)
    dt = math.pi / math.sqrt(omega2) / steps_per_contact
    if gamma > 0:
        dt = min(dt, 0.1 * m_r / gamma)
    return dt
