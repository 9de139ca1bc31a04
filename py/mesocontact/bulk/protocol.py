"""How a bulk sample is made: the particles' material and the stages' stresses and speeds (pure Python).

A ``Protocol`` holds everything ``bulk.prepare`` needs, in the scene's own units (SI, or the
papers' mm, us, mg where a stress of 1 is 1e9 Pa). It is a plain value: it travels into the saved
scene (``O.tags``) as JSON, so the tests on a loaded sample know its length and force scales.

    from mesocontact.bulk import protocol
    p = protocol.Protocol.ratios(material, d0=1e-4, sinter=0.02)        # d0 p_s/kp = 0.02
    p = protocol.Protocol.pascal(material, d0=1e-4, sinter_pa=2e6)      # SI scene: 2 MPa
    p = protocol.appendix_f()       # Appendix F of Singh, Magnanimo & Luding, in mm, us, mg
"""
import dataclasses
import json
import math

from .. import checks as _checks

PACKINGS = ("full", "frictionless")   # the law while the gas is compacted: full, or without friction and adhesion
DISTRIBUTIONS = ("gaussian", "uniform", "lognormal")  # the radii's, about d0/2 with relative std rel_std
WALL_KINDS = ("boxes", "facets")    # the mould's six walls: YADE boxes, or one large facet each
_LATER_DEFAULTS = {"distribution": "gaussian", "mixture": (), "walls": "boxes"}
GLUES = ("loading", "all", "sinter")   # adhesive walls: the two x walls after sintering, all six after, all six before
TAG = "mesocontact.bulk"               # the O.tags key that carries the protocol with the scene
REQUIRED = ("density", "k1", "kp", "kc", "phiF", "gammaN")  # MesoMat keywords the stages read
_REAL = (int, float)


@dataclasses.dataclass(frozen=True)
class Protocol:
    """The preparation of a sintered sample and the scales of its tests.

    material: the particles' MesoMat keywords (a dict; 'label' is set by the library);
    d0: the mean particle diameter (the length scale of every report);
    sinter_stress, release_stress: the walls' stress while sintering (p_s) and after release (p_r);
    n, rel_std, gas_fraction, seed, aspect: n radii about d0/2 with this relative standard
    deviation, drawn from ``distribution`` (DISTRIBUTIONS: 'gaussian', cut at 2 sigma; 'uniform';
    'lognormal', cut at 2 sigma of its logarithm), placed at random at this solid fraction in a
    box with these side ratios; walls: the six walls of that box, YADE boxes ('boxes') or one
    facet each ('facets': a triangle reaching well past its face, so that no sphere meets an
    edge; contacts made in overlap, as with boxes; not under MPI);
    packing: 'full' compacts with the full law, 'frictionless' packs without friction, rolling,
    torsion and adhesion to rest at packing_stress first; glue: which walls become adhesive
    and when (GLUES); compaction_speed, sinter_speed: the walls' largest speed (default: a
    tenth and 1/400 of the elastic wave speed d0 sqrt(kp/m)); release_steps: steps over which
    the stress is lowered from p_s to p_r; tol_stress, tol_ke: 'static' means every wall
    within tol_stress of its goal and the kinetic energy below tol_ke of energy_scale;
    drag: the background drag gamma_b, gamma_br over the material's gammaN; wall_kc_over_kp,
    wall_mu: the adhesive walls' kc/kp and friction coefficient; energy_stress: the stress of
    the energy scale (default p_s); hold_speed: the x walls' largest speed while the tests'
    start is relaxed (default a fifth of sinter_speed); name, units: labels carried into the
    descriptions.
    """
    material: dict
    d0: float
    sinter_stress: float
    release_stress: float
    n: int = 1728
    rel_std: float = 0.05
    gas_fraction: float = 0.2
    seed: int = 1
    aspect: tuple = (1, 1, 1)
    packing: str = "full"
    packing_stress: float = None
    glue: str = "loading"
    compaction_speed: float = None
    sinter_speed: float = None
    release_steps: int = 40000
    tol_stress: float = 0.01
    tol_ke: float = 1e-4
    drag: tuple = (4.0, 1.0)
    wall_kc_over_kp: float = 20.0
    wall_mu: float = 10.0
    energy_stress: float = None
    hold_speed: float = None
    name: str = "user"
    units: str = ""
    distribution: str = "gaussian"
    mixture: tuple = ()
    walls: str = "boxes"

    def __post_init__(self):
        # A value, not a view of the caller's objects: the material copied, sequences as tuples.
        if isinstance(self.material, dict):
            object.__setattr__(self, "material", dict(self.material))
        for key in ("aspect", "drag"):
            if isinstance(getattr(self, key), list):
                object.__setattr__(self, key, tuple(getattr(self, key)))
        if isinstance(self.mixture, (list, tuple)):
            object.__setattr__(self, "mixture", tuple(
                (f, dict(m)) if isinstance(m, dict) else (f, m) for f, m in
                (x if isinstance(x, (list, tuple)) and len(x) == 2 else (None, x) for x in self.mixture)))
        _validate(self)
        try:
            self.to_json()
        except (TypeError, ValueError) as e:
            raise TypeError(f"material = {self.material!r} is invalid: not plain numbers and strings ({e})") from None

    @classmethod
    def ratios(cls, material, d0, sinter=0.02, release=1e-3, **kw):
        """The stresses as the papers give them: d0 p_s/kp = sinter, p_r/p_s = release."""
        _checks.positive("sinter", sinter)
        _checks.positive("release", release)
        p_s = sinter * _kp(material) / d0 if _checks.is_number(d0) and d0 > 0 else math.nan
        return cls(material, d0, p_s, release * p_s, **kw)

    @classmethod
    def pascal(cls, material, d0, sinter_pa, release_pa=None, pa_per_unit=1.0, **kw):
        """The stresses in Pa; ``pa_per_unit``: one stress unit of the scene in Pa (1 in SI, 1e9 in
        mm, us, mg). release_pa defaults to 1e-3 sinter_pa."""
        _checks.positive("sinter_pa", sinter_pa)
        _checks.positive("pa_per_unit", pa_per_unit)
        release_pa = 1e-3 * sinter_pa if release_pa is None else release_pa
        _checks.positive("release_pa", release_pa)
        return cls(material, d0, sinter_pa / pa_per_unit, release_pa / pa_per_unit, **kw)

    @property
    def kp(self):
        return float(self.material["kp"])

    @property
    def reference_stress(self):
        """The stress of the energy scale (energy_stress, else p_s)."""
        return self.sinter_stress if self.energy_stress is None else self.energy_stress

    def mean_mass(self):
        return self.material["density"] * math.pi * self.d0 ** 3 / 6

    def wave_speed(self):
        """d0 sqrt(kp/m) of the mean particle: an elastic wave's speed along a chain of them."""
        return self.d0 * math.sqrt(self.kp / self.mean_mass())

    def speeds(self):
        """(compaction_speed, sinter_speed), the defaults filled in."""
        c = self.wave_speed()
        return (0.1 * c if self.compaction_speed is None else self.compaction_speed,
                c / 400 if self.sinter_speed is None else self.sinter_speed)

    def holding_speed(self):
        """hold_speed, the default filled in."""
        return 0.2 * self.speeds()[1] if self.hold_speed is None else self.hold_speed

    def sintering_ratio(self):
        """d0 p_s/kp, the papers' measure of the sintering stress."""
        return self.sinter_stress * self.d0 / self.kp

    def replace(self, **changes):
        return dataclasses.replace(self, **changes)

    def to_json(self):
        d = dataclasses.asdict(self)
        for key, default in _LATER_DEFAULTS.items():  # fields added later: absent at their default, so that
            if d[key] == default:                     # the scenes and descriptions made before stay the same
                del d[key]
        return json.dumps(d, sort_keys=True)

    @classmethod
    def from_json(cls, text):
        kw = json.loads(text)
        kw["aspect"], kw["drag"] = tuple(kw["aspect"]), tuple(kw["drag"])
        if "mixture" in kw:
            kw["mixture"] = tuple((f, m) for f, m in kw["mixture"])
        return cls(**kw)

    def kind_counts(self):
        """The number of spheres of each kind of materials(): the fractions of n, the largest
        remainders taking the spheres left, so that they add up to n."""
        kinds = self.materials()
        counts = [int(f * self.n) for _, f, _ in kinds]
        for k in sorted(range(len(kinds)), key=lambda k: -(kinds[k][1] * self.n - counts[k]))[:self.n - sum(counts)]:
            counts[k] += 1
        return counts

    def materials(self):
        """[(label, number fraction, MesoMat keywords)] of the particles: 'particles' (the
        ``material``, the rest of the fractions), then 'particles-1', 'particles-2', ... of the
        mixture."""
        rest = 1.0 - sum(f for f, _ in self.mixture)
        return [("particles", rest, dict(self.material))] + [
            (f"particles-{k + 1}", f, dict(m)) for k, (f, m) in enumerate(self.mixture)]


def _kp(material):
    if not isinstance(material, dict):
        raise TypeError(f"material = {material!r} is invalid: a dict of MesoMat keywords")
    kp = material.get("kp")
    if not (_checks.is_number(kp) and kp > 0):
        raise ValueError(f"material['kp'] = {kp!r} is invalid: a positive number")
    return kp


def _validate(p):
    _validate_numbers(p)
    _validate_choices(p)


def _validate_material(name, material):
    if name == "material":
        _kp(material)
    elif not (_checks.is_number(material.get("kp")) and material["kp"] > 0):
        raise ValueError(f"{name}['kp'] = {material.get('kp')!r} is invalid: a positive number")
    for key in REQUIRED:
        if key not in material:
            raise ValueError(f"{name} is invalid: it lacks {key!r} (needs {', '.join(REQUIRED)})")
    # The stages come to rest through the law's dashpot and the background drag (drag x gammaN):
    # without gammaN they never would.
    _checks.positive(f"{name}['gammaN']", material["gammaN"])
    _checks.positive(f"{name}['density']", material["density"])
    for key in ("k1", "kc", "phiF", "fa", "kca", "kt", "kr", "ko", "gammaT", "gammaR", "gammaO"):
        if key in material:
            _checks.nonnegative(f"{name}[{key!r}]", material[key])


def _validate_mixture(p):
    """The mixture: pairs (number fraction, a material dict as ``material``), fractions in (0, 1)
    leaving the first material a share."""
    if not isinstance(p.mixture, tuple):
        raise ValueError(f"mixture = {p.mixture!r} is invalid: pairs (number fraction, material dict)")
    for k, (f, m) in enumerate(p.mixture):
        if not (_checks.is_number(f) and 0 < f < 1) or isinstance(f, bool):
            raise ValueError(f"mixture[{k}] is invalid: its number fraction {f!r} must lie in (0, 1)")
        if not isinstance(m, dict):
            raise ValueError(f"mixture[{k}] is invalid: its material {m!r} must be a dict of MesoMat keywords")
        _validate_material(f"mixture[{k}]", m)
    if sum(f for f, _ in p.mixture) >= 1:
        raise ValueError("mixture is invalid: its fractions add up to 1 or more (the first material needs a share)")
    if p.mixture and isinstance(p.n, int) and 0 in p.kind_counts():
        raise ValueError(f"mixture is invalid: with n = {p.n} a kind gets no sphere ({p.kind_counts()})")


def _validate_numbers(p):
    """_validate's first half: the materials and the numbers (stresses, speeds, tolerances, n, rel_std)."""
    _validate_material("material", p.material)
    _validate_mixture(p)
    for key in ("d0", "sinter_stress", "release_stress", "gas_fraction", "tol_stress", "tol_ke"):
        _checks.positive(key, getattr(p, key))
    for key in ("packing_stress", "compaction_speed", "sinter_speed", "energy_stress", "hold_speed"):
        if getattr(p, key) is not None:
            _checks.positive(key, getattr(p, key))
    if not p.release_stress < p.sinter_stress:
        raise ValueError(f"release_stress = {p.release_stress!r} is invalid: must be below sinter_stress "
                         f"({p.sinter_stress!r})")
    if p.packing_stress is not None and not p.packing_stress < p.sinter_stress:
        raise ValueError(f"packing_stress = {p.packing_stress!r} is invalid: must be below sinter_stress "
                         f"({p.sinter_stress!r})")
    if isinstance(p.n, bool) or not isinstance(p.n, int) or p.n < 8:
        raise ValueError(f"n = {p.n!r} is invalid: an integer, at least 8 particles")
    if not (isinstance(p.rel_std, _REAL) and 0 <= p.rel_std < 0.3):
        raise ValueError(f"rel_std = {p.rel_std!r} is invalid: must lie in [0, 0.3)")
    if not p.gas_fraction <= 0.3:
        raise ValueError(f"gas_fraction = {p.gas_fraction!r} is invalid: the random gas needs (0, 0.3]")


def _validate_choices(p):
    """_validate's second half, after _validate_numbers: the shapes (aspect, drag), choices (packing, glue)
    and the remaining integers, numbers and strings."""
    if not (isinstance(p.aspect, (tuple, list)) and len(p.aspect) == 3
            and all(isinstance(a, _REAL) and 0.1 <= a <= 10 for a in p.aspect)):
        raise ValueError(f"aspect = {p.aspect!r} is invalid: three side ratios in [0.1, 10]")
    if p.packing not in PACKINGS:
        raise ValueError(f"packing = {p.packing!r} is invalid: one of {PACKINGS}")
    if p.glue not in GLUES:
        raise ValueError(f"glue = {p.glue!r} is invalid: one of {GLUES}")
    if p.walls not in WALL_KINDS:
        raise ValueError(f"walls = {p.walls!r} is invalid: one of {WALL_KINDS}")
    if p.distribution not in DISTRIBUTIONS:
        raise ValueError(f"distribution = {p.distribution!r} is invalid: one of {DISTRIBUTIONS}")
    # The release lowers the goal every 1000 steps: fewer would be one sudden drop.
    if isinstance(p.release_steps, bool) or not isinstance(p.release_steps, int) or p.release_steps < 1000 \
            or p.release_steps % 1000:
        raise ValueError(f"release_steps = {p.release_steps!r} is invalid: a multiple of 1000 steps, at least 1000")
    if not (isinstance(p.drag, (tuple, list)) and len(p.drag) == 2 and all(_checks.is_number(g) and g >= 0
                                                                           for g in p.drag)):
        raise ValueError(f"drag = {p.drag!r} is invalid: two finite numbers >= 0 (gamma_b, gamma_br over gammaN)")
    _checks.nonnegative("wall_kc_over_kp", p.wall_kc_over_kp)
    _checks.nonnegative("wall_mu", p.wall_mu)
    if not isinstance(p.seed, int) or isinstance(p.seed, bool):
        raise TypeError(f"seed = {p.seed!r} is invalid: an integer")
    for key in ("name", "units"):
        if not isinstance(getattr(p, key), str):
            raise TypeError(f"{key} = {getattr(p, key)!r} is invalid: a string")


# Appendix F of the long paper (Table 2 of Luding 2008 with kc/kp = 0.2, mu_r = mu_o = 0.2 and
# gamma_r/gamma0 = gamma_o/gamma0 = 0.1), in mm, us, mg: d0 = 0.01, kp = 5 (5e6 N/m).
APPENDIX_F_D0 = 0.01
APPENDIX_F_KP = 5.0
_GAMMA0 = 5e-5
TABLE2 = dict(density=2.0, k1=0.5 * APPENDIX_F_KP, kp=APPENDIX_F_KP, kc=0.5 * APPENDIX_F_KP, phiF=0.05,
              gammaN=_GAMMA0, frictionAngle=math.atan(1.0), kt=0.2 * APPENDIX_F_KP, gammaT=0.2 * _GAMMA0,
              kr=0.1 * APPENDIX_F_KP, gammaR=0.05 * _GAMMA0, muR=0.1, ko=0.1 * APPENDIX_F_KP,
              gammaO=0.05 * _GAMMA0, muO=0.1)
APPENDIX_F = dict(TABLE2, kc=0.2 * APPENDIX_F_KP, gammaR=0.1 * _GAMMA0, muR=0.2, gammaO=0.1 * _GAMMA0, muO=0.2)
APPENDIX_F_SINTER = 0.02       # d0 p_s/kp
APPENDIX_F_RELEASE = 1e-3      # p_r/p_s
APPENDIX_F_SPEEDS = (2.0, 0.05)  # compaction and sintering wall speeds [mm/us]
APPENDIX_F_PACKING_RATIO = 0.1   # the frictionless packing's stress over p_s


def appendix_f(material=None, **kw):
    """Appendix F's protocol in mm, us, mg: p_s = 10 (d0 p_s/kp = 0.02 with the paper's kp = 5)
    and p_r = 1e-3 p_s, walls at 2 mm/us while compacting, 0.05 mm/us after and 0.01 mm/us while
    the tests' start is relaxed, the frictionless packing at 0.1 p_s, the energy scale at p_s;
    the material is APPENDIX_F unless ``material`` (the stresses stay the paper's, whatever its
    kp); ``kw`` overrides."""
    p_s = APPENDIX_F_SINTER * APPENDIX_F_KP / APPENDIX_F_D0
    args = dict(material=dict(APPENDIX_F if material is None else material), d0=APPENDIX_F_D0, sinter_stress=p_s,
                release_stress=APPENDIX_F_RELEASE * p_s, packing_stress=APPENDIX_F_PACKING_RATIO * p_s,
                compaction_speed=APPENDIX_F_SPEEDS[0], sinter_speed=APPENDIX_F_SPEEDS[1], energy_stress=p_s,
                hold_speed=0.01,
                name="appendixF", units="mm, us, mg (stress 1 = 1e9 Pa)")
    args.update(kw)
    return Protocol(**args)
