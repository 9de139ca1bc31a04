"""Pictures of a bulk sample without a GUI, and where it comes apart (inside ``yade``).

- ``png``: the spheres seen along y (the viewer at -y), ray-cast and shaded as spheres, coloured
  by their distance from the viewer red -> green -> blue (as the long paper's Figs. 17 and 19);
- ``visible_gap``: the largest crack seen from the front face, the paper's "first visible gap";
- ``vtk``: the spheres (radius, depth, velocity) as legacy VTK polydata for ParaView;
- ``see_through_holes``: the area of the holes one sees through the sample along y (empty pixels
  of the projection not connected to its outside), the "visible gap";
- ``walls_connected``: whether the mechanical contacts still link the two loading walls.

Lengths in units of d0: the ``d0`` argument, else the scene's bulk protocol's (sample.current()).
"""
import numpy as np

try:
    from yade import O
    from yade import export as _export
    from yade import wrapper as _w
except ImportError as _exc:  # pragma: no cover - outside yade
    raise ImportError("mesocontact.bulk.pictures needs YADE: run it inside `yade`") from _exc

from . import sample


def _d0(d0):
    return sample.current().d0 if d0 is None else d0


def _spheres():
    ids = sample.sphere_ids()
    pos = np.array([list(O.bodies[i].state.pos) for i in ids])
    rad = np.array([O.bodies[i].shape.radius for i in ids])
    return ids, pos, rad


def depth_colours(depth):
    """red (near) -> green -> blue (far) for depth normalised to [0, 1]."""
    d = np.clip(depth, 0.0, 1.0)
    r = np.clip(1.0 - 2.0 * d, 0.0, 1.0)
    g = 1.0 - np.abs(2.0 * d - 1.0)
    b = np.clip(2.0 * d - 1.0, 0.0, 1.0)
    return np.stack([r, g, b], axis=-1)


def wall_slab(i, name, d0):
    """(lo, hi) corners of wall ``name`` (body ``i``) as drawn: a box itself; a facet as its face
    (the walls' inner box; the triangle reaches far beyond it), a quarter d0 thick outside its plane."""
    b = O.bodies[i]
    if not isinstance(b.shape, _w.Facet):
        c, e = b.state.pos, b.shape.extents
        return [c[k] - e[k] for k in range(3)], [c[k] + e[k] for k in range(3)]
    corners = [b.state.pos + b.state.ori * v for v in b.shape.vertices]
    box_lo, box_hi = sample.inner_box()
    lo = [min(p[k] for p in corners) if box_lo[k] is None else box_lo[k] for k in range(3)]
    hi = [max(p[k] for p in corners) if box_hi[k] is None else box_hi[k] for k in range(3)]
    axis, outward = sample.WALLS.index(name) // 2, (1 if sample.WALLS.index(name) % 2 else -1)
    lo[axis] = hi[axis] = b.state.pos[axis]
    (hi if outward > 0 else lo)[axis] += outward * 0.25 * d0
    return lo, hi


def window(margin=1.0, stretch=0.0, d0=None):
    """(x0, x1, z0, z1) around the spheres and walls present, ``margin`` d0 wide, and ``stretch``
    d0 wider on each side in x (room for a pull): one window for every panel of a series."""
    _, pos, rad = _spheres()
    x0, x1 = (pos[:, 0] - rad).min(), (pos[:, 0] + rad).max()
    d0 = _d0(d0)
    for name, i in sample.wall_ids().items():
        lo, hi = wall_slab(i, name, d0)
        x0, x1 = min(x0, lo[0]), max(x1, hi[0])
    m = margin * d0
    return (x0 - m - stretch * d0, x1 + m + stretch * d0,
            (pos[:, 2] - rad).min() - m, (pos[:, 2] + rad).max() + m)


def depth_buffer(win, pixel):
    """Ray-casts the spheres seen from -y along +y on a grid of ``pixel`` over ``win``: returns
    (surface y of the first sphere hit, inf where none; its index; the surface normal), each an
    array indexed [z, x]."""
    _, pos, rad = _spheres()
    x0, x1, z0, z1 = win
    nx, nz = int((x1 - x0) / pixel) + 1, int((z1 - z0) / pixel) + 1
    xs, zs = x0 + (np.arange(nx) + 0.5) * pixel, z0 + (np.arange(nz) + 0.5) * pixel
    ybuf = np.full((nz, nx), np.inf)
    owner = np.full((nz, nx), -1)
    normal = np.zeros((nz, nx, 3))
    for k, ((x, y, z), r) in enumerate(zip(pos, rad)):
        i0, i1 = max(0, int((x - r - x0) / pixel)), min(nx, int((x + r - x0) / pixel) + 1)
        j0, j1 = max(0, int((z - r - z0) / pixel)), min(nz, int((z + r - z0) / pixel) + 1)
        if i0 >= i1 or j0 >= j1:
            continue
        dx = xs[None, i0:i1] - x
        dz = zs[j0:j1, None] - z
        h2 = r * r - dx * dx - dz * dz
        hit = h2 > 0
        h = np.sqrt(np.where(hit, h2, 0.0))
        ys = y - h
        sub = ybuf[j0:j1, i0:i1]
        better = hit & (ys < sub)
        sub[better] = ys[better]
        owner[j0:j1, i0:i1][better] = k
        nrm = normal[j0:j1, i0:i1]
        nrm[better] = np.stack([np.broadcast_to(dx, h.shape), -h, np.broadcast_to(dz, h.shape)], axis=-1)[better] / r
    return ybuf, owner, normal


def png(path, title="", win=None, pixel=None, d0=None, unit=""):
    """Renders the spheres seen from -y (the paper's view) into ``path``: each sphere shaded as a
    sphere (light from the viewer's upper left) and coloured by its centre's distance from the
    viewer, red -> green -> blue over the sample's depth (its bulk: 1st to 99th percentile); the
    walls in grey, drawn over the height of the sample's bulk (its centres' 1st to 99th percentile
    in z, plus d0; the boxes themselves reach further). ``win`` (see window()) fixes the frame, so
    that a series of panels shares one scale; a sphere not wholly inside it is left out (not cut
    by the frame's edge) and counted in the panel's corner. ``pixel`` defaults to d0/16; ``unit``
    labels the axes (e.g. "mm")."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    pixel = pixel or _d0(d0) / 16
    win = win or window(d0=d0)
    _, pos, rad = _spheres()
    x0, x1, z0, z1 = win
    inside = ((pos[:, 0] - rad >= x0) & (pos[:, 0] + rad <= x1) & (pos[:, 2] - rad >= z0) & (pos[:, 2] + rad <= z1))
    ybuf, owner, normal = depth_buffer(win, pixel)
    owner[(owner >= 0) & ~inside[np.maximum(owner, 0)]] = -1  # a sphere the frame would cut is left out
    y = pos[:, 1]
    # the colour spans the bulk's depth (1st to 99th percentile): a few spheres squeezed out of a
    # compressed sample must not stretch it until the bulk is one colour (Fig. 19's late panels)
    lo, hi = np.percentile(y, [1, 99])
    depth = np.clip((y - lo) / max(hi - lo, 1e-300), 0.0, 1.0)
    light = np.array([-0.45, -1.0, 0.55])
    light /= np.linalg.norm(light)
    shade = 0.3 + 0.7 * np.clip(normal @ light, 0.0, 1.0)  # both point towards the viewer's side
    img = np.ones(ybuf.shape + (3,))
    xs = x0 + (np.arange(img.shape[1]) + 0.5) * pixel
    zs = z0 + (np.arange(img.shape[0]) + 0.5) * pixel
    bulk_z = np.percentile(pos[:, 2], [1, 99]) + np.array([-1.0, 1.0]) * _d0(d0)
    for name, i in sample.wall_ids().items():  # the walls: grey, behind nothing, as tall as the sample's bulk
        lo, hi = wall_slab(i, name, _d0(d0))
        inx = (xs >= lo[0]) & (xs <= hi[0])
        inz = (zs >= max(lo[2], bulk_z[0])) & (zs <= min(hi[2], bulk_z[1]))
        img[np.ix_(inz, inx)] = 0.72
    seen = owner >= 0
    img[seen] = depth_colours(depth[owner[seen]]) * shade[seen][:, None]
    fig, ax = plt.subplots(figsize=(6.4, 6.4 * img.shape[0] / img.shape[1] + 0.6))
    ax.imshow(img, origin="lower", extent=(x0, x1, z0, z1), interpolation="bilinear")
    ax.set_xlabel(f"x [{unit}]" if unit else "x")
    ax.set_ylabel(f"z [{unit}]" if unit else "z")
    ax.set_title(title, fontsize=9)
    if (~inside).any():
        ax.text(0.98, 0.02, f"{int((~inside).sum())} outside the frame", transform=ax.transAxes, ha="right",
                va="bottom", fontsize=7, color="0.3")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def visible_gap(depth_behind=3.0, band=0.6, pixel=None, d0=None):
    """Area [d0^2] of the largest crack seen from the front face (-y): the largest 4-connected
    region of pixels where the first sphere seen lies ``depth_behind`` d0 or more behind the
    front face (or none is seen), within the central ``band`` of the sample's height in z and
    between the inner faces of the x walls (one d0 in from each). The front face is the median
    surface depth seen in that window. A sample seen whole gives 0; the paper's "first
    visible gap" is the first Dx where this reaches one d0^2."""
    d0 = _d0(d0)
    pixel = pixel or d0 / 10
    _, pos, rad = _spheres()
    lo, hi = sample.inner_box()
    zc, zh = pos[:, 2].mean(), 0.5 * band * ((pos[:, 2] + rad).max() - (pos[:, 2] - rad).min())
    x0 = (lo[0] if lo[0] is not None else (pos[:, 0] - rad).min()) + d0
    x1 = (hi[0] if hi[0] is not None else (pos[:, 0] + rad).max()) - d0
    if x1 <= x0:
        return 0.0
    ybuf, _, _ = depth_buffer((x0, x1, zc - zh, zc + zh), pixel)
    front = np.median(ybuf[np.isfinite(ybuf)]) if np.isfinite(ybuf).any() else 0.0
    deep = ybuf >= front + depth_behind * d0
    return _largest_region(deep) * pixel * pixel / d0 ** 2


def _largest_region(mask):
    """Pixel count of the largest 4-connected True region of a boolean array."""
    seen = np.zeros_like(mask)
    best = 0
    nz, nx = mask.shape
    for j0, i0 in zip(*np.nonzero(mask)):
        if seen[j0, i0]:
            continue
        seen[j0, i0] = True
        todo, count = [(j0, i0)], 0
        while todo:
            j, i = todo.pop()
            count += 1
            for jj, ii in ((j + 1, i), (j - 1, i), (j, i + 1), (j, i - 1)):
                if 0 <= jj < nz and 0 <= ii < nx and mask[jj, ii] and not seen[jj, ii]:
                    seen[jj, ii] = True
                    todo.append((jj, ii))
        best = max(best, count)
    return best


def vtk(base, label, comment="meso-particle sample"):
    """Writes ``base-spheres-<label>.vtk`` (label: a non-negative integer)."""
    exporter = _export.VTKExporter(base)
    y0 = min(O.bodies[i].state.pos[1] for i in sample.sphere_ids())
    exporter.exportSpheres(what=dict(depth=f"b.state.pos[1] - {y0!r}", velocity="b.state.vel"), numLabel=int(label),
                           comment=f"{comment}, iter {O.iter}")


def see_through_holes(pixel=None, d0=None):
    """Area [d0^2] of the holes in the projection of the spheres along y: empty pixels that are
    not connected (4-neighbours) to the border of the picture. 0 while the sample is opaque."""
    d0 = _d0(d0)
    pixel = pixel or d0 / 10
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
    return holes.sum() * pixel * pixel / (d0 ** 2)


def walls_connected(left, right):
    """True while a chain of mechanical contacts (overlap > 0) joins body ``left`` to ``right``."""
    nbrs = {}
    for inter in O.interactions:
        if inter.isReal and inter.geom.penetrationDepth > 0:
            nbrs.setdefault(inter.id1, []).append(inter.id2)
            nbrs.setdefault(inter.id2, []).append(inter.id1)
    seen, todo = {left}, [left]
    while todo:
        for j in nbrs.get(todo.pop(), ()):
            if j == right:
                return True
            if j not in seen:
                seen.add(j)
                todo.append(j)
    return False


DEPTH_KEY = ("colour: depth from the viewer (at -y), red front, green middle, blue back "
             "(the sample's 1st to 99th percentile)")


def montage(pngs, path, ncols=4, titles=None, key=DEPTH_KEY):
    """The panels ``pngs`` side by side in one picture (a series shares its frame and scale),
    lettered (a), (b), ... as the paper's snapshot figures, each with its title if given, and
    ``key`` (default: png()'s depth colours) as a colour bar under them (None: no key)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.image as mpimg
    import matplotlib.pyplot as plt
    imgs = [mpimg.imread(p) for p in pngs]
    nrows = (len(imgs) + ncols - 1) // ncols
    h, w = imgs[0].shape[:2]
    fig, axes = plt.subplots(nrows, ncols, figsize=(3.2 * ncols, 3.2 * nrows * h / w), squeeze=False)
    for ax in axes.flat:
        ax.axis("off")
    for k, (ax, img) in enumerate(zip(axes.flat, imgs)):
        ax.imshow(img)
        ax.set_title(f"({chr(97 + k)})" + (f" {titles[k]}" if titles else ""), fontsize=9, loc="left")
    fig.tight_layout(pad=0.2)
    if key:
        bar = fig.add_axes([0.3, -0.035, 0.4, 0.018])
        bar.imshow(depth_colours(np.linspace(0.0, 1.0, 256))[None, :, :], aspect="auto", extent=(0, 1, 0, 1))
        bar.set_yticks([])
        bar.set_xticks([0, 0.5, 1])
        bar.set_xticklabels(["front", "middle", "back"], fontsize=8)
        bar.set_title(key, fontsize=8)
    fig.savefig(path, dpi=130, bbox_inches="tight", pad_inches=0.08)  # the first row's letters inside the picture
    plt.close(fig)
