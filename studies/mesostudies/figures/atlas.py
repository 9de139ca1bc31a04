"""The figure atlas: every figure of both papers behind one command (inside ``yade``).

    yade -n -x studies/scripts/figure.py 9 [--paper long|short] [--out DIR] [--quick]
    yade -n -x studies/scripts/figure.py --all [--no-tablet] [--quick]

Pair figures (long 5-15, short 5-6) run YADE collisions over the closed form; long 16-19 are
the tablet of Appendix F (``mesostudies.tablet.cli``, hours, runs cached in --tablet-out). Every
figure writes CSV + PNG into DIR and its summary into DIR/atlas.json. The figures are the jobs of
the registry JOBS (named paper-number, as in atlas.json), declared here above the modules that
draw them."""
import fcntl
import json
import os
import time

from mesocontact import outputs
from mesocontact.jobs import Job, Registry
from . import appendix as fa, long as figures, short as fs


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


def _pair(draw):
    """A pair figure's job: ``draw(out, quick)`` (the tablet's directory is not its business)."""
    return lambda out, quick, tablet_out: draw(out, quick)


def _tablet(number):
    """The tablet's figure ``number`` (long 16-19): its job in the tablet's own command line, its runs
    cached in tablet_out (default out/tablet)."""
    def job(out, quick, tablet_out):
        from ..tablet import cli  # only here: the pair figures need none of the tablet
        tablet = tablet_out or os.path.join(out, "tablet")
        cli.main(f"fig{number}", ["--out", tablet] + (["--quick"] if quick else []))
        return dict(figure=f"long {number}", outputs=tablet, note="see docs/tablet/README.md")
    return job


# The atlas's figures, in the order --all makes them (long 8 comes with long 6: one run makes both).
JOBS = Registry([
    Job("long-5", _pair(_long5), "e(zeta) with jump-in adhesion, two sticking regimes (alpha = 0.042, 0.42)."),
    Job("long-6", _pair(_long6_8), "e(chi) for fa = 0, eta = 4, beta = 1 (and Fig. 8: one run makes both)."),
    Job("long-7", _pair(_long7), "force-overlap loops of single collisions (eta = 4, beta = 1, phiF = 0.05)."),
    Job("long-8", _pair(_long6_8), "the sticking overlap delta_c/deltaMax^p (and Fig. 6: one run makes both)."),
    Job("long-9", _pair(fa.fig9), "e(chi) for beta/beta* = 1/3, 1, 3 at eta = 4 and Appendix A's tuned model."),
    Job("long-10", _pair(fa.fig10), "the force law with phiF and with phiF' (kp' of Eq. A.3)."),
    Job("long-11", _pair(fa.fig11), "chi = 1, eta = 4: kc below, at and above beta* k1, with and without viscosity."),
    Job("long-12", _pair(fa.fig12), "log-log e(chi <= 1), beta = 0, eta = 5, 50, 500, with the asymptote C.2."),
    Job("long-13", _pair(fa.fig13), "log-log e(chi <= 1), eta = 50, beta = 0.01, 0.1, 1, with C.3."),
    Job("long-14", _pair(fa.fig14), "linear against square-root k2 interpolation (eta = 50, beta = 0; D.2)."),
    Job("long-15", _pair(fa.fig15), "the energies of one collision: kinetic, plastic potential, available."),
    Job("short-5", _pair(fs.short_fig5), "elastic-adhesive against elasto-plastic adhesive spheres (fa = 5e-7 N)."),
    Job("short-6", _pair(fs.short_fig6), "e(v_i) for fa = 0 to 0.1 N (elasto-plastic, kp = 5 k1)."),
    Job("long-16", _tablet(16), "the tablet's tension cycles (Appendix F; hours, runs cached in --tablet-out)."),
    Job("long-17", _tablet(17), "the tablet's pull to rupture with snapshots (Appendix F; hours)."),
    Job("long-18", _tablet(18), "the tablet's compression cycles (Appendix F; hours)."),
    Job("long-19", _tablet(19), "the tablet's compression to large strain with snapshots (Appendix F; hours)."),
], what="figure")
TABLET = ("long-16", "long-17", "long-18", "long-19")


def known(paper, number):
    """Raises ValueError naming what is wrong unless the atlas has figure number of paper."""
    if paper not in ("long", "short"):
        raise ValueError(f"paper = {paper!r} is invalid: must be 'long' or 'short'")
    if f"{paper}-{number}" not in JOBS:
        have = ", ".join(n.replace("-", " ") for n in JOBS)
        raise ValueError(f"figure {number} of the {paper} paper is not in the atlas (it has: {have})")


def figure(paper, number, out, quick=False, tablet_out=None):
    """Makes one figure; returns its summary (also merged into out/atlas.json). The tablet's
    figures (long 16-19) go to tablet_out (default out/tablet), where their runs are cached."""
    known(paper, number)
    os.makedirs(out, exist_ok=True)
    t0 = time.time()
    summary = JOBS.get(f"{paper}-{number}").function(out, quick, tablet_out)
    summary["wall_clock_s"] = time.time() - t0
    summary["quick"] = quick
    _merge(out, f"{paper}-{number}", summary)
    print(f"[atlas] {paper} fig. {number} done in {summary['wall_clock_s']:.1f} s: "
          + ", ".join(f"{k} = {v}" for k, v in summary.items() if k in ("collisions", "worst_abs_e_error")), flush=True)
    return summary


def everything(out, quick=False, tablet=True, tablet_out=None):
    """The whole atlas; returns {name: summary}."""
    t0, done = time.time(), {}
    for name in JOBS:
        if name == "long-8" or (name in TABLET and not tablet):  # long 8: made by long 6's run
            continue
        paper, n = name.split("-")
        done[name] = figure(paper, int(n), out, quick, tablet_out)
    print(f"[atlas] {len(done)} figure commands in {time.time() - t0:.1f} s; outputs in {os.path.abspath(out)}",
          flush=True)
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
