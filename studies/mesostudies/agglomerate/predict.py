"""Issue #59, item 3: the restitution predicted from the cycles alone and set against the ensemble
(inside ``yade``: the meso pair with viscosity runs in YADE).

What the law takes from where:
- k1, kp, kc, phiF (and the overlap's offset): the fit to the slowest pair cycles (the campaign's
  cycles-v0.625, ``compare.fit``), nothing from a collision;
- the dashpots, three ways, each from cycles: the first prediction's gammaN from the rate cycles' loop
  areas over the slow cycles' (``loss.viscous_gamma``, the median); the second's from the energy-tracked
  cycles (``energy_prediction``); the third's gammaN and gammaN2 together from the energy-tracked cycles
  of every block pooled (``rate_law_prediction``), the rule fixed before the final fit. The third is
  the result (e_predicted, difference, fitted_to); the first is kept as first_prediction;
- e(v): two meso-particles of that law (``compare.meso_collisions``) at each speed of the ensemble.

Written: ensemble.json (speeds, n_blocks, n_directions, e_mean, e_sd over every block and direction
of ``ensemble_report``'s primary measure, e_predicted, fitted_to, the verdict per speed
(``ensemble_report.verdict``), the other measures' means, and the tension beyond the first touch
against the fitted law's, ``tension.report``), ensemble.md (the tables) and ensemble.png
(``plots.ensemble``) in ``out``.
"""
import json
import os
import statistics

from mesocontact import outputs
from mesocontact.outputs import read_csv
from . import compare, ensemble_report, loss, plots, tension

# The measure: e along the normal impulse with the spin, at the contact point (e_contact). It is not
# bounded at a rough, tilted contact (above 1 in 4 of the first 42 runs), and e_rigid (the rigid motion's
# energy, spin and sliding included) reads high against a frictionless head-on pair: both, and e_normal
# (no spin), are compared, each in ensemble.json.
PRIMARY = "e_contact"
SLOW = "cycles-v0.625"
GOAL_TOP = 80.0  # m/s: the goal's speeds end here


def _run(d, name):
    """(rows, the run's JSON) of a cycle run."""
    with open(os.path.join(d, name + ".json")) as f:
        info = json.load(f)
    return [tuple(r) for r in read_csv(os.path.join(d, name + ".csv"))], info


def viscosity(campaign, block, slow=SLOW):
    """(gammaN [kg/s], its values per rate run and amplitude): the fast pair cycles in ``block``
    (rate-cycles-v<m/s per cap>) against the slow ones in ``campaign``; relative speeds are twice
    the caps' [mm/us]."""
    rows, info = _run(campaign, slow)
    base, v_slow = loss.loops(rows, info["events"]), 2 * info["speed_per_cap_m_s"] / 1e3
    per = {}
    for name in sorted(f[:-5] for f in os.listdir(block) if f.startswith("rate-cycles-v") and f.endswith(".json")):
        rows, info = _run(block, name)
        per[name] = loss.viscous_gamma(base, loss.loops(rows, info["events"]), v_slow,
                                       2 * info["speed_per_cap_m_s"] / 1e3)
    values = [g for gs in per.values() for g in gs if g is not None]
    return (statistics.median(values) if values else None), per


def predict(out, campaign, info, progress=True):
    """The comparison (see the module); ``info``: make.ensure's description of the pair whose
    radii and masses the meso-particles take; returns the JSON written."""
    tab = ensemble_report.table(ensemble_report.collected(out))
    speeds = sorted(tab)
    with open(os.path.join(campaign, "agglomerate-vs-meso.json")) as f:
        params = json.load(f)["fit"]
    gamma, per = viscosity(campaign, os.path.join(out, "block-s1"))
    if gamma is None:
        raise ValueError(f"{out}/block-s1 holds no rate cycles matching {SLOW}'s turns: gammaN cannot be measured "
                         "(run the job 'rate' first)")
    e_pred = compare.meso_collisions(params, info, [v / 1e3 for v in speeds], progress=progress, gammaN=gamma)
    res = {"speeds": speeds, "n_blocks": [tab[v]["n_blocks"] for v in speeds],
           "n_directions": [tab[v]["n_directions"] for v in speeds], "n_runs": [tab[v]["n"] for v in speeds],
           "measure": PRIMARY, "n_measured": [tab[v][PRIMARY]["n"] for v in speeds],
           "e_mean": [tab[v][PRIMARY]["mean"] for v in speeds], "e_sd": [tab[v][PRIMARY]["sd"] for v in speeds],
           "e_predicted": e_pred,
           "fitted_to": {"k1, kp, kc, phiF, shift": f"the pair's slow cycles ({SLOW}, campaigns/agglomerate)",
                         "gammaN": f"the rate cycles' extra loss over {SLOW} ({', '.join(per) or 'none'}): "
                                   f"median {gamma} kg/s", "collisions": "nothing"},
           "gammaN_per_run": per, "params": params, "table": {str(v): tab[v] for v in speeds}}
    res["difference"] = [None if m is None else p - m for m, p in zip(res["e_mean"], e_pred)]
    res["by_measure"] = {m: {"e_mean": [tab[v][m]["mean"] for v in speeds], "e_sd": [tab[v][m]["sd"] for v in speeds],
                             "range": [[tab[v][m]["min"], tab[v][m]["max"]] for v in speeds]}
                         for m in ensemble_report.MEASURES}
    res["gamma_scan"] = gamma_scan(params, info, speeds, res["by_measure"], gamma)
    res["rate_energy"] = rate_energy(os.path.join(out, "block-s1"))
    res["energy_prediction"] = energy_prediction(os.path.join(out, "block-s1"), params, info, speeds, res)
    res["rate_law_prediction"] = rate_law_prediction(out, params, info, speeds, res)
    _final(res)
    res["tension"] = tension.report(campaign, os.path.join(out, "block-s1"), params)
    res["goal"] = "|e_mean - e_predicted| <= 0.1 at every speed from 0.01 to 80 m/s without fragmentation"
    res["stuck_counted_as"] = 0.0
    res["verdict"] = ensemble_report.verdict(tab, dict(zip(speeds, res["e_predicted"])), PRIMARY)
    outputs.write_atomic(os.path.join(out, "ensemble.json"), json.dumps(res, indent=1))
    plots.ensemble(res, ensemble_report.collected(out), os.path.join(out, "ensemble.png"), PRIMARY)
    outputs.write_atomic(os.path.join(out, "ensemble.md"), ensemble_report.text(tab)
                         + "\n\n" + ensemble_report.verdict_text(res["verdict"])
                         + "\n\nThe first prediction (gammaN from the rate cycles' loop areas):\n\n"
                         + _verdict_table(res["first_prediction"], res)
                         + "\n\n" + _scan_table(res["gamma_scan"])
                         + "\n\n" + _energy_table(res["rate_energy"])
                         + "\n\n" + _energy_prediction_table(res["energy_prediction"], res)
                         + "\n\n" + _rate_law_table(res["rate_law_prediction"], res)
                         + "\n\nThe tension, per unloading, against the fitted law (tension.py):\n\n"
                         + res["tension"]["table"])
    return res


SCAN = (0.0,) + tuple(2.0 ** (k / 4) for k in range(-8, 21))  # gammaN over the cycles' value: 0, 1/4 to 32


def gamma_scan(params, info, speeds, by_measure, gamma, factors=SCAN):
    """Could any gammaN have met the goal with the cycles' k1, kp, kc, phiF? For each gammaN =
    factor x the cycles' value, the law's e at every speed up to GOAL_TOP m/s and the largest
    |e_mean - e| over them, per measure; and the factor with the least of it. A diagnostic: it
    takes gammaN from the collisions, so it predicts nothing."""
    at = [k for k, v in enumerate(speeds) if v <= GOAL_TOP]
    rows = []
    for f in factors:
        e = compare.meso_collisions(params, info, [speeds[k] / 1e3 for k in at], progress=False, gammaN=f * gamma)
        worst = {m: max(abs(by_measure[m]["e_mean"][k] - x) for k, x in zip(at, e)
                        if by_measure[m]["e_mean"][k] is not None) for m in by_measure}
        rows.append({"factor": f, "gammaN": f * gamma, "e": e, "worst": worst})
    best = {m: min(rows, key=lambda r: r["worst"][m])["factor"] for m in by_measure}
    return {"speeds": [speeds[k] for k in at], "rows": rows, "best_factor": best}


def _energy_runs(block):
    """{cap speed [m/s]: (rows, description)} of the energy-cycles-v<m/s per cap> runs in ``block``."""
    runs = {}
    for name in sorted(f[:-5] for f in os.listdir(block) if f.startswith("energy-cycles-v") and f.endswith(".json")):
        rows, info = _run(block, name)
        runs[info["speed_per_cap_m_s"]] = (rows, info)
    return runs


def _energy_loops(block):
    """{cap speed: (loss.loops, loss.dissipated)} of the energy-tracked runs in ``block``."""
    return {v: (loss.loops(rows, i["events"]), loss.dissipated(i["events"], i["event_energy"]))
            for v, (rows, i) in _energy_runs(block).items()}


def rate_energy(block):
    """The energy-cycles runs in ``block`` (measure.rate_energy), slowest first: per loop the law's
    dissipation by term (loss.dissipated), its sum over the contacts' terms, the background drag's
    beside it, the sum over that of the slowest run at the same amplitude, and the loop's work three
    ways: the caps' own (loss.caps_work), O.energy's whole change, and F d(delta) (loss.loops)."""
    runs = []
    for v, (rows, info) in sorted(_energy_runs(block).items()):
        loops = loss.dissipated(info["events"], info["event_energy"])
        caps = loss.caps_work(rows, info["events"], v / 1e3, info["dt"])
        for lp, w, fd in zip(loops, caps, loss.loops(rows, info["events"])):
            whole = sum(x for t, x in lp.items() if t not in ("amplitude", "total", "kinetic", "gravWork"))
            lp.update(caps_work=w, f_ddelta=fd["loss"], energy_sum=whole)
        runs.append({"speed_per_cap_m_s": v, "loops": loops})
    if runs:
        base = {lp["amplitude"]: lp["total"] for lp in runs[0]["loops"]}
        for r in runs:
            for lp in r["loops"]:
                lp["over_slowest"] = lp["total"] / base[lp["amplitude"]] if base.get(lp["amplitude"]) else None
    return runs


def energy_prediction(block, params, info, speeds, res):
    """A second prediction from cycles alone: gammaN from the energy-tracked cycles
    (loss.viscous_gamma_dissipated, each faster run against the slowest; the median), and e of the
    meso pair with it at every speed; None without two energy runs."""
    runs = _energy_loops(block)
    if len(runs) < 2:
        return None
    slow = min(runs)
    per = {f"{v:g} against {slow:g} m/s per cap": loss.viscous_gamma_dissipated(*runs[slow], *runs[v], 2 * slow / 1e3,
                                                                                2 * v / 1e3)
           for v in sorted(runs) if v != slow}
    values = [g for gs in per.values() for g in gs if g is not None]
    gamma = statistics.median(values)
    e = compare.meso_collisions(params, info, [v / 1e3 for v in speeds], progress=False, gammaN=gamma)
    return {"gammaN": gamma, "gammaN_per_run": per, "slowest_cap_m_s": slow, "e_predicted": e,
            "difference": [None if m is None else p - m for m, p in zip(res["e_mean"], e)],
            "fitted_to": "k1, kp, kc, phiF: the slow cycles' fit; gammaN: the energy-tracked cycles' contact "
                         "dissipation per loop (drag left out) over the slowest's; nothing from a collision"}


def _extra_loss_points(block, reference=None):
    """[(label, (v_slow, v_fast, extra loss per metre))] of ``block``'s energy-tracked runs, each faster
    run's loops against its slowest run's, or against the run at ``reference`` m/s per cap (SI:
    relative speeds [m/s], loss per metre of path [N])."""
    runs = _energy_loops(block)
    slow = min(runs) if reference is None and runs else reference
    if slow not in runs or len(runs) < 2:
        return []
    out = []
    for v in sorted(runs):
        if v <= slow:
            continue
        for pt in loss.extra_loss_points(*runs[slow], *runs[v], 2 * slow, 2 * v):
            if pt is not None:
                out.append((f"{os.path.basename(block)}: {v:g} against {slow:g} m/s per cap, loop to "
                            f"{pt[3]:g} d0", (pt[0], pt[1], pt[2] / 1e-3)))
    return out


def rate_law_prediction(out, params, info, speeds, res):
    """A third prediction from cycles alone, with the law's rate feature (issue #59, item 4): the
    linear and the quadratic dashpot, gammaN v + gammaN2 v^2 (MesoMat.gammaN2), fitted together to the
    energy-tracked cycles' extra contact dissipation per length of path over the slowest run's of the
    same pair (loss.extra_loss_points, loss.rate_dashpots: least squares over every loop kept by the
    rule of energy_prediction), every block's loops pooled (each block's own fit reported beside),
    and e of the meso pair with both at every speed; None with fewer than two pairs of speeds."""
    blocks = sorted(os.path.join(out, b) for b in os.listdir(out)
                    if b.startswith("block-s") and os.path.isdir(os.path.join(out, b)))
    per_block = {os.path.basename(b): _extra_loss_points(b) for b in blocks}
    pooled = [x for pts in per_block.values() for x in pts]

    def pairs(pts):
        return len({p[:2] for _, p in pts})

    if pairs(pooled) < 2:  # two dashpots need two pairs of speeds (loss.rate_dashpots)
        return None
    g1, g2, resid = loss.rate_dashpots([p for _, p in pooled])
    fits = {b: dict(zip(("gammaN", "gammaN2"), loss.rate_dashpots([p for _, p in pts])[:2]))
            for b, pts in per_block.items() if pairs(pts) >= 2}
    e = compare.meso_collisions(params, info, [v / 1e3 for v in speeds], progress=False, gammaN=g1, gammaN2=g2)
    by_measure = {m: [None if x is None else y - x for x, y in zip(res["by_measure"][m]["e_mean"], e)]
                  for m in res["by_measure"]}
    return {"gammaN": g1, "gammaN2": g2, "per_block": fits, "difference_by_measure": by_measure,
            "sensitivity": _rate_law_sensitivity(blocks, per_block, params, info, speeds, res),
            "points": [{"loop": lab, "v_slow": p[0], "v_fast": p[1], "extra_loss_per_m": p[2], "residual": r}
                       for (lab, p), r in zip(pooled, resid)],
            "e_predicted": e, "difference": [None if m is None else x - m for m, x in zip(res["e_mean"], e)],
            "fitted_to": "k1, kp, kc, phiF: the slow cycles' fit; gammaN and gammaN2: least squares to the "
                         "energy-tracked cycles' contact dissipation per loop (drag left out) over the slowest's "
                         "of the same pair, per length of its path in contact, every block pooled; nothing from "
                         "a collision"}


def _rate_law_sensitivity(blocks, per_block, params, info, speeds, res):
    """The third prediction's choices varied (diagnostics, not the rule): each block alone, every block
    against its 2.5 m/s run, and the least squares weighted by 1/|extra loss|: gammaN, gammaN2 and
    e_predicted - e_mean per speed for each."""
    variants = {f"{os.path.basename(b)} alone": (per_block[os.path.basename(b)], False) for b in blocks}
    variants["every block against its 2.5 m/s run"] = ([x for b in blocks for x in _extra_loss_points(b, 2.5)], False)
    variants["weighted by 1/|extra loss|"] = ([x for pts in per_block.values() for x in pts], True)
    out = {}
    for name, (pts, relative) in variants.items():
        if len({p[:2] for _, p in pts}) < 2:
            continue
        g1, g2, _ = loss.rate_dashpots([p for _, p in pts], relative=relative)
        e = compare.meso_collisions(params, info, [v / 1e3 for v in speeds], progress=False, gammaN=g1, gammaN2=g2)
        out[name] = {"gammaN": g1, "gammaN2": g2,
                     "difference": [None if m is None else x - m for m, x in zip(res["e_mean"], e)]}
    return out


def _rate_law_table(rp, res):
    if rp is None:
        return "(no third prediction: the energy-tracked cycles give fewer than two pairs of speeds)"
    each = "; ".join(f"{b}: {f['gammaN']:.3g} kg/s, {f['gammaN2']:.3g} kg/m" for b, f in rp["per_block"].items())
    lines = [f"The third prediction from cycles alone, with the quadratic dashpot: gammaN = {rp['gammaN']:.3g} kg/s "
             f"and gammaN2 = {rp['gammaN2']:.3g} kg/m, least squares to the energy-tracked cycles' extra loss per "
             f"metre of path over the slowest run's of the same pair, every block pooled (each alone: {each})",
             "", "| loop | relative speed [m/s] | extra loss per metre [N] | fit's residual [N] |", "|---|---|---|---|"]
    for p in rp["points"]:
        lines.append(f"| {p['loop']} | {p['v_fast']:g} | {p['extra_loss_per_m']:.3g} | {p['residual']:+.3g} |")
    by = rp["difference_by_measure"]
    lines += ["", f"| v [m/s] | {res['measure']} mean | predicted | difference | "
              + " | ".join(f"difference, {m}" for m in by) + " |", "|---|---|---|---|" + "---|" * len(by)]
    for k, (v, m, x, d) in enumerate(zip(res["speeds"], res["e_mean"], rp["e_predicted"], rp["difference"])):
        others = " | ".join("–" if by[q][k] is None else f"{by[q][k]:+.3f}" for q in by)
        first = f"| {v:g} | {m:.3f} | {x:.3f} | {d:+.3f} | " if m is not None else f"| {v:g} | – | {x:.3f} | – | "
        lines.append(first + others + " |")
    lines += ["", "The choices varied (diagnostics, not the rule): predicted - e_mean per speed", "",
              "| variant | gammaN [kg/s] | gammaN2 [kg/m] | " + " | ".join(f"{v:g} m/s" for v in res["speeds"]) + " |",
              "|---|---|---|" + "---|" * len(res["speeds"])]
    for name, r in rp["sensitivity"].items():
        lines.append(f"| {name} | {r['gammaN']:.3g} | {r['gammaN2']:.3g} | "
                     + " | ".join("–" if d is None else f"{d:+.3f}" for d in r["difference"]) + " |")
    return "\n".join(lines)


def _energy_prediction_table(ep, res):
    if ep is None:
        return "(no second prediction: fewer than two energy-tracked cycle runs)"
    per = "; ".join(f"{k}: " + ", ".join("–" if g is None else f"{g:.3g}" for g in gs)
                    for k, gs in ep["gammaN_per_run"].items())
    lines = [f"The second prediction from cycles alone: gammaN = {ep['gammaN']:.3g} kg/s from the energy-tracked "
             f"cycles (the median of {per})",
             "", f"| v [m/s] | {res['measure']} mean | predicted | difference |", "|---|---|---|---|"]
    for v, m, p, d in zip(res["speeds"], res["e_mean"], ep["e_predicted"], ep["difference"]):
        lines.append(f"| {v:g} | {m:.3f} | {p:.3f} | {d:+.3f} |" if m is not None else f"| {v:g} | – | {p:.3f} | – |")
    return "\n".join(lines)


def _energy_table(runs):
    terms = [t[4:] for t in loss.LOSS_TERMS]
    lines = ["The pair's cycles with the law's energy (rate-energy): each loop's dissipation inside the agglomerates "
             "[1e-7 J], by term; the background drag and the change of the particles' kinetic energy beside it (a "
             "fast start leaves the free parts moving, and that energy is dissipated in the loops that follow); the "
             "contacts' sum over the slowest run's; the loop's work as the caps' own, as O.energy's whole change "
             "and as F d(delta)",
             "", "| cap speed [m/s] | loop to [d0] | " + " | ".join(terms)
             + " | contacts' sum | drag | kinetic change | over the slowest | caps' work | O.energy sum | F d(delta) |",
             "|---|---|" + "---|" * (len(terms) + 7)]
    for r in runs:
        for lp in r["loops"]:
            cells = [f"{lp.get(t, 0.0) * 1e7:.2f}" for t in loss.LOSS_TERMS]
            ratio = "–" if lp["over_slowest"] is None else f"{lp['over_slowest']:.2f}"
            lines.append(f"| {r['speed_per_cap_m_s']:g} | {lp['amplitude']:g} | " + " | ".join(cells)
                         + f" | {lp['total'] * 1e7:.2f} | {lp.get('mesoBackground', 0.0) * 1e7:.2f} | "
                         f"{lp.get('particles_kinetic', 0.0) * 1e7:+.2f} | {ratio} | {lp['caps_work'] * 1e7:.2f} | "
                         f"{lp['energy_sum'] * 1e7:.2f} | {lp['f_ddelta'] * 1e7:.2f} |")
    return "\n".join(lines) if runs else "(no rate-energy runs yet)"


def _scan_table(scan):
    ms = list(scan["best_factor"])
    lines = ["gammaN scanned (the cycles' k1, kp, kc, phiF; a diagnostic, gammaN from the collisions): the law's e "
             f"at {', '.join(f'{v:g}' for v in scan['speeds'])} m/s and the largest |e_mean - e| over them",
             "", "| gammaN / cycles' | gammaN [kg/s] | e(v) | " + " | ".join(f"worst, {m}" for m in ms) + " |",
             "|---|---|---|" + "---|" * len(ms)]
    for r in scan["rows"]:
        lines.append(f"| {r['factor']:.3g} | {r['gammaN']:.3g} | {', '.join(f'{x:.3f}' for x in r['e'])} | "
                     + " | ".join(f"{r['worst'][m]:.3f}" + (" (least)" if scan["best_factor"][m] == r["factor"] else "")
                                  for m in ms) + " |")
    return "\n".join(lines)


def _final(res):
    """The prediction the rule named (the third: both dashpots, every block pooled) becomes the result's
    e_predicted, difference and fitted_to; the first (gammaN from the rate cycles' loop areas) moves to
    first_prediction. Without a third prediction the first stays the result's."""
    first = {k: res[k] for k in ("e_predicted", "difference", "fitted_to")}
    first["gammaN_per_run"] = res.pop("gammaN_per_run")
    res["first_prediction"] = first
    rp = res["rate_law_prediction"]
    if rp is None:
        return
    res["e_predicted"], res["difference"] = rp["e_predicted"], rp["difference"]
    res["fitted_to"] = {"k1, kp, kc, phiF, shift": first["fitted_to"]["k1, kp, kc, phiF, shift"],
                        "gammaN, gammaN2": f"{rp['gammaN']:.4g} kg/s, {rp['gammaN2']:.4g} kg/m: " + rp["fitted_to"],
                        "collisions": "nothing"}


def _verdict_table(pred, res):
    lines = [f"| v [m/s] | runs | {res['measure']} mean ± sd | predicted | difference |", "|---|---|---|---|---|"]
    for v, n, k, m, sd, p, d in zip(res["speeds"], res["n_runs"], res["n_measured"], res["e_mean"],
                                    res["e_sd"], pred["e_predicted"], pred["difference"]):
        n = f"{n} ({k} measured)" if k != n else n
        lines.append(f"| {v:g} | {n} | {m:.3f} ± {sd:.3f} | {p:.3f} | {d:+.3f} |" if m is not None else
                     f"| {v:g} | {n} | – | {p:.3f} | – |")
    return "\n".join(lines)
