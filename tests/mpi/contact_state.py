"""Every real contact's complete state (MesoPhys and MesoTangentialPhys) and its comparison with a
serial reference, for the yade.mpy checks in this directory."""
from yade import O

PHYS = ("deltaMax", "delta0", "k2", "touched", "hystereticForce", "adhesiveForce", "viscousForce", "normalForce",
        "shearForce", "slidingSpring", "rollingSpring", "rollingForce", "rollingTorque", "torsionSpring",
        "torsionForce",
        "torsionTorque")


def contacts():
    """{"id1-id2": [each PHYS quantity]} of this rank's real contacts."""
    return {f"{i.id1}-{i.id2}": [list(x) if hasattr(x, "__len__") else x for x in (getattr(i.phys, k) for k in PHYS)]
            for i in O.interactions if i.isReal}


def _flat(x):
    return x if isinstance(x, list) else [x]


def compare(copies, want):
    """Missing and extra pairs, and per quantity the largest difference of any copy (a pair that
    crosses subdomains has one on each side) from the serial value over the largest serial value
    of that quantity."""
    seen = set().union(*(set(c) for c in copies))
    scale = {n: max([abs(v) for c in want.values() for v in _flat(c[k])] + [1e-300]) for k, n in enumerate(PHYS)}
    worst = {n: 0.0 for n in PHYS}
    for part in copies:
        for pair, values in part.items():
            if pair in want:
                for n, a, b in zip(PHYS, values, want[pair]):
                    worst[n] = max(worst[n], max(abs(x - y) for x, y in zip(_flat(a), _flat(b))) / scale[n])
    return {"serial": len(want), "mpi": len(seen), "copies": sum(len(c) for c in copies),
            "missing": sorted(set(want) - seen), "extra": sorted(seen - set(want)), "worst": worst}
