"""Issue #47's experiments on the tablet's tension branch, in one generated table (plain Python,
from a campaign tree's committed files):

    python3 -m mesostudies.tablet.experiments campaigns/tablet    # writes branch/experiments.md and .json

- E1, cyclic tension of the tested sample (``chosen/``, d0 p_s/kp = 0.02) against the deep-sintered
  one (``deep/``, 0.1, the same preparation otherwise): per amplitude and period the first pull's
  peak, the force where the first cycle turns back against that peak (how much tension the pull
  to the amplitude left: "mostly lost contact" is a small value), the peaks of cycles 2-4 and
  their spread (max - min, over their mean and over the first peak: cycles that retrace one branch
  spread little), and cycle 2's peak against the first.
- E2, the sintering-stress sweep (``factors/``, the chosen preparation at each d0 p_s/kp, one row
  per realization): the pull's peak tension and the Dx where it lies, F(0.2)/F_peak, the first
  visible gap, the last chain, L0 against the paper's, how far from the nearer loading wall the
  crack plane runs at Dx = 0.81 (the weakest plane: at a wall or in the bulk); and, where
  ``affine/`` holds it, the peak Dx of the affine estimate (mesostudies.tablet.affine).
- E3, non-affinity up to the peak (``profile/<sample>/``, mesostudies.tablet.profile): the pull's
  peak, F(0.2)/F_peak, where the largest local strain first reaches 2x the affine one, and the
  start's contacts on the tensile branch and open at the peak, measured against the affine stretch.
- E4, the same pulls and cycles loaded through glued particles instead of the flat walls (grips
  of 1 and 2 d0, ``grips1-``, ``grips2-``; uniaxial.Test.use_grips): the profiles in
  ``profile/<sample>-grips1|2/`` (E3's measures, with the free length's share), the cycles in
  ``variants/<sample>/`` beside E1's.
- E5 and E6, test variants on the same states (``variants/<sample>/``): kc/kp 0.5 instead of 0.2
  (``kc0.5-`` runs), and cycles back to the start's force instead of Dx = 0 (``force-return-``
  runs), each beside the E1 run of its sample, amplitude and period.
"""
import json
import os
import sys

from mesocontact import theory

from .measures import retrace
from .profile import persistent_from
from .statements import load_json, read_csv

E1_SAMPLES = (("chosen", 0.02), ("mid", 0.05), ("deep", 0.1))
# variants/<sample> -> its E1 folder (None: no E1 run)
VARIANT_SAMPLES = {"tested": "chosen", "deep": "deep", "0.1-seed2": None}
K1_OVER_KP, KC_OVER_KP = 0.5, 0.2  # the Appendix F particles' k1/kp and kc/kp (mesostudies.tablet.sample.MATERIALS)


def pull_ratio(kc_new, kc_old=KC_OVER_KP):
    """How much more a contact pulls with kc_new than with kc_old (both over kp): its largest pull
    kc k2 delta0 / (k2 + kc) along its k2 line, k2 between k1 (a contact loaded barely past elastic)
    and kp (one at the plastic limit). Returns (ratio at k2 = k1, ratio at k2 = kp)."""
    return tuple(theory.largest_pull(k2, kc_new, 1.0) / theory.largest_pull(k2, kc_old, 1.0)
                 for k2 in (K1_OVER_KP, 1.0))


PAPER_L0 = 0.115  # the paper's sample length [mm]
D0_MM = 0.01  # the primaries' mean diameter [mm] (mesostudies.tablet.sample.D0)


def e1(tree):
    """Rows of E1: one per sample, amplitude and period whose run is in the tree."""
    rows = []
    for folder, sinter in E1_SAMPLES:
        d = os.path.join(tree, folder)
        if not os.path.isdir(d):
            continue
        for name in sorted(os.listdir(d)):
            if name.startswith("tension-Dx") and name.endswith(".json"):
                rows.append(dict(_cyclic_row(d, name), sample=folder, sinter=sinter))
    return sorted(rows, key=lambda r: (r["sinter"], r["amplitude"], r["period"]))


def _cyclic_row(d, name):
    """The measures of one cyclic tension run (JSON ``name`` in ``d`` and its CSV)."""
    run = load_json(d, name)
    peaks = run["peaks"]
    later = peaks[1:]
    of_first, of_mean = retrace(peaks)
    rows = read_csv(os.path.join(d, name[:-5] + ".csv"))
    turns = run.get("turns")  # cycles back to the start's force: where each stroke ended
    first = [r for r in rows if r[0] <= turns[0][0]] if turns else _first_stroke(rows, run["steps_per_cycle"])
    turn = first[-1][2] if turns else max(first, key=lambda r: r[1])[2]
    return {"amplitude": run["amplitude"], "period": run["period_crossings"], "first_peak": peaks[0],
            "first_peak_Dx": min(first, key=lambda r: r[2])[1], "later_peaks": later,
            "turnaround_over_first": turn / peaks[0] if peaks[0] else None,
            "later_spread": of_mean, "later_spread_of_first": of_first,
            "second_over_first": later[0] / peaks[0] if later else None, "L0": run["L0"],
            "returns_at_Dx": [t[1] for t in turns[1::2]] if turns else None,
            "kc_over_kp": (run.get("tensile_stiffness") or {}).get("kc_over_kp"),
            # through grips only L0 - 2 t d0 stretches: the walls' Dx that strains the free part as much
            "free_amplitude": run["amplitude"] / (1.0 - 2 * run["grips"]["thickness_d0"] * D0_MM / run["L0"])
            if run.get("grips") else None}


def _first_stroke(rows, steps_per_cycle):
    """The first cycle's records up to its largest Dx (where it turns back): the first pull."""
    first = [r for r in rows if r[0] - rows[0][0] < steps_per_cycle] or rows
    far = max(range(len(first)), key=lambda k: first[k][1])
    return first[:far + 1]


def _force_at(rows, dx):
    """The pull's force at the first record at or past ``dx`` (tension: Dx > 0 in the CSV)."""
    return next((f for _, x, f in rows if x >= dx), None)


def _nearer_wall(plane):
    return min(plane["from_left_d0"], plane["from_right_d0"]) if plane else None


def e2(tree):
    """Rows of E2: one per pull of the chosen preparation in factors/, by sintering stress and seed."""
    table = load_json(os.path.join(tree, "factors"), "factors.json")
    rows = []
    for r in table:
        if (r["packing"], r["glue"], r["rel_std"], r["drag"]) != ("frictionless", "sinter", 0.1, "contacts"):
            continue
        js = os.path.join(tree, "factors", r["pull"])  # the row's pull, as factor_table names it
        folder = os.path.dirname(os.path.dirname(js))
        name = os.path.relpath(folder, os.path.join(tree, "factors"))
        pull = read_csv(js[:-5] + ".csv")
        f02 = _force_at(pull, 0.2)
        aff = load_json(os.path.join(folder, "affine"), "affine.json")
        gap = r["first_gap_Dx_by_area"]
        rows.append({"sinter": r["sinter"], "seed": r["seed"],
                     "L0_vs_paper": r["L0"] / PAPER_L0 - 1 if r["L0"] else None,
                     "peak_tension": r["peak_tension"], "peak_Dx": r["peak_Dx"],
                     # factors.json holds the peak's magnitude; the CSV's tension is negative
                     "F02_over_peak": -f02 / r["peak_tension"] if f02 is not None and r["peak_tension"] else None,
                     "first_gap_Dx": gap.get("1") if isinstance(gap, dict) else gap,
                     "last_chain_Dx": r["last_chain_Dx"],
                     "crack_from_wall_d0": _nearer_wall(r["weakest_at_marks"].get("0.81")),
                     "affine_peak_Dx": aff["peak_Dx"] if aff else None,
                     "affine_F02_over_peak": aff["F_at_0.2_over_peak"] if aff else None, "folder": name})
    return sorted(rows, key=lambda r: (r["sinter"], r["seed"]))


def e3(tree):
    """Rows of E3: one per pull profile in profile/<sample>/."""
    rows = []
    base = os.path.join(tree, "profile")
    for sample in sorted(os.listdir(base)) if os.path.isdir(base) else ():
        info = load_json(os.path.join(base, sample), "profile.json")
        if info is None:
            continue
        pull = read_csv(os.path.join(base, sample, "profile.csv"))
        f02 = _force_at(pull, 0.2)
        at_peak = min(info["records"], key=lambda r: abs(r["Dx"] - info["peak_Dx"]))
        at_02 = min(info["records"], key=lambda r: abs(r["Dx"] - 0.2))  # where the stretch gathers after the peak
        proto = info["protocol"]
        grips = info.get("grips")
        # The profile divides the local strain by Dx d0 / L0; through grips only L0 - 2 t d0 is free
        # to stretch, whose even stretch is L0 / (L0 - 2 t d0) times that: the strains below are the free part's.
        free = 1.0 if not grips else 1.0 - 2 * grips["thickness_d0"] * D0_MM / info["L0"]
        f02_free = _force_at(pull, 0.2 * free)  # the same strain of the free part as Dx = 0.2 through walls
        rows.append({"sample": sample, "sinter": proto.get("sinter", 0.02), "seed": proto.get("seed", 1),
                     "peak_Dx_free": info["peak_Dx"] / free,
                     "F02_free_over_peak": (f02_free / info["peak_F"] if f02_free is not None and info["peak_F"]
                                            else None),
                     "loading": (((f"grips {grips['thickness_d0']:g} d0 ({grips['left']} + {grips['right']} of "
                                   f"{grips['left'] + grips['right'] + grips['free']} particles; "
                                   f"free {free:.2f} of L0)")
                                  if grips else "walls")
                                 + (f"; sliding, rolling, torsion {info['limits']['limits']} (E7)"
                                    if info.get("limits") else "")),
                     "peak_F": info["peak_F"],
                     "peak_Dx": info["peak_Dx"],
                     "F02_over_peak": f02 / info["peak_F"] if f02 is not None and info["peak_F"] else None,
                     "free_fraction": free, "strain_2x_from_Dx": persistent_from(info["records"], 2.0 / free),
                     "strain_at_peak": (at_peak["max_strain_over_affine"] * free if at_peak["max_strain_over_affine"]
                                        else None),
                     "strain_at_peak_where_d0": at_peak["at_d0"],
                     "strain_at_02": (at_02["max_strain_over_affine"] * free if at_02["max_strain_over_affine"]
                                      else None),
                     "strain_at_02_where_d0": at_02["at_d0"], "record_02_Dx": at_02["Dx"],
                     "record_Dx": at_peak["Dx"], "measured": at_peak["measured"], "affine": at_peak["affine"],
                     "max_tensile_measured": max(r["measured"]["tensile"] for r in info["records"]),
                     "max_tensile_affine": max(r["affine"]["tensile"] for r in info["records"])})
    walls = {(r["sinter"], r["seed"]): r["peak_F"] for r in rows if r["loading"] == "walls"}
    tested = [r["peak_F"] for r in rows if r["loading"] == "walls" and r["sinter"] == 0.02 and r["seed"] == 1]
    for r in rows:  # a grips run's peak over its own sample's through the walls, and over the tested sample's
        base = walls.get((r["sinter"], r["seed"]))
        r["peak_over_walls"] = r["peak_F"] / base if base and r["loading"] != "walls" else None
        r["peak_over_tested"] = r["peak_F"] / tested[0] if tested and r["loading"] != "walls" else None
    return sorted(rows, key=lambda r: (r["sinter"], r["seed"], r["loading"] != "walls"))  # E4's beside E3's


def e56(tree, one):
    """Rows of E5 and E6: every variant run in variants/<sample>/ with the E1 run of its sample,
    amplitude and period (``one``: e1's rows) beside it."""
    rows = []
    for sample, folder in VARIANT_SAMPLES.items():
        d = os.path.join(tree, "variants", sample)
        for name in sorted(os.listdir(d)) if os.path.isdir(d) else ():
            if not (name.endswith(".json") and "-tension-Dx" in name and not name.startswith("fig")):
                continue
            r = dict(_cyclic_row(d, name), sample=sample, variant=name.split("-tension-")[0])
            base = next((b for b in one if b["sample"] == folder and b["amplitude"] == r["amplitude"]
                         and b["period"] == r["period"]), None)
            r["E1"] = {k: base[k] for k in ("first_peak", "first_peak_Dx", "turnaround_over_first", "second_over_first",
                                            "later_spread")} if base else None
            r["peak_over_E1"] = r["first_peak"] / base["first_peak"] if base else None
            r["contact_pull_ratio"] = pull_ratio(r["kc_over_kp"]) if r["kc_over_kp"] is not None else None
            rows.append(r)
    return rows


def _f(x, fmt="{:.3g}"):
    return "–" if x is None else fmt.format(x)


def markdown(one, two, label, three=(), five_six=()):
    md = [f"# The tension branch decided by experiment ({label})", "",
          "Generated by `python3 -m mesostudies.tablet.experiments` from the committed runs; forces F/(kp d0), "
          "tension negative; Dx in d0, > 0 in tension.", "",
          "## E1: cyclic tension, tested sample (d0 p_s/kp 0.02), intermediate (0.05) and deep-sintered (0.1)", "",
          "| sample | d0 p_s/kp | Dx | period [t_w] | first peak | at Dx | F at the first turn / first peak | cycles "
          "2-4 peaks | spread of 2-4 / their mean | spread of 2-4 / first peak | cycle 2 / first |",
          "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in one:
        md.append(f"| {r['sample']} | {r['sinter']:g} | {r['amplitude']:g} | {r['period']:g} | {r['first_peak']:.4f} | "
                  f"{r['first_peak_Dx']:.3f} | "
                  f"{_f(r['turnaround_over_first'], '{:.2f}')} | " + ", ".join(f"{x:.4f}" for x in r["later_peaks"])
                  + f" | {_f(r['later_spread'], '{:.1%}')} | {_f(r['later_spread_of_first'], '{:.1%}')} | "
                  f"{_f(r['second_over_first'], '{:.2f}')} |")
    md += ["", "## E2: the sintering-stress sweep (the chosen preparation; one row per realization)", "",
           "| d0 p_s/kp | seed | L0 vs paper | peak tension (magnitude) | peak Dx | F(0.2)/F_peak | first gap Dx | "
           "last chain Dx | crack plane at Dx 0.81 from the nearer wall [d0] | affine peak Dx | affine F(0.2)/F_peak |",
           "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in two:
        md.append(f"| {r['sinter']:g} | {r['seed']} | {_f(r['L0_vs_paper'], '{:+.2%}')} | {r['peak_tension']:.4f} | "
                  f"{r['peak_Dx']:.3f} | {_f(r['F02_over_peak'], '{:.2f}')} | {_f(r['first_gap_Dx'], '{:.2f}')} | "
                  f"{_f(r['last_chain_Dx'], '{:.2f}')} | {_f(r['crack_from_wall_d0'], '{:.2f}')} | "
                  f"{_f(r['affine_peak_Dx'], '{:.3f}')} | {_f(r['affine_F02_over_peak'], '{:.2f}')} |")
    if three:
        md += ["", "## E3: non-affinity up to the peak (the pull's first part; `profile/`), and E4's "
                   "pulls through grips", "",
               "Through grips of thickness t only L0 - 2 t d0 is free to stretch: the local strains are given against "
               "the free part's even stretch (the recorded ratio times (L0 - 2 t d0)/L0); the affine contact counts "
               "remain those of a stretch Dx d0/L0 of every contact outside the grips, which understates the free "
               "part's (free fraction in the loading column). In brackets, for grips: the peak's Dx over the free "
               "fraction, and the force at Dx = 0.2 times the free fraction over the peak (the walls' Dx of the same "
               "strain of the free part); after the peak, its ratio to the same sample's peak through the walls and to "
               "the tested sample's (seed 1, walls).", "",
               "| sample | d0 p_s/kp | seed | loaded by | peak | peak Dx | F(0.2)/F_peak | largest local strain / "
               "affine at the peak (where, from the left face [d0]) | the same at Dx = 0.2 (where) | stays >= 2x "
               "affine from Dx | on -kc delta at the peak: measured / affine | open at the peak: measured / affine "
               "| most on -kc delta: measured / affine |",
               "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in three:
            grip = r["loading"] != "walls"
            ratio = (f" ({r['peak_over_walls']:.2f} x walls, {r['peak_over_tested']:.2f} x tested)"
                     if r.get("peak_over_walls") else "")
            md.append(f"| {r['sample']} | {r['sinter']:g} | {r['seed']} | {r['loading']} | {r['peak_F']:.4f}{ratio} "
                      f"| {r['peak_Dx']:.3f}"
                      + (f" ({r['peak_Dx_free']:.3f})" if grip else "") + " | "
                      f"{_f(r['F02_over_peak'], '{:.2f}')}"
                      + (f" ({_f(r['F02_free_over_peak'], '{:.2f}')})" if grip else "")
                      + f" | {_f(r['strain_at_peak'], '{:.1f}')} "
                      f"({_f(r['strain_at_peak_where_d0'], '{:.1f}')}) | {_f(r['strain_at_02'], '{:.1f}')} "
                      f"({_f(r['strain_at_02_where_d0'], '{:.1f}')}) | {_f(r['strain_2x_from_Dx'], '{:.3f}')} | "
                      f"{r['measured']['tensile']:.1%} / {r['affine']['tensile']:.1%} | "
                      f"{r['measured']['open']:.1%} / {r['affine']['open']:.1%} | "
                      f"{r['max_tensile_measured']:.1%} / {r['max_tensile_affine']:.1%} |")
    if five_six:
        md += ["", "## E4, E5 and E6: the same states loaded through grips of glued particles (grips1, grips2: 1 "
                   "and 2 d0), kc/kp 0.5 "
               "(kc0.5) and cycles back to the start's force (force-return); in brackets the E1 run of the same "
               "sample, amplitude and period; for grips, after Dx the walls' Dx that strains the free part as much", "",
               "| sample | variant | Dx | period [t_w] | first peak | over E1's | a contact's largest pull over E1's "
               "(k2 = k1 to kp) | at Dx | F at the first turn / first peak "
               "| cycle 2 / first | spread of 2-4 / their mean | returns ended at Dx |",
               "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in five_six:
            b = r["E1"] or {}
            amp = f"{r['amplitude']:g}" + (f" (walls' {r['free_amplitude']:.3f})" if r.get("free_amplitude") else "")
            md.append(f"| {r['sample']} | {r['variant']} | {amp} | {r['period']:g} | "
                      f"{r['first_peak']:.4f} ({_f(b.get('first_peak'), '{:.4f}')}) | "
                      f"{_f(r['peak_over_E1'], '{:.2f}')} | "
                      + ("–" if r["contact_pull_ratio"] is None else
                         f"{r['contact_pull_ratio'][0]:.2f} – {r['contact_pull_ratio'][1]:.2f}") + " | "
                      f"{r['first_peak_Dx']:.3f} ({_f(b.get('first_peak_Dx'), '{:.3f}')}) | "
                      f"{_f(r['turnaround_over_first'], '{:.2f}')} ({_f(b.get('turnaround_over_first'), '{:.2f}')}) | "
                      f"{_f(r['second_over_first'], '{:.2f}')} ({_f(b.get('second_over_first'), '{:.2f}')}) | "
                      f"{_f(r['later_spread'], '{:.1%}')} ({_f(b.get('later_spread'), '{:.1%}')}) | "
                      + (", ".join(f"{x:.3f}" for x in r["returns_at_Dx"]) if r["returns_at_Dx"] else "–") + " |")
    return "\n".join(md) + "\n"


def main(argv):
    if len(argv) != 1 or not os.path.isdir(argv[0]):
        sys.exit("usage: python3 -m mesostudies.tablet.experiments TREE (a campaign tree: chosen/, deep/, factors/)")
    tree = argv[0]
    one, two = e1(tree), e2(tree)
    three, five_six = e3(tree), e56(tree, one)
    out = os.path.join(tree, "branch")
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "experiments.json"), "w") as f:
        json.dump({"E1": one, "E2": two, "E3": three, "E5_E6": five_six}, f, indent=1)
        f.write("\n")
    with open(os.path.join(out, "experiments.md"), "w") as f:
        f.write(markdown(one, two, tree.rstrip("/"), three, five_six))
    print(markdown(one, two, tree.rstrip("/"), three, five_six))


if __name__ == "__main__":
    main(sys.argv[1:])
