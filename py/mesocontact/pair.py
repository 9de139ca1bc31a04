"""Pair collisions in YADE: a scene builder and a driver (run inside ``yade``).

    from mesocontact import pair
    s = pair.build(radius1=1.1e-3, v_inf=0.05, material=dict(k1=100, kp=500, kc=100, phiF=0.1))
    r = pair.collide(s)
    print(r.e, r.stuck, r.final_overlap)
"""
import math
from dataclasses import dataclass, field

from . import loop as _loop
from . import params as _params
from . import scene as _scene
from . import checks as _checks
from . import theory as _theory

try:
    from yade import O
    from yade import wrapper as _w
    from yade import utils as _utils
    from yade import plot as _plot
except ImportError as _exc:  # pragma: no cover - outside yade
    raise ImportError("mesocontact.pair needs YADE: run it inside `yade`") from _exc


@dataclass
class PairScene:
    """What build() set up (SI units)."""
    ids: tuple
    radii: tuple
    masses: tuple
    m_r: float
    a12: float
    v_inf: float
    delta_a: float       # range of the non-contact force (<= 0) [m]
    contact_time: float  # pi sqrt(m_r/kp) [s]
    material: object = None
    wall_top: float = None  # sphere-wall scenes: height of the wall's surface (the sphere moves along z) [m]
    start_gap: float = 0.0  # surface gap at the start [m]
    mixed: dict = None      # the pair's parameters, from the Ip2 (Ip2_MesoMat_MesoMat_MesoPhys.mixedParameters)


@dataclass
class PairResult:
    """Outcome of collide()."""
    e: float                 # restitution (0 if stuck)
    stuck: bool
    final_overlap: float     # resting overlap (viscous) or lower turning point delta_c (elastic oscillation) [m]
    steps: int
    trace: list = field(default_factory=list)  # (time, overlap, hysteretic force, total force) if recorded


def _materials(material, material2, density):
    """The MesoMat objects of the two bodies (registered in O.materials) and the parameters of
    the pair, as the Ip2 mixes them (its own code: ``dominant`` included)."""
    m1 = _material(material, density)
    m2 = m1 if material2 is None else _material(material2, density)
    O.materials.append(m1)
    if m2 is not m1:
        O.materials.append(m2)
    return m1, m2, _w.Ip2_MesoMat_MesoMat_MesoPhys().mixedParameters(m1, m2)


def _check_step(dt, gap):
    if dt is not None and not (_checks.is_number(dt) and math.isfinite(dt) and dt > 0):
        raise ValueError(f"dt = {dt!r} is invalid: must be a finite number > 0 [s]")
    if gap is not None and not (_checks.is_number(gap) and math.isfinite(gap) and gap >= 0):
        raise ValueError(f"gap = {gap!r} is invalid: must be a finite number >= 0 [m] (the pair starts apart)")


def _stable(m1, m2, radius1, radius2, rotations, dt, steps_per_contact):
    """O.dt for a pair, refused above the leapfrog's stability bound of its stiffest element
    (Ip2.stableStep): a collision there creates energy (e = 6.9 at 0.5 steps per contact)."""
    bound = _w.Ip2_MesoMat_MesoMat_MesoPhys().stableStep(m1, m2, radius1, radius2, bool(rotations))
    step = O.dt if dt is None else dt
    if step > bound:
        given = f"dt = {dt!r}" if dt is not None else f"steps_per_contact = {steps_per_contact!r} (dt = {step:.4g} s)"
        raise ValueError(f"{given} is invalid: above the pair's stable step {bound:.4g} s "
                         f"(Ip2_MesoMat_MesoMat_MesoPhys.stableStep)")


def _material(material, density):
    if isinstance(material, _w.MesoMat):
        return material
    kw = dict(material or {})
    kw.setdefault("density", density)
    return _w.MesoMat(**kw)


def build(radius1, v_inf, material=None, radius2=None, density=2000.0, material2=None, dt=None,
          steps_per_contact=2000, track_energy=False, gap=None):
    """Two spheres on the x axis approaching head-on with relative speed v_inf, in the centre of
    mass frame, starting just outside the range of the non-contact force.

    material/material2: ``MesoMat`` or dict of its attributes (material2 defaults to material).
    The collider and the geometry functor are set to detect the pair at the gap where the
    non-contact force starts. dt defaults to params.resolved_step of kp and the pair's reduced
    mass (the half period of kp over steps_per_contact).
    The scene replaces whatever O holds (O.reset(); O.tags survive).
    """
    _checks.positive("radius1", radius1)
    _checks.positive("v_inf", v_inf)
    radius2 = radius1 if radius2 is None else radius2
    _checks.positive("radius2", radius2)
    _checks.positive("steps_per_contact", steps_per_contact)
    _check_step(dt, gap)
    _scene.reset()
    m1, m2, mixed = _materials(material, material2, density)
    delta_a = mixed["deltaA"]
    mass1, mass2 = _params.sphere_mass(radius1, m1.density), _params.sphere_mass(radius2, m2.density)
    m_r = _params.reduced_mass(mass1, mass2)
    a12 = _params.reduced_radius(radius1, radius2)
    t_c = _params.contact_time(mixed["kp"], m_r)
    O.dt = dt if dt is not None else _params.resolved_step(mixed["kp"], min(mass1, mass2), m_r=m_r,
                                                           steps_per_contact=steps_per_contact)
    _stable(m1, m2, radius1, radius2, False, dt, steps_per_contact)

    start_gap = gap if gap is not None else _pull_in_range(mixed) + 3.0 * v_inf * O.dt
    factor = 1.0 + 1.2 * max(start_gap, -delta_a) / (radius1 + radius2)  # detect the whole force range, with margin
    b1 = _utils.sphere((0, 0, 0), radius1, material=m1)
    b2 = _utils.sphere((radius1 + radius2 + start_gap, 0, 0), radius2, material=m2)
    ids = tuple(O.bodies.append([b1, b2]))
    b1.state.vel = (v_inf * mass2 / (mass1 + mass2), 0, 0)
    b2.state.vel = (-v_inf * mass1 / (mass1 + mass2), 0, 0)
    O.engines = [
        _w.ForceResetter(),
        _w.InsertionSortCollider([_w.Bo1_Sphere_Aabb(aabbEnlargeFactor=factor)], verletDist=0),
        _w.InteractionLoop(
            [_w.Ig2_Sphere_Sphere_ScGeom(interactionDetectionFactor=factor)],
            [_w.Ip2_MesoMat_MesoMat_MesoPhys()],
            [_w.Law2_ScGeom_MesoPhys_Meso()]),
        _w.NewtonIntegrator(damping=0.0, gravity=(0, 0, 0)),
    ]
    O.trackEnergy = track_energy
    return PairScene(ids, (radius1, radius2), (mass1, mass2), m_r, a12, v_inf, delta_a, t_c, m1, start_gap=start_gap,
                     mixed=mixed)


def build_wall(radius, v_inf, material=None, wall_material=None, density=2000.0, kind="box", six_d=False, dt=None,
               steps_per_contact=2000, track_energy=False, spin=(0, 0, 0), tangential_velocity=(0, 0, 0), gap=None,
               gravity=(0, 0, 0)):
    """A sphere falling with speed v_inf (along -z) onto a fixed wall whose surface is z = 0.

    kind: 'box' (Ig2_Box_Sphere_ScGeom[6D]), 'wall' (Ig2_Wall_Sphere_MesoScGeom) or 'facet'
    (Ig2_Facet_Sphere_MesoScGeom[6D]), each detecting the sphere at the gap where reversible pull-in
    starts (YADE's own wall and facet functors see it only in contact); six_d selects the ScGeom6D
    functors (rolling and torsion act). The wall's own material mixes with the sphere's; a12 = 2 a
    and the reduced mass is the sphere's mass. spin and tangential_velocity set the sphere's
    initial angular and tangential velocity.
    """
    _checks.positive("radius", radius)
    if not v_inf >= 0:
        raise ValueError(f"v_inf = {v_inf!r} is invalid: must be >= 0")
    if kind not in ("box", "wall", "facet"):
        raise ValueError(f"kind = {kind!r} is invalid: must be 'box', 'wall' or 'facet'")
    if six_d and kind == "wall":
        raise ValueError("six_d = True needs kind 'box' or 'facet': YADE has no ScGeom6D functor for Wall")
    _checks.positive("steps_per_contact", steps_per_contact)
    _check_step(dt, gap)
    _scene.reset()
    m, w, mixed = _materials(material, wall_material, density)
    delta_a = mixed["deltaA"]
    mass = _params.sphere_mass(radius, m.density)
    t_c = _params.contact_time(mixed["kp"], mass)
    O.dt = dt if dt is not None else _params.resolved_step(mixed["kp"], mass, m_r=mass,
                                                           steps_per_contact=steps_per_contact)
    _stable(m, w, radius, 0.0, six_d, dt, steps_per_contact)
    start_gap = gap if gap is not None else _pull_in_range(mixed) + 3.0 * max(v_inf, 1e-12) * O.dt
    factor = 1.0 + 1.2 * max(start_gap, -delta_a) / radius
    size = 50 * radius
    if kind == "box":
        wall = _utils.box((0, 0, -size), (size, size, size), material=w, fixed=True)
        ig2 = _w.Ig2_Box_Sphere_ScGeom6D(interactionDetectionFactor=factor) if six_d else \
            _w.Ig2_Box_Sphere_ScGeom(interactionDetectionFactor=factor)
        bo1 = _w.Bo1_Box_Aabb()
    elif kind == "wall":
        wall = _utils.wall(0, axis=2, material=w)
        ig2, bo1 = _w.Ig2_Wall_Sphere_MesoScGeom(interactionDetectionFactor=factor), _w.Bo1_Wall_Aabb()
    else:
        wall = _utils.facet([(-size, -size, 0), (size, -size, 0), (0, size, 0)], material=w, fixed=True)
        ig2 = _w.Ig2_Facet_Sphere_MesoScGeom6D(interactionDetectionFactor=factor) if six_d else \
            _w.Ig2_Facet_Sphere_MesoScGeom(interactionDetectionFactor=factor)
        bo1 = _w.Bo1_Facet_Aabb()
    ball = _utils.sphere((0, 0, radius + start_gap), radius, material=m)
    ids = tuple(O.bodies.append([wall, ball]))
    ball.state.vel = (tangential_velocity[0], tangential_velocity[1], -v_inf)
    ball.state.angVel = spin
    O.engines = [
        _w.ForceResetter(),
        _w.InsertionSortCollider([_w.Bo1_Sphere_Aabb(aabbEnlargeFactor=factor), bo1], verletDist=0),
        _w.InteractionLoop([ig2], [_w.Ip2_MesoMat_MesoMat_MesoPhys()], [_w.Law2_ScGeom_MesoPhys_Meso()]),
        _w.NewtonIntegrator(damping=0.0, gravity=gravity),
    ]
    O.trackEnergy = track_energy
    return PairScene(ids, (math.inf, radius), (math.inf, mass), mass, 2.0 * radius, v_inf, delta_a, t_c, m, 0.0,
                     start_gap=start_gap,
                     mixed=mixed)


def _pull_in_range(mixed):
    """The gap across which a force acts on approach: -deltaA for reversible adhesion; none for
    jump-in (no force before the first touch, so the pair may start close: a slow approach over
    the whole pull-off range would cost millions of force-free steps)."""
    return -mixed["deltaA"] if mixed["adhesion"] == "reversible" else 0.0


def overlap(s):
    """Current overlap delta = a1 + a2 - distance (sphere-wall: a - height above the wall) [m]."""
    if s.wall_top is not None:
        return s.radii[1] - (O.bodies[s.ids[1]].state.pos[2] - s.wall_top)
    p1, p2 = O.bodies[s.ids[0]].state.pos, O.bodies[s.ids[1]].state.pos
    return s.radii[0] + s.radii[1] - (p2 - p1).norm()


def separation_speed(s):
    """Relative normal speed, > 0 while the bodies recede [m/s]."""
    if s.wall_top is not None:
        return O.bodies[s.ids[1]].state.vel[2]
    b1, b2 = O.bodies[s.ids[0]].state, O.bodies[s.ids[1]].state
    n = (b2.pos - b1.pos).normalized()
    return (b2.vel - b1.vel).dot(n)


def collide(s, max_contact_times=40.0, record=False, settle_contact_times=6.0, max_steps=2e7):
    """Runs the collision until the pair has separated beyond the non-contact range, or for
    max_contact_times loading times (then it is stuck). The loading time is the half period
    pi sqrt(m_r/k1) of the loading branch, the slowest elastic part of a contact (k1 <= k2 <= kp):
    a plastic contact (kp >> k1) lasts many periods of kp.

    For a stuck pair, final_overlap is the lower turning point of the oscillation it settled
    into (delta_c of Eqs. 36/38), the minimum overlap over settle_contact_times further loading
    times (a pair that leaves during them rebounded after all and is reported so); with viscosity that is the
    resting overlap. record=True keeps (t, delta, f_hysteretic, f_total) at every step (and feeds them to
    yade.plot: t, overlap, force).

    Refused before it starts (ValueError): no approach (v_inf = 0), a step budget above
    max_steps, an impact so hard that it would press the bodies more than the smaller radius
    into each other (theory.pair_collision's delta_max; the model, and YADE's geometry, stop making sense).
    Checked after (RuntimeError): the pair never touched, or passed through each other.
    """
    if not s.v_inf > 0:
        raise ValueError(f"v_inf = {s.v_inf!r} is invalid for collide: the bodies must approach (> 0)")
    p = s.mixed
    d_max = _theory.pair_collision(s.v_inf, p["k1"], p["kp"], p["kc"], p["phiF"], s.a12, s.m_r, p["fa"],
                                   p["kca"] if p["fa"] > 0 else math.inf, p["adhesion"], p["k2Interpolation"]).delta_max
    radius = min(r for r in s.radii if math.isfinite(r))
    if d_max > radius:
        raise ValueError(f"v_inf = {s.v_inf!r} is too fast for this pair: the collision would reach the overlap "
                         f"{d_max:.3g} m, {d_max / radius:.3g} radii; the bodies would pass through each other")
    approach = s.start_gap / (s.v_inf * O.dt)
    t_load = _params.contact_time(p["k1"], s.m_r)
    steps = int(max_contact_times * t_load / O.dt) + int(approach) + 10
    if steps > max_steps:
        raise ValueError(f"max_steps = {max_steps:g} is too small: this collision may need {steps:.3g} steps "
                         f"({approach:.3g} to approach over the gap {s.start_gap:.3g} m at {s.v_inf:g} "
                         f"m/s, dt = {O.dt:.3g} s)")
    trace = []
    check_every = max(1, int(0.02 * s.contact_time / O.dt))
    limit = O.iter + steps
    state = dict(scene=s, trace=trace if record else None, low=math.inf, separated=False, touched=False)
    # the watcher runs inside YADE's loop (one PyRunner), so that a collision costs one O.run()
    watcher = _loop.runner(lambda: _watch(state), 1 if record else check_every, "pairWatcher")
    O.engines = O.engines + [watcher]
    try:
        _run_until(limit)
        if not state["touched"] and not _touching(s):
            raise RuntimeError(f"the pair never came into contact in {steps} steps (gap {s.start_gap:.3g} m, "
                               f"v_inf {s.v_inf:g} m/s)")
        if _passed_through(s):
            raise RuntimeError(f"the bodies passed through each other (v_inf = {s.v_inf:g} m/s, dt = {O.dt:.3g} s): no "
                               f"collision to report")
        if state["separated"]:
            return PairResult(separation_speed(s) / s.v_inf, False, 0.0, O.iter, trace)
        watcher.iterPeriod = 1
        _loop.register("pairWatcher", lambda: _track_low(state))
        _run_until(O.iter + int(settle_contact_times * t_load / O.dt))
        if state["separated"]:
            return PairResult(separation_speed(s) / s.v_inf, False, 0.0, O.iter, trace)
        return PairResult(0.0, True, state["low"], O.iter, trace)
    finally:
        O.engines = [e for e in O.engines if e is not watcher]


def _run_until(iteration):
    O.stopAtIter = iteration
    O.run()
    O.wait()


def _touching(s):
    i = O.interactions[s.ids[0], s.ids[1]] if O.interactions.has(s.ids[0], s.ids[1]) else None
    return i is not None and i.isReal and i.phys.touched or overlap(s) > 0


def _passed_through(s):
    """The sphere centres have changed sides (sphere-sphere along x; a sphere below the wall)."""
    if s.wall_top is not None:
        return O.bodies[s.ids[1]].state.pos[2] < s.wall_top
    return O.bodies[s.ids[1]].state.pos[0] < O.bodies[s.ids[0]].state.pos[0]


def _watch(state):
    s = state["scene"]
    if state["trace"] is not None:
        state["trace"].append(_sample(s))
        _plot.addData(t=O.time, overlap=state["trace"][-1][1], force=state["trace"][-1][3])  # live: plot.plot()
    if overlap(s) > 0:
        state["touched"] = True
    if overlap(s) < s.delta_a and separation_speed(s) > 0:
        state["separated"] = True
        # end the run after this step through stopAtIter, not O.pause(): a pause from inside the
        # loop lets O.wait() return while this step is still in Python, and the next O.reset()
        # (pair.build) then deadlocks on YADE's thread lock against the GIL (seen under load)
        O.stopAtIter = O.iter + 1


def _track_low(state):
    s = state["scene"]
    state["low"] = min(state["low"], overlap(s))
    if state["trace"] is not None:
        state["trace"].append(_sample(s))
    if overlap(s) < s.delta_a and separation_speed(s) > 0:  # beyond every force, moving apart: free for good
        state["separated"] = True
        O.stopAtIter = O.iter + 1


def _sample(s):
    i = O.interactions[s.ids[0], s.ids[1]] if O.interactions.has(s.ids[0], s.ids[1]) else None
    fh = ft = 0.0
    if i is not None and i.isReal:
        fh = i.phys.hystereticForce
        ft = i.phys.normalForce.dot(i.geom.normal)
    return (O.time, overlap(s), fh, ft)
