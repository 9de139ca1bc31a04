"""The preparation of a sintered sample, stage by stage (inside ``yade``): ``prepare``.

compact (walls driven in, no drag, until each carries 0.9 of the goal) -> [frictionless: rest at
the packing stress, then the full law] -> sinter at p_s until static -> glue -> release to p_r
(the goal lowered geometrically) -> relax -> save. A sudden release lets the stored elastic
energy throw the particles apart: released at once, a sintered sample expanded by 14 % in
length and lost half its contacts.
"""
import json
import os
import time

try:
    from yade import O
    from yade import wrapper as _w
except ImportError as _exc:  # pragma: no cover - outside yade
    raise ImportError("mesocontact.bulk.sintering needs YADE: run it inside `yade`") from _exc

from . import sample as _s
from .protocol import Protocol


def controller(protocol, goal):
    """YADE's TriaxialStressController holding all six walls at ``goal`` (compressive > 0); it
    reads the walls' centres, so ``thickness`` is the boxes' (a facet is its own face)."""
    return _w.TriaxialStressController(
        internalCompaction=False, stressMask=7, goal1=-goal, goal2=-goal, goal3=-goal,
        thickness=0.5 * protocol.d0 if protocol.walls == "boxes" else 0.0, max_vel=protocol.speeds()[1],
        stressDamping=0.25, label="triax")


def _triax():
    return [e for e in O.engines if isinstance(e, _w.TriaxialStressController)][0]


def set_goal(p):
    """The controller's stress goal (compressive > 0; YADE counts tension positive)."""
    triax = _triax()
    triax.goal1 = triax.goal2 = triax.goal3 = -p


def relax(protocol, goal, stage, progress, max_steps=400000):
    """The stress-controlled walls run until every wall's stress is within tol_stress of the goal
    and the kinetic energy below tol_ke energy_scale(); returns stats() with the goal."""
    def measure():
        s = _s.stats(protocol)
        err = max(abs(v / goal - 1.0) for v in s["wall_stress"].values())
        text = (f"max |stress/goal - 1| = {err:.3g}  E_kin/E_ref = {s['kinetic_energy_ratio']:.2e}  "
                f"solid fraction {s['solid_fraction']:.4f}  C {s['coordination']:.2f}")
        return err < protocol.tol_stress and s["kinetic_energy_ratio"] < protocol.tol_ke, text, s
    steps, s = _s.run_until_static(measure, stage, max_steps=max_steps, progress=progress)
    s["goal"], s["steps"] = goal, steps
    return s


def release(protocol, goal, steps, progress, chunk=1000):
    """Lowers the walls' stress goal geometrically from the present one to ``goal`` over
    ``steps`` steps."""
    triax = _triax()
    start = -triax.goal1
    n = max(1, steps // chunk)
    for k in range(1, n + 1):
        set_goal(start * (goal / start) ** (k / n))
        O.run(chunk, True)
        if progress and k % 10 == 0:
            s = _s.stats(protocol)
            print(f"  release ramp: {k * chunk:7d}/{n * chunk} steps  goal {-triax.goal1:.4g}  "
                  f"solid fraction {s['solid_fraction']:.4f}  C {s['coordination']:.2f}", flush=True)


def compact(protocol, goal, speed, progress, chunk=500, max_steps=200000):
    """Drives the walls in at up to ``speed``, without background drag, until every wall first
    carries 0.9 goal; returns stats() then. The particles meet faster than they stick, so the
    skeleton is formed by the pressure rather than by slow aggregation into clusters."""
    drag = [e for e in O.engines if isinstance(e, _w.MesoBackgroundDamping)][0]
    triax = _triax()
    gammas, triax.max_vel = (drag.gammaB, drag.gammaBR), speed
    drag.gammaB = drag.gammaBR = 0.0
    start = O.iter
    while True:
        O.run(chunk, True)
        s = _s.stats(protocol)
        if progress:
            print(f"  compaction: step {O.iter - start:6d}  smallest wall stress/goal "
                  f"{min(s['wall_stress'].values()) / goal:.3f}  solid fraction {s['solid_fraction']:.4f}", flush=True)
        if min(s["wall_stress"].values()) >= 0.9 * goal:
            break
        if O.iter - start > max_steps:
            raise RuntimeError(f"compaction: the wall stress did not reach {goal:g} in {max_steps} steps")
    drag.gammaB, drag.gammaBR = gammas
    triax.max_vel = protocol.speeds()[1]
    s["steps"] = O.iter - start
    return s


def switch_particles(label):
    """Gives every sphere the material ``label`` ('particles' or 'packing'; in a mixture each
    sphere the one of its own kind, 'particles-k' or 'packing-k'), each contact keeping its
    history."""
    by_label = {m.label: m for m in O.materials}
    kinds = {}
    for i in _s.sphere_ids():
        kinds.setdefault(O.bodies[i].material.label.partition("-")[2], []).append(i)
    for kind, ids in sorted(kinds.items()):
        _s.give_material(ids, by_label[label + ("-" + kind if kind else "")])


def wall_contacts(name):
    """The mechanical contacts of wall ``name``."""
    wid = _s.wall_ids()[name]
    return sum(1 for inter in O.bodies[wid].intrs() if inter.isReal and inter.geom.penetrationDepth > 0)


def _pack_frictionless(p, info, progress):
    """Packed without friction, rolling, torsion and adhesion to rest at the packing stress, then
    the full law back, each contact keeping its history."""
    packing_stress = p.packing_stress if p.packing_stress is not None else 0.1 * p.sinter_stress
    for label, _, mat in p.materials():  # each kind of particle without friction and adhesion
        O.materials.append(_w.MesoMat(**dict(mat, **_s.without_adhesion(mat), frictionAngle=0.0, muR=0.0, muO=0.0,
                                             label=label.replace("particles", "packing"))))
    switch_particles("packing")
    set_goal(packing_stress)
    info["compacted"] = compact(p, packing_stress, p.speeds()[0], progress)
    info["packed"] = relax(p, packing_stress, "packing", progress)
    switch_particles("particles")
    set_goal(p.sinter_stress)


def _packed(p, info, progress):
    if p.packing == "frictionless":
        _pack_frictionless(p, info, progress)
    else:
        info["compacted"] = compact(p, p.sinter_stress, p.speeds()[0], progress)


def _sintered(p, info, progress):
    if p.glue == "sinter":  # sintered against six adhesive walls
        _s.make_adhesive_walls([_s.wall_ids()[w] for w in _s.WALLS], p)
    info["sintered"] = relax(p, p.sinter_stress, "sintering", progress, max_steps=1000000)
    # The loading walls are glued where the sample was sintered against them: released against
    # the smooth mould first, only the few particles still touching at p_r (12 and 16 of about
    # 144 per face) held it, and a pull tore it off a wall.
    _s.make_adhesive_walls([_s.wall_ids()[w] for w in (("left", "right") if p.glue == "loading" else _s.WALLS)], p)
    info["loading_wall_contacts_sintered"] = {k: wall_contacts(k) for k in ("left", "right")}


def _released(p, info, progress):
    release(p, p.release_stress, p.release_steps, progress)
    info["released"] = relax(p, p.release_stress, "release", progress)
    info["release_steps"] = p.release_steps
    info["loading_wall_contacts_released"] = {k: wall_contacts(k) for k in ("left", "right")}


STAGES = (("packed", _packed), ("sintered", _sintered), ("released", _released))


def stage_path(path, stage):
    """Where prepare(..., keep_stages=True) keeps the state after ``stage``."""
    return f"{path[:-len('.yade.gz')]}.stage-{stage}.yade.gz"


def _resume(path, p, progress):
    """(index of the next stage, description) from the latest kept stage made with this very
    protocol, loaded into O; (0, None) when there is none."""
    for k in range(len(STAGES) - 1, -1, -1):
        kept = stage_path(path, STAGES[k][0])
        if os.path.exists(kept) and os.path.exists(kept + ".json"):
            O.load(kept)
            if _s.TAG in O.tags.keys() and O.tags[_s.TAG] == p.to_json():
                with open(kept + ".json") as f:
                    info = json.load(f)
                info.setdefault("resumed_after", []).append(STAGES[k][0])
                if progress:
                    print(f"  resuming after the kept stage '{STAGES[k][0]}' ({kept})", flush=True)
                return k + 1, info
            if progress:
                print(f"  {kept} was made with another protocol: not resumed", flush=True)
    return 0, None


def prepare(path, protocol, progress=True, describe=None, keep_stages=False):
    """Makes the released sample of ``protocol`` (bulk.protocol.Protocol): built, compacted (or
    packed without friction), sintered at p_s until static, glued (protocol.glue), released to
    p_r over release_steps and relaxed. Saves it to ``path`` (a .yade.gz, O.save) with its
    description in ``path + '.json'``, both atomically, and returns the description (solid
    fraction, coordination, rattlers, wall stresses and side lengths at each stage).
    ``describe(info)``: adds to the description before it is saved. ``keep_stages``: also saves
    the state after each stage (stage_path), and a call that finds such states made with the
    same protocol goes on from the latest: an interrupted preparation loses no finished stage."""
    if not isinstance(protocol, Protocol):
        raise TypeError(f"protocol = {protocol!r} is invalid: a mesocontact.bulk.protocol.Protocol")
    if not (isinstance(path, str) and path.endswith(".yade.gz")):
        raise ValueError(f"path = {path!r} is invalid: a file name ending in .yade.gz")
    if not isinstance(keep_stages, bool):
        raise TypeError(f"keep_stages = {keep_stages!r} is invalid: True or False")
    if describe is not None and not callable(describe):
        raise TypeError(f"describe = {describe!r} is invalid: a function of the description, or None")
    folder = os.path.dirname(os.path.abspath(path))
    if not (os.path.isdir(folder) and os.access(folder, os.W_OK)):
        raise ValueError(f"path = {path!r} is invalid: {folder} is not a writable folder")
    p = protocol
    t0 = time.time()
    first, info = _resume(path, p, progress) if keep_stages else (0, None)
    if info is None:
        info = {"built": _s.build(p)}
        info["built"].update(packing=p.packing, glue=p.glue)
        if describe is not None:
            describe(info)
        O.engines = _s.engines(p, controller(p, p.sinter_stress), reference="lab")
    for name, stage in STAGES[first:]:
        stage(p, info, progress)
        if keep_stages and name != STAGES[-1][0]:
            _s.save_atomic(stage_path(path, name), info)
    info["units"] = p.units
    info["d0"] = p.d0
    info["kp"] = p.kp
    info["wall_clock_s"] = time.time() - t0
    _s.save_atomic(path, info)
    return info
