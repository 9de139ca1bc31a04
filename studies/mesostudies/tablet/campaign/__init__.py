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

The package, by job: ``common`` (constants, run places, the MPI mode), ``runs`` (every test the
figures need), ``plots`` (their pictures) and ``report`` (tables, the docs copy, plan and totals,
the jobs' step estimates). The jobs' registry and command line are the tablet's ``cli``, above
this package (it imports this package; nothing here imports it). What the scripts and tests use is
reachable here; the rest from its module.
"""
from .common import (
    DT_FACTORS, FIG17_DX, FIRST_PROTOCOL, PERIODS, PROTOCOL, PULL_SPEED, cycle_peaks, is_master, mpy,
    prepare, protocol_of, read_csv, root, run_dir, run_name, use_mpi,)
from .runs import (
    cyclic, drag_share, factor_dir, factor_run, large_compression, pull, rates, run_cycles,
    timestep_study, timestep_table,)
from .report import factor_report, factor_table, log_job, peaks_table, plan, report, restore, totals

__all__ = [
    "DT_FACTORS", "FIG17_DX", "FIRST_PROTOCOL", "PERIODS", "PROTOCOL", "PULL_SPEED", "cycle_peaks", "is_master", "mpy",
    "prepare", "protocol_of", "read_csv", "root", "run_dir", "run_name", "use_mpi", "cyclic", "drag_share",
    "factor_dir", "factor_run", "large_compression", "pull", "rates", "run_cycles", "timestep_study", "timestep_table",
    "factor_report", "factor_table", "log_job", "peaks_table", "plan", "report", "restore", "totals",
]
