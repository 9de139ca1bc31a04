"""The pull slaved to the affine stretch (issue #60, item 1): does the tested sample lose its tension
because its contacts do (shallow sintered overlaps), or collectively (a zone that gives first)?

The sample is pulled as uniaxial.Test.pull pulls it (each loading wall, or grip, out at ``speed``),
but every other particle's x velocity is prescribed: the affine field

    v_x(x) = speed (x - x_mid) / h,   h = L0/2 (walls) or L0/2 - t d0 (grips of thickness t),

clipped to +-speed, set once at the start and kept by YADE's blocked degrees of freedom (a
particle moving with its prescribed velocity stays on the affine field exactly: x - x_mid scales
as h(t)). ``hold`` says what else is held: 'x' (y, z and the rotations free: the sample is
unconfined, so its contacts decide its lateral contraction and spins; the mode of the deciding
run), 'xyz' (y and z held at their start too: the static estimate's kinematics, no lateral
contraction; rotations free) or 'xyzXYZ' (rotations held as well).

Recorded every ``every`` steps: Dx, the force on the loading walls (uniaxial.Test.force,
``F_wall``), the contacts' mean tension ``F_bulk`` (the force work-conjugate to the affine field:
sum over contacts of f_x (w2 - w1), w the field over twice the wall speed, +-1/2 at the walls and
grips; in a free pull at rest it equals F_wall, in the slaved one it is what the contacts carry,
the quantity the static estimate computes) and the contacts' branch fractions
(mesocontact.scene.branch_fractions, as Test records them); every ``slab_every`` records the
start's particle contacts on the tensile limit and open, overall and by slab, the slabs' local
strain, and the rms deviation of the particles from the affine field (x) and their lateral
displacement.

The static estimate (``static_curve``, plain numpy) is affine.curve for any field w: each contact
opens by Dx d0 (w2 - w1) nx and carries the law's unloading force from its own history; with the
walls' field w = (x - x_mid)/L0 it is affine.curve to rounding.

``job`` (inside YADE) runs the tested sample (free, slaved 'x', slaved 'xyz') and the deep sample
(d0 p_s/kp = 0.1, made in <out>/deep) through its 2-d0 grips and through the walls (free and
slaved 'x'), each a bundle <out>/<sample>/<run>/; ``report`` (plain Python) compares them with the static estimates and
draws slaved.png."""
import json
import os
import time

import numpy as np

from . import affine as _affine

HOLDS = ("x", "xyz", "xyzXYZ")
STATIC_BRANCHES = ("line", "tensile", "open")  # as profile.BRANCH_GROUPS
# The runs of the job: (sample, run name, preparation options, grips [d0], mode, hold).
DEEP = {"sinter": 0.1}
# The committed static estimate of the tested sample (affine.run; its L0 is the spheres' extent along x)
AFFINE_CSV = "campaigns/tablet/factors/frictionless-sinter-std0.1/affine/affine.csv"
RUNS = (("tested", "free", {}, None, "free", None),
        ("tested", "slaved-x", {}, None, "slaved", "x"),
        ("tested", "slaved-xyz", {}, None, "slaved", "xyz"),
        ("deep-grips2", "free", DEEP, 2.0, "free", None),
        ("deep-grips2", "slaved-x", DEEP, 2.0, "slaved", "x"),
        ("deep-walls", "free", DEEP, None, "free", None),
        ("deep-walls", "slaved-x", DEEP, None, "slaved", "x"))


def field(x, x_mid, half):
    """The affine field over twice the wall speed at positions ``x``: (x - x_mid) / (2 half), clipped
    to +-1/2 (the walls' and grips' own values)."""
    return np.clip((np.asarray(x, float) - x_mid) / (2.0 * half), -0.5, 0.5)


def static_state(c, dx, d0):
    """The contacts ``c`` (columns delta, delta0, k2, kc, nx, dw; dw = w2 - w1, nx the normal's x
    component from 1 to 2) when the loading ends have moved apart by dx d0 and every particle with
    the field: (force [force units] per contact, overlap)."""
    delta, delta0, k2, kc, nx, dw = (c[:, k] for k in range(6))
    d = delta - dx * d0 * dw * nx
    f = np.where(d > 0, np.maximum(k2 * (d - delta0), -kc * d), 0.0)
    return f, d


def static_curve(c, dx, d0):
    """The static estimate for the amplitudes ``dx``: rows (F, line, tensile, open) with F the wall
    force sum f nx dw [force units] (> 0 in compression) and the fractions of the contacts on a
    k1/kp/k2 line, on the tensile limit -kc delta and without overlap (profile.affine_branches)."""
    out = []
    n = max(1, len(c))
    for x in np.asarray(dx, float):
        f, d = static_state(c, x, d0)
        tensile = (d > 0) & (c[:, 2] * (d - c[:, 1]) <= -c[:, 3] * d)
        out.append((float(np.sum(f * c[:, 4] * c[:, 5])), float(np.sum((d > 0) & ~tensile) / n),
                    float(np.sum(tensile) / n), float(np.sum(d <= 0) / n)))
    return np.array(out)


def static_parts(c, dx, d0):
    """The static estimate's force at one amplitude ``dx`` split as PARTS' normal entries: the
    contacts on the tensile limit, the attractive and the repulsive ones on a line [force units]."""
    f, d = static_state(c, dx, d0)
    tensile = (d > 0) & (c[:, 2] * (d - c[:, 1]) <= -c[:, 3] * d)
    fx = f * c[:, 4] * c[:, 5]
    return (float(np.sum(fx[tensile])), float(np.sum(fx[~tensile & (f < 0)])), float(np.sum(fx[~tensile & (f >= 0)])))


# The parts of the contacts' mean tension recorded at each slab record: the particle contacts'
# normal forces on the tensile limit, attractive on a line, repulsive; their tangential forces; the
# walls' contacts.
PARTS = ("pp_normal_tensile", "pp_normal_attractive", "pp_normal_repulsive", "pp_shear", "walls")
START_CONTACTS_COLUMNS = ("iter", "Dx", "line", "tensile", "open", "static_line", "static_tensile", "static_open",
                          "rms_affine_dev_d0", "rms_lateral_d0", "max_strain_over_affine", "at_d0", "F_contacts",
                          *("F_" + p for p in PARTS), "static_F_tensile", "static_F_attractive", "static_F_repulsive")


def peak_summary(dx, force):
    """The most tensile force (min), where, and what is kept of it at Dx 0.1, 0.2 and 0.3."""
    dx, force = np.asarray(dx, float), np.asarray(force, float)
    k = int(np.argmin(force))
    kept = {f"{x:g}": float(np.interp(x, dx, force) / force[k]) if dx[-1] >= x - 1e-9 and force[k] < 0 else None
            for x in (0.05, 0.1, 0.2, 0.3)}
    return {"peak_F": float(force[k]), "peak_Dx": float(dx[k]), "kept_of_peak": kept}


def first_reaching(dx, values, level):
    """The first Dx where ``values`` reach ``level`` (None if they do not)."""
    return next((float(x) for x, v in zip(dx, values) if v >= level), None)


# ---------------------------------------------------------------------------------------------
# Inside YADE


def _start_contacts(walls, grips, x_mid, half):
    """The particle contacts of the scene in overlap, as the static estimate reads them (contacts
    inside one grip left out): (array delta, delta0, k2, kc, nx, dw; list of id pairs)."""
    from yade import O
    rows, pairs = [], []
    grip_of = {i: side for side, ids in grips.items() for i in ids}
    for i, branch, length, delta in _affine.particle_contacts(
            lambda i: i.id1 in grip_of and grip_of.get(i.id2) == grip_of[i.id1]):
        w1, w2 = (0.5 * grip_of[b] if b in grip_of else float(field(O.bodies[b].state.pos[0], x_mid, half))
                  for b in (i.id1, i.id2))
        rows.append((delta, i.phys.delta0, i.phys.k2, i.phys.kc, branch[0] / length, w2 - w1))
        pairs.append((i.id1, i.id2))
    return np.array(rows), pairs


DEFINITIONS = {
    "F_wall": "uniaxial.Test.force: (f_right - f_left)/2 on the loading walls (grips), over kp d0, > 0 in "
              "compression",
    "F_bulk": "sum over bodies of w F_x (F this step's force on the body: its contacts and the drag), w = "
              "(x - x_mid)/(2 h) clipped to +-1/2 (+-1/2 on the walls and grips), over kp d0: the force "
              "work-conjugate to the affine field; = sum over contacts of f_x (w2 - w1) but for the drag "
              "(max_F_bulk_bodies_minus_contacts: the largest difference at the slab records)",
    "F_pp": "F_bulk less its walls' contacts' part: the particle contacts' mean tension, the quantity "
            "of the static estimate (in a free pull at rest F_pp = F_wall (1 - about d0/L0): the "
            "particle contacts span the centres of the outer layers, not the walls' distance)",
    "F_contacts": "F_bulk from the contacts alone (no drag), recorded with start-contacts.csv, and its "
                  "parts F_<part> (PARTS: particle contacts' normal force on the tensile limit, "
                  "attractive on a line, repulsive, their tangential force, the walls' contacts); "
                  "static_F_*: the static estimate's tensile, attractive-line and repulsive parts",
    "start contacts": "the particle contacts in overlap at the start (inside one grip left out): on a "
                      "k1/kp/k2 line, on the tensile limit -kc delta, open (no overlap or gone)",
    "static": "each start contact opened by Dx d0 (w2 - w1) nx along its own unloading (affine.curve "
              "for the field w)"}


class _Recorder:
    """What one pull records (inside YADE): ``hook`` is the test's on_record. ``rows`` (iter, Dx,
    F_wall, F_bulk, F_pp) every record; every ``slab_every`` records ``contact_rows``
    (START_CONTACTS_COLUMNS), ``slab_rows`` and ``drag_check`` (F_bulk from the bodies less from the
    contacts). The field: x_mid, the walls' and grips' fixed values (``grip_side``: +-1 -> ids), the
    free part's half length h = L/2 - t_grip d0."""

    def __init__(self, test, walls, grip_side, x_mid, t_grip, contacts, pairs, slab_every):
        from yade import O
        from mesocontact import scene as _scene
        from . import sample
        self.O, self.sample, self.test = O, sample, test
        self.x_mid, self.t_grip, self.contacts, self.pairs, self.slab_every = x_mid, t_grip, contacts, pairs, slab_every
        self.scale = sample.KP * sample.D0
        self.tensile_index = _scene.BRANCHES.index("tensile")
        self.wall_set = set(walls.values())
        self.ids = sample.sphere_ids()
        in_grip = {i for m in grip_side.values() for i in m}
        self.free_ids = [i for i in self.ids if i not in in_grip]
        self.lo, hi = sample.inner_box()
        self.half0 = self.half()  # after the test's first step (its L0)
        self.start = {i: O.bodies[i].state.pos for i in self.ids}
        self.start = {i: (p[0], p[1], p[2]) for i, p in self.start.items()}
        self.w_start = {i: float(field(self.start[i][0], x_mid, self.half0)) for i in self.free_ids}
        self.fixed_w = {walls["left"]: -0.5, walls["right"]: 0.5}  # the field's value, fixed for walls and grips
        for s, m in grip_side.items():
            self.fixed_w.update({i: 0.5 * s for i in m})
        lo, length = self.lo[0], hi[0] - self.lo[0]
        self.n_slabs = n = max(2, int(round(length / sample.D0)))
        slab_of = {i: min(n - 1, max(0, int((self.start[i][0] - lo) / length * n))) for i in self.ids}
        self.slab_ids = [[i for i in self.ids if slab_of[i] == k] for k in range(n)]
        self.slab_x0 = [sum(self.start[i][0] for i in m) / len(m) for m in self.slab_ids]
        self.pair_slab = np.array([min(n - 1, max(0, int((0.5 * (self.start[a][0] + self.start[b][0]) - lo) / length
                                                         * n))) for a, b in pairs])
        self.rows, self.contact_rows, self.slab_rows, self.drag_check = [], [], [], []

    def half(self):
        lo, hi = self.sample.inner_box()
        return 0.5 * (hi[0] - lo[0]) - self.t_grip * self.sample.D0

    def w_of(self, b, half):
        if b in self.fixed_w:
            return self.fixed_w[b]
        return min(0.5, max(-0.5, (self.O.bodies[b].state.pos[0] - self.x_mid) / (2 * half)))

    def slave(self, hold, speed):
        """Prescribes the free particles' velocities: x on the field (2 speed w), y and z zero where
        ``hold`` holds them, the spins zero if it holds rotations; blockedDOFs keeps them."""
        from yade import Vector3
        for i in self.free_ids:
            st = self.O.bodies[i].state
            v = st.vel
            st.blockedDOFs = hold
            st.vel = Vector3(2.0 * speed * self.w_start[i], 0.0 if "y" in hold else v[1], 0.0 if "z" in hold else v[2])
            if "X" in hold:
                st.angVel = Vector3(0, 0, 0)

    def f_bodies(self):
        """F_bulk over kp d0 from the bodies' forces of this step: the loading ends' (Test.force) and
        the free particles' (these include the background drag)."""
        half, total = self.half(), 0.0
        for i in self.free_ids:
            total += self.O.forces.f(i)[0] * self.w_of(i, half)
        return self.test.force() + total / self.scale

    def f_parts(self):
        """F_bulk over kp d0 from the contacts' forces, as the parts of PARTS (a pass over the
        interactions)."""
        half, parts = self.half(), [0.0] * len(PARTS)
        for inter in self.O.interactions:
            if not inter.isReal:
                continue
            w1, w2 = self.w_of(inter.id1, half), self.w_of(inter.id2, half)
            if w1 == w2:
                continue
            fn, fs = inter.phys.normalForce, inter.phys.shearForce
            if inter.id1 in self.wall_set or inter.id2 in self.wall_set:
                parts[4] += (fn[0] + fs[0]) * (w2 - w1)
                continue
            k = 0 if inter.phys.branchIndex == self.tensile_index else 1 if fn.dot(inter.geom.normal) < 0 else 2
            parts[k] += fn[0] * (w2 - w1)
            parts[3] += fs[0] * (w2 - w1)
        return [x / self.scale for x in parts]

    def f_walls(self):
        """The walls' contacts' part of F_bulk (PARTS' 'walls'), over kp d0: F_bulk less it is the
        particle contacts' mean tension F_pp, what the static estimate computes."""
        half, total = self.half(), 0.0
        for wid in self.wall_set:
            for inter in self.O.bodies[wid].intrs():
                if inter.isReal:
                    total += ((inter.phys.normalForce[0] + inter.phys.shearForce[0])
                              * (self.w_of(inter.id2, half) - self.w_of(inter.id1, half)))
        return total / self.scale

    def status(self):
        """The start's contacts now: 0 on a line, 1 on the tensile limit, 2 open (no overlap or gone)."""
        out = []
        for a, b in self.pairs:
            inter = self.O.interactions[a, b] if self.O.interactions.has(a, b) else None
            if inter is None or not inter.isReal or inter.geom.penetrationDepth <= 0:
                out.append(2)
            else:
                out.append(1 if inter.phys.branchIndex == self.tensile_index else 0)
        return np.array(out)

    def deviations(self):
        """The rms deviation of the free particles from the affine field along x and their rms
        lateral displacement [d0]."""
        half, dev, lat = self.half(), 0.0, 0.0
        for i in self.free_ids:
            p = self.O.bodies[i].state.pos
            dev += (p[0] - (self.x_mid + 2 * self.w_start[i] * half)) ** 2
            lat += (p[1] - self.start[i][1]) ** 2 + (p[2] - self.start[i][2]) ** 2
        n, d0 = len(self.free_ids), self.sample.D0
        return (dev / n) ** 0.5 / d0, (lat / n) ** 0.5 / d0

    def strains(self, dx):
        """The local strain between neighbouring slabs over the field's (ones at Dx = 0)."""
        u = [sum(self.O.bodies[i].state.pos[0] - self.start[i][0] for i in m) / len(m) for m in self.slab_ids]
        eps = dx * self.sample.D0 / (2 * self.half0)
        return np.diff(u) / np.diff(self.slab_x0) / eps if eps > 0 else np.ones(self.n_slabs - 1)

    def hook(self, t, row):
        f = self.f_bodies()
        self.rows.append((row[0], row[1], row[2], f, f - self.f_walls()))
        if (len(t.rows) - 1) % self.slab_every:
            return
        parts = self.f_parts()
        self.drag_check.append(abs(self.rows[-1][3] - sum(parts)))
        dev, lat = self.deviations()
        status = self.status()
        counts = [float(np.mean(status == k)) for k in range(3)]
        d0 = self.sample.D0
        f_st = static_curve(self.contacts, [row[1]], d0)[0]
        strains = self.strains(row[1])
        k = int(np.argmax(strains))
        self.contact_rows.append((row[0], row[1], *counts, *f_st[1:], dev, lat, float(strains[k]),
                                  0.5 * (self.slab_x0[k] + self.slab_x0[k + 1] - 2 * self.lo[0]) / d0, sum(parts),
                                  *parts, *(x / self.scale for x in static_parts(self.contacts, row[1], d0))))
        last = self.n_slabs - 2
        for s in range(self.n_slabs):
            sel = status[self.pair_slab == s]
            n = max(1, len(sel))
            strain = strains[min(s, last)] if s == 0 else 0.5 * (strains[s - 1] + strains[min(s, last)])
            self.slab_rows.append((row[0], row[1], s, (self.slab_x0[s] - self.lo[0]) / d0, float(strain),
                                   float(np.sum(sel == 0) / n), float(np.sum(sel == 1) / n),
                                   float(np.sum(sel == 2) / n)))


def _first_dx(rec, dx_static, static):
    """The first Dx where 1 % and 10 % of the start's contacts are on the tensile limit or open
    (measured and static), and where the largest local strain first reaches twice the field's."""
    dx = [r[1] for r in rec.contact_rows]
    out = {}
    for key, col in (("tensile_1pc", 3), ("tensile_10pc", 3), ("open_1pc", 4), ("open_10pc", 4)):
        level = 0.01 if key.endswith("_1pc") else 0.1
        out[key] = {"measured": first_reaching(dx, [r[col] for r in rec.contact_rows], level),
                    "static": first_reaching(dx_static, static[:, col - 1], level)}
    out["local_strain_2x"] = first_reaching(dx[1:], [r[10] for r in rec.contact_rows][1:], 2.0)
    return out


def _write(where, rec, test, dx_static, static, info):
    from mesocontact import outputs
    from mesocontact import scene as _scene
    from .campaign.common import csv_text
    with outputs.Bundle(where) as b:
        b.write_text("run.csv", csv_text(rec.rows, "iter,Dx,F_wall,F_bulk,F_pp"))
        b.write_text("branches.csv", csv_text(test.branches, "iter,Dx," + ",".join(_scene.BRANCHES)))
        b.write_text("start-contacts.csv", csv_text(rec.contact_rows, ",".join(START_CONTACTS_COLUMNS)))
        b.write_text("slabs.csv", csv_text(rec.slab_rows, "iter,Dx,slab,x_d0,strain_over_affine,line,tensile,open"))
        b.write_text("static.csv", "Dx,F_over_kp_d0,line,tensile,open\n"
                     + "".join(f"{x!r}," + ",".join(repr(float(v)) for v in r) + "\n"
                               for x, r in zip(dx_static, static)))
        b.write_json("run.json", info)


def run(outdir, sample_name, name, protocol=None, grips=None, mode="slaved", hold="x", until=0.3, speed=None,
        every=10, slab_every=10, quick=False, progress=True):
    """One pull of the unconfined start (campaign.prepare with ``protocol``, in ``outdir``) to
    Dx = ``until`` at ``speed`` (default PULL_SPEED) with the campaign's pull step, free or slaved
    (``hold``), through the walls or ``grips`` [d0]: bundle <outdir>/<sample_name>/<name>/ with
    run.csv, branches.csv, start-contacts.csv, slabs.csv, static.csv and run.json. Returns the
    description."""
    from yade import O
    from mesocontact import outputs
    from . import sample, uniaxial
    from .campaign.common import DT_FACTORS, PROTOCOL, PULL_SPEED, prepare

    if mode not in ("free", "slaved"):
        raise ValueError(f"mode = {mode!r} is invalid: 'free' or 'slaved'")
    if mode == "slaved" and hold not in HOLDS:
        raise ValueError(f"hold = {hold!r} is invalid: one of {HOLDS}")
    speed = speed or PULL_SPEED
    where = os.path.join(outdir, "quick" if quick else "", sample_name, name)
    if outputs.complete(where):
        with open(os.path.join(where, "run.json")) as f:
            return json.load(f)
    t_start = time.time()
    prepare(outdir, quick, progress, **(protocol or {}))
    O.dt *= DT_FACTORS["pull"]
    walls = sample.wall_ids()
    lo, hi = sample.inner_box()
    x_mid = 0.5 * (lo[0] + hi[0])
    t_grip = grips or 0.0
    members = uniaxial.grip_members(grips) if grips is not None else {}
    side = {walls["left"]: -1.0, walls["right"]: 1.0}
    grip_side = {side[w]: ids for w, ids in members.items()}
    half0 = 0.5 * (hi[0] - lo[0]) - t_grip * sample.D0
    contacts, pairs = _start_contacts(walls, grip_side, x_mid, half0)  # before the test's first step, as affine.run
    dx_static = np.round(np.arange(0.0, until + 1e-9, 0.002), 6)
    static = static_curve(contacts, dx_static, sample.D0)
    static[:, 0] /= sample.KP * sample.D0

    test = uniaxial.Test(progress=progress)
    if grips is not None:
        test.use_grips(grips, members)
    rec = _Recorder(test, walls, grip_side, x_mid, t_grip, contacts, pairs, slab_every)
    if mode == "slaved":
        rec.slave(hold, speed)
    t0, it0 = time.time(), O.iter
    test.pull(speed, until=until, every=every, on_record=rec.hook)
    wall = time.time() - t0
    steps = O.iter - it0
    dx = np.array([r[1] for r in rec.rows])
    info = {"sample": sample_name, "name": name, "mode": mode, "hold": hold if mode == "slaved" else None,
            "grips": test.grips, "grip_thickness_d0": grips, "speed": speed, "until": until, "every": every,
            "dt": O.dt, "L0": test.L0, "L0_d0": test.L0 / sample.D0, "free_half_length_d0": rec.half0 / sample.D0,
            "protocol": dict(PROTOCOL, **(protocol or {})), "quick": quick,
            "particles": len(rec.ids), "slaved_particles": len(rec.free_ids) if mode == "slaved" else 0,
            "start_contacts": len(pairs), "slabs": rec.n_slabs,
            "wall": peak_summary(dx, [r[2] for r in rec.rows]), "bulk": peak_summary(dx, [r[3] for r in rec.rows]),
            "pp": peak_summary(dx, [r[4] for r in rec.rows]),
            "static": peak_summary(dx_static, static[:, 0]),
            "max_rms_affine_deviation_d0": max(r[8] for r in rec.contact_rows),
            "max_rms_lateral_d0": max(r[9] for r in rec.contact_rows),
            "max_F_bulk_bodies_minus_contacts": max(rec.drag_check),
            "steps": steps, "wall_clock_s": wall, "total_wall_clock_s": time.time() - t_start,
            "ms_per_step": 1e3 * wall / max(1, steps), "definitions": DEFINITIONS,
            "first_Dx": _first_dx(rec, dx_static, static)}
    _write(where, rec, test, dx_static, static, info)
    if progress:
        print(f"{sample_name}/{name}: F_pp peak {info['pp']['peak_F']:.4g} at Dx {info['pp']['peak_Dx']:.3g}, "
              f"wall peak {info['wall']['peak_F']:.4g}; static {info['static']['peak_F']:.4g}; {wall:.0f} s for "
              f"{steps} steps", flush=True)
    return info


def job(outdir, quick=False, until=0.3, speed=None, runs=RUNS, progress=True, affine_csv=AFFINE_CSV):
    """The runs (RUNS: the tested sample free and slaved, the deep one through 2-d0 grips and through
    the walls, free and slaved), one after the other in this process (each from a freshly loaded
    start), then the report. The deep sample's start is made in <outdir>/deep (stages.ensure).
    Returns the report."""
    for sample_name, name, protocol, grips, mode, hold in runs:
        where = outdir if not protocol else os.path.join(outdir, sample_name.split("-")[0])
        t0 = time.time()
        run(where, sample_name, name, protocol, grips, mode, hold, until=until, speed=speed, quick=quick,
            progress=progress)
        if progress:
            print(f"{sample_name}/{name}: {time.time() - t0:.0f} s in this job", flush=True)
    return report(outdir, quick, affine_csv=affine_csv)


# ---------------------------------------------------------------------------------------------
# Plain Python: the comparison and the figure


def _read(path):
    with open(path) as f:
        head = f.readline().strip().split(",")
        data = np.array([[float(x) for x in line.split(",")] for line in f if line.strip()])
    return {h: data[:, k] for k, h in enumerate(head)}


def _bundle(outdir, quick, sample_name, name):
    """The run's tables and description, searched in <outdir>[/deep]/[quick/]<sample>/<name>/."""
    for base in (outdir, os.path.join(outdir, sample_name.split("-")[0])):
        d = os.path.join(base, "quick" if quick else "", sample_name, name)
        if os.path.exists(os.path.join(d, "run.json")):
            with open(os.path.join(d, "run.json")) as f:
                info = json.load(f)
            return {"dir": d, "info": info, **{k: _read(os.path.join(d, k + ".csv"))
                                               for k in ("run", "branches", "start-contacts", "slabs", "static")}}
    return None


def compare(runs):
    """The numbers the verdict reads, per sample: the static estimate's peak and force at a few Dx;
    for each run the particle contacts' mean tension F_pp (and the walls' force) with its peak,
    what it keeps, its ratio to the static estimate, and its parts (PARTS) at those Dx."""
    marks = (0.01, 0.02, 0.03, 0.04, 0.06, 0.1, 0.2, 0.3)
    out = {}
    for sample_name, by_name in runs.items():
        static = next(iter(by_name.values()))["static"]
        sdx, sf = static["Dx"], static["F_over_kp_d0"]
        rows = {"static": {**peak_summary(sdx, sf), "F_at": {f"{x:g}": float(np.interp(x, sdx, sf)) for x in marks}}}
        for name, r in by_name.items():
            dx = r["run"]["Dx"]
            at = [x for x in marks if x <= dx[-1] + 1e-9]
            sc = r["start-contacts"]
            rows[name] = {
                "F_pp": peak_summary(dx, r["run"]["F_pp"]), "F_wall": peak_summary(dx, r["run"]["F_wall"]),
                "F_pp_at": {f"{x:g}": float(np.interp(x, dx, r["run"]["F_pp"])) for x in at},
                "F_wall_at": {f"{x:g}": float(np.interp(x, dx, r["run"]["F_wall"])) for x in at},
                "F_pp_over_static_at": {f"{x:g}": float(np.interp(x, dx, r["run"]["F_pp"]) / np.interp(x, sdx, sf))
                                        for x in at},
                "parts_at": {f"{x:g}": {p: float(np.interp(x, sc["Dx"], sc["F_" + p])) for p in PARTS} for x in at},
                "start_contacts_at": {f"{x:g}": {k: float(np.interp(x, sc["Dx"], sc[k]))
                                                 for k in ("tensile", "open", "static_tensile", "static_open",
                                                           "max_strain_over_affine", "rms_lateral_d0")} for x in at},
                "first_Dx": r["info"]["first_Dx"],
                "localization_from_Dx": {f"{k:g}": persistent_from(sc["Dx"], sc["max_strain_over_affine"], k)
                                         for k in (1.5, 2.0)},
                "wall_clock_s": r["info"]["wall_clock_s"], "steps": r["info"]["steps"]}
        out[sample_name] = rows
    return out


def persistent_from(dx, strain, factor):
    """The Dx from which the largest local strain stays at least ``factor`` times the affine one
    (profile.persistent_from for columns; None if it does not by the end)."""
    start = None
    for x, m in zip(dx, strain):
        if x <= 0:
            continue
        if m < factor:
            start = None
        elif start is None:
            start = float(x)
    return start


def report(outdir, quick=False, png=None, affine_csv=None):
    """Reads the job's bundles, writes <outdir>/slaved.json (compare) and the figures slaved.png and
    slaved-force.png; ``affine_csv``: the committed static estimate of the tested sample to draw
    beside this code's (campaigns/tablet/factors/frictionless-sinter-std0.1/affine/affine.csv).
    Returns the comparison."""
    runs = {}
    for sample_name, name, *_ in RUNS:
        b = _bundle(outdir, quick, sample_name, name)
        if b is not None:
            runs.setdefault(sample_name, {})[name] = b
    cmp = compare(runs)
    root = os.path.join(outdir, "quick") if quick else outdir
    with open(os.path.join(root, "slaved.json"), "w") as f:
        json.dump(cmp, f, indent=1)
    png = png or os.path.join(root, "slaved.png")
    affine_csv = None if quick else affine_csv  # the committed estimate is the full sample's
    plot(runs, png, affine_csv)
    plot_force(runs, png.replace(".png", "-force.png"), affine_csv)
    return cmp


STYLE = {"free": "k", "slaved-x": "C3", "slaved-xyz": "C1", "slaved-xyzXYZ": "C4"}


def _title(sample_name, by_name):
    grips = next(iter(by_name.values()))["info"].get("grip_thickness_d0")
    return sample_name + (f" (through {grips:g}-d0 grips)" if grips else " (through the walls)")


def _force_axes(a, sample_name, by_name, affine_csv, letter="a"):
    """The force panel, lettered ``letter`` ((a) in ``plot``): the static estimate, the committed one
    (tested), each run's F_pp, the free pull's wall force and the slaved pulls' normal part of F_pp."""
    static = next(iter(by_name.values()))["static"]
    a.plot(static["Dx"], -static["F_over_kp_d0"], color="C0", ls="--", lw=2.2, label="static affine estimate")
    if affine_csv and sample_name == "tested" and os.path.exists(affine_csv):
        committed = _read(affine_csv)
        sel = committed["Dx"] <= static["Dx"][-1] + 1e-9
        a.plot(committed["Dx"][sel], -committed["F_over_kp_d0"][sel], color="C9", ls=":", lw=1.2,
               label="static, committed affine.csv (L0: spheres' extent)")
    for name, r in by_name.items():
        colour = STYLE.get(name, "C2")
        a.plot(r["run"]["Dx"], -r["run"]["F_pp"], color=colour, lw=1.6, label=f"{name}: particle contacts F_pp")
        sc = r["start-contacts"]
        if name.startswith("free"):
            a.plot(r["run"]["Dx"], -r["run"]["F_wall"], color=colour, lw=0.7, ls="--", label=f"{name}: wall force")
        else:
            normal = sum(sc["F_" + p] for p in PARTS[:3])
            a.plot(sc["Dx"], -normal, color=colour, lw=1.0, ls=":", label=f"{name}: F_pp's normal forces only")
    a.axhline(0, color="0.6", lw=0.6)
    a.set_xlabel("Dx = (L - L0)/d0")
    a.set_ylabel("tension -F/(kp d0)")
    a.set_title(f"({letter}) {_title(sample_name, by_name)}: force", fontsize=10)
    a.legend(fontsize=7)


def plot_force(runs, png, affine_csv=None):
    """Only the force panels (a) of ``plot``, one per sample, lettered (a), (b), ... in the samples'
    order. Returns the panels' titles."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(runs), figsize=(6 * len(runs), 4.6), squeeze=False)
    for k, (a, sample_name) in enumerate(zip(axes[0], runs)):
        _force_axes(a, sample_name, runs[sample_name], affine_csv, letter=chr(ord("a") + k))
    titles = [a.get_title() for a in axes[0]]
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    plt.close(fig)
    return titles


def plot(runs, png, affine_csv=None):
    """Per sample: (a) F against Dx (_force_axes); (b) the start's contacts on the tensile limit and
    open, measured and static; (c) where: the start's contacts on the tensile limit or open by slab,
    free (solid) and slaved 'x' (dashed), at a few Dx."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    samples = list(runs)
    fig, axes = plt.subplots(len(samples), 3, figsize=(17, 4.8 * len(samples)), squeeze=False)
    for row, sample_name in zip(axes, samples):
        a, b, c = row
        by_name = runs[sample_name]
        _force_axes(a, sample_name, by_name, affine_csv)
        sc = next(iter(by_name.values()))["start-contacts"]
        for key, colour in (("tensile", "C3"), ("open", "C0")):
            b.plot(sc["Dx"], sc["static_" + key], color=colour, ls="--", lw=2.2, label=f"{key}: static")
        for name, r in by_name.items():
            s = r["start-contacts"]
            ls = {"free": ":", "slaved-x": "-", "slaved-xyz": "-."}.get(name, "-")
            for key, colour in (("tensile", "C3"), ("open", "C0")):
                b.plot(s["Dx"], s[key], color=colour, ls=ls, lw=1.2, label=f"{key}: {name}")
        b.set_xlabel("Dx")
        b.set_ylabel("fraction of the start's particle contacts")
        b.set_title("(b) on the tensile limit -kc delta, and open", fontsize=10)
        b.legend(fontsize=7, ncol=2)
        marks = (0.01, 0.02, 0.04, 0.1, 0.3)
        for name, ls in (("free", "-"), ("slaved-x", "--")):
            if name not in by_name:
                continue
            sl = by_name[name]["slabs"]
            its = np.unique(sl["iter"])
            dxs = np.array([sl["Dx"][sl["iter"] == i][0] for i in its])
            for k, m in enumerate(marks):
                it = its[int(np.argmin(abs(dxs - m)))]
                sel = sl["iter"] == it
                c.plot(sl["x_d0"][sel], sl["open"][sel] + sl["tensile"][sel], color=f"C{k}", ls=ls, marker="o", ms=2.5,
                       lw=1, label=f"{name}, Dx = {dxs[its == it][0]:.3f}")
        c.set_xlabel("slab centre: distance from the left wall's face [d0]")
        c.set_ylabel("start contacts on -kc delta or open")
        c.set_title("(c) where: by slab (free solid, slaved-x dashed)", fontsize=10)
        c.legend(fontsize=6, ncol=2)
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    plt.close(fig)
