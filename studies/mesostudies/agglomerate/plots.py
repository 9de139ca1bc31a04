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
                    lw=0.9 if k == 0 else 0.6, color=f"C{k}", label=f"agglomerates, {name}",
                    alpha=1.0 if k == 0 else 0.7)
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


def wall_cycles(c, path, d0, force_scale, title):
    """The agglomerate against a wall: its cycle runs (c['runs'], slowest first, fitted), the law
    fitted to them and what the pair's fit predicts (c['predicted']: name -> forces)."""
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    names = list(c["runs"])
    touch = c["touch"]
    for k, name in reversed(list(enumerate(names))):
        rows = c["runs"][name]
        ax.plot([(r[1] - touch) / d0 for r in rows], [r[2] / force_scale for r in rows], lw=0.9 if k == 0 else 0.6,
                color=f"C{k}", alpha=1.0 if k == 0 else 0.7, label=f"agglomerate on a wall, {name}")
    x = [(r[1] - touch) / d0 for r in c["runs"][names[0]]]
    ax.plot(x, [f / force_scale for f in c["fit"]], "k--", lw=0.9, label="law fitted to these cycles")
    for (name, f), style in zip(c["predicted"].items(), (":", "-.")):
        ax.plot(x, [v / force_scale for v in f], style, color="C3", lw=1.0, label=f"pair's fit, {name}")
    ax.axhline(0, color="0.6", lw=0.5)
    ax.set_xlim(-0.3, max((r[1] - touch) / d0 for rows in c["runs"].values() for r in rows) + 0.03)
    ax.set_xlabel("(delta - delta_touch)/d0, beyond the first touch")
    ax.set_ylabel("F/(kp d0)")
    ax.set_title(title, fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    outputs.savefig_atomic(fig, path, dpi=120, bbox_inches="tight")
    plt.close(fig)


def restitution(speeds, e_agg, e_meso, e_theory, broken, path, e_viscous=None, directions=(), e_normal=None,
                stuck=None):
    """e(v): the x pair's agglomerates (e along x; open where mass broke off), every direction's e
    along its normal impulse (x included, small markers; a cross at 0 where they stuck), the
    meso-particle pair, the closed form, and the pair with its viscosity fitted to one collision."""
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    families = ([{"e_normal": e_normal, "stuck": stuck}] if e_normal is not None else []) + list(directions)
    for k, d in enumerate(families):
        pts = [(v, e) for v, e, st in zip(speeds, d["e_normal"], d["stuck"]) if e is not None and not st]
        ax.plot([p[0] for p in pts], [p[1] for p in pts], ".", color="C4", alpha=0.7, ms=6,
                label="agglomerates, each direction: e along the normal impulse" if k == 0 else None)
        sticks = [v for v, st in zip(speeds, d["stuck"]) if st]
        ax.plot(sticks, [0.0] * len(sticks), "x", color="C4", ms=6,
                label="agglomerates stuck (any direction)" if k == 0 else None)
    ax.plot(speeds, e_theory, "k-", lw=1, label="closed form, fitted law")
    ax.plot(speeds, e_meso, "s", mfc="none", label="two meso-particles (YADE)")
    if e_viscous is not None:
        ax.plot(speeds, e_viscous, "^", mfc="none", color="C2", label="two meso-particles, gammaN from one collision")
    whole = [k for k, b in enumerate(broken) if b < 0.01]
    frag = [k for k, b in enumerate(broken) if b >= 0.01]
    ax.plot([speeds[k] for k in whole], [e_agg[k] for k in whole], "o", color="C3",
            label="agglomerates along x: e along x")
    if frag:
        ax.plot([speeds[k] for k in frag], [e_agg[k] for k in frag], "o", mfc="none", color="C3",
                label="agglomerates along x, >= 1 % of the mass broken off")
    ax.set_xscale("log")
    ax.set_xlabel("relative speed [m/s]")
    ax.set_ylabel("restitution e")
    ax.set_ylim(-0.04, 1.02)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))  # beside: the points fill the axes
    ax.grid(alpha=0.3)
    outputs.savefig_atomic(fig, path, dpi=120, bbox_inches="tight")
    plt.close(fig)


def ensemble(res, rows, path, measure="e_contact"):
    """The ensemble against the predictions (predict's result ``res``, the collisions' ``rows``): every
    run's ``measure`` as a dot beside its speed (a stuck run as a cross at 0), each block's mean, the mean
    with two standard errors of the runs (thick) and the blocks' Student's t interval (thin, wider), a
    speed outside the goal's in grey, and the three predictions from cycles, the third (the result) with
    the goal's band of +-0.1 over the goal's speeds."""
    fig, ax = plt.subplots(figsize=(11, 5))
    speeds = res["speeds"]
    seeds = sorted({r["seed"] for r in rows})
    for k, seed in enumerate(seeds):  # each block beside the speed, its directions spread across (no overlap)
        xs = [r["v_rel_m_s"] * 1.07 ** (k - 1) * 1.004 ** (r["direction_index"] - 10.5) for r in rows
              if r["seed"] == seed]
        ys = [None if r["stuck"] else r.get(measure) for r in rows if r["seed"] == seed]
        ax.plot([x for x, y in zip(xs, ys) if y is not None], [y for y in ys if y is not None], ".",
                ms=3, color=f"C{k}", alpha=0.35, label=f"block {seed}: each run")
        stuck = [x for x, r in zip(xs, (r for r in rows if r["seed"] == seed)) if r["stuck"]]
        ax.plot(stuck, [0.0] * len(stuck), "x", ms=3, color=f"C{k}", alpha=0.6,
                label=f"block {seed}: stuck (counted at 0)")
    by = {r["speed"]: r for r in res["verdict"]["rows"] if r["n"]}
    for k, seed in enumerate(seeds):
        pts = [(v * 1.07 ** (k - 1), by[v]["block_means"].get(str(seed))) for v in speeds if v in by]
        ax.plot([p[0] for p in pts if p[1] is not None], [p[1] for p in pts if p[1] is not None], "_", ms=12, mew=2,
                color=f"C{k}", label=f"block {seed}: mean")
    kinds = (("within", "beyond"), "k", "k", "mean of the runs measured, two standard errors of the runs"), \
        (("outside the goal",), "0.55", "0.55", "the same, beyond the goal's speeds"), \
        (("partial",), "w", "k", "mean of a speed still running")
    for states, face, edge, label in kinds:
        vs = [v for v in speeds if v in by and by[v]["state"] in states]
        if not vs:
            continue
        ax.errorbar(vs, [by[v]["mean"] for v in vs], yerr=[by[v]["half_blocks"] or 0.0 for v in vs], fmt="none",
                    ecolor=edge, lw=0.7,
                    capsize=6, alpha=0.6,
                    label="thin bars: the blocks' Student's t interval (95 %)" if face == "k" else None)
        ax.errorbar(vs, [by[v]["mean"] for v in vs], yerr=[by[v]["half_runs"] or 0.0 for v in vs], fmt="s",
                    mfc=face, mec=edge, ecolor=edge, elinewidth=1.8, ms=5, capsize=3, label=label)
    goal = [v for v in speeds if v <= 80]
    third = dict(zip(speeds, res["e_predicted"]))
    ax.fill_between(goal, [third[v] - 0.1 for v in goal], [third[v] + 0.1 for v in goal], color="C3", alpha=0.12,
                    label="the goal: third prediction +- 0.1")
    ax.plot(speeds, res["e_predicted"], "C3-", lw=1.6, label="third prediction: both dashpots, blocks pooled")
    if res.get("energy_prediction"):
        ax.plot(speeds, res["energy_prediction"]["e_predicted"], "C4--", lw=1,
                label="second: one dashpot, energy-tracked cycles")
    ax.plot(speeds, res["first_prediction"]["e_predicted"], "C7:", lw=1.2, label="first: one dashpot, loop areas")
    ax.set_xscale("log")
    ax.set_xlabel("relative speed [m/s]")
    ax.set_ylabel(f"{measure}: the contact point's normal e, with spin")
    ax.axhline(1.0, color="0.7", lw=0.5)
    ax.set_ylim(-0.1, 1.35)
    ax.grid(alpha=0.3, which="both")
    complete = sum(1 for r in res["verdict"]["rows"] if r["state"] in ("within", "beyond"))
    ax.set_title(f"Agglomerate collisions against a head-on meso pair of the law fitted to cycles alone: the goal "
                 f"{res['verdict']['goal']} ({complete} of 8 goal speeds complete)", fontsize=9)
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    outputs.savefig_atomic(fig, path, dpi=120, bbox_inches="tight")
    plt.close(fig)
