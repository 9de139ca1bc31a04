"""Collisions of two agglomerates (inside ``yade``).

From two agglomerates at rest (lists of body ids, e.g. carved and relaxed with
``bulk.agglomerate.carve_pair`` and ``relax``) the second agglomerate is moved along the approach
direction (``axis``, default x: the pair as carved; another direction first places the second
agglomerate beside the first along it, agglomerate.place_along, so that other faces meet) until its
surface lies ``gap`` d0 from the first's (agglomerate.move_to_gap), and each is given half the relative
speed towards the other, every particle the same velocity and no spin. There is no background drag:
a collision's losses are the contacts' own (viscous, plastic, and what breaks). The run ends when no
contact has joined the two for ``quiet`` of the touch's duration so far and the smallest gap between
their surfaces has grown over PARTING checks (head-on, or sliding past each other where the faces
that meet are tilted to the approach), or when the two largest fragments, one from each
agglomerate, are separate clusters moving apart (particles they exchanged may still join them), or
after ``max_time`` (default STUCK_AFTER primary contact times; then the
agglomerates are read as stuck together if one cluster holds most of both).

Read at the end: the fragments (connected clusters through contacts in overlap); the two
largest, each named by the agglomerate most of its mass comes from; e = -(relative velocity of
their centres of mass along the approach direction after)/(before), 0 when one fragment holds most of both
(e_speed: the relative speed after over before; the deflection: the angle of the relative
velocity after to the approach direction, which faces tilted to it turn sideways; e_normal: e
along the impulse of the contacts' normal forces, the mean normal of the rough, tilted contact,
and the tilt, that normal's angle to the approach; e_impulse: e along the whole impulse, normal
and frictional, and the frictional impulse over the normal one); the mass
that broke off (everything but the two largest fragments, or the largest when stuck) over the
total; the contact time, from the first to the last step a contact joined the two agglomerates;
the press, the largest meso-overlap beyond the one at the first contact [d0], and the largest
normal force between them along the approach (the scene's units). ``rows``: (iter, time, delta, the
two velocities along the approach, that normal force) every ``every`` steps. Lengths are
reported over the Protocol's d0 and times scaled by a primary pair's contact time from its kp (the
``protocol`` argument, else the scene's)::

    from mesocontact.bulk import collisions
    c = collisions.Collision(members, radii, axis=(1, 0, 0))
    out = c.run(1e-3, snapshot="collision.png")     # relative speed, the scene's units
    print(out["e"], out["broken_mass_fraction"], out["energy_over_impact"])
"""
import math
import numbers
import time

try:
    from yade import O
    from yade import Vector3
    from yade import wrapper as _w
except ImportError as _exc:  # pragma: no cover - outside yade
    raise ImportError("mesocontact.bulk.collisions needs YADE: run it inside `yade`") from _exc

from .. import checks as _checks
from .. import loop as _loop
from . import agglomerate
from . import pictures as _pictures
from . import impact as _impact
from . import sample
from .uniaxial import before_newton

APPROACH = 0.002  # us of free flight before the surfaces meet, at most (about 140 steps)
PARTING = 4  # checks over which the surface gap must grow before a run ends (the surfaces' vibration is noise)
_NO_SPIN = dict.fromkeys(("e_contact", "e_rigid", "spin_energy_share", "spin"))  # a run whose first impact never ended
STUCK_AFTER = 2000  # primary contact times (about twenty of a rebound's contact time) after which one cluster is stuck


class Collision:
    """Two agglomerates (``members``, radii R) about to collide along ``axis``; ``run`` one collision."""

    def __init__(self, members, radii, every=20, axis=agglomerate.X_AXIS, protocol=None):
        if isinstance(every, bool) or not isinstance(every, numbers.Integral) or every < 1:
            raise ValueError(f"every = {every!r} is invalid: an integer >= 1")
        agglomerate.check_pair(members, radii)
        agglomerate.axis_frame(axis)  # refuses a bad axis
        if set(members[0]) & set(members[1]):
            raise ValueError("members is invalid: the two agglomerates share particles")
        self.protocol = sample.resolve(protocol)
        self.members = [list(m) for m in members]
        self.radii = list(radii)
        self.n = Vector3(*agglomerate.axis_frame(axis)[0])
        if tuple(axis) != agglomerate.X_AXIS:
            agglomerate.place_along(self.members[0], self.members[1], axis, self.radii, protocol=self.protocol)
        self.owner = {i: k for k, m in enumerate(self.members) for i in m}
        self.every = every
        self.first = self.last = None
        self.normal_impulse = Vector3(0, 0, 0)
        self.point_sum, self.point_weight, self.recontacts = Vector3(0, 0, 0), 0.0, 0
        self.first_impact = None  # a followed run's measures when the first impact ended (see _first_end)
        O.engines = [e for e in O.engines if not isinstance(e, _w.MesoBackgroundDamping)]
        self._pair = agglomerate.Watched(self.members, self.radii)  # checked once; _watch reads it every few steps
        before_newton([_loop.runner(self._watch, every, "agg_watch")])
        self.rows = []

    def delta(self):
        return self._pair.meso_overlap()

    def joined(self):
        return any(True for _ in self._pair.joining())

    def _normal_force(self):
        """(contacts in overlap joining the two, the sum of their normal forces on the second
        agglomerate's particles, the sum of their contact points weighted by |normal force|, that
        weight)."""
        count, f, point, weight = 0, Vector3(0, 0, 0), Vector3(0, 0, 0), 0.0
        for inter, on_id2 in self._pair.joining():
            count += 1
            f += inter.phys.normalForce if on_id2 else -inter.phys.normalForce  # Law2: +normalForce acts on id2
            w = inter.phys.normalForce.norm()
            point += inter.geom.contactPoint * w
            weight += w
        return count, f, point, weight

    def _watch(self):
        count, f, point, weight = self._normal_force()
        if self.first_impact is None:  # a followed run: the first impact's only (exchanged particles rest)
            self.normal_impulse += f * (self.every * O.dt)  # the normal forces' impulse, sampled every ``every`` steps
            self.point_sum += point  # the collision's contact point: the force-weighted mean
            self.point_weight += weight
        delta = self.delta()
        if count:
            if self.first is None:
                self.first, self.touch_delta = O.time, delta
            elif O.time - self.last > 1.5 * self.every * O.dt:
                self.recontacts += 1  # joined again after at least one look without a joining contact
            self.last = O.time
        v = [self._pair.velocity(k).dot(self.n) for k in (0, 1)]
        self.rows.append((O.iter, O.time, delta, v[0], v[1], f.dot(self.n) * self._side if count else 0.0))

    def run(self, v_rel, gap=0.05, quiet=1.0, max_time=None, progress=True, snapshot=None, unit="",
            speed_label=None, follow=None):
        """One collision at relative speed v_rel (the scene's units); returns its outcome (a dict).
        The surfaces start ``gap`` d0 apart, at most what the pair crosses in APPROACH time units;
        ``quiet``: how long no contact must have joined them, over the touch's duration so far;
        ``max_time``: the run's end in any case (default: the approach and STUCK_AFTER primary
        contact times). ``snapshot``: a PNG of the end state (bulk.pictures.png; ``unit``: the
        length unit of its axes), titled with ``speed_label`` (default 'v_rel = <v_rel>'), e and
        the mass broken off. ``follow`` (default None): a parted pair's run goes on until the two
        largest fragments' surfaces are ``follow`` times the press apart (the press sets the
        collision's length scale at every speed: at low speeds the separation is slow, and the
        internal vibration small, in proportion), re-contacts counted, and the outcome also holds
        the spin-aware measures, the broken bonds and whether the fragments, moving on rigidly,
        would touch again (``recontact_ahead``; ``bulk.impact``)."""
        _checks.positive("v_rel", v_rel)
        _checks.positive("gap", gap)
        _checks.nonnegative("quiet", quiet)
        if max_time is not None:
            _checks.positive("max_time", max_time)
        if follow is not None:
            _checks.positive("follow", follow)
        for name, value in (("snapshot", snapshot), ("speed_label", speed_label)):
            if value is not None and not isinstance(value, str):
                raise TypeError(f"{name} = {value!r} is invalid: a string (or None)")
        if not isinstance(unit, str):
            raise TypeError(f"unit = {unit!r} is invalid: a string")
        d0 = self.protocol.d0
        c = [agglomerate.centre_of_mass(m)[0].dot(self.n) for m in self.members]
        side = self._side = 1.0 if c[1] > c[0] else -1.0
        agglomerate.move_to_gap(self.members[0], self.members[1], min(gap * d0, v_rel * APPROACH), tuple(self.n))
        for k, m in enumerate(self.members):
            v = self.n * (side * (0.5 if k == 0 else -0.5) * v_rel)
            for i in m:
                O.bodies[i].state.vel, O.bodies[i].state.angVel = v, Vector3(0, 0, 0)
        O.energy.clear()
        O.trackEnergy = True  # the law's dissipation, for where the impact's energy goes
        ke0 = sample.kinetic_energy()
        masses = [agglomerate.centre_of_mass(m)[1] for m in self.members]
        ke_rel = 0.5 * masses[0] * masses[1] / (masses[0] + masses[1]) * v_rel ** 2  # the relative motion's
        O.run(1, True)  # the stored energies' values before the impact (the dissipated ones start at 0)
        self._energy0 = dict(O.energy.items())
        bonds = _impact.bonds(self.members) if follow is not None else None  # after a step: a loaded scene's geometry
        t0, start_time = time.time(), O.time
        approach = min(gap * d0, v_rel * APPROACH) / v_rel
        max_time = max_time if max_time is not None else approach + STUCK_AFTER * self._t_scale()
        chunk = max(500, int(0.25 * approach / O.dt)) // self.every * self.every
        state, gaps = "approach", []
        while O.time - start_time < max_time:
            O.run(chunk, True)
            if self.first is not None:
                ended, state, gaps = self._ended(quiet, chunk, gaps)
                if ended and follow is not None and self.first_impact is None:
                    self.first_impact = self._first_end(v_rel, side, ke_rel)
                if ended and self._far(follow):
                    break
            if progress:
                print(f"  v_rel {v_rel:g}: t = {(O.time - start_time):.4g} us  {state}  "
                      f"delta = {self.delta() / d0:+.4f} d0  ({time.time() - t0:.0f} s)", flush=True)
        out = self._outcome(v_rel, side, start_time, time.time() - t0)
        out["energy_over_impact"] = self._energy_shares(ke0)
        if follow is not None:
            out.update(self._followed(v_rel, side, bonds))
        if snapshot:
            label = f"v_rel = {v_rel:g}" if speed_label is None else speed_label
            _pictures.png(snapshot, d0=d0, unit=unit,
                          title=f"{label}: e = {out['e']:.3f}, "
                                f"broken off {out['broken_mass_fraction']:.3f}")
        return out

    def _ended(self, quiet, chunk, gaps):
        """(whether the impact has ended, the state, the surface gaps of the checks since the two
        last parted): no contact for a while and the surfaces part over PARTING checks (head-on
        or sliding past), or the two largest fragments, one from each, separate (exchanged
        particles may still join them)."""
        touch = self.last - self.first
        apart = not self.joined() and O.time - self.last > max(quiet * touch, 5 * chunk * O.dt)
        state = "apart" if apart else "joined"
        gaps = gaps[-(PARTING - 1):] + [self.surface_gap()] if apart else []
        if len(gaps) == PARTING and all(a < b for a, b in zip(gaps, gaps[1:])):
            return True, state, gaps
        if O.time - self.first > 5 * chunk * O.dt and self._parted():
            return True, "parted", gaps
        return False, state, gaps

    def _far(self, follow):
        """Whether the two largest fragments' surfaces lie ``follow`` presses apart (always,
        without ``follow``)."""
        if follow is None:
            return True
        parts = agglomerate.clusters([i for m in self.members for i in m])[:2]
        return len(parts) == 2 and _surface_gap(*parts) > follow * self._press()

    def _press(self):
        """The largest meso-overlap beyond the one at the first touch (the scene's length)."""
        return max(r[2] for r in self.rows) - self.touch_delta

    def _fragments(self):
        """The two largest fragments (first's, second's) when they come one from each agglomerate,
        else None."""
        parts = agglomerate.clusters([i for m in self.members for i in m])[:2]
        own = [max((0, 1), key=lambda k: sum(1 for i in p if self.owner[i] == k)) for p in parts]
        if len(parts) < 2 or own[0] == own[1]:
            return None
        return (parts[0], parts[1]) if own[0] == 0 else (parts[1], parts[0])

    def _first_end(self, v_rel, side, ke_rel):
        """The spin-aware restitution (bulk.impact) when the first impact ends (where a run without
        ``follow`` ends), with that impact's normal impulse and mean contact point and the
        fragments' centres there; the impulse stops adding up from then on."""
        frags = self._fragments()
        out = dict(_NO_SPIN, first_end_time=O.time)
        if frags and self.point_weight > 0 and self.normal_impulse.norm() > 0:
            out.update(_impact.spin_measures(*frags, tuple(self.normal_impulse),
                                             tuple(self.point_sum / self.point_weight),
                                             tuple(self.n * (-side * v_rel)), impact_energy=ke_rel))
        return out

    def _followed(self, v_rel, side, bonds):
        """The measures of a followed run: re-contacts, broken bonds, the final gap, and the
        spin-aware restitution of the first impact (None when it never ended: stuck)."""
        lost = _impact.broken(bonds)
        out = {"recontacts": self.recontacts, "bonds_before": len(bonds), "bonds_broken": len(lost),
               "bonds_broken_fraction": len(lost) / len(bonds) if bonds else None,
               **(self.first_impact or _NO_SPIN)}
        frags = self._fragments()
        if frags:
            out["final_gap_over_press"] = _surface_gap(*frags) / self._press()
            # three presses part a slow pair by little (7e-5 d0 at 0.01 m/s): would the fragments, moving
            # on rigidly, spinning as they do, touch again? (impact.closest_approach)
            gap, _, _ = _impact.closest_approach(*frags, max_time=20.0 * (O.time - self.first))
            out.update(closest_gap_ahead_over_press=gap / self._press(), recontact_ahead=bool(gap <= 0))
        return out

    def _energy_shares(self, ke0):
        """Where the impact's kinetic energy went, over it: the motion of the two agglomerates'
        centres of mass, the particles' motion about them (internal waves and rattling), and the
        law's tracked terms (O.energy: the change of the stored elastic energies, the viscous,
        plastic, sliding, rolling and torsion dissipation) since the impact's start."""
        bulk = 0.0
        for m in self.members:
            mass = sum(O.bodies[i].state.mass for i in m)
            bulk += 0.5 * mass * agglomerate.velocity(m).squaredNorm()
        shares = {"centres_of_mass": bulk / ke0, "internal_kinetic": (sample.kinetic_energy() - bulk) / ke0}
        shares.update({k: (v - self._energy0.get(k, 0.0)) / ke0 for k, v in O.energy.items()
                       if k not in ("kinetic", "gravWork")})  # changes since the impact's start
        return shares

    def _t_scale(self):
        """A primary pair's contact time pi sqrt(m/(2 kp)), the scale of the waits."""
        m = min(O.bodies[i].state.mass for m in self.members for i in m)
        return 3.1416 * (0.5 * m / self.protocol.kp) ** 0.5

    def _parted(self):
        """The two largest fragments are separate clusters, each holding at least half of one
        agglomerate's particles (one from each), moving apart."""
        frags = self._fragments()
        if frags is None or any(sum(1 for i in p if self.owner[i] == k) < 0.5 * len(self.members[k])
                                for k, p in enumerate(frags)):
            return False  # one cluster still holds both, or a small piece is the second largest
        return self._receding(*frags)

    def surface_gap(self):
        """The smallest distance between the surfaces of a particle of one agglomerate and one of
        the other."""
        return _surface_gap(*self.members)

    @staticmethod
    def _receding(a, b):
        """The centres of mass of ``a`` and ``b`` move apart (along the line joining them: an
        oblique rebound, surfaces tilted to the approach, ends too)."""
        return (agglomerate.velocity(b) - agglomerate.velocity(a)).dot(
            agglomerate.centre_of_mass(b)[0] - agglomerate.centre_of_mass(a)[0]) > 0

    def _impulse_measures(self, dv, side, v_rel):
        """e along the impulse the second agglomerate received (its particles' momentum change: the
        first's normal and frictional forces together), -(dv after . j)/(dv before . j), and that
        impulse's angle to the approach; e_normal along the normal forces' impulse (their sum over
        the contacts and the collision: the mean normal of a tilted, rough contact), its angle to the
        approach (the tilt), and the frictional impulse over the normal one."""
        before = self.n * (-side * 0.5 * v_rel)
        total = sum((O.bodies[i].state.mass * (O.bodies[i].state.vel - before) for i in self.members[1]),
                    Vector3(0, 0, 0))
        dv0 = self.n * (-side * v_rel)

        def along(u):
            u = u / u.norm()
            return -dv.dot(u) / dv0.dot(u), math.degrees(math.acos(max(-1.0, min(1.0, side * u.dot(self.n)))))
        out = dict(zip(("e_impulse", "impulse_angle_deg"), along(total)))
        if self.normal_impulse.norm() > 0:
            nn = self.normal_impulse / self.normal_impulse.norm()
            out.update(zip(("e_normal", "tilt_deg"), along(self.normal_impulse)))
            out["friction_over_normal_impulse"] = (total - nn * total.dot(nn)).norm() / abs(total.dot(nn))
        return out

    def _outcome(self, v_rel, side, start_time, seconds):
        ids = [i for m in self.members for i in m]
        parts = agglomerate.clusters(ids)
        mass = {i: O.bodies[i].state.mass for i in ids}
        total = sum(mass.values())
        frag = []
        for p in parts[:2]:
            share = [sum(mass[i] for i in p if self.owner[i] == k) for k in (0, 1)]
            frag.append({"ids": p, "mass": sum(share), "from": 0 if share[0] >= share[1] else 1,
                         "mixed": min(share) / sum(share), "v": agglomerate.velocity(p)})
        stuck = len(frag) < 2 or frag[0]["from"] == frag[1]["from"] or frag[0]["mixed"] > 0.25
        e_speed, deflection = 0.0, None
        impulse = dict.fromkeys(("e_impulse", "impulse_angle_deg", "e_normal", "tilt_deg",
                                 "friction_over_normal_impulse"))
        impulse["e_impulse"] = 0.0
        if stuck:
            e, broken = 0.0, 1.0 - frag[0]["mass"] / total
        else:
            a, b = sorted(frag, key=lambda f: f["from"])
            dv = b["v"] - a["v"]
            e = side * dv.dot(self.n) / v_rel
            e_speed = dv.norm() / v_rel  # with what the surfaces' tilt turned sideways
            impulse.update(self._impulse_measures(dv, side, v_rel))
            deflection = (math.degrees(math.acos(max(-1.0, min(1.0, side * dv.dot(self.n) / dv.norm()))))
                          if dv.norm() > 0 else None)
            broken = 1.0 - (a["mass"] + b["mass"]) / total
        return {"v_rel": v_rel, "e": e, "e_speed": e_speed, "deflection_deg": deflection, **impulse,
                "stuck": stuck, "broken_mass_fraction": broken,
                "fragments": len(parts), "largest": [f["mass"] / total for f in frag],
                "contact_time": (self.last - self.first) if self.first is not None else None,
                "touched": self.first is not None, "time": O.time - start_time, "wall_clock_s": seconds,
                "press_d0": ((max(r[2] for r in self.rows) - self.touch_delta) / self.protocol.d0
                             if self.first is not None else None),
                "largest_normal_force": max(r[5] for r in self.rows)}


def _surface_gap(first, second):
    """The smallest distance between the surfaces of a particle of ``first`` and one of ``second``."""
    import numpy as np
    pos = [np.array([list(O.bodies[i].state.pos) for i in m]) for m in (first, second)]
    rad = [np.array([O.bodies[i].shape.radius for i in m]) for m in (first, second)]
    return float((np.linalg.norm(pos[0][:, None, :] - pos[1][None, :, :], axis=2)
                  - rad[0][:, None] - rad[1][None, :]).min())
