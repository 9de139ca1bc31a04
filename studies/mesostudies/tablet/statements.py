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
from mesocontact import theory

PHI_F = 0.05
TOL_L0 = 0.01  # the tested sample's length against the paper's 0.115: 1 %
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


def _runs(d):
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


def _pct(x, f=".2g"):
    return "–" if x is None else f"{100 * x:{f}} %"


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
    return sorted((r for r in rows if (r["packing"], r["glue"], r["rel_std"], r.get("sinter", SINTER), r["drag"]) ==
                   (b.get("packing", "full"), b.get("glue", "loading"), b.get("rel_std", 0.05), b.get("sinter", SINTER),
                    "contacts")), key=lambda r: r["seed"])


def statements(d):
    """The list of statements of Appendix F with number, definition and verdict (see the module)."""
    st = load_json(d, "unconfined.yade.gz.json") or load_json(d, "released.yade.gz.json")
    runs = _runs(d)
    pull = load_json(d, "fig17.json")
    out = []

    def add(quote, number, definition, verdict, note="", why=""):
        out.append({"n": len(out) + 1, "paper": quote, "project": number, "definition": definition,
                    "verdict": verdict, "note": note, "why": why})

    limit = _tensile_limit(d, st, pull, runs)
    cracked = _cracked(pull, runs) if limit else ""

    amps = {m: sorted({k[1] for k in runs if k[0] == m}) for m in ("tension", "compression")}
    L0s = sorted({j["L0"] for j, _ in runs.values()})
    # -- the sample
    if L0s:
        L0 = L0s[0]
        err = L0 / 0.115 - 1
        add("an agglomerate (cubic) of size L0 = 0.115", f"L0 = {L0:.5f} ({_pct(err)} from 0.115)",
            "x length between the loading walls at the start of every test",
            "✓" if abs(err) <= TOL_L0 else ("◐" if abs(err) <= 0.05 else "✗"), f"within {_pct(TOL_L0)}: ✓; 5 %: ◐")
    else:
        add("an agglomerate (cubic) of size L0 = 0.115", "–", "x length at the test start", "–")
    if st:
        b = st["built"]
        add("N = 1728 primary particles of diameter d0 = 0.01 (with some variation in size)",
            f"N = {b['n']}, radii {b['radii'][0] / 0.005:.3f}–{b['radii'][1] / 0.005:.3f} d0/2",
            f"particles built; Gaussian radii, relative std {_pct(b.get('rel_std', 0.05))}, cut at 2 sigma",
            "✓" if b["n"] == 1728 else "✗")
        s = st["sintered"]
        ws = max(abs(v / s["goal"] - 1) for v in s["wall_stress"].values()) if "goal" in s else None
        add("compressed (pressure-sintered) with a dimensionless wall stress d0 p_s/kp = 0.02",
            f"every wall within {_pct(ws)} of p_s" if ws is not None else "–",
            "wall stresses when sintering ends", "✓" if ws is not None and ws < 0.01 else "–")
        add("to form a stable, rather dense agglomerate",
            f"solid fraction {s['solid_fraction']:.3f}, C {s['coordination']:.2f}, {s['rattlers']} rattlers, "
            f"E_kin/E_ref {s['kinetic_energy_ratio']:.1e}",
            "sintered state; static: E_kin below 1e-4 of the elastic energy scale; dense: solid fraction >= 0.60",
            "✓" if s["kinetic_energy_ratio"] < 1e-4 and s["solid_fraction"] >= 0.60 else "◐")
        r = st["released"]
        wr = max(abs(v / r["goal"] - 1) for v in r["wall_stress"].values()) if "goal" in r else None
        add("the stress is first released to 2e-5, i.e. p_r/p_s = 1e-3, for all walls",
            (f"every wall within {_pct(wr)} of p_r; " if wr is not None else "")
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
        rev = {a: max(c["loop_over_elastic"] for c in t[a][1][1:]) for a in amps["tension"]}
        add("repeated cyclic loading remains on the same branch with positive slope (elastic)",
            ", ".join(f"{a:g}: {_pct(rev[a])}" for a in small),
            "largest loop area of cycles 2–4 against the elastic energy of the force swing, amplitudes below 0.2 "
            "(slowest run); reversible: <= 5 %", "✓" if max(rev[a] for a in small) <= 0.05 else "✗", why=cracked)
        far = {a: max(abs(c["peak"]) for c in t[a][1]) for a in amps["tension"]}
        add("while it is not completely, perfectly detached",
            "tensile force at every cycle's far point: " + ", ".join(f"{a:g}: {far[a]:.3g}" for a in amps["tension"]),
            "|F|/(kp d0) at each amplitude's peak (> 0: still attached)", "✓" if all(far[a] > 0 for a in far) else "✗")
        ratio = rev[0.2] / max(rev[a] for a in small)
        add("for the largest amplitude (0.2) the behaviour is not perfectly elastic, first plastic effects",
            f"loop of cycles 2–4 at 0.2: {_pct(rev[0.2])}, {ratio:.1f} x the smaller amplitudes' largest",
            "loop area against elastic energy, 0.2 against the smaller amplitudes; plastic effects: > 2 x",
            "✓" if ratio > 2 else "✗", why=cracked)
    # -- the pull and Dx = 0.2
    if pull:
        at = (pull.get("planes_at_marks") or {}).get("0.2")
        p0 = pull.get("planes_at_start")
        if at and p0:
            w, before = crack_plane(pull)
            kept = w["count"] / before
            add("at 0.2 d0 the sample has mostly, but not completely lost mechanical contact",
                f"across the crack plane ({w['from_left_d0']:.1f} / {w['from_right_d0']:.1f} d0 from the walls) "
                f"{w['count']} of {before} contacts ({_pct(kept)}); in total {at.get('total', '–')} of "
                f"{p0.get('total', '–')}; tension {_pct(at['F'] / pull['max_tension'])} of the peak",
                "contacts in overlap crossing the crack plane (the weakest plane at Dx = 0.2) at Dx = 0.2, against the "
                "same plane at Dx = 0, and all contacts; mostly lost: < 50 % left, not completely: > 0",
                "✓" if 0 < kept < 0.5 else "✗",
                why=(f"By the force it carries the sample has mostly lost contact at Dx = 0.2 (tension "
                     f"{_pct(at['F'] / pull['max_tension'])} of the peak); by the count across the crack it is short of "
                     f"it ({_pct(kept)} left against < 50 %): the count includes contacts still in overlap that carry no "
                     "tension (not separated here)." if kept >= 0.5 else ""))
        else:
            add("at 0.2 d0 the sample has mostly, but not completely lost mechanical contact", "–",
                "contacts across the weakest plane at Dx = 0.2 (not recorded by this campaign's pull)", "–")
        lc = pull.get("last_contact_Dx")
        add("complete detachment at much higher amplitude than expected from a two-particle interaction",
            f"last chain at Dx = {lc:.2f}" if lc else "–",
            "last chain of contacts between the walls against a pair's separation from the sintered overlap to "
            "detachment (about 0.05 d0): much higher: > 20 x", "✓" if lc and lc > 1.0 else "–")
    if t and 0.2 in t:
        rev2 = max(c["loop_over_elastic"] for c in t[0.2][1][1:])
        add("the reversible, elastic un-/re-loading stretches to four times phi_f d0 and higher",
            f"loop of cycles 2–4 at Dx = 0.2 = {0.2 / PHI_F:g} phi_f d0: {_pct(rev2)}",
            "loop area against elastic energy at Dx = 4 phi_f d0; elastic: <= 10 %", "✓" if rev2 <= 0.10 else "✗",
            why=cracked)
    rate = [(a, t[a]) for a in amps["tension"] if len([k for k in runs if k[:2] == ("tension", a)]) > 1]
    if rate:
        worst = 0.0
        for a, _ in rate:
            ks = sorted(k for k in runs if k[:2] == ("tension", a))[-2:]
            p1, p2 = ([c["peak"] for c in runs[k][1]] for k in ks)
            worst = max(worst, max(abs(x / y - 1) for x, y in zip(p1, p2)))
        add("thick lines, four times slower: not an effect of viscosity (tension)",
            f"largest change of a cycle's peak between the two slowest periods: {_pct(worst)}",
            "every cycle's peak, fast against 4 x slower; quasi-static: <= 5 %", "✓" if worst <= 0.05 else "✗",
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
                f"fracture faces ({rough['snapshot']}): heights' 5–95 % range {ranges[0]:.1f} and {ranges[1]:.1f} d0 (rms "
                f"{lr['rms']:.2f}, {rr['rms']:.2f})" + (f"; a flat cut through the sample: {flat_range:.1f} d0" if flat else ""),
                "each torn half's outermost sphere surface over d0 x d0 columns across the pull "
                "(mesostudies.tablet.roughness); several particles: range >= 2 d0 on both faces and >= 2 x a flat cut's",
                "✓" if min(ranges) >= 2 and flat and min(ranges) >= 2 * flat_range else
                ("◐" if min(ranges) >= 1 else "✗"))
        else:
            add("the contact surface has developed a roughness of the size of several primary particles", "–",
                "not measured (roughness.json absent: python3 -m mesostudies.tablet.roughness)", "–")
        g = pull.get("first_gap_Dx")
        add("the first visible gap is opened at Dx ~ d0", f"Dx = {g:.2f}" if g else "–",
            pull.get("gap_criterion", "") + "; ~ d0: 0.6–1.4", "✓" if g and 0.6 <= g <= 1.4 else "✗")
        chance = _realizations(d, st)
        add("the contact is lost only at Dx ~ 8 d0, when the last of the thin threads breaks",
            f"Dx = {lc:.2f}" if lc else "–", "no chain of contacts in overlap from wall to wall; ~ 8 d0: 6–10",
            "✓" if lc and 6 <= lc <= 10 else "✗", why=chance)
        add("the contact is completely lost only at the extreme, final deformation (g)",
            f"last chain at {lc:.2f}" if lc else "–", "between snapshots (f) 7.4 and (g) 8.6",
            "✓" if lc and 7.4 < lc <= 8.6 else ("◐" if lc and 6 <= lc <= 10 else "✗"), why=chance)
        pdx = pull.get("max_tension_Dx")
        add("the elastic, irreversible tension branch is strongly developed only for Dx ~ d0/5",
            f"peak tension {-pull['max_tension']:.3g} at Dx = {pdx:.2f}", "Dx of the pull's largest tension; ~ 0.2: 0.1–0.4",
            "✓" if 0.1 <= pdx <= 0.4 else "✗", why=limit + _loose_peak(d))
    # -- compression
    c = {a: _slowest(runs, "compression", a) for a in amps["compression"]}
    if c and all(a in c for a in (0.05, 0.1, 0.2, 0.3)):
        rv = {a: max(x["loop_over_elastic"] for x in c[a][1][1:]) for a in c}
        sets = {a: c[a][1][-1]["set"] for a in c}
        add("the smallest amplitudes remain elastic throughout", f"0.05: loop {_pct(rv[0.05])}, set {_pct(sets[0.05])}",
            "loop of cycles 2–4 against elastic energy and the permanent set after the last cycle at Dx = 0.05; "
            "elastic: loop <= 5 %, set <= 5 % of the amplitude", "✓" if rv[0.05] <= 0.05 and sets[0.05] <= 0.05 else "✗")
        add("plastic deformation kicks in for Dx > 0.1 (the red curve)",
            "set " + ", ".join(f"{a:g}: {_pct(sets[a])}" for a in sorted(sets)),
            "permanent set after the last cycle against the amplitude; kicks in: the set at 0.2 over 1.5 x that at 0.1",
            "✓" if sets[0.2] > 1.5 * sets[0.1] else "✗")
        drift = abs(c[0.2][1][-1]["set"] - c[0.2][1][1]["set"])  # a fraction of the amplitude
        add("unloading and re-loading on the same branch: a new elastic branch (Dx = 0.2)",
            f"loop of cycles 2–4 {_pct(rv[0.2])}, set changes by {drift * 0.2:.2g} d0 ({_pct(drift)} of the amplitude) "
            "from cycle 2 to 4",
            "loop against elastic energy <= 5 % and set constant within 1 % of the amplitude over cycles 2–4",
            "✓" if rv[0.2] <= 0.05 and drift <= 0.01 else "◐")
        pk = [x["peak"] for x in c[0.3][1]]
        st3 = [x["set"] for x in c[0.3][1]]
        lp3 = [x["loop_over_elastic"] for x in c[0.3][1]]
        add("at 0.3 (yellow): continuous damage by irreversible re-arrangement during each cycle",
            f"peaks {', '.join(f'{x:.3g}' for x in pk)}; sets {', '.join(_pct(x) for x in st3)}; "
            f"loops {', '.join(_pct(x) for x in lp3)}",
            "peak, set and loop of each cycle at 0.3; continuing damage: loop of cycles 2–4 above 5 % and above "
            "the 0.2 loop", "✓" if min(lp3[1:]) > 0.05 and min(lp3[1:]) > rv[0.2] else "✗")
        worst = 0.0
        for a in c:
            ks = sorted(k for k in runs if k[:2] == ("compression", a))[-2:]
            if len(ks) == 2:
                p1, p2 = ([x["peak"] for x in runs[k][1]] for k in ks)
                worst = max(worst, max(abs(x / y - 1) for x, y in zip(p1, p2)))
        add("thick lines four times slower: small quantitative difference, qualitative agreement (compression)",
            f"largest change of a cycle's peak: {_pct(worst)}", "every cycle's peak, fast against 4 x slower; <= 5 %",
            "✓" if worst <= 0.05 else "✗")
    f19 = load_json(d, "fig19.json") or {}
    big = f19.get("until") or max(f19.get("amplitudes") or [0])  # a monotonic compression, or cycles (earlier campaigns)
    add("Fig. 19: the continuous plastic deformation of the sample at large strains",
        f"compression to Dx = {big:g}" if big else "–",
        "a compression well beyond the cyclic amplitudes (> 1 d0) with snapshots",
        "✓" if big > 1.0 else "✗")
    return out


def _tensile_limit(d, st, pull, runs):
    """Where the rising tension of a contact ends, from the closed form and the files: under an
    affine stretch every contact along x reaches its tensile limit by the strain phiF kc/(2 (kp + kc))
    (theory.max_tensile_range over the centre distance, a12 <= l/2); its tension then falls along
    -kc delta, over a range that grows with the sintering depth (docs/tablet/branch.md)."""
    if not (st and pull and runs):
        return ""
    kc = st["built"]["kc_over_kp"]
    L0 = sorted({j["L0"] for j, _ in runs.values()})[0] / st["d0"]
    eps = theory.max_tensile_range(1.0, kc, PHI_F, 0.5)  # in units of the centre distance l = 2 a12
    aff = load_json(d, "affine.json")
    return (f"A contact can open at most phiF a12 kc/(kp + kc) from its force-free overlap before its tension starts to "
            f"fall (theory.max_tensile_range), then carries less along -kc delta until it lets go; stretched affinely, every "
            f"contact along x reaches that limit by the strain {100 * eps:.2f} %, Dx = {eps * L0:.3f} on L0 = {L0:.2f} d0"
            + (f" (this sample's contacts along x: half by Dx = {aff['Dx_to_tensile_limit']['50']:.3f}, affine.json)"
               if aff else "")
            + f". The pull's tension peaks at Dx = {pull['max_tension_Dx']:.3f}, inside that bound. Deeper-sintered samples "
              "peak later, where the affine estimate of their own contacts does (docs/tablet/branch.md, E2).")


def _cracked(pull, runs):
    """Why the repeated tension cycles are not reversible: the first pull beyond the peak cracks the sample."""
    pdx = pull["max_tension_Dx"]
    above = sorted(k for k in runs if k[0] == "tension" and k[1] > pdx)
    if not above:
        return ""
    k = min(above, key=lambda k: (k[1], -k[2]))  # the smallest amplitude above the peak, slowest run
    peaks = [c["peak"] for c in runs[k][1]]
    drop = 1 - max(abs(x) for x in peaks[1:]) / abs(peaks[0])
    return (f"The pull's tension peaks at Dx = {pdx:.3f} (statement 21): every tension amplitude above it cracks the "
            f"sample in its first pull (at Dx = {k[1]:g} the later peaks are {_pct(drop)} or more below the first), so "
            "cycles 2–4 are those of a cracked sample. Why the peak comes so early: 21.")


def _rate(d):
    """Whether the tension runs' rate difference is viscosity or chance (sensitivity.json, if present)."""
    sens = load_json(d, "sensitivity.json")
    if not sens:
        return ""
    parts = []
    for a, v in sorted(sens["amplitudes"].items(), key=lambda kv: float(kv[0])):
        parts.append(f"at Dx = {a}: the first pull's peak {_pct(v['rate_change'][0])} apart between the rates; cycles 2–4 "
                     f"{', '.join(_pct(x) for x in v['rate_change'][1:])} apart, against "
                     f"{', '.join(_pct(x) for x in v['perturbation_change'][1:])} for a time step changed by 1e-6")
    return ("The uncracked first pulls are quasi-static; the cracked sample's later cycles are not, and the time-step "
            "perturbation (sensitivity.json) tells a rate effect from the crack's own sensitivity: " + "; ".join(parts)
            + ". Where the rate moves a peak several times more than the perturbation, the cracked sample is rate "
            "dependent, measured.")


def _loose_peak(d):
    """Which preparations of the factor study (../factors/factors.json) peak late, if present."""
    rows = load_json(os.path.join(d, "..", "factors"), "factors.json") or []
    late = [r for r in rows if r["peak_Dx"] >= 0.1]
    dense = [r["peak_Dx"] for r in rows if abs(r["L0"] / 0.115 - 1) <= TOL_L0 and r.get("sinter", SINTER) == SINTER]
    if not late or not dense:
        return ""
    return (f" In the factor study (../factors/factors.md), at the paper's sintering stress the {len(dense)} pulls of "
            f"samples with L0 within {_pct(TOL_L0)} of 0.115 peak at Dx = {min(dense):.3f}–{max(dense):.3f}; the pulls that "
            "peak at Dx >= 0.1 are: "
            + "; ".join(f"packing {r['packing']}, glue {r['glue']}, d0 p_s/kp {r.get('sinter', SINTER):g}: Dx "
                        f"{r['peak_Dx']:.3f}, solid fraction at the test start {r['test_start']['solid_fraction']:.3f}, "
                        f"L0 {100 * (r['L0'] / 0.115 - 1):+.1f} %" for r in late) + ".")


def _realizations(d, st):
    """The last chain over the realizations of this sample's preparation (../factors/factors.json)."""
    v = sorted(r["last_chain_Dx"] for r in realizations(d, st) if r["last_chain_Dx"] is not None)
    if len(v) < 2:
        return ""
    m, sd = statistics.mean(v), statistics.stdev(v)
    inside = sum(6 <= x <= 10 for x in v)
    return (f"One draw: over {len(v)} realizations of this preparation (../factors/factors.md) the last chain is "
            f"{', '.join(f'{x:.2f}' for x in v)} (mean {m:.2f}, sd {sd:.2f}; {inside} inside 6–10); the paper's 8 is "
            f"{(8 - m) / (sd / len(v) ** 0.5):.1f} standard errors from the mean.")


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
        lines += ["", "## Why the statements not met are not met (from the closed form and the files)", ""]
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
