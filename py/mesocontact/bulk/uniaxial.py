"""Unconfined uni-axial tension and compression of a released bulk sample (inside ``yade``).

The tests start from the unconfined start (``make_unconfined`` on a sample of
``bulk.prepare``): the four lateral walls erased with their contacts (unconfined: no lateral
stress at all), the stress controller removed, and the sample, glued to the adhesive x walls
(bulk.sample.make_adhesive_walls), relaxed again with the x walls held at p_r; the background
drag acts relative to each particle's contacts, so a part of the sample moving as a body is not
dragged. From there the two x walls (or grips of the sample's own particles) move symmetrically:

- ``cycles``: cosine strain cycles to an amplitude Dx and back, L(t) = L0 -+ Dx d0 (1 - cos wt)/2,
  driven by YADE's ``HarmonicMotionEngine`` (one per wall); a cycle is a whole number of steps,
  so the walls return to L0 to rounding;
- ``pull``: a monotonic pull at constant wall speed (YADE's ``TranslationEngine``).

Recorded: Dx = (L - L0)/d0 (> 0 in tension) and the force on the loading walls,
F = (f_right - f_left)/2 along x, > 0 when the sample pushes the walls (compression). Lengths
and forces are reported over the protocol's d0 and kp d0 (bulk.protocol; read from the scene).
"""
import math
import time

try:
    from yade import O
    from yade import wrapper as _w
    from yade import Vector3
    from yade import plot as _plot
except ImportError as _exc:  # pragma: no cover - outside yade
    raise ImportError("mesocontact.bulk.uniaxial needs YADE: run it inside `yade`") from _exc

from .. import checks as _checks
from .. import loop as _loop
from .. import scene as _scene
from . import checkpoint as _checkpoint
from . import protocol as _protocol
from . import records as _records
from . import sample

MODES = ("tension", "compression")


def check_mode(mode):
    """The sign of the walls' motion for a test mode (tension +1, compression -1); a ValueError
    naming any other mode."""
    if mode not in MODES:
        raise ValueError(f"mode = {mode!r} is invalid: must be 'tension' or 'compression'")
    return 1.0 if mode == "tension" else -1.0


def crossing_time(protocol=None):
    """Time an elastic wave needs to cross the sample along x: L0/c with c = d0 sqrt(kp/m) of
    the mean particle (a linear chain of springs kp and masses m at spacing d0)."""
    p = sample.resolve(protocol)
    ids = sample.sphere_ids()
    m = sum(O.bodies[i].state.mass for i in ids) / len(ids)
    lo, hi = sample.inner_box()
    return (hi[0] - lo[0]) / (p.d0 * math.sqrt(p.kp / m))


def before_newton(extra):
    """O.engines with ``extra`` inserted right before the NewtonIntegrator (the last engine in a
    serial scene; yade.mpy appends its communication engines after it)."""
    engines = list(O.engines)
    at = next(k for k, e in enumerate(engines) if isinstance(e, _w.NewtonIntegrator))
    O.engines = engines[:at] + list(extra) + engines[at:]


def _wall_stiffness(wid):
    return sum(i.phys.kn for i in O.interactions if i.isReal and wid in (i.id1, i.id2) and i.geom.penetrationDepth > 0)


class _Servo:
    """Holds the two x walls at the force target: each step a wall moves by a fraction of
    (force error)/(stiffness of its contacts), as YADE's TriaxialStressController does."""

    def __init__(self, left, right, target, kp, v_max, gain=0.5):
        self.left, self.right, self.target, self.gain, self.v_max = left, right, target, gain, v_max
        self.kp = kp
        self.k = {}

    def __call__(self):
        if O.iter % 100 == 0 or not self.k:
            self.k = {w: max(_wall_stiffness(w), self.kp) for w in (self.left, self.right)}
        for wid, outward in ((self.right, 1.0), (self.left, -1.0)):
            push = outward * O.forces.f(wid)[0]  # > 0: the sample pushes the wall out
            v = self.gain * (push - self.target) / (self.k[wid] * O.dt)
            O.bodies[wid].state.vel = Vector3(outward * max(-self.v_max, min(self.v_max, v)), 0, 0)


def make_unconfined(progress=True, tol_force=1e-4, tol_ke=1e-4, max_steps=200000, protocol=None, v_max=None):
    """Turns the loaded released state into the common start of the uni-axial tests: the four
    lateral walls erased with their contacts (no lateral stress), the stress controller
    removed, and the sample (glued to the two x walls since sintering) relaxed again
    with the x walls held at the release stress p_r (the lateral walls had held it), until the
    wall force is within tol_force kp d0 of p_r L_y L_z and the kinetic energy below tol_ke of
    the energy scale; the background drag then acts relative to the contacts, as in the tests.
    v_max: the x walls' largest speed meanwhile (default: the protocol's holding_speed()).
    Returns the description of this stage."""
    return _held_at_release(True, progress, tol_force, tol_ke, max_steps, protocol, v_max)


def make_confined(progress=True, tol_force=1e-4, tol_ke=1e-4, max_steps=200000, protocol=None, v_max=None):
    """The start of a die test: as make_unconfined, but the four lateral walls stay where the
    release left them, fixed (the die), with their contacts; the x walls are the pistons. Then
    ``Test.compress`` compacts in the die and ``Test.pull`` pulls back."""
    return _held_at_release(False, progress, tol_force, tol_ke, max_steps, protocol, v_max)


def _held_at_release(erase_lateral, progress, tol_force, tol_ke, max_steps, protocol, v_max):
    p = sample.resolve(protocol)
    v_max = p.holding_speed() if v_max is None else v_max
    for name, value in (("tol_force", tol_force), ("tol_ke", tol_ke), ("v_max", v_max)):
        _checks.positive(name, value)
    _whole("max_steps", max_steps)
    walls = sample.wall_ids()
    if not {"left", "right"} <= set(walls):
        raise ValueError("this scene has no x walls: make the sample with bulk.prepare")
    lo, hi = sample.inner_box()
    area = (hi[1] - lo[1]) * (hi[2] - lo[2])
    lateral = [walls[name] for name in ("bottom", "top", "back", "front") if name in walls]
    if erase_lateral:
        for i in lateral:
            O.bodies.erase(i)
    else:
        for i in lateral:
            O.bodies[i].state.vel = Vector3(0, 0, 0)
    O.engines = [e for e in O.engines if not isinstance(e, _w.TriaxialStressController)]
    target = p.release_stress * area
    before_newton([_loop.runner(_Servo(walls["left"], walls["right"], target, p.kp, v_max=v_max), 1, "servo")])
    scale = p.kp * p.d0
    stage = "unconfined relaxation" if erase_lateral else "relaxation in the die"

    def measure():
        err = max(abs(s * O.forces.f(w)[0] - target) for w, s in ((walls["right"], 1), (walls["left"], -1))) / scale
        ke = sample.kinetic_energy() / sample.energy_scale(len(sample.sphere_ids()), p)
        return err < tol_force and ke < tol_ke, f"|F - p_r A|/(kp d0) = {err:.2e}  E_kin/E_ref = {ke:.2e}", (err, ke)

    steps, (err, ke) = sample.run_until_static(measure, stage, max_steps=max_steps, progress=progress)
    O.engines = [e for e in O.engines if e.label != "servo"]
    for w in (walls["left"], walls["right"]):
        O.bodies[w].state.vel = Vector3(0, 0, 0)
    for e in O.engines:
        if isinstance(e, _w.MesoBackgroundDamping):
            e.reference = "contacts"
    return {"steps": steps, "force_error": err, "kinetic_energy_ratio": ke, "target_force": target,
            "stats": sample.stats(p)}


def _whole(name, value):
    if isinstance(value, bool) or not isinstance(value, int) or value < 1:
        raise ValueError(f"{name} = {value!r} is invalid: a positive whole number")


def _cycle_arguments(amplitude, n_cycles, every):
    _checks.positive("amplitude", amplitude)
    if not (_checks.is_number(n_cycles) and math.isfinite(n_cycles) and int(n_cycles) == n_cycles >= 1):
        raise ValueError(f"n_cycles = {n_cycles!r} is invalid: a positive integer")
    if every is not None:
        _whole("every", every)


def crossing_profile(spacing=0.25, protocol=None):
    """The contacts in overlap that cross each plane x = const between the loading walls' inner
    faces, planes ``spacing`` d0 apart: a particle pair crosses the planes between its centres,
    a particle-wall contact those between the centre and the wall's face. Returns {'x': plane
    distances from the left face [d0], 'count': contacts crossing each, 'mean', 'length_d0',
    'total' (all contacts in overlap), 'weakest': weakest_plane()}; the weakest plane is where a
    pull tears the sample."""
    _checks.positive("spacing", spacing)
    d0 = sample.resolve(protocol).d0
    walls = sample.wall_ids()
    lo, hi = sample.inner_box()
    x0, x1 = lo[0], hi[0]
    n = max(1, int((x1 - x0) / (spacing * d0)))
    xs = [x0 + (k + 0.5) * (x1 - x0) / n for k in range(n)]
    diff, total = [0] * (n + 1), 0
    face = {walls["left"]: x0, walls["right"]: x1}
    lateral = set(walls.values()) - set(face)  # present only before the unconfined start
    for inter in O.interactions:
        if inter.geom.penetrationDepth <= 0 or inter.id1 in lateral or inter.id2 in lateral:
            continue
        total += 1
        a, b = (face[i] if i in face else O.bodies[i].state.pos[0] for i in (inter.id1, inter.id2))
        lo_x, hi_x = min(a, b), max(a, b)
        first = max(0, int(math.ceil((lo_x - x0) / (x1 - x0) * n - 0.5)))  # planes with lo_x < x < hi_x
        last = min(n - 1, int(math.floor((hi_x - x0) / (x1 - x0) * n - 0.5)))
        if first <= last:
            diff[first] += 1
            diff[last + 1] -= 1
    count, run = [], 0
    for k in range(n):
        run += diff[k]
        count.append(run)
    prof = {"x": [(x - x0) / d0 for x in xs], "count": count, "mean": sum(count) / n,
            "length_d0": (x1 - x0) / d0, "total": total}
    prof["weakest"] = weakest_plane(prof)
    return prof


def weakest_plane(prof, margin=0.5):
    """The plane of a crossing_profile with the fewest contacts, at least ``margin`` d0 from both
    walls' faces (nearer, only the contacts with the glued walls cross, with the adhesive walls' own
    law): its count and distances from the left and right faces [d0]."""
    xs, count, length = prof["x"], prof["count"], prof["length_d0"]
    inner = [k for k, x in enumerate(xs) if margin <= x <= length - margin] or list(range(len(xs)))
    k = min(inner, key=lambda j: count[j])
    return {"count": count[k], "from_left_d0": xs[k], "from_right_d0": length - xs[k]}


def grip_members(thickness=1.0, protocol=None):
    """The particles whose centres lie within ``thickness`` d0 of each loading wall's face: {wall
    id: particle ids}, the grips of Test.use_grips."""
    _checks.positive("thickness", thickness)
    d0 = sample.resolve(protocol).d0
    walls = sample.wall_ids()
    lo, hi = sample.inner_box()
    ids = sample.sphere_ids()
    return {walls["left"]: [i for i in ids if O.bodies[i].state.pos[0] - lo[0] < thickness * d0],
            walls["right"]: [i for i in ids if hi[0] - O.bodies[i].state.pos[0] < thickness * d0]}


class _WallWork:
    """The work the loading walls do on the sample, added up every step by a PyRunner after the
    NewtonIntegrator (this step's force on each wall times the velocity it moved with); also
    the gross work (absolute values), the scale of the energy balance."""

    def __init__(self, walls):
        self.walls, self.work, self.gross, self.e0 = walls, 0.0, 0.0, None

    def __call__(self):
        if self.e0 is None:  # the stored energies of existing contacts enter O.energy on the first tracked step
            self.e0 = _energy_total()
            return
        for i in self.walls:
            dw = -O.forces.f(i).dot(O.bodies[i].state.vel) * O.dt
            self.work += dw
            self.gross += abs(dw)


def _energy_total():
    """O.energy without YADE's 'kinetic' (which counts the moving walls too) plus the particles'
    kinetic energy (the scene's energy unit)."""
    return sum(O.energy[k] for k in O.energy.keys() if k != "kinetic") + sample.kinetic_energy()


class Test:
    """An unconfined uni-axial test on the loaded unconfined start (stages.ensure('unconfined')).
    ``run(n)`` advances the scene by n steps (default ``O.run(n, True)``; under yade.mpy
    ``mpy.mpirun``, with ``records`` true on the master only: a worker may not hold both walls,
    and ``share(x)`` giving every rank the master's x, for decisions made from the walls).
    ``Test.steps_run`` counts the steps every test of this process has run (a campaign job's
    total)."""

    steps_run = 0

    def __init__(self, progress=True, run=None, records=True, share=None, protocol=None):
        self.p = sample.resolve(protocol)
        self.progress = progress and records
        self.records = records
        self._run = run or (lambda n: O.run(n, True))
        self._run_given = run is not None
        self._share = share or (lambda x: x)
        walls = sample.wall_ids()
        self.left, self.right = walls["left"], walls["right"]
        self.grip = {self.left: [self.left], self.right: [self.right]}  # what each end moves: the wall alone
        self.grips = None  # use_grips' description of the grips, when the test loads through them
        O.step()  # forces are not saved: one step with the walls at rest restores them
        self.L0 = self.length()
        self.t_cross = crossing_time(self.p)
        self.rows = []  # (iter, Dx, F/(kp d0))
        self.lengths = []  # the length L measured with each row
        self.branches = []  # (iter, Dx, fraction of the contacts on each scene.BRANCHES), with each row
        self.energy = []  # (iter, walls' work, energy change) with each row, once track_energy() is on
        self._motion = []

    def use_grips(self, thickness=1.0, members=None):
        """Loads through glued particles instead of the flat walls (issue #47, E4): the particles
        of grip_members(thickness) (or ``members``) become each end's grip, moved with its wall as
        one rigid body (every degree of freedom blocked, the wall's velocity imposed); the walls'
        contacts are erased and the walls stop touching anything (mask 0), so the sample is held
        only by its own particle contacts, with the particles' adhesion. Dx keeps its definition
        (the walls' distance, which moves with the grips); the force is the one on each grip's
        particles. Returns the grips' sizes (also kept as ``self.grips``)."""
        members = members or grip_members(thickness, self.p)
        for wid in (self.left, self.right):
            for inter in O.bodies[wid].intrs():
                O.interactions.erase(inter.id1, inter.id2)
            O.bodies[wid].mask = 0
            for i in members[wid]:
                st = O.bodies[i].state
                st.blockedDOFs, st.vel, st.angVel = "xyzXYZ", Vector3(0, 0, 0), Vector3(0, 0, 0)
            self.grip[wid] = list(members[wid]) + [wid]
        O.step()  # the grips' forces, from the particle contacts alone
        self.L0 = self.length()
        n = len(sample.sphere_ids())
        self.grips = {"thickness_d0": thickness, "left": len(members[self.left]), "right": len(members[self.right]),
                      "free": n - len(members[self.left]) - len(members[self.right])}
        return self.grips

    def track_energy(self):
        """Tracks the energy from now on: O.energy, and the walls' work on the sample every step;
        energy_balance() compares them."""
        O.trackEnergy = True
        self._work = _WallWork((self.left, self.right))
        O.engines = O.engines + [_loop.runner(self._work, 1, "wallwork")]

    def energy_balance(self):
        """From the first step after track_energy(): the walls' work W, the change of kinetic + stored + dissipated
        energy dE, and (dE - W) against the walls' gross work (the sum of |work| per step)."""
        d_e = _energy_total() - self._work.e0
        return {"wall_work": self._work.work, "energy_change": d_e, "gross_wall_work": self._work.gross,
                "residual_over_gross": (d_e - self._work.work) / self._work.gross if self._work.gross else None}

    def write_csv(self, path):
        """One row per record: iter, Dx, F/(kp d0), the length L, the walls' work and the energy
        change (after track_energy(); else empty) and the contacts' fraction on each branch."""
        _records.write_csv(self, path)

    def plot(self, path, title=""):
        """F/(kp d0) against Dx, and the branch fractions against the record, in one PNG."""
        _records.plot(self, path, title)

    def length(self):
        lo, hi = sample.inner_box()
        return hi[0] - lo[0]

    def dx(self):
        return (self.length() - self.L0) / self.p.d0

    def force(self):
        """Force on the loading walls, > 0 in compression, over kp d0."""
        f = 0.5 * (self._end_force(self.right) - self._end_force(self.left))
        return f / (self.p.kp * self.p.d0)

    def _end_force(self, wid):
        grip = self.grip[wid]
        return O.forces.f(wid)[0] if len(grip) == 1 else sum(O.forces.f(i)[0] for i in grip)

    def _install(self, motion, every, on_record):
        """Replaces the previous motion engines and recorder by these."""
        old = {id(e) for e in self._motion}
        O.engines = [e for e in O.engines if id(e) not in old and e.label != "recorder"]
        self._motion = motion
        self._on_record = on_record
        before_newton(motion + [_loop.runner(self._record, every, "recorder")])

    def _record(self):
        """Records (iter, Dx, F), the branch fractions and the plot data, once per iteration: a test
        records its start explicitly, and the recorder installed with it runs in the next step at
        the same O.iter (engines run before the step is counted); that second record is left out,
        the first kept (force_cycles' f_start reads it)."""
        if not self.records or (self.rows and self.rows[-1][0] == O.iter):
            return
        row = (O.iter, self.dx(), self.force())
        self.rows.append(row)
        self.lengths.append(self.length())
        fractions = _scene.branch_fractions()
        self.branches.append((row[0], row[1], *(fractions.get(b, 0.0) for b in _scene.BRANCHES)))
        _plot.addData(iter=row[0], Dx=row[1], F_over_kp_d0=row[2])  # live in the shell: plot.plot()
        if getattr(self, "_work", None) is not None and self._work.e0 is not None:
            self.energy.append((row[0], self._work.work, _energy_total() - self._work.e0))
        if self._on_record is not None:
            self._on_record(self, row)

    def cycles(self, mode, amplitude, n_cycles=4, steps_per_cycle=None, period=40.0, every=None,
               on_record=None, wall_speed=None, checkpoint=None):
        """n_cycles cosine cycles of amplitude Dx = amplitude (in d0) in tension or compression.
        The period is ``steps_per_cycle`` steps, or the one at which the two walls' relative speed
        (twice each wall's) peaks at ``wall_speed`` (the scene's units: pi amplitude d0 / wall_speed;
        the period is a multiple of 8 steps, so the peak is up to 8/steps faster: at least 800 steps
        are required, 1 %), or ``period``
        elastic crossing times. Returns the rows (iter, Dx, F/(kp d0)) recorded every ``every``
        steps (default: 400 per cycle). ``checkpoint`` (a .yade.gz path): saved there after every
        quarter cycle (``save``), so that a run of hours survives its process: ``Test.load(path)
        .resume(path)`` finishes it. The run goes on from each save as loaded from the file, so it
        is the same row for row whether or not its process died (a load renews the collider's order
        of new contacts, which moves a run without saves by rounding); the files go at the end."""
        sign = check_mode(mode)
        _cycle_arguments(amplitude, n_cycles, every)
        _checkpoint.check_path("checkpoint", checkpoint, none=True)
        if checkpoint and self._run_given:
            raise ValueError("checkpoint is invalid under yade.mpy (a test with its own run()): a serial run only")
        if steps_per_cycle is not None and wall_speed is not None:
            raise ValueError("wall_speed is invalid together with steps_per_cycle: give one")
        if steps_per_cycle is not None:
            _whole("steps_per_cycle", steps_per_cycle)
        elif wall_speed is not None:
            _checks.positive("wall_speed", wall_speed)
            exact = math.pi * amplitude * self.p.d0 / wall_speed / O.dt
            if max(8, 8 * (int(round(exact)) // 8)) > 1.01 * exact or exact < 800:
                raise ValueError(f"wall_speed = {wall_speed!r} is invalid: a period of {exact:.1f} steps, too few to "
                                 "hold the walls' speed within 1 % (at least 800 steps: wall_speed <= "
                                 f"{math.pi * amplitude * self.p.d0 / (800 * O.dt):.4g})")
            steps_per_cycle = int(round(exact))
        else:
            _checks.positive("period", period)
            steps_per_cycle = int(round(period * self.t_cross / O.dt))
        steps_per_cycle = max(8, 8 * (int(steps_per_cycle) // 8))
        every = every or max(1, steps_per_cycle // 400)
        w = 0.5 * amplitude * self.p.d0  # each wall moves by w at the peak
        freq = 1.0 / (steps_per_cycle * O.dt)
        phase = -2 * math.pi * freq * O.time  # the cosine starts now
        motion = [_w.HarmonicMotionEngine(ids=self.grip[wid], A=Vector3(a, 0, 0), f=Vector3(freq, 0, 0),
                                          fi=Vector3(phase, 0, 0), label=f"cycle_{wid}")
                  for wid, a in ((self.right, -0.5 * sign * w), (self.left, 0.5 * sign * w))]
        self.steps_per_cycle = steps_per_cycle
        self._install(motion, every, on_record)
        self._record()
        total = int(n_cycles) * steps_per_cycle
        self._cycling = {"mode": mode, "amplitude": amplitude, "n_cycles": int(n_cycles), "start": O.iter,
                         "total": total, "chunk": max(every, steps_per_cycle // 4 // every * every)}
        return self._cycle_on(checkpoint)

    def _cycle_on(self, checkpoint):
        """The cycles' steps from where they are, in chunks of a quarter cycle (a progress line and,
        with ``checkpoint``, a save after each); then the walls halted."""
        c, t0 = self._cycling, time.time()
        while O.iter - c["start"] < c["total"]:
            left = c["total"] - (O.iter - c["start"])
            # a short tail joins the last chunk: one last progress line
            k = left if left < c["chunk"] + c["chunk"] // 2 else c["chunk"]
            self._run(k)
            Test.steps_run += k
            if self.progress:
                done = (O.iter - c["start"]) / self.steps_per_cycle
                print(f"  {c['mode']} Dx={c['amplitude']:g}: cycle {done:5.2f}/{c['n_cycles']}  Dx={self.dx():+.4f}"
                      f"  F/(kp d0)={self.force():+.4e}  ({time.time() - t0:.0f} s)", flush=True)
            if checkpoint and O.iter - c["start"] < c["total"]:
                self.save(checkpoint)
                self._bind(_checkpoint.load(checkpoint), self._on_record)  # on from the file, as a new process
        self._halt(self._motion)
        self._cycling = None
        _checkpoint.remove(checkpoint)
        return self.rows

    _UNSAVED = ("p", "_run", "_share", "_motion", "_on_record", "_work", "grip")

    def save(self, path):
        """The scene and this test's state while it cycles (bulk.checkpoint.save): Test.load(path)
        gives it back in another process, and its ``resume()`` finishes the cycles."""
        if getattr(self, "_cycling", None) is None:
            raise RuntimeError("Test.save: only a test inside its cycles can be saved (cycles(..., checkpoint=...))")
        if self._run_given:
            raise ValueError("Test.save: a test with its own run() (yade.mpy) cannot be saved")
        state = {k: v for k, v in vars(self).items() if k not in self._UNSAVED}
        work = getattr(self, "_work", None)
        state.update(protocol=self.p.to_json(), grip=[[k, v] for k, v in self.grip.items()],
                     work=None if work is None else [work.walls, work.work, work.gross, work.e0])
        _checkpoint.save(path, state)

    @classmethod
    def load(cls, path, on_record=None):
        """Loads a test saved inside its cycles (``save``) into O; ``on_record`` as in cycles()."""
        test = cls.__new__(cls)
        test._bind(_checkpoint.load(path), on_record)
        return test

    def _bind(self, state, on_record):
        self.p = _protocol.Protocol.from_json(state.pop("protocol"))
        self.grip = {k: v for k, v in state.pop("grip")}
        work = state.pop("work")
        self.__dict__.update(state)
        for key in ("rows", "branches", "energy"):
            setattr(self, key, [tuple(r) for r in getattr(self, key)])
        self._run, self._share, self._on_record = (lambda n: O.run(n, True)), (lambda x: x), on_record
        self._motion = [e for e in O.engines if e.label in (f"cycle_{self.left}", f"cycle_{self.right}")]
        _loop.register("recorder", self._record)
        self._work = None
        if work is not None:
            self._work = _WallWork(tuple(work[0]))
            self._work.work, self._work.gross, self._work.e0 = work[1:]
            _loop.register("wallwork", self._work)

    def resume(self, checkpoint=None):
        """Finishes the cycles of a loaded test (``load``), saving on to ``checkpoint``; returns the rows."""
        if getattr(self, "_cycling", None) is None:
            raise RuntimeError("Test.resume: this test is not inside its cycles (Test.load a saved one)")
        _checkpoint.check_path("checkpoint", checkpoint, none=True)
        return self._cycle_on(checkpoint)

    def force_cycles(self, amplitude, n_cycles=4, period=480.0, every=None, on_record=None, max_strokes_steps=None,
                     mode="tension"):
        """n_cycles tension cycles that turn back at Dx = amplitude and return until the force is
        back at the start's (F >= the first record's F) or, whichever comes first, the length is
        (Dx <= 0): cycles about the sample's present length rather than its first one (``mode``
        'compression': turning at Dx = -amplitude, back until F <= the start's or Dx >= 0). The walls
        move at constant speed, each amplitude d0 / (period t_w), the cosine cycle's mean speed,
        so that a return to Dx = 0 takes the cosine cycle's time. The turns are checked every
        quarter record (the overshoot is below 1/800 of the amplitude). Returns the rows;
        ``self.turns`` holds (iter, Dx, F) where each stroke ended."""
        sign = check_mode(mode)
        _cycle_arguments(amplitude, n_cycles, every)
        _checks.positive("period", period)
        if max_strokes_steps is not None:
            _whole("max_strokes_steps", max_strokes_steps)
        speed = amplitude * self.p.d0 / (period * self.t_cross)
        self.steps_per_cycle = int(round(period * self.t_cross / O.dt))
        every = every or max(1, self.steps_per_cycle // 400)
        check = max(1, every // 4)
        limit = max_strokes_steps or 4 * self.steps_per_cycle  # a stroke that does not end is an error
        motion = [_w.TranslationEngine(ids=self.grip[wid], translationAxis=Vector3(s, 0, 0), velocity=speed,
                                       label=f"stroke_{wid}")
                  for wid, s in ((self.right, 1.0), (self.left, -1.0))]
        self._install(motion, every, on_record)
        self._record()
        f_start = self.rows[-1][2]
        self.turns = []
        t0 = time.time()
        for cycle in range(int(n_cycles)):
            for outward in (True, False):
                for e in motion:
                    e.velocity = (speed if outward else -speed) * sign
                start = O.iter
                while True:
                    self._run(check)
                    Test.steps_run += check
                    dx, f = self.dx(), self.force()
                    if sign > 0 and ((dx >= amplitude) if outward else (f >= f_start or dx <= 0)):
                        break
                    if sign < 0 and ((dx <= -amplitude) if outward else (f <= f_start or dx >= 0)):
                        break
                    if O.iter - start > limit:
                        raise RuntimeError(f"force_cycles: the {'outward' if outward else 'return'} stroke of cycle "
                                           f"{cycle + 1} did not end in {limit} steps (Dx = {dx:.4g}, F = {f:.4g})")
                self.turns.append((O.iter, dx, f))
                if self.progress:
                    print(f"  {mode} Dx={amplitude:g} to the start's force: cycle {cycle + 1}/{n_cycles} "
                          f"{'out' if outward else 'back'} at Dx={dx:+.4f}  F/(kp d0)={f:+.4e}  "
                          f"({time.time() - t0:.0f} s)",
                          flush=True)
        self._halt(motion)
        return self.rows

    def _halt(self, motion):
        """Ends a test's motion: its engines dead, the walls (grips) at rest, and the end recorded."""
        for e in motion:
            e.dead = True
        for i in self.grip[self.left] + self.grip[self.right]:
            if O.bodies[i]:  # under mpy a worker may not hold both walls
                O.bodies[i].state.vel = Vector3(0, 0, 0)
        self._record()

    def pull(self, speed, until=9.0, every=100, on_record=None, stop=None, exact=True):
        """Monotonic tension: each wall moves out at ``speed`` [length/time] until Dx = until (or, checked
        between chunks of 50 records, until ``stop()`` is true). ``exact``: the last chunk ends at
        Dx = until (to a step) and the walls stop there; otherwise the walls go on to the end of
        the chunk in which Dx passes until, and keep moving. Returns the recorded rows."""
        return self._monotonic(1.0, speed, until, every, on_record, stop, exact)

    def compress(self, speed, until=3.0, every=100, on_record=None, stop=None, exact=True):
        """Monotonic compression: each wall moves in at ``speed`` [length/time] until Dx = -until
        (``exact``: as in pull)."""
        if not 0 < until < 0.9 * self.L0 / self.p.d0:
            raise ValueError(f"until = {until} is invalid: between 0 and 90 % of the sample's length in d0")
        return self._monotonic(-1.0, speed, until, every, on_record, stop, exact)

    MAX_STEPS = 10 ** 8  # a monotonic test that would need more steps is refused, not run for days

    def _monotonic(self, sign, speed, until, every, on_record, stop, exact):
        _checks.positive("speed", speed)
        _checks.positive("until", until)
        _whole("every", every)
        need = until * self.p.d0 / (2 * speed * O.dt)  # both walls move
        if not need <= self.MAX_STEPS:
            raise ValueError(f"speed = {speed:g} is invalid: the walls would need {need:.3g} steps to reach "
                             f"Dx = {sign * until:g} (at most {self.MAX_STEPS:.0e}; speed >= "
                             f"{until * self.p.d0 / (2 * self.MAX_STEPS * O.dt):.3g} per time unit)")
        motion = [_w.TranslationEngine(ids=self.grip[wid], translationAxis=Vector3(sign * s, 0, 0), velocity=speed,
                                       label=f"pull_{wid}")
                  for wid, s in ((self.right, 1.0), (self.left, -1.0))]
        self._install(motion, every, on_record)
        self._record()
        t0 = time.time()
        chunk = 50 * every
        while self._share(sign * self.dx() < until and not (stop and stop()) if self.records else None):
            k = chunk
            if exact:  # the steps left to until, both walls moving at speed
                left = (until - sign * self.dx()) * self.p.d0 / (2 * speed * O.dt)
                k = max(1, min(chunk, int(math.ceil(left - 1e-6))))
            self._run(k)
            Test.steps_run += k
            if self.progress:
                print(f"  {'pull' if sign > 0 else 'compression'}: Dx={self.dx():.3f}/{sign * until:g}  "
                      f"F/(kp d0)={self.force():+.4e}  ({time.time() - t0:.0f} s)",
                      flush=True)
        if exact:
            self._halt(motion)
        return self.rows
