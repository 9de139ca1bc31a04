"""The tablet campaign's shared ground: its constants (amplitudes, periods, time-step factors, the
protocol), where runs live, their CSV, and whether this process runs under yade.mpy (inside ``yade``)."""
import os

from mesocontact.outputs import read_csv  # noqa: F401 (the campaign's modules read their CSVs with it)
from .. import stages as _stages

# yade.mpy when the campaign runs under mpiexec with --mpi N (use_mpi), else None
_MPY = None


def use_mpi(ranks):
    """Runs the cyclic tests of this process under yade.mpy on ``ranks`` MPI processes (a master
    holding the walls and ranks - 1 workers; the process must have been started by
    ``mpiexec -n ranks``). Every rank computes, the master writes. Returns the mpy module."""
    global _MPY
    from yade import mpy as module  # configures MPI on import
    if module.numThreads != ranks:
        raise ValueError(f"--mpi {ranks}: start this job with `mpiexec -n {ranks} yade ...` (it has "
                         f"{module.numThreads} process(es))")
    _MPY = module
    return module


def mpy():
    """yade.mpy when this process runs the campaign under MPI (use_mpi), else None."""
    return _MPY


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
# The periods of the figures (thin, thick), from the rate checks (docs/tablet/first-protocol.md (commit 410fda8),
# section 4): compression agrees within 0.6 % between 120 and 480 t_w in every cycle; tension does not (the
# re-loading cycles 6.5 % apart at Dx = 0.2) but agrees within 1.95 % between 480 and 1920 t_w
# at every amplitude (0.025 to 0.3).
PERIODS = {"tension": (480.0, 1920.0), "compression": (120.0, 480.0)}
# Fig. 17: each wall's speed [mm/us]: the peak wall speed of 240 t_w cycles at Dx = 0.2, where the first pull's peak
# agrees within 2.2 % from 120 t_w on (Dx = 9 in about 1 040 000 steps)
PULL_SPEED = 0.0025
FAST, SLOW = PERIODS["compression"]
GAP_AREA = 1.0  # a crack (or see-through hole) this large [d0^2] counts as visible
# The campaign's time step per test, as a multiple of tablet.contact_step (t_c/50), from the
# time-step study (campaigns/tablet/timestep.md): the largest factor whose outcome stays within 0.5 %
# of 1 dt, or within the spread of perturbed runs where that is larger.
DT_FACTORS = {"tension": 3.0, "compression": 4.0, "pull": 1.0}


# The preparation the campaign's tests start from (tablet.prepare's packing, glue, rel_std), chosen
# by the factor study (campaigns/tablet/factors/factors.md): packed without friction and adhesion, all
# six walls adhesive through sintering, radii spread 0.1 - the only preparation that meets the
# paper's L0 and first gap (its tear is still next to a wall). Every run records it; a run made
# from another preparation is made again, not read back.
FIRST_PROTOCOL = {"packing": "full", "glue": "loading", "rel_std": 0.05}  # what a run without a record was made from
PROTOCOL = {"packing": "frictionless", "glue": "sinter", "rel_std": 0.1}


def protocol_of(info):
    """The preparation a run's description records (FIRST_PROTOCOL for runs made before records)."""
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


def csv_text(rows, header="iter,Dx,F_over_kp_d0"):
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


def stroke_peaks(rows, turns):
    """The most tensile force (min F) of each cycle of uniaxial.Test.force_cycles: a cycle ends
    where its return stroke does (every second turn)."""
    ends = [t[0] for t in turns[1::2]]
    peaks, k = [], 0
    for end in ends:
        cycle = [r[2] for r in rows[k:] if r[0] <= end]
        k += len(cycle)
        peaks.append(min(cycle) if cycle else None)
    return peaks
