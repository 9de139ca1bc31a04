"""Figures 16-19 of the long paper (Appendix F) from the tablet tests (inside ``yade``).

Each figure function runs its tests from the cached unconfined start (stages.ensure: made once,
reused), prints progress and returns a summary dict. Results are bundles (outputs.Bundle: whole
or absent, whatever stops the job): each run in ``runs/<run>/`` (``<run>.csv``: iter, Dx,
F/(kp d0); ``<run>.json``: its description and peaks), each figure in ``<figure>/`` (its JSON and
PNG with copies of the runs it plots). ``quick=True``: a 216-particle tablet and one cycle, for
the test suite, under ``<out>/quick/`` (quick and full results never share a name).

Rates: a cycle lasts ``period`` elastic crossing times of the sample (uniaxial.crossing_time).
``rates`` runs one amplitude at three periods, each 4x the last; the figures run FAST and the
4x slower SLOW, the pair where the peak force of every cycle agrees within 5 %.
"""
import json
import math
import os
import tempfile
import time

from yade import O
from yade import wrapper as _w

from . import mpi as _mpi
from . import outputs as _out
from . import scene as _scene
from . import snapshots as _snap
from . import stages as _stages
from . import tablet as _tablet
from . import uniaxial as _uni

# yade.mpy when the campaign runs under mpiexec with --mpi N (use_mpi), else None
_MPY = None


def use_mpi(ranks):
    """Runs the cyclic tests of this process under yade.mpy on ``ranks`` MPI processes (a master
    holding the walls and ranks - 1 workers; the process must have been started by
    ``mpiexec -n ranks``). Every rank computes, the master writes. Returns the mpy module."""
    global _MPY
    from yade import mpy  # configures MPI on import
    if mpy.numThreads != ranks:
        raise ValueError(f"--mpi {ranks}: start this job with `mpiexec -n {ranks} yade ...` (it has "
                         f"{mpy.numThreads} process(es))")
    _MPY = mpy
    return mpy


def is_master():
    """True on the process that writes the outputs (always, without MPI)."""
    return _MPY is None or _MPY.rank == 0


FULL = dict(n=1728, cycles=4)
QUICK = dict(n=216, cycles=1)
TENSION_AMPLITUDES = (0.025, 0.05, 0.1, 0.2, 0.3)
COMPRESSION_AMPLITUDES = (0.05, 0.1, 0.2, 0.3)
FIG17_DX = (0.0, 0.81, 1.8, 3.1, 4.7, 7.4, 8.6)
# Cycle periods in elastic crossing times (uniaxial.crossing_time): the rate study runs all
# three; the figures run FAST (thin) and SLOW (thick), where the peaks agree within 5 %.
RATE_PERIODS = (30.0, 120.0, 480.0)
# The periods of the figures (thin, thick), from the rate checks (docs/tablet/README.md, section 4):
# compression agrees within 0.6 % between 120 and 480 t_w in every cycle; tension does not (the
# re-loading cycles 6.5 % apart at Dx = 0.2) but agrees within 1.95 % between 480 and 1920 t_w
# at every amplitude (0.025 to 0.3).
PERIODS = {"tension": (480.0, 1920.0), "compression": (120.0, 480.0)}
PULL_SPEED = 0.0025  # Fig. 17: each wall's speed [mm/us]: the peak wall speed of 240 t_w cycles at Dx = 0.2, where the first pull's peak agrees within 2.2 % from 120 t_w on (Dx = 9 in about 1 040 000 steps)
FAST, SLOW = PERIODS["compression"]
GAP_AREA = 1.0  # a crack (or see-through hole) this large [d0^2] counts as visible
# The campaign's time step per test, as a multiple of tablet.contact_step (t_c/50), from the
# time-step study (docs/tablet/timestep.md): the largest factor whose outcome stays within 0.5 %
# of 1 dt, or within the spread of perturbed runs where that is larger.
DT_FACTORS = {"tension": 3.0, "compression": 4.0, "pull": 1.0}


# The preparation the campaign's tests start from (tablet.prepare's packing, glue, rel_std), chosen
# by the factor study (docs/tablet/factors/factors.md): packed without friction and adhesion, all
# six walls adhesive through sintering, radii spread 0.1 - the only preparation that meets the
# paper's L0 and first gap (its tear is still next to a wall). Every run records it; a run made
# from another preparation is made again, not read back.
FIRST_PROTOCOL = {"packing": "full", "glue": "loading", "rel_std": 0.05}  # what a run without a record was made from
PROTOCOL = {"packing": "frictionless", "glue": "sinter", "rel_std": 0.1}


def _protocol_of(info):
    return dict(FIRST_PROTOCOL, **(info.get("protocol") or {}))


def prepare(outdir, quick=False, progress=True, **tablet_kw):
    """The unconfined start of the tests loaded into O, with the released state it is made from
    (each made once and reused: stages.ensure), by the campaign's PROTOCOL unless tablet_kw
    says otherwise; returns the description."""
    return _stages.ensure("unconfined", outdir, quick, progress=progress, **dict(PROTOCOL, **tablet_kw))


def run_name(mode, amplitude, period, prefix=""):
    return f"{prefix}{mode}-Dx{amplitude:g}-P{period:g}"


def root(outdir, quick=False):
    """Where the results of a campaign (quick: of its quick mode) go."""
    return os.path.join(outdir, "quick") if quick else outdir


def run_dir(outdir, name, quick=False):
    return os.path.join(root(outdir, quick), "runs", name)


def read_csv(path):
    with open(path) as f:
        return [tuple(float(x) for x in line.split(",")) for line in f.read().split("\n")[1:] if line]


def _csv_text(rows, header="iter,Dx,F_over_kp_d0"):
    return header + "\n" + "".join(f"{int(r[0])}," + ",".join(repr(x) for x in r[1:]) + "\n" for r in rows)


def cycle_peaks(mode, rows, steps_per_cycle):
    """The peak force of each cycle: the most tensile (min F) in tension, the largest in compression."""
    start = rows[0][0]
    cycles = {}
    for it, _, f in rows:
        k = min(int((it - start) // steps_per_cycle), int((rows[-1][0] - start - 1) // steps_per_cycle))
        cycles.setdefault(k, []).append(f)
    pick = min if mode == "tension" else max
    return [pick(cycles[k]) for k in sorted(cycles)]


def _test(progress):
    """The uni-axial test on the loaded start, serially or, under yade.mpy, split over the ranks
    (the master records, every rank follows its decisions). Returns (test, f0): f0 the first
    row's force under mpy, read before the split clears the master's forces; None serially."""
    if _MPY is None:
        return _uni.Test(progress=progress), None
    test = _uni.Test(progress=progress, run=lambda n: _MPY.mpirun(n), records=_MPY.rank == 0,
                     share=lambda x: _MPY.comm.bcast(x, root=0))
    f0 = test.force()
    _mpi.split_tablet(_MPY)
    return test, f0


def run_cycles(outdir, mode, amplitude, period, quick=False, progress=True, prefix="", dt_factor=None,
               energy=False, cycles=None):
    """One cyclic run (the campaign's cycle count, period in crossing times) from the unconfined
    start: writes ``<name>.csv`` (iter, Dx, F/(kp d0)) and ``<name>.json`` (the run's
    description, peaks per cycle) in the bundle runs/<name>/. A complete bundle made from the
    campaign's PROTOCOL is read back, not repeated. ``dt_factor`` scales tablet.contact_step (default
    DT_FACTORS[mode]); ``energy`` adds the energy balance of the run (uniaxial.Test.energy_balance)
    to the JSON; ``cycles`` overrides the campaign's cycle count. Returns (description, rows)."""
    name = run_name(mode, amplitude, period, prefix)
    where = run_dir(outdir, name, quick)
    if _out.complete(where):
        with open(os.path.join(where, name + ".json")) as f:
            info = json.load(f)
        if _protocol_of(info) == PROTOCOL:
            return info, read_csv(os.path.join(where, name + ".csv"))
        if progress:
            print(f"{name}: the run in {where} was made from another preparation ({_protocol_of(info)}): made again",
                  flush=True)
    n_cycles = cycles or (QUICK if quick else FULL)["cycles"]
    t0 = time.time()
    prepare(outdir, quick, progress and is_master())
    dt_factor = DT_FACTORS[mode] if dt_factor is None else dt_factor
    O.dt *= dt_factor
    bundle = _out.Bundle(where) if is_master() else None
    try:
        test, f0 = _test(progress)
        if energy:
            test.track_energy()
        rows = test.cycles(mode, amplitude, n_cycles=n_cycles, period=period)
        if _MPY is not None:
            rows = _MPY.comm.bcast(rows, root=0)  # the master's rows: one result on every rank
            rows[0] = (*rows[0][:2], f0)
    except BaseException:
        if bundle is not None:
            bundle.discard()
        raise
    info = {"name": name, "mode": mode, "amplitude": amplitude, "period_crossings": period, "cycles": n_cycles,
            "quick": quick, "steps_per_cycle": test.steps_per_cycle, "dt": O.dt, "t_cross": test.t_cross,
            "L0": test.L0, "final_Dx": rows[-1][1], "max_abs_Dx": max(abs(r[1]) for r in rows),
            "F_range": [min(r[2] for r in rows), max(r[2] for r in rows)],
            "peaks": cycle_peaks(mode, rows, test.steps_per_cycle), "wall_clock_s": time.time() - t0,
            "steps": O.iter - rows[0][0], "ms_per_step": 1e3 * (time.time() - t0) / max(1, O.iter - rows[0][0]),
            "mpi_ranks": _MPY.numThreads if _MPY else 1, "dt_factor": dt_factor, "final_F": rows[-1][2],
            "protocol": dict(PROTOCOL)}
    if energy:
        info["energy_balance"] = test.energy_balance()
    if bundle is None:
        return info, rows
    with bundle:
        bundle.write_text(name + ".csv", _csv_text(rows))
        bundle.write_text(name + "-branches.csv", _csv_text(test.branches, "iter,Dx," + ",".join(_scene.BRANCHES)))
        bundle.write_json(name + ".json", info)
    if progress:
        print(f"{name}: {info['wall_clock_s']:.0f} s, peaks {['%.4g' % x for x in info['peaks']]}", flush=True)
    return info, rows


def cyclic(mode, outdir, amplitudes=None, quick=False, periods=None, progress=True, slow_amplitudes=None):
    """Fig. 16 (tension) or Fig. 18 (compression): cycles at each amplitude and period (crossing
    times, default PERIODS[mode]; thin lines the first, thick the others; the slower periods
    only for ``slow_amplitudes`` when given); writes the figure's bundle (fig16 or fig18)."""
    _uni._check_mode(mode)
    amplitudes = tuple(amplitudes or (TENSION_AMPLITUDES if mode == "tension" else COMPRESSION_AMPLITUDES))
    periods = tuple(periods or PERIODS[mode])
    runs, data = {}, {}
    for amplitude in amplitudes:
        for k, period in enumerate(periods):
            if k > 0 and slow_amplitudes is not None and amplitude not in slow_amplitudes:
                continue
            info, rows = run_cycles(outdir, mode, amplitude, period, quick, progress)
            runs[info["name"]] = info
            data[info["name"]] = rows
    fig = "fig16" if mode == "tension" else "fig18"
    summary = {"mode": mode, "quick": quick, "periods_crossings": list(periods), "amplitudes": list(amplitudes),
               "runs": runs, "wall_clock_s": sum(r["wall_clock_s"] for r in runs.values())}
    if not is_master():
        return summary
    with _out.Bundle(os.path.join(root(outdir, quick), fig)) as b:
        for name in runs:
            b.copy_from(run_dir(outdir, name, quick))
        b.write_json(fig + ".json", summary)
        plot_cycles(mode, amplitudes, periods, runs, data, b.path(fig + ".png"), quick)
    return summary


def rates(outdir, quick=False, amplitude=0.2, periods=RATE_PERIODS, progress=True, run_missing=True):
    """The rate study: the tension and compression cycles of one amplitude at every period of
    ``periods`` (crossing times, each 4x the last); writes rates.json, rates.csv (peak force per
    cycle and period, and the change from each period to the next) and rates.png. Periods beyond
    RATE_PERIODS, and with run_missing=False every period, enter only where their run is complete."""
    table, runs = [], {}
    for mode in _uni.MODES:
        peaks = {}
        for period in periods:
            name = run_name(mode, amplitude, period)
            if (period not in RATE_PERIODS or not run_missing) and not _out.complete(run_dir(outdir, name, quick)):
                continue  # a slower period only where it was run (it is long)
            info, _ = run_cycles(outdir, mode, amplitude, period, quick, progress)
            runs[info["name"]] = info
            peaks[period] = info["peaks"]
        first = next(q for q in periods if q in peaks)
        for c in range(len(peaks[first])):
            row = {"mode": mode, "amplitude": amplitude, "cycle": c + 1}
            for period in periods:
                row[f"P{period:g}"] = peaks[period][c] if period in peaks else ""
            for p1, p2 in zip(periods, periods[1:]):
                row[f"change_P{p1:g}_P{p2:g}"] = abs(peaks[p1][c] / peaks[p2][c] - 1) if p1 in peaks and p2 in peaks else ""
            table.append(row)
    keys = list(table[0])
    text = ",".join(keys) + "\n" + "".join(",".join(str(row[k]) for k in keys) + "\n" for row in table)
    summary = {"amplitude": amplitude, "periods_crossings": list(periods), "table": table, "runs": runs,
               "criterion": "peak force of every cycle within 5 % between a period and the next (4x slower)"}
    with _out.Bundle(os.path.join(root(outdir, quick), "rates")) as b:
        for name in runs:
            b.copy_from(run_dir(outdir, name, quick))
        b.write_text("rates.csv", text)
        b.write_json("rates.json", summary)
        _plot_rates(table, periods, b.path("rates.png"))
    return summary


# The time-step study: one tension cycle (Dx = 0.2, the tension FAST period), one compression
# cycle (Dx = 0.3, the compression FAST period) and the pull to TIMESTEP_PULL_UNTIL, at these
# multiples of the campaign's time step (tablet.contact_step); PERTURBED, a step changed by 1e-6,
# measures how much the rupture moves for a change far below any integration error.
TIMESTEP_FACTORS = (1.0, 2.0, 3.0, 4.0)
PERTURBED = 1.000001
# More perturbed runs (tension and pull in the committed study): the spread among them all is the
# sample's sensitivity; one run alone can be lucky.
PERTURBED_MORE = (1.000002, 0.999999)
TIMESTEP_RUNS = ("tension", "compression", "pull")
TIMESTEP_PULL_UNTIL = 5.0
TIMESTEP_TOLERANCE = 0.005  # the largest change against 1 dt accepted for a quantity


def timestep_run(outdir, run, factor, quick=False, progress=True):
    """One run of the time-step study (run: 'tension', 'compression' or 'pull'), with energy
    balance; read back when complete. Returns its JSON description."""
    tag = f"timestep-x{factor:.10g}"  # 1.000001 too
    if run == "pull":
        where = os.path.join(root(outdir, quick), f"{tag}-pull")
        if _out.complete(where):
            with open(os.path.join(where, f"{tag}-pull.json")) as f:
                return json.load(f)
        return pull(outdir, quick, until=TIMESTEP_PULL_UNTIL, progress=progress, dx_marks=(), tag=f"{tag}-pull",
                    dt_factor=factor, energy=True, check_every=2)
    amplitude, period = (0.2, PERIODS["tension"][0]) if run == "tension" else (0.3, PERIODS["compression"][0])
    info, _ = run_cycles(outdir, run, amplitude, period, quick, progress, prefix=tag + "-", dt_factor=factor,
                         energy=True, cycles=1)  # one cycle shows the step's effect
    return info


def timestep_table(outdir, quick=False, factors=TIMESTEP_FACTORS + (PERTURBED,) + PERTURBED_MORE):
    """Gathers the study's complete runs into timestep.json: per factor the peaks, the force back
    at Dx = 0, the pull's events, the energy balance, the cost, and each quantity's change against
    1 dt (relative; the force at Dx = 0 against the cycle's peak). For each test (tension,
    compression, pull): the largest factor up to which every quantity stays within TIMESTEP_TOLERANCE, or
    within PERTURBED's change (the sample's own sensitivity) where that is larger."""
    import glob
    rows = {}
    for path in glob.glob(os.path.join(root(outdir, quick), "**", "timestep-x*.json"), recursive=True):
        with open(path) as f:
            j = json.load(f)
        factor = j["dt_factor"]
        if factor not in factors:
            continue
        row = rows.setdefault(factor, {"factor": factor, "dt": j["dt"]})
        kind = "pull" if "first_gap_Dx" in j else j["mode"]
        if kind == "pull":
            row.update(pull_max_tension=j["max_tension"], pull_max_tension_Dx=j["max_tension_Dx"],
                       first_gap_Dx=j["first_gap_Dx"], last_contact_Dx=j["last_contact_Dx"])
        else:
            row.update({f"{kind}_peak": j["peaks"][0], f"{kind}_F_at_Dx0": j["final_F"]})  # the cycle ends at Dx = 0
        row[f"{kind}_energy_residual"] = j["energy_balance"]["residual_over_gross"]
        row[f"{kind}_ms_per_step"] = j["ms_per_step"]
    keys = ("tension_peak", "tension_F_at_Dx0", "compression_peak", "compression_F_at_Dx0", "pull_max_tension",
            "first_gap_Dx", "last_contact_Dx")
    ref = rows.get(1.0, {})

    def change(row, k):
        # The force back at Dx = 0 is small beside the peak: its change is measured against the peak.
        scale = ref.get(k.replace("F_at_Dx0", "peak"))
        return abs(row[k] - ref[k]) / abs(scale) if k.endswith("F_at_Dx0") else abs(row[k] / ref[k] - 1)

    for row in rows.values():
        row["change_vs_1dt"] = {k: change(row, k) for k in keys if row.get(k) is not None and ref.get(k) not in (None, 0)}
    perturbed = [rows[f]["change_vs_1dt"] for f in (PERTURBED,) + PERTURBED_MORE if f in rows]
    sensitivity = {k: max(p[k] for p in perturbed if k in p) for k in keys if any(k in p for p in perturbed)}
    groups = {"tension": keys[:2], "compression": keys[2:4], "pull": keys[4:]}

    def accepted(group):
        # the largest factor up to which every factor has all the group's quantities within bounds
        best = None
        for f in sorted(x for x in rows if x in TIMESTEP_FACTORS):
            ch = rows[f]["change_vs_1dt"]
            if not all(k in ch for k in groups[group] if ref.get(k) is not None) or \
                    any(ch[k] > max(TIMESTEP_TOLERANCE, sensitivity.get(k, 0)) for k in groups[group] if k in ch):
                break
            best = f
        return best

    out = {"tolerance": TIMESTEP_TOLERANCE, "perturbed_factors": [f for f in (PERTURBED,) + PERTURBED_MORE if f in rows],
           "pull_until": TIMESTEP_PULL_UNTIL,
           "rows": [rows[f] for f in sorted(rows)], "perturbation_sensitivity": sensitivity,
           "largest_accepted_factor": {g: accepted(g) for g in groups}}
    with _out.Bundle(os.path.join(root(outdir, quick), "timestep")) as b:
        b.write_json("timestep.json", out)
        b.write_text("timestep.md", timestep_markdown(out))
    return out


def timestep_markdown(ts):
    """The study's table (timestep.json) as Markdown: one row per factor, changes against 1 dt in %."""
    cols = (("tension_peak", "tension peak", ".5f"), ("tension_F_at_Dx0", "tension F at Dx=0", "+.5f"),
            ("compression_peak", "compression peak", ".5f"), ("compression_F_at_Dx0", "compression F at Dx=0", "+.5f"),
            ("pull_max_tension", "pull peak", ".5f"), ("first_gap_Dx", "first gap Dx", ".3f"),
            ("last_contact_Dx", "last chain Dx", ".3f"))
    out = ["| dt / dt_campaign | " + " | ".join(c[1] for c in cols) + " | energy residual (t, c, pull) | ms/step (t, c, pull) |",
           "|---" * (len(cols) + 3) + "|"]
    for r in ts["rows"]:
        cells = []
        for key, _, fmt in cols:
            v, ch = r.get(key), r.get("change_vs_1dt", {}).get(key)
            cells.append("—" if v is None else f"{v:{fmt}}" + ("" if ch is None or r["factor"] == 1.0 else f" ({100 * ch:.2f} %)"))
        res = ", ".join("—" if r.get(f"{m}_energy_residual") is None else f"{r[f'{m}_energy_residual']:.1e}"
                        for m in ("tension", "compression", "pull"))
        ms = ", ".join("—" if r.get(f"{m}_ms_per_step") is None else f"{r[f'{m}_ms_per_step']:.2f}"
                       for m in ("tension", "compression", "pull"))
        out.append(f"| {r['factor']:.10g} | " + " | ".join(cells) + f" | {res} | {ms} |")
    return "\n".join(out) + "\n"


def timestep_study(outdir, quick=False, factors=TIMESTEP_FACTORS + (PERTURBED,) + PERTURBED_MORE, runs=TIMESTEP_RUNS,
                   progress=True):
    """The runs of the study for these factors and runs (complete ones are read back), then the
    table of every complete run (timestep_table)."""
    for factor in factors:
        for run in runs:
            timestep_run(outdir, run, factor, quick, progress)
    return timestep_table(outdir, quick)


def drag_share(outdir, quick=False, amplitude=0.2, period=FAST, progress=True):
    """How much of the tension peak the background drag supplies: one tension cycle with the
    drag relative to the lab (the old form), relative to the contacts (the tests' form) and
    without drag; writes drag-share.json."""
    out = {"amplitude": amplitude, "period_crossings": period, "runs": {}}
    for label in ("lab", "contacts", "none"):
        prepare(outdir, quick, progress)
        drag = [e for e in O.engines if isinstance(e, _w.MesoBackgroundDamping)][0]
        if label == "none":
            drag.gammaB = drag.gammaBR = 0.0
        else:
            drag.reference = label
        test = _uni.Test(progress=False)
        rows = test.cycles("tension", amplitude, n_cycles=1, period=period)
        out["runs"][label] = {"peak": cycle_peaks("tension", rows, test.steps_per_cycle)[0], "final_F": rows[-1][2]}
        if progress:
            print(f"  drag {label}: tension peak F/(kp d0) = {out['runs'][label]['peak']:.5g}", flush=True)
    none = out["runs"]["none"]["peak"]
    for label in ("lab", "contacts"):
        out["runs"][label]["drag_share_of_peak"] = 1 - none / out["runs"][label]["peak"]
    with _out.Bundle(os.path.join(root(outdir, quick), "drag-share")) as b:
        b.write_json("drag-share.json", out)
    return out


def _plot_rates(table, periods, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(9, 3.8))
    for ax, mode in zip(axes, _uni.MODES):
        rows = [r for r in table if r["mode"] == mode]
        for period in periods:
            if rows[0][f"P{period:g}"] != "":
                ax.plot([r["cycle"] for r in rows], [r[f"P{period:g}"] for r in rows], "o-", label=f"period {period:g} t_w")
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


def plot_cycles(mode, amplitudes, periods, runs, data, png, quick=False):
    """Force-displacement cycles as the paper draws them: compressive displacement (L0 - L)/d0
    and force > 0 (tension on the negative axes), the paper's colours, the amplitudes of the
    paper's figure in panel (a) and any larger ones in panel (b); thick: the slower period, drawn
    first and pale so that the thin (first period) line stays visible on it; the largest
    amplitude drawn first so that none hides a smaller one; arrows: black on the first
    loading, coloured on the re-loading of the last cycle."""
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
                ax.plot([p[0] for p in xy], [p[1] for p in xy], color=colour, lw=3.2 if slow else 0.8,
                        alpha=0.35 if slow else 1.0, zorder=2 if slow else 3,
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
        ax.set_xlabel("compression (L0 - L)/d0  [tension < 0]")
        ax.set_ylabel("F/(kp d0)  [compressive > 0]")
        what = "the paper's amplitudes" if n == 0 else "a larger amplitude than the paper's"
        ax.set_title(f"({chr(97 + n)}) {mode} cycles, {what}" + (" (quick mode)" if quick else ""), fontsize=10)
        ax.legend(fontsize=6.5, ncol=2)
    fig.tight_layout()
    fig.savefig(png, dpi=130)
    plt.close(fig)


def pull(outdir, quick=False, speed=None, until=9.0, progress=True, dx_marks=FIG17_DX, tag="fig17", dt_factor=None,
         energy=False, check_every=10, protocol=None, drag="contacts", stop_after_last=None):
    """Fig. 17: monotonic tension to Dx = until, each wall moving out at ``speed`` [mm/us], with
    PNG and VTK snapshots at dx_marks (one frame for all); records where the first crack is
    visible from the front face (snapshots.visible_gap >= GAP_AREA d0^2), where one first sees
    through the sample, where the last contact chain between the walls breaks, and the force
    after that (no drag acts on a detached half moving as a body: it must vanish). Under
    yade.mpy (--mpi) the same force rows, without the events and snapshots. ``tag`` names the
    bundle; ``dt_factor`` scales tablet.contact_step (default DT_FACTORS['pull']); ``energy`` adds
    the run's energy balance; ``check_every``: records (each 100 campaign steps of wall travel, the
    same Dx at any dt_factor) between the costly gap and connectivity checks, their resolution.
    ``protocol``: the preparation's options (tablet.prepare's packing, glue); ``drag``: the
    background drag's reference in the test ('contacts' as in every test, or 'lab'). Also records
    the contacts crossing each plane x = const (uniaxial.crossing_profile) at Dx = 0 and at the
    largest tension seen at a check, and the first gap at half and twice the area criterion.
    ``stop_after_last``: end the pull this far (in Dx) past the last chain's break."""
    speed = speed or PULL_SPEED
    if drag not in ("contacts", "lab"):
        raise ValueError(f"drag = {drag!r} is invalid: 'contacts' or 'lab'")
    prepare(outdir, quick, progress and is_master(), **(protocol or {}))
    for e in O.engines:
        if isinstance(e, _w.MesoBackgroundDamping):
            e.reference = drag
    dt_factor = DT_FACTORS["pull"] if dt_factor is None else dt_factor
    O.dt *= dt_factor
    test, f0 = _test(progress)
    if energy:
        test.track_energy()
    bundle = _out.Bundle(os.path.join(root(outdir, quick), tag)) if is_master() else None
    marks = list(dx_marks)
    events = {"first_gap_Dx": None, "see_through_Dx": None, "last_contact_Dx": None, "snapshots": [],
              "gap_area": [], "planes_at_start": _uni.crossing_profile() if _MPY is None else None, "planes_at_peak": None,
              "planes_at_marks": {}}
    peak = [0.0]
    plane_marks = sorted({0.2, *dx_marks[1:]})  # Dx = 0.2: "mostly, but not completely lost mechanical contact"

    def hook(t, row):
        dx = row[1]
        if marks and dx >= marks[0]:
            label = f"{tag}-{len(events['snapshots']):02d}"
            _snap.png(os.path.join(bundle.tmp, label + ".png"),
                      f"tension, Dx = {dx:.2f} (mark {marks[0]:g}), F/(kp d0) = {row[2]:+.3g}", win=win)
            _snap.vtk(os.path.join(bundle.tmp, tag), len(events["snapshots"]))
            events["snapshots"].append({"mark": marks.pop(0), "Dx": dx, "F": row[2], "png": label + ".png"})
        while plane_marks and dx >= plane_marks[0]:
            events["planes_at_marks"][f"{plane_marks.pop(0):g}"] = dict(_uni.crossing_profile(), Dx=dx, F=row[2])
        # The largest tension so far (F < 0 in tension): where does the sample tear? Looked at on
        # every record that sets a new peak (only while the force rises, a few hundred records),
        # since a dense sample's peak is too sharp for the coarser checks below.
        if row[2] < peak[0]:
            peak[0] = row[2]
            events["planes_at_peak"] = dict(_uni.crossing_profile(), Dx=dx, F=row[2])
        if len(t.rows) % check_every == 0:
            if not events["gap_area"] or events["gap_area"][-1][1] < 2 * GAP_AREA:  # up to twice the criterion
                area = _snap.visible_gap()
                events["gap_area"].append((dx, area))
                if area >= GAP_AREA and events["first_gap_Dx"] is None:
                    events["first_gap_Dx"] = dx
            if events["see_through_Dx"] is None and _snap.see_through_holes() > GAP_AREA:
                events["see_through_Dx"] = dx
            if events["last_contact_Dx"] is None and not _snap.walls_connected(t.left, t.right):
                events["last_contact_Dx"] = dx

    # The events and snapshots look at every particle, which under yade.mpy no rank holds.
    if _MPY is None:
        win = _snap.window(margin=1.0, stretch=0.5 * until)
    t0 = time.time()
    try:
        stop = None if stop_after_last is None else (
            lambda: events["last_contact_Dx"] is not None and test.dx() > events["last_contact_Dx"] + stop_after_last)
        rows = test.pull(speed, until=until, every=max(1, int(round(100 / dt_factor))),
                         on_record=hook if _MPY is None else None, stop=stop)
    except BaseException:
        if bundle is not None:
            bundle.discard()
        raise
    if bundle is None:
        return None
    if f0 is not None:
        rows[0] = (*rows[0][:2], f0)
    after = [r[2] for r in rows if events["last_contact_Dx"] is not None and r[1] > events["last_contact_Dx"] + 0.05]
    summary = dict(events, speed=speed, until=until, t_cross=test.t_cross, L0=test.L0, quick=quick,
                   wall_clock_s=time.time() - t0, max_tension=min(r[2] for r in rows),
                   max_tension_Dx=min(rows, key=lambda r: r[2])[1],
                   # a drag on the halves would show as a mean force; they ring about zero
                   mean_force_after_last_contact=sum(after) / len(after) if after else None,
                   rms_force_after_last_contact=(sum(f * f for f in after) / len(after)) ** 0.5 if after else None,
                   gap_criterion=f"a crack of >= {GAP_AREA:g} d0^2 seen >= 3 d0 behind the front face, "
                                 "in the central 60 % of the height, between the walls",
                   first_gap_Dx_by_area={f"{k:g}": next((d for d, a in events["gap_area"] if a >= k), None)
                                         for k in (0.5 * GAP_AREA, GAP_AREA, 2 * GAP_AREA)},
                   protocol=dict(PROTOCOL, **(protocol or {})), drag=drag,
                   mpi_ranks=_MPY.numThreads if _MPY else 1, dt=O.dt, dt_factor=dt_factor,
                   steps=O.iter - rows[0][0], ms_per_step=1e3 * (time.time() - t0) / max(1, O.iter - rows[0][0]))
    if energy:
        summary["energy_balance"] = test.energy_balance()
    if _MPY is not None:
        summary["events_note"] = ("under yade.mpy the crack events and snapshots are not taken (they need every "
                                  "particle on one process): run the pull without --mpi for them")
    with bundle:
        bundle.write_text(tag + ".csv", _csv_text(rows))
        bundle.write_json(tag + ".json", summary)
        _plot_pull(rows, events, bundle.path(tag + ".png"))
    return summary


FIG19_DX = (0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0)  # compression marks of Fig. 19's panels (a)-(g) [d0]


def large_compression(outdir, quick=False, speed=None, until=3.0, progress=True, dx_marks=FIG19_DX, tag="fig19"):
    """Fig. 19: monotonic unconfined compression to Dx = -until (3 d0: ten times the largest
    cyclic amplitude, a quarter of the sample's length), the walls moving in at ``speed``
    [mm/us] (the pull's), with lettered PNG and VTK snapshots at ``dx_marks`` and, at each mark,
    the sample's lateral widths, solid fraction and coordination (the continuous plastic
    deformation: the sample flattens and spreads while the force stays on a plateau). At the
    pull's time step (large strains are beyond the time-step study's cycles)."""
    speed = speed or PULL_SPEED
    prepare(outdir, quick, progress)
    O.dt *= DT_FACTORS["pull"]
    test, f0 = _test(progress)
    bundle = _out.Bundle(os.path.join(root(outdir, quick), tag))
    marks, snaps = list(dx_marks), []
    # Room for the lateral spread: compressed by 3 d0 the sample widened by 3.8 d0 (y) and 5.9 d0 (z)
    # on each side (chosen/fig19.json); 0.3 until clipped the panels from (e) on.
    win = _snap.window(margin=1.5 + 2.5 * until)

    def hook(t, row):
        if marks and -row[1] >= marks[0]:
            k = len(snaps)
            label = f"{tag}-{k:02d}"
            _snap.png(os.path.join(bundle.tmp, label + ".png"),
                      f"({chr(97 + k)}) compression, Dx = {-row[1]:.2f}, F/(kp d0) = {row[2]:+.3g}", win=win)
            _snap.vtk(os.path.join(bundle.tmp, tag), k)
            s = _tablet.stats()
            wy, wz = _spread_widths()
            snaps.append({"mark": marks.pop(0), "Dx": row[1], "F": row[2], "png": label + ".png",
                          "width_y_d0": wy / _tablet.D0, "width_z_d0": wz / _tablet.D0,
                          "coordination": s["coordination"], "rattlers": s["rattlers"]})

    t0 = time.time()
    try:
        rows = test.compress(speed, until=until, every=100, on_record=hook)
    except BaseException:
        bundle.discard()
        raise
    if f0 is not None:
        rows[0] = (*rows[0][:2], f0)
    summary = {"speed": speed, "until": until, "L0": test.L0, "quick": quick, "snapshots": snaps, "dt": O.dt,
               "protocol": dict(PROTOCOL),
               "max_force": max(r[2] for r in rows), "final_force": rows[-1][2], "steps": O.iter - rows[0][0],
               "wall_clock_s": time.time() - t0, "strain_at_end": until * _tablet.D0 / test.L0}
    with bundle:
        bundle.write_text(tag + ".csv", _csv_text(rows))
        bundle.write_json(tag + ".json", summary)
        _plot_compression(rows, snaps, bundle.path(tag + ".png"))
    return summary


def _spread_widths():
    """The sample's widths in y and z from the spread of the particle centres, sqrt(12) std + d0
    (exact for centres spread evenly over a slab; a few particles squeezed out barely move it,
    where they would set the extent)."""
    import statistics
    ids = _tablet.sphere_ids()
    return tuple(math.sqrt(12) * statistics.pstdev(O.bodies[i].state.pos[k] for i in ids) + _tablet.D0 for k in (1, 2))


def _plot_compression(rows, snaps, png):
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


FACTOR_VARIANTS = (("full", "loading", "contacts"), ("frictionless", "loading", "contacts"), ("full", "all", "contacts"),
                   ("frictionless", "all", "contacts"), ("full", "loading", "lab"), ("frictionless", "all", "lab"))


def factor_dir(outdir, packing, glue, rel_std=0.05, seed=1):
    """Where the factor study keeps one preparation (its stages and its pulls; quick ones in quick/)."""
    return os.path.join(outdir, "factors", f"{packing}-{glue}" + (f"-std{rel_std:g}" if rel_std != 0.05 else "")
                        + (f"-seed{seed}" if seed != 1 else ""))


def factor_run(outdir, packing, glue, drag, quick=False, progress=True, rel_std=0.05, seed=1):
    """One run of the tablet's factor study: the preparation (packing, glue) made or reused in
    factor_dir(), then the Fig. 17 pull with the drag relative to ``drag``, ended 1 Dx past the
    last chain's break (bundle pull-<drag>; a complete one is read back, so the study resumes).
    ``seed``: another realization of the same preparation (the gas's positions and radii)."""
    out = factor_dir(outdir, packing, glue, rel_std, seed)
    done = os.path.join(root(out, quick), f"pull-{drag}")
    if _out.complete(done):  # made by an earlier job: read back, not repeated
        with open(os.path.join(done, f"pull-{drag}.json")) as f:
            return json.load(f)
    protocol = dict({"packing": packing, "glue": glue, "rel_std": rel_std}, **({"seed": seed} if seed != 1 else {}))
    return pull(out, quick, progress=progress, tag=f"pull-{drag}", protocol=protocol,
                drag=drag, stop_after_last=1.0, until=12.0)


def _stage_numbers(s, L=None):
    return {"solid_fraction": s["solid_fraction"], "coordination": s["coordination"], "rattlers": s["rattlers"],
            "Lx_d0": (L if L is not None else s["side"][0]) / _tablet.D0}


def _factor_row(st, p):
    """One row of the factor study from a preparation's description ``st`` and a pull's ``p``."""
    start = st["unconfined"]["stats"]
    for key in ("planes_at_start", "planes_at_peak"):  # the weakest plane from the counts, by today's rule
        prof = p[key]
        prof.setdefault("length_d0", p["L0"] / _tablet.D0 + (prof.get("Dx") or 0.0))
        prof["weakest"] = _uni.weakest_plane(prof)
    p0 = p["planes_at_start"]
    length = p0["length_d0"]
    near = [c for x, c in zip(p0["x"], p0["count"]) if 0.5 <= x <= 1.5 or length - 1.5 <= x <= length - 0.5]
    bulk = [c for x, c in zip(p0["x"], p0["count"]) if 3 <= x <= length - 3]
    return {"near_wall_mean_at_start": sum(near) / len(near) if near else None,
            "bulk_mean_at_start": sum(bulk) / len(bulk) if bulk else None,
            "packing": st["built"].get("packing", "full"), "glue": st["built"].get("glue", "loading"),
            "rel_std": st["built"].get("rel_std", 0.05), "seed": st["built"].get("seed", 1),
            "drag": p["drag"], "sintered": _stage_numbers(st["sintered"]), "released": _stage_numbers(st["released"]),
            "test_start": _stage_numbers(start, p["L0"]), "L0": p["L0"],
            "peak_tension": -p["max_tension"], "peak_Dx": p["max_tension_Dx"],
            "weakest_at_start": p["planes_at_start"]["weakest"], "mean_at_start": p["planes_at_start"]["mean"],
            "weakest_at_peak": p["planes_at_peak"]["weakest"], "mean_at_peak": p["planes_at_peak"]["mean"],
            "planes_at_peak_Dx": p["planes_at_peak"]["Dx"], "first_gap_Dx_by_area": p["first_gap_Dx_by_area"],
            "last_chain_Dx": p["last_contact_Dx"], "mean_force_after_last_chain": p["mean_force_after_last_contact"],
            "steps": p.get("steps"), "wall_clock_s": p["wall_clock_s"]}


def factor_table(outdir, quick=False):
    """The factor study's table from the files in <outdir>/factors/: one row per pull, with the
    sample after sintering, after release and at the test start, the peak tension, the weakest
    plane at Dx = 0 and at the peak, the first gap (at 0.5, 1 and 2 d0^2), the last chain and the
    force after it. Returns the rows (also factors.json and factors.md in <outdir>/factors/)."""
    import glob
    rows = []
    for prep_dir in sorted(glob.glob(os.path.join(outdir, "factors", "*-*"))):
        pulls = [p for p in sorted(glob.glob(os.path.join(root(prep_dir, quick), "pull-*", "pull-*.json")))
                 if os.path.basename(p) != _out.MANIFEST]
        if not pulls or not os.path.exists(_stages.path("unconfined", prep_dir, quick) + ".json"):
            continue
        with open(_stages.path("unconfined", prep_dir, quick) + ".json") as f:
            st = json.load(f)
        for js in pulls:
            with open(js) as f:
                rows.append(_factor_row(st, json.load(f)))
    fmt = lambda x, f=".3g": "–" if x is None else format(x, f)  # noqa: E731
    md = ["# The tested tablet: the factor study", "",
          "Written by `yade -n -x scripts/tablet_factors.py --out DIR --table` (or `--report DOCS`) from the files under "
          "`factors/` (each preparation's stage descriptions, each pull's CSV and JSON). One row per pull "
          "(Fig. 17's pull at the campaign's speed, ended 1 Dx after the last chain broke). Sample columns: "
          "after sintering / after release / at the test start (L0 between the loading walls; ν and C of the "
          "stage's statistics). Weakest plane: the plane x = const with the fewest contacts in overlap across "
          "it, at least 0.5 d0 from the walls' faces, planes 0.25 d0 apart; n (the mean over the planes); its "
          "distances from the left and right loading walls. First gap at three area thresholds; last chain: "
          "no chain of contacts from wall to wall.", "",
          "| packing | glue | radii std | seed | drag | L0/d0 sint. / rel. / test | ν sint. / rel. / test | C sint. / rel. / test | "
          "rattlers test | crossing contacts at Dx=0: 0.5–1.5 d0 from a wall / bulk (≥ 3 d0) | "
          "peak F/(kp d0) at Dx | weakest plane Dx=0: n (mean), from L / R [d0] | at peak | "
          "first gap Dx (0.5 / 1 / 2 d0²) | last chain Dx | F after /(kp d0) |", "|" + "---|" * 16]
    for r in rows:
        s3 = [r["sintered"], r["released"], r["test_start"]]
        w0, wp = r["weakest_at_start"], r["weakest_at_peak"]
        g = r["first_gap_Dx_by_area"]
        md.append(f"| {r['packing']} | {r['glue']} | {r['rel_std']:g} | {r.get('seed', 1)} | {r['drag']} | " + " / ".join(fmt(s['Lx_d0'], '.4g') for s in s3)
                  + " | " + " / ".join(fmt(s["solid_fraction"]) for s in s3) + " | "
                  + " / ".join(fmt(s["coordination"]) for s in s3) + f" | {r['test_start']['rattlers']} | "
                  f"{fmt(r['near_wall_mean_at_start'], '.0f')} / {fmt(r['bulk_mean_at_start'], '.0f')} | "
                  f"{fmt(r['peak_tension'], '.4g')} at {fmt(r['peak_Dx'], '.3f')} | "
                  f"{w0['count']} ({r['mean_at_start']:.0f}), {w0['from_left_d0']:.2f} / {w0['from_right_d0']:.2f} | "
                  f"{wp['count']} ({r['mean_at_peak']:.0f}), {wp['from_left_d0']:.2f} / {wp['from_right_d0']:.2f} | "
                  + " / ".join(fmt(g.get(k), ".2f") for k in sorted(g, key=float)) + f" | {fmt(r['last_chain_Dx'], '.2f')} | "
                  f"{fmt(r['mean_force_after_last_chain'], '.2g')} |")
    md += ["", "Against the criteria of the tested sample (L0 = 0.115 within 1 %; weakest plane at the peak at "
           "least 3 d0 from both loading walls; first gap 0.6–1.4; last chain 6–10):", ""]
    for r in rows:
        w = r["weakest_at_peak"]
        checks = {"L0": abs(r["L0"] / 0.115 - 1) <= 0.01, "bulk rupture": min(w["from_left_d0"], w["from_right_d0"]) >= 3,
                  "first gap": r["first_gap_Dx_by_area"].get("1") is not None and 0.6 <= r["first_gap_Dx_by_area"]["1"] <= 1.4,
                  "last chain": r["last_chain_Dx"] is not None and 6 <= r["last_chain_Dx"] <= 10}
        md.append(f"- {r['packing']}, {r['glue']}, radii std {r['rel_std']:g}, seed {r.get('seed', 1)}, {r['drag']}: " + ", ".join(f"{k} {'✓' if v else '✗'}" for k, v in checks.items())
                  + f" (L0 {100 * (r['L0'] / 0.115 - 1):+.2f} %)")
    md += ["", "What each factor does (pairs of runs that differ in it alone): L0/d0 at the test start; the "
           "weakest plane at the peak, its distance from the nearer loading wall [d0]; first gap; last chain.", ""]
    names = ("packing", "glue", "rel_std", "seed", "drag")
    key = lambda r: tuple(r.get(n, 1) for n in names)  # noqa: E731  (seed: 1 in rows made before the option)
    for k, name in enumerate(names):
        for a in rows:
            for b in rows:
                ka, kb = key(a), key(b)
                if ka[k] < kb[k] and all(ka[j] == kb[j] for j in range(len(names)) if j != k):
                    def say(r):
                        w = r["weakest_at_peak"]
                        return (f"{r.get(name, 1)}: L0 {r['L0'] / _tablet.D0:.3f}, weakest plane "
                                f"{min(w['from_left_d0'], w['from_right_d0']):.2f} from a wall, first gap "
                                f"{fmt(r['first_gap_Dx_by_area'].get('1'), '.2f')}, last chain {fmt(r['last_chain_Dx'], '.2f')}")
                    others = ", ".join(f"{n} {v:g}" if isinstance(v, float) else f"{n} {v}"
                                       for j, (n, v) in enumerate(zip(names, ka)) if j != k)
                    md.append(f"- {name} ({others}): {say(a)} | {say(b)}")
    base = os.path.join(outdir, "factors", "quick" if quick else "")
    os.makedirs(base, exist_ok=True)
    _out.write_atomic(os.path.join(base, "factors.json"), json.dumps(rows, indent=1))
    _out.write_atomic(os.path.join(base, "factors.md"), "\n".join(md) + "\n")
    return rows


def factor_report(outdir, docsdir):
    """Copies the factor study's files (each preparation's stage descriptions; each pull's CSV,
    JSON and force plot) from <outdir>/factors/ to <docsdir>/factors/, in the same layout, and
    writes the table there from the copies (factor_table(docsdir))."""
    import glob
    import shutil
    for prep_dir in sorted(glob.glob(os.path.join(outdir, "factors", "*-*"))):
        dest = os.path.join(docsdir, "factors", os.path.basename(prep_dir))
        os.makedirs(dest, exist_ok=True)
        for f in glob.glob(os.path.join(prep_dir, "*.yade.gz.json")):
            shutil.copy(f, dest)
        for bundle in sorted(glob.glob(os.path.join(prep_dir, "pull-*"))):
            if not _out.complete(bundle):
                continue
            os.makedirs(os.path.join(dest, os.path.basename(bundle)), exist_ok=True)
            tag = os.path.basename(bundle)
            for ext in ("csv", "json", "png"):
                shutil.copy(os.path.join(bundle, f"{tag}.{ext}"), os.path.join(dest, tag))
    return factor_table(docsdir)


def _plot_pull(rows, events, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    ax.plot([r[1] for r in rows], [r[2] for r in rows], lw=0.8)
    for key, style in (("first_gap_Dx", "g--"), ("see_through_Dx", "b--"), ("last_contact_Dx", "r--")):
        if events[key] is not None:
            ax.axvline(events[key], color=style[0], ls="--", lw=0.8, label=key.replace("_", " "))
    for s in events["snapshots"]:
        ax.plot(s["Dx"], s["F"], "ko", ms=3)
    ax.set_xlabel("Dx = (L - L0)/d0")
    ax.set_ylabel("F/(kp d0)  [compressive > 0]")
    if ax.get_legend_handles_labels()[0]:  # no empty box when no event was reached (or taken)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=130)
    plt.close(fig)


FIGURES = ("prepare", "drag", "timestep", "rates", "fig16", "fig17", "fig18", "fig19", "factors")
MPI_FIGURES = ("fig16", "fig17", "fig18")


def parse_args(figure, argv):
    """The checked options of a tablet script: argparse's error (SystemExit 2, the option named)
    for any value outside its range, an unwritable --out included, before any work starts.
    Returns (namespace, amplitudes, slow_amplitudes, periods)."""
    import argparse
    if figure not in FIGURES:
        raise ValueError(f"figure = {figure!r} is invalid: one of {FIGURES}")
    p = argparse.ArgumentParser(prog=f"yade -n -x scripts/tablet_{figure}.py",
                                description=f"Appendix F, {figure}: writes CSV, JSON, PNG (and VTK) into --out.")
    p.add_argument("--quick", action="store_true", help="216 particles, one cycle (for tests)")
    p.add_argument("--out", default="results/tablet", help="output directory (the cached states are reused from it)")
    default_periods = {"rates": RATE_PERIODS, "fig19": (FAST,), "fig16": PERIODS["tension"]}.get(figure, (FAST, SLOW))
    p.add_argument("--periods", default=",".join(f"{x:g}" for x in default_periods),
                   help="comma-separated cycle periods in elastic crossing times (the first drawn thin)")
    p.add_argument("--amplitudes", default=None, help="comma-separated amplitudes Dx in d0")
    p.add_argument("--slow-amplitudes", default=None,
                   help="fig16, fig18: comma-separated amplitudes that also run at the slower periods (default: all)")
    p.add_argument("--no-run", action="store_true", help="rates: only the periods whose runs are complete")
    p.add_argument("--speed", type=float, default=PULL_SPEED, help="fig17: wall speed [mm/us]")
    p.add_argument("--until", type=float, default=None,
                   help="fig17: pull until Dx = UNTIL (default 9); fig19: compress until Dx = -UNTIL (default 3) (in d0)")
    p.add_argument("--factors", default=None,
                   help="timestep: comma-separated multiples of the campaign's time step (default 1,2,3,4 and the perturbed 1.000001, 1.000002, 0.999999)")
    p.add_argument("--runs", default=None, help="timestep: comma-separated runs of tension, compression, pull (default all)")
    p.add_argument("--material", default="appendixF", choices=sorted(_tablet.MATERIALS),
                   help="prepare: particle parameters, Appendix F of the long paper or Table 2 of Luding 2008")
    p.add_argument("--kc-over-kp", type=float, default=None, help="prepare: overrides the set's kc/kp")
    p.add_argument("--n", type=int, default=None, help="prepare: number of particles (1728; 216 with --quick)")
    p.add_argument("--packing", default="full", choices=_tablet.PACKINGS,
                   help="factors: the law while the gas is compacted (full; frictionless: without friction and adhesion)")
    p.add_argument("--glue", default="loading", choices=_tablet.GLUES,
                   help="factors: the walls made adhesive after sintering (loading: the two x walls; all: six)")
    p.add_argument("--rel-std", type=float, default=0.05,
                   help="factors: relative standard deviation of the radii (Gaussian, cut at 2 sigma; default 0.05)")
    p.add_argument("--seed", type=int, default=1,
                   help="factors: the random seed of the gas (positions and radii): another realization of the preparation")
    p.add_argument("--drag", default="contacts", choices=("contacts", "lab"),
                   help="factors: the background drag's reference in the pull")
    p.add_argument("--table", action="store_true", help="factors: only gather the table of the runs made")
    p.add_argument("--report", default=None, metavar="DOCS",
                   help="factors: copy the study's files to DOCS/factors/ and write the table there from them")
    p.add_argument("--mpi", type=int, default=None, metavar="N",
                   help="fig16, fig17, fig18: run under yade.mpy on N ranks (start with `mpiexec -n N yade -j1 -n -x ...`;"
                        " fig17 without crack events and snapshots)")
    a = p.parse_args(argv)
    if a.mpi is not None and figure not in MPI_FIGURES:
        p.error(f"--mpi {a.mpi}: only {', '.join(MPI_FIGURES)} run under yade.mpy (not {figure})")
    if a.mpi is not None and a.mpi < 2:
        p.error(f"--mpi {a.mpi} is invalid: a master and at least one worker (N >= 2)")
    if a.mpi is not None:
        try:
            use_mpi(a.mpi)
        except ValueError as e:
            p.error(str(e))
    n = a.n or (_stages.QUICK_N if a.quick else FULL["n"])
    if not 8 <= n <= 10 ** 6:
        p.error(f"--n {n} is invalid: between 8 and 1000000 particles")
    side = n ** (1 / 3)  # the sample's length in d0, roughly
    mode = {"fig18": "compression", "fig19": "compression"}.get(figure, "tension")
    amps = _numbers(p, "--amplitudes", a.amplitudes, 0, 0.5 * side if mode == "compression" else side,
                    f"a {mode} amplitude in d0 (the sample is about {side:.3g} d0 long)") if a.amplitudes else None
    slow = _numbers(p, "--slow-amplitudes", a.slow_amplitudes, 0, side, "an amplitude in d0") if a.slow_amplitudes else None
    a.factors = _numbers(p, "--factors", a.factors, 0, 10, "a multiple of the campaign's time step") if a.factors else None
    a.runs = tuple(a.runs.split(",")) if a.runs else None
    if a.runs and not set(a.runs) <= set(TIMESTEP_RUNS):
        p.error(f"--runs {','.join(a.runs)}: each must be one of {', '.join(TIMESTEP_RUNS)}")
    periods = _numbers(p, "--periods", a.periods, 1, 1e5, "a cycle period in elastic crossing times (about 320 steps each)")
    _numbers(p, "--speed", str(a.speed), 0, 0.2, "a wall speed in mm/us (the sound speed is about 22)")
    if a.until is not None:
        _numbers(p, "--until", str(a.until), 0, 1e3, "the final Dx of the pull or compression in d0")
    if a.kc_over_kp is not None and not (math.isfinite(a.kc_over_kp) and 0 <= a.kc_over_kp <= 100):
        p.error(f"--kc-over-kp {a.kc_over_kp} is invalid: must lie in [0, 100]")
    try:  # an unwritable --out fails now, not after the computation
        os.makedirs(a.out, exist_ok=True)
        with tempfile.NamedTemporaryFile(dir=a.out, prefix=".writable-"):
            pass  # a name of its own: two jobs sharing --out must not remove each other's probe
    except OSError as e:
        p.error(f"--out {a.out}: not writable ({e.strerror})")
    return a, amps, slow, periods


def main(figure, argv):
    """Command line of the tablet scripts (prepare, rates, fig16 ... fig19)."""
    a, amps, slow, periods = parse_args(figure, argv)
    if _MPY is None:
        return _main(figure, a, amps, slow, periods)
    _mpi.run_ranks(_MPY, lambda: _main(figure, a, amps, slow, periods))


def _main(figure, a, amps, slow, periods):
    if is_master():
        _out.sweep(a.out)
    t0 = time.time()
    if figure == "prepare":
        info = prepare(a.out, a.quick, material=a.material, kc_over_kp=a.kc_over_kp, n=a.n)
        out = {k: info[k] for k in ("compacted", "sintered", "released", "unconfined") if k in info}
    elif figure == "drag":
        out = drag_share(a.out, a.quick)
    elif figure == "timestep":
        out = timestep_study(a.out, a.quick, factors=a.factors or TIMESTEP_FACTORS + (PERTURBED,) + PERTURBED_MORE,
                             runs=a.runs or TIMESTEP_RUNS)
    elif figure == "rates":
        out = rates(a.out, a.quick, amplitude=(amps or (0.2,))[0], periods=periods, run_missing=not a.no_run)
    elif figure in ("fig16", "fig18"):
        out = cyclic("tension" if figure == "fig16" else "compression", a.out, amps, a.quick, periods,
                     slow_amplitudes=slow)
    elif figure == "fig19":
        out = large_compression(a.out, a.quick, speed=a.speed, until=a.until or 3.0)
    elif figure == "fig17":
        out = pull(a.out, a.quick, speed=a.speed, until=a.until or 9.0)
    elif figure == "factors":
        if a.report:
            out = factor_report(a.out, a.report)
        else:
            if not a.table:
                factor_run(a.out, a.packing, a.glue, a.drag, a.quick, rel_std=a.rel_std, seed=a.seed)
            out = factor_table(a.out, a.quick)
    else:
        raise ValueError(f"figure = {figure!r} is invalid")
    if not is_master():
        return
    print(json.dumps(out, indent=1, default=str)[:4000])
    print(f"{figure} done in {time.time() - t0:.0f} s; outputs in {os.path.abspath(a.out)}", flush=True)


def _numbers(parser, option, text, low, high, what):
    """Comma-separated numbers in (low, high], or the parser's error naming the option."""
    values = []
    for x in text.split(","):
        try:
            v = float(x)
        except ValueError:
            parser.error(f"{option} {text}: {x!r} is not a number")
        if not (math.isfinite(v) and low < v <= high):
            parser.error(f"{option} {text}: {x} is invalid: must lie in ({low:g}, {high:g}], {what}")
        values.append(v)
    return tuple(values)


def peaks_table(runs):
    """Markdown table of cyclic runs (their JSON descriptions with final_F, the last row's force):
    peak force of every cycle, the force back at Dx = 0, the cost."""
    out = ["| run | period [t_w] | peak F/(kp d0), cycles 1-4 | F at the end (Dx = 0) | steps | ms per step | wall-clock |",
           "|---|---|---|---|---|---|---|"]
    key = lambda r: (r["mode"], r["amplitude"], r["period_crossings"])  # noqa: E731
    for r in sorted(runs, key=key):
        out.append(f"| {r['name']} | {r['period_crossings']:g} | " + ", ".join(f"{x:.4f}" for x in r["peaks"])
                   + f" | {r['final_F']:+.4f} | {r['steps']} | {r['ms_per_step']:.2f} | "
                   f"{r['wall_clock_s'] / 60:.1f} min |")
    return "\n".join(out) + "\n"


def restore(docsdir, outdir):
    """The inverse of ``report`` for the runs: every run copied into ``docsdir`` (a JSON naming
    itself, with peaks, and its CSV) becomes the committed bundle runs/<name>/ in ``outdir``
    again, so that a fresh clone regathers the figures and peaks.md without repeating runs of
    hours. A run is restored only if the peaks recomputed from its CSV equal the JSON's; a
    complete bundle already there is left as it is. Returns the names restored."""
    import glob
    restored = []
    for js in sorted(glob.glob(os.path.join(docsdir, "*.json"))):
        name = os.path.basename(js)[:-5]
        with open(js) as f:
            info = json.load(f)
        csv_path = js[:-5] + ".csv"
        if not (isinstance(info, dict) and info.get("name") == name and "peaks" in info and os.path.exists(csv_path)):
            continue
        where = run_dir(outdir, name, info.get("quick", False))
        if _out.complete(where):
            continue
        rows = read_csv(csv_path)
        if cycle_peaks(info["mode"], rows, info["steps_per_cycle"]) != info["peaks"]:
            raise ValueError(f"restore: {csv_path} does not give the peaks of {js}")
        with _out.Bundle(where) as b:
            b.copy_from(docsdir, only=(name + ".csv", name + ".json"))
        restored.append(name)
    return restored


def report(outdir, docsdir):
    """Copies a campaign's data and figures (CSV, JSON, PNG; not the saved states or VTK) from
    ``outdir`` into ``docsdir``: the stages' descriptions, every complete bundle (runs/*, the
    figures) flattened, the snapshot series side by side (fig17-snapshots.png,
    fig19-snapshots.png) and the states of the kc study (kc-*/) in one table (kc-study.csv)."""
    import glob
    import shutil
    os.makedirs(docsdir, exist_ok=True)
    for f in glob.glob(os.path.join(outdir, "*.yade.gz.json")):
        shutil.copy(f, docsdir)
    bundles = sorted(glob.glob(os.path.join(outdir, "runs", "*"))) + sorted(
        d for d in glob.glob(os.path.join(outdir, "*")) if os.path.isdir(d) and _out.complete(d))
    for d in bundles:
        if not _out.complete(d):
            print(f"report: {d} is incomplete, left out", flush=True)
            continue
        for f in os.listdir(d):
            if f.rsplit(".", 1)[-1] in ("csv", "json", "png") and f != _out.MANIFEST:
                shutil.copy(os.path.join(d, f), docsdir)
    for name in ("campaign-plan.json", "campaign-time.json"):  # the campaign's cost, planned and measured
        if os.path.exists(os.path.join(outdir, name)):
            shutil.copy(os.path.join(outdir, name), docsdir)
    for fig, tag in (("fig17", "fig17"), ("fig19", "fig19")):
        pngs = sorted(glob.glob(os.path.join(outdir, fig, f"{tag}-[0-9][0-9].png")))
        if pngs:
            titles = None
            js = os.path.join(outdir, fig, fig + ".json")
            if os.path.exists(js):
                with open(js) as f:
                    snaps = json.load(f).get("snapshots") or []
                if len(snaps) == len(pngs):
                    titles = [f"Dx = {x['Dx']:.2f}" for x in snaps]
            _snap.montage(pngs, os.path.join(docsdir, fig + "-snapshots.png"), ncols=4 if len(pngs) > 6 else 3,
                          titles=titles)
    runs = []
    for js in sorted(glob.glob(os.path.join(outdir, "runs", "*", "*.json"))):
        if os.path.basename(js) != _out.MANIFEST and _out.complete(os.path.dirname(js)):
            with open(js) as f:
                info = json.load(f)
            csv_path = js[:-5] + ".csv"
            if "peaks" in info and os.path.exists(csv_path):
                info["final_F"] = read_csv(csv_path)[-1][2]
                runs.append(info)
    if runs:
        _out.write_atomic(os.path.join(docsdir, "peaks.md"), peaks_table(runs))
    rows = []
    for js in sorted(glob.glob(os.path.join(outdir, "kc-*", "released.yade.gz.json"))):
        with open(js) as f:
            info = json.load(f)
        for stage in ("sintered", "released"):
            s = info[stage]
            rows.append([info["built"]["material"], info["built"]["kc_over_kp"], stage, s["solid_fraction"], s["coordination"],
                         s["coordination_with_walls"], s["rattlers"], s["kinetic_energy_ratio"]]
                        + [s["wall_stress"][w] for w in _tablet.WALLS] + s["side"])
    if rows:
        _out.write_atomic(os.path.join(docsdir, "kc-study.csv"),
                          "material,kc_over_kp,stage,solid_fraction,coordination,coordination_with_walls,rattlers,"
                          "kinetic_energy_ratio," + ",".join(f"stress_{w}" for w in _tablet.WALLS) + ",Lx,Ly,Lz\n"
                          + "".join(",".join(str(x) for x in r) + "\n" for r in rows))
    return rows


def _job_steps(figure, cells, t_cross, dt0):
    """Steps of one campaign job (a table line's figure and cells), each test at its time step
    (dt0 times DT_FACTORS)."""
    import ast

    def numbers(key, default):
        v = cells.get(key)
        v = ast.literal_eval(v) if v not in (None, "None") else None
        return tuple(float(x) for x in str(v).split(",")) if v is not None else default

    cycle = lambda period, mode: int(round(period * t_cross / (dt0 * DT_FACTORS[mode])))  # noqa: E731
    if figure in ("fig16", "fig18"):
        mode = "tension" if figure == "fig16" else "compression"
        amps = numbers("amplitudes", TENSION_AMPLITUDES if mode == "tension" else COMPRESSION_AMPLITUDES)
        return sum(FULL["cycles"] * cycle(p, mode) for _ in amps for p in numbers("periods", PERIODS[mode]))
    if figure == "fig19":
        until, speed = numbers("until", (3.0,))[0], numbers("speed", (PULL_SPEED,))[0]
        return int(until * _tablet.D0 / (2 * speed * dt0 * DT_FACTORS["pull"]))
    if figure == "fig17":
        until, speed = numbers("until", (9.0,))[0], numbers("speed", (PULL_SPEED,))[0]
        return int(until * _tablet.D0 / (2 * speed * dt0 * DT_FACTORS["pull"]))
    if figure == "drag":
        return 3 * int(round(FAST * t_cross / dt0))  # drag_share runs at the campaign's base step
    if figure == "rates":
        return sum(FULL["cycles"] * cycle(p, m) for p in numbers("periods", RATE_PERIODS) for m in _uni.MODES)
    return 0  # prepare and the rest: minutes, not counted


JOBS_LOG = "jobs.jsonl"


def log_job(outdir, job, figure, start, end):
    """Appends one finished campaign job to <outdir>/jobs.jsonl: its name (the table line's
    description when yade-batch ran it), figure, start and end (epoch s), job time and the
    steps its tests ran (uniaxial.Test.steps_run)."""
    try:
        job = O.tags["description"] or job
    except KeyError:
        pass
    rec = {"job": job, "figure": figure, "start": start, "end": end, "seconds": end - start,
           "steps": _uni.Test.steps_run}
    os.makedirs(outdir, exist_ok=True)
    with open(os.path.join(outdir, JOBS_LOG), "a") as f:  # one short line per write: appends do not interleave
        f.write(json.dumps(rec) + "\n")


def totals(outdir, since=None, lanes=None, progress=True):
    """The measured time of a campaign from <outdir>/jobs.jsonl (jobs that started at or after
    ``since``, epoch s): each job's time and steps, their sum (single-job time), the wall time
    from the first start to the last end, and the mean ms per step. Prints it; returns it."""
    with open(os.path.join(outdir, JOBS_LOG)) as f:
        jobs = [json.loads(ln) for ln in f if ln.strip()]
    jobs = [j for j in jobs if since is None or j["start"] >= since]
    if not jobs:
        raise ValueError(f"totals: no job in {os.path.join(outdir, JOBS_LOG)}" + (f" since {since}" if since else ""))
    seconds, steps = sum(j["seconds"] for j in jobs), sum(j["steps"] for j in jobs)
    out = {"jobs": jobs, "single_job_hours": seconds / 3600, "steps": steps,
           "wall_hours": (max(j["end"] for j in jobs) - min(j["start"] for j in jobs)) / 3600,
           "ms_per_step": 1e3 * seconds / steps if steps else None, "lanes": lanes}
    if progress:
        for j in sorted(jobs, key=lambda j: j["start"]):
            print(f"  {j['job']:20s} {j['figure']:8s} {j['steps']:>10,d} steps  {j['seconds'] / 3600:5.2f} h", flush=True)
        print(f"total: {len(jobs)} jobs, {steps:,d} steps, {out['single_job_hours']:.2f} h of job time"
              + (f" ({out['ms_per_step']:.2f} ms/step)" if steps else "")
              + f", {out['wall_hours']:.2f} h of wall time" + (f" on {lanes} lanes" if lanes else ""), flush=True)
    return out


def plan(table, outdir, lanes=2, progress=True):
    """The plan of a campaign table before it runs: each job's steps at the campaign's time step,
    the ms per step measured on the unconfined start (300 steps, walls at rest), the estimated
    hours of each job, their sum (single-job time) and the wall time on ``lanes`` lanes taking
    the longest job first. Prints it; returns it."""
    prepare(outdir, False, progress)
    test = _uni.Test(progress=False)
    O.run(20, True)
    t0, n = time.time(), 300
    O.run(n, True)
    ms = 1e3 * (time.time() - t0) / n
    jobs = []
    with open(table) as f:
        lines = [ln.split() for ln in f if ln.strip() and not ln.lstrip().startswith("#")]
    head = lines[0]
    for cells in lines[1:]:
        c = dict(zip(head, cells))
        figure = c["figure"].strip("'\"")
        steps = _job_steps(figure, c, test.t_cross, O.dt)
        jobs.append({"job": c["description"], "figure": figure, "steps": steps, "hours": steps * ms / 3.6e6})
    finish = [0.0] * lanes
    for j in sorted(jobs, key=lambda j: -j["hours"]):
        k = finish.index(min(finish))
        finish[k] += j["hours"]
    out = {"table": table, "dt": O.dt, "ms_per_step": ms, "jobs": jobs, "single_job_hours": sum(j["hours"] for j in jobs),
           "lanes": lanes, "wall_hours_estimate": max(finish)}
    if progress:
        for j in jobs:
            print(f"  {j['job']:20s} {j['figure']:8s} {j['steps']:>10,d} steps  {j['hours']:5.2f} h", flush=True)
        print(f"plan: {len(jobs)} jobs, {sum(j['steps'] for j in jobs):,d} steps at {ms:.2f} ms/step (measured): "
              f"{out['single_job_hours']:.2f} h of single-job time, about {out['wall_hours_estimate']:.2f} h on {lanes} lanes",
              flush=True)
    return out
