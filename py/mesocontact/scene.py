"""What every scene builder of this package shares (inside ``yade``)."""
import math

from yade import O

from .scene_names import BRANCHES  # noqa: F401  (MesoPhys.branch's names, in branchIndex order)
from . import checks
from .checks import is_number
from . import theory


def reset():
    """O.reset() keeping O.tags: yade-batch puts a job's description and parameters there, and a
    builder that wipes them makes the job fail (KeyError: 'Invalid key: description.')."""
    tags = {k: O.tags[k] for k in O.tags.keys()}
    O.reset()
    for k, v in tags.items():
        O.tags[k] = v


def engines(gravity=(0, 0, -9.81), sorted_loop=False):
    """The engine loop of a scene of spheres and boxes with the meso law, the collider and the
    integrator labelled as yade.mpy looks them up (``collider``, ``newton``). ``sorted_loop``:
    visit the contacts in (id1, id2) order every step (YADE's
    ``InteractionLoop.loopOnSortedInteractions``), so that a run continued from a saved file is
    the uninterrupted run to the bit with any law (YADE saves no potential interaction, and the
    collider makes them again in another order); it costs 2.6 times the step (2000 spheres on a
    floor, scripts/restart_check.py and docs/usage.md)."""
    from yade import wrapper as w
    gravity = checks.vector("gravity", gravity)  # NaN would move every body to NaN; Boost names no argument
    if not isinstance(sorted_loop, bool):
        raise TypeError(f"sorted_loop = {sorted_loop!r} is invalid: must be True or False")
    return [
        w.ForceResetter(),
        w.InsertionSortCollider([w.Bo1_Sphere_Aabb(), w.Bo1_Box_Aabb()], label="collider"),
        w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom6D(), w.Ig2_Box_Sphere_ScGeom6D()],
                          [w.Ip2_MesoMat_MesoMat_MesoPhys()], [w.Law2_ScGeom_MesoPhys_Meso()],
                          loopOnSortedInteractions=sorted_loop),
        w.NewtonIntegrator(damping=0, gravity=gravity, label="newton"),
    ]


def adhesion_range():
    """The largest gap across which a non-contact force acts between the MesoMat materials in
    O.materials, -deltaA of the Ip2's own mixing over every pair of them [m] (0 without adhesion)."""
    from yade import wrapper as w
    mats = [m for m in O.materials if isinstance(m, w.MesoMat)]
    ip2 = w.Ip2_MesoMat_MesoMat_MesoPhys()
    return max((-ip2.mixedParameters(a, b)["deltaA"] for i, a in enumerate(mats) for b in mats[i:]), default=0.0)


# YADE's sphere-surface functors without a detection distance, and this package's that have one.
_SURFACE_FUNCTORS = {"Ig2_Facet_Sphere_ScGeom": "Ig2_Facet_Sphere_MesoScGeom",
                     "Ig2_Facet_Sphere_ScGeom6D": "Ig2_Facet_Sphere_MesoScGeom6D",
                     "Ig2_Wall_Sphere_ScGeom": "Ig2_Wall_Sphere_MesoScGeom"}


def check():
    """Refuses, naming the body or material, what YADE would abort on or run on without a word:
    a Wall whose axis is not 0, 1 or 2 (YADE takes any integer, and its Bo1_Wall_Aabb aborts the
    process at the first step), a Facet with a vertex that is not finite (no collider or functor
    can find it), a Sphere whose radius is not a finite number > 0, and a material with a young
    or poisson (MesoMat, FrictMat: YADE's FrictMat laws read them) that is not finite. set_detection
    and time_step call it; a scene builder calls it before running."""
    from yade import wrapper as w
    for b in O.bodies:
        if b is None:
            continue
        if isinstance(b.shape, w.Wall) and b.shape.axis not in (0, 1, 2):
            raise ValueError(f"body #{b.id}: Wall.axis = {b.shape.axis!r} is invalid: must be 0, 1 or 2 (x, y, z); "
                             f"YADE's Bo1_Wall_Aabb aborts the process on another")
        if isinstance(b.shape, w.Facet) and not all(math.isfinite(x) for v in list(b.shape.vertices) + [b.state.pos]
                                                    for x in v):
            raise ValueError(f"body #{b.id} is a Facet with a vertex that is not finite (NaN or inf): "
                             f"no collider or functor can find it")
        if isinstance(b.shape, w.Sphere) and not (math.isfinite(b.shape.radius) and b.shape.radius > 0):
            raise ValueError(f"body #{b.id}: Sphere.radius = {b.shape.radius!r} is invalid: must be a "
                             f"finite number > 0 [m]")
    # a body's material need not be in O.materials (utils.sphere(material=MesoMat(...)))
    materials = {id(m): m for m in list(O.materials) + [b.material for b in O.bodies if b is not None and b.material]}
    for m in materials.values():
        if isinstance(m, w.ElastMat):
            for name in ("young", "poisson"):
                if not math.isfinite(getattr(m, name)):
                    raise ValueError(f"{type(m).__name__} {m.label or '#' + str(m.id)}: "
                                     f"{name} = {getattr(m, name)!r} is invalid: must be finite")


def set_detection(margin=1.2):
    """Makes the collider and the geometry functors in O.engines see pairs at the adhesion range,
    so that reversible pull-in acts before contact (YADE's default factors find pairs only in
    contact). Sets Bo1_Sphere_Aabb.aabbEnlargeFactor and every Ig2 interactionDetectionFactor to
    1 + margin range/a_min (a_min: the smallest sphere; enough for sphere-sphere, whose gap is
    compared with the sum of the radii, and for sphere-box/facet/wall, compared with one radius).
    YADE's facet and wall functors (Ig2_Facet_Sphere_ScGeom[6D], Ig2_Wall_Sphere_ScGeom) have no
    detection distance: each is replaced by this package's (Ig2_Facet_Sphere_MesoScGeom[6D],
    Ig2_Wall_Sphere_MesoScGeom), the same geometry in overlap (a facet's shrinkFactor must be 0,
    neither may be hertzian). Call it after O.engines, O.materials and the spheres are in place;
    returns the factor (1.0 when no material is adhesive: then only YADE's facet functors are
    replaced, for one contact per mesh surface with its history kept across edges). A refused
    margin or scene (check()) changes nothing."""
    from yade import wrapper as w
    if not (is_number(margin) and math.isfinite(margin) and margin >= 1):  # inf made every factor inf
        raise ValueError(f"margin = {margin!r} is invalid: must be a finite number >= 1")
    check()
    gap = adhesion_range()
    radii = [b.shape.radius for b in O.bodies if b is not None and isinstance(b.shape, w.Sphere)]
    if gap <= 0:
        _facets_as_one_surface()
        return 1.0
    if not radii:
        raise ValueError("set_detection: O.bodies holds no sphere (add the particles first)")
    factor = 1.0 + margin * gap / min(radii)
    if not math.isfinite(factor):
        raise ValueError(f"margin = {margin!r} is invalid here: 1 + margin range/a_min overflows (range {gap:.3g} m, "
                         f"a_min {min(radii):.3g} m)")
    bounds = [f for e in O.engines if isinstance(e, w.Collider) and hasattr(e, "boundDispatcher")
              for f in e.boundDispatcher.functors if isinstance(f, w.Bo1_Sphere_Aabb)]
    if not bounds:
        raise ValueError("set_detection: no Bo1_Sphere_Aabb in O.engines' collider (define O.engines first)")
    # every replacement made (and refused) before anything changes
    loops = [(e, [_with_detection(f) for f in e.geomDispatcher.functors]) for e in O.engines
             if isinstance(e, w.InteractionLoop)]
    factors = [(f, "aabbEnlargeFactor") for f in bounds] + \
        [(f, "interactionDetectionFactor")
         for _, functors in loops for f in functors if hasattr(f, "interactionDetectionFactor")]
    before = [(f, name, getattr(f, name)) for f, name in factors]
    try:  # a functor that refuses the factor leaves none set
        for f, name in factors:
            setattr(f, name, factor)
    except Exception:
        for f, name, value in before:
            setattr(f, name, value)
        raise
    for e, functors in loops:
        if any(a is not b for a, b in zip(functors, e.geomDispatcher.functors)):
            e.geomDispatcher.functors = functors
    return factor


def _facets_as_one_surface():
    """Without a pull-in to detect, YADE's facet functors are still replaced by this package's (as
    they are, factor 1), which makes one contact per mesh surface and carries its history across
    the mesh's edges; one set to what they lack (hertzian, shrinkFactor) is left as it is."""
    from yade import wrapper as w
    for e in O.engines:
        if not isinstance(e, w.InteractionLoop):
            continue
        functors = list(e.geomDispatcher.functors)
        made = [_with_detection(f) if type(f).__name__.startswith("Ig2_Facet_Sphere_ScGeom")
                and not getattr(f, "hertzian", False) and getattr(f, "shrinkFactor", 0) == 0 else f for f in functors]
        if any(a is not b for a, b in zip(made, functors)):
            e.geomDispatcher.functors = made


def _with_detection(functor):
    """A geometry functor that can see a sphere across a gap: this package's for YADE's facet and
    wall functors (refusing settings it does not have), the functor itself otherwise."""
    from yade import wrapper as w
    name = type(functor).__name__
    if name not in _SURFACE_FUNCTORS:
        return functor
    if getattr(functor, "hertzian", False) or getattr(functor, "shrinkFactor", 0) != 0:
        raise ValueError(f"set_detection: {name} with hertzian = {functor.hertzian}"
                         + (f", shrinkFactor = {functor.shrinkFactor}" if hasattr(functor, "shrinkFactor") else "")
                         + f" cannot be replaced by {_SURFACE_FUNCTORS[name]}, which has neither; "
                         "set them to their defaults (False, 0) or do without the pull-in at these surfaces")
    made = getattr(w, _SURFACE_FUNCTORS[name])(label=functor.label)
    if hasattr(functor, "noRatch"):
        made.noRatch = functor.noRatch
    return made


def time_step(safety=0.05):
    """A stable O.dt for the scene as it stands, before any contact exists: safety times the
    smallest stable step (Ip2_MesoMat_MesoMat_MesoPhys.stableStep, the bound each new contact is
    checked against) over every pair of MesoMat materials that meet, taken at the smallest sphere
    of each material, sphere-sphere and sphere-wall (boxes, walls, facets). It sees kp with gamma0
    and the sliding, rolling and torsion elements with the spheres' inertia, where YADE's
    PWaveTimeStep (young) and GlobalStiffnessTimeStepper (kn, ks) do not. [s]

    safety = 1 is the edge of stability (2/omega without damping): about 1.6 steps per contact
    duration pi/omega. Accuracy needs far less: the default 0.05 gives about 32 steps per period of
    the stiffest element (the leapfrog's energy error per contact scales as (omega dt)^2), what the
    examples and tests use; the pair figures use 2000 per contact for 1e-7 in e. For a cohesive
    packing under slow cyclic load the tablet's convergence study (campaigns/tablet/timestep.md)
    supports 0.1: its cycles at 0.096 and 0.128 of the bound stay within what a 1e-6 perturbation
    of the step changes; the last contact chain of a pull to rupture is resolved only at 0.032.
    safety > 1 gives an unstable step on purpose (to show what instability looks like): it is
    returned with a warning."""
    import warnings
    from yade import wrapper as w
    if not (is_number(safety) and 0 < safety < math.inf):
        raise ValueError(f"safety = {safety!r} is invalid: must be a finite number > 0 (at most 1 for a stable step)")
    check()
    if safety > 1:
        warnings.warn(f"time_step(safety={safety!r}): the step exceeds the stability bound of the scene's stiffest "
                      "contact element; the integration will blow up", stacklevel=2)
    smallest, walls, count = {}, {}, {}
    for b in O.bodies:
        if b is None or not isinstance(b.material, w.MesoMat):
            continue
        if isinstance(b.shape, w.Sphere) and (b.isClumpMember or b.dynamic):
            r = b.shape.radius
            count[b.material.id] = count.get(b.material.id, 0) + 1
            if b.material.id not in smallest or r < smallest[b.material.id][1]:
                smallest[b.material.id] = (b.material, r)
        else:  # walls, boxes, facets and fixed spheres: partners that do not move back (infinite mass)
            walls[b.material.id] = b.material
    if not smallest:
        raise ValueError("time_step: O.bodies holds no dynamic MesoMat sphere")
    loops = [e for e in O.engines if isinstance(e, w.InteractionLoop)]
    ig2 = [type(f).__name__ for e in loops for f in e.geomDispatcher.functors]
    rotations = not ig2 or any("6D" in n for n in ig2)
    ip2 = next((f for e in loops for f in e.physDispatcher.functors if isinstance(f, w.Ip2_MesoMat_MesoMat_MesoPhys)),
               w.Ip2_MesoMat_MesoMat_MesoPhys())
    spheres = list(smallest.values())
    steps = [ip2.stableStep(m1, m2, r1, r2, rotations) for i, (m1, r1) in enumerate(spheres) for m2, r2 in spheres[i:]
             if m2 is not m1 or count[m1.id] > 1]  # a lone sphere has no partner of its own material
    steps += [ip2.stableStep(m, wm, r, 0.0, rotations) for m, r in spheres for wm in walls.values()]
    return safety * min(steps, default=math.inf)


def contact_cohesion(requested=None):
    """What holds the scene's meso contacts together now: per contact in overlap, the largest pull
    it resists if pulled apart slowly from its present state, kc k2 delta0 / (k2 + kc) (where its
    k2 line meets the tensile limit -kc delta; 0 for a contact that has not been loaded past
    elastic, delta0 = 0) plus fa of its non-contact adhesion when it acts in contact. In a bed
    loaded by gravity alone the contacts stay shallow (delta0 far below the plastic limit), so
    this is far below the pull_off_force that params.material_from fits, which is that of a
    contact loaded to the plastic limit: the cohesion comes from fa. Returns {'contacts', 'mean',
    'median', 'max', 'fa_share' (the share of the summed cohesion that fa gives)} [N]
    ({'contacts': 0} without contacts in overlap). With ``requested`` (a pull-off force [N], e.g. the
    one given to params.material_from), a warning says when fewer than half the contacts reach it."""
    from yade import wrapper as w
    if requested is not None and not (is_number(requested) and requested > 0 and requested < math.inf):
        raise ValueError(f"requested = {requested!r} is invalid: a pull-off force > 0 [N]")
    contact, fa = [], []
    for i in O.interactions:
        if not (i.isReal and isinstance(i.phys, w.MesoPhys) and i.geom.penetrationDepth > 0):
            continue
        p = i.phys
        contact.append(theory.largest_pull(p.k2, p.kc, p.delta0))
        fa.append(-p.adhesiveForce)  # in overlap the law's non-contact part is -fa where it acts, else 0
    if not contact:
        return {"contacts": 0}
    total = sorted(c + f for c, f in zip(contact, fa))
    n = len(total)
    reach = sum(t >= requested for t in total) if requested is not None else n
    if reach < 0.5 * n:  # most contacts hold less than the user asked for: say so, and why
        import warnings
        warnings.warn(f"contact_cohesion: {reach} of {n} contacts resist the requested pull-off {requested:.3g} N "
                      f"(median {0.5 * (total[(n - 1) // 2] + total[n // 2]):.3g} N): pull_off_force is that of a "
                      "contact loaded to the plastic limit, and these contacts are shallower; their cohesion "
                      "comes mostly from fa",
                      stacklevel=2)
    return {"contacts": n, "mean": sum(total) / n, "median": 0.5 * (total[(n - 1) // 2] + total[n // 2]),
            "max": total[-1], "fa_share": sum(fa) / sum(total) if sum(total) > 0 else None}


def branch_fractions():
    """The fraction of the scene's meso contacts (real interactions with a MesoPhys) on each
    branch of the law at the last step: a dict over BRANCHES that sums to 1 ({} without contacts).
    'loading' is k1, 'limit' the limit branch kp, 'unloading' an un-/re-loading line k2,
    'tensile' the tensile limit -kc delta, 'nonContact' the non-contact adhesion without overlap."""
    from yade import wrapper as w
    counts = [0] * len(BRANCHES)
    for i in O.interactions:
        if i.isReal and isinstance(i.phys, w.MesoPhys):
            counts[i.phys.branchIndex] += 1
    total = sum(counts)
    return {b: c / total for b, c in zip(BRANCHES, counts)} if total else {}


# What export_contacts writes per contact: the field's name -> how to read it from an interaction i.
VTK_CONTACT_FIELDS = {
    "overlap": lambda i: i.geom.penetrationDepth, "deltaMax": lambda i: i.phys.deltaMax,
    "delta0": lambda i: i.phys.delta0, "k2": lambda i: i.phys.k2, "branch": lambda i: i.phys.branchIndex,
    "normalForce": lambda i: i.phys.normalForce, "hystereticForce": lambda i: i.phys.hystereticForce,
    "adhesiveForce": lambda i: i.phys.adhesiveForce, "viscousForce": lambda i: i.phys.viscousForce,
    "shearForce": lambda i: i.phys.shearForce, "slidingSpring": lambda i: i.phys.slidingSpring,
    "rollingSpring": lambda i: i.phys.rollingSpring, "torsionSpring": lambda i: i.phys.torsionSpring,
}


def _contact_ends(i):
    """The two ends of a contact's line: the two centres for two spheres; for a sphere against a
    wall, box or facet its centre and the contact point (a surface's body position can lie far
    from where it touches the sphere)."""
    b1, b2 = O.bodies[i.id1], O.bodies[i.id2]
    p1, p2 = b1.state.pos, b2.state.pos
    if O.periodic and any(i.cellDist):  # the second sphere's image next to the first
        from yade import Vector3
        p2 = p2 + O.cell.hSize * Vector3(*i.cellDist)
    s1, s2 = (hasattr(b.shape, "radius") for b in (b1, b2))
    if s1 and s2:
        return p1, p2
    return (p1, i.geom.contactPoint) if s1 else (i.geom.contactPoint, p2)


def export_contacts(base, number=None):
    """Writes the meso contacts' state as a legacy VTK file for ParaView: one line per contact (between
    the centres of two spheres; from a sphere's centre to the contact point against a wall, box or
    facet), one cell each with VTK_CONTACT_FIELDS (``branch`` is MesoPhys.branchIndex, see
    BRANCHES). The file is ``base``-intrs-NNNNNNNN.vtk with NNNNNNNN = number, by default O.iter:
    a PyRunner calling it every N steps gives ParaView a time series, and a rerun overwrites its
    files. Every real interaction must carry a MesoPhys. Returns the file's name (None without
    contacts: no file)."""
    import os
    from yade import wrapper as w
    import numbers
    if not isinstance(base, (str, os.PathLike)):  # None would write None-intrs-....vtk
        raise TypeError(f"base = {base!r} is invalid: must be a path (str), the files' prefix")
    if number is None:
        number = O.iter
    if not (isinstance(number, numbers.Integral) and not isinstance(number, bool) and 0 <= number < 10 ** 12):
        raise ValueError(f"number = {number!r} is invalid: must be an integer in [0, 10**12) (the file's number)")
    number = int(number)
    contacts = [i for i in O.interactions if i.isReal]
    if not contacts:
        return None
    foreign = [i for i in contacts if not isinstance(i.phys, w.MesoPhys)]
    if foreign:
        raise TypeError(f"export_contacts: interaction #{foreign[0].id1}+#{foreign[0].id2} carries "
                        f"{type(foreign[0].phys).__name__}, not MesoPhys")
    lines = ["# vtk DataFile Version 3.0", f"meso contacts at iteration {O.iter}", "ASCII", "DATASET POLYDATA",
             f"POINTS {2 * len(contacts)} double"]
    for i in contacts:
        for p in _contact_ends(i):
            lines.append(f"{p[0]!r} {p[1]!r} {p[2]!r}")
    lines.append(f"LINES {len(contacts)} {3 * len(contacts)}")
    lines += [f"2 {2 * k} {2 * k + 1}" for k in range(len(contacts))]
    lines.append(f"CELL_DATA {len(contacts)}")
    for name, read in VTK_CONTACT_FIELDS.items():
        values = [read(i) for i in contacts]
        if hasattr(values[0], "__len__"):
            lines.append(f"VECTORS {name} double")
            lines += [f"{v[0]!r} {v[1]!r} {v[2]!r}" for v in values]
        else:
            lines += [f"SCALARS {name} double 1", "LOOKUP_TABLE default"] + [repr(float(v)) for v in values]
    name = f"{base}-intrs-{number:08d}.vtk"
    from . import outputs
    outputs.write_atomic(name, "\n".join(lines) + "\n")
    return name if os.path.exists(name) else None
