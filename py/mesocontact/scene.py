"""What every scene builder of this package shares (inside ``yade``)."""
from yade import O


def reset():
    """O.reset() keeping O.tags: yade-batch puts a job's description and parameters there, and a
    builder that wipes them makes the job fail (KeyError: 'Invalid key: description.')."""
    tags = {k: O.tags[k] for k in O.tags.keys()}
    O.reset()
    for k, v in tags.items():
        O.tags[k] = v


def adhesion_range():
    """The largest gap across which a non-contact force acts between the MesoMat materials in
    O.materials, -deltaA of the Ip2's own mixing over every pair of them [m] (0 without adhesion)."""
    from yade import wrapper as w
    mats = [m for m in O.materials if isinstance(m, w.MesoMat)]
    ip2 = w.Ip2_MesoMat_MesoMat_MesoPhys()
    return max((-ip2.mixedParameters(a, b)["deltaA"] for i, a in enumerate(mats) for b in mats[i:]), default=0.0)


def set_detection(margin=1.2):
    """Makes the collider and the geometry functors in O.engines see pairs at the adhesion range,
    so that reversible pull-in acts before contact (YADE's default factors find pairs only in
    contact). Sets Bo1_Sphere_Aabb.aabbEnlargeFactor and every Ig2 interactionDetectionFactor to
    1 + margin range/a_min (a_min: the smallest sphere; enough for sphere-sphere, whose gap is
    compared with the sum of the radii, and for sphere-box/facet, compared with one radius).
    Call it after O.engines, O.materials and the spheres are in place; returns the factor (1.0
    when no material is adhesive, leaving the engines unchanged)."""
    from yade import wrapper as w
    if not (isinstance(margin, (int, float)) and margin >= 1):
        raise ValueError(f"margin = {margin!r} is invalid: must be a number >= 1")
    gap = adhesion_range()
    radii = [b.shape.radius for b in O.bodies if b is not None and isinstance(b.shape, w.Sphere)]
    if gap <= 0:
        return 1.0
    if not radii:
        raise ValueError("set_detection: O.bodies holds no sphere (add the particles first)")
    factor = 1.0 + margin * gap / min(radii)
    found = False
    for e in O.engines:
        if isinstance(e, w.Collider) and hasattr(e, "boundDispatcher"):
            for f in e.boundDispatcher.functors:
                if isinstance(f, w.Bo1_Sphere_Aabb):
                    f.aabbEnlargeFactor, found = factor, True
        if isinstance(e, w.InteractionLoop):
            for f in e.geomDispatcher.functors:
                if hasattr(f, "interactionDetectionFactor"):
                    f.interactionDetectionFactor = factor
    if not found:
        raise ValueError("set_detection: no Bo1_Sphere_Aabb in O.engines' collider (define O.engines first)")
    return factor
