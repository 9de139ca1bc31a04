"""Two agglomerates as meso-particles (inside ``yade``): the law fitted to their cycles, checked
against their collisions, in one call.

    from mesocontact.bulk import agglomerate, coarse
    members, R, loose = agglomerate.carve_pair()            # or any two lists of body ids
    agglomerate.relax(members)
    radii = [agglomerate.describe(m)["radius"] for m in members]
    cg = coarse.coarse_grain(members, radii, speeds=(1e-4, 1e-3, 1e-2), directions=3, out="cg")
    print(cg.report())
    mat = cg.mesomat()                                       # a yade MesoMat of the meso-particle

Everything is in the scene's units (any consistent set; d0 and kp come from the Protocol, the
``protocol`` argument, else the scene's). Each stage starts from the scene as given (saved once,
loaded before each stage, loaded back at the end):

1. **cycles**: ``bulk.pair_cycles.Pair.cycles`` (the far caps gripped and moved at ``cap_speed``,
   default wave_speed/8000, about the tablet's pull speed, loading to each of ``amplitudes`` d0
   beyond the first touch and unloading 0.2 d0 below it, then pulled apart);
2. **fit**: ``calibrate.fit_cycles`` with a free overlap offset (the outer spheres' overlap is not
   where the surfaces touch), a12 = 2 R1 R2/(R1 + R2) as the law's Ip2 computes it;
3. **collisions**: ``bulk.collisions.Collision`` at each of ``speeds`` along each approach direction
   (x, as carved, then drawn uniformly on the sphere: ``agglomerate.directions``);
4. **the meso-particle**: MesoMat keywords (the fitted k1, kp, kc, phiF; density from the mean
   mass and outer radius; gammaN 0 and no friction, rolling or torsion: the quasi-static,
   head-on cycles do not see them) and its pair's e at each speed from the closed form
   (``theory.pair_collision``, which YADE's pair reproduces to 1e-4: yade.restitution);
5. **the verdict** per speed: the agglomerates' mean e over the directions, its range, the
   meso-particle's e; the law holds where |mean - meso| <= ``tolerance`` and no collision broke off
   more than 1 % of the mass. ``holds_below``: the first speed where it does not.

With ``out``, the folder receives cycles.csv, coarse-grained.json and coarse-grained.png. The scene
given back is the one saved at the start, loaded: as after any O.load, its contacts' geometry
(penetrationDepth) is made by the next step.
"""
import dataclasses
import json
import math
import numbers
import os
import tempfile

try:
    from yade import O
    from yade import wrapper as _w
except ImportError as _exc:  # pragma: no cover - outside yade
    raise ImportError("mesocontact.bulk.coarse needs YADE: run it inside `yade`") from _exc

from .. import calibrate
from .. import checks as _checks
from .. import outputs
from .. import params as _params
from .. import theory
from . import agglomerate
from . import pair_cycles
from . import sample
from .collisions import Collision

AMPLITUDES = (0.1, 0.2)      # d0 beyond the first touch
FRAGMENTED = 0.01            # the mass broken off above which a collision is fragmentation
NOT_FROM_CYCLES = ("gammaN: the cycles are quasi-static (set 0)",
                   "friction, rolling and torsion: the cycles are head-on (set 0)")


@dataclasses.dataclass
class CoarseGrained:
    """The outcome of ``coarse_grain`` (scene units)."""
    fit: object                  # calibrate.CycleFit of the pair's cycles
    material: dict               # MesoMat keywords of the meso-particle
    radii: list
    masses: list
    speeds: list
    directions: list             # approach axes
    e_agglomerates: list         # [speed][direction]; 0 when stuck
    broken: list                 # [speed][direction]: mass broken off over the total
    e_meso: list                 # [speed]: the meso pair's closed-form e
    tolerance: float
    cycle_rows: list             # (iter, delta, F) of the cycles
    d0: float
    kp: float

    def mean_e(self):
        return [sum(row) / len(row) for row in self.e_agglomerates]

    def holds(self):
        """Per speed: |mean e - meso e| <= tolerance and no fragmentation."""
        return [abs(m - e) <= self.tolerance and max(b) <= FRAGMENTED
                for m, e, b in zip(self.mean_e(), self.e_meso, self.broken)]

    def holds_below(self):
        """The first speed (ascending) at which the law does not hold (None: at none)."""
        bad = [v for v, ok in sorted(zip(self.speeds, self.holds())) if not ok]
        return bad[0] if bad else None

    def mesomat(self, **overrides):
        """A yade MesoMat of the meso-particle (keywords override the fitted ones)."""
        return _w.MesoMat(**{**self.material, **overrides})

    def to_json(self):
        return {"material": self.material, "fit": self.fit.to_json(), "radii": self.radii, "masses": self.masses,
                "speeds": self.speeds, "directions": [list(a) for a in self.directions],
                "e_agglomerates": self.e_agglomerates, "e_mean": self.mean_e(),
                "e_range": [[min(r), max(r)] for r in self.e_agglomerates], "broken_mass_fraction": self.broken,
                "e_meso": self.e_meso, "tolerance": self.tolerance, "holds": self.holds(),
                "holds_below": self.holds_below(), "undetermined": self.undetermined(),
                "d0": self.d0, "kp": self.kp}

    def undetermined(self):
        """What the cycles cannot determine, in words."""
        return ([f"{n}: {self.fit.bound(n)} (the value given is one of many that fit as well)"
                 for n in self.fit.undetermined] + list(self.fit.statements) + list(NOT_FROM_CYCLES))

    def report(self):
        lines = ["The law fitted to the cycles:", self.fit.report(), "",
                 f"{'speed':>10s} {'e agglomerates (mean, range)':>30s} {'e meso':>8s} {'holds':>6s}"]
        for v, m, row, e, ok in zip(self.speeds, self.mean_e(), self.e_agglomerates, self.e_meso, self.holds()):
            lines.append(f"{v:10.4g} {m:12.3f} [{min(row):.3f}, {max(row):.3f}]{'':6s} {e:8.3f} "
                         f"{'yes' if ok else 'no':>6s}")
        below = self.holds_below()
        lines.append("the law holds at every speed" if below is None else
                     f"the law holds below {below:g} only (the slowest speed where |mean - meso| > "
                     f"{self.tolerance:g} or a collision fragments)")
        if self.fit.undetermined:
            lines.append("e meso is the fit's point: it depends on " + ", ".join(self.fit.undetermined)
                         + ", which the cycles do not fix (another point that fits as well gives another e)")
        lines += ["not determined by the cycles:"] + ["  " + t for t in self.undetermined()]
        return "\n".join(lines)

    def plot(self, path):
        """Two panels: (a) the cycles' F(delta) and the fitted law; (b) e against speed, each
        direction's, their mean and the meso-particle's, with the tolerance band."""
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
        d = [r[1] / self.d0 for r in self.cycle_rows]
        a.plot(d, [r[2] / (self.kp * self.d0) for r in self.cycle_rows], lw=0.8, label="agglomerates")
        a.plot(d, [f / (self.kp * self.d0) for f in self.fit.curve([r[1] for r in self.cycle_rows])], "--",
               lw=1.0, label="fitted law")
        a.set_xlabel(r"meso-overlap $\delta/d_0$")
        a.set_ylabel(r"$F/(k_p d_0)$")
        a.set_title("(a) cycles and the fitted law", loc="left")
        a.legend()
        for k in range(len(self.directions)):
            b.plot(self.speeds, [row[k] for row in self.e_agglomerates], "o", ms=3, color="0.6",
                   label="agglomerates, each direction" if k == 0 else None)
        b.plot(self.speeds, self.mean_e(), "o-", color="C0", label="agglomerates, mean")
        b.plot(self.speeds, self.e_meso, "s--", color="C1", label="meso-particle (fitted law)")
        b.fill_between(self.speeds, [e - self.tolerance for e in self.e_meso],
                       [e + self.tolerance for e in self.e_meso], color="C1", alpha=0.15, label="tolerance")
        b.set_xscale("log")
        b.set_ylim(min([-0.05] + [x - 0.05 for row in self.e_agglomerates for x in row]), 1.05)
        b.set_xlabel("relative speed (scene units)")
        b.set_ylabel("coefficient of restitution e")
        b.set_title("(b) collisions", loc="left")
        b.legend(fontsize=8)
        fig.tight_layout()
        outputs.savefig_atomic(fig, path, dpi=120)
        plt.close(fig)

    def write(self, folder):
        """cycles.csv, coarse-grained.json and coarse-grained.png in ``folder``."""
        os.makedirs(folder, exist_ok=True)
        outputs.write_atomic(os.path.join(folder, "cycles.csv"),
                             "iter,delta,F\n" + "".join(f"{r[0]},{r[1]!r},{r[2]!r}\n" for r in self.cycle_rows))
        outputs.write_atomic(os.path.join(folder, "coarse-grained.json"), json.dumps(self.to_json(), indent=1))
        self.plot(os.path.join(folder, "coarse-grained.png"))


def _sequence(name, values):
    if isinstance(values, (str, bytes, dict)) or not hasattr(values, "__len__") or not len(values):
        raise ValueError(f"{name} = {values!r} is invalid: a non-empty sequence of positive numbers")
    for k, x in enumerate(values):
        _checks.positive(f"{name}[{k}]", x)
    return [float(x) for x in values]


def _axes(directions, seed):
    if isinstance(directions, numbers.Integral) and not isinstance(directions, bool):
        if directions < 1:
            raise ValueError(f"directions = {directions!r} is invalid: a count >= 1 or a list of axes")
        return agglomerate.directions(directions, seed)
    if isinstance(directions, (str, bytes)) or not hasattr(directions, "__len__") or not len(directions):
        raise ValueError(f"directions = {directions!r} is invalid: a count >= 1 or a list of axes")
    for a in directions:
        agglomerate.axis_frame(a)  # refuses a bad axis, naming it
    return [tuple(float(x) for x in a) for a in directions]


def coarse_grain(members, radii, speeds, directions=1, amplitudes=AMPLITUDES, cap_speed=None, tolerance=0.1,
                 out=None, protocol=None, progress=True, direction_seed=1):
    """The module's five stages on the two agglomerates ``members`` (lists of body ids) of outer
    radii ``radii``; returns a CoarseGrained. Every argument is checked before any work."""
    agglomerate.check_pair(members, radii)
    speeds = _sequence("speeds", speeds)
    amplitudes = _sequence("amplitudes", amplitudes)
    axes = _axes(directions, direction_seed)
    _checks.positive("tolerance", tolerance)
    if cap_speed is not None:
        _checks.positive("cap_speed", cap_speed)
    if out is not None and not isinstance(out, str):
        raise TypeError(f"out = {out!r} is invalid: a folder name (or None)")
    p = sample.resolve(protocol)
    cap_speed = p.wave_speed() / 8000 if cap_speed is None else cap_speed
    masses = [agglomerate.centre_of_mass(m)[1] for m in members]
    fd, saved = tempfile.mkstemp(suffix=".yade.gz", prefix="coarse-")
    os.close(fd)
    O.save(saved)
    try:
        if progress:
            print(f"coarse_grain: cycles at {cap_speed:g} per cap, amplitudes {amplitudes} d0", flush=True)
        pair = pair_cycles.Pair(members, radii, progress=progress, protocol=p)
        rows = [tuple(r) for r in pair.cycles(amplitudes, cap_speed)]
        a12 = _params.reduced_radius(*radii)  # as YADE's Ip2 computes it
        fit = calibrate.fit_cycles([r[1] for r in rows], [r[2] for r in rows], a12, shift=True)
        if progress:
            print(fit.report(), flush=True)
        e_agg, broken = [], []
        for v in speeds:
            e_agg.append([])
            broken.append([])
            for axis in axes:
                O.load(saved)
                r = Collision(members, radii, axis=axis, protocol=p).run(v, progress=False)
                e_agg[-1].append(r["e"])
                broken[-1].append(r["broken_mass_fraction"])
                if progress:
                    print(f"coarse_grain: collision at {v:g} along {tuple(round(x, 3) for x in axis)}: "
                          f"e = {r['e']:.4f}, broken off {r['broken_mass_fraction']:.3f}", flush=True)
    finally:
        O.load(saved)
        os.remove(saved)
    m_r = _params.reduced_mass(*masses)
    fp = fit.params
    e_meso = [theory.pair_collision(v, fp["k1"], fp["kp"], fp["kc"], fp["phiF"], a12, m_r).e for v in speeds]
    r_mean, m_mean = sum(radii) / 2, sum(masses) / 2
    material = dict(density=m_mean / (4.0 / 3.0 * math.pi * r_mean ** 3), k1=fp["k1"], kp=fp["kp"], kc=fp["kc"],
                    phiF=fp["phiF"], gammaN=0.0, frictionAngle=0.0)
    cg = CoarseGrained(fit, material, list(radii), masses, speeds, axes, e_agg, broken, e_meso, float(tolerance),
                       rows, p.d0, p.kp)
    if out is not None:
        cg.write(out)
    return cg
