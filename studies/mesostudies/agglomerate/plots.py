"""The study's pictures (plain Python, matplotlib)."""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from mesocontact import outputs  # noqa: E402


def cycles(runs, law, path, d0, force_scale, touch):
    """F(delta) of each cycle run (name -> rows (iter, delta, F); the first is the fitted one, drawn
    on top) and the fitted law along it (law: forces at its rows), in d0 beyond that run's first
    touch and F/(kp d0): (a) the loops, (b) the same near F = 0, where the pull-offs are."""
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    names = list(runs)
    for ax, ylim in zip(axes, (None, 0.004)):
        for k, name in reversed(list(enumerate(names))):  # the fitted run last, on top
            rows = runs[name]
            ax.plot([(r[1] - touch) / d0 for r in rows], [r[2] / force_scale for r in rows],
                    lw=0.9 if k == 0 else 0.6, color=f"C{k}", label=f"agglomerates, {name}", alpha=1.0 if k == 0 else 0.7)
        if law is not None:
            rows = runs[names[0]]
            ax.plot([(r[1] - touch) / d0 for r in rows], [f / force_scale for f in law], "k--", lw=0.9,
                    label="fitted meso-particle law")
        ax.axhline(0, color="0.6", lw=0.5)
        ax.set_xlim(-0.3, max((r[1] - touch) / d0 for rows in runs.values() for r in rows) + 0.03)
        if ylim:
            ax.set_ylim(-ylim, ylim)
        ax.set_xlabel("(delta - delta_touch)/d0, beyond the first touch")
        ax.set_ylabel("F/(kp d0)")
        ax.grid(alpha=0.3)
    axes[0].set_title("(a) the cycles (the last pull apart goes on flat to the left)", fontsize=9)
    axes[1].set_title("(b) near F = 0: the pull-offs", fontsize=9)
    axes[0].legend(fontsize=8)
    fig.subplots_adjust(wspace=0.3)
    outputs.savefig_atomic(fig, path, dpi=120, bbox_inches="tight")
    plt.close(fig)


def restitution(speeds, e_agg, e_meso, e_theory, broken, path, e_viscous=None):
    """e(v): agglomerates (open where mass broke off), meso-particle pair, closed form, and the
    pair with its viscosity fitted to one collision."""
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    ax.plot(speeds, e_theory, "k-", lw=1, label="closed form, fitted law")
    ax.plot(speeds, e_meso, "s", mfc="none", label="two meso-particles (YADE)")
    if e_viscous is not None:
        ax.plot(speeds, e_viscous, "^", mfc="none", color="C2", label="two meso-particles, gammaN from one collision")
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
