"""The branches of the law the tablet's contacts are on through a cyclic test, from the
``<run>-branches.csv`` a cyclic run writes (campaign.cyclic): plain Python, no YADE.

    python3 studies/scripts/tablet_branches.py campaigns/tablet/chosen/tension-Dx0.025-P480-branches.csv out.png --period 59272
"""  # noqa: E501 (a command line)
import csv

from mesocontact.scene_names import BRANCHES

# Colours by meaning: loading k1 and the limit kp warm, un-/re-loading k2 blue, the tensile limit
# -kc and non-contact adhesion green, contacts just made or apart grey.
COLOURS = {"loading": "#d62728", "limit": "#8c1a1a", "unloading": "#1f77b4", "tensile": "#2ca02c",
           "nonContact": "#98df8a", "new": "#bbbbbb", "apart": "#777777"}
LABELS = {"loading": "loading k1", "limit": "limit branch kp", "unloading": "un-/re-loading k2",
          "tensile": "tensile limit -kc", "nonContact": "non-contact adhesion", "new": "new", "apart": "apart"}


def read(path):
    """(iters, Dx, {branch: fractions}) of a branches CSV; ValueError naming the file and the row
    for a missing column, a non-number or fractions that do not sum to 1."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise ValueError(f"{path}: empty")
    head = [h.strip() for h in rows[0]]
    need = ["iter", "Dx", *BRANCHES]
    missing = [c for c in need if c not in head]
    if missing:
        raise ValueError(f"{path}: columns {missing} missing (the header is {head})")
    idx = {c: head.index(c) for c in need}
    iters, dx, frac = [], [], {b: [] for b in BRANCHES}
    for n, r in enumerate(rows[1:], start=2):
        try:
            vals = {c: float(r[idx[c]]) for c in need}
        except (ValueError, IndexError):
            raise ValueError(f"{path}: row {n} is not a row of numbers: {r}") from None
        total = sum(vals[b] for b in BRANCHES)
        if total and abs(total - 1) > 1e-9:
            raise ValueError(f"{path}: row {n}: the fractions sum to {total!r}, not 1")
        iters.append(vals["iter"])
        dx.append(vals["Dx"])
        for b in BRANCHES:
            frac[b].append(vals[b])
    if not iters:
        raise ValueError(f"{path}: no rows")
    return iters, dx, frac


def _contacts_hint(frac):
    """About how many contacts the fractions count: 1 / the smallest nonzero fraction."""
    smallest = min((v for vals in frac.values() for v in vals if v > 0), default=1.0)
    return int(round(1 / smallest))


def plot(path, png, title=None, cycles=None, steps_per_cycle=None):
    """The fraction of the contacts on each branch (bottom, log scale) under the strain Dx (top), against
    the cycle count when steps_per_cycle is given (and only the first ``cycles`` of them), else the
    step. Returns the fractions' mean over the plotted rows."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    iters, dx, frac = read(path)
    x = [(i - iters[0]) / steps_per_cycle for i in iters] if steps_per_cycle else [i - iters[0] for i in iters]
    keep = [k for k, v in enumerate(x) if cycles is None or v <= cycles + 1e-9]
    x = [x[k] for k in keep]
    dx = [dx[k] for k in keep]
    frac = {b: [v[k] for k in keep] for b, v in frac.items()}
    order = [b for b in COLOURS if max(frac[b]) > 0]  # the legend in COLOURS' order
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(8, 6), gridspec_kw={"height_ratios": [1, 2.2]})
    top.plot(x, dx, color="k", lw=1)
    top.set_ylabel("Dx")
    top.grid(alpha=0.3)
    # Lines on a log scale: one branch holds most contacts, and the few on the others are the news.
    floor = 0.5 / max(1, _contacts_hint(frac))
    for b in order:
        bottom.semilogy(x, [v if v > 0 else float("nan") for v in frac[b]], color=COLOURS[b], lw=1.2, label=LABELS[b])
    bottom.set_ylim(floor, 1.5)
    bottom.set_xlim(x[0], x[-1])
    bottom.grid(alpha=0.3, which="both")
    bottom.set_ylabel("fraction of the contacts")
    bottom.set_xlabel("cycle" if steps_per_cycle else "step")
    bottom.legend(loc="center left", bbox_to_anchor=(1.0, 0.5), fontsize=8, frameon=False)
    if title:
        top.set_title(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    plt.close(fig)
    return {b: sum(v) / len(v) for b, v in frac.items()}
