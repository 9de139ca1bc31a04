"""The study's page from its summary (plain Python):

    python3 -m mesostudies.agglomerate.report DIR      # DIR/agglomerate-vs-meso.json -> DIR/summary.md

Every number docs/agglomerate.md quotes is on this page.
"""
import json
import os
import sys

D0_MM = 0.01     # the primaries' mean diameter [mm] (primaries.D0; this page is pure Python)
KP = 5e6         # their kp [N/m]; forces are given over kp d0
KP_D0 = KP * D0_MM * 1e-3   # kp d0 [N]
STUDY_FORCE = 1e3           # the study's force unit, mg mm/us^2, in N
DISSIPATED = ("mesoPlastic", "mesoViscous", "mesoSliding", "mesoRolling", "mesoTorsion", "mesoAdhesive")
STORED = ("mesoElastic", "mesoSprings")


def _f(x, fmt="{:.3g}"):
    return "–" if x is None else fmt.format(x)


def _cycles(cycles, rate_check):
    md = ["| run | cap speed [m/s] | amplitudes beyond the touch [d0] | unloaded to [d0 below the touch] "
          "| force at each loaded turn, F/(kp d0) | most tensile force of each unloading | mean tension 0.05 - 0.2 d0 "
          "below the touch, each unloading | mean force of each loading at the first touch's delta (+- 0.005 d0) |",
          "|---|---|---|---|---|---|---|---|"]
    scale = KP_D0 / STUDY_FORCE  # kp d0 in the study's force unit
    for name, c in cycles.items():
        md.append(f"| {name} | {c['speed_per_cap_m_s']:g} | " + ", ".join(f"{a:g}" for a in c.get("amplitudes_d0", []))
                  + " | " + ", ".join(f"{b:.2g}" for b in c.get("unload_below_touch_d0", [])) + " | "
                  + ", ".join(f"{x / scale:.4f}" for x in c["turn_forces"])
                  + " | " + ", ".join(_f(x / scale if x is not None else None, "{:.4f}") for x in c["pull_offs"])
                  + " | " + ", ".join(_f(x / scale if x is not None else None, "{:.5f}")
                                      for x in c.get("tension_plateaus", []))
                  + " | " + ", ".join(_f(x / scale if x is not None else None, "{:+.4f}")
                                      for x in c.get("loading_at_touch", [])) + " |")
    for name, r in rate_check.items():
        md.append("")
        md.append(f"Rate check: {name} differs from the slowest run by at most {_f(r, '{:.1%}')} of the slowest run's "
                  "largest force (turn forces and mean tensions; the most tensile values ring and are not compared).")
    return md


def _fit_table(fit):
    md = [f"{fit['n_points']} points; residual rms {fit['rms_relative']:.3f} and largest {fit['max_relative']:.3f} "
          f"of the force scale max |F| = {fit['force_scale'] / KP_D0:.4f} kp d0.", "",
          "| parameter | value | 95 % interval | determined |", "|---|---|---|---|"]
    for k in list(fit["free"]):
        lo, hi = fit["ci95"][k]
        md.append(f"| {k} | {fit[k]:.4g} | [{_f(lo, '{:.4g}')}, {_f(hi, '{:.4g}')}] | "
                  f"{'no' if k in fit['undetermined'] else 'yes'} |")
    return md + ["", "What the cycles cannot determine:", ""] + [f"- {t}" for t in fit["statements"]]


def markdown(s):
    prep, fit = s["preparation"], s["fit"]
    md = ["# An agglomerate as a meso-particle: the results", "",
          "Written by `python3 -m mesostudies.agglomerate.report` from `agglomerate-vs-meso.json`.", "",
          "## The agglomerates", "",
          f"Carved with radius {prep['carve_radius_d0']:.3f} d0 from the sintered block; {prep['removed_loose']} "
          "particles cut loose were removed.", "",
          "| agglomerate | primaries | R [d0] | mass [kg] | core solid fraction | coordination "
          "| rattlers | mean deltaMax/deltaMax^p |",
          "|---|---|---|---|---|---|---|---|"]
    for k, a in enumerate(prep["agglomerates"]):
        md.append(f"| {k} | {a['n']} | {a['radius_d0']:.3f} | {a['mass'] * 1e-6:.4g} | "
                  f"{a['solid_fraction_core']:.3f} | "
                  f"{a['coordination']:.2f} | {a['rattlers']} | {_f(a['mean_depth'], '{:.2f}')} |")
    md += ["", "## The cycles and the rate check", ""] + _cycles(s["cycles"], s["rate_check"])
    md += ["", f"## The fit (run {s.get('fitted_run', '–')})", ""] + _fit_table(fit)
    w = s.get("fit_widest_run")
    if w:
        md += ["", f"Fitted to {w['run']} instead (all amplitudes, the faster run): k1 = {w['k1']:.4g} "
                   f"[{_f(w['ci95']['k1'][0], '{:.4g}')}, {_f(w['ci95']['k1'][1], '{:.4g}')}], kp = {w['kp']:.4g}, "
                   f"phiF = {w['phiF']:.4g}, kc = {w['kc']:.3g} "
                   f"(undetermined: {', '.join(w['undetermined']) or 'none'}); "
                   f"residual rms {w['rms_relative']:.3f}, largest {w['max_relative']:.3f} of its force scale."]
    md += ["", "## Collisions", "",
           "e of the agglomerates (the two largest fragments' centres of mass, along the approach x, and along the "
           "impulse of the normal forces they exchanged), of two meso-particles of the fitted "
           "law (YADE) and of the closed form; the mass broken off; the contact time; the press (the largest "
           "meso-overlap beyond the one at the first contact) and the largest normal force between them; "
           "where the impact's kinetic energy went, over it (the centres of mass' motion, the particles' motion "
           "about them, the law's stored energies' change, its dissipation).", "",
           "| v [m/s] | e agglomerates | e along the normal impulse | e meso pair | e closed form | stuck | broken off "
           "| contact time [us] | press [d0] | largest force F/(kp d0) | centres of mass | internal motion | stored "
           "| dissipated |",
           "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for k, v in enumerate(s["speeds"]):
        en = s["energy_over_impact"][k]
        stored = sum(en.get(n, 0.0) for n in STORED)
        lost = sum(en.get(n, 0.0) for n in DISSIPATED)
        md.append(f"| {v:g} | {s['e_agglomerate'][k]:.3f} | "
                  f"{_f((s.get('e_normal') or [None] * len(s['speeds']))[k], '{:.3f}')} | "
                  f"{s['e_meso'][k]:.3f} | {s['e_theory'][k]:.3f} | "
                  f"{'yes' if s['stuck'][k] else 'no'} | {s['fragmented'][k]:.3f} | "
                  f"{_f(s['contact_time'][k], '{:.4f}')} | "
                  f"{_f((s.get('press_d0') or [None] * len(s['speeds']))[k], '{:.3g}')} | "
                  f"""{_f(None if not s.get('largest_normal_force') or s['largest_normal_force'][k] is None
                          else s['largest_normal_force'][k] / (KP_D0 / STUDY_FORCE), '{:.3g}')} | """
                  f"{en['centres_of_mass']:.3f} | {en['internal_kinetic']:.3f} | {stored:.3f} | {lost:.3f} |")
    vis = s.get("meso_viscous")
    if vis:
        md += ["", f"The meso-particles with viscosity gammaN = {vis['gammaN']:.4g} kg/s, "
                   "fitted to the agglomerates' e at "
                   f"{vis['fitted_at_m_s']:g} m/s (e = {vis['e_at_fit']:.3f}):", "",
               "| v [m/s] | e agglomerates | e meso pair, gammaN fitted | difference |", "|---|---|---|---|"]
        for k, v in enumerate(s["speeds"]):
            md.append(f"| {v:g} | {s['e_agglomerate'][k]:.3f} | {vis['e_meso'][k]:.3f} | "
                      f"{abs(s['e_agglomerate'][k] - vis['e_meso'][k]):.3f} |")
    whole = [k for k, b in enumerate(s["fragmented"]) if b < 0.01]
    if whole:
        k = max(whole, key=lambda k: abs(s["e_agglomerate"][k] - s["e_meso"][k]))
        md += ["", f"Largest |e agglomerates - e meso pair| without fragmentation (< 1 % of the mass broken off): "
                   f"{abs(s['e_agglomerate'][k] - s['e_meso'][k]):.3f} at {s['speeds'][k]:g} m/s."]
        if vis:
            k = max(whole, key=lambda k: abs(s["e_agglomerate"][k] - vis["e_meso"][k]))
            md += ["", f"With gammaN fitted, the largest difference without fragmentation: "
                       f"{abs(s['e_agglomerate'][k] - vis['e_meso'][k]):.3f} at {s['speeds'][k]:g} m/s"]
            rb = [k for k in whole if not s["stuck"][k]]
            if rb:
                k = max(rb, key=lambda k: abs(s["e_agglomerate"][k] - vis["e_meso"][k]))
                md[-1] += (f"; over the rebounds: {abs(s['e_agglomerate'][k] - vis['e_meso'][k]):.3f} at "
                           f"{s['speeds'][k]:g} m/s.")
            else:
                md[-1] += "."
    md += _directions(s) + _adhesion(s)
    for w in (s.get("walls") or {}).values():
        md += _wall(w)
    return "\n".join(md) + "\n"


def _directions(s):
    dirs = s.get("directions") or []
    if not dirs:
        return []
    md = ["", "## Other approach directions", "",
          "The same two agglomerates meeting with other faces: the second placed beside the first along a direction "
          "drawn on the sphere (its contacts' history moved with it). The faces that meet are rough and tilted to "
          "the approach, so the rebound turns sideways and the agglomerates spin. First table: e along the "
          "normal forces' impulse (the rough contact's mean normal), with that normal's tilt to the approach in "
          "brackets; (s) stuck, (b) >= 1 % of the mass broken off. The spread is the largest minus the smallest of "
          "these e over the directions where they rebound. Second table: e along the approach, the deflection of the "
          "relative velocity after from it, and the frictional impulse over the normal one (or the mass broken "
          "off where they stick).", "",
          "| v [m/s] | x | " + " | ".join(f"direction {d['index']}" for d in dirs) + " | spread of rebounds |",
          "|---|---|" + "---|" * len(dirs) + "---|"]
    x = {"index": "x", "e": s["e_agglomerate"], "broken_mass_fraction": s["fragmented"],
         **{k: s[k] for k in ("e_normal", "tilt_deg", "stuck", "deflection_deg", "friction_over_normal_impulse")}}
    runs = [x] + dirs

    def flags(stuck, broken):
        return (" (s)" if stuck else "") + (" (b)" if broken is not None and broken >= 0.01 else "")
    for k, v in enumerate(s["speeds"]):
        cells, rebounds = [], []
        for r in runs:
            en, tilt, stuck = r["e_normal"][k], r["tilt_deg"][k], r["stuck"][k]
            if en is None and not stuck:
                cells.append("–")
                continue
            cells.append(("0" if stuck else f"{en:.3f}") + (f" ({tilt:.0f}°)" if tilt is not None else "")
                         + flags(stuck, r["broken_mass_fraction"][k]))
            if not stuck and en is not None:
                rebounds.append(en)
        spread = max(rebounds) - min(rebounds) if len(rebounds) > 1 else None
        md.append(f"| {v:g} | " + " | ".join(cells) + f" | {_f(spread)} |")
    md += ["", "| v [m/s] | " + " | ".join(f"{'x' if r['index'] == 'x' else 'direction ' + str(r['index'])}: "
                                           "e along the approach, deflection, friction/normal" for r in runs) + " |",
           "|---|" + "---|" * len(runs)]
    for k, v in enumerate(s["speeds"]):
        md.append(f"| {v:g} | " + " | ".join(
            f"stuck, {r['broken_mass_fraction'][k]:.3f} broken off" if r["stuck"][k]
            else f"{r['e'][k]:.3f}, {_f(r['deflection_deg'][k], '{:.0f}')}°, "
                 f"{_f(r['friction_over_normal_impulse'][k], '{:.2f}')}"
            for r in runs) + " |")
    md += ["", "Directions: " + "; ".join(f"{d['index']}: (" + ", ".join(f"{x:.3f}" for x in d["axis"]) + ")"
                                          for d in dirs) + "."]
    return md


def _adhesion(s):
    ad = s.get("adhesion") or []
    if not ad:
        return []
    md = ["", "## The cycles' tension as the law's non-contact force", "",
          "fa from the mean tension 0.05 - 0.2 d0 below the touch of each unloading of the fitted run; the shortest "
          "tail the cycles allow (from the fitted law's contact end to where the unloading turned), kca = fa/tail; "
          "'jumpIn' (-fa in contact, the tail after it). The closed form's e with it, and the speed below which the "
          "meso-particle pair sticks:", "",
          "| after loading to [d0] | fa [N] | fa/(kp d0) | tail [d0] | kca [N/m] | pair sticks below [m/s] "
          "| smallest fa on this tail that sticks the pair at the slowest speed [N] |",
          "|---|---|---|---|---|---|---|"]
    for a in ad:
        # inf: sticks at every speed tried
        md.append(f"| {a['after_d0']:g} | {a['fa_N']:.3g} | {a['fa_N'] / KP_D0:.3g} | "
                  f"{a['tail_m'] / (D0_MM * 1e-3):.3f} | {a['kca_N_m']:.4g} | {a['sticks_below_m_s']:.3g} | "
                  f"{_f(a.get('fa_sticking_slowest_N'), '{:.2g}')} |")
    md += ["", "The fitted law's largest overlap in the pair's collision (closed form) is counted from its contact's "
               "start, which lies (touch - shift)/d0 below the cycles' first touch.", "",
           "| v [m/s] | e agglomerates | fitted law's largest overlap [d0] | "
           + " | ".join(f"e closed form, fa after {a['after_d0']:g} d0" for a in ad) + " |",
           "|---|---|---|" + "---|" * len(ad)]
    for k, v in enumerate(s["speeds"]):
        md.append(f"| {v:g} | {s['e_agglomerate'][k]:.3f} | "
                  f"{_f((s.get('overlap_theory_d0') or [None] * len(s['speeds']))[k], '{:.3g}')} | "
                  + " | ".join(f"{a['e_theory'][k]:.3f}" for a in ad) + " |")
    return md


WALLS = {"own": "the primaries' own material (their k, adhesion and friction; "
                "the law's sphere-wall a12 = 2 a_i, twice a primary pair's)",
         "smooth": "the tablet's smooth mould (the primaries' normal law without adhesion or friction)"}


def _wall(w):
    md = ["", f"## One agglomerate against a flat wall: {w['material']}", "",
          f"Agglomerate 0 pressed by its far cap against a fixed wall of {WALLS.get(w['material'], w['material'])}, "
          "force read on the wall; delta = R - (x_wall - x) "
          "of its centre of mass.", ""] + _cycles(w["cycles"], w["rate_check"])
    md += ["", f"The law fitted to {w['fitted_run']} "
               f"(a12 = 2 R = {w['a12_m']:.4g} m, the law's sphere-wall value):", ""]
    md += _fit_table(w["fit"])
    md += ["", "The force at each loaded turn over the pair's at the same amplitude (slowest runs): "
           + ", ".join(f"{r:.2f} at {a} d0" for a, r in w.get("turn_force_over_pair", {}).items()) + "."]
    md += ["", f"Against the pair's fit: k1(wall)/k1(pair) = {w['k1_over_pair']:.3f} (two agglomerates in series "
               f"against one: 2 for linear springs, 2^1.5 = 2.83 for Hertz contacts). The fitted law's contact starts "
               f"{w['law_start_beyond_touch_d0']:+.4f} d0 beyond the first touch (the pair's: "
               f"{w['pair_law_start_beyond_touch_d0']:+.4f} d0).", "",
           "What the pair's fit predicts for the wall cycles, nothing refitted:", "",
           "| wall in the law | rms of the misfit | largest |", "|---|---|---|"]
    for name, p in w["predictions"].items():
        md.append(f"| {name} | {p['rms_relative']:.3f} | {p['max_relative']:.3f} |")
    return md


def main(argv):
    d = argv[0]
    with open(os.path.join(d, "agglomerate-vs-meso.json")) as f:
        s = json.load(f)
    with open(os.path.join(d, "summary.md"), "w") as f:
        f.write(markdown(s))
    print(os.path.join(d, "summary.md"))


if __name__ == "__main__":
    main(sys.argv[1:])
