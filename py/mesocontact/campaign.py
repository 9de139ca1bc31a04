"""Figures 16-19 of the long paper (Appendix F) from the tablet tests (inside ``yade``).

Each figure function runs its tests from the saved released state (prepared once, reused),
writes one CSV per run and a PNG, prints progress, and returns a summary dict. ``quick=True``:
a 216-particle tablet and one cycle, for the test suite.

Rates: a cycle lasts ``period`` elastic crossing times of the sample (uniaxial.crossing_time);
the slow runs last ``slow`` times longer (4, as in the paper).
"""
import json
import os
import time

from yade import O

from . import snapshots as _snap
from . import stages as _stages
from . import tablet as _tablet
from . import uniaxial as _uni

FULL = dict(n=1728, cycles=4)
QUICK = dict(n=216, cycles=1)
TENSION_AMPLITUDES = (0.025, 0.05, 0.1, 0.2, 0.3)
COMPRESSION_AMPLITUDES = (0.05, 0.1, 0.2, 0.3)
FIG17_DX = (0.0, 0.81, 1.8, 3.1, 4.7, 7.4, 8.6)
GAP_AREA = 0.5  # a see-through hole this large [d0^2] counts as the first visible gap


def prepare(outdir, quick=False, progress=True, **tablet_kw):
    """The unconfined start of the tests loaded into O, with the released state it is made from
    (each made once and reused: stages.ensure); returns the description."""
    return _stages.ensure("unconfined", outdir, quick, progress=progress, **tablet_kw)


def _run_name(mode, amplitude, slow, prefix=""):
    return f"{prefix}{mode}-Dx{amplitude:g}-{'slow' if slow else 'fast'}"


def cyclic(mode, outdir, amplitudes=None, quick=False, period=30.0, slow=4.0, progress=True,
           snapshot_amplitude=None, figure=None):
    """Fig. 16 (tension) or Fig. 18 (compression): cycles at each amplitude, fast and slow.
    With snapshot_amplitude, the fast run of that amplitude also writes PNG and VTK snapshots
    at the start, at every peak and at every return (Fig. 19). figure: the name of the JSON
    and PNG written (default fig16 for tension, fig18 for compression), and the prefix of its
    CSV files when given. slow = 1 or None: the fast runs only."""
    prefix = f"{figure}-" if figure else ""
    _uni._check_mode(mode)
    cfg = QUICK if quick else FULL
    amplitudes = tuple(amplitudes or (TENSION_AMPLITUDES if mode == "tension" else COMPRESSION_AMPLITUDES))
    prepare(outdir, quick, progress)
    summary = {"mode": mode, "quick": quick, "period_crossings": period, "slow_factor": slow,
               "cycles": cfg["cycles"], "runs": {}}
    t_all = time.time()
    for amplitude in amplitudes:
        for is_slow in ((False,) if quick or not slow or slow == 1 else (False, True)):
            name = _run_name(mode, amplitude, is_slow, prefix)
            t0 = time.time()
            prepare(outdir, quick, progress)
            test = _uni.Test(progress=progress)
            hook = None
            if snapshot_amplitude == amplitude and not is_slow:
                hook = _cycle_snapshots(outdir, mode, amplitude, test)
            rows = test.cycles(mode, amplitude, n_cycles=cfg["cycles"], period=period * (slow if is_slow else 1.0),
                               on_record=hook)
            _uni.write_csv(os.path.join(outdir, name + ".csv"), rows)
            summary["runs"][name] = {
                "amplitude": amplitude, "slow": is_slow, "steps_per_cycle": test.steps_per_cycle,
                "dt": O.dt, "t_cross": test.t_cross, "L0": test.L0, "final_Dx": rows[-1][1],
                "max_abs_Dx": max(abs(r[1]) for r in rows), "F_range": [min(r[2] for r in rows), max(r[2] for r in rows)],
                "wall_clock_s": time.time() - t0}
            if progress:
                print(f"{name}: {time.time() - t0:.0f} s", flush=True)
    summary["wall_clock_s"] = time.time() - t_all
    fig = figure or ("fig16" if mode == "tension" else "fig18")
    if quick:
        fig += "-quick"
    # A figure re-run for some amplitudes keeps the runs of the others.
    js = os.path.join(outdir, fig + ".json")
    if os.path.exists(js):
        with open(js) as f:
            old = json.load(f)
        if old.get("period_crossings") == period and old.get("cycles") == cfg["cycles"]:
            summary["runs"] = dict(old.get("runs", {}), **summary["runs"])
            summary["wall_clock_s"] += old.get("wall_clock_s", 0)
    with open(js, "w") as f:
        json.dump(summary, f, indent=1)
    shown = sorted({r["amplitude"] for r in summary["runs"].values()})
    plot_cycles(outdir, mode, shown, os.path.join(outdir, fig + ".png"), quick, prefix)
    return summary


def _cycle_snapshots(outdir, mode, amplitude, test):
    """A record hook writing snapshots at the start, at the peaks and at the returns."""
    state = {"next": 0}
    tag = "fig19" if mode == "compression" else "fig16-snap"

    def hook(t, row):
        spc = t.steps_per_cycle
        it = row[0] - t.rows[0][0]
        k = state["next"]
        if it >= k * spc // 2:  # half-cycle marks: 0 start, 1 first peak, 2 first return, ...
            label = f"{tag}-{mode}-Dx{amplitude:g}-{k:02d}"
            what = "start" if k == 0 else ("peak" if k % 2 else "return") + f" {(k + 1) // 2}"
            _snap.png(os.path.join(outdir, label + ".png"),
                      f"{mode}, amplitude {amplitude:g} d0: {what}, Dx = {row[1]:+.3f}, F/(kp d0) = {row[2]:+.3g}")
            _snap.vtk(os.path.join(outdir, f"{tag}-{mode}-Dx{amplitude:g}"), k)
            state["next"] = k + 1
    return hook


def plot_cycles(outdir, mode, amplitudes, png, quick=False, prefix=""):
    """Force-displacement cycles, compressive displacement (L0 - L)/d0 and force > 0 (tension
    on the negative axes); thin: fast, thick: four times slower."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for k, amplitude in enumerate(amplitudes):
        for is_slow in (False, True):
            f = os.path.join(outdir, _run_name(mode, amplitude, is_slow, prefix) + ".csv")
            if not os.path.exists(f):
                continue
            d = np.loadtxt(f, delimiter=",", skiprows=1, ndmin=2)
            ax.plot(-d[:, 1], d[:, 2], color=colours[k % len(colours)], lw=2.4 if is_slow else 0.8,
                    label=f"Dx = {amplitude:g}" + (" (4x slower)" if is_slow else ""))
    ax.plot([0], [0], "ko", ms=6)
    ax.axhline(0, color="0.6", lw=0.5)
    ax.axvline(0, color="0.6", lw=0.5)
    ax.set_xlabel("compression (L0 - L)/d0  [tension < 0]")
    ax.set_ylabel("F/(kp d0)  [compressive > 0]")
    ax.set_title(f"Unconfined uni-axial {mode} cycles of the tablet" + (" (quick mode)" if quick else ""), fontsize=10)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(png, dpi=130)
    plt.close(fig)


def pull(outdir, quick=False, speed=0.0075, until=9.0, progress=True, dx_marks=FIG17_DX):
    """Fig. 17: monotonic tension to Dx = until at wall speed ``speed`` [mm/us] with PNG and
    VTK snapshots at dx_marks; records where the first see-through gap opens and where the last
    contact chain between the walls breaks."""
    prepare(outdir, quick, progress)
    tag = "fig17-quick" if quick else "fig17"
    test = _uni.Test(progress=progress)
    marks = list(dx_marks)
    events = {"first_gap_Dx": None, "last_contact_Dx": None, "snapshots": []}
    check_every = 10  # records between the (costly) gap and connectivity checks

    def hook(t, row):
        dx = row[1]
        if marks and dx >= marks[0]:
            label = f"{tag}-{len(events['snapshots']):02d}"
            _snap.png(os.path.join(outdir, label + ".png"), f"tension, Dx = {dx:.2f} (mark {marks[0]:g}), F/(kp d0) = {row[2]:+.3g}")
            _snap.vtk(os.path.join(outdir, tag), len(events["snapshots"]))
            events["snapshots"].append({"mark": marks.pop(0), "Dx": dx, "F": row[2], "png": label + ".png"})
        if len(t.rows) % check_every == 0:
            if events["first_gap_Dx"] is None and _snap.see_through_holes() > GAP_AREA:
                events["first_gap_Dx"] = dx
            if events["last_contact_Dx"] is None and not _snap.walls_connected(t.left, t.right):
                events["last_contact_Dx"] = dx

    t0 = time.time()
    rows = test.pull(speed, until=until, on_record=hook)
    _uni.write_csv(os.path.join(outdir, tag + ".csv"), rows)
    summary = dict(events, speed=speed, until=until, t_cross=test.t_cross, L0=test.L0, quick=quick,
                   wall_clock_s=time.time() - t0, max_tension=min(r[2] for r in rows))
    with open(os.path.join(outdir, tag + ".json"), "w") as f:
        json.dump(summary, f, indent=1)
    _plot_pull(rows, events, os.path.join(outdir, tag + ".png"))
    return summary


def _plot_pull(rows, events, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    ax.plot([r[1] for r in rows], [r[2] for r in rows], lw=0.8)
    for key, style in (("first_gap_Dx", "g--"), ("last_contact_Dx", "r--")):
        if events[key] is not None:
            ax.axvline(events[key], color=style[0], ls="--", lw=0.8, label=key.replace("_", " "))
    for s in events["snapshots"]:
        ax.plot(s["Dx"], s["F"], "ko", ms=3)
    ax.set_xlabel("Dx = (L - L0)/d0")
    ax.set_ylabel("F/(kp d0)  [compressive > 0]")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=130)
    plt.close(fig)


def main(figure, argv):
    """Command line of the figure scripts: [--quick] [--out DIR] [--period P] [--amplitudes a,b]."""
    import argparse
    p = argparse.ArgumentParser(prog=f"yade -n -x scripts/tablet_{figure}.py",
                                description=f"Appendix F, {figure}: writes CSV, PNG (and VTK) into --out.")
    p.add_argument("--quick", action="store_true", help="216 particles, one cycle (for tests)")
    p.add_argument("--out", default="results/tablet", help="output directory (the released state is reused from it)")
    p.add_argument("--period", type=float, default=30.0, help="cycle period in elastic crossing times (fast runs)")
    p.add_argument("--amplitudes", default=None, help="comma-separated amplitudes Dx in d0")
    p.add_argument("--speed", type=float, default=0.0075, help="fig17: wall speed [mm/us]")
    if figure == "prepare":
        p.add_argument("--material", default="appendixF", choices=sorted(_tablet.MATERIALS),
                       help="particle parameters: Appendix F of the long paper or Table 2 of Luding 2008")
        p.add_argument("--kc-over-kp", type=float, default=None, help="overrides the set's kc/kp")
        p.add_argument("--n", type=int, default=None, help="number of particles (1728; 216 with --quick)")
    a = p.parse_args(argv)
    amps = tuple(float(x) for x in a.amplitudes.split(",")) if a.amplitudes else None
    t0 = time.time()
    if figure == "prepare":
        info = prepare(a.out, a.quick, material=a.material, kc_over_kp=a.kc_over_kp, n=a.n)
        out = {k: info[k] for k in ("compacted", "sintered", "released", "unconfined") if k in info}
    elif figure == "fig16":
        out = cyclic("tension", a.out, amps, a.quick, a.period)
    elif figure == "fig18":
        out = cyclic("compression", a.out, amps, a.quick, a.period)
    elif figure == "fig19":
        amp = (amps or (0.3,))[-1]
        out = cyclic("compression", a.out, (amp,), a.quick, a.period, slow=1.0, snapshot_amplitude=amp, figure="fig19")
    elif figure == "fig17":
        out = pull(a.out, a.quick, speed=a.speed)
    else:
        raise ValueError(f"figure = {figure!r} is invalid")
    print(json.dumps(out, indent=1, default=str)[:4000])
    print(f"{figure} done in {time.time() - t0:.0f} s; outputs in {os.path.abspath(a.out)}", flush=True)
