"""The ensemble of collisions (issue #59): independently sintered blocks (seeds) x approach
directions drawn uniformly on the sphere x speeds, each collision followed to its end
(bulk.collisions.Collision.run with ``follow``: re-contacts, broken bonds, restitution with the
spin), one JSON per collision, so that an interrupted campaign goes on where it stopped and two
lanes (or yade-batch jobs) can share it.

Layout: <out>/block-s<seed>/ holds the block and its carved pair (make.ensure with that seed);
<out>/block-s<seed>/ensemble/d<k>-v<m/s>.json one collision. Direction k is the k-th of
bulk.agglomerate.directions(., DIRECTION_SEED) (k >= 1: drawn; 0 is x, the pair as carved, not
drawn and not part of the ensemble by default).
"""
import json
import os

from mesocontact import outputs
from mesocontact.bulk import agglomerate
from mesocontact.bulk.collisions import Collision
from . import make
from .primaries import SCALES

DIRECTION_SEED = 1
DIRECTIONS = tuple(range(1, 21))  # 20 drawn directions
SPEEDS = (20.0, 40.0, 10.0, 80.0, 1.0, 160.0, 0.01, 0.1, 3.0)  # m/s; the informative ones first
FOLLOW = 3.0  # presses: a parted pair is followed until its fragments' surfaces are this far apart


def block_dir(out, seed):
    return os.path.join(out, f"block-s{seed}")


def result_path(out, seed, direction, speed):
    return os.path.join(block_dir(out, seed), "ensemble", f"d{direction}-v{speed:g}.json")


def run_one(out, seed, direction, speed, follow=FOLLOW, quick=False):
    """One collision of block ``seed``'s pair along direction ``direction`` at ``speed`` m/s
    (skipped when its JSON exists); returns the outcome."""
    path = result_path(out, seed, direction, speed)
    if os.path.exists(path):
        with open(path) as f:
            return json.load(f)
    info = make.ensure(block_dir(out, seed), quick=quick, seed=seed)
    axis = agglomerate.directions(direction + 1, DIRECTION_SEED)[direction]
    c = Collision(info["members"], [g["radius"] for g in info["agglomerates"]], axis=axis, protocol=SCALES)
    print(f"block {seed}, direction {direction} {tuple(round(x, 3) for x in axis)}, {speed:g} m/s", flush=True)
    r = c.run(speed / 1e3, follow=follow)  # mm/us
    r.update(seed=seed, direction_index=direction, direction=list(axis), v_rel_m_s=speed, follow=follow)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    outputs.write_atomic(path, json.dumps(r, indent=1))
    print(f"  e = {r['e']:.4f}  e_contact {r.get('e_contact')}  e_rigid {r.get('e_rigid')}  stuck {r['stuck']}  "
          f"broken off {r['broken_mass_fraction']:.3f}  bonds broken {r['bonds_broken']}  "
          f"re-contacts {r['recontacts']}  ({r['wall_clock_s']:.0f} s)", flush=True)
    return r


def runs(out, seeds, directions=DIRECTIONS, speeds=SPEEDS, follow=FOLLOW, quick=False):
    """Every collision not yet on disk, speed by speed (the informative speeds first), each
    block's directions in turn."""
    for v in speeds:
        for s in seeds:
            for k in directions:
                run_one(out, s, k, v, follow, quick)
