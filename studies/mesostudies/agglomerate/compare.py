"""The meso-particle law fitted to the agglomerates' cycles, and collisions compared (plain Python;
``meso_collisions`` needs YADE).

Units: the study's (mm, us, mg) inside; the library's functions take SI, converted here.
"""
import math

from mesocontact import calibrate
from mesocontact import params as _params
from mesocontact import theory

MM, US, MG = 1e-3, 1e-6, 1e-6     # in m, s, kg
FORCE = MG * MM / US ** 2          # the study's force unit in N (1e3)
SPEED = MM / US                    # the study's speed unit in m/s (1e3)
FREE = ("k1", "kp", "kc", "phiF")


def geometry(info):
    """(a12 [m], m_r [kg], radii [m], masses [kg]) of the two agglomerates of make.ensure's description
    (a12 = 2 R1 R2/(R1 + R2), the law's, as YADE's Ip2 computes it)."""
    radii = [a["radius"] * MM for a in info["agglomerates"]]
    masses = [a["mass"] * MG for a in info["agglomerates"]]
    return _params.reduced_radius(*radii), _params.reduced_mass(*masses), radii, masses


def wall_a12(info):
    """a12 [m] of the first agglomerate against a flat wall: 2 R, the law's sphere-wall value."""
    return 2.0 * info["agglomerates"][0]["radius"] * MM


def fit(rows, info, free=FREE, a12=None):
    """The law fitted to cycle rows (iter, delta [mm], F [study units]) with a free overlap shift
    (the meso-overlap of the outer spheres is not where the surfaces touch): calibrate.fit_cycles
    in SI, a12 the pair's (default) or ``a12`` [m] (wall_a12). Returns its result."""
    a12 = geometry(info)[0] if a12 is None else a12
    delta = [r[1] * MM for r in rows]
    force = [r[2] * FORCE for r in rows]
    return calibrate.fit_cycles(delta, force, a12, free=free, shift=True)


def law_curve(params, rows, a12):
    """The fitted law's force [study units] along the rows' overlaps."""
    delta = [r[1] * MM - params.get("shift", 0.0) for r in rows]
    f = theory.normal_force_path(delta, params["k1"], params["kp"], params["kc"], params["phiF"], a12)
    return [x / FORCE for x in f]


WALLS = {"same material": 1.0, "rigid wall": 2.0}  # the factor on k1, kp, kc a wall contact gets


def wall_predictions(params, rows, info, touch_pair, touch_wall):
    """The force [study units] along the wall cycles' rows that the law fitted to the pair's cycles
    predicts, with nothing refitted. Where the law's contact starts is taken from the first touch
    (the faces that meet are not equally deep inside the outer spheres): the pair's law starts
    shift - touch_pair beyond its touch, made of two faces, so the wall's starts half that beyond
    touch_wall [mm]. a12 = 2 R, the law's sphere-wall convention (springs in series exactly would
    rather halve the pair's a12; phiF is kept). Per WALLS: a wall of the meso-particle's own material
    (k1, kp, kc as in the pair), and a rigid one (the harmonic mixing of docs/model.md §8 with an
    infinitely stiff wall doubles k1, kp and kc: the two agglomerates of a pair are springs in
    series, one against a wall is one spring)."""
    start = touch_wall * MM + 0.5 * (params.get("shift", 0.0) - touch_pair * MM)
    delta = [r[1] * MM - start for r in rows]
    out = {}
    for name, x in WALLS.items():
        f = theory.normal_force_path(delta, x * params["k1"], x * params["kp"], x * params["kc"], params["phiF"],
                                     wall_a12(info))
        out[name] = [v / FORCE for v in f]
    return out


def misfit(forces, rows):
    """(rms, largest) of forces - the rows' F over the rows' largest |F|."""
    scale = max(abs(r[2]) for r in rows)
    d = [(f - r[2]) / scale for f, r in zip(forces, rows)]
    return math.sqrt(sum(x * x for x in d) / len(d)), max(abs(x) for x in d)


def _closed_form(params, info, v, **adhesion):
    """theory.pair_collision of the fitted law's pair at relative speed v [m/s]."""
    a12, m_r = geometry(info)[:2]
    return theory.pair_collision(v, params["k1"], params["kp"], params["kc"], params["phiF"], a12, m_r, **adhesion)


def theory_overlap(params, info, speeds):
    """The closed form's largest overlap [d0 of 0.01 mm] of the fitted law's pair at each relative
    speed [mm/us], counted from the law's contact start (delta = shift, which the cycles place
    (touch - shift)/d0 below their first touch): how deep a collision presses, against the
    cycles' amplitudes."""
    return [_closed_form(params, info, v * SPEED).delta_max / (0.01 * MM) for v in speeds]


def theory_e(params, info, speeds):
    """The closed form's e at each relative speed [mm/us] (no viscosity, no adhesion beyond kc)."""
    return [_closed_form(params, info, v * SPEED).e for v in speeds]


def _threshold(lo, hi, sticks):
    """Where ``sticks`` changes between lo and hi (each on its own side): geometric bisection, 100
    halvings; returns the upper end."""
    at_lo = sticks(lo)
    for _ in range(100):
        mid = math.sqrt(lo * hi)
        lo, hi = (mid, hi) if sticks(mid) == at_lo else (lo, mid)
    return hi


def adhesion_consequence(params, info, plateau, touch, speeds, d0=0.01, below=0.2):
    """What the cycles' tension does to collisions if the law takes it as its non-contact force
    ('jumpIn': -fa throughout a contact, the tail -kca delta - fa after it): fa = -plateau (a
    tension plateau of cycle_measures [study units]), and the shortest tail the cycles allow, down
    to where they turned (``below`` d0 below the touch ``touch`` [mm], bulk.pair_cycles.BELOW_TOUCH)
    measured from the fitted law's own contact end (delta = shift), kca = fa/that. A longer tail only holds on harder.
    Returns fa [N], kca [N/m], the closed form's e at ``speeds`` [mm/us], the speed [m/s] below
    which the pair sticks (0 if it rebounds at 1e-6 m/s, inf if it sticks at 1e4 m/s), and the
    smallest fa on the same tail that sticks it at the slowest speed (fa itself if that one does
    not, 1e-12 fa if every fa tried does)."""
    fa = -plateau * FORCE
    reach = params.get("shift", 0.0) - (touch - below * d0) * MM
    if not (fa > 0 and reach > 0):
        return None

    def e(v, f=fa):  # v in m/s, fa = f on the same tail
        return _closed_form(params, info, v, fa=f, kca=f / reach, adhesion="jumpIn").e
    lo, hi = 1e-6, 1e4
    stick = 0.0 if e(lo) > 0 else math.inf if e(hi) == 0 else _threshold(lo, hi, lambda v: e(v) == 0)
    slowest = min(speeds) * SPEED
    lo_f, hi_f = fa * 1e-12, fa
    least = (_threshold(lo_f, hi_f, lambda f: e(slowest, f) == 0)
             if e(slowest, lo_f) > 0 and e(slowest, hi_f) == 0 else hi_f)
    return {"fa_N": fa, "kca_N_m": fa / reach, "tail_m": reach, "e_theory": [e(v * SPEED) for v in speeds],
            "sticks_below_m_s": stick, "fa_sticking_slowest_N": least, "slowest_m_s": slowest}


def meso_material(params, radius, mass, gammaN=0.0, gammaN2=0.0):
    """MesoMat keywords (SI) of one meso-particle: the fitted normal law, the agglomerate's mass
    (density from its outer radius), viscosity gammaN [kg/s] (0: the cycles' law) and the quadratic
    dashpot gammaN2 [kg/m] (given only when > 0), no friction or rolling (head-on collisions)."""
    density = mass / (4.0 / 3.0 * math.pi * radius ** 3)
    kw = dict(density=density, k1=params["k1"], kp=params["kp"], kc=params["kc"], phiF=params["phiF"],
              gammaN=gammaN, frictionAngle=0.0)
    if gammaN2 > 0:
        kw["gammaN2"] = gammaN2
    return kw


def meso_collisions(params, info, speeds, progress=True, gammaN=0.0, gammaN2=0.0):
    """e of two meso-particles of the fitted law (YADE, mesocontact.pair) at each relative speed
    [mm/us], with viscosity gammaN [kg/s] and the quadratic dashpot gammaN2 [kg/m]; replaces the
    scene in O."""
    from mesocontact import pair
    from yade import wrapper as _w
    a12, m_r, radii, masses = geometry(info)
    out = []
    for v in speeds:
        mats = [_w.MesoMat(**meso_material(params, r, m, gammaN, gammaN2)) for r, m in zip(radii, masses)]
        s = pair.build(radii[0], v * SPEED, material=mats[0], radius2=radii[1], material2=mats[1])
        out.append(pair.collide(s).e)
        if progress:
            print(f"  meso pair at {v * SPEED:g} m/s{f' (gammaN {gammaN:.4g} kg/s)' if gammaN else ''}: "
                  f"e = {out[-1]:.4f}", flush=True)
    return out


def fit_viscosity(params, info, speed, e_target, tol=1e-4):
    """The meso-particles' gammaN [kg/s] whose pair rebounds with e_target at ``speed`` [mm/us]
    (YADE, bisection between 0 and the critical damping 2 sqrt(m_r k1) of the loading branch): the
    one parameter the quasi-static cycles cannot give, taken from one collision."""
    m_r, k1 = geometry(info)[1], params["k1"]
    lo, hi = 0.0, 2.0 * math.sqrt(m_r * k1)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        e = meso_collisions(params, info, [speed], progress=False, gammaN=mid)[0]
        if abs(e - e_target) < tol:
            return mid, e
        lo, hi = (mid, hi) if e > e_target else (lo, mid)
    return mid, e


def cycle_measures(rows, events, d0=0.01, band=(-0.2, -0.05), near=0.005):
    """Per cycle of a run (its events): the force at each loaded turn, the most tensile force of
    each unloading, the mean force of each unloading over delta - delta_touch in ``band`` [d0]
    (the tension's plateau; the most tensile value of a ringing signal is a spike), and the mean
    force of each loading within ``near`` d0 of the first touch's delta (> 0 when the contact now
    starts before the first touch's overlap, e.g. a face drawn out or a neck still attached; a
    face pressed in reads 0 as an unchanged one) [study units]."""
    turns, pulls, plateaus, at_touch = [], [], [], []
    touch = next(e[2] for e in events if e[0] == "touch")
    its = [e[1] for e in events]
    for k, e in enumerate(events):
        if e[0].startswith("loaded to"):
            turns.append(e[3])
            end = its[k + 1] if k + 1 < len(its) else math.inf
            stroke = [r for r in rows if e[1] <= r[0] <= end]
            pulls.append(min((r[2] for r in stroke), default=None))
            flat = [r[2] for r in stroke if band[0] <= (r[1] - touch) / d0 <= band[1]]
            plateaus.append(sum(flat) / len(flat) if flat else None)
            loading = [r for r in rows if its[k - 1] <= r[0] <= e[1]]
            there = [r[2] for r in loading if abs(r[1] - touch) <= near * d0]
            at_touch.append(sum(there) / len(there) if there else None)
    return {"turn_forces": turns, "pull_offs": pulls, "tension_plateaus": plateaus, "loading_at_touch": at_touch}


def rate_check(measures, keys=("turn_forces", "tension_plateaus")):
    """The largest difference of the runs' ``keys`` (the turn forces and the tension plateaus)
    from the slowest run's, over the slowest run's largest force (measures: name ->
    cycle_measures, slowest first)."""
    names = list(measures)
    slow = measures[names[0]]
    scale = max(abs(x) for key in keys for x in slow[key] if x is not None)
    out = {}
    for n in names[1:]:
        m = measures[n]
        diffs = [abs(a - b) for key in keys for a, b in zip(m[key], slow[key]) if a is not None and b is not None]
        out[n] = max(diffs) / scale if diffs else None
    return out
