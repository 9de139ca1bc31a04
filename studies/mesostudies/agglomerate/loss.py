"""Where the agglomerates' cycles lose energy and hold on (issue #59, item 2; plain Python).

Rows are a cycle run's (iter, delta, F) with F > 0 pushing the two apart; events its turns
(what, iter, delta, F). Work is the trapezoidal sum of F d(delta): > 0 while pressing, < 0 while the
pair pushes the caps back. Units are the run's (mm and the study's force unit, 1e3 N: work in
1e3 N mm = 1 J).

- ``loops``: per cycle (a loading to a turn and the unloading after it), the work put in while
  loading, the work given back while unloading, the loss (their sum, the loop's area when it
  closes), and the tension's work (the part of the unloading with F < 0);
- ``pull``: the last stroke apart of a run that ends apart: the tension's work, its largest
  force, and its range (from the first touch to where the last contact let go, in d0);
- ``viscous_gamma``: gammaN from the extra loss of a faster run over a slower one, both through
  the same turns: a dashpot gammaN at constant relative speed v adds gammaN v per unit of path in
  contact, so gammaN = (loss_fast - loss_slow) / (v_fast - v_slow) / path.
"""
D0 = 0.01  # mm, the primaries' d0


def work(rows):
    """sum F d(delta) along rows (trapezoids): > 0 while pressing, < 0 while the pair pushes back."""
    return sum(0.5 * (a[2] + b[2]) * (b[1] - a[1]) for a, b in zip(rows, rows[1:]))


def _between(rows, i0, i1):
    return [r for r in rows if i0 <= r[0] <= i1]


def _tension_work(rows):
    """The work of the tensile forces (F < 0) along rows: > 0 when the pair held on while pulled apart."""
    return -sum(0.5 * (min(a[2], 0.0) + min(b[2], 0.0)) * (a[1] - b[1]) for a, b in zip(rows, rows[1:]))


def loops(rows, events):
    """[{amplitude, w_in, w_back, loss, tension_work, path}] per loaded turn (see the module);
    path: the loading's and unloading's length where |F| exceeds 1 % of the run's largest."""
    scale = max(abs(r[2]) for r in rows)
    out = []
    for k, e in enumerate(events):
        if not e[0].startswith("loaded to") or k + 1 >= len(events):
            continue
        load, unload = _between(rows, events[k - 1][1], e[1]), _between(rows, e[1], events[k + 1][1])
        w_in, w_back = work(load), work(unload)
        path = sum(abs(b[1] - a[1]) for a, b in list(zip(load, load[1:])) + list(zip(unload, unload[1:]))
                   if abs(a[2]) > 0.01 * scale)
        out.append({"amplitude": float(e[0].split()[2]), "w_in": w_in, "w_back": w_back, "loss": w_in + w_back,
                    "tension_work": _tension_work(unload), "path": path})
    return out


def pull(rows, events):
    """The last stroke apart (from the last turn to the end): tension work, largest tension, the
    range from the first touch to where the last contact let go [d0], and how the stroke ended."""
    touch = next(e for e in events if e[0] == "touch")
    last = events[-1]
    start = max(e[1] for e in events if e[0].startswith("loaded to"))
    stroke = _between(rows, start, last[1])
    return {"tension_work": _tension_work(stroke), "largest_tension": -min(r[2] for r in stroke),
            "range_d0": (touch[2] - last[2]) / D0, "ended": last[0]}


def viscous_gamma(slow, fast, v_slow, v_fast):
    """gammaN per loaded turn from two runs' loops (loops()) at relative speeds v_slow < v_fast, over
    the slow run's path in contact [force/(length/time)]; None for a fast loop whose loading takes
    no work (the force read on the caps is then their inertia's, not the contact's)."""
    return [(f["loss"] - s["loss"]) / (v_fast - v_slow) / s["path"] if f["w_in"] > 0 else None
            for s, f in zip(slow, fast) if s["amplitude"] == f["amplitude"] and s["path"] > 0]


LOSS_TERMS = ("mesoPlastic", "mesoRolling", "mesoSliding", "mesoTorsion", "mesoViscous")  # dissipated for good


def dissipated(events, event_energy, terms=LOSS_TERMS):
    """Per loop (from the turn before a loading to the unloading after it), the change of each
    dissipation term of O.energy read at the turns (Pair.event_energy), their sum ``total``, and
    the change of the other terms (stored, drag, kinetic) beside them: [{amplitude, by term}]."""
    out = []
    for k, e in enumerate(events):
        if not e[0].startswith("loaded to") or k + 1 >= len(events):
            continue
        a, b = event_energy[k - 1], event_energy[k + 1]
        row = {"amplitude": float(e[0].split()[2])}
        row.update({t: b.get(t, 0.0) - a.get(t, 0.0) for t in sorted(set(a) | set(b))})
        row["total"] = sum(row.get(t, 0.0) for t in terms)
        out.append(row)
    return out


def viscous_gamma_dissipated(slow_loops, slow_dissipated, fast_loops, fast_dissipated, v_slow, v_fast):
    """viscous_gamma on the law's own bookkeeping: the contacts' dissipation per loop (dissipated()'s
    ``total``, the background drag left out, as in a collision) instead of the caps' loop, whose
    F d(delta) misses the work of caps that the free parts lag behind; over the slow run's path.
    None where the fast loop's loading takes no work by the caps' reading (a start dominated by
    the caps' inertia, as viscous_gamma)."""
    out = []
    for sl, sd, fl, fd in zip(slow_loops, slow_dissipated, fast_loops, fast_dissipated):
        if sl["amplitude"] != fl["amplitude"] or sl["path"] <= 0:
            continue
        out.append((fd["total"] - sd["total"]) / (v_fast - v_slow) / sl["path"] if fl["w_in"] > 0 else None)
    return out


def extra_loss_points(slow_loops, slow_dissipated, fast_loops, fast_dissipated, v_slow, v_fast):
    """Per loop as viscous_gamma_dissipated: (v_slow, v_fast, the contacts' extra dissipation over the
    slow run's per length of the slow run's path in contact [force], the loop's amplitude); None for a
    fast loop whose loading takes no work. What a rate law of the contact must lose on that path at v_fast."""
    return [(v_slow, v_fast, (fd["total"] - sd["total"]) / sl["path"], sl["amplitude"]) if fl["w_in"] > 0 else None
            for sl, sd, fl, fd in zip(slow_loops, slow_dissipated, fast_loops, fast_dissipated)
            if sl["amplitude"] == fl["amplitude"] and sl["path"] > 0]


def rate_dashpots(points, relative=False):
    """(gammaN, gammaN2, residuals): the linear and the quadratic dashpot, each >= 0, whose loss along
    a path run at constant speed, gammaN v + gammaN2 v^2 per length, meets the points' extra loss
    y = gammaN (v_fast - v_slow) + gammaN2 (v_fast^2 - v_slow^2) in least squares (points from
    extra_loss_points; None skipped), unweighted: the largest losses (the fastest loops) weigh most.
    Residuals y - fit, per point given. ValueError with fewer than two distinct speed pairs.
    relative: each point weighted by 1/|y| instead (its relative miss counts), a diagnostic."""
    pts = [p for p in points if p is not None]
    pairs = {p[:2] for p in pts}
    if len(pairs) < 2:
        raise ValueError(f"rate_dashpots: {len(pts)} usable point(s) from {len(pairs)} pair(s) of speeds; two pairs "
                         "are needed for two dashpots (one pair fixes only their sum there)")
    raw = [(vf - vs, vf * vf - vs * vs, y) for vs, vf, y, *_ in pts]
    if relative and any(y == 0 for *_, y in raw):
        raise ValueError("rate_dashpots: relative=True weights each point by 1/|y|, and a point has y = 0")
    cols = [(a / abs(y), b / abs(y), y / abs(y)) for a, b, y in raw] if relative else raw

    def one(k):  # the best with the other dashpot at 0
        return max(sum(c[k] * c[2] for c in cols) / sum(c[k] * c[k] for c in cols), 0.0)

    s11, s12, s22 = (sum(c[0] * c[0] for c in cols), sum(c[0] * c[1] for c in cols), sum(c[1] * c[1] for c in cols))
    r1, r2 = sum(c[0] * c[2] for c in cols), sum(c[1] * c[2] for c in cols)
    det = s11 * s22 - s12 * s12
    g1, g2 = (r1 * s22 - r2 * s12) / det, (s11 * r2 - s12 * r1) / det
    if g1 < 0 or g2 < 0:  # the least squares lie on a bound: the better of the two one-dashpot fits
        cands = [(one(0), 0.0), (0.0, one(1))]
        g1, g2 = min(cands, key=lambda g: sum((c[2] - g[0] * c[0] - g[1] * c[1]) ** 2 for c in cols))
    return g1, g2, [c[2] - g1 * c[0] - g2 * c[1] for c in raw]


def caps_work(rows, events, cap_speed, dt):
    """Per loop (as loops()), the caps' own work: F times the caps' approach, each cap moving at
    ``cap_speed`` (> 0) for (iter_b - iter_a) steps of ``dt`` between rows, towards the other while
    loading and away while unloading. Unlike loops()' F d(delta), it holds when the free parts lag
    behind the caps (delta is then not the caps' displacement)."""
    out = []
    for k, e in enumerate(events):
        if not e[0].startswith("loaded to") or k + 1 >= len(events):
            continue
        work = 0.0
        for i0, i1, sign in ((events[k - 1][1], e[1], 1.0), (e[1], events[k + 1][1], -1.0)):
            part = _between(rows, i0, i1)
            work += sign * sum(0.5 * (a[2] + b[2]) * 2 * cap_speed * dt * (b[0] - a[0]) for a, b in zip(part, part[1:]))
        out.append(work)
    return out
