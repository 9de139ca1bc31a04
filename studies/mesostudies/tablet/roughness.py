"""The roughness of the fracture faces of a torn tablet, from a snapshot's sphere positions (plain
Python with numpy; the legacy VTK files the pull writes, ``snapshots.vtk``):

    python3 -m mesostudies.tablet.roughness SNAPSHOT.vtk [--flat WHOLE.vtk] [--json OUT]

The two halves are the two largest clusters of spheres in contact (centre distance at most the sum
of the radii); the rest (single spheres and threads' remnants) is counted, not used. Each half's
face toward the other is a height field over a grid of d0 x d0 columns across the pulling axis x
(d0 the mean diameter of the snapshot's spheres): the left half's outermost sphere surface
max(x + R) per column, the right half's min(x - R), over the columns both halves cover, less the
outermost column on each side (the sample's free lateral surface). A face's roughness is the
spread of its heights, in d0: the root mean square about the mean and the range between the 5th
and 95th percentiles (robust to a single protruding sphere). With --flat, the same for a flat cut
at the median x of a whole sample: the roughness the spheres alone make."""
import argparse
import json
import os
import sys

import numpy as np


def read_vtk_spheres(path):
    """(positions n x 3, radii n) from a legacy ASCII VTK POLYDATA file with a 'radius' scalar."""
    with open(path) as f:
        lines = f.read().split("\n")
    n = pos = rad = None
    for i, line in enumerate(lines):
        w = line.split()
        if w[:1] == ["POINTS"]:
            n = int(w[1])
            pos = np.array([[float(v) for v in lines[i + 1 + k].split()] for k in range(n)])
        elif w[:2] == ["SCALARS", "radius"]:
            start = i + 2 if lines[i + 1].startswith("LOOKUP_TABLE") else i + 1
            rad = np.array([float(lines[start + k]) for k in range(n)])
    if pos is None or rad is None:
        raise ValueError(f"{path}: not a sphere snapshot (needs POINTS and a 'radius' scalar)")
    return pos, rad


def clusters(pos, rad):
    """Cluster label of every sphere: connected through centre distances <= the sum of the radii."""
    n = len(rad)
    parent = np.arange(n)

    def root(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for i in range(n - 1):
        d = np.linalg.norm(pos[i + 1:] - pos[i], axis=1)
        for j in np.nonzero(d <= rad[i + 1:] + rad[i])[0] + i + 1:
            a, b = root(i), root(j)
            if a != b:
                parent[b] = a
    return np.array([root(i) for i in range(n)])


def torn_halves(pos, rad, smallest=0.1):
    """The sphere indices of the two largest clusters, left (smaller mean x) first; a ValueError
    when the second holds less than ``smallest`` of the spheres (the tablet is not torn apart)."""
    lab = clusters(pos, rad)
    roots, counts = np.unique(lab, return_counts=True)
    order = np.argsort(counts)[::-1]
    if len(roots) < 2 or counts[order[1]] < smallest * len(rad):
        raise ValueError(f"the snapshot is not torn apart: its largest cluster holds {counts[order[0]]} of "
                         f"{len(rad)} spheres, the next {counts[order[1]] if len(roots) > 1 else 0}")
    halves = [np.nonzero(lab == roots[k])[0] for k in order[:2]]
    return sorted(halves, key=lambda idx: pos[idx, 0].mean())


def planar_cut(pos):
    """The sphere indices on either side of the plane x = median x: the halves of a flat cut, the
    roughness a face has from the spheres alone."""
    xm = np.median(pos[:, 0])
    return [np.nonzero(pos[:, 0] < xm)[0], np.nonzero(pos[:, 0] >= xm)[0]]


def faces(pos, rad, halves, d0=None, margin=1):
    """The two halves' face heights (x, in d0) on the shared d0 x d0 columns of (y, z), without the
    ``margin`` outermost columns on each side (the sample's free lateral surface, not the fracture):
    a dict with the left and right face arrays, d0, the halves' sizes and the spheres in neither half."""
    d0 = 2.0 * float(np.mean(rad)) if d0 is None else d0
    lo = np.maximum(pos[halves[0], 1:].min(axis=0), pos[halves[1], 1:].min(axis=0))
    hi = np.minimum(pos[halves[0], 1:].max(axis=0), pos[halves[1], 1:].max(axis=0))
    ncell = np.floor((hi - lo) / d0).astype(int) + 1  # the last column holds the centres at hi
    heights = []
    for side, idx in enumerate(halves):
        cell = np.floor((pos[idx, 1:] - lo) / d0).astype(int)
        inside = np.all((cell >= 0) & (cell < ncell), axis=1)
        surf = pos[idx, 0] + (rad[idx] if side == 0 else -rad[idx])
        h = np.full(tuple(ncell), np.nan)
        for (cy, cz), x in zip(cell[inside], surf[inside]):
            cur = h[cy, cz]
            if np.isnan(cur) or (x > cur if side == 0 else x < cur):
                h[cy, cz] = x
        heights.append(h / d0)
    both = ~np.isnan(heights[0]) & ~np.isnan(heights[1])
    edge = np.ones_like(both)
    edge[margin:ncell[0] - margin, margin:ncell[1] - margin] = False
    both &= ~edge
    if not both.any():
        raise ValueError(f"the halves share no column of d0^2 inside a margin of {margin} d0")
    return {"left": heights[0][both], "right": heights[1][both], "d0": d0, "columns": int(both.sum()),
            "halves": [len(halves[0]), len(halves[1])], "elsewhere": int(len(rad) - len(halves[0]) - len(halves[1]))}


def roughness(heights):
    """rms about the mean and the 5-95 % range of a face's heights (in the heights' unit)."""
    h = np.asarray(heights, dtype=float)
    p5, p95 = np.percentile(h, [5, 95])
    return {"rms": float(np.std(h)), "range_5_95": float(p95 - p5),
            "peak_to_valley": float(h.max() - h.min())}


def _faces_roughness(pos, rad, halves):
    f = faces(pos, rad, halves)
    return {"d0": f["d0"], "columns": f["columns"], "halves": f["halves"], "elsewhere": f["elsewhere"],
            "left": roughness(f["left"]), "right": roughness(f["right"]),
            "gap_d0": float(np.median(f["right"] - f["left"]))}


def measure(path, flat=None):
    """The roughness of both fracture faces of a torn snapshot (a JSON-ready dict; lengths in d0);
    with ``flat`` (a snapshot of the whole tablet) also that of a flat cut through it."""
    pos, rad = read_vtk_spheres(path)
    out = dict(snapshot=os.path.basename(path), **_faces_roughness(pos, rad, torn_halves(pos, rad)))
    if flat:
        pos, rad = read_vtk_spheres(flat)
        out["flat_cut"] = dict(snapshot=os.path.basename(flat), **_faces_roughness(pos, rad, planar_cut(pos)))
    out["definition"] = __doc__.split("\n\n", 2)[2].strip().replace("\n", " ")  # after the usage line
    return out


def main(argv):
    p = argparse.ArgumentParser(prog="python3 -m mesostudies.tablet.roughness")
    p.add_argument("snapshot", help="a legacy VTK sphere snapshot of the torn tablet")
    p.add_argument("--flat",
                   help="a snapshot of the whole tablet (Dx = 0): also the roughness of a flat cut through it")
    p.add_argument("--json", help="write the result here")
    a = p.parse_args(argv)
    try:
        out = measure(a.snapshot, a.flat)
    except (OSError, ValueError) as e:
        p.error(str(e))
    print(f"{out['halves']} spheres in the halves, {out['elsewhere']} elsewhere, {out['columns']} columns of d0^2; "
          f"face roughness (d0): left rms {out['left']['rms']:.2f}, 5-95 % {out['left']['range_5_95']:.2f}; "
          f"right rms {out['right']['rms']:.2f}, 5-95 % {out['right']['range_5_95']:.2f}; median gap "
          f"{out['gap_d0']:.2f}")
    if a.flat:
        c = out["flat_cut"]
        print(f"a flat cut at the median x of {c['snapshot']}: left rms {c['left']['rms']:.2f}, 5-95 % "
              f"{c['left']['range_5_95']:.2f}; right rms {c['right']['rms']:.2f}, 5-95 % "
              f"{c['right']['range_5_95']:.2f}")
    if a.json:
        with open(a.json, "w") as f:
            json.dump(out, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
