"""The study's pictures (plain Python, matplotlib)."""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from mesocontact import outputs  # noqa: E402


def cycles(runs, law, path, d0, force_scale, touch):
    """F(delta) of each cycle run (name -> rows (iter, delta, F)) and the fitted law along the
    first run (law: forces at its rows), in d0 beyond that run's first touch and F/(kp d0)."""
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for k, (name, rows) in enumerate(runs.items()):
        ax.plot([(r[1] - touch) / d0 for r in rows], [r[2] / force_scale for r in rows], lw=0.7 if k else 1.0,
                label=f"agglomerates, {name}", alpha=0.8)
    if law is not None:
        rows = next(iter(runs.values()))
        ax.plot([(r[1] - touch) / d0 for r in rows], [f / force_scale for f in law], "k--", lw=0.9, label="fitted meso-particle law")
    ax.axhline(0, color="0.6", lw=0.5)
    ax.set_xlabel("meso-overlap beyond the first touch, (delta - delta_touch)/d0")
    ax.set_ylabel("F/(kp d0)")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    outputs.savefig_atomic(fig, path, dpi=120, bbox_inches="tight")
    plt.close(fig)


def restitution(speeds, e_agg, e_meso, e_theory, broken, path):
    """e(v): agglomerates (open where mass broke off), meso-particle pair, closed form."""
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    ax.plot(speeds, e_theory, "k-", lw=1, label="closed form, fitted law")
    ax.plot(speeds, e_meso, "s", mfc="none", label="two meso-particles (YADE)")
    whole = [k for k, b in enumerate(broken) if b < 0.01]
    frag = [k for k, b in enumerate(broken) if b >= 0.01]
    ax.plot([speeds[k] for k in whole], [e_agg[k] for k in whole], "o", color="C3", label="agglomerates")
    if frag:
        ax.plot([speeds[k] for k in frag], [e_agg[k] for k in frag], "o", mfc="none", color="C3",
                label="agglomerates, >= 1 % of the mass broken off")
    ax.set_xscale("log")
    ax.set_xlabel("relative speed [m/s]")
    ax.set_ylabel("restitution e")
    ax.set_ylim(-0.02, 1.02)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    outputs.savefig_atomic(fig, path, dpi=120, bbox_inches="tight")
    plt.close(fig)
