"""Every statement of Appendix F on the tablet, measured the way it is stated, from a campaign's
committed files (plain Python: the JSON and CSV that ``campaign.report`` copies into a docs
directory):

    python3 -m mesostudies.tablet.statements campaigns/tablet/chosen# writes statements.md and statements.json there

Each statement gets the project's number, the definition it is measured by, and a verdict:
'✓' met, '◐' met in part or only approximately (the reason given), '✗' not met, '–' not in this
campaign's files. The thresholds are stated with each statement; the cycle measures are those of
``mesostudies.tablet.measures`` (loop area against the elastic energy of the force swing, permanent set
from the starting force).
"""
import glob
import json
import os
import statistics
import sys

from . import measures

PHI_F = 0.05
TOL_L0 = 0.01  # the tested sample's length against the paper's 0.115: 1 %
APPROX = 1.5  # the paper's "~ x": within a factor 1.5 of x, one rule for every "~"
SINTER = 0.02  # the paper's sintering stress d0 p_s/kp (sample.SINTER, which needs YADE)


def load_json(d, name):
    """The JSON file ``name`` of folder ``d``, or None where it is absent."""
    p = os.path.join(d, name)
    if not os.path.exists(p):
        return None
    with open(p) as f:
        return json.load(f)


def read_csv(path):
    """The rows of a campaign CSV (header skipped) as tuples of floats."""
    with open(path) as f:
        return [tuple(float(x) for x in ln.split(",")) for ln in f.read().split("\n")[1:] if ln]


def runs_of(d):
    """The cyclic runs of the campaign: {(mode, amplitude, period): (json, measures per cycle)}."""
    out = {}
    for js in sorted(glob.glob(os.path.join(d, "*-Dx*-P*.json"))):
        base = os.path.basename(js)
        if base.startswith(("fig", "timestep")):
            continue
        j = load_json(d, base)
        if not j or "steps_per_cycle" not in j or not os.path.exists(js[:-5] + ".csv"):
            continue
        rows = read_csv(js[:-5] + ".csv")
        out[(j["mode"], j["amplitude"], j["period_crossings"])] = (j, measures.cycle_measures(
            rows, j["steps_per_cycle"], j["mode"], j["cycles"]))
    return out


def _slowest(runs, mode, amp):
    keys = sorted((k for k in runs if k[0] == mode and k[1] == amp), key=lambda k: -k[2])
    return runs[keys[0]] if keys else None


def pct(x, f=".2g"):
    return "–" if x is None else f"{100 * x:{f}} %"


def _plastic_onset(c, sets):
    """Statement 23 (plastic deformation kicks in for Dx > 0.1) by three measures of the compression
    cycles (slowest runs ``c``): the set after the last cycle, the peak's decay from cycle 1 to 4 and
    cycle 2's loop over its elastic energy; each says 'above 0.1' when it is at most 5 % at 0.1 and
    above 5 % at 0.2 (the elastic line of statement 22). Returns add()'s arguments."""
    decay = {a: 1 - c[a][1][-1]["peak"] / c[a][1][0]["peak"] for a in c}
    loop2 = {a: c[a][1][1]["loop_over_elastic"] for a in c}
    measures = {"set": sets, "peak decay over the cycles": decay, "cycle-2 loop": loop2}
    above = {n: m[0.1] <= 0.05 < m[0.2] for n, m in measures.items()}
    growth = {n: (m[0.1] / m[0.05], m[0.2] / m[0.1]) for n, m in measures.items()}
    return dict(
        quote="plastic deformation kicks in for Dx > 0.1 (the red curve)",
        number="; ".join(f"{n} " + ", ".join(f"{a:g}: {pct(m[a])}" for a in sorted(m)) for n, m in measures.items()),
        definition=("three measures against the amplitude: the permanent set after the last cycle, the peak's decay "
                    "from cycle 1 to 4, cycle 2's loop over its elastic energy; plastic: above 5 % (statement 22's "
                    "elastic line); kicks in above 0.1: at most 5 % at 0.1 and above it at 0.2; ✓ all three, ◐ one "
                    "or two"),
        verdict="✓" if all(above.values()) else ("◐" if any(above.values()) else "✗"),
        why="Above 0.1 by " + (", ".join(n for n in above if above[n]) or "none") + "; "
        + (", ".join(f"the {n} is {pct(measures[n][0.1])} at 0.1 already" for n in above if not above[n])
           or "every measure agrees") + ". Each grows about as fast from 0.05 to 0.1 as from 0.1 to 0.2 ("
        + ", ".join(f"{n} x{g[0]:.1f} then x{g[1]:.1f}" for n, g in growth.items())
        + "): the onset is gradual, not a kink at 0.1, and the 5 % line decides the verdict (a 3 % line puts "
        "the cycle-2 loop's crossing between 0.05 and 0.1, a 10 % line between 0.2 and 0.3); the set, the direct "
        "measure of plastic deformation, and statement 22's first-cycle loop (15 % at 0.1) say plastic at 0.1.")


def crack_plane(pull):
    """The crack plane at Dx = 0.2 (the weakest plane there) and the contacts that crossed the same
    plane at Dx = 0 (the nearest profile plane): (weakest, count before), or None if not recorded."""
    at, p0 = (pull.get("planes_at_marks") or {}).get("0.2"), pull.get("planes_at_start")
    if not (at and p0):
        return None
    w = at["weakest"]
    return w, min(zip(p0["x"], p0["count"]), key=lambda xc: abs(xc[0] - w["from_left_d0"]))[1]


def realizations(d, st):
    """The factor study's rows (../factors/factors.json) of this sample's preparation, one per seed."""
    rows = load_json(os.path.join(d, "..", "factors"), "factors.json") or []
    if not st:
        return []
    b = st["built"]
    return sorted((r for r in rows if (r["packing"], r["glue"], r["rel_std"], r.get("sinter", SINTER), r["drag"])
                   == (b.get("packing", "full"), b.get("glue", "loading"), b.get("rel_std", 0.05),
                       b.get("sinter", SINTER), "contacts")), key=lambda r: r["seed"])


def statements(d):
    """The list of statements of Appendix F with number, definition and verdict (see the module)."""
    st = load_json(d, "unconfined.yade.gz.json") or load_json(d, "released.yade.gz.json")
    runs = runs_of(d)
    pull = load_json(d, "fig17.json")
    out = []

    def add(quote, number, definition, verdict, note="", why=""):
        out.append({"n": len(out) + 1, "paper": quote, "project": number, "definition": definition,
                    "verdict": verdict, "note": note, "why": why})

    amps = {m: sorted({k[1] for k in runs if k[0] == m}) for m in ("tension", "compression")}
    L0s = sorted({j["L0"] for j, _ in runs.values()})
    # -- the sample
    if L0s:
        L0 = L0s[0]
        err = L0 / 0.115 - 1
        errs = [r["L0"] / 0.115 - 1 for r in realizations(d, st) if r.get("L0")]
        sd = statistics.stdev(errs) if len(errs) > 1 else None
        mean = statistics.mean(errs) if errs else None
        verdict = "✓" if abs(err) <= TOL_L0 else ("◐" if abs(err) <= 0.05 else "✗")
        if sd is not None:  # the paper's single value against the realizations
            verdict = "✓" if abs(mean) <= sd and abs(err) <= 0.05 else ("◐" if abs(mean) <= 2 * sd else "✗")
        add("an agglomerate (cubic) of size L0 = 0.115", f"L0 = {L0:.5f} ({pct(err)} from 0.115)"
            + (f"; over {len(errs)} realizations mean {pct(mean)} from 0.115, sd {pct(sd)}: the paper's value "
               f"{abs(mean) / sd:.1f} sd from their mean, this seed {abs(err - mean) / sd:.1f} sd" if sd else ""),
            "x length between the loading walls at the start of every test; the tested sample is seed 1, the first "
            "realization, fixed before any run",
            verdict, "the paper's value within one sd of the realizations' mean: ✓ (without realizations: within "
            f"{pct(TOL_L0)}); within two: ◐")
    else:
        add("an agglomerate (cubic) of size L0 = 0.115", "–", "x length at the test start", "–")
    if st:
        b = st["built"]
        add("N = 1728 primary particles of diameter d0 = 0.01 (with some variation in size)",
            f"N = {b['n']}, radii {b['radii'][0] / 0.005:.3f}–{b['radii'][1] / 0.005:.3f} d0/2",
            f"particles built; Gaussian radii, relative std {pct(b.get('rel_std', 0.05))}, cut at 2 sigma",
            "✓" if b["n"] == 1728 else "✗")
        s = st["sintered"]
        ws = max(abs(v / s["goal"] - 1) for v in s["wall_stress"].values()) if "goal" in s else None
        add("compressed (pressure-sintered) with a dimensionless wall stress d0 p_s/kp = 0.02",
            f"every wall within {pct(ws)} of p_s" if ws is not None else "–",
            "wall stresses when sintering ends", "✓" if ws is not None and ws < 0.01 else "–")
        add("to form a stable, rather dense agglomerate",
            f"solid fraction {s['solid_fraction']:.3f}, C {s['coordination']:.2f}, {s['rattlers']} rattlers, "
            f"E_kin/E_ref {s['kinetic_energy_ratio']:.1e}",
            "sintered state; static: E_kin below 1e-4 of the elastic energy scale; dense: solid fraction >= 0.60",
            "✓" if s["kinetic_energy_ratio"] < 1e-4 and s["solid_fraction"] >= 0.60 else "◐")
        r = st["released"]
        wr = max(abs(v / r["goal"] - 1) for v in r["wall_stress"].values()) if "goal" in r else None
        add("the stress is first released to 2e-5, i.e. p_r/p_s = 1e-3, for all walls",
            (f"every wall within {pct(wr)} of p_r; " if wr is not None else "")
            + f"solid fraction {r['solid_fraction']:.3f}, C {r['coordination']:.2f}, {r['rattlers']} rattlers",
            "wall stresses of the released state", "✓" if wr is not None and wr < 0.01 else "–")
        add("kc/kp = 0.2, mu_r = mu_o = 0.2, gamma_r/gamma = gamma_o/gamma = 0.1 (else Table 2 of Luding 2008)",
            f"material set '{b['material']}', kc/kp = {b['kc_over_kp']:g}", "the particles' MesoMat",
            "✓" if b["material"] == "appendixF" and abs(b["kc_over_kp"] - 0.2) < 1e-12 else "✗")
    if runs:
        same = len(L0s) == 1
        add("all simulations start from the same configuration, the released state (0, 0)",
            f"{len(runs)} runs, {len(L0s)} distinct L0", "the L0 of every cyclic run's JSON", "✓" if same else "✗")
        cyc = sorted({j["cycles"] for j, _ in runs.values()})
        add("each test, when it reaches zero strain, is repeated for three more cycles", f"cycles per run: {cyc}",
            "cycles of every run", "✓" if cyc == [4] else "✗")
    # -- tension
    t = {a: _slowest(runs, "tension", a) for a in amps["tension"]}
    small = [a for a in amps["tension"] if a < 0.2]
    if t and small and 0.2 in t:
        second = {a: t[a][1][1]["peak"] / t[a][1][0]["peak"] for a in amps["tension"]}
        add("incomplete detachment and partly/weaker elastic response for re-loading (the appendix's aim)",
            "cycle 2's peak over the first: " + ", ".join(f"{a:g}: {second[a]:.2f}" for a in amps["tension"]),
            "tension, slowest run; weaker re-loading: below 1 beyond the smallest amplitude, still attached: > 0",
            "✓" if all(0 < second[a] < 1 for a in amps["tension"]) else "✗")
        ret = {a: retrace(t[a][1]) for a in amps["tension"]}
        met = [ret[a][0] <= 0.05 and ret[a][1] <= 0.05 for a in small]
        add("repeated cyclic loading remains on the same branch with positive slope (elastic)",
            ", ".join(f"{a:g}: {pct(ret[a][0])} / {pct(ret[a][1])}" for a in small),
            "cycles 2–4 retrace one branch: the range of their peaks over the first peak / over their own mean, "
            "amplitudes below 0.2 (slowest run); one branch: both <= 5 % (changed from the loop area, which also "
            "counts the hysteresis of a branch that is retraced: Fig. 16's caption calls the repeated "
            "branches reversible)",
            "✓" if all(met) else ("◐" if any(met) or all(ret[a][0] <= 0.05 for a in small) else "✗"),
            why=_drift(runs, [a for a in small if not (ret[a][0] <= 0.05 and ret[a][1] <= 0.05)]) + _first_pull(d))
        far = {a: _far_force(t[a][0], d) for a in amps["tension"]}
        add("while it is not completely, perfectly detached",
            "tension at the last cycle's far point: " + ", ".join(f"{a:g}: {-far[a]:.3g}" for a in amps["tension"]),
            "-F/(kp d0) where cycle 4 turns back (> 0: still attached; slowest run)",
            "✓" if all(far[a] < 0 for a in far) else "✗")
        ratios = {}
        for k in sorted(k for k in runs if k[0] == "tension" and k[1] == 0.2):
            lo = [retrace(runs[("tension", a, k[2])][1])[1] for a in small if ("tension", a, k[2]) in runs]
            if lo:
                ratios[k[2]] = retrace(runs[k][1])[1] / max(lo)
        both = list(ratios.values())
        add("for the largest amplitude (0.2) the behaviour is not perfectly elastic, first plastic effects",
            "drift of cycles 2–4 at 0.2 over the smaller amplitudes' largest: "
            + ", ".join(f"{r:.2f} x at {p:g} t_w" for p, r in ratios.items()),
            "the retrace measure of the repeated cycles above (range of cycles 2–4 peaks over their mean), 0.2 against "
            "the smaller amplitudes, each period; the red curve less reversible: > 1.5 x at both periods (◐ when the "
            "periods disagree: rate-dependent)",
            "✓" if all(r > 1.5 for r in both) else ("✗" if all(r <= 1.5 for r in both) else "◐"),
            why=_drift(runs, [0.2, 0.1]))
    # -- the pull and Dx = 0.2
    if pull:
        at = (pull.get("planes_at_marks") or {}).get("0.2")
        p0 = pull.get("planes_at_start")
        if at and p0:
            w, before = crack_plane(pull)
            kept = w["count"] / before
            add("at 0.2 d0 the sample has mostly, but not completely lost mechanical contact",
                f"across the crack plane ({w['from_left_d0']:.1f} / {w['from_right_d0']:.1f} d0 from the walls) "
                f"{w['count']} of {before} contacts ({pct(kept)}); in total {at.get('total', '–')} of "
                f"{p0.get('total', '–')}; tension {pct(at['F'] / pull['max_tension'])} of the peak",
                "contacts in overlap crossing the crack plane (the weakest plane at Dx = 0.2) at Dx = 0.2, against the "
                "same plane at Dx = 0, and all contacts; read with the force-displacement figure it stands beside: "
                "mostly lost, the tension below 50 % of the peak; not completely, > 0 (the count is given beside)",
                "✓" if 0 < at["F"] / pull["max_tension"] < 0.5 else "✗")
        else:
            add("at 0.2 d0 the sample has mostly, but not completely lost mechanical contact", "–",
                "contacts across the weakest plane at Dx = 0.2 (not recorded by this campaign's pull)", "–")
        lc = pull.get("last_contact_Dx")
        add("complete detachment at much higher amplitude than expected from a two-particle interaction",
            f"last chain at Dx = {lc:.2f}" if lc else "–",
            "last chain of contacts between the walls against a pair's separation from the sintered overlap to "
            "detachment (about 0.05 d0): much higher: > 20 x", "✓" if lc and lc > 1.0 else "–")
    if t and 0.2 in t:
        keys = sorted((k for k in runs if k[0] == "tension" and k[1] >= 0.2), key=lambda k: (k[1], -k[2]))
        got = {k: retrace(runs[k][1]) for k in keys}
        ok = {k: max(v) <= 0.05 for k, v in got.items()}
        add("the reversible, elastic un-/re-loading stretches to four times phi_f d0 and even higher",
            "cycles 2–4 peaks' range over the first peak / over their mean: "
            + ", ".join(f"Dx {k[1]:g} at {k[2]:g} t_w: {pct(v[0])} / {pct(v[1], '.3g')}" for k, v in got.items()),
            f"cycles 2–4 retrace one branch (both <= 5 %, as for the repeated cycles above) at "
            f"Dx = 0.2 = {0.2 / PHI_F:g} phi_f d0 and "
            "beyond, each period (changed from the loop area, as there)",
            "✓" if all(ok.values()) else ("◐" if any(ok.values()) or any(v[0] <= 0.05 for v in got.values()) else "✗"),
            why=_drift(runs, [0.2, 0.3]))
    rate = [(a, t[a]) for a in amps["tension"] if len([k for k in runs if k[:2] == ("tension", a)]) > 1]
    if rate:
        first, later = 0.0, 0.0
        for a, _ in rate:
            ks = sorted(k for k in runs if k[:2] == ("tension", a))[-2:]
            p1, p2 = ([c["peak"] for c in runs[k][1]] for k in ks)
            first = max(first, abs(p2[0] / p1[0] - 1))  # the slower run against the faster, as sensitivity.json
            later = max([later] + [abs(y / x - 1) for x, y in zip(p1[1:], p2[1:])])
        add("thick lines, four times slower: not an effect of viscosity (tension)",
            f"largest change between the two slowest periods: of a first peak {pct(first)}, of a later cycle's peak "
            f"{pct(later)}",
            "each cycle's peak, the 4 x slower run's against the faster's; quasi-static: <= 5 % (the paper: "
            "'qualitatively'; ◐ when only the first peaks are)",
            "✓" if max(first, later) <= 0.05 else ("◐" if first <= 0.05 else "✗"),
            why=_rate(d))
    if pull:
        marks = [round(s["mark"], 2) for s in pull.get("snapshots", [])]
        add("snapshots at Dx = 0, 0.81, 1.8, 3.1, 4.7, 7.4 and 8.6 (a)–(g)", f"snapshots at {marks}",
            "the pull's snapshot marks", "✓" if marks == [0.0, 0.81, 1.8, 3.1, 4.7, 7.4, 8.6] else "✗")
        rough = load_json(d, "roughness.json")
        if rough:
            lr, rr, flat = rough["left"], rough["right"], rough.get("flat_cut")
            ranges = (lr["range_5_95"], rr["range_5_95"])
            flat_range = max(flat["left"]["range_5_95"], flat["right"]["range_5_95"]) if flat else None
            add("the contact surface has developed a roughness of the size of several primary particles",
                f"fracture faces ({rough['snapshot']}): heights' 5–95 % range {ranges[0]:.1f} and {ranges[1]:.1f} "
                f"d0 (rms {lr['rms']:.2f}, {rr['rms']:.2f})" + (f"; a flat cut through the sample: {flat_range:.1f} d0"
                                                                if flat else ""),
                "each torn half's outermost sphere surface over d0 x d0 columns across the pull "
                "(mesostudies.tablet.roughness); several particles: range >= 2 d0 on both faces and >= 2 x a flat "
                "cut's",
                "✓" if min(ranges) >= 2 and flat and min(ranges) >= 2 * flat_range else
                ("◐" if min(ranges) >= 1 else "✗"))
        else:
            add("the contact surface has developed a roughness of the size of several primary particles", "–",
                "not measured (roughness.json absent: python3 -m mesostudies.tablet.roughness)", "–")
        g = pull.get("first_gap_Dx")
        add("the first visible gap is opened at Dx ~ d0", f"Dx = {g:.2f}" if g else "–",
            pull.get("gap_criterion", "") + f"; ~ d0: within a factor {APPROX:g} ({1 / APPROX:.2f}–{APPROX:g})",
            "✓" if g and 1 / APPROX <= g <= APPROX else "✗")
        chance, spread = _realizations(d, st)
        add("the contact is lost only at Dx ~ 8 d0, when the last of the thin threads breaks; completely only at the "
            "extreme, final deformation (the paper: 'Fig. 19(g)', read as Fig. 17(g))", f"Dx = {lc:.2f}" if lc else "–",
            f"no chain of contacts in overlap from wall to wall; ~ 8 d0: within a factor {APPROX:g} "
            f"({8 / APPROX:.2f}–{8 * APPROX:g}; one measurement for the paper's two sentences); ◐ where this seed "
            "misses it but the paper's 8 lies within one sd of the realizations' mean",
            "✓" if lc and 8 / APPROX <= lc <= 8 * APPROX else ("◐" if spread is not None and spread <= 1 else "✗"),
            why=chance)
        branch = tension_extent(d)
        add("the elastic, irreversible tension branch is strongly developed only for Dx ~ d0/5",
            (f"peak tension {-pull['max_tension']:.3g} at Dx = {pull['max_tension_Dx']:.3f}; below half the peak "
             f"for good from Dx = {branch[0]:.3f}, below a third from {branch[1]:.3f}") if branch else "–",
            "the extent of the significant tension against the 8 d0 of the last thread: where the pull's tension stays "
            f"below half (a third) of its peak; ~ d0/5: within a factor {APPROX:g} "
            f"({0.2 / APPROX:.3f}–{0.2 * APPROX:g}; "
            "changed from the peak's Dx: read so, the sentence would contradict the paper's own 'mostly lost contact' "
            "at 0.2); ◐ when one of the two is",
            ("✓" if all(0.2 / APPROX <= x <= 0.2 * APPROX for x in branch) else
             ("◐" if any(0.2 / APPROX <= x <= 0.2 * APPROX for x in branch) else "✗"))
            if branch else "–", why=_early_peak(d))
    # -- compression
    c = {a: _slowest(runs, "compression", a) for a in amps["compression"]}
    if c and all(a in c for a in (0.05, 0.1, 0.2, 0.3)):
        rv = {a: max(x["loop_over_elastic"] for x in c[a][1][1:]) for a in c}
        sets = {a: c[a][1][-1]["set"] for a in c}
        rv1 = {a: max(x["loop_over_elastic"] for x in c[a][1]) for a in c}  # every cycle, the first included
        smallest = (0.05, 0.1)
        elastic = {a: rv1[a] <= 0.05 and sets[a] <= 0.05 for a in smallest}
        add("the smallest amplitudes remain elastic throughout",
            "; ".join(f"{a:g}: largest loop {pct(rv1[a])} (cycle 1), set {pct(sets[a])}" for a in smallest),
            "every cycle's loop against its elastic energy and the permanent set after the last cycle, at the two "
            "smallest amplitudes; elastic: loop <= 5 %, set <= 5 % of the amplitude; ◐ when the smallest is within 2 "
            "points of both",
            "✓" if all(elastic.values()) else ("◐" if rv1[0.05] <= 0.07 and sets[0.05] <= 0.07 else "✗"),
            why=(f"The first cycle dissipates {pct(rv1[0.05])} of its elastic energy at 0.05 and the sample keeps a "
                 f"set of {pct(sets[0.05])} of the amplitude there, {pct(sets[0.1])} at 0.1: it sets from the "
                 "smallest amplitude on, evenly with the amplitude (next statement)."))
        add(**_plastic_onset(c, sets))
        drift = abs(c[0.2][1][-1]["set"] - c[0.2][1][1]["set"])  # a fraction of the amplitude
        rc = retrace(c[0.2][1])
        add("unloading and re-loading on the same branch: a new elastic branch (Dx = 0.2)",
            f"cycles 2–4 peaks' range {pct(rc[0])} of the first peak / {pct(rc[1])} of their mean; loop of "
            f"cycles 2–4 {pct(rv[0.2])}; set changes by {drift * 0.2:.2g} d0 ({pct(drift)} of the "
            f"amplitude) from cycle 2 to 4",
            "cycles 2–4 retrace one branch (both ranges <= 5 %, as for the repeated cycles above) with the set "
            "constant within 1 % of the amplitude; the loop area beside it (◐ when one of the two holds)",
            "✓" if max(rc) <= 0.05 and drift <= 0.01 else ("◐" if max(rc) <= 0.05 or drift <= 0.01 else "✗"),
            why=(f"The branch is retraced (peaks within {pct(max(rc))}) but moves: the set drifts by {pct(drift)} "
                 "of the amplitude over cycles 2–4 and each peak is lower than the last." if drift > 0.01 else ""))
        pk = [x["peak"] for x in c[0.3][1]]
        st3 = [x["set"] for x in c[0.3][1]]
        lp3 = [x["loop_over_elastic"] for x in c[0.3][1]]
        add("at 0.3 (yellow): continuous damage by irreversible re-arrangement during each cycle",
            f"peaks {', '.join(f'{x:.3g}' for x in pk)}; sets {', '.join(pct(x) for x in st3)}; "
            f"loops {', '.join(pct(x) for x in lp3)}",
            "peak, set and loop of each cycle at 0.3; continuing damage: loop of cycles 2–4 above 5 % and above "
            "the 0.2 loop", "✓" if min(lp3[1:]) > 0.05 and min(lp3[1:]) > rv[0.2] else "✗")
        worst = 0.0
        for a in c:
            ks = sorted(k for k in runs if k[:2] == ("compression", a))[-2:]
            if len(ks) == 2:
                p1, p2 = ([x["peak"] for x in runs[k][1]] for k in ks)
                worst = max(worst, max(abs(y / x - 1) for x, y in zip(p1, p2)))  # slower against faster
        add("thick lines four times slower: small quantitative difference, qualitative agreement (compression)",
            f"largest change of a cycle's peak: {pct(worst, '.3g')}",
            "every cycle's peak, the 4 x slower run's against the faster's (as summary.md); <= 5 %",
            "✓" if worst <= 0.05 else "✗")
    f19 = load_json(d, "fig19.json") or {}
    # a monotonic compression, or cycles (earlier campaigns)
    big = f19.get("until") or max(f19.get("amplitudes") or [0])
    sn = f19.get("snapshots") or []
    add("Fig. 19: the continuous plastic deformation of the sample at large strains",
        (f"compression to Dx = {big:g}" + (f"; width in y {sn[0]['width_y_d0']:.1f} to {sn[-1]['width_y_d0']:.1f} d0, "
                                           f"coordination {sn[0]['coordination']:.2f} to {sn[-1]['coordination']:.2f}"
                                           if len(sn) > 1 else "")) if big else "–",
        "a compression well beyond the cyclic amplitudes (> 1 d0) with snapshots",
        "✓" if big > 1.0 else "✗")
    extent = next((x["n"] for x in out if x["paper"].startswith("the elastic, irreversible tension branch")), None)
    for x in out:
        x["why"] = x["why"].replace("§extent", str(extent))
    return out


def retrace(cycles):
    """measures.retrace of a run's cycle measures."""
    return measures.retrace([c["peak"] for c in cycles])


def _drift(runs, amps):
    """The later cycles' peaks of the tension runs at ``amps``, each period, with their range over
    their mean: how far cycles 2-4 are from retracing one branch, and how that depends on the rate."""
    parts = []
    for a in amps:
        for k in sorted(k for k in runs if k[:2] == ("tension", a)):
            later = [c["peak"] for c in runs[k][1][1:]]
            parts.append(f"at {a:g}, {k[2]:g} t_w: {', '.join(f'{x:.4f}' for x in later)} "
                         f"({pct(retrace(runs[k][1])[1], '.3g')})")
    return ("Cycles 2–4 peaks (range over their mean): " + "; ".join(parts) + ". ") if parts else ""


def _far_force(run, d):
    """The force where the run's last cycle turns back (its largest Dx)."""
    rows = read_csv(os.path.join(d, run["name"] + ".csv"))
    start, n = rows[0][0], run["steps_per_cycle"]
    last = [r for r in rows if r[0] - start >= (run["cycles"] - 1) * n] or rows
    return max(last, key=lambda r: r[1])[2]


def tension_extent(d, name="fig17.csv", until=None):
    """Where the pull's tension stays below half and below a third of its peak for good (Dx past
    the peak, to the pull's end or to Dx = ``until``), from the pull ``name`` in ``d``; None without it."""
    p = os.path.join(d, name)
    if not os.path.exists(p):
        return None
    rows = [r for r in read_csv(p) if until is None or r[1] <= until]
    peak = min(rows, key=lambda r: r[2])
    out = []
    for frac in (0.5, 1 / 3):
        since = None
        for r in rows:
            if r[1] <= peak[1]:
                continue
            if r[2] > frac * peak[2]:
                since = r[1] if since is None else since
            else:
                since = None
        out.append(since)
    return tuple(out) if None not in out else None


def _experiments(d):
    """Issue #47's experiment table of the campaign tree (../branch/experiments.json), or {}."""
    return load_json(os.path.join(d, "..", "branch"), "experiments.json") or {}


def _first_pull(d):
    """Why the repeated tension cycles are weaker than the first pull, from E1 and E6 (the
    experiments' table); '' without it."""
    ex = _experiments(d)
    one = {(r["amplitude"], r["period"]): r for r in ex.get("E1", []) if r["sample"] == "chosen"}
    six = {r["amplitude"]: r for r in ex.get("E5_E6", []) if r["sample"] == "tested" and r["variant"] == "force-return"}
    if not one:
        return ""
    txt = ("Cycles 2–4 retrace one branch; what they lack is what the first pull lost: where the first cycle "
           "turns back the tested sample keeps "
           + ", ".join(f"{one[(a, 480.0)]['turnaround_over_first']:.2f} at {a:g}"
                       for a in (0.025, 0.05, 0.1, 0.2) if (a, 480.0) in one)
           + " of its first peak (480 t_w; branch/experiments.md, E1)")
    if six:
        txt += (". Not the return to Dx = 0, which compresses the lengthened sample: cycles that return only to the "
                "start's force (E6) keep "
                + ", ".join(f"{six[a]['second_over_first']:.2f} at {a:g}" for a in sorted(six))
                + " in cycle 2, against "
                + ", ".join(f"{one[(a, 480.0)]['second_over_first']:.2f}" for a in sorted(six) if (a, 480.0) in one)
                + " returning to Dx = 0; they return at Dx = "
                + ", ".join(f"{six[a]['returns_at_Dx'][0]:.3f}" for a in sorted(six)) + " (the lengthening)")
    return txt + (". Why the first pull loses so early: statement §extent." if ex.get("E3") else ".")


def _early_peak(d):
    """Why the tension peaks and falls early, from E3 and E5 (the experiments' table); '' without it."""
    ex = _experiments(d)
    three = {r["sample"]: r for r in ex.get("E3", [])}
    five = [r for r in ex.get("E5_E6", []) if r["variant"].startswith("kc") and r["E1"]]
    parts = []
    if "tested" in three:
        r = three["tested"]
        parts.append(f"Up to its peak (Dx = {r['peak_Dx']:.3f}) the tested sample stretches about evenly (largest "
                     f"local strain {r['strain_at_peak']:.1f} x the affine one; for good >= 2 x only from Dx = "
                     f"{r['strain_2x_from_Dx']:.3f}), yet at the peak {100 * r['measured']['tensile']:.1f} % of its "
                     f"contacts are on the tensile limit where an affine stretch of the same contacts puts "
                     f"{100 * r['affine']['tensile']:.1f} % (E3): the contacts do not share the stretch as an affine "
                     "estimate assumes, and the sample does not localize before its peak")
    tested = [r for r in five if r["sample"] == "tested"]
    if tested:
        r = max(tested, key=lambda x: x["amplitude"])
        lo, hi = r["contact_pull_ratio"]
        parts.append(f"its peak force is set by the contacts' pull: with kc/kp {r['kc_over_kp']:g} instead of 0.2 on "
                     f"the same sample the first peak grows {r['peak_over_E1']:.2f} times, as a contact's largest "
                     f"pull does ({lo:.2f} – {hi:.2f} times), and moves from Dx = {r['E1']['first_peak_Dx']:.3f} to "
                     f"{r['first_peak_Dx']:.3f} (E5)")
    return ("; ".join(parts) + ". See docs/tablet/branch.md.") if parts else ""


def _rate(d):
    """Whether the tension runs' rate difference is viscosity or chance (sensitivity.json, if present)."""
    sens = load_json(d, "sensitivity.json")
    if not sens:
        return ""
    parts = []
    for a, v in sorted(sens["amplitudes"].items(), key=lambda kv: float(kv[0])):
        parts.append(f"at Dx = {a}: the first pull's peak {pct(v['rate_change'][0])} apart between the rates; "
                     f"cycles 2–4 {', '.join(pct(x) for x in v['rate_change'][1:])} apart, against "
                     f"{', '.join(pct(x) for x in v['perturbation_change'][1:])} for a time step changed by 1e-6")
    return ("The first pulls are quasi-static. Whether the later cycles are is told by a time step changed by 1e-6 "
            "(sensitivity.json), which shows how much such a run moves by chance: " + "; ".join(parts)
            + ". Where the rate moves a peak several times more than the perturbation (at 0.1), the later cycles "
            "depend on the rate; where it does not (at 0.3, cycle 2), the difference is the runs' own sensitivity.")


def _realizations(d, st):
    """The last chain over the realizations of this sample's preparation (../factors/factors.json):
    (text, the paper's 8 in the realizations' sd from their mean), ('', None) with fewer than two."""
    v = sorted(r["last_chain_Dx"] for r in realizations(d, st) if r["last_chain_Dx"] is not None)
    if len(v) < 2:
        return "", None
    m, sd = statistics.mean(v), statistics.stdev(v)
    inside = sum(8 / APPROX <= x <= 8 * APPROX for x in v)
    return (f"One draw: over {len(v)} realizations of this preparation (../factors/factors.md) the last chain is "
            f"{', '.join(f'{x:.2f}' for x in v)} (mean {m:.2f}, sd {sd:.2f}; {inside} inside "
            f"{8 / APPROX:.2f}–{8 * APPROX:g}); "
            f"the paper's single pull, about 8, lies {abs(8 - m) / sd:.2f} sd from the mean: within the "
            "realizations' spread."), abs(8 - m) / sd


def markdown(items, source):
    lines = [f"# Appendix F, statement by statement ({source})", "",
             "Computed by `python3 -m mesostudies.tablet.statements DIR` from the files in this directory; "
             "✓ met, ◐ in part, ✗ not met, – not in these files.", "",
             "| # | the paper | the project | measured as | verdict |", "|---|---|---|---|---|"]
    for s in items:
        note = f" ({s['note']})" if s["note"] else ""
        lines.append(f"| {s['n']} | {s['paper']} | {s['project']} | {s['definition']}{note} | {s['verdict']} |")
    why = [s for s in items if s.get("why") and s["verdict"] in ("✗", "◐")]
    if why:
        lines += ["", "## Why the statements not or only partly met are so (from the files and the experiments)", ""]
        lines += [f"- **{s['n']}.** {s['why']}" for s in why]
    return "\n".join(lines) + "\n"


def main(argv):
    if len(argv) != 1 or not os.path.isdir(argv[0]):
        sys.exit("usage: python3 -m mesostudies.tablet.statements DOCS_DIR (a campaign's docs directory)")
    items = statements(argv[0])
    with open(os.path.join(argv[0], "statements.json"), "w") as f:
        json.dump(items, f, indent=1, ensure_ascii=False)
    with open(os.path.join(argv[0], "statements.md"), "w") as f:
        f.write(markdown(items, argv[0]))
    print(markdown(items, argv[0]))


if __name__ == "__main__":
    main(sys.argv[1:])
