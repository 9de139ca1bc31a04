"""Two agglomerates pressed together and pulled apart under displacement control, or one against a
flat wall (inside ``yade``).

Each agglomerate (a list of body ids, e.g. of ``bulk.agglomerate.carve_pair``) is held at its far
cap: the particles whose centres lie beyond ``grip`` R from its centre of mass, on the side away
from the other, move as one rigid body (every degree of freedom blocked, the velocity imposed), as
the bulk tests' grips do; the rest of it is free. The two caps move towards or away from each other
at ``speed`` each. Recorded every ``every`` steps: the meso-overlap delta = R1 + R2 - |x1 - x2| of
the centres of mass (all particles) and the force F between the agglomerates, read on the caps:
(f_x of the right cap - f_x of the left cap)/2, > 0 when they push each other apart. With the caps
at rest it is the force across the contact; while they move it carries the free parts' inertia and
drag too, which a slower run measures::

    from mesocontact.bulk import pair_cycles
    pair = pair_cycles.Pair(members, radii)                 # or pair_cycles.Wall(members, radii[0])
    rows = pair.cycles((0.1, 0.2, 0.4), speed=2.5e-3)       # amplitudes in d0, speed of each cap
    print(pair.touch, pair.events)

The cycles (``Pair.cycles``): approach until the agglomerates first touch (a contact in overlap
joins them; delta_touch), then for each amplitude a: load to delta_touch + a d0 and unload to
delta_touch - BELOW_TOUCH d0, through the pull-off and the tension after it (a fixed turning
point: a force criterion would turn on the force's ringing); after the last amplitude pull apart
until no contact joins the two (or MAX_PULL d0 below delta_touch). A stroke's end is checked
inside the loop every ``check`` steps and pauses it there. Lengths and forces are reported over
the Protocol's d0 and kp d0 (the ``protocol`` argument, else the scene's).
"""
import numbers
import time

try:
    from yade import O
    from yade import Vector3
    from yade import utils as _utils
    from yade import wrapper as _w
except ImportError as _exc:  # pragma: no cover - outside yade
    raise ImportError("mesocontact.bulk.pair_cycles needs YADE: run it inside `yade`") from _exc

from .. import checks as _checks
from .. import loop as _loop
from . import agglomerate
from . import checkpoint as _checkpoint
from . import protocol as _protocol
from . import sample
from .uniaxial import before_newton

BELOW_TOUCH = 0.2  # d0 below the first touch where an unloading turns
MAX_PULL = 1.5     # d0 below the first touch at which the last stroke apart ends in any case
PROGRESS_EVERY = 60.0  # s of wall clock between a long stroke's progress lines
WALL_MATERIALS = {"own": "particles",   # the particles' own k, adhesion, friction; the law's sphere-wall a12 = 2 a_i
                  "smooth": "walls"}     # bulk.prepare's mould: the normal law without adhesion or friction, dominant


def _whole(name, value):
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < 1:
        raise ValueError(f"{name} = {value!r} is invalid: an integer >= 1")


def _common(grip, every, check):
    if not (_checks.is_number(grip) and 0 < grip < 1):
        raise ValueError(f"grip = {grip!r} is invalid: the caps start at a fraction of R in (0, 1)")
    _whole("every", every)
    _whole("check", check)


class Pair:
    """Two agglomerates (``members``, radii R), gripped at their far caps."""

    def __init__(self, members, radii, grip=0.5, progress=True, every=50, check=10, protocol=None):
        _common(grip, every, check)
        agglomerate.check_pair(members, radii)
        self.protocol = sample.resolve(protocol)
        self.members = [list(m) for m in members]
        self.radii = list(radii)
        c = [agglomerate.centre_of_mass(m)[0] for m in self.members]
        # the far side of each
        self._hold([-1.0, 1.0] if c[0][0] < c[1][0] else [1.0, -1.0], grip, progress, every, check)

    def _hold(self, side, grip, progress, every, check):
        """Grips each agglomerate's cap beyond ``grip`` R on its ``side`` (+-1 along x) and inserts
        the caps' motion, the recorder and the stroke's check."""
        self.progress, self.every, self.check = progress, int(every), int(check)
        c = [agglomerate.centre_of_mass(m)[0] for m in self.members]
        self.grips = [[i for i in m if side[k] * (O.bodies[i].state.pos[0] - c[k][0]) > grip * self.radii[k]]
                      for k, m in enumerate(self.members)]
        self.side = side
        for g in self.grips:
            for i in g:
                st = O.bodies[i].state
                st.blockedDOFs, st.vel, st.angVel = "xyzXYZ", Vector3(0, 0, 0), Vector3(0, 0, 0)
        self.grip_fraction = grip
        self.rows = []
        self.events = []
        self._motion = [_w.TranslationEngine(ids=g, translationAxis=Vector3(-side[k], 0, 0), velocity=0.0,
                                             label=f"cap{k}") for k, g in enumerate(self.grips)]
        before_newton(self._motion + [_loop.runner(self._record, self.every, "agg_recorder"),
                                      _loop.runner(lambda: None, self.check, "agg_check")])

    def set_gap(self, gap):
        """Moves the second agglomerate along x until its surface lies ``gap`` (a length) from the
        first's (agglomerate.move_to_gap; its contacts move with it); returns delta then."""
        agglomerate.move_to_gap(self.members[0], self.members[1], gap)
        return self.delta()

    def delta(self):
        return agglomerate.meso_overlap(self.members, self.radii)

    def force(self):
        f = [sum(O.forces.f(i)[0] for i in g) for g in self.grips]
        return 0.5 * (self.side[1] * f[1] + self.side[0] * f[0])

    def touching(self):
        """Contacts in overlap between the two agglomerates."""
        return agglomerate.contacts_between(*self.members)

    def _record(self):
        if self.rows and self.rows[-1][0] == O.iter:  # the explicit start record and the recorder's at one step
            return
        self.rows.append((O.iter, self.delta(), self.force()))

    def _move(self, speed):
        """Each cap moves towards the other at ``speed`` (< 0: apart)."""
        for e in self._motion:
            e.velocity = speed

    def stroke(self, speed, until, limit_steps):
        """Moves the caps at ``speed`` (> 0 together) until ``until(delta, F)``, checked every
        ``check`` steps inside the loop; returns (delta, F) there."""
        if not (_checks.is_number(speed) and speed == speed and abs(speed) < float("inf")):
            raise ValueError(f"speed = {speed!r} is invalid: a finite number")
        if not callable(until):
            raise TypeError(f"until = {until!r} is invalid: a function of (delta, F)")
        _whole("limit_steps", limit_steps)
        hit, shown = [], [time.time()]

        def check():
            d, f = self.delta(), self.force()
            if until(d, f):
                hit.append((d, f))
                O.pause()
            elif self.progress and time.time() - shown[0] > PROGRESS_EVERY:  # a long stroke (a pull apart) shows itself
                shown[0] = time.time()
                d0, kp = self.protocol.d0, self.protocol.kp
                print(f"    stroke at {speed:+g}: delta = {d / d0:+.4f} d0  F/(kp d0) = {f / (kp * d0):+.4e}  "
                      f"{self.touching()} contacts across  ({O.iter} steps)", flush=True)
        self._move(speed)
        _loop.register("agg_check", check)
        try:
            O.run(int(limit_steps), True)
        finally:
            _loop.register("agg_check", lambda: None)
            self._move(0.0)
        if not hit:
            raise RuntimeError(f"stroke at speed {speed:g} did not end in {limit_steps} steps "
                               f"(delta = {self.delta():.4g}, F = {self.force():.4g})")
        return hit[0]

    def cycles(self, amplitudes, speed, gap=0.05, max_steps=10 ** 7, final=True, max_pull=MAX_PULL, checkpoint=None,
               checkpoint_steps=200000):
        """The protocol of the module's docstring; amplitudes in d0 beyond the first touch, speed
        of each cap, gap: the surfaces' distance at the start [d0]. Returns the rows (iter, delta,
        F); ``events`` holds (what, iter, delta, F) at each turn (with O.trackEnergy on, ``event_energy``
        O.energy's terms and the members' kinetic energy there); ``final``: pull apart at the end
        (a rate check's run may leave it out), to ``max_pull`` d0 below the touch at most;
        ``checkpoint``, ``checkpoint_steps``: that pull saved on the way (pull_apart)."""
        if isinstance(amplitudes, (str, bytes, dict)) or not hasattr(amplitudes, "__len__") or not len(amplitudes):
            raise ValueError(f"amplitudes = {amplitudes!r} is invalid: a sequence of amplitudes [d0]")
        for k, a in enumerate(amplitudes):
            _checks.positive(f"amplitudes[{k}]", a)
        _checks.positive("speed", speed)
        _checks.nonnegative("gap", gap)
        _checks.positive("max_pull", max_pull)
        _whole("max_steps", max_steps)
        d0 = self.protocol.d0
        self._t0 = time.time()
        self.set_gap(gap * d0)
        self._record()
        d, f = self.stroke(speed, lambda d, f: self.touching() > 0, max_steps)
        self.touch = touch = d
        self._note("touch", d, f)
        for a in amplitudes:
            d, f = self.stroke(speed, lambda d, f, a=a: d >= touch + a * d0, max_steps)
            self._note(f"loaded to {a:g} d0", d, f)
            d, f = self.stroke(-speed, lambda d, f: d <= touch - BELOW_TOUCH * d0, max_steps)
            self._note("unloaded", d, f)
        if final:  # the last pull apart (a rate check's run may leave it out)
            return self.pull_apart(speed, max_pull, max_steps, checkpoint, checkpoint_steps)
        self._record()
        return self.rows

    def elapsed(self):
        """Seconds of wall clock since the cycles started, over every process a saved pull ran in."""
        return time.time() - getattr(self, "_t0", time.time())

    def _note(self, what, d, f):
        self.events.append((what, O.iter, d, f))
        if O.trackEnergy:  # where the work went, at each turn (O.energy's terms and the particles' kinetic energy)
            if not hasattr(self, "event_energy"):
                self.event_energy = []
            kinetic = sum(0.5 * b.state.mass * b.state.vel.squaredNorm()
                          + 0.5 * sum(w * w * j for w, j in zip(b.state.angVel, b.state.inertia))
                          for m in self.members for b in (O.bodies[i] for i in m))
            self.event_energy.append(dict(O.energy.items(), particles_kinetic=kinetic))
        if self.progress:
            d0, kp = self.protocol.d0, self.protocol.kp
            print(f"  {what}: delta = {d / d0:+.4f} d0  F/(kp d0) = {f / (kp * d0):+.4e}  "
                  f"({O.iter} steps, {self.elapsed():.0f} s)", flush=True)

    def pull_apart(self, speed, max_pull=MAX_PULL, max_steps=10 ** 7, checkpoint=None, checkpoint_steps=200000):
        """The cycles' last stroke: each cap moves apart at ``speed`` until no contact joins the two
        or delta is ``max_pull`` d0 below the touch; returns the rows. With ``checkpoint`` (a path
        ending in .yade.gz) the stroke is saved there every ``checkpoint_steps`` steps (Pair.save), so
        that a pull of hours survives its process: ``Pair.load(checkpoint).pull_apart(...)`` goes on
        from the last save. The run itself goes on from each save as loaded from the file, so that it
        is the same row for row whether or not its process died (a load renews the collider's
        order of new contacts, which moves a run without saves by rounding). The files are removed
        at the end."""
        _checks.positive("speed", speed)
        _checks.positive("max_pull", max_pull)
        _whole("max_steps", max_steps)
        _whole("checkpoint_steps", checkpoint_steps)
        _checkpoint.check_path("checkpoint", checkpoint, none=True)
        if not hasattr(self, "touch"):
            raise RuntimeError("pull_apart: the pair has not touched yet (run cycles first)")
        beyond = self.touch - max_pull * self.protocol.d0
        while True:
            until = O.iter + checkpoint_steps if checkpoint else None
            d, f = self.stroke(-speed, lambda d, f: (self.touching() == 0 or d <= beyond
                                                     or (until is not None and O.iter >= until)), max_steps)
            if self.touching() == 0 or d <= beyond:
                break
            self.save(checkpoint)
            self._reload(checkpoint)  # go on from the file, as a new process would: where it dies changes nothing
        self._note("apart" if self.touching() == 0 else f"still joined at {max_pull:g} d0", d, f)
        self._record()
        _checkpoint.remove(checkpoint)
        return self.rows

    def save(self, path):
        """The scene and this pair's state (bulk.checkpoint.save); Pair.load(path) makes the pair
        again in another process."""
        state = {k: v for k, v in vars(self).items() if k not in ("_motion", "protocol", "_t0")}
        _checkpoint.save(path, dict(state, protocol=self.protocol.to_json(), kind=type(self).__name__,
                                    elapsed=self.elapsed()))

    @classmethod
    def load(cls, path):
        """Loads a scene saved by ``save`` into O and returns its pair, the caps' engines and the
        recorder bound to it again."""
        pair = cls.__new__(cls)
        pair._reload(path)
        return pair

    def _reload(self, path):
        """Loads the scene saved to ``path`` and binds this pair to it (again)."""
        state = _checkpoint.load(path)
        if state.pop("kind") != type(self).__name__:
            raise ValueError(f"path = {path!r} is invalid: it holds another kind's state, not a {type(self).__name__}")
        self._t0 = time.time() - state.pop("elapsed")
        self.__dict__.update(state)
        self.protocol = _protocol.Protocol.from_json(state["protocol"])
        self.rows = [tuple(r) for r in self.rows]
        self.events = [tuple(e) for e in self.events]
        labels = {e.label: e for e in O.engines}
        self._motion = [labels[f"cap{k}"] for k in range(len(self.grips))]
        _loop.register("agg_recorder", self._record)
        _loop.register("agg_check", lambda: None)


class Wall(Pair):
    """One agglomerate (``members[keep]``; the others are erased) pressed against a flat wall and
    pulled off it: the same cycles (Pair.cycles), its far cap moving at ``speed`` towards a fixed
    wall (a YADE box of WALL_MATERIALS[material], a material of bulk.prepare's scene) whose face
    is normal to x on the agglomerate's +x side. delta = R - (x_wall - x) of the centre of mass;
    F is the force on the wall along x (> 0 pushed away), the force across the contact itself."""

    def __init__(self, members, radius, grip=0.5, progress=True, every=50, check=10, keep=0, material="own",
                 protocol=None):
        if material not in WALL_MATERIALS:
            raise ValueError(f"material = {material!r} is invalid: one of {sorted(WALL_MATERIALS)}")
        _common(grip, every, check)
        _checks.positive("radius", radius)
        if isinstance(members, (str, bytes, dict)) or not hasattr(members, "__len__") or not len(members):
            raise ValueError(f"members = {members!r} is invalid: a sequence of agglomerates (lists of body ids)")
        if isinstance(keep, bool) or not isinstance(keep, numbers.Integral) or not 0 <= keep < len(members):
            raise ValueError(f"keep = {keep!r} is invalid: the index of one of the {len(members)} agglomerates")
        agglomerate.centre_of_mass(members[keep])  # refuses bad ids
        label = WALL_MATERIALS[material]
        mat = [m for m in O.materials if m.label == label]
        if len(mat) != 1:
            raise ValueError(f"material = {material!r} is invalid: the scene holds {len(mat)} materials labelled "
                             f"{label!r}, not one (not a scene of bulk.prepare)")
        self.protocol = sample.resolve(protocol)
        for k, m in enumerate(members):
            if k != keep:
                for i in m:
                    O.bodies.erase(i)
        self.members, self.radii = [list(members[keep])], [radius]
        c = agglomerate.centre_of_mass(self.members[0])[0]
        d0 = self.protocol.d0
        half = Vector3(0.5 * d0, 2.0 * radius, 2.0 * radius)
        self.wall = O.bodies.append(_utils.box(center=c + Vector3(2.0 * radius + half[0], 0, 0), extents=half,
                                               fixed=True, material=mat[0]))
        self._hold([-1.0], grip, progress, every, check)

    def face(self):
        return O.bodies[self.wall].state.pos[0] - O.bodies[self.wall].shape.extents[0]

    def set_gap(self, gap):
        """Moves the wall until its face lies ``gap`` (a length) from the agglomerate's nearest surface."""
        _checks.nonnegative("gap", gap)
        reach = max(O.bodies[i].state.pos[0] + O.bodies[i].shape.radius for i in self.members[0])
        agglomerate.translate([self.wall], Vector3(reach + gap - self.face(), 0, 0))
        return self.delta()

    def delta(self):
        return self.radii[0] - (self.face() - agglomerate.centre_of_mass(self.members[0])[0][0])

    def force(self):
        return O.forces.f(self.wall)[0]

    def touching(self):
        return sum(1 for inter in O.bodies[self.wall].intrs() if inter.isReal and inter.geom.penetrationDepth > 0)
