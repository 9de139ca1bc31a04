"""Parameter helpers for the meso-particle law (plain Python, SI units)."""
import inspect
import math
import sys

from .checks import is_number, nonnegative, positive, positive_or_inf


# Every nonzero number a MesoMat holds lies in this range (pkg/core/MesoParams.hpp, kSmallestValue/kLargestValue).
MESOMAT_RANGE = (1e-100, 1e100)


def _representable(f, zero_ok=False):
    """The helper's result must be a finite number > 0 (>= 0 where zero_ok): inputs whose result
    overflows or underflows raise ValueError naming them, instead of returning inf or 0."""
    import functools

    @functools.wraps(f)
    def checked(*args, **kw):
        r = f(*args, **kw)
        if not (math.isfinite(r) and (r >= 0 if zero_ok else r > 0)):
            bound = inspect.signature(f).bind(*args, **kw)
            given = ", ".join(f"{k}={v!r}" for k, v in bound.arguments.items())
            raise ValueError(f"{f.__name__}({given}) = {r!r} is out of floating-point range: the "
                             f"arguments are too extreme")
        return r
    return checked


def _zero_ok(f):
    return _representable(f, zero_ok=True)


def sphere_mass(radius, density):
    """Mass of a sphere [kg]."""
    positive("radius", radius)
    positive("density", density)
    try:
        m = 4.0 / 3.0 * math.pi * radius ** 3 * density
    except OverflowError:
        m = math.inf
    if not (sys.float_info.min <= m < math.inf):  # a subnormal mass has lost its digits
        raise ValueError(f"radius = {radius!r}, density = {density!r}: the mass {m!r} kg is out of "
                         "floating-point range")
    return m


@_representable
def reduced_mass(m1, m2=math.inf):
    """m1 m2/(m1 + m2); against a wall (m2 = inf) the sphere's own mass [kg]."""
    positive("m1", m1)
    positive_or_inf("m2", m2)
    return m1 if math.isinf(m2) else m1 * m2 / (m1 + m2)


@_representable
def reduced_radius(a1, a2=math.inf):
    """a12 = 2 a1 a2/(a1 + a2); against a wall (a2 = inf) 2 a1 [m]."""
    positive("a1", a1)
    positive_or_inf("a2", a2)
    return 2.0 * a1 if math.isinf(a2) else 2.0 * a1 * a2 / (a1 + a2)


@_zero_ok
def fa_from_alpha(alpha, k1, m_r, v_i):
    """Non-contact force from the adhesivity alpha = sqrt(fa^2/(k1 m_r v_i^2)) (Eq. 27c) [N]."""
    nonnegative("alpha", alpha)
    positive("k1", k1)
    positive("m_r", m_r)
    nonnegative("v_i", v_i)
    return alpha * math.sqrt(k1 * m_r) * v_i


@_representable
def contact_time(k, m_r):
    """Half period pi sqrt(m_r/k) of a linear contact of stiffness k [s]."""
    positive("k", k)
    positive("m_r", m_r)
    return math.pi * math.sqrt(m_r / k)


@_representable
def resolved_step(kp, m_min, kt=0.0, kr=0.0, ko=0.0, gamma=0.0, steps_per_contact=50, m_r=None):
    """An accuracy step, not a stability bound: the time step that resolves the half period of
    the law's stiffest element by steps_per_contact steps, for the smallest particle mass m_min,
    in closed form [s]; the package's one accuracy recipe (the tablet: t_c/50; the pair drivers:
    t_c/2000 of kp). For a scene's O.dt use mesocontact.scene.time_step(safety), a fraction of
    the stable step of every pair that can meet (walls and mixed materials included); its
    safety 0.05 gives about 16 steps per half period of the stiffest element where
    resolved_step gives 50.

    Highest angular frequencies of a pair of equal spheres (the worst case; a sphere against a
    wall is slower): normal kp/m_r with m_r = m/2 (or the pair's own ``m_r``: unequal spheres,
    a sphere on a wall with m_r = m); sliding 3.5 kt/m_r (the spring drags translation and
    rotation, I = 2/5 m a^2); rolling and torsion about 2.5 k/m with the lever a'12 = a/2
    (10 k/m with lever 'a12'; pass 4 kr, 4 ko for that convention). The period of the fastest
    one is resolved by 2 steps_per_contact steps; gamma: the largest dashpot [kg/s].
    """
    positive("kp", kp)
    positive("m_min", m_min)
    positive("steps_per_contact", steps_per_contact)
    for name, v in (("kt", kt), ("kr", kr), ("ko", ko), ("gamma", gamma)):
        nonnegative(name, v)
    if m_r is None:
        m_r = 0.5 * m_min
    positive("m_r", m_r)
    omega2 = max(kp / m_r, 3.5 * kt / m_r, 2.5 * kr / m_min, 2.5 * ko / m_min)
    dt = math.pi / math.sqrt(omega2) / steps_per_contact
    if gamma > 0:
        dt = min(dt, 0.1 * m_r / gamma)
    return dt


def _solve(f, lo, hi, name, what):
    """The root of the monotonic f on [lo, hi] (log-spaced bisection to a relative 1e-13)."""
    flo, fhi = f(lo), f(hi)
    if flo == 0 or fhi == 0:
        return lo if flo == 0 else hi
    if (flo > 0) == (fhi > 0):
        raise ValueError(f"{name}: no {what} in [{lo:.3g}, {hi:.3g}] reproduces it (the inputs contradict each other)")
    for _ in range(200):
        mid = math.sqrt(lo * hi)
        fm = f(mid)
        if (fm > 0) == (flo > 0):
            lo, flo = mid, fm
        else:
            hi = mid
        if hi / lo - 1 < 1e-13:
            break
    return math.sqrt(lo * hi)


def _newton(f, x, tol=1e-13):
    """A root of the 2-vector f near x (Newton with a finite-difference Jacobian and step
    halving), or None."""
    r = f(x)
    for _ in range(60):
        if r is None:
            return None
        if max(abs(r[0]), abs(r[1])) < tol:
            return x
        h = 1e-7
        cols = []
        for n in range(2):
            z = list(x)
            z[n] += h
            rz = f(z)
            if rz is None:
                return None
            cols.append(((rz[0] - r[0]) / h, (rz[1] - r[1]) / h))
        det = cols[0][0] * cols[1][1] - cols[1][0] * cols[0][1]
        if det == 0:
            return None
        step = ((r[0] * cols[1][1] - r[1] * cols[1][0]) / det, (cols[0][0] * r[1] - cols[0][1] * r[0]) / det)
        for _ in range(30):
            z = [x[0] - step[0], x[1] - step[1]]
            rz = f(z)
            if rz is not None and max(abs(rz[0]), abs(rz[1])) < max(abs(r[0]), abs(r[1])):
                x, r = z, rz
                break
            step = (0.5 * step[0], 0.5 * step[1])
        else:
            return None
    return None


# the stiffnesses material_from tries [N/m]: their collisions' products stay inside floating point
K1_RANGE = (1e-200, 1e200)


def material_from(radius, density, impact_speed, restitution, contact_time, phiF=None, plastic_overlap=None,
                  kc_over_kp=0.0, pull_off_force=None, fa=0.0, kca=None, adhesion="jumpIn", radius2=None,
                  interpolation="linear", limit=None):
    """MesoMat parameters from what a user can measure on a collision of two equal spheres (or of
    a sphere on a wall: radius2 = inf), through the closed-form theory [SI units]. Returns a dict
    for MesoMat(**kw): k1, kp, kc, phiF, fa, kca, adhesion, k2Interpolation, gammaN = 0, density.

    What fixes what (the law has more parameters than one collision measures):
    - restitution e and contact_time (how long the overlap lasts, first touch to separation,
      theory.contact_duration) at one impact_speed (the approach speed before any force acts)
      fix k1 and kp together, with everything else given;
    - one speed's e and contact time can fit two materials, one whose collision reached the
      plastic limit (beyond it e rises again with the speed, Eq. 33) and one whose did not:
      limit=True or False says which (a collision beyond the limit leaves the full plastic_overlap);
      without it, two fits raise ValueError listing both;
    - phiF (or plastic_overlap = phiF a12, the permanent overlap a collision at or beyond the
      plastic limit leaves) is an input: e at one speed cannot tell a stiffer limit branch from a
      wider plastic range (Appendix A);
    - the contact adhesion: kc_over_kp, or pull_off_force, the largest pull a contact loaded to
      the plastic limit resists, kp kc/(kp + kc) phiF a12 (below kp phiF a12);
    - the non-contact adhesion fa (with kca, default k1; its range is fa/kca) is an input: a
      sticking speed does not fix it, since kc alone can hold a pair at the same speed
      (fa_from_alpha turns an adhesivity into fa);
    - not fixed here: the viscosity gammaN (0: one e mixes it with plasticity) and the sliding,
      rolling and torsion elements (docs/tangential.md).
    Raises ValueError naming the input that no parameters reproduce."""
    from .theory import ADHESION_MODES, K2_INTERPOLATIONS, contact_duration, pair_collision
    positive("radius", radius)
    positive("density", density)
    positive("impact_speed", impact_speed)
    if not (is_number(restitution) and 0 < restitution < 1):
        raise ValueError(f"restitution = {restitution!r} is invalid: must lie in (0, 1) (1 has no plasticity, 0 is "
                         f"the sticking regime)")
    positive("contact_time", contact_time)
    nonnegative("kc_over_kp", kc_over_kp)
    nonnegative("fa", fa)
    if kca is not None:
        positive("kca", kca)
    if adhesion not in ADHESION_MODES:
        raise ValueError(f"adhesion = {adhesion!r} is invalid: must be one of {ADHESION_MODES}")
    if fa > 0 and adhesion == "none":  # MesoMat refuses this pair of values: so does the fit, before it runs
        raise ValueError("adhesion = 'none' is invalid with fa > 0: choose 'reversible' or 'jumpIn', or set fa = 0")
    if limit not in (None, True, False):
        raise ValueError(f"limit = {limit!r} is invalid: None, True or False")
    if interpolation not in K2_INTERPOLATIONS:
        raise ValueError(f"interpolation = {interpolation!r} is invalid: must be one of {K2_INTERPOLATIONS}")
    radius2 = radius if radius2 is None else radius2
    positive_or_inf("radius2", radius2)
    # what MesoMat takes; beyond, the masses leave floating point
    if not MESOMAT_RANGE[0] <= density <= MESOMAT_RANGE[1]:
        raise ValueError(f"density = {density!r} is invalid: must lie in [1e-100, 1e100] [kg/m^3], as MesoMat's")
    m1 = sphere_mass(radius, density)
    try:
        m2 = math.inf if math.isinf(radius2) else sphere_mass(radius2, density)
    except ValueError as e:
        raise ValueError(f"radius2 = {radius2!r}: {e}") from None
    m_r = reduced_mass(m1, m2)
    a12 = reduced_radius(radius, radius2)
    if (phiF is None) == (plastic_overlap is None):
        raise ValueError("phiF, plastic_overlap: give exactly one (phiF = plastic_overlap/a12)")
    if plastic_overlap is not None:
        positive("plastic_overlap", plastic_overlap)
        phiF = plastic_overlap / a12
    if not (is_number(phiF) and 0 < phiF <= 1):
        raise ValueError(f"phiF = {phiF!r} is invalid: must lie in (0, 1] (plastic_overlap up to a12 = {a12!r})")
    if pull_off_force is not None:
        positive("pull_off_force", pull_off_force)

    def kc_of(kp):
        if pull_off_force is None:
            return kc_over_kp * kp
        x = pull_off_force / (kp * phiF * a12)
        return math.inf if x >= 1 else kp * x / (1 - x)

    def law(x):  # x = (ln k1, ln(kp/k1 - 1))
        k1 = math.exp(x[0])
        kp = k1 * (1 + math.exp(x[1]))
        kc = kc_of(kp)
        if not math.isfinite(kc):
            return None
        return dict(k1=k1, kp=kp, kc=kc, phiF=phiF, a12=a12, m_r=m_r, fa=fa, kca=kca or k1,
                    adhesion=adhesion if fa > 0 else "none", interpolation=interpolation)

    def gaps(x):  # the misfits of e and of the contact time
        p = law(x)
        if p is None:
            return None
        o = pair_collision(impact_speed, **p)
        if o.regime == "sticking-contact":
            return None
        return o.e - restitution, contact_duration(impact_speed, **p) / contact_time - 1

    # e(kp) need not be monotonic (it turns where the collision crosses the plastic limit, and
    # where the pull-off force ties kc to kp): a grid finds the cells where both misfits change
    # sign, Newton refines each. The loading arc alone lasts pi/2 sqrt(m_r/k1) or longer, so
    # k1 >= m_r (pi/(2 contact_time))^2; the grid spans e^10 above that, kp/k1 - 1 in [1e-6, 1.3e3].
    # In logarithms: m_r (pi/(2 contact_time))^2 itself over- or underflows for contact times like 1e-300 or 1e300 s.
    a0 = math.log(m_r) + 2 * (math.log(0.5 * math.pi) - math.log(contact_time))
    lo, hi = math.log(K1_RANGE[0]), math.log(K1_RANGE[1])
    if not lo <= a0 <= hi - 10:
        raise ValueError(f"contact_time = {contact_time!r} is out of range for radius = {radius!r}, "
                         f"density = {density!r}: the stiffness of a contact that lasts that long, m_r (pi/(2 "
                         f"contact_time))^2 = 1e{a0 / math.log(10):+.0f} N/m (m_r = {m_r:.4g} kg), lies outside "
                         f"{K1_RANGE[0]:g} to {K1_RANGE[1]:g} N/m")
    xs = [a0 + 10 * i / 80 for i in range(81)]
    ys = [math.log(1e-6) + 21 * j / 80 for j in range(81)]
    try:
        grid = [[gaps((x, y)) for y in ys] for x in xs]
        found = []
        for i in range(80):
            for j in range(80):
                corners = [grid[i][j], grid[i + 1][j], grid[i][j + 1], grid[i + 1][j + 1]]
                if None in corners or any(len({c[n] > 0 for c in corners}) < 2 for n in (0, 1)):
                    continue
                x = _newton(gaps, [0.5 * (xs[i] + xs[i + 1]), 0.5 * (ys[j] + ys[j + 1])])
                if x and not any(abs(x[0] - f[0]) < 1e-6 and abs(x[1] - f[1]) < 1e-6 for f in found):
                    found.append(x)
    except ValueError as e:  # the inputs are each valid: together they put the trial collisions outside floating point
        raise ValueError(f"impact_speed = {impact_speed!r}, contact_time = {contact_time!r}, "
                         f"kc_over_kp = {kc_over_kp!r}, pull_off_force = {pull_off_force!r}, fa = {fa!r}, "
                         f"kca = {kca!r}: the trial collisions (k1 from {math.exp(xs[0]):.3g} to "
                         f"{math.exp(xs[-1]):.3g} N/m) cannot be computed: {e}") from None
    reached = {tuple(x): pair_collision(impact_speed, **law(x)).plastic_limit for x in found}
    if limit is not None:
        found = [x for x in found if reached[tuple(x)] == limit]
    if not found:
        raise ValueError(f"restitution = {restitution!r}, contact_time = {contact_time!r}: no k1, kp reproduce both at "
                         f"impact_speed = {impact_speed!r}" + ("" if limit is None else f" with limit={limit!r}")
                         + _why_not(grid, restitution, contact_time))
    if len(found) > 1:
        alts = "; ".join(f"k1 = {law(x)['k1']:.4g}, kp = {law(x)['kp']:.4g}, kc = {law(x)['kc']:.4g} "
                         f"({'beyond' if reached[tuple(x)] else 'below'} the plastic limit)" for x in found)
        raise ValueError(f"restitution = {restitution!r}, contact_time = {contact_time!r}: {len(found)} materials "
                         f"reproduce them at impact_speed = {impact_speed!r} ({alts}); say which with "
                         f"limit=True or limit=False")
    p = law(found[0])
    out = FittedMaterial(k1=p["k1"], kp=p["kp"], kc=p["kc"], phiF=phiF, fa=fa, kca=p["kca"], adhesion=p["adhesion"],
                         k2Interpolation=interpolation, gammaN=0.0, density=density)
    _within_mesomat(out, f"radius = {radius!r}, density = {density!r}, fa = {fa!r}, contact_time = {contact_time!r}")
    out.stable_step = 2.0 * math.sqrt(m_r / p["kp"])
    out.report = (f"kp/k1 = {p['kp'] / p['k1']:.3g} (kp = {p['kp']:.4g} N/m); the stiffest element of this pair, kp on "
                  f"the reduced mass, is stable for dt < 2 sqrt(m_r/kp) = {out.stable_step:.3g} s: a scene of these "
                  f"spheres runs at scene.time_step() = 0.05 of that or less, "
                  f"{contact_time / (0.05 * out.stable_step):.3g} "
                  "steps per contact")
    return out


class FittedMaterial(dict):
    """material_from's result: the MesoMat keywords (use it as ``MesoMat(**m)``), with ``report``
    (kp/k1 and what kp costs in time step) and ``stable_step`` (2 sqrt(m_r/kp) of the fitted pair
    [s], the normal element's leapfrog bound without damping)."""
    report = ""
    stable_step = math.inf


def _why_not(grid, restitution, contact_time):
    """What a failed fit could not meet, from its grid of misfits (e - target, t/target - 1):
    the contact times at which the target e is reached, or the range of e there is."""
    cells = [c for row in grid for c in row if c is not None]
    if not cells:
        return ": every trial material sticks at this speed (raise impact_speed, or lower fa / kc)"
    es = [restitution + c[0] for c in cells]
    if not min(es) <= restitution <= max(es):
        return (f": the materials stiff enough for contacts that short give e in [{min(es):.3g}, {max(es):.3g}] "
                "at this speed with these phiF and adhesion (relax restitution or contact_time, or change phiF, the "
                "adhesion or the speed)")
    near = sorted(cells, key=lambda c: abs(c[0]))[:max(3, len(cells) // 50)]  # the trial materials closest to e
    times = [contact_time * (1 + c[1]) for c in near]
    if not math.isfinite(min(times)):  # theory.contact_duration loses its precision on a tensile pull far below k1's
        return (f": the materials that give e = {restitution!r} have no finite contact time in the closed form (a kc "
                "or fa below about 1e-16 of k1's scale is lost to rounding there: give "
                "kc_over_kp = 0 or fa = 0 instead)")
    return (f": the materials that give e = {restitution!r} last {min(times):.3g} to {max(times):.3g} s in contact "
            f"(relax contact_time towards that range, or change phiF or the adhesion, which shift it)")


# scale_material: how each MesoMat attribute goes with the particles' size (x s) and density (x r) when
# the approach speeds are kept: times then go x s, masses x r s^3 and every force x r s^2 (m v^2/L).
_SCALED = {**{k: (1, 1) for k in ("k1", "kp", "kc", "kca", "kt", "kr", "ko")},   # N/m: x r s
           **{k: (1, 2) for k in ("fa", "gammaN", "gammaN2", "gammaT", "gammaR", "gammaO")},  # N, kg/s, kg/m: x r s^2
           "density": (1, 0), "young": (1, 0)}                                     # kg/m^3, Pa: x r
_KEPT = ("phiF", "phiD", "muR", "muO", "frictionAngle", "poisson", "adhesion", "k2Interpolation", "dominant", "label")


def scale_material(material, radius_factor, density_factor=1.0):
    """A MesoMat's parameters for particles radius_factor times larger (and density_factor times
    denser) whose collisions keep the restitution e(v) at every approach speed v: the law's
    similarity (docs/calibration.md, "Larger particles, the same e(v)"). With lengths x s and the
    speeds kept, times go x s, masses x r s^3 and every force x r s^2; so the stiffnesses (k1, kp,
    kc, kca, kt, kr, ko) go x r s, fa and the dashpots (gamma*) x r s^2, density and young x r;
    phiF, the friction coefficients, the adhesion mode and the k2 rule are kept.

    Kept: e(v) at the same speeds, in every regime and adhesion mode, and so the plastic-limit
    speed v_p, the sticking window and the speed below which the non-contact force holds a pair
    (the stickiness limit); eta, beta, kca/k1, the adhesivity alpha at a given speed; overlaps
    over the radius; the tangential response at the same speeds. Changed: overlaps and the
    adhesion range fa/kca x s; forces (fa, the pull-off force kp kc/(kp + kc) phiF a12, the peak
    force) x r s^2; contact durations and the stable time step x s; energies x r s^3; a body's
    weight x r s^3, so gravity grows against the contact forces x s (the Bond number changes).

    material: a dict of MesoMat keywords (calibrate.material, params.material_from) or a MesoMat.
    Returns a dict for MesoMat(**...); a MesoMat's id is left out (O.materials gives one).
    Raises ValueError naming an attribute it does not know or a value that leaves floating point."""
    positive("radius_factor", radius_factor)
    positive("density_factor", density_factor)
    if hasattr(material, "keys"):
        given = dict(material)
    elif callable(getattr(material, "dict", None)):  # a YADE Serializable (MesoMat)
        given = dict(material.dict())
        given.pop("id", None)
    else:
        raise TypeError(f"material = {material!r:.80} is invalid: must be a dict of MesoMat keywords or a MesoMat")
    out = {}
    for k, v in given.items():
        if k in _KEPT:
            out[k] = v
            continue
        if k not in _SCALED:
            raise ValueError(f"material[{k!r}] = {v!r}: not a MesoMat attribute scale_material knows how to scale")
        if not (is_number(v) and math.isfinite(v)):
            raise ValueError(f"material[{k!r}] = {v!r} is invalid: must be a finite number")
        a, b = _SCALED[k]
        try:
            x = v * density_factor ** a * radius_factor ** b
        except OverflowError:
            x = math.inf
        if not math.isfinite(x) or (v != 0 and abs(x) < sys.float_info.min):
            raise ValueError(f"material[{k!r}] = {v!r} times {density_factor!r}^{a} {radius_factor!r}^{b} = {x!r} is "
                             "out of floating-point range: the factors are too extreme")
        out[k] = x
    _within_mesomat(out, f"radius_factor = {radius_factor!r}, density_factor = {density_factor!r}")
    return out


def _within_mesomat(material, inputs):
    """Every nonzero number of a material this module returns lies where MesoMat takes it
    ([1e-100, 1e100]): a result MesoMat would refuse is refused here, naming the inputs."""
    for k, v in material.items():
        if (is_number(v) and v != 0 and k not in ("frictionAngle", "poisson", "phiF", "phiD")
                and not MESOMAT_RANGE[0] <= abs(v) <= MESOMAT_RANGE[1]):
            raise ValueError(f"{inputs}: they give {k} = {v!r}, outside the [1e-100, 1e100] a MesoMat takes "
                             "(0 allowed)")
