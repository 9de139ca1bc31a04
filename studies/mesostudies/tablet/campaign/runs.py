"""The tablet campaign's runs: the cyclic tests and the rate study (Figs. 16 and 18), the time-step
study, the drag share, the pull (Fig. 17), the large compression (Fig. 19) and the factor study's
pulls (inside ``yade``)."""
import json
import os
import time

from yade import O
from yade import wrapper as _w

from mesocontact import mpi as _mpi
from mesocontact import outputs as _out
from mesocontact import scene as _scene
from .. import snapshots as _snap
from .. import sample
from .. import uniaxial as _uni
from .common import (
    COMPRESSION_AMPLITUDES, DT_FACTORS, FAST, FIG17_DX, FULL, GAP_AREA, PERIODS, PROTOCOL,
    PULL_SPEED, QUICK, RATE_PERIODS, TENSION_AMPLITUDES, csv_text, protocol_of, cycle_peaks, stroke_peaks,
    is_master, mpy as _mpy, prepare, read_csv, root, run_dir, run_name,
)
from .plots import plot_compression, plot_cycles, plot_pull, plot_rates


def new_test(progress, grips=None, members=None):
    """The uni-axial test on the loaded start, serially or, under yade.mpy, split over the ranks
    (the master records, every rank follows its decisions). Returns (test, f0): f0 the first
    row's force under mpy, read before the split clears the master's forces; None serially.
    ``grips``: load through glued particles of this thickness [d0] instead of the flat walls
    (uniaxial.Test.use_grips; serially only), their sizes in ``test.grips``."""
    if grips is not None and _mpy() is not None:
        raise ValueError("grips: without yade.mpy (the grips' force is summed over particles on every rank)")
    if _mpy() is None:
        test = _uni.Test(progress=progress)
        if grips is not None:
            test.use_grips(grips, members)
        return test, None
    test = _uni.Test(progress=progress, run=lambda n: _mpy().mpirun(n), records=_mpy().rank == 0,
                     share=lambda x: _mpy().comm.bcast(x, root=0))
    f0 = test.force()
    _mpi.split_slabs(_mpy())
    return test, f0


RETURNS = ("length", "force")  # where a tension cycle turns back: at Dx = 0, or at the start's force (E6)


def variant_prefix(returns="length", kc_over_kp=None, grips=None):
    """The name prefix of the cyclic runs of a test variant (none for the campaign's cycles)."""
    if returns not in RETURNS:
        raise ValueError(f"returns = {returns!r} is invalid: one of {RETURNS}")
    return ((f"grips{grips:g}-" if grips is not None else "") + (f"kc{kc_over_kp:g}-" if kc_over_kp is not None else "")
            + ("force-return-" if returns == "force" else ""))


def run_cycles(outdir, mode, amplitude, period, quick=False, progress=True, prefix="", dt_factor=None,
               energy=False, cycles=None, protocol=None, returns="length", kc_over_kp=None, grips=None,
               checkpoint=False):
    """One cyclic run (the campaign's cycle count, period in crossing times) from the unconfined
    start: writes ``<name>.csv`` (iter, Dx, F/(kp d0)) and ``<name>.json`` (the run's
    description, peaks per cycle) in the bundle runs/<name>/. A complete bundle made from the
    campaign's PROTOCOL is read back, not repeated. ``dt_factor`` scales tablet.contact_step (default
    DT_FACTORS[mode]); ``energy`` adds the energy balance of the run (uniaxial.Test.energy_balance)
    to the JSON; ``cycles`` overrides the campaign's cycle count; ``protocol``: preparation options
    that differ from PROTOCOL (tablet.prepare's sinter, seed, ...). Test variants on the same
    state (named by variant_prefix, recorded in the JSON): ``returns='force'``, tension cycles
    that turn back at the start's force (uniaxial.Test.force_cycles) instead of at Dx = 0;
    ``kc_over_kp``, the particles' kc/kp changed on the unconfined start, every contact keeping
    its history (sample.set_tensile_stiffness); ``grips``, loaded through glued particles of this
    thickness [d0] instead of the flat walls (uniaxial.Test.use_grips). ``checkpoint``: the cycles
    saved after every quarter cycle beside the bundle (<name>.checkpoint.yade.gz; uniaxial.Test's
    checkpoint), and a run found saved there goes on from its save; such a run is the same bit for
    bit wherever its processes stopped, and the same to rounding as one without saves (serial
    cosine cycles only). Returns (description, rows)."""
    proto = dict(PROTOCOL, **(protocol or {}))
    if returns == "force" and (mode != "tension" or _mpy() is not None):
        raise ValueError("returns = 'force': tension cycles only, without yade.mpy")
    if checkpoint and (returns == "force" or _mpy() is not None or kc_over_kp is not None or grips is not None):
        raise ValueError("checkpoint: the plain cosine cycles in one process only (not returns = 'force', "
                         "kc_over_kp, grips, yade.mpy)")
    prefix = variant_prefix(returns, kc_over_kp, grips) + prefix
    name = run_name(mode, amplitude, period, prefix)
    where = run_dir(outdir, name, quick)
    if _out.complete(where):
        with open(os.path.join(where, name + ".json")) as f:
            info = json.load(f)
        if protocol_of(info) == proto:
            return info, read_csv(os.path.join(where, name + ".csv"))
        if progress:
            print(f"{name}: the run in {where} was made from another preparation ({protocol_of(info)}): made again",
                  flush=True)
    n_cycles = cycles or (QUICK if quick else FULL)["cycles"]
    t0 = time.time()
    dt_factor = DT_FACTORS[mode] if dt_factor is None else dt_factor
    saved = os.path.join(os.path.dirname(where), name + ".checkpoint.yade.gz") if checkpoint else None
    if saved and os.path.exists(saved + ".json"):
        return _resumed(saved, name, where, mode, amplitude, period, quick, n_cycles, dt_factor, proto, energy,
                        progress, t0)
    prepare(outdir, quick, progress and is_master(), **(protocol or {}))
    O.dt *= dt_factor
    bundle = _out.Bundle(where) if is_master() else None
    variant = {}
    if kc_over_kp is not None:
        variant["tensile_stiffness"] = sample.set_tensile_stiffness(kc_over_kp)
    try:
        test, f0 = new_test(progress, grips)
        if grips is not None:
            variant["grips"] = test.grips
        if energy:
            test.track_energy()
        if saved:
            rows = test.cycles(mode, amplitude, n_cycles=n_cycles, period=period, checkpoint=saved)
        elif returns == "force":
            rows = test.force_cycles(amplitude, n_cycles=n_cycles, period=period)
            variant["returns"] = "force"
            variant["turns"] = test.turns
        else:
            rows = test.cycles(mode, amplitude, n_cycles=n_cycles, period=period)
        if _mpy() is not None:
            rows = _mpy().comm.bcast(rows, root=0)  # the master's rows: one result on every rank
            rows[0] = (*rows[0][:2], f0)
    except BaseException:
        if bundle is not None:
            bundle.discard()
        raise
    info = _description(name, mode, amplitude, period, quick, n_cycles, test, rows, t0, dt_factor, proto, variant,
                        returns)
    if saved:
        info["checkpoint"] = "saved every quarter cycle"
    if energy:
        info["energy_balance"] = test.energy_balance()
    if bundle is None:
        return info, rows
    return _written(bundle, name, info, rows, test, progress)


def _description(name, mode, amplitude, period, quick, n_cycles, test, rows, t0, dt_factor, proto, variant,
                 returns="length"):
    return {"name": name, "mode": mode, "amplitude": amplitude, "period_crossings": period, "cycles": n_cycles,
            "quick": quick, "steps_per_cycle": test.steps_per_cycle, "dt": O.dt, "t_cross": test.t_cross,
            "L0": test.L0, "final_Dx": rows[-1][1], "max_abs_Dx": max(abs(r[1]) for r in rows),
            "F_range": [min(r[2] for r in rows), max(r[2] for r in rows)],
            "peaks": (stroke_peaks(rows, test.turns) if returns == "force"
                      else cycle_peaks(mode, rows, test.steps_per_cycle)),
            "wall_clock_s": time.time() - t0,
            "steps": O.iter - rows[0][0], "ms_per_step": 1e3 * (time.time() - t0) / max(1, O.iter - rows[0][0]),
            "mpi_ranks": _mpy().numThreads if _mpy() else 1, "dt_factor": dt_factor, "final_F": rows[-1][2],
            "protocol": proto, **variant}


def _resumed(saved, name, where, mode, amplitude, period, quick, n_cycles, dt_factor, proto, energy, progress, t0):
    """A run_cycles run found saved (its checkpoint): loaded, finished, written as run_cycles does."""
    test = _uni.Test.load(saved)
    test.progress = progress
    if progress:
        print(f"{name}: resumed at step {O.iter} from {saved}", flush=True)
    it = O.iter
    rows = test.resume(saved)
    info = _description(name, mode, amplitude, period, quick, n_cycles, test, rows, t0, dt_factor, proto, {})
    info.update(checkpoint="saved every quarter cycle", resumed_at_step=it,
                wall_clock_s_note="of the last process only (from its resume)")
    if energy:
        info["energy_balance"] = test.energy_balance()
    return _written(_out.Bundle(where), name, info, rows, test, progress)


def _written(bundle, name, info, rows, test, progress):
    with bundle:
        bundle.write_text(name + ".csv", csv_text(rows))
        bundle.write_text(name + "-branches.csv", csv_text(test.branches, "iter,Dx," + ",".join(_scene.BRANCHES)))
        bundle.write_json(name + ".json", info)
    if progress:
        print(f"{name}: {info['wall_clock_s']:.0f} s, peaks {['%.4g' % x for x in info['peaks']]}", flush=True)
    return info, rows


def cyclic(mode, outdir, amplitudes=None, quick=False, periods=None, progress=True, slow_amplitudes=None,
           protocol=None, returns="length", kc_over_kp=None, grips=None):
    """Fig. 16 (tension) or Fig. 18 (compression): cycles at each amplitude and period (crossing
    times, default PERIODS[mode]; thin lines the first, thick the others; the slower periods
    only for ``slow_amplitudes`` when given; ``protocol``, ``returns``, ``kc_over_kp``, ``grips`` as in
    run_cycles); writes the figure's bundle (fig16 or fig18, a variant's with its prefix)."""
    _uni.check_mode(mode)
    amplitudes = tuple(amplitudes or (TENSION_AMPLITUDES if mode == "tension" else COMPRESSION_AMPLITUDES))
    periods = tuple(periods or PERIODS[mode])
    runs, data = {}, {}
    for amplitude in amplitudes:
        for k, period in enumerate(periods):
            if k > 0 and slow_amplitudes is not None and amplitude not in slow_amplitudes:
                continue
            info, rows = run_cycles(outdir, mode, amplitude, period, quick, progress, protocol=protocol,
                                    returns=returns, kc_over_kp=kc_over_kp, grips=grips)
            runs[info["name"]] = info
            data[info["name"]] = rows
    fig = variant_prefix(returns, kc_over_kp, grips) + ("fig16" if mode == "tension" else "fig18")
    summary = {"mode": mode, "quick": quick, "periods_crossings": list(periods), "amplitudes": list(amplitudes),
               "runs": runs, "wall_clock_s": sum(r["wall_clock_s"] for r in runs.values())}
    if not is_master():
        return summary
    with _out.Bundle(os.path.join(root(outdir, quick), fig)) as b:
        for name in runs:
            b.copy_from(run_dir(outdir, name, quick))
        b.write_json(fig + ".json", summary)
        plot_cycles(mode, amplitudes, periods, runs, data, b.path(fig + ".png"), quick, variant=", ".join(
            ([f"kc/kp = {kc_over_kp:g} on the same sample"] if kc_over_kp is not None else [])
            + ([f"loaded through glued particles ({grips:g} d0) instead of walls"] if grips is not None else [])
            + (["back to the start's force"] if returns == "force" else [])))
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
                row[f"change_P{p1:g}_P{p2:g}"] = (abs(peaks[p1][c] / peaks[p2][c] - 1) if p1 in peaks and p2 in peaks
                                                  else "")
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
        plot_rates(table, periods, b.path("rates.png"))
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
        row["change_vs_1dt"] = {k: change(row, k) for k in keys
                                if row.get(k) is not None and ref.get(k) not in (None, 0)}
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

    out = {"tolerance": TIMESTEP_TOLERANCE,
           "perturbed_factors": [f for f in (PERTURBED,) + PERTURBED_MORE if f in rows],
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
    out = ["| dt / dt_campaign | " + " | ".join(c[1] for c in cols)
           + " | energy residual (t, c, pull) | ms/step (t, c, pull) |",
           "|---" * (len(cols) + 3) + "|"]
    for r in ts["rows"]:
        cells = []
        for key, _, fmt in cols:
            v, ch = r.get(key), r.get("change_vs_1dt", {}).get(key)
            cells.append("—" if v is None else f"{v:{fmt}}"
                         + ("" if ch is None or r["factor"] == 1.0 else f" ({100 * ch:.2f} %)"))
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


# The repeats (issue #60): the tested sample's tension cycles with the campaign's step
# (DT_FACTORS['tension']) multiplied by 1 + k 1e-6, k = +-1 .. +-5, far below any integration error:
# the sample is chaotic after the peak, so the spread over these runs is what a single run's
# post-peak verdict may move by. The unperturbed runs are the campaign's own (factor 1 repeats them).
# The compression cycles and the pull repeat the same way (their own steps, DT_FACTORS[mode]).
REPEAT_FACTORS = tuple(1 + s * k * 1e-6 for k in range(1, 6) for s in (1, -1))
REPEAT_AMPLITUDES = (0.2, 0.1)
REPEAT_PULL_UNTIL = 1.0  # d0: past the tension's extent (statement 21 reads it below 0.3), 1/9 of Fig. 17's pull


def repeats(outdir, amplitudes=REPEAT_AMPLITUDES, factors=REPEAT_FACTORS, periods=PERIODS["tension"][:1], quick=False,
            progress=True, checkpoint=False, modes=("tension",), until=REPEAT_PULL_UNTIL):
    """The campaign's cycles (run_cycles) in each of ``modes`` ('tension', 'compression') at each factor,
    amplitude and period, the step DT_FACTORS[mode] x factor, each named
    repeat-x<factor>-<mode>-Dx<a>-P<period> (complete runs are read back); ``checkpoint``: each saved on
    the way (run_cycles). Mode 'pull': Fig. 17's pull to Dx = ``until`` at each factor, its step
    DT_FACTORS['pull'] x factor, in the bundle repeat-x<factor>-pull (one snapshot, at the start; a
    complete bundle is not run again). Returns {name: description}."""
    out = {}
    for factor in factors:
        for mode in modes:
            if mode == "pull":
                tag = f"repeat-x{factor:.10g}-pull"
                where = os.path.join(root(outdir, quick), tag)
                if _out.complete(where):
                    with open(os.path.join(where, tag + ".json")) as f:
                        out[tag] = json.load(f)
                    continue
                out[tag] = pull(outdir, quick, until=until, progress=progress, dx_marks=FIG17_DX[:1], tag=tag,
                                dt_factor=DT_FACTORS["pull"] * factor)
                continue
            for amplitude in amplitudes:
                for period in periods:
                    info, _ = run_cycles(outdir, mode, amplitude, period, quick, progress,
                                         prefix=f"repeat-x{factor:.10g}-", dt_factor=DT_FACTORS[mode] * factor,
                                         checkpoint=checkpoint)
                    out[info["name"]] = info
    return out


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
    test, f0 = new_test(progress)
    if energy:
        test.track_energy()
    bundle = _out.Bundle(os.path.join(root(outdir, quick), tag)) if is_master() else None
    marks = list(dx_marks)
    events = {"first_gap_Dx": None, "see_through_Dx": None, "last_contact_Dx": None, "snapshots": [],
              "gap_area": [], "planes_at_start": _uni.crossing_profile() if _mpy() is None else None,
              "planes_at_peak": None,
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
        # Every check_every-th record, counted from 2 as before #50 (the start was recorded twice,
        # the hook called twice): the records the committed pulls checked.
        if (len(t.rows) + 1) % check_every == 0:
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
    if _mpy() is None:
        win = _snap.window(margin=1.0, stretch=0.5 * until)
    t0 = time.time()
    try:
        stop = None if stop_after_last is None else (
            lambda: events["last_contact_Dx"] is not None and test.dx() > events["last_contact_Dx"] + stop_after_last)
        rows = test.pull(speed, until=until, every=max(1, int(round(100 / dt_factor))),
                         on_record=hook if _mpy() is None else None, stop=stop)
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
                   mpi_ranks=_mpy().numThreads if _mpy() else 1, dt=O.dt, dt_factor=dt_factor,
                   steps=O.iter - rows[0][0], ms_per_step=1e3 * (time.time() - t0) / max(1, O.iter - rows[0][0]))
    if energy:
        summary["energy_balance"] = test.energy_balance()
    if _mpy() is not None:
        summary["events_note"] = ("under yade.mpy the crack events and snapshots are not taken (they need every "
                                  "particle on one process): run the pull without --mpi for them")
    with bundle:
        bundle.write_text(tag + ".csv", csv_text(rows))
        bundle.write_json(tag + ".json", summary)
        plot_pull(rows, events, bundle.path(tag + ".png"))
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
    test, f0 = new_test(progress)
    bundle = _out.Bundle(os.path.join(root(outdir, quick), tag))
    marks, snaps = list(dx_marks), []
    # Room for the lateral spread: compressed by 3 d0 the sample widened by 4.0 d0 (y) and 4.0 d0 (z)
    # on each side (chosen/fig19.json); 0.3 until clipped the panels from (e) on.
    win = _snap.window(margin=1.5 + 2.5 * until)

    def hook(t, row):
        if marks and -row[1] >= marks[0]:
            k = len(snaps)
            label = f"{tag}-{k:02d}"
            _snap.png(os.path.join(bundle.tmp, label + ".png"),
                      f"({chr(97 + k)}) compression, Dx = {row[1]:.2f}, F/(kp d0) = {row[2]:+.3g}", win=win)
            _snap.vtk(os.path.join(bundle.tmp, tag), k)
            s = sample.stats()
            wy, wz = _spread_widths()
            snaps.append({"mark": marks.pop(0), "Dx": row[1], "F": row[2], "png": label + ".png",
                          "width_y_d0": wy / sample.D0, "width_z_d0": wz / sample.D0,
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
               "wall_clock_s": time.time() - t0, "strain_at_end": until * sample.D0 / test.L0}
    with bundle:
        bundle.write_text(tag + ".csv", csv_text(rows))
        bundle.write_json(tag + ".json", summary)
        plot_compression(rows, snaps, bundle.path(tag + ".png"))
    return summary


def _spread_widths():
    """The sample's widths in y and z: from the 1st percentile of the particles' lower surfaces to
    the 99th of their upper ones, so that the few particles squeezed out of the sample (up to 1 %)
    do not set it. At the unconfined start it is the extent of the sample to 0.03 d0 (the spread
    estimate sqrt(12) std + d0 used before was 0.8 d0 wider)."""
    ids = sample.sphere_ids()
    widths = []
    for k in (1, 2):
        lo = sorted(O.bodies[i].state.pos[k] - O.bodies[i].shape.radius for i in ids)
        hi = sorted(O.bodies[i].state.pos[k] + O.bodies[i].shape.radius for i in ids)
        n = len(ids) - 1
        widths.append(hi[int(0.99 * n)] - lo[int(0.01 * n)])
    return tuple(widths)


FACTOR_VARIANTS = (("full", "loading", "contacts"), ("frictionless", "loading", "contacts"),
                   ("full", "all", "contacts"),
                   ("frictionless", "all", "contacts"), ("full", "loading", "lab"), ("frictionless", "all", "lab"))


def factor_dir(outdir, packing, glue, rel_std=0.05, seed=1, sinter=sample.SINTER):
    """Where the factor study keeps one preparation (its stages and its pulls; quick ones in quick/)."""
    return os.path.join(outdir, "factors", f"{packing}-{glue}" + (f"-std{rel_std:g}" if rel_std != 0.05 else "")
                        + (f"-sinter{sinter:g}" if sinter != sample.SINTER else "")
                        + (f"-seed{seed}" if seed != 1 else ""))


def factor_run(outdir, packing, glue, drag, quick=False, progress=True, rel_std=0.05, seed=1, sinter=sample.SINTER):
    """One run of the tablet's factor study: the preparation (packing, glue) made or reused in
    factor_dir(), then the Fig. 17 pull with the drag relative to ``drag``, ended 1 Dx past the
    last chain's break (bundle pull-<drag>; a complete one is read back, so the study resumes).
    ``seed``: another realization of the same preparation (the gas's positions and radii);
    ``sinter``: the sintering stress d0 p_s/kp."""
    out = factor_dir(outdir, packing, glue, rel_std, seed, sinter)
    done = os.path.join(root(out, quick), f"pull-{drag}")
    if _out.complete(done):  # made by an earlier job: read back, not repeated
        with open(os.path.join(done, f"pull-{drag}.json")) as f:
            return json.load(f)
    protocol = dict({"packing": packing, "glue": glue, "rel_std": rel_std}, **({"seed": seed} if seed != 1 else {}),
                    **({"sinter": sinter} if sinter != sample.SINTER else {}))
    return pull(out, quick, progress=progress, tag=f"pull-{drag}", protocol=protocol,
                drag=drag, stop_after_last=1.0, until=12.0)
