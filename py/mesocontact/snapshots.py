"""Snapshots of the tablet without a GUI, and where it comes apart (inside ``yade``).

- ``png``: the spheres seen along y (the viewer at -y), drawn far to near, coloured by their
  distance from the viewer red -> green -> blue as in the paper's Figs. 17 and 19;
- ``vtk``: the spheres (radius, depth, velocity) as legacy VTK polydata for ParaView;
- ``see_through_holes``: the area of the holes one sees through the sample along y (empty pixels
  of the projection not connected to its outside), the "visible gap";
- ``walls_connected``: whether the mechanical contacts still link the two loading walls.
"""
import numpy as np

try:
    from yade import O
    from yade import export as _export
    from yade import wrapper as _w
except ImportError as _exc:  # pragma: no cover - outside yade
    raise ImportError("mesocontact.snapshots needs YADE: run it inside `yade`") from _exc

from . import tablet as _tablet


def _spheres():
    ids = _tablet.sphere_ids()
    pos = np.array([list(O.bodies[i].state.pos) for i in ids])
    rad = np.array([O.bodies[i].shape.radius for i in ids])
    return ids, pos, rad


def depth_colours(depth):
    """red (near) -> green -> blue (far) for depth normalised to [0, 1]."""
    d = np.clip(depth, 0.0, 1.0)
    r = np.clip(1.0 - 2.0 * d, 0.0, 1.0)
    g = 1.0 - np.abs(2.0 * d - 1.0)
    b = np.clip(2.0 * d - 1.0, 0.0, 1.0)
    return np.stack([r, g, b], axis=1)


def png(path, title="", xlim=None, zlim=None):
    """Renders the spheres seen along +y into ``path``."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PatchCollection
    from matplotlib.patches import Circle, Rectangle
    _, pos, rad = _spheres()
    y = pos[:, 1]
    depth = (y - y.min()) / max(y.max() - y.min(), 1e-300)
    order = np.argsort(-y)  # far first, near drawn on top
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for i in _tablet.wall_ids().values():  # the walls' faces, grey, behind the particles
        b = O.bodies[i]
        c, e = b.state.pos, b.shape.extents
        ax.add_patch(Rectangle((c[0] - e[0], c[2] - e[2]), 2 * e[0], 2 * e[2], color="0.8", zorder=0))
    circles = [Circle((pos[i, 0], pos[i, 2]), rad[i]) for i in order]
    col = PatchCollection(circles, facecolors=depth_colours(depth[order]), edgecolors="k", linewidths=0.15)
    ax.add_collection(col)
    ax.set_aspect("equal")
    ax.set_xlim(xlim or (pos[:, 0].min() - 2 * _tablet.D0, pos[:, 0].max() + 2 * _tablet.D0))
    ax.set_ylim(zlim or (pos[:, 2].min() - _tablet.D0, pos[:, 2].max() + _tablet.D0))
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("z [mm]")
    ax.set_title(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def vtk(base, label):
    """Writes ``base-spheres-<label>.vtk`` (label: a non-negative integer)."""
    exporter = _export.VTKExporter(base)
    y0 = min(O.bodies[i].state.pos[1] for i in _tablet.sphere_ids())
    exporter.exportSpheres(what=dict(depth=f"b.state.pos[1] - {y0!r}", velocity="b.state.vel"), numLabel=int(label),
                           comment=f"meso-particle tablet, iter {O.iter}")


def see_through_holes(pixel=None):
    """Area [d0^2] of the holes in the projection of the spheres along y: empty pixels that are
    not connected (4-neighbours) to the border of the picture. 0 while the sample is opaque."""
    pixel = pixel or _tablet.D0 / 10
    _, pos, rad = _spheres()
    x0, z0 = pos[:, 0].min() - rad.max() - 2 * pixel, pos[:, 2].min() - rad.max() - 2 * pixel
    nx = int((pos[:, 0].max() + rad.max() + 2 * pixel - x0) / pixel) + 1
    nz = int((pos[:, 2].max() + rad.max() + 2 * pixel - z0) / pixel) + 1
    full = np.zeros((nx, nz), dtype=bool)
    xs, zs = x0 + (np.arange(nx) + 0.5) * pixel, z0 + (np.arange(nz) + 0.5) * pixel
    for (x, _, z), r in zip(pos, rad):
        i0, i1 = int((x - r - x0) / pixel), int((x + r - x0) / pixel) + 1
        j0, j1 = int((z - r - z0) / pixel), int((z + r - z0) / pixel) + 1
        dx = xs[i0:i1, None] - x
        dz = zs[None, j0:j1] - z
        full[i0:i1, j0:j1] |= dx * dx + dz * dz <= r * r
    outside = np.zeros_like(full)
    outside[0, :] = outside[-1, :] = True
    outside[:, 0] = outside[:, -1] = True
    outside &= ~full
    while True:  # flood fill of the empty pixels from the border
        grown = outside.copy()
        grown[1:, :] |= outside[:-1, :]
        grown[:-1, :] |= outside[1:, :]
        grown[:, 1:] |= outside[:, :-1]
        grown[:, :-1] |= outside[:, 1:]
        grown &= ~full
        if (grown == outside).all():
            break
        outside = grown
    holes = ~full & ~outside
    return holes.sum() * pixel * pixel / (_tablet.D0 ** 2)


def walls_connected(left, right):
    """True while a chain of mechanical contacts (overlap > 0) joins body ``left`` to ``right``."""
    nbrs = {}
    for I in O.interactions:
        if I.isReal and I.geom.penetrationDepth > 0:
            nbrs.setdefault(I.id1, []).append(I.id2)
            nbrs.setdefault(I.id2, []).append(I.id1)
    seen, todo = {left}, [left]
    while todo:
        for j in nbrs.get(todo.pop(), ()):
            if j == right:
                return True
            if j not in seen:
                seen.add(j)
                todo.append(j)
    return False
