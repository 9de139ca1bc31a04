"""Where the agglomerates' tension acts, and what the law fitted to their cycles makes of it (issue
#59, item 2 and D5; plain Python).

The fit's measure (calibrate.fit_cycles: residuals over the run's largest |F|) weighs a tension of
a few per cent of the peak force as noise. ``unloadings`` measures it on its own, per unloading of
a cycle or pull run (rows (iter, delta, F) and events as loss reads them), beyond the first touch
(delta < delta_touch: where the faces had not met on the way in, a neck drawn out of the contact):

- press_work: the work put in while loading to the turn;
- held_beyond: the net work of the force beyond the first touch, sum F d(delta) along the
  unloading there (delta decreasing: > 0 when the pair held on in tension; a ringing force's halves
  cancel, which a sum of the tensile parts alone would count as tension). The unloadings end at
  a fixed distance beyond the touch, maybe still in tension: then it is a lower bound;
- plateau: the mean force over delta - delta_touch in ``band`` [d0] (< 0: tension);
- end_d0, end_force: where the unloading ended (delta - delta_touch [d0]) and the force there;
- with ``law`` (the fitted law's force along the same rows, compare.law_curve): its held_beyond and
  plateau, and the misfit over the points beyond the touch (rms over the run's largest |F|, the
  fit's own measure) with their count.
"""
import json
import math
import os

from mesocontact.outputs import read_csv
from . import compare, loss

D0 = loss.D0
BAND = (-0.2, -0.05)  # d0 beyond the first touch: compare.cycle_measures' plateau band


def _work_below(rows, x):
    """loss's work sum F d(delta) over the part of ``rows`` at delta <= x, a segment that crosses x
    cut there (its force interpolated): exact on straight pieces."""
    cut = []
    for a, b in zip(rows, rows[1:]):
        if a[1] <= x and b[1] <= x:
            cut.append((a, b))
        elif (a[1] - x) * (b[1] - x) < 0:
            f = a[2] + (b[2] - a[2]) * (x - a[1]) / (b[1] - a[1])
            cut.append(((a[0], x, f), b) if b[1] < x else (a, (b[0], x, f)))
    return sum(loss.work([a, b]) for a, b in cut)


def _plateau(stroke, touch, d0, band):
    flat = [r[2] for r in stroke if band[0] <= (r[1] - touch) / d0 <= band[1]]
    return sum(flat) / len(flat) if flat else None


def unloadings(rows, events, law=None, d0=D0, band=BAND):
    """[{amplitude, press_work, held_beyond, plateau, end_d0, end_force, ...}] per loaded turn
    followed by an unloading (see the module); ``law``: forces along ``rows``."""
    touch = next(e[2] for e in events if e[0] == "touch")
    scale = max(abs(r[2]) for r in rows)
    out = []
    for k, e in enumerate(events):
        if not e[0].startswith("loaded to") or k + 1 >= len(events):
            continue
        its = (events[k - 1][1], e[1], events[k + 1][1])
        idx = [j for j, r in enumerate(rows) if its[1] <= r[0] <= its[2]]
        stroke = [rows[j] for j in idx]
        press = loss.work([r for r in rows if its[0] <= r[0] <= its[1]])
        one = {"amplitude": float(e[0].split()[2]), "press_work": press,
               "held_beyond": _work_below(stroke, touch), "plateau": _plateau(stroke, touch, d0, band),
               "end_d0": (stroke[-1][1] - touch) / d0, "end_force": stroke[-1][2]}
        if law is not None:
            fitted = [(rows[j][0], rows[j][1], law[j]) for j in idx]
            beyond = [(rows[j][2], law[j]) for j in idx if rows[j][1] < touch]
            one.update(law_held_beyond=_work_below(fitted, touch), law_plateau=_plateau(fitted, touch, d0, band),
                       points_beyond=len(beyond), points=len(idx),
                       misfit_beyond=(math.sqrt(sum((a - b) ** 2 for a, b in beyond) / len(beyond)) / scale
                                      if beyond else None))
        out.append(one)
    return out


MARKS = (0.05, 0.1, 0.2, 0.5, 1.0, 1.5, 2.0, 3.0, 5.0)  # d0 beyond the first touch


def pull_range(rows, events, d0=D0, marks=MARKS, quiet=1e-3):
    """How far a pull's tension reaches (a pull run's rows and events, or a saved pull's: its checkpoint
    holds both): the press work (first touch to the loaded turn), the work held beyond the first touch
    (as ``unloadings``) up to each mark [d0 beyond the touch] the pull reached, over the press work, and
    the last distance beyond the touch where |F| exceeded ``quiet`` times the run's largest |F|."""
    touch = next(e[2] for e in events if e[0] == "touch")
    start = next(e[1] for e in events if e[0] == "touch")
    turn = next(e[1] for e in events if e[0].startswith("loaded to"))
    press = loss.work([r for r in rows if start <= r[0] <= turn])
    after = [r for r in rows if r[0] >= turn]
    reached = (touch - min(r[1] for r in after)) / d0
    held = {m: _work_below([r for r in after if r[1] >= touch - m * d0], touch) / press
            for m in marks if m <= reached}
    peak = max(abs(r[2]) for r in rows)
    loud = [r for r in after if r[1] < touch and abs(r[2]) > quiet * peak]
    return {"press_work": press, "reached_d0": reached, "held_over_press": held, "peak": peak,
            "last_force_d0": (touch - min(r[1] for r in loud)) / d0 if loud else 0.0, "quiet": quiet}


def table(runs):
    """Markdown rows of {name: (unloadings(...), the run's largest |F|)}: one line per unloading."""
    lines = ["| run | press [d0] | held beyond the first touch / press work | tension plateau / peak "
             "| the fitted law's | misfit beyond the touch (of peak) | unloading ends at |",
             "|---|---|---|---|---|---|---|"]
    for name, (ups, peak) in runs.items():
        for u in ups:
            plateau = "–" if u["plateau"] is None else f"{u['plateau'] / peak:+.3f}"
            law = "–" if u.get("law_plateau") is None else (f"{u['law_held_beyond'] / u['press_work']:+.1e}, "
                                                            f"{u['law_plateau'] / peak:+.1e}")
            mis = (f"{u['misfit_beyond']:.3f} ({u['points_beyond']} of {u['points']} points)"
                   if u.get("misfit_beyond") is not None else "–")
            held = (f"{u['held_beyond'] / u['press_work']:+.3f}" if u["press_work"] > 0 else
                    f"– (press work {u['press_work']:.1e} ≤ 0: the caps' inertia)")
            lines.append(f"| {name} | {u['amplitude']:g} | {held} | {plateau} | "
                         f"{law} | {mis} | {u['end_d0']:+.3f} d0, F = {u['end_force']:.2e} |")
    return "\n".join(lines)


def report(campaign, block, params):
    """unloadings of the campaign's cycle runs (cycles-v*) and the block's pulls and rate cycles
    (pull-*, rate-cycles-*), each against the law ``params`` (compare's fit, SI) along its own rows:
    {"runs": {name: [unloading, ...]}, "table": markdown}. Runs missing from disk are left out."""
    runs, peaks = {}, {}
    for folder, prefixes in ((campaign, ("cycles-v",)), (block, ("pull-", "rate-cycles-"))):
        names = sorted(f[:-5] for f in os.listdir(folder) if f.endswith(".json") and f.startswith(prefixes)) \
            if os.path.isdir(folder) else []
        for name in names:
            if not os.path.exists(os.path.join(folder, name + ".csv")):
                continue
            with open(os.path.join(folder, name + ".json")) as f:
                events = json.load(f)["events"]
            rows = [tuple(r) for r in read_csv(os.path.join(folder, name + ".csv"))]
            runs[name] = unloadings(rows, events, compare.law_curve(params, rows, params["a12"]))
            peaks[name] = max(abs(r[2]) for r in rows)
    return {"runs": runs, "table": table({k: (v, peaks[k]) for k, v in runs.items()})}


def main(argv):
    """python3 -m mesostudies.agglomerate.tension RUN.json [RUN.csv]: pull_range of a pull run (its CSV
    beside it) or of a saved pull (a checkpoint's .yade.gz.json, rows inside)."""
    with open(argv[0]) as f:
        info = json.load(f)
    csv_path = argv[1] if len(argv) > 1 else argv[0][:-5] + ".csv"
    rows = ([tuple(r) for r in info["rows"]] if "rows" in info else [tuple(r) for r in read_csv(csv_path)])
    r = pull_range(rows, info["events"])
    print(f"press work {r['press_work']:.4g}, pulled to {r['reached_d0']:.2f} d0 beyond the touch, |F| above "
          f"{r['quiet']:g} of the peak until {r['last_force_d0']:.2f} d0")
    for m, h in r["held_over_press"].items():
        print(f"  held beyond the touch to {m:g} d0: {h:+.4f} of the press work")


if __name__ == "__main__":
    import sys
    main(sys.argv[1:])
