"""The agglomerates: a block pressure-sintered as the tablet is, and two spheres carved from it
(inside ``yade``), with the library's tools (``mesocontact.bulk.agglomerate``: carve_pair,
relax, describe); what is this study's is the block (ASPECT, N_QUICK, N_FULL), MARGIN and the
files.

The block is sintered as the tablet is (the library's ``bulk.prepare`` with Appendix F's protocol
and the preparation the tablet study chose, ``primaries.protocol``: packed without friction,
sintered against six adhesive walls at d0 p_s/kp = 0.02, released to p_r/p_s = 1e-3) in a box of two
cubes side by side along x. Each cube's centre is the centre of one agglomerate: the particles that
lie wholly within ``radius`` of it (default: the largest sphere that keeps MARGIN = 0.5 d0 from the
block's walls, whose flat faces order the layers next to them) are kept with their contacts and
sintering history, everything else is erased, and the largest connected cluster of each sphere is
what the agglomerate is (particles cut loose by the carving are removed and counted). The two are
relaxed apart, with the background drag in the lab frame, until their kinetic energy is below 1e-12
of the sintered state's elastic energy scale (quiet for collisions at centimetres per second), and
saved with the drag relative to each particle's contacts (as the tablet's tests have it), with their
description:

    from mesostudies.agglomerate import make
    info = make.ensure("results/agglomerate", quick=True)   # made once, then loaded
    print(info["agglomerates"][0]["n"], info["agglomerates"][0]["radius"])

Each agglomerate's radius R is that of the smallest sphere about its centre of mass that holds
all its particles (agglomerate.outer_radius: the first point another body can touch, whatever the
direction); the meso-overlap of two is delta = R1 + R2 - |x1 - x2| of their centres of mass
(agglomerate.meso_overlap).
"""
import json
import os
import time

from yade import O

from mesocontact.bulk import agglomerate
from mesocontact.bulk import sample
from mesocontact.bulk import sintering as _sintering
from . import primaries
from .primaries import D0, KP, SCALES

ASPECT = (2, 1, 1)   # two cubes along x
N_FULL = 5400        # about 600 primaries per agglomerate (the released block holds 1.4 per d0^3)
N_QUICK = 600        # about 45 per agglomerate, for the pipeline's test
MARGIN = 0.5         # d0 between a carved sphere and the block's walls: its particles' centres keep 1 d0,
#                      beyond the layer the flat wall orders (with 1 d0 the agglomerates held 419 and 431)


def path(outdir, stage, quick=False):
    return os.path.join(outdir, f"{stage}{'-quick' if quick else ''}.yade.gz")


def _block(outdir, quick, seed, progress):
    """The sintered, released block loaded into O (prepared first if ``outdir`` lacks it)."""
    p = path(outdir, "block", quick)
    n = N_QUICK if quick else N_FULL
    if os.path.exists(p) and os.path.exists(p + ".json"):
        with open(p + ".json") as f:
            info = json.load(f)
        built = info["built"]
        if (built["n"], built["seed"], built.get("aspect")) != (n, seed, list(ASPECT)):
            raise ValueError(f"{p} holds a block of {built['n']} particles, seed {built['seed']}, aspect "
                             f"{built.get('aspect')}: not the one asked for (use another output directory)")
        O.load(p)
        return info
    os.makedirs(outdir, exist_ok=True)
    if progress:
        print(f"preparing the sintered block {p} ({n} particles, sides {ASPECT})", flush=True)
    return _sintering.prepare(p, primaries.protocol(n, seed, ASPECT), progress)


def ensure(outdir, quick=False, seed=1, radius=None, progress=True, tol_ke=1e-12, max_steps=400000):
    """The carved, relaxed pair of agglomerates loaded into O (made first, from the block, if
    ``outdir`` lacks it); returns its description ('agglomerates': describe() of each, 'members':
    their ids, 'block': the block's description, 'carve_radius', 'removed_loose'). The carving,
    the relaxation and the descriptions are the library's (mesocontact.bulk.agglomerate), with
    the primaries' scales passed explicitly (primaries.SCALES: scenes saved without the
    protocol's tag load too)."""
    p = path(outdir, "agglomerates", quick)
    if os.path.exists(p) and os.path.exists(p + ".json"):
        with open(p + ".json") as f:
            info = json.load(f)
        O.load(p)
        return info
    t0 = time.time()
    block = _block(outdir, quick, seed, progress)
    O.step()  # a loaded state's contact geometry (penetrationDepth) is made by a step: carve after one, either way
    members, r_carve, loose = agglomerate.carve_pair(radius, MARGIN, protocol=SCALES)
    # Quiet enough for the slowest collision: the tablet's "static" (1e-4 of the sintering's
    # elastic energy) leaves the particles a few m/s of vibration; the lab-frame drag takes it out.
    steps, ke = agglomerate.relax(members, tol_ke, max_steps, progress, protocol=SCALES)
    info = {"block": block, "carve_radius": r_carve, "carve_radius_d0": r_carve / D0,
            "removed_loose": loose, "relax_steps": steps, "kinetic_energy_ratio": ke,
            "members": members, "agglomerates": [agglomerate.describe(m, protocol=SCALES) for m in members],
            "definitions": {"radius": "smallest sphere about the centre of mass holding every particle",
                            "delta": "R1 + R2 - |x1 - x2| of the centres of mass"},
            "units": "mm, us, mg", "d0": D0, "kp": KP, "wall_clock_s": time.time() - t0}
    sample.save_atomic(p, info)
    if progress:
        for k, a in enumerate(info["agglomerates"]):
            print(f"agglomerate {k}: {a['n']} particles, R = {a['radius_d0']:.3f} d0, solid fraction "
                  f"{a['solid_fraction_core']:.3f}, coordination {a['coordination']:.2f}, rattlers {a['rattlers']}",
                  flush=True)
    return info
