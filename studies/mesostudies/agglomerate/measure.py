"""What the agglomerates do that a law must reproduce (issue #59, item 2), on the campaign's pair
(block seed 1, or --seeds' first):

- ``rate``: the pair's cycles (amplitudes 0.1, 0.2 d0) with each cap at collision-like speeds
  (RATE_SPEEDS m/s, relative speeds twice that): is the loss per cycle rate-dependent?
- ``rate_energy``: the same cycles at 0.625, 2.5, 10 and 40 m/s per cap with the law's energy
  tracked, each term read at every turn: the loss per loop by term, independent of the caps' force;
- ``pulls``: for each amplitude of PULL_AMPLITUDES, a fresh pair pressed once at the fit's slow
  cap speed (0.625 m/s) and pulled until no contact joins them (at most MAX_PULL d0 below the
  touch): the tension's work and range against the press.

Each run writes <name>.csv (iter, delta, F) and <name>.json (its events) in the pair's folder and
is skipped when they exist. A pull saves itself every CHECKPOINT_STEPS steps in its last stroke
(<name>.checkpoint.yade.gz and .json) and a new process goes on from there, row for row.
"""
import json
import os

from yade import O

from mesocontact import outputs
from mesocontact.bulk import pair_cycles
from . import make
from .primaries import SCALES

RATE_SPEEDS = (10.0, 40.0)                 # m/s per cap
RATE_AMPLITUDES = (0.1, 0.2)               # d0 beyond the touch, as the slow fit's run
ENERGY_SPEEDS = (0.625, 2.5, 10.0, 40.0)   # m/s per cap: the fit's two runs' and the rate check's
PULL_AMPLITUDES = (0.02, 0.05, 0.1, 0.2)   # d0 beyond the touch
PULL_SPEED = 0.625                         # m/s per cap, the fit's run
MAX_PULL = 8.0                             # d0 below the touch (the slow cycles were still joined at 1.5)
CHECKPOINT_STEPS = 200000                  # a pull's saves (Pair.pull_apart): about 0.36 d0, 7 min of one core


def _one(d, name, seed, quick, amplitudes, speed_m_s, final, max_pull=pair_cycles.MAX_PULL, energy=False):
    base = os.path.join(d, name)
    if os.path.exists(base + ".json") and os.path.exists(base + ".csv"):
        return
    info = make.ensure(d, quick=quick, seed=seed)
    if energy:  # the law's dissipation by term at each turn (Pair.event_energy)
        O.energy.clear()
        O.trackEnergy = True
    print(f"{name}: amplitudes {amplitudes} d0, {speed_m_s:g} m/s per cap", flush=True)
    it0 = O.iter
    checkpoint = base + ".checkpoint.yade.gz" if final else None  # a pull apart takes hours: saved on the way
    if checkpoint and os.path.exists(checkpoint + ".json"):
        pair = pair_cycles.Pair.load(checkpoint)
        print(f"  resumed at step {O.iter} from {checkpoint}", flush=True)
        rows = pair.pull_apart(speed_m_s / 1e3, max_pull, checkpoint=checkpoint, checkpoint_steps=CHECKPOINT_STEPS)
    else:
        pair = pair_cycles.Pair(info["members"], [g["radius"] for g in info["agglomerates"]], protocol=SCALES)
        rows = pair.cycles(amplitudes, speed_m_s / 1e3, final=final, max_pull=max_pull, checkpoint=checkpoint,
                           checkpoint_steps=CHECKPOINT_STEPS)
    outputs.write_atomic(base + ".csv", "iter,delta_mm,F\n" + "".join(f"{r[0]},{r[1]!r},{r[2]!r}\n" for r in rows))
    info = {"speed_per_cap_m_s": speed_m_s, "amplitudes_d0": list(amplitudes), "touch_delta_mm": pair.touch,
            "events": pair.events, "max_pull_d0": max_pull if final else None, "steps": O.iter - it0,
            "wall_clock_s": pair.elapsed(), "dt": O.dt, "units": "delta mm, F mg mm/us^2 (1e3 N)"}
    if energy:
        info["event_energy"] = pair.event_energy  # O.energy's terms in the study's unit (1e3 N mm = 1 J)
    outputs.write_atomic(base + ".json", json.dumps(info, indent=1))


def rate(d, seed=1, quick=False, speeds=RATE_SPEEDS):
    for v in speeds:
        _one(d, f"rate-cycles-v{v:g}", seed, quick, RATE_AMPLITUDES, v, final=False)


def rate_energy(d, seed=1, quick=False, speeds=ENERGY_SPEEDS):
    """The pair's cycles (RATE_AMPLITUDES) at each cap speed with the law's energy tracked: where
    each loop's work goes (loss.dissipated), read inside the agglomerates, not through the caps'
    force (which carries the free parts' inertia at collision-like speeds)."""
    for v in speeds:
        _one(d, f"energy-cycles-v{v:g}", seed, quick, RATE_AMPLITUDES, v, final=False, energy=True)


def pulls(d, seed=1, quick=False, amplitudes=PULL_AMPLITUDES):
    for a in amplitudes:
        _one(d, f"pull-a{a:g}-v{PULL_SPEED:g}", seed, quick, (a,), PULL_SPEED, final=True, max_pull=MAX_PULL)
