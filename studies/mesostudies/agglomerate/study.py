"""The agglomerate study's jobs behind one command line (inside ``yade``; studies/scripts/agglomerate.py).

Each job loads the saved agglomerates afresh; its results go to --out (default results/agglomerate;
--quick: <out>/quick, the small agglomerates of the pipeline's test).
"""
import argparse
import json
import os
import time

from yade import O

from mesocontact import outputs
from mesocontact.bulk import agglomerate, pair_cycles
from mesocontact.bulk.collisions import Collision
from mesocontact.jobs import Job, Registry
from mesocontact.outputs import read_csv
from . import compare, ensemble, make, measure, plots, predict, report
from .primaries import D0, KP, SCALES

AMPLITUDES = {False: (0.1, 0.2, 0.4), True: (0.05, 0.1, 0.2)}    # d0 beyond the first touch
SPEEDS = {False: (0.01, 0.03, 0.1, 0.3, 1.0, 3.0, 10.0, 20.0, 40.0, 80.0, 160.0, 320.0), True: (0.1, 1.0, 10.0)}  # m/s
CAP_SPEED = 0.0025   # each cap's speed in the cycles [mm/us], the tablet's pull speed (2.5 m/s)
SLOWER = 4
DIRECTION_SEED = 1
CAMPAIGN = "campaigns/agglomerate"  # the committed campaign: its slow cycles and their fit


def _parser():
    p = argparse.ArgumentParser(prog="yade -n -x studies/scripts/agglomerate.py",
                                description=__doc__ + "\njobs:\n" + JOBS.describe(),
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("job", choices=JOBS)
    p.add_argument("--out", default="results/agglomerate")
    p.add_argument("--quick", action="store_true", help="small agglomerates (about 45 primaries), few speeds")
    p.add_argument("--speeds", type=lambda s: tuple(float(x) for x in s.split(",")), default=None,
                   help="relative collision speeds [m/s], comma-separated")
    p.add_argument("--factors", type=lambda s: tuple(int(x) for x in s.split(",")), default=None,
                   help=f"cycles: the cap speed's divisors (default 1,{SLOWER}; --quick: 1), one run each; "
                        "separate jobs may run them side by side")
    p.add_argument("--wall-material", choices=sorted(pair_cycles.WALL_MATERIALS), default="own",
                   help="wall: the primaries' own material (default) or the tablet's smooth mould "
                        "(no adhesion, no friction)")
    p.add_argument("--direction", type=int, default=0,
                   help="collide: the approach direction's index in agglomerate.directions (0: x, as carved; "
                        "k > 0: drawn on the sphere, seed DIRECTION_SEED)")
    p.add_argument("--amplitudes", type=lambda s: tuple(float(x) for x in s.split(",")), default=None,
                   help="cycle amplitudes beyond the first touch [d0], comma-separated")
    p.add_argument("--seeds", type=lambda s: tuple(int(x) for x in s.split(",")), default=None,
                   help="ensemble: the blocks' seeds, comma-separated (default 1,2,3)")
    p.add_argument("--directions", type=lambda s: tuple(int(x) for x in s.split(",")), default=None,
                   help="ensemble: direction indices, comma-separated (default 1..20, drawn on the sphere)")
    p.add_argument("--follow", type=float, default=ensemble.FOLLOW,
                   help="ensemble: a parted pair is followed until its fragments are this many presses apart")
    return p


def batch_columns():
    """yade-batch's table columns: every option, named with underscores, absent unless given."""
    return {"job": None, **{x.dest: None for x in _parser()._actions if x.option_strings and x.dest != "help"}}


def _check(a, p):
    if a.direction < 0:
        p.error(f"--direction {a.direction} is invalid: an index >= 0")
    for name in ("seeds", "directions"):
        v = getattr(a, name)
        if v is not None and (not v or any(x < (1 if name == "seeds" else 0) for x in v)):
            p.error(f"--{name} {','.join(map(str, v))} is invalid: integers >= {1 if name == 'seeds' else 0}")
    if not (a.follow > 0 and a.follow < float("inf")):
        p.error(f"--follow {a.follow} is invalid: a positive finite number")
    if a.factors is not None and (not a.factors or any(f < 1 for f in a.factors)):
        p.error(f"--factors {a.factors} is invalid: positive integers")
    for name in ("speeds", "amplitudes"):
        v = getattr(a, name)
        if v is not None and (not v or any(not (x > 0 and x < float("inf")) for x in v)):
            p.error(f"--{name} {','.join(map(str, v))} is invalid: positive finite numbers")


def _dir(a):
    return os.path.join(a.out, "quick") if a.quick else a.out


def _write(path, obj):
    outputs.write_atomic(path, json.dumps(obj, indent=1))


def prepare(a):
    return make.ensure(_dir(a), quick=a.quick)


def cycles(a, wall=False):
    """One cycle run per speed divisor: cycles-v<m/s>.csv and .json (``wall``: wall-cycles-v<m/s>)
    in the study's folder."""
    prepare(a)
    out = {}
    for factor in a.factors or ((1,) if a.quick else (1, SLOWER)):  # quick: the pipeline, no rate check
        info = make.ensure(_dir(a), quick=a.quick)
        speed = CAP_SPEED / factor
        print(f"{'wall ' if wall else ''}cycles at {speed * 1e3:g} m/s per cap", flush=True)
        t0, it0 = time.time(), O.iter
        radii = [g["radius"] for g in info["agglomerates"]]
        pair = (pair_cycles.Wall(info["members"], radii[0], material=a.wall_material, protocol=SCALES) if wall
                else pair_cycles.Pair(info["members"], radii, protocol=SCALES))
        rows = pair.cycles(a.amplitudes or AMPLITUDES[a.quick], speed, final=factor == 1)  # slower runs: the rate check
        name = f"{_wall_prefix(a.wall_material) if wall else ''}cycles-v{speed * 1e3:g}"
        outputs.write_atomic(os.path.join(_dir(a), name + ".csv"),
                             "iter,delta_mm,F\n" + "".join(f"{r[0]},{r[1]!r},{r[2]!r}\n" for r in rows))
        out[name] = {"speed_per_cap_m_s": speed * 1e3, "touch_delta_mm": pair.touch, "events": pair.events,
                     "grip_fraction": pair.grip_fraction, "grip_particles": [len(g) for g in pair.grips],
                     "steps": O.iter - it0, "wall_clock_s": time.time() - t0, "dt": O.dt,
                     "units": "delta mm, F mg mm/us^2 (1e3 N)"}
        if wall:
            out[name]["against"] = (f"a flat wall, material {a.wall_material!r} "
                                    f"({pair_cycles.WALL_MATERIALS[a.wall_material]}), agglomerate 0")
        _write(os.path.join(_dir(a), name + ".json"), out[name])
    return out


def _wall_prefix(material):
    return "wall-" if material == "own" else f"{material}-wall-"


def _cycle_runs(d, prefix="cycles-v"):
    """{name: description} of the cycle runs in the study's folder (``prefix``: the pair's, or
    'wall-cycles-v'), slowest first."""
    runs = {}
    for f in sorted(os.listdir(d)):
        if f.startswith(prefix) and f.endswith(".json"):
            with open(os.path.join(d, f)) as fh:
                runs[f[:-5]] = json.load(fh)
    return dict(sorted(runs.items(), key=lambda kv: kv[1]["speed_per_cap_m_s"]))


def collision_file(direction):
    return "collisions.json" if direction == 0 else f"collisions-dir{direction}.json"


def collisions(a):
    axis = agglomerate.directions(a.direction + 1, DIRECTION_SEED)[a.direction]
    tag = "" if a.direction == 0 else f"-dir{a.direction}"
    out = []
    for v in a.speeds or SPEEDS[a.quick]:
        info = make.ensure(_dir(a), quick=a.quick)
        c = Collision(info["members"], [g["radius"] for g in info["agglomerates"]], axis=axis, protocol=SCALES)
        print(f"collision at {v:g} m/s{f', direction {a.direction} {axis}' if a.direction else ''}", flush=True)
        v_rel = v / 1e3  # mm/us
        r = c.run(v_rel, snapshot=os.path.join(_dir(a), f"collision{tag}-v{v:g}.png"), unit="mm",
                  speed_label=f"{v_rel * 1e3:g} m/s")
        outputs.write_atomic(os.path.join(_dir(a), f"collision{tag}-v{v:g}.csv"),
                             "iter,time_us,delta_mm,v0_mm_us,v1_mm_us,F_normal\n"
                             + "".join(",".join(repr(x) for x in row) + "\n" for row in c.rows))
        print(f"  e = {r['e']:.4f}  stuck {r['stuck']}  broken off {r['broken_mass_fraction']:.3f}  "
              f"contact time {r['contact_time']}", flush=True)
        out.append(dict(r, v_rel_m_s=v, direction=list(axis)))
    _write(os.path.join(_dir(a), collision_file(a.direction)), out)
    return out


def main(argv):
    p = _parser()
    a = p.parse_args(argv)
    _check(a, p)
    t0 = time.time()
    JOBS.get(a.job).function(a)
    print(f"agglomerate {a.job}: done in {time.time() - t0:.0f} s", flush=True)


def _cycles_summary(runs, measures):
    return {n: dict(measures[n], speed_per_cap_m_s=runs[n]["speed_per_cap_m_s"],
                    amplitudes_d0=[float(e[0].split()[2]) for e in runs[n]["events"] if e[0].startswith("loaded to")],
                    unload_below_touch_d0=[(runs[n]["touch_delta_mm"] - e[2]) / D0
                                           for e in runs[n]["events"] if e[0] == "unloaded"])
            for n in runs}


def _wall(d, info, params, touch_pair, material, pair_turns):
    """The cycles against a wall of ``material`` (if run): the law fitted to the slowest with the
    wall's a12, and what the pair's fit predicts for them (compare.wall_predictions). Returns
    (summary, curves) or (None, None). pair_turns: {amplitude: the pair's force there}, slowest run."""
    runs = _cycle_runs(d, _wall_prefix(material) + "cycles-v")
    if not runs:
        return None, None
    names = list(runs)
    rows = {n: read_csv(os.path.join(d, n + ".csv")) for n in names}
    fitted_run = names[0]
    fitted = compare.fit(rows[fitted_run], info, a12=compare.wall_a12(info))
    touch = runs[fitted_run]["touch_delta_mm"]
    predicted = compare.wall_predictions(params, rows[fitted_run], info, touch_pair, touch)
    measures = {n: compare.cycle_measures(rows[n], runs[n]["events"]) for n in names}
    summary = {"material": material, "fitted_run": fitted_run, "fit": fitted.to_json(), "a12_m": compare.wall_a12(info),
               "k1_over_pair": fitted.params["k1"] / params["k1"],
               "law_start_beyond_touch_d0": (fitted.params["shift"] / compare.MM - touch) / D0,
               "pair_law_start_beyond_touch_d0": (params["shift"] / compare.MM - touch_pair) / D0,
               "predictions": {k: dict(zip(("rms_relative", "max_relative"), compare.misfit(v, rows[fitted_run])))
                               for k, v in predicted.items()},
               "cycles": _cycles_summary(runs, measures), "rate_check": compare.rate_check(measures)}
    own = summary["cycles"][fitted_run]
    summary["turn_force_over_pair"] = {f"{a:g}": f / pair_turns[a]
                                       for a, f in zip(own["amplitudes_d0"], own["turn_forces"])
                                       if a in pair_turns}
    curves = {"runs": rows, "fit": compare.law_curve(fitted.params, rows[fitted_run], compare.wall_a12(info)),
              "predicted": predicted, "touch": touch}
    print(fitted.report(), flush=True)
    return summary, curves


def _directions(d, speeds):
    """The collisions along the other approach directions (collisions-dir<k>.json present), at
    the x run's speeds."""
    out = []
    k = 1
    while os.path.exists(os.path.join(d, collision_file(k))):
        with open(os.path.join(d, collision_file(k))) as f:
            hits = {h["v_rel_m_s"]: h for h in json.load(f)}
        out.append({"index": k, "axis": next(iter(hits.values()))["direction"],
                    **{key: [hits[v].get(key) if v in hits else None for v in speeds]
                       for key in ("e", "e_speed", "e_impulse", "e_normal", "deflection_deg", "tilt_deg",
                                   "impulse_angle_deg", "friction_over_normal_impulse", "stuck", "broken_mass_fraction",
                                   "contact_time")}})
        k += 1
    return out


def compare_job(a):
    d = _dir(a)
    with open(make.path(d, "agglomerates", a.quick) + ".json") as f:
        info = json.load(f)
    runs = _cycle_runs(d)
    names = list(runs)
    rows = {n: read_csv(os.path.join(d, n + ".csv")) for n in names}
    # The fit takes the slowest run (the faster one's pull-offs ring); the run with the most
    # amplitudes, if another, is fitted too, to show what the larger amplitude changes.
    turns = {n: sum(1 for e in runs[n]["events"] if e[0].startswith("loaded to")) for n in names}
    fitted_run = names[0]
    fitted = compare.fit(rows[fitted_run], info)
    widest = max(names, key=lambda n: (turns[n], -runs[n]["speed_per_cap_m_s"]))
    also = None
    if widest != fitted_run:
        f2 = compare.fit(rows[widest], info)
        also = {"run": widest, **{k: f2.to_json()[k] for k in ("k1", "kp", "kc", "phiF", "shift", "ci95",
                                                               "undetermined", "rms_relative", "max_relative")}}
    with open(os.path.join(d, collision_file(0))) as f:
        hits = json.load(f)
    speeds = [h["v_rel_m_s"] for h in hits]
    params = fitted.params
    e_theory = compare.theory_e(params, info, [v / 1e3 for v in speeds])
    e_meso = compare.meso_collisions(params, info, [v / 1e3 for v in speeds])
    # The law's viscosity from one collision, the slowest the agglomerates rebound in, then every speed.
    k0 = next((k for k, h in enumerate(hits) if not h["stuck"] and h["broken_mass_fraction"] < 0.01), None)
    viscous = None
    if k0 is not None:
        gamma, e_fit = compare.fit_viscosity(params, info, speeds[k0] / 1e3, hits[k0]["e"])
        viscous = {"gammaN": gamma, "fitted_at_m_s": speeds[k0], "e_at_fit": e_fit,
                   "e_meso": compare.meso_collisions(params, info, [v / 1e3 for v in speeds], gammaN=gamma)}
    measures = {n: compare.cycle_measures(rows[n], runs[n]["events"]) for n in names}
    # The cycles' tension taken as the law's non-contact force: one estimate per unloading of the fitted run.
    cycles = _cycles_summary(runs, measures)
    adhesion = []
    for p, amp in zip(measures[fitted_run]["tension_plateaus"], cycles[fitted_run]["amplitudes_d0"]):
        c = (compare.adhesion_consequence(params, info, p, runs[fitted_run]["touch_delta_mm"],
                                          [v / 1e3 for v in speeds])
             if p is not None and p < 0 else None)
        if c:
            adhesion.append(dict(c, after_d0=amp))
    pair_turns = dict(zip(cycles[fitted_run]["amplitudes_d0"], cycles[fitted_run]["turn_forces"]))
    walls = {m: _wall(d, info, params, runs[fitted_run]["touch_delta_mm"], m, pair_turns)
             for m in pair_cycles.WALL_MATERIALS}
    summary = {"fitted_run": fitted_run, "fit_widest_run": also,
               "cycles": cycles,
               "rate_check": compare.rate_check(measures),
               "preparation": {k: info[k] for k in ("carve_radius_d0", "removed_loose", "agglomerates", "definitions")},
               "fit": fitted.to_json(), "speeds": speeds, "e_agglomerate": [h["e"] for h in hits],
               "e_meso": e_meso, "e_theory": e_theory,
               "overlap_theory_d0": compare.theory_overlap(params, info, [v / 1e3 for v in speeds]),
               "fragmented": [h["broken_mass_fraction"] for h in hits],
               "stuck": [h["stuck"] for h in hits], "contact_time": [h["contact_time"] for h in hits],
               "e_speed": [h.get("e_speed") for h in hits], "e_impulse": [h.get("e_impulse") for h in hits],
               "press_d0": [h.get("press_d0") for h in hits],
               "largest_normal_force": [h.get("largest_normal_force") for h in hits],
               "e_normal": [h.get("e_normal") for h in hits], "tilt_deg": [h.get("tilt_deg") for h in hits],
               "impulse_angle_deg": [h.get("impulse_angle_deg") for h in hits],
               "friction_over_normal_impulse": [h.get("friction_over_normal_impulse") for h in hits],
               "deflection_deg": [h.get("deflection_deg") for h in hits],
               "energy_over_impact": [h["energy_over_impact"] for h in hits], "meso_viscous": viscous,
               "directions": _directions(d, speeds), "adhesion": adhesion,
               "walls": {m: w[0] for m, w in walls.items() if w[0]},
               "d0_mm": D0}
    _write(os.path.join(d, "agglomerate-vs-meso.json"), summary)
    outputs.write_atomic(os.path.join(d, "summary.md"), report.markdown(summary))
    a12 = compare.geometry(info)[0]
    force_scale = KP * D0
    plots.cycles({n: rows[n] for n in [fitted_run] + [m for m in names if m != fitted_run]},
                 compare.law_curve(params, rows[fitted_run], a12), os.path.join(d, "cycles.png"),
                 D0, force_scale, runs[fitted_run]["touch_delta_mm"])
    for m, (w, curves) in walls.items():
        if curves:
            plots.wall_cycles(curves, os.path.join(d, _wall_prefix(m) + "cycles.png"), D0, force_scale,
                              f"one agglomerate against a flat wall, material '{m}'")
    plots.restitution(speeds, summary["e_agglomerate"], e_meso, e_theory, summary["fragmented"],
                      os.path.join(d, "restitution.png"), e_viscous=viscous["e_meso"] if viscous else None,
                      directions=summary["directions"], e_normal=summary["e_normal"], stuck=summary["stuck"])
    print(fitted.report(), flush=True)
    return summary


def everything(a):
    """The job 'all': the others in turn, in the registry's order."""
    for job in JOBS:
        if job not in ("all", "ensemble", "rate", "pulls", "predict"):
            JOBS.get(job).function(a)


# The study's jobs, in the order --help lists them and 'all' runs them; each runs with the parsed
# options. This module is the package's top: it imports the modules the jobs run (make, compare,
# plots, report, and the library's bulk.pair_cycles and bulk.collisions), none of them imports it.
# A new job is a function (here or in a module of its own) and one record here.
JOBS = Registry([
    Job("prepare", prepare, "the sintered block and the two carved agglomerates (make.ensure)."),
    Job("cycles", cycles, "their F(delta) cycles at the speed and 4x slower (bulk.pair_cycles.Pair.cycles)."),
    Job("wall", lambda a: cycles(a, wall=True),
        "the first agglomerate's cycles against a flat wall, the same way (bulk.pair_cycles.Wall)."),
    Job("collide", collisions, "head-on collisions at each speed (bulk.collisions.Collision); --direction K: approach "
        "along the K-th direction of bulk.agglomerate.directions (0: x, the pair as carved)."),
    Job("compare", compare_job, "the law fitted to the slowest cycles (and to the run with the most amplitudes), the "
        "meso-particle pair and the closed form at the same speeds: agglomerate-vs-meso.json, cycles.png, "
        "restitution.png."),
    Job("ensemble", lambda a: ensemble.runs(a.out, a.seeds or (1, 2, 3), a.directions or ensemble.DIRECTIONS,
                                            a.speeds or ensemble.SPEEDS, a.follow, a.quick),
        "issue #59's ensemble: collisions of each seed's block (--seeds) along each direction (--directions) at each "
        "speed, followed to their end, one JSON each under <out>/block-s<seed>/ensemble; finished ones are skipped. "
        "Not part of 'all'."),
    Job("rate", lambda a: measure.rate(ensemble.block_dir(a.out, (a.seeds or (1,))[0]), (a.seeds or (1,))[0],
                                       a.quick, a.speeds or measure.RATE_SPEEDS),
        "issue #59: the pair's cycles with the caps at collision-like speeds (--speeds, m/s per cap), in the "
        "ensemble's block folder (--seeds' first). Not part of 'all'."),
    Job("rate-energy", lambda a: measure.rate_energy(ensemble.block_dir(a.out, (a.seeds or (1,))[0]),
                                                     (a.seeds or (1,))[0], a.quick, a.speeds or measure.ENERGY_SPEEDS),
        "issue #59: the pair's cycles at 0.625 to 40 m/s per cap (--speeds) with the law's energy tracked: the "
        "loss per loop by term (loss.dissipated). Not part of 'all'."),
    Job("pulls", lambda a: measure.pulls(ensemble.block_dir(a.out, (a.seeds or (1,))[0]), (a.seeds or (1,))[0],
                                         a.quick, a.amplitudes or measure.PULL_AMPLITUDES),
        "issue #59: a fresh pair pressed once to each --amplitudes and pulled fully apart, slowly. Not part of 'all'."),
    Job("predict", lambda a: predict.predict(a.out, CAMPAIGN, make.ensure(ensemble.block_dir(a.out, 1), seed=1)),
        "issue #59: e predicted from the cycles alone (the slow cycles' fit, gammaN from the rate cycles) against "
        "the ensemble under --out: ensemble.json, ensemble.md. Not part of 'all'."),
    Job("all", everything, "prepare, cycles, wall, collide and compare in turn."),
])
