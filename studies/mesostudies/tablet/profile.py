"""Non-affinity up to the peak (issue #47, E3): where and when the pulled sample stops stretching
evenly. The pull of Fig. 17 (same speed and time step, so its force rows are the factor study's
pull's) runs to a small Dx while, every few records,

- the particles are grouped into slabs along x by their position at the start, and each slab's
  mean displacement along x is recorded: the local strain between neighbouring slabs against
  the affine one (Dx d0 / L0 everywhere);
- the particle contacts that existed at the start are counted on the tensile limit -kc delta,
  open (no overlap, or gone) or on one of the law's lines k1, kp, k2 (in compression, or in
  tension below delta0), against the same counts for an affine stretch of the same contacts
  (affine.py: each opens by eps l nx^2 along its own k2 line, then along -kc delta).

``localization(...)`` and ``affine_branches(...)`` are plain numpy; ``run`` needs YADE and writes
the bundle ``profile/`` (profile.csv, profile-slabs.csv, profile.json, profile.png)."""
import numpy as np

BRANCH_GROUPS = ("line", "tensile", "open")  # on a k1, kp or k2 line; on the tensile limit -kc delta; no overlap


def affine_branches(delta, delta0, k2, kc, length, nx2, eps):
    """The fractions of the contacts on each of BRANCH_GROUPS when every contact opens by
    eps l nx^2 (affine.curve's stretch): arrays of the contacts, strain eps."""
    d = delta - eps * length * nx2
    tensile = (d > 0) & (k2 * (d - delta0) <= -kc * d)
    n = max(1, len(d))
    return {"line": float(np.sum((d > 0) & ~tensile) / n), "tensile": float(np.sum(tensile) / n),
            "open": float(np.sum(d <= 0) / n)}


def local_strains(x0, u):
    """The strain between neighbouring slabs: (u[k+1] - u[k]) / (x0[k+1] - x0[k]) for slab centres
    x0 and mean displacements u (same units)."""
    x0, u = np.asarray(x0, float), np.asarray(u, float)
    return np.diff(u) / np.diff(x0)


def localization(strains, affine):
    """The largest local strain over the affine one (1: an even stretch), and where it lies (index
    of the gap between slabs k and k + 1)."""
    strains = np.asarray(strains, float)
    k = int(np.argmax(strains))
    return float(strains[k] / affine) if affine > 0 else None, k


def persistent_from(records, factor):
    """The Dx from which the largest local strain stays at least ``factor`` times the affine one
    in every later record (None if it does not by the last): where localization sets in for good,
    which the first crossing is not at tiny Dx, where slab noise over a tiny affine strain is large."""
    start = None
    for r in records:
        m = r.get("max_strain_over_affine")
        if m is None:
            continue
        if m < factor:
            start = None
        elif start is None:
            start = r["Dx"]
    return start


def run(outdir, quick=False, protocol=None, until=0.3, slabs=None, every_records=5, progress=True, grips=None,
        limits=None):
    """The pull to Dx = ``until`` on the unconfined start (campaign.prepare with ``protocol``),
    recorded every ``every_records`` records (each 100 steps): writes profile/ in ``outdir``.
    ``slabs``: how many slabs along x (default: one per d0 of the sample's length). ``grips``:
    pulled through glued particles of this thickness [d0] instead of the flat walls (E4; bundle
    profile-grips<D>/); the contacts inside one grip, which cannot deform, are not counted.
    ``limits``: the particles' sliding, rolling and torsion limits set to sample.LIMITS[limits] on
    the unconfined start (E7; bundle profile-<limits>/)."""
    import json
    import os

    from yade import O
    from mesocontact import outputs
    from mesocontact import scene as _scene
    from . import affine, sample
    from .campaign.common import PROTOCOL, PULL_SPEED, csv_text, prepare, root
    from .campaign.runs import new_test

    from . import uniaxial
    prepare(outdir, quick, progress, **(protocol or {}))
    variant = sample.set_limits(limits) if limits is not None else None
    members = uniaxial.grip_members(grips) if grips is not None else {}
    rigid = [set(m) for m in members.values()]
    contacts, _ = affine.contacts_of_scene(rigid)  # before the test's first step, as affine.run reads them
    test, _ = new_test(progress, grips, members or None)
    ids = sample.sphere_ids()
    lo, hi = sample.inner_box()
    n_slabs = slabs or max(2, int(round((hi[0] - lo[0]) / sample.D0)))
    start = {i: O.bodies[i].state.pos[0] for i in ids}
    slab_of = {i: min(n_slabs - 1, max(0, int((x - lo[0]) / (hi[0] - lo[0]) * n_slabs))) for i, x in start.items()}
    members = [[i for i in ids if slab_of[i] == k] for k in range(n_slabs)]
    x0 = [sum(start[i] for i in m) / len(m) for m in members]
    pairs = {(I.id1, I.id2) for I in O.interactions if I.isReal and I.id1 in start and I.id2 in start
             and not any(I.id1 in r and I.id2 in r for r in rigid)}
    tensile_index = _scene.BRANCHES.index("tensile")
    records, slab_rows = [], []

    def hook(t, row):
        # The start, then every every_records-th record counted as before #50 (the start was recorded
        # twice): the records the committed profiles hold.
        if len(t.rows) > 1 and len(t.rows) % every_records:
            return
        u = [sum(O.bodies[i].state.pos[0] - start[i] for i in m) / len(m) for m in members]
        counts = {"line": 0, "tensile": 0}
        for a, b in pairs:
            I = O.interactions[a, b] if O.interactions.has(a, b) else None
            if I is not None and I.isReal and I.geom.penetrationDepth > 0:
                counts["tensile" if I.phys.branchIndex == tensile_index else "line"] += 1
        measured = {k: v / len(pairs) for k, v in counts.items()}
        measured["open"] = 1.0 - measured["line"] - measured["tensile"]
        eps = row[1] * sample.D0 / test.L0
        strains = local_strains(x0, u)
        factor, where = localization(strains, eps) if eps > 0 else (None, None)
        records.append({"iter": row[0], "Dx": row[1], "F": row[2], "measured": measured,
                        "affine": affine_branches(*(contacts[:, k] for k in range(6)), eps),
                        "max_strain_over_affine": factor,
                        "at_d0": (0.5 * (x0[where] + x0[where + 1]) - lo[0]) / sample.D0
                        if where is not None else None})
        slab_rows.append((row[0], row[1], *(float(s / eps) if eps > 0 else 1.0 for s in strains)))

    rows = test.pull(PULL_SPEED, until=until, every=100, on_record=hook)
    peak = min(rows, key=lambda r: r[2])
    first = {f"{k:g}": next((r["Dx"] for r in records if r["max_strain_over_affine"]
                             and r["max_strain_over_affine"] >= k), None)
             for k in (1.5, 2.0, 4.0)}
    info = {"until": until, "L0": test.L0, "slabs": n_slabs, "slab_centres_d0": [(x - lo[0]) / sample.D0 for x in x0],
            "particles_per_slab": [len(m) for m in members], "contacts_at_start": len(pairs),
            "peak_Dx": peak[1], "peak_F": peak[2], "localization_first_Dx": first,
            "records": records, "protocol": dict(PROTOCOL, **(protocol or {})), "quick": quick, "speed": PULL_SPEED,
            "grips": test.grips, "limits": variant,
            "definitions": {"local strain": "difference of neighbouring slabs' mean x displacement over their centres' "
                                            "distance, over the affine strain Dx d0 / L0",
                            "measured branches": "the particle contacts of the start: on -kc delta (tensile), in "
                                                 "overlap otherwise (line: k1, kp or k2, compressive or tensile), "
                                                 "without overlap or gone (open)",
                            "affine branches": "the same contacts stretched affinely (affine.py)"}}
    name = "profile" + (f"-grips{grips:g}" if grips is not None else "") + (f"-{limits}" if limits is not None else "")
    with outputs.Bundle(os.path.join(root(outdir, quick), name)) as b:
        b.write_text("profile.csv", csv_text(rows))
        b.write_text("profile-slabs.csv",
                     csv_text(slab_rows, "iter,Dx," + ",".join(f"gap{k}" for k in range(n_slabs - 1))))
        b.write_json("profile.json", info)
        plot(info, slab_rows, b.path("profile.png"))
    if progress:
        print(f"profile: peak {peak[2]:.4g} at Dx {peak[1]:.4g}; local strain >= 2x affine from Dx {first['2']}",
              flush=True)
    return json.loads(json.dumps({k: v for k, v in info.items() if k != "records"}))


def plot(info, slab_rows, png):
    """(a) the local strain over the affine one along the sample at a few Dx up to and past the
    peak; (b) the contacts on the tensile limit -kc delta and open, measured and affine, against Dx."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
    centres = info["slab_centres_d0"]
    gaps = [0.5 * (x + y) for x, y in zip(centres, centres[1:])]
    peak = info["peak_Dx"]
    wanted = [0.25 * peak, 0.5 * peak, peak, 2 * peak, 4 * peak]
    for w in wanted:
        row = min(slab_rows[1:] or slab_rows, key=lambda r: abs(r[1] - w))
        a.plot(gaps, row[2:], marker="o", ms=3, label=f"Dx = {row[1]:.3f}" + (" (peak)" if w == peak else ""))
    a.axhline(1.0, color="0.5", lw=0.8, ls="--")
    a.set_xlabel("position along x from the left wall's face [d0]")
    a.set_ylabel("local strain / affine strain")
    a.set_title("(a) the stretch along the sample", fontsize=10)
    a.legend(fontsize=7)
    rec = info["records"]
    dx = [r["Dx"] for r in rec]
    for key, colour, name in (("tensile", "C3", "on -kc delta"), ("open", "C0", "open")):
        b.plot(dx, [r["measured"][key] for r in rec], color=colour, label=f"{name}, measured")
        b.plot(dx, [r["affine"][key] for r in rec], color=colour, ls="--", label=f"{name}, affine stretch")
    b.axvline(peak, color="0.4", lw=0.8, ls=":")
    b.set_xlabel("Dx [d0], tension > 0")
    b.set_ylabel("fraction of the start's particle contacts")
    b.set_title(f"(b) contacts on the tensile limit and open (peak at Dx = {peak:.3f})", fontsize=10)
    b.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(png, dpi=130)
    plt.close(fig)
