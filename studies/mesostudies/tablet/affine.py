"""The tension a sample would carry if it stretched affinely along x (issue #47, E2): every contact
of the saved state opens by eps l nx^2 under the strain eps = Dx d0 / L0 (centre distance l, normal
n; no lateral contraction), its force following the law's unloading from its own history,

    f(delta) = max(k2 (delta - delta0), -kc delta)   for delta > 0,   0 beyond,

(its k2 line down to the tensile limit, then along -kc delta to detachment; docs/model.md §3), and
the wall force is the virial sum F = sum f l nx^2 / L0. A sample whose measured pull peaks far
before this curve does localizes; one that follows it is as brittle as its contacts.

``curve`` is plain Python (numpy); ``run`` reads the unconfined start in YADE and writes the bundle
``affine/`` (affine.json, affine.csv)."""
import numpy as np


def contact_force(delta, delta0, k2, kc):
    """The law's force along its unloading from (delta0, k2), for overlaps ``delta`` (arrays)."""
    f = np.maximum(k2 * (delta - delta0), -kc * delta)
    return np.where(delta > 0, f, 0.0)


def curve(delta, delta0, k2, kc, length, nx2, L0, d0, dx):
    """F(Dx) for the amplitudes ``dx`` (in d0, > 0 in tension): returns F [force units] per Dx, the
    affine wall force; the contacts given as arrays (overlap, delta0, k2, kc, centre distance,
    squared x component of the normal)."""
    out = []
    for x in np.asarray(dx, dtype=float):
        eps = x * d0 / L0
        d = delta - eps * length * nx2
        out.append(float(np.sum(contact_force(d, delta0, k2, kc) * length * nx2) / L0))
    return np.array(out)


def summary(dx, force):
    """The curve's peak tension (most negative force), where it lies, and the force at Dx = 0.2
    against the peak."""
    k = int(np.argmin(force))
    return {"peak_force": float(force[k]), "peak_Dx": float(dx[k]),
            "F_at_0.2_over_peak": float(np.interp(0.2, dx, force) / force[k]) if force[k] < 0 else None,
            "F_at_0": float(force[0])}


def particle_contacts(skip=lambda i: False):
    """The real particle-particle contacts in overlap, the overlap taken from the positions (a
    saved state keeps no geometry), in the order of O.interactions, those ``skip(i)`` leaves out
    excepted: (interaction, branch x2 - x1, its length, overlap)."""
    from yade import O
    for i in O.interactions:
        b1, b2 = O.bodies[i.id1], O.bodies[i.id2]
        if not (i.isReal and hasattr(b1.shape, "radius") and hasattr(b2.shape, "radius")) or skip(i):
            continue
        branch = b2.state.pos - b1.state.pos
        length = branch.norm()
        delta = b1.shape.radius + b2.shape.radius - length
        if delta > 0:
            yield i, branch, length, delta


def contacts_of_scene(rigid=()):
    """The particle contacts of the scene in YADE as rows (delta, delta0, k2, kc, length, nx2,
    deltaMax, k1), and the sample's length L0 along x. The overlap is taken from the positions
    (a saved state keeps no geometry). ``rigid``: sets of particle ids moved as one body, whose
    inner contacts are left out."""
    from yade import O
    rows = []
    for i, branch, length, delta in particle_contacts(lambda i: any(i.id1 in r and i.id2 in r for r in rigid)):
        ph = i.phys
        rows.append((delta, ph.delta0, ph.k2, ph.kc, length, (branch[0] / length) ** 2, ph.deltaMax, ph.k1))
    xs = [b.state.pos[0] - b.shape.radius for b in O.bodies if b is not None and hasattr(b.shape, "radius")]
    xe = [b.state.pos[0] + b.shape.radius for b in O.bodies if b is not None and hasattr(b.shape, "radius")]
    return np.array(rows), max(xe) - min(xs)


def run(outdir, quick=False, protocol=None, progress=True):
    """The affine curve of the unconfined start (campaign.prepare with ``protocol``) up to Dx = 1:
    bundle affine/ with affine.csv (Dx, F/(kp d0)) and affine.json (the peak, the contacts'
    overlaps against the plastic limit, the preparation)."""
    import os

    from mesocontact import outputs
    from . import sample
    from .campaign.common import PROTOCOL, prepare, root
    prepare(outdir, quick, progress, **(protocol or {}))
    c, L0 = contacts_of_scene()
    dx = np.round(np.arange(0.0, 1.0 + 1e-9, 0.002), 6)
    force = curve(c[:, 0], c[:, 1], c[:, 2], c[:, 3], c[:, 4], c[:, 5], L0, sample.D0, dx) / (sample.KP * sample.D0)
    info = dict(summary(dx, force), contacts=len(c), L0_d0=L0 / sample.D0, quick=quick,
                mean_overlap_d0=float(c[:, 0].mean() / sample.D0), protocol=dict(PROTOCOL, **(protocol or {})),
                formula="F = sum max(k2 (delta - eps l nx^2 - delta0), -kc (delta - eps l nx^2)) l nx^2 / "
                        "L0, eps = Dx d0 / L0")
    with outputs.Bundle(os.path.join(root(outdir, quick), "affine")) as b:
        b.write_text("affine.csv", "Dx,F_over_kp_d0\n" + "".join(f"{x!r},{f!r}\n" for x, f in zip(dx, force)))
        b.write_json("affine.json", info)
    if progress:
        print(f"affine: peak {info['peak_force']:.4g} at Dx {info['peak_Dx']:.3g}, {len(c)} contacts", flush=True)
    return info
