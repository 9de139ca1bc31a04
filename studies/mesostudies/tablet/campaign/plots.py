"""The tablet campaign's pictures: Figs. 16 and 18 (cycles), the rate study, Fig. 17's pull and
Fig. 19's compression (matplotlib, from the runs' rows)."""
from mesocontact import outputs as _out
from .. import uniaxial as _uni


def plot_rates(table, periods, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.8))
    for ax, mode in zip(axes, _uni.MODES):
        rows = [r for r in table if r["mode"] == mode]
        for period in periods:
            if rows[0][f"P{period:g}"] != "":
                ax.plot([r["cycle"] for r in rows], [r[f"P{period:g}"] for r in rows], "o-",
                        label=f"period {period:g} t_w")
        ax.set_xlabel("cycle")
        ax.set_ylabel("peak F/(kp d0)")
        ax.set_title(f"{mode}, Dx = {rows[0]['amplitude']:g}", fontsize=10)
        ax.set_xticks([r["cycle"] for r in rows])
        ax.legend(fontsize=8)
    fig.suptitle("Peak force per cycle against the cycle period (t_w: elastic crossing time)", fontsize=10)
    fig.tight_layout()
    fig.savefig(png, dpi=130)
    plt.close(fig)


# The paper's colours where its text names them (Fig. 16: red, the largest amplitude of its set,
# 0.2; Fig. 18: red the curve that turns plastic beyond 0.1, i.e. 0.2, and yellow 0.3).
AMPLITUDE_COLOURS = {0.025: "tab:blue", 0.05: "tab:green", 0.1: "tab:purple", 0.2: "red", 0.3: "goldenrod"}
PAPER_LARGEST = {"tension": 0.2, "compression": 0.3}  # the largest amplitude each of the paper's figures shows


def _arrow(ax, rows, frac, colour, lw=1.4):
    """An arrow along the path ``rows`` (plot coordinates) at the fraction ``frac`` of its length."""
    k = max(1, min(len(rows) - 1, int(frac * (len(rows) - 1))))
    (x0, y0), (x1, y1) = rows[max(0, k - max(3, len(rows) // 12))], rows[k]
    if (x0, y0) != (x1, y1):  # no shrinking: on a short segment it would turn the arrow round
        ax.annotate("", xy=(x1, y1), xytext=(x0, y0), zorder=6,
                    arrowprops=dict(arrowstyle="-|>", color=colour, lw=lw, mutation_scale=16, shrinkA=0, shrinkB=0))


def plot_cycles(mode, amplitudes, periods, runs, data, png, quick=False, variant=""):
    """Force-displacement cycles as the paper draws them: compressive displacement (L0 - L)/d0
    and force > 0 (tension on the negative axes; the CSVs' Dx = (L - L0)/d0 is the abscissa's
    negative), the paper's colours, the amplitudes up to the largest the paper's figure shows in
    one panel and any larger ones in a second (panel letters only with two panels); thick: the
    slower period, drawn first and pale so that the thin (first period) line stays visible on it;
    the thin lines stacked by amplitude, the smallest on top (it retraces the start that every
    other amplitude shares); arrows: black on the first loading, coloured on the re-loading of the
    last cycle; ``variant`` names a test variant in the titles."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    extra = [a for a in amplitudes if a > PAPER_LARGEST[mode]]
    panels = [[a for a in amplitudes if a <= PAPER_LARGEST[mode]]] + ([extra] if extra else [])
    fig, axes = plt.subplots(1, len(panels), figsize=(6.4 * len(panels), 4.8), squeeze=False)
    fallback = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for n, (ax, amps) in enumerate(zip(axes[0], panels)):
        for a in sorted(amps, reverse=True):
            colour = AMPLITUDE_COLOURS.get(a, fallback[amplitudes.index(a) % len(fallback)])
            mine = sorted((r for r in runs.items() if r[1]["amplitude"] == a), key=lambda r: -r[1]["period_crossings"])
            for name, info in mine:
                slow = info["period_crossings"] != periods[0]
                xy = [(-r[1], r[2]) for r in data[name]]
                rank = sorted(amplitudes, reverse=True).index(a)  # the smallest amplitude on top
                ax.plot([p[0] for p in xy], [p[1] for p in xy], color=colour, lw=3.2 if slow else 0.9,
                        alpha=0.35 if slow else 1.0, zorder=2 if slow else 3 + 0.1 * rank,
                        label=f"Dx = {a:g}, {info['period_crossings']:g} t_w" + (" (4x slower)" if slow else ""))
                if not slow:  # arrows on the thin line: first loading (black), last re-loading (colour)
                    far = max(range(len(xy)), key=lambda k: abs(xy[k][0]))
                    first_far = next(k for k in range(1, len(xy)) if abs(xy[k][0]) >= 0.999 * abs(xy[far][0]))
                    _arrow(ax, xy[:first_far + 1], 0.55, "black")
                    last = xy[len(xy) - len(xy) // info["cycles"]:]  # the last cycle
                    lf = max(range(len(last)), key=lambda k: abs(last[k][0]))
                    _arrow(ax, last[lf:], 0.45, colour)
        ax.plot([0], [0], "ko", ms=6, zorder=7)
        ax.axhline(0, color="0.6", lw=0.5)
        ax.axvline(0, color="0.6", lw=0.5)
        ax.set_xlabel("(L0 - L)/d0 = -Dx  [tension < 0]")
        ax.set_ylabel("F/(kp d0)  [compressive > 0]")
        what = (f"amplitudes up to {PAPER_LARGEST[mode]:g}, the largest the paper draws" if n == 0
                else "beyond the paper's largest amplitude")
        letter = f"({chr(97 + n)}) " if len(panels) > 1 else ""
        ax.set_title(f"{letter}{mode} cycles, {variant or what}" + (" (quick mode)" if quick else ""), fontsize=10)
        ax.legend(fontsize=6.5, ncol=2)
    fig.tight_layout()
    fig.savefig(png, dpi=130)
    plt.close(fig)


def plot_compression(rows, snaps, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.plot([-r[1] for r in rows], [r[2] for r in rows], "k-", lw=0.8)
    for k, s in enumerate(snaps):
        ax.plot(-s["Dx"], s["F"], "o", color="tab:red", ms=4)
        ax.annotate(f"({chr(97 + k)})", (-s["Dx"], s["F"]), textcoords="offset points", xytext=(3, 5), fontsize=8)
    ax.set_xlabel("compression (L0 - L)/d0")
    ax.set_ylabel("F/(kp d0)  [compressive > 0]")
    ax.set_title("Fig. 19: unconfined compression to large strain, snapshots (a)-(g)", fontsize=10)
    fig.tight_layout()
    _out.savefig_atomic(fig, png, dpi=130)
    plt.close(fig)


def plot_pull(rows, events, png):
    """The pull's force against Dx: (a) the whole pull with the crack events and the snapshots'
    marks, lettered as the snapshot panels; (b) its first 0.5 d0, where the tension branch lies
    (on the whole pull's axis it is a spike at 0)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11.5, 4.0))
    for n, (ax, until) in enumerate(zip(axes, (None, 0.5))):
        shown = [r for r in rows if until is None or r[1] <= until]
        ax.plot([r[1] for r in shown], [r[2] for r in shown], lw=0.8)
        for key, style in (("first_gap_Dx", "g--"), ("see_through_Dx", "b--"), ("last_contact_Dx", "r--")):
            if events[key] is not None and (until is None or events[key] <= until):
                ax.axvline(events[key], color=style[0], ls="--", lw=0.8, label=key.replace("_", " "))
        for k, snap in enumerate(events["snapshots"]):
            if until is None or snap["Dx"] <= until:
                ax.plot(snap["Dx"], snap["F"], "ko", ms=3)
                ax.annotate(f"({chr(97 + k)})", (snap["Dx"], snap["F"]), textcoords="offset points", xytext=(3, 5),
                            fontsize=8)
        ax.axhline(0, color="0.6", lw=0.5)
        ax.set_xlabel("Dx = (L - L0)/d0  [tension > 0]")
        ax.set_ylabel("F/(kp d0)  [compressive > 0]")
        ax.set_title("(a) the pull to rupture" if n == 0 else f"(b) its first {until:g} d0: the tension branch",
                     fontsize=10)
        if ax.get_legend_handles_labels()[0]:  # no empty box when no event was reached (or taken)
            ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=130)
    plt.close(fig)
