"""The tablet's jobs and their command line (studies/scripts/tablet.py JOB): the registry JOBS,
declared here, at the top of the package, above every module it dispatches to (campaign's runs and
report, affine, profile, slaved; none of them imports this one), the options of every job, their
checks and the dispatch."""
import json
import math
import os
import tempfile
import time


from mesocontact import mpi as _mpi
from mesocontact import outputs as _out
from mesocontact.jobs import Job, Registry
from . import stages as _stages
from . import sample
from .campaign.common import (
    FAST, FULL, PERIODS, PULL_SPEED, RATE_PERIODS, SLOW, is_master, mpy as _mpy, prepare, use_mpi,
)
from .campaign.runs import (
    PERTURBED, PERTURBED_MORE, REPEAT_AMPLITUDES, REPEAT_FACTORS, REPEAT_PULL_UNTIL, RETURNS, TIMESTEP_FACTORS,
    TIMESTEP_RUNS, cyclic, drag_share, factor_run, large_compression, pull, rates, repeats, timestep_study,
)
from .campaign.report import (
    compression_steps, drag_steps, factor_report, factor_table, large_compression_steps, pull_steps, rates_steps,
    tension_steps,
)
from .affine import run as affine_run
from .profile import run as profile_run
from .slaved import job as slaved_job


# The options of every tablet job, declared once: argparse takes them as they are, and a yade-batch
# table takes each as a column of its name with underscores (batch_columns). (flag, keywords)
OPTIONS = (
    ("--quick", dict(action="store_true", help="216 particles, one cycle (for tests)")),
    ("--out", dict(default="results/tablet", help="output directory (the cached states are reused from it)")),
    ("--periods",
     dict(default=None, help="comma-separated cycle periods in elastic crossing times (the first drawn thin)")),
    ("--amplitudes", dict(default=None, help="comma-separated amplitudes Dx in d0")),
    ("--slow-amplitudes", dict(default=None,
                               help="fig16, fig18: comma-separated amplitudes that also run at the slower "
                                    "periods (default: all)")),
    ("--no-run", dict(action="store_true", help="rates: only the periods whose runs are complete")),
    ("--speed", dict(type=float, default=PULL_SPEED, help="fig17: wall speed [mm/us]")),
    ("--until", dict(type=float, default=None,
                     help="fig17: pull until Dx = UNTIL (default 9); profile: likewise (default 0.3); repeats: the "
                          "pull likewise (default 1); fig19: compress "
                          "until Dx = -UNTIL (default 3) (in d0)")),
    ("--factors",
     dict(default=None, help="timestep: comma-separated multiples of the campaign's time step (default 1,2,3,4 "
                             "and the perturbed 1.000001, 1.000002, 0.999999); repeats: multiples of the "
                             "campaign's tension step (default 1 +- k 1e-6, k = 1..5)")),
    ("--runs", dict(default=None, help="timestep: comma-separated runs of tension, compression, pull (default all); "
                                       "repeats: likewise (default tension)")),
    ("--material", dict(default="appendixF", choices=sorted(sample.MATERIALS),
                        help="prepare: particle parameters, Appendix F of the long paper or Table 2 of Luding 2008")),
    ("--kc-over-kp", dict(type=float, default=None, help="prepare: overrides the set's kc/kp")),
    ("--n", dict(type=int, default=None, help="prepare: number of particles (1728; 216 with --quick)")),
    ("--packing", dict(default="full", choices=sample.PACKINGS,
                       help="factors: the law while the gas is compacted (full; frictionless: without "
                            "friction and adhesion)")),
    ("--glue", dict(default="loading", choices=sample.GLUES,
                    help="factors: the walls made adhesive after sintering (loading: the two x walls; all: six)")),
    ("--rel-std", dict(type=float, default=0.05,
                       help="factors: relative standard deviation of the radii (Gaussian, cut at 2 sigma; "
                            "default 0.05)")),
    ("--seed",
     dict(type=int, default=1,
          help="factors, fig16, fig18, affine, profile: the random seed of the gas (positions and radii): "
               "another realization of the preparation")),
    ("--sinter", dict(type=float, default=sample.SINTER,
                      help="factors, fig16, fig18, affine, profile: the sintering stress d0 p_s/kp "
                           "(the paper's 0.02)")),
    ("--returns", dict(default="length", choices=RETURNS,
                       help="fig16: where the cycles turn back: at Dx = 0 (length), or at the start's force (force), "
                            "walls at constant speed")),
    ("--test-kc-over-kp", dict(type=float, default=None,
                               help="fig16: the particles' kc/kp from the unconfined start on, every contact keeping "
                                    "its history (the same sample with another tensile stiffness)")),
    ("--test-limits", dict(default=None, choices=sorted(sample.LIMITS),
                           help="profile: the particles' sliding, rolling and torsion limits from the unconfined "
                                "start on (locked: never slip; free: none), every contact keeping its "
                                "history (issue #47, E7)")),
    ("--grips", dict(type=float, default=None, metavar="D",
                     help="fig16, profile: load through the particles within D d0 of each wall, moved as rigid grips, "
                          "instead of the flat walls (issue #47, E4)")),
    ("--drag",
     dict(default="contacts", choices=("contacts", "lab"),
          help="factors: the background drag's reference in the pull")),
    ("--table", dict(action="store_true", help="factors: only gather the table of the runs made")),
    ("--checkpoint", dict(action="store_true",
                          help="repeats: save each run every quarter cycle beside its bundle; started again, a run "
                               "goes on from its save (the same bit for bit wherever it stopped; to rounding the "
                               "same as a run without saves)")),
    ("--report", dict(default=None, metavar="DOCS",
                      help="factors: copy the study's files to DOCS/factors/ and write the table there from them")),
    ("--mpi", dict(type=int, default=None, metavar="N",
                   help="fig16, fig17, fig18: run under yade.mpy on N ranks (start with `mpiexec -n N yade -j1 -n "
                        "-x ...`; fig17 without crack events and snapshots)")),
)
# The periods a job runs when --periods is not given (FAST, SLOW otherwise).
DEFAULT_PERIODS = {"rates": RATE_PERIODS, "fig19": (FAST,), "fig16": PERIODS["tension"],
                   "repeats": PERIODS["tension"][:1]}
MPI_FIGURES = ("fig16", "fig17", "fig18")
PREPARATION_FIGURES = ("factors", "fig16", "fig18", "affine", "profile")  # the jobs that take --sinter and --seed


def batch_columns():
    """The yade-batch table's columns for the tablet jobs: every option, named with underscores,
    absent (None) unless the table gives it (mesocontact.batch.argv)."""
    return {flag[2:].replace("-", "_"): None for flag, _ in OPTIONS}


def parse_args(figure, argv):
    """The checked options of a tablet script: argparse's error (SystemExit 2, the option named)
    for any value outside its range, an unwritable --out included, before any work starts.
    Returns (namespace, amplitudes, slow_amplitudes, periods)."""
    import argparse
    job = JOBS.get(figure)  # ValueError naming an unknown job and the known ones
    p = argparse.ArgumentParser(prog=f"yade -n -x studies/scripts/tablet.py {figure}",
                                description=f"Appendix F, {figure}: {job.description} Writes CSV, JSON, PNG "
                                            f"(and VTK) into --out.")
    for flag, keywords in OPTIONS:
        p.add_argument(flag, **keywords)
    a = p.parse_args(argv)
    a.periods = a.periods or ",".join(f"{x:g}" for x in DEFAULT_PERIODS.get(figure, (FAST, SLOW)))
    _check_mpi(p, a, figure)
    n = a.n or (_stages.QUICK_N if a.quick else FULL["n"])
    if not 8 <= n <= 10 ** 6:
        p.error(f"--n {n} is invalid: between 8 and 1000000 particles")
    side = n ** (1 / 3)  # the sample's length in d0, roughly
    mode = {"fig18": "compression", "fig19": "compression"}.get(figure, "tension")
    amps = _numbers(p, "--amplitudes", a.amplitudes, 0, 0.5 * side if mode == "compression" else side,
                    f"a {mode} amplitude in d0 (the sample is about {side:.3g} d0 long)") if a.amplitudes else None
    slow = (_numbers(p, "--slow-amplitudes", a.slow_amplitudes, 0, side, "an amplitude in d0") if a.slow_amplitudes
            else None)
    a.factors = _numbers(p, "--factors", a.factors, 0, 10,
                         "a multiple of the campaign's time step") if a.factors else None
    a.runs = tuple(a.runs.split(",")) if a.runs else None
    if a.runs and not set(a.runs) <= set(TIMESTEP_RUNS):
        p.error(f"--runs {','.join(a.runs)}: each must be one of {', '.join(TIMESTEP_RUNS)}")
    if not (math.isfinite(a.sinter) and 0 < a.sinter <= 1):
        p.error(f"--sinter {a.sinter} is invalid: must lie in (0, 1], a sintering stress d0 p_s/kp")
    if _preparation(a) and figure not in PREPARATION_FIGURES:  # the others run on the campaign's sample only
        p.error(f"--sinter and --seed: only {', '.join(PREPARATION_FIGURES)} take another preparation (not {figure})")
    periods = _numbers(p, "--periods", a.periods, 1, 1e5,
                       "a cycle period in elastic crossing times (about 320 steps each)")
    _numbers(p, "--speed", str(a.speed), 0, 0.2, "a wall speed in mm/us (the sound speed is about 22)")
    if a.until is not None:
        _numbers(p, "--until", str(a.until), 0, 1e3, "the final Dx of the pull or compression in d0")
    _check_variants(p, a, figure, side)
    try:  # an unwritable --out fails now, not after the computation
        os.makedirs(a.out, exist_ok=True)
        with tempfile.NamedTemporaryFile(dir=a.out, prefix=".writable-"):
            pass  # a name of its own: two jobs sharing --out must not remove each other's probe
    except OSError as e:
        p.error(f"--out {a.out}: not writable ({e.strerror})")
    return a, amps, slow, periods


# Two groups of parse_args' checks, run at the same points as before they were split off (which keeps
# the order of the errors) so that each function stays within the complexity limit.
def _check_mpi(p, a, figure):
    if a.mpi is not None and figure not in MPI_FIGURES:
        p.error(f"--mpi {a.mpi}: only {', '.join(MPI_FIGURES)} run under yade.mpy (not {figure})")
    if a.mpi is not None and a.mpi < 2:
        p.error(f"--mpi {a.mpi} is invalid: a master and at least one worker (N >= 2)")
    if a.mpi is not None:
        try:
            use_mpi(a.mpi)
        except ValueError as e:
            p.error(str(e))


def _check_variants(p, a, figure, side):
    if (a.returns != "length" or a.test_kc_over_kp is not None) and figure != "fig16":
        p.error(f"--returns and --test-kc-over-kp: only fig16 runs these variants (not {figure})")
    if a.test_limits is not None and figure != "profile":
        p.error(f"--test-limits: only profile runs this variant (not {figure})")
    if a.grips is not None and figure not in ("fig16", "profile"):
        p.error(f"--grips: only fig16 and profile load through grips (not {figure})")
    if a.grips is not None and not (math.isfinite(a.grips) and 0.25 <= a.grips <= 0.25 * side):
        p.error(f"--grips {a.grips} is invalid: must lie in [0.25, {0.25 * side:.3g}] d0 (a quarter of the sample)")
    if a.grips is not None and a.mpi is not None:
        p.error("--grips: without --mpi")
    if a.returns != "length" and a.mpi is not None:
        p.error("--returns force: without --mpi (the turns are decided every few steps from the walls)")
    if a.test_kc_over_kp is not None and not (math.isfinite(a.test_kc_over_kp) and 0 <= a.test_kc_over_kp <= 100):
        p.error(f"--test-kc-over-kp {a.test_kc_over_kp} is invalid: must lie in [0, 100]")
    if a.kc_over_kp is not None and not (math.isfinite(a.kc_over_kp) and 0 <= a.kc_over_kp <= 100):
        p.error(f"--kc-over-kp {a.kc_over_kp} is invalid: must lie in [0, 100]")


def main(figure, argv):
    """Command line of the tablet scripts (prepare, rates, fig16 ... fig19)."""
    a, amps, slow, periods = parse_args(figure, argv)
    if _mpy() is None:
        return _main(figure, a, amps, slow, periods)
    _mpi.run_ranks(_mpy(), lambda: _main(figure, a, amps, slow, periods))


def _main(figure, a, amps, slow, periods):
    if is_master():
        _out.sweep(a.out)
    t0 = time.time()
    out = JOBS.get(figure).function(a, amps, slow, periods)
    if not is_master():
        return
    print(json.dumps(out, indent=1, default=str)[:4000])
    print(f"{figure} done in {time.time() - t0:.0f} s; outputs in {os.path.abspath(a.out)}", flush=True)


def _prepare(a, amps, slow, periods):
    info = prepare(a.out, a.quick, material=a.material, kc_over_kp=a.kc_over_kp, n=a.n)
    return {k: info[k] for k in ("compacted", "sintered", "released", "unconfined") if k in info}


def _timestep(a, amps, slow, periods):
    return timestep_study(a.out, a.quick, factors=a.factors or TIMESTEP_FACTORS + (PERTURBED,) + PERTURBED_MORE,
                          runs=a.runs or TIMESTEP_RUNS)


def _factors(a, amps, slow, periods):
    if a.report:
        return factor_report(a.out, a.report)
    if not a.table:
        factor_run(a.out, a.packing, a.glue, a.drag, a.quick, rel_std=a.rel_std, seed=a.seed, sinter=a.sinter)
    return factor_table(a.out, a.quick)


# The tablet's jobs, in the order --help lists them: each runs with the parsed options (a, amps,
# slow, periods); the ones that count in a campaign's plan (report.plan) carry their estimate of
# steps. A new job is a driver (runs.py or a module of its own) and one record here; its options
# join OPTIONS if it needs new ones.
JOBS = Registry([
    Job("prepare", _prepare, "the sample, made once and cached in --out."),
    Job("drag", lambda a, amps, slow, periods: drag_share(a.out, a.quick),
        "the share of the tension peak the background drag supplies.", cost=drag_steps),
    Job("timestep", _timestep, "the time-step convergence study."),
    Job("rates", lambda a, amps, slow, periods: rates(a.out, a.quick, amplitude=(amps or (0.2,))[0], periods=periods,
                                                      run_missing=not a.no_run),
        "the cycles of one amplitude at three periods.", cost=rates_steps),
    Job("fig16", lambda a, amps, slow, periods: cyclic("tension", a.out, amps, a.quick, periods, slow_amplitudes=slow,
                                                       protocol=_preparation(a), returns=a.returns,
                                                       kc_over_kp=a.test_kc_over_kp, grips=a.grips),
        "tension cycles (Fig. 16).", cost=tension_steps),
    Job("fig17", lambda a, amps, slow, periods: pull(a.out, a.quick, speed=a.speed, until=a.until or 9.0),
        "the pull to rupture with snapshots (Fig. 17).", cost=pull_steps),
    Job("fig18", lambda a, amps, slow, periods: cyclic("compression", a.out, amps, a.quick, periods,
                                                       slow_amplitudes=slow, protocol=_preparation(a)),
        "compression cycles (Fig. 18).", cost=compression_steps),
    Job("fig19", lambda a, amps, slow, periods: large_compression(a.out, a.quick, speed=a.speed,
                                                                  until=a.until or 3.0),
        "compression to large strain with snapshots (Fig. 19).", cost=large_compression_steps),
    Job("factors", _factors, "one pull of the factor study (a preparation), then its table."),
    Job("repeats", lambda a, amps, slow, periods: repeats(a.out, amps or REPEAT_AMPLITUDES,
                                                          a.factors or REPEAT_FACTORS, periods, a.quick,
                                                          checkpoint=a.checkpoint, modes=a.runs or ("tension",),
                                                          until=a.until or REPEAT_PULL_UNTIL),
        "the tested sample's tension cycles (--runs: also compression cycles, the pull) with the campaign's step "
        "perturbed by 1e-6 .. 5e-6 (issue #60): the spread of single runs' post-peak verdicts."),
    Job("affine", lambda a, amps, slow, periods: affine_run(a.out, a.quick, protocol=_preparation(a)),
        "the pull an affine stretch of the unconfined start's contacts would give (no steps run)."),
    Job("profile", lambda a, amps, slow, periods: profile_run(a.out, a.quick, protocol=_preparation(a),
                                                              until=a.until or 0.3, grips=a.grips,
                                                              limits=a.test_limits),
        "the pull's first part with the strain by slab and the contacts' branches against an affine stretch."),
    Job("slaved", lambda a, amps, slow, periods: slaved_job(a.out, a.quick, until=a.until or 0.3, speed=a.speed),
        "the pull to Dx 0.3 with the particles slaved to the affine stretch against the free pull and the static "
        "estimate: the tested sample and the deep one through 2-d0 grips (issue #60)."),
])


def _preparation(a):
    """The options of --sinter and --seed that differ from the campaign's preparation (recorded
    in each run's JSON only then, so that the campaign's own runs stay as they were)."""
    return dict(**({"sinter": a.sinter} if a.sinter != sample.SINTER else {}),
                **({"seed": a.seed} if a.seed != 1 else {}))


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
