# A sintered block as two meso-particles (docs/bulk.md): two agglomerates carved from a released
# sample of bulk.prepare (a box of two cubes, aspect (2, 1, 1)), brought to rest, then
# bulk.coarse.coarse_grain: their cycles, the law fitted to them, their collisions at the given
# speeds along the given number of directions against the meso-particle's, and the report.
#   yade -j1 -n -x scripts/coarse_grain.py BLOCK.yade.gz --speeds 1e-3,1e-2 [--directions 3]
#       [--amplitudes 0.1,0.2] [--cap-speed V] [--tolerance 0.1] [--radius R] [--margin 0.5] [--out DIR]
# Speeds and lengths in the block's own units (its Protocol, saved with it); the out folder
# (default coarse-grained) receives agglomerates.yade.gz, cycles.csv, coarse-grained.json and .png.
import argparse
import math
import os
import sys

from yade import O

from mesocontact.bulk import agglomerate, coarse, sample


def _numbers(text):
    try:
        values = tuple(float(x) for x in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r}: comma-separated numbers")
    if not values or any(not (v > 0 and math.isfinite(v)) for v in values):
        raise argparse.ArgumentTypeError(f"{text!r}: positive finite numbers")
    return values


def _parser():
    p = argparse.ArgumentParser(prog="yade -n -x scripts/coarse_grain.py", description=__doc__)
    p.add_argument("block", help="a released sample of bulk.prepare, aspect (2, 1, 1)")
    p.add_argument("--speeds", type=_numbers, required=True, help="relative collision speeds (the block's units)")
    p.add_argument("--directions", type=int, default=1, help="approach directions: x, then drawn (default 1)")
    p.add_argument("--amplitudes", type=_numbers, default=coarse.AMPLITUDES, help="cycle amplitudes [d0]")
    p.add_argument("--cap-speed", type=float, default=None, help="the cycles' cap speed (default wave speed/8000)")
    p.add_argument("--tolerance", type=float, default=0.1, help="largest |e mean - e meso| that holds")
    p.add_argument("--radius", type=float, default=None, help="carving radius (default: largest with the margin)")
    p.add_argument("--margin", type=float, default=0.5, help="d0 between a carved sphere and the walls")
    p.add_argument("--out", default="coarse-grained")
    return p


def main(argv):
    parser = _parser()
    a = parser.parse_args(argv)
    if not os.path.exists(a.block):
        parser.error(f"block {a.block!r}: no such file")
    if a.directions < 1:  # refused before any work, as the library would refuse them after the carving
        parser.error(f"--directions {a.directions}: a count >= 1")
    for name in ("tolerance", "cap_speed", "radius", "margin"):
        v = getattr(a, name)
        if v is not None and not (v > 0 and math.isfinite(v)) and not (name == "margin" and v == 0):
            parser.error(f"--{name.replace('_', '-')} {v}: a positive finite number")
    O.load(a.block)
    p = sample.current()  # refuses a scene without its Protocol
    O.step()  # a loaded state's contact geometry is made by a step
    members, radius, loose = agglomerate.carve_pair(a.radius, a.margin)
    print(f"carved two agglomerates of radius {radius / p.d0:.3f} d0 ({loose} particles cut loose)", flush=True)
    agglomerate.relax(members)
    radii = [agglomerate.describe(m)["radius"] for m in members]
    os.makedirs(a.out, exist_ok=True)
    sample.save_atomic(os.path.join(a.out, "agglomerates.yade.gz"), {"members": members, "radii": radii})
    cg = coarse.coarse_grain(members, radii, a.speeds, a.directions, a.amplitudes,
                             a.cap_speed, a.tolerance, out=a.out)
    print(cg.report(), flush=True)
    print(f"written: {a.out}/coarse-grained.json, coarse-grained.png, cycles.csv", flush=True)


main(sys.argv[1:])
