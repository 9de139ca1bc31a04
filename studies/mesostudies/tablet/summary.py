"""Every number the tablet's documentation quotes about a campaign, computed from its committed
files (plain Python, like ``statements``):

    python3 -m mesostudies.tablet.summary campaigns/tablet/chosen     # writes summary.md there

The sample at three stages, the pull (peak, weakest planes, first gap, last chain), the cyclic
runs (each cycle's peak, loop and permanent set, the rates against each other, the force where each
tension cycle is back at Dx = 0), the deeper-sintered samples' tension cycles (../mid, ../deep,
../variants/deep: loop and set of each cycle), Fig. 19, the drag share, the roughness, the
time-step perturbation, the realizations of the preparation (../factors/factors.json) and the
campaign's cost on an idle machine (../quiet/campaign-time.json).
A section whose files are absent is left out. docs/tablet/README.md quotes these numbers; the
test python.tablet_docs checks that it quotes no other.
"""
import glob
import os
import statistics
import sys

from . import statements as _st
from .statements import pct as _pct

D0 = 0.01  # the paper's d0 [mm], for kc-study.csv's box sides


def _f(x, f=".3g"):
    return "–" if x is None else format(x, f)


def _stages(d, out, runs):
    st = _st.load_json(d, "unconfined.yade.gz.json")
    pull = _st.load_json(d, "fig17.json")
    if not st:
        return
    L0 = sorted({j["L0"] for j, _ in runs.values()})[0] if runs else None
    b = st["built"]
    out += ["## The sample", "",
            f"Preparation: packing {b.get('packing', 'full')}, glue {b.get('glue', 'loading')}, radii std "
            f"{b.get('rel_std', 0.05):g}, seed {b.get('seed', 1)}, d0 p_s/kp {b.get('sinter', 0.02):g}, N = {b['n']}, "
            f"material {b['material']} (kc/kp {b['kc_over_kp']:g}); released over "
            f"{format(st.get('release_steps', 0), ',').replace(',', ' ')} steps"
            + (f"; the pull at {pull['speed']:g} mm/µs per wall." if pull else "."), "",
            "| stage | x length [d0] | solid fraction ν | C | rattlers |", "|---|---|---|---|---|"]
    for name, s, L in (("sintered", st["sintered"], None), ("released", st["released"], None),
                       ("test start", st["unconfined"]["stats"], L0)):
        x = (L if L is not None else s["side"][0]) / st["d0"]
        out.append(f"| {name} | {x:.3f} | {s['solid_fraction']:.4f} | {s['coordination']:.2f} | {s['rattlers']} |")
    if L0:
        out += ["", f"L0 = {L0:.5f} mm at the test start, {100 * (L0 / 0.115 - 1):+.2f} % from the paper's 0.115."]
    out.append("")


def _plane(name, prof):
    w = prof["weakest"]
    return (f"| {name} | {_f(prof.get('Dx', 0.0), '.3f')} | {w['count']} | {prof['mean']:.0f} | "
            f"{w['from_left_d0']:.2f} | "
            f"{w['from_right_d0']:.2f} | {_f(prof.get('total'), 'd')} | {_f(prof.get('F'), '.3g')} |")


def _pull(d, out):
    p = _st.load_json(d, "fig17.json")
    if not p:
        return
    g = p.get("first_gap_Dx_by_area") or {"1": p.get("first_gap_Dx")}  # older pulls: one threshold
    out += ["## The pull (Fig. 17, fig17.json)", "",
            f"- Peak tension {-p['max_tension']:.4f} kp d0 at Dx = {p['max_tension_Dx']:.3f}.",
            f"- First visible gap at Dx = {_f(g.get('0.5'), '.2f')}, {_f(g.get('1'), '.2f')}, {_f(g.get('2'), '.2f')} "
            f"for 0.5, 1 and 2 d0²; see-through at {_f(p.get('see_through_Dx'), '.2f')}.",
            f"- Last chain at Dx = {_f(p['last_contact_Dx'], '.2f')}; mean force after it "
            f"{_f(p.get('mean_force_after_last_contact'), '.2g')} kp d0.", ""]
    if "planes_at_start" not in p:  # older pulls did not count the crossing contacts
        out.append("")
        return
    out += [
        "Weakest plane (fewest contacts in overlap across x = const, ≥ 0.5 d0 from the walls):", "",
        "| when | Dx | contacts | mean over planes | from left [d0] | from right [d0] | all contacts | F/(kp d0) |",
        "|---|---|---|---|---|---|---|---|", _plane("start", p["planes_at_start"]), _plane("peak", p["planes_at_peak"])]
    out += [_plane(f"mark {m}", prof)
            for m, prof in sorted(p.get("planes_at_marks", {}).items(), key=lambda kv: float(kv[0]))]
    crack = _st.crack_plane(p)
    if crack:
        (w, before), at, p0 = crack, p["planes_at_marks"]["0.2"], p["planes_at_start"]
        out += ["", f"At Dx = 0.2 the crack plane keeps {w['count']} of the {before} contacts that crossed it "
                f"at Dx = 0 ({_pct(w['count'] / before)}), the sample {_pct(at['total'] / p0['total'])} of all "
                f"its contacts, and the tension is {_pct(at['F'] / p['max_tension'])} of the peak."]
    aff = _st.load_json(d, "affine.json")
    if aff:
        t, z = aff["Dx_to_tensile_limit"], aff["Dx_to_detachment"]
        out += ["",
                f"Affine stretch of the test start's contacts (affine.json): {aff['contacts']} particle contacts "
                "in overlap (the totals above count the walls' contacts too; its L0 is the spheres' extent, "
                "which reaches into the "
                f"walls' faces), {aff['along_x']} "
                f"along x; mean overlap {aff['mean_overlap_d0']:.4f} d0, δmax {aff['mean_deltaMax_d0']:.4f} d0, δ0 "
                f"{aff['mean_delta0_d0']:.4f} d0, δmin {aff['mean_delta_min_d0']:.4f} d0; the contacts along x reach "
                f"their tensile limit at Dx = {t['10']:.4f}, {t['25']:.4f}, {t['50']:.4f}, {t['75']:.4f} "
                "(10, 25, 50, 75 %) "
                f"and let go at {z['10']:.3f}, {z['25']:.3f}, {z['50']:.3f}, {z['75']:.3f}."]
    out.append("")


def _cyclic(runs, out):
    if not runs:
        return
    out += ["## The cyclic runs (Figs. 16 and 18)", "",
            "Per run: each cycle's peak F/(kp d0), its change from the first cycle, the loop area against the "
            "elastic energy of the force swing, and the permanent set against the amplitude "
            "(mesostudies.tablet.measures).", "",
            "| run | peaks | change from cycle 1 | loops | sets |", "|---|---|---|---|---|"]
    for (mode, a, per), (j, cm) in sorted(runs.items()):
        pk = [c["peak"] for c in cm]
        out.append(f"| {mode} {a:g}, {per:g} t_w | {', '.join(f'{x:.4f}' for x in pk)} | "
                   f"{', '.join(_pct(x / pk[0] - 1, '.3g') for x in pk[1:])} | "
                   f"{', '.join(_pct(c['loop_over_elastic']) for c in cm)} | {', '.join(_pct(c['set']) for c in cm)} |")
    out += ["", "Fast against 4 x slower: each cycle's peak, slower over faster − 1:", "",
            "| mode, amplitude | periods | per cycle |", "|---|---|---|"]
    for mode in ("tension", "compression"):
        for a in sorted({k[1] for k in runs if k[0] == mode}):
            ks = sorted(k for k in runs if k[:2] == (mode, a))
            if len(ks) < 2:
                continue
            p1, p2 = ([c["peak"] for c in runs[k][1]] for k in ks[-2:])
            out.append(f"| {mode} {a:g} | {ks[-2][2]:g} / {ks[-1][2]:g} | "
                       f"{', '.join(_pct(y / x - 1, '.3g') for x, y in zip(p1, p2))} |")
    out.append("")


def _returns(d, runs, out):
    """The force where each tension cycle is back at Dx = 0 (the re-loading's end), over the first
    peak's magnitude: the return to the start's length compresses the lengthened sample."""
    ends = {}
    for (mode, a, per), (j, _) in sorted(runs.items()):
        p = os.path.join(d, f"{j['name']}.csv")
        if mode != "tension" or not os.path.exists(p):
            continue
        cyc = _st.measures.split_cycles(_st.read_csv(p), j["steps_per_cycle"], j["cycles"])
        ends[(a, per)] = ([c[-1][2] for c in cyc], abs(j["peaks"][0]))
    if not ends:
        return
    out += ["Back at Dx = 0 (tension runs): the force where each cycle ends, compressive, over the first peak's "
            "magnitude (the sample's strength in that run):", "",
            "| amplitude, period | F at each cycle's end | over the first peak |", "|---|---|---|"]
    for (a, per), (f, pk) in sorted(ends.items()):
        out.append(f"| {a:g}, {per:g} t_w | {', '.join(f'{x:+.4f}' for x in f)} | "
                   f"{', '.join(f'{x / pk:.2f}' for x in f)} |")
    largest = max((max(f) / pk, a, per) for (a, per), (f, pk) in ends.items())
    out += ["", f"Largest: {largest[0]:.2f} times the first peak ({largest[1]:g}, {largest[2]:g} t_w).", ""]


def _deeper(d, out):
    """Each cycle's loop and set of the tension runs of the deeper-sintered samples (../mid,
    ../deep, and ../variants/deep: the deep sample through grips or with kc/kp 0.5)."""
    rows = []
    for sub in ("mid", "deep", os.path.join("variants", "deep")):
        folder = os.path.join(d, "..", sub)
        for js in sorted(glob.glob(os.path.join(folder, "*tension-Dx*-P*.json"))):
            j = _st.load_json(folder, os.path.basename(js))
            if not j or "steps_per_cycle" not in j or not os.path.exists(js[:-5] + ".csv"):
                continue
            cm = _st.measures.cycle_measures(_st.read_csv(js[:-5] + ".csv"), j["steps_per_cycle"], j["mode"],
                                             j["cycles"])
            rows.append((sub.replace(os.sep, "/"), j["name"], cm))
    if not rows:
        return
    out += ["## The deeper-sintered samples' tension cycles (../mid, ../deep, ../variants/deep)", "",
            "Per run, as above: each cycle's peak, the loop over the elastic energy of the force swing, and the "
            "permanent set over the amplitude (Dx of the run: through grips the walls' distance, not the free "
            "part's strain; ../branch/experiments.md gives the walls' equivalent).", "",
            "| folder | run | peaks | loops | sets |", "|---|---|---|---|---|"]
    for sub, name, cm in rows:
        peaks = ", ".join(format(c["peak"], ".4f") for c in cm)
        out.append(f"| {sub} | {name} | {peaks} | "
                   f"{', '.join(_pct(c['loop_over_elastic'], '.3g') for c in cm)} | "
                   f"{', '.join(_pct(c['set'], '.3g') for c in cm)} |")
    out.append("")


def _fig19(d, out):
    f = _st.load_json(d, "fig19.json")
    if not f or "snapshots" not in f:
        return
    out += ["## Fig. 19 (fig19.json)", "",
            f"Unconfined compression to Dx = {f['until']:g} ({_pct(f.get('strain_at_end'))} strain); largest force "
            f"{f['max_force']:.3f} kp d0, at the end {f['final_force']:.3f}.", "",
            "| panel | Dx | F/(kp d0) | width y [d0] | width z [d0] | C | rattlers |", "|---|---|---|---|---|---|---|"]
    for k, s in enumerate(f["snapshots"]):
        out.append(f"| ({'abcdefg'[k]}) | {abs(s['Dx']):.2f} | {s['F']:.3f} | {s['width_y_d0']:.1f} | "
                   f"{s['width_z_d0']:.1f} | "
                   f"{s['coordination']:.2f} | {s['rattlers']} |")
    out.append("")


def _others(d, out):
    ds = _st.load_json(d, "drag-share.json")
    if ds:
        r = ds["runs"]
        out += ["## Drag share (drag-share.json)", "",
                f"One tension cycle to Dx = {ds['amplitude']:g} at {ds['period_crossings']:g} t_w: "
                f"peak {r['lab']['peak']:.4f} "
                f"(lab-frame drag), {r['contacts']['peak']:.4f} (relative to the contacts), "
                f"{r['none']['peak']:.4f} (none): "
                f"the drag carries {_pct(r['lab']['drag_share_of_peak'])} "
                f"and {_pct(r['contacts']['drag_share_of_peak'])} "
                "of the peak.", ""]
    ro = _st.load_json(d, "roughness.json")
    if ro:
        fl = ro.get("flat_cut")
        out += ["## Fracture faces (roughness.json)", "",
                f"{ro['snapshot']}: halves of {ro['halves'][0]} and {ro['halves'][1]} spheres "
                f"({ro['elsewhere']} loose), "
                f"median gap {ro['gap_d0']:.1f} d0, {ro['columns']} columns; "
                f"heights' 5–95 % range {ro['left']['range_5_95']:.1f} "
                f"and {ro['right']['range_5_95']:.1f} d0 (rms {ro['left']['rms']:.2f}, {ro['right']['rms']:.2f})"
                + (f"; a flat cut: {max(fl['left']['range_5_95'], fl['right']['range_5_95']):.1f} d0 (rms "
                   f"{fl['left']['rms']:.2f}, {fl['right']['rms']:.2f})" if fl else "") + ".", ""]
    se = _st.load_json(d, "sensitivity.json")
    if se:
        out += ["## Rate or chance (sensitivity.json)", "",
                "| amplitude | rate change per cycle | time step × (1 ± 1e-6) | rate over perturbation, cycles 2–4 |",
                "|---|---|---|---|"]
        for a, v in sorted(se["amplitudes"].items(), key=lambda kv: float(kv[0])):
            out.append(f"| {a} | {', '.join(_pct(x, '.3g') for x in v['rate_change'])} | "
                       f"{', '.join(_pct(x, '.3g') for x in v['perturbation_change'])} | "
                       f"{', '.join(f'{x:.1f}' for x in v['rate_over_perturbation_cycles_2_4'])} |")
        out.append("")


def _kc(d, out):
    p = os.path.join(d, "kc-study.csv")
    if not os.path.exists(p):
        return
    with open(p) as f:
        head, *rows = [ln.split(",") for ln in f.read().split("\n") if ln]
    col = {k: i for i, k in enumerate(head)}
    out += ["## How kc shows (kc-study.csv: the same preparation with other particles)", "",
            "| set | kc/kp | stage | solid fraction | C | rattlers | box [d0] |", "|---|---|---|---|---|---|---|"]
    for r in sorted(rows, key=lambda r: (float(r[col["kc_over_kp"]]), r[col["stage"]] != "sintered")):
        box = " × ".join(f"{float(r[col[k]]) / D0:.2f}" for k in ("Lx", "Ly", "Lz"))
        out.append(f"| {r[col['material']]} | {float(r[col['kc_over_kp']]):g} | {r[col['stage']]} | "
                   f"{float(r[col['solid_fraction']]):.4f} | {float(r[col['coordination']]):.2f} | "
                   f"{r[col['rattlers']]} | {box} |")
    out.append("")


def _realizations(d, out):
    same = _st.realizations(d, _st.load_json(d, "unconfined.yade.gz.json"))
    if len(same) < 2:
        return
    out += ["## Realizations of this preparation (../factors/factors.json, "
            f"seeds {', '.join(str(r['seed']) for r in same)})", ""]
    for name, v, f in (("last chain Dx", [r["last_chain_Dx"] for r in same], ".2f"),
                       ("first gap Dx (1 d0²)", [r["first_gap_Dx_by_area"]["1"] for r in same], ".2f"),
                       ("L0 against 0.115 [%]", [100 * (r["L0"] / 0.115 - 1) for r in same], ".2f"),
                       ("peak tension F/(kp d0)", [r["peak_tension"] for r in same], ".4f"),
                       ("peak Dx", [r["peak_Dx"] for r in same], ".3f")):
        out.append(f"- {name}: {', '.join(format(x, f) for x in v)}; mean {statistics.mean(v):{f}}, sd "
                   f"{statistics.stdev(v):{f}}, standard error {statistics.stdev(v) / len(v) ** 0.5:{f}}")
    lc = [r["last_chain_Dx"] for r in same]
    out += [f"- last chain inside 6–10: {sum(6 <= x <= 10 for x in lc)} of {len(lc)}", ""]


def _cost(d, out):
    c = _st.load_json(os.path.join(d, "..", "quiet"), "campaign-time.json")
    if not c:
        return
    out += ["## Cost (../quiet/campaign-time.json: the same campaign on an idle machine)", "",
            f"{c['steps'] / 1e6:.2f} million steps, {c['single_job_hours']:.2f} h of job time "
            f"({c['ms_per_step']:.2f} ms per "
            f"step), {c['wall_hours']:.2f} h on {c['lanes']} lanes.", ""]


def summary(d):
    runs = _st.runs_of(d)
    out = [f"# The campaign in numbers ({os.path.join(*os.path.normpath(os.path.abspath(d)).split(os.sep)[-2:])})", "",
           "Written by `python3 -m mesostudies.tablet.summary DIR` from the files named in each section; "
           "Dx in d0, forces F/(kp d0).", ""]
    _stages(d, out, runs)
    _pull(d, out)
    _cyclic(runs, out)
    _returns(d, runs, out)
    _deeper(d, out)
    _fig19(d, out)
    _others(d, out)
    _kc(d, out)
    _realizations(d, out)
    _cost(d, out)
    return "\n".join(out).rstrip() + "\n"


def main(argv):
    if len(argv) != 1 or not os.path.isdir(argv[0]):
        sys.exit("usage: python3 -m mesostudies.tablet.summary DOCS_DIR (a campaign's docs directory)")
    text = summary(argv[0])
    with open(os.path.join(argv[0], "summary.md"), "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main(sys.argv[1:])
