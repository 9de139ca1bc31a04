"""The figure atlas: every figure of both papers behind one command (inside ``yade``).

    yade -n -x studies/scripts/figure.py 9 [--paper long|short] [--out DIR] [--quick]
    yade -n -x studies/scripts/figure.py --all [--no-tablet] [--quick]

Pair figures (long 5-15, short 5-6) run YADE collisions over the closed form; long 16-19 are
the tablet of Appendix F (``mesostudies.tablet.campaign``, hours, runs cached in --tablet-out). Every
figure writes CSV + PNG into DIR and its summary into DIR/atlas.json."""
import fcntl
import json
import os
import time

from mesocontact import outputs
from . import appendix as fa, long as figures, short as fs

LONG_PAIR = (5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15)
LONG_TABLET = (16, 17, 18, 19)
SHORT = (5, 6)


def _worst(rows, i, j):
    return max(abs(r[i] - r[j]) for r in rows)


def _long5(out, quick):
    rows = figures.fig5(out, zetas=[0.01, 0.5, 2.0] if quick else None)
    return dict(figure="long 5", collisions=len(rows), worst_abs_e_error=_worst(rows, 4, 5))


def _long6_8(out, quick):
    rows = figures.fig6_fig8(out, chis=[0.1, 0.8, 2.0] if quick else None)
    stuck = [r for r in rows if r[4]]
    return dict(figure="long 6 and 8", collisions=len(rows), worst_abs_e_error=_worst(rows, 2, 3),
                worst_abs_delta_c_error_over_dmp=_worst(stuck, 5, 6) if stuck else None)


def _long7(out, quick):
    chis = (0.34, 1.1) if quick else (0.34, 0.69, 1.1, 1.37)
    figures.fig7(out, chis=chis)
    return dict(figure="long 7", collisions=len(chis), note="force-overlap loops (no single number)")


PAIR = {("long", 5): _long5, ("long", 6): _long6_8, ("long", 8): _long6_8, ("long", 7): _long7,
        ("long", 9): fa.fig9, ("long", 10): fa.fig10, ("long", 11): fa.fig11, ("long", 12): fa.fig12,
        ("long", 13): fa.fig13, ("long", 14): fa.fig14, ("long", 15): fa.fig15,
        ("short", 5): fs.short_fig5, ("short", 6): fs.short_fig6}


def known(paper, number):
    """Raises ValueError naming what is wrong unless the atlas has figure number of paper."""
    if paper not in ("long", "short"):
        raise ValueError(f"paper = {paper!r} is invalid: must be 'long' or 'short'")
    if (paper, number) not in PAIR and not (paper == "long" and number in LONG_TABLET):
        have = ", ".join(f"{p} {n}" for p, n in sorted(PAIR) + [("long", n) for n in LONG_TABLET])
        raise ValueError(f"figure {number} of the {paper} paper is not in the atlas (it has: {have})")


def figure(paper, number, out, quick=False, tablet_out=None):
    """Makes one figure; returns its summary (also merged into out/atlas.json). The tablet's
    figures (long 16-19) go to tablet_out (default out/tablet), where their runs are cached."""
    known(paper, number)
    key = (paper, number)
    os.makedirs(out, exist_ok=True)
    t0 = time.time()
    if key in PAIR:
        summary = PAIR[key](out, quick)
    else:
        from ..tablet import campaign  # the tablet's figures: their own cached runs and outputs
        tablet = tablet_out or os.path.join(out, "tablet")
        campaign.main(f"fig{number}", ["--out", tablet] + (["--quick"] if quick else []))
        summary = dict(figure=f"long {number}", outputs=tablet, note="see docs/tablet/README.md")
    summary["wall_clock_s"] = time.time() - t0
    summary["quick"] = quick
    _merge(out, f"{paper}-{number}", summary)
    print(f"[atlas] {paper} fig. {number} done in {summary['wall_clock_s']:.1f} s: "
          + ", ".join(f"{k} = {v}" for k, v in summary.items() if k in ("collisions", "worst_abs_e_error")), flush=True)
    return summary


def everything(out, quick=False, tablet=True, tablet_out=None):
    """The whole atlas; returns {name: summary}."""
    t0, done = time.time(), {}
    keys = [("long", n) for n in LONG_PAIR if n != 8] + [("short", n) for n in SHORT]
    keys += [("long", n) for n in LONG_TABLET] if tablet else []
    for paper, n in keys:
        done[f"{paper}-{n}"] = figure(paper, n, out, quick, tablet_out)
    print(f"[atlas] {len(done)} figure commands in {time.time() - t0:.1f} s; outputs in {os.path.abspath(out)}", flush=True)
    return done


def _merge(out, name, summary):
    """Read, update, write atlas.json under a lock: yade-batch jobs of one table share the file."""
    path = os.path.join(out, "atlas.json")
    with open(os.path.join(out, ".atlas.lock"), "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        try:
            with open(path) as f:
                table = json.load(f)
        except (OSError, ValueError):
            table = {}
        table[name] = summary
        if name == "long-6":
            table["long-8"] = summary  # one run makes both
        outputs.write_atomic(path, json.dumps(table, indent=1, sort_keys=True))
