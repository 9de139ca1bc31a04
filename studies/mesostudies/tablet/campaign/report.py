"""The tablet campaign's tables and records: the factor table, the peaks table, the copy of the
runs into the docs and back (report, restore), the jobs' log, the plan and the totals."""
import json
import os
import statistics
import time

from yade import O

from mesocontact import outputs as _out
from .. import snapshots as _snap
from .. import stages as _stages
from .. import sample
from .. import uniaxial as _uni
from .common import (
    COMPRESSION_AMPLITUDES, DT_FACTORS, FAST, FULL, PERIODS, PULL_SPEED, RATE_PERIODS,
    TENSION_AMPLITUDES, cycle_peaks, stroke_peaks, prepare, read_csv, root, run_dir,
)


def _stage_numbers(s, L=None):
    return {"solid_fraction": s["solid_fraction"], "coordination": s["coordination"], "rattlers": s["rattlers"],
            "Lx_d0": (L if L is not None else s["side"][0]) / sample.D0}


# Where the crack runs: the weakest plane at the paper's panel (b), Dx = 0.81, before the first
# visible gap of any pull (0.6-1.7 d0) but after the peak, when the contacts across the crack have
# begun to go; at the peak itself no crack exists and the weakest plane is the wall layers' order.
CRACK_MARKS = ("0.2", "0.81")


def _weakest(prof, L0):
    """The weakest plane of a crossing profile, by today's rule (None if the pull did not record it)."""
    if prof is None:
        return None
    prof.setdefault("length_d0", L0 / sample.D0 + (prof.get("Dx") or 0.0))
    prof["weakest"] = _uni.weakest_plane(prof)
    return prof["weakest"]


def _factor_row(st, p):
    """One row of the factor study from a preparation's description ``st`` and a pull's ``p``."""
    start = st["unconfined"]["stats"]
    for key in ("planes_at_start", "planes_at_peak"):
        _weakest(p[key], p["L0"])
    marks = p.get("planes_at_marks") or {}
    p0 = p["planes_at_start"]
    length = p0["length_d0"]
    near = [c for x, c in zip(p0["x"], p0["count"]) if 0.5 <= x <= 1.5 or length - 1.5 <= x <= length - 0.5]
    bulk = [c for x, c in zip(p0["x"], p0["count"]) if 3 <= x <= length - 3]
    return {"near_wall_mean_at_start": sum(near) / len(near) if near else None,
            "bulk_mean_at_start": sum(bulk) / len(bulk) if bulk else None,
            "packing": st["built"].get("packing", "full"), "glue": st["built"].get("glue", "loading"),
            "rel_std": st["built"].get("rel_std", 0.05), "seed": st["built"].get("seed", 1),
            "sinter": st["built"].get("sinter", sample.SINTER),
            "drag": p["drag"], "sintered": _stage_numbers(st["sintered"]), "released": _stage_numbers(st["released"]),
            "test_start": _stage_numbers(start, p["L0"]), "L0": p["L0"],
            "peak_tension": -p["max_tension"], "peak_Dx": p["max_tension_Dx"],
            "weakest_at_start": p["planes_at_start"]["weakest"], "mean_at_start": p["planes_at_start"]["mean"],
            "weakest_at_peak": p["planes_at_peak"]["weakest"], "mean_at_peak": p["planes_at_peak"]["mean"],
            "planes_at_peak_Dx": p["planes_at_peak"]["Dx"],
            "weakest_at_marks": {m: _weakest(marks.get(m), p["L0"]) for m in CRACK_MARKS},
            "mean_at_marks": {m: marks[m]["mean"] if m in marks else None for m in CRACK_MARKS},
            "first_gap_Dx_by_area": p["first_gap_Dx_by_area"],
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
        for js in pulls:  # each row names its pull's JSON (relative to factors/), for readers of factors.json
            with open(js) as f:
                rows.append(dict(_factor_row(st, json.load(f)),
                                 pull=os.path.relpath(js, os.path.join(outdir, "factors"))))
    fmt = lambda x, f=".3g": "–" if x is None else format(x, f)  # noqa: E731
    md = ["# The tested tablet: the factor study", "",
          "Written by `yade -n -x studies/scripts/tablet.py factors --out DIR --table` (or `--report DOCS`) from the "
          "files under `factors/` (each preparation's stage descriptions, each pull's CSV and JSON). One row per pull "
          "(Fig. 17's pull at the campaign's speed, ended 1 Dx after the last chain broke). Sample columns: "
          "after sintering / after release / at the test start (L0 between the loading walls; ν and C of the "
          "stage's statistics). Weakest plane: the plane x = const with the fewest contacts in overlap across "
          "it, at least 0.5 d0 from the walls' faces, planes 0.25 d0 apart; n (the mean over the planes); its "
          "distances from the left and right loading walls; at Dx = 0, at the peak tension and at Dx = 0.2 and 0.81 "
          "(the paper's panel (b): where the crack runs). First gap at three area thresholds; last chain: "
          "no chain of contacts from wall to wall.", "",
          "| packing | glue | radii std | d0 p_s/kp | seed | drag | L0/d0 sint. / rel. / test | ν sint. / rel. / test "
          "| C sint. / rel. / test | rattlers test | crossing contacts at Dx=0: 0.5–1.5 d0 from a wall / bulk (≥ 3 "
          "d0) | peak F/(kp d0) at Dx | weakest plane Dx=0: n (mean), from L / R [d0] | at peak | at Dx=0.2 | at "
          "Dx=0.81 | first gap Dx (0.5 / 1 / 2 d0²) | last chain Dx | F after /(kp d0) |", "|" + "---|" * 19]
    for r in rows:
        s3 = [r["sintered"], r["released"], r["test_start"]]
        g = r["first_gap_Dx_by_area"]
        md.append(f"| {r['packing']} | {r['glue']} | {r['rel_std']:g} | {r['sinter']:g} | "
                  f"{r.get('seed', 1)} | {r['drag']} | " + " / ".join(fmt(s['Lx_d0'], '.4g') for s in s3)
                  + " | " + " / ".join(fmt(s["solid_fraction"]) for s in s3) + " | "
                  + " / ".join(fmt(s["coordination"]) for s in s3) + f" | {r['test_start']['rattlers']} | "
                  f"{fmt(r['near_wall_mean_at_start'], '.0f')} / {fmt(r['bulk_mean_at_start'], '.0f')} | "
                  f"{fmt(r['peak_tension'], '.4g')} at {fmt(r['peak_Dx'], '.3f')} | "
                  f"{_plane(r['weakest_at_start'], r['mean_at_start'])} | "
                  f"{_plane(r['weakest_at_peak'], r['mean_at_peak'])} | "
                  + " | ".join(_plane(r["weakest_at_marks"][m], r["mean_at_marks"][m]) for m in CRACK_MARKS) + " | "
                  + " / ".join(fmt(g.get(k), ".2f") for k in sorted(g, key=float))
                  + f" | {fmt(r['last_chain_Dx'], '.2f')} | "
                  f"{fmt(r['mean_force_after_last_chain'], '.2g')} |")
    md += ["", "Against the criteria of the tested sample (L0 = 0.115 within 1 %; bulk rupture: weakest "
               "plane at the peak at "
           "least 3 d0 from both loading walls; crack in the bulk: the same at Dx = 0.81; first gap 0.6–1.4; "
           "last chain 6–10):", ""]
    for r in rows:
        crack = _from_wall(r["weakest_at_marks"][CRACK_MARKS[-1]])
        checks = {"L0": abs(r["L0"] / 0.115 - 1) <= 0.01, "bulk rupture": _from_wall(r["weakest_at_peak"]) >= 3,
                  "crack in the bulk": crack is not None and crack >= 3,
                  "first gap": (r["first_gap_Dx_by_area"].get("1") is not None
                                and 0.6 <= r["first_gap_Dx_by_area"]["1"] <= 1.4),
                  "last chain": r["last_chain_Dx"] is not None and 6 <= r["last_chain_Dx"] <= 10}
        sinter = f", d0 p_s/kp {r['sinter']:g}" if r["sinter"] != sample.SINTER else ""
        md.append(f"- {r['packing']}, {r['glue']}, radii std {r['rel_std']:g}{sinter}, seed "
                  f"{r.get('seed', 1)}, {r['drag']}: "
                  + ", ".join(f"{k} {'✓' if v else ('–' if k == 'crack in the bulk' and crack is None else '✗')}"
                              for k, v in checks.items())
                  + f" (L0 {100 * (r['L0'] / 0.115 - 1):+.2f} %)")
    md += ["", "What each factor does (pairs of runs that differ in it alone): L0/d0 at the test start; the "
           "weakest plane at the peak and at Dx = 0.81, its distance from the nearer loading wall [d0]; first gap; "
           "last chain.", ""]
    names = ("packing", "glue", "rel_std", "sinter", "seed", "drag")
    key = lambda r: tuple(r.get(n, 1) for n in names)  # noqa: E731  (seed: 1 in rows made before the option)
    for k, name in enumerate(names):
        if name == "seed":  # realizations are a distribution, summarized below, not pairs
            continue
        for a in rows:
            for b in rows:
                ka, kb = key(a), key(b)
                if ka[k] < kb[k] and all(ka[j] == kb[j] for j in range(len(names)) if j != k):
                    def say(r):
                        return (f"{r.get(name, 1)}: L0 {r['L0'] / sample.D0:.3f}, weakest plane "
                                f"{_from_wall(r['weakest_at_peak']):.2f} from a wall (at Dx = 0.81: "
                                f"{fmt(_from_wall(r['weakest_at_marks'][CRACK_MARKS[-1]]), '.2f')}), first gap "
                                f"{fmt(r['first_gap_Dx_by_area'].get('1'), '.2f')}, last chain "
                                f"{fmt(r['last_chain_Dx'], '.2f')}")
                    others = ", ".join(f"{n} {v:g}" if isinstance(v, float) else f"{n} {v}"
                                       for j, (n, v) in enumerate(zip(names, ka)) if j != k)
                    md.append(f"- {name} ({others}): {say(a)} | {say(b)}")
    md += _realizations(rows, names, key)
    base = os.path.join(outdir, "factors", "quick" if quick else "")
    os.makedirs(base, exist_ok=True)
    _out.write_atomic(os.path.join(base, "factors.json"), json.dumps(rows, indent=1))
    _out.write_atomic(os.path.join(base, "factors.md"), "\n".join(md) + "\n")
    return rows


def _from_wall(w):
    """A weakest plane's distance from the nearer loading wall [d0] (None if not recorded)."""
    return None if w is None else min(w["from_left_d0"], w["from_right_d0"])


def _plane(w, mean):
    """A weakest plane in the table: its count (the mean over the planes), distances from L / R."""
    if w is None:
        return "–"
    return f"{w['count']} ({mean:.0f}), {w['from_left_d0']:.2f} / {w['from_right_d0']:.2f}"


def _spread(values, f=".2f"):
    """The values, their mean and sample standard deviation (None values left out)."""
    v = [x for x in values if x is not None]
    if len(v) < 2:
        return ", ".join(format(x, f) for x in v) or "–"
    return f"{', '.join(format(x, f) for x in v)}: mean {statistics.mean(v):{f}}, sd {statistics.stdev(v):{f}}"


def _realizations(rows, names, key):
    """One line per preparation run with several seeds: its values over the realizations."""
    groups = {}
    for r in rows:
        groups.setdefault(tuple(v for n, v in zip(names, key(r)) if n != "seed"), []).append(r)
    md = []
    for g, rs in groups.items():
        if len(rs) < 2:
            continue
        rs = sorted(rs, key=lambda r: r.get("seed", 1))
        others = ", ".join(f"{n} {v:g}" if isinstance(v, float) else f"{n} {v}"
                           for n, v in zip((n for n in names if n != "seed"), g))
        md += ["", f"Realizations of one preparation ({others}; seeds {', '.join(str(r.get('seed', 1)) for r in rs)}):",
               f"- last chain Dx: {_spread([r['last_chain_Dx'] for r in rs])}",
               f"- first gap Dx (1 d0^2): {_spread([r['first_gap_Dx_by_area'].get('1') for r in rs])}",
               f"- L0 against 0.115 [%]: {_spread([100 * (r['L0'] / 0.115 - 1) for r in rs])}",
               f"- weakest plane at Dx = 0.81 from the nearer wall [d0]: "
               f"{_spread([_from_wall(r['weakest_at_marks'][CRACK_MARKS[-1]]) for r in rs], '.1f')}",
               f"- peak tension F/(kp d0): {_spread([abs(r['peak_tension']) for r in rs], '.4f')}"]
    return md


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


def peaks_table(runs):
    """Markdown table of cyclic runs (their JSON descriptions with final_F, the last row's force):
    peak force of every cycle, the force back at Dx = 0, the cost."""
    out = ["| run | period [t_w] | peak F/(kp d0), cycles 1-4 | F at the end (Dx = 0) | steps | ms per "
           "step | wall-clock |",
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
    if not os.path.isdir(docsdir):
        raise ValueError(f"docsdir = {docsdir!r} is invalid: not a directory (the committed runs' folder)")
    if os.path.realpath(docsdir) == os.path.realpath(outdir):
        raise ValueError(f"outdir = {outdir!r} is invalid: the committed folder itself (restore into a results tree)")
    if os.path.exists(outdir) and not os.path.isdir(outdir):
        raise ValueError(f"outdir = {outdir!r} is invalid: a file, not a directory (the results tree to restore into)")
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
        peaks = stroke_peaks(rows, info["turns"]) if info.get("turns") else cycle_peaks(info["mode"], rows,
                                                                                        info["steps_per_cycle"])
        if peaks != info["peaks"]:
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
            rows.append([info["built"]["material"], info["built"]["kc_over_kp"], stage, s["solid_fraction"],
                         s["coordination"],
                         s["coordination_with_walls"], s["rattlers"], s["kinetic_energy_ratio"]]
                        + [s["wall_stress"][w] for w in sample.WALLS] + s["side"])
    if rows:
        _out.write_atomic(os.path.join(docsdir, "kc-study.csv"),
                          "material,kc_over_kp,stage,solid_fraction,coordination,coordination_with_walls,rattlers,"
                          "kinetic_energy_ratio," + ",".join(f"stress_{w}" for w in sample.WALLS) + ",Lx,Ly,Lz\n"
                          + "".join(",".join(str(x) for x in r) + "\n" for r in rows))
    return rows


# The cost estimates of the jobs that count (the tablet's registry, cli.JOBS, attaches them): the
# steps a job's table line runs, each test at its time step (dt0 times DT_FACTORS). Each takes the
# line's cells ({column: text}), the elastic crossing time and the campaign's base step.
def _numbers(cells, key, default):
    import ast
    v = cells.get(key)
    v = ast.literal_eval(v) if v not in (None, "None") else None
    return tuple(float(x) for x in str(v).split(",")) if v is not None else default


def _cycle(period, mode, t_cross, dt0):
    return int(round(period * t_cross / (dt0 * DT_FACTORS[mode])))


def _cyclic_steps(mode, cells, t_cross, dt0):
    amps = _numbers(cells, "amplitudes", TENSION_AMPLITUDES if mode == "tension" else COMPRESSION_AMPLITUDES)
    return sum(FULL["cycles"] * _cycle(p, mode, t_cross, dt0) for _ in amps
               for p in _numbers(cells, "periods", PERIODS[mode]))


def _pull_steps(until, cells, dt0):
    until, speed = _numbers(cells, "until", (until,))[0], _numbers(cells, "speed", (PULL_SPEED,))[0]
    return int(until * sample.D0 / (2 * speed * dt0 * DT_FACTORS["pull"]))


def tension_steps(cells, t_cross, dt0):
    """fig16: every amplitude's cycles at every period."""
    return _cyclic_steps("tension", cells, t_cross, dt0)


def compression_steps(cells, t_cross, dt0):
    """fig18: every amplitude's cycles at every period."""
    return _cyclic_steps("compression", cells, t_cross, dt0)


def pull_steps(cells, t_cross, dt0):
    """fig17: the pull to Dx = until (9)."""
    return _pull_steps(9.0, cells, dt0)


def large_compression_steps(cells, t_cross, dt0):
    """fig19: the compression to Dx = -until (3)."""
    return _pull_steps(3.0, cells, dt0)


def drag_steps(cells, t_cross, dt0):
    """drag: three runs at the campaign's base step (drag_share)."""
    return 3 * int(round(FAST * t_cross / dt0))


def rates_steps(cells, t_cross, dt0):
    """rates: the cycles at every period, in tension and compression."""
    return sum(FULL["cycles"] * _cycle(p, m, t_cross, dt0) for p in _numbers(cells, "periods", RATE_PERIODS)
               for m in _uni.MODES)


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
            print(f"  {j['job']:20s} {j['figure']:8s} {j['steps']:>10,d} steps  {j['seconds'] / 3600:5.2f} h",
                  flush=True)
        print(f"total: {len(jobs)} jobs, {steps:,d} steps, {out['single_job_hours']:.2f} h of job time"
              + (f" ({out['ms_per_step']:.2f} ms/step)" if steps else "")
              + f", {out['wall_hours']:.2f} h of wall time" + (f" on {lanes} lanes" if lanes else ""), flush=True)
    return out


def plan(table, outdir, registry, lanes=2, progress=True):
    """The plan of a campaign table before it runs: each job's steps at the campaign's time step
    (its cost in ``registry``, the tablet's cli.JOBS; none declared: not counted), the ms per
    step measured on the unconfined start (300 steps, walls at rest), the estimated hours of each
    job, their sum (single-job time) and the wall time on ``lanes`` lanes taking the longest job
    first. A line whose job the registry does not know is a ValueError naming it, before any work.
    Prints it; returns it."""
    with open(table) as f:
        lines = [ln.split() for ln in f if ln.strip() and not ln.lstrip().startswith("#")]
    head = lines[0]
    cells = [dict(zip(head, c)) for c in lines[1:]]
    for c in cells:  # every line's job known before the preparation's minutes, not after
        try:
            registry.get(c["figure"].strip("'\""))
        except ValueError as e:
            raise ValueError(f"{table}: line {c['description']}: {e}") from None
    prepare(outdir, False, progress)
    test = _uni.Test(progress=False)
    O.run(20, True)
    t0, n = time.time(), 300
    O.run(n, True)
    ms = 1e3 * (time.time() - t0) / n
    jobs = []
    for c in cells:
        figure = c["figure"].strip("'\"")
        steps = registry.cost(figure, c, test.t_cross, O.dt) or 0  # prepare and the like: minutes, not counted
        jobs.append({"job": c["description"], "figure": figure, "steps": steps, "hours": steps * ms / 3.6e6})
    finish = [0.0] * lanes
    for j in sorted(jobs, key=lambda j: -j["hours"]):
        k = finish.index(min(finish))
        finish[k] += j["hours"]
    out = {"table": table, "dt": O.dt, "ms_per_step": ms, "jobs": jobs,
           "single_job_hours": sum(j["hours"] for j in jobs),
           "lanes": lanes, "wall_hours_estimate": max(finish)}
    if progress:
        for j in jobs:
            print(f"  {j['job']:20s} {j['figure']:8s} {j['steps']:>10,d} steps  {j['hours']:5.2f} h", flush=True)
        print(f"plan: {len(jobs)} jobs, {sum(j['steps'] for j in jobs):,d} steps at {ms:.2f} ms/step (measured): "
              f"{out['single_job_hours']:.2f} h of single-job time, about "
              f"{out['wall_hours_estimate']:.2f} h on {lanes} lanes",
              flush=True)
    return out
