"""The statements of Appendix F for every finished repeat (issue 60 item 2): per perturbation factor an
overlay of campaigns/tablet/chosen in which the tested sample's tension run at each repeated amplitude
and period is replaced by the repeat's (repeat-x<f>-tension-Dx<a>-P<period>), then
mesostudies.tablet.statements.statements(overlay). Prints the chosen campaign's verdicts and each
factor's, for the statements named (default 10 11 12 15; 'all' for every one), and writes
verdicts.json into the repeats' working folder (REPEATS, default results/repeats). The repeats are
read from the committed campaign (campaigns/tablet/repeats, flat) and from the lanes' run bundles
(REPEATS + lane, lane in LANES: <folder>/runs/<name>/; a bundle found in both is the lane's). Run from
the repository:

    PYTHONPATH=py:studies python3 studies/scripts/tablet_repeats.py [10 12 15 | all]
"""
import glob
import json
import os
import re
import shutil
import sys

from mesostudies.tablet import statements as S

CHOSEN = os.path.abspath("campaigns/tablet/chosen")
COMMITTED = os.path.abspath("campaigns/tablet/repeats")
HERE = os.path.abspath(os.environ.get("REPEATS", "results/repeats"))
OVERLAY = os.path.join(HERE, "overlay")
LANES = ("", "2", "3", "-c", "-d")  # REPEATS + lane: the lanes' working folders
NAME = re.compile(r"repeat-x([0-9.]+)-(tension|compression)-Dx([0-9.]+)-P([0-9.]+)\.json$")
PARTS = (".json", ".csv", "-branches.csv")  # a run's files


def finished():
    """{factor: {(mode, amplitude, period): [its files]}} of the complete repeats (a run's JSON is written last)."""
    out = {}
    found = sorted(glob.glob(os.path.join(COMMITTED, "repeat-x*.json")))
    found += [j for lane in LANES for j in sorted(glob.glob(os.path.join(HERE + lane, "runs", "repeat-x*", "*.json")))]
    for js in found:
        m = NAME.match(os.path.basename(js))
        if m:
            stem = js[:-len(".json")]
            out.setdefault(m.group(1), {})[(m.group(2), float(m.group(3)), float(m.group(4)))] = [
                stem + e for e in PARTS]
    return out


def pulls():
    """{factor: the pull's CSV} of the complete pull repeats (repeat-x<f>-pull: committed, or a lane's bundle)."""
    found = sorted(glob.glob(os.path.join(COMMITTED, "repeat-x*-pull.json")))
    found += [j for lane in LANES for j in sorted(glob.glob(os.path.join(HERE + lane, "repeat-x*-pull", "*.json")))]
    out = {}
    for js in found:
        m = re.match(r"repeat-x([0-9.]+)-pull\.json$", os.path.basename(js))
        if m:
            out[m.group(1)] = js[:-len(".json")] + ".csv"
    return out


def overlay(factor, runs):
    """campaigns/tablet/chosen with the repeats' runs in place of its tension runs at their amplitudes and periods."""
    d = os.path.join(OVERLAY, "x" + factor)
    shutil.rmtree(d, ignore_errors=True)
    os.makedirs(d)
    for side in ("factors", "branch"):  # statements reads ../factors, ../branch
        link = os.path.join(OVERLAY, side)
        if not os.path.lexists(link):
            os.symlink(os.path.join(CHOSEN, "..", side), link)
    replaced = {f"{m}-Dx{a:g}-P{p:g}{e}" for m, a, p in runs for e in PARTS}
    for f in os.listdir(CHOSEN):
        if f not in replaced:
            os.symlink(os.path.join(CHOSEN, f), os.path.join(d, f))
    for files in runs.values():
        for f in files:
            os.symlink(f, os.path.join(d, re.sub(r"^repeat-x[0-9.]+-", "", os.path.basename(f))))
        # statement 11 reads a run's CSV by the name in its JSON (the repeat's own): that name too
        os.symlink(files[1], os.path.join(d, os.path.basename(files[1])))
    return d


def _rate_at(table, amplitude=0.3):
    """The 4x slower run (one, the campaign's) against the fast runs at ``amplitude`` (the campaign's and
    the repeats'), cycle by cycle: its peak over their mean, their range over it, how far beyond the
    nearest fast run it lies, and z = (slow - mean)/sd (one new draw: |z| > 2.78 lies outside the 95 %
    prediction interval of six)."""
    import statistics
    slow = S.runs_of(CHOSEN)[("tension", amplitude, 1920.0)][1]
    fast = [S.runs_of(CHOSEN if name == "chosen" else os.path.join(OVERLAY, name))[("tension", amplitude, 480.0)][1]
            for name, row in table.items() if name == "chosen" or amplitude in row["amplitudes"] and name != "x1"]
    print(f"== the slow run at {amplitude} against {len(fast)} fast runs: cycle, slow/mean - 1, fast range/|mean|, "
          "beyond the nearest fast run, z")
    for k in range(1, len(slow)):
        vals = [f[k]["peak"] for f in fast]
        m, sd = statistics.mean(vals), statistics.stdev(vals)
        near = min(abs(slow[k]["peak"] / v - 1) for v in vals)
        inside = min(vals) <= slow[k]["peak"] <= max(vals)
        where = "inside" if inside else f"{100 * near:.1f} % beyond"
        print(f"  cycle {k + 1}: {100 * (slow[k]['peak'] / m - 1):+.1f} %  "
              f"{100 * (max(vals) - min(vals)) / abs(m):.1f} %  {where}  z {(slow[k]['peak'] - m) / sd:+.1f}")


def _p1920(table):
    """The numbers the 1920 t_w runs decide, per run set that repeated one (and the campaign's): the retrace
    (range of cycles 2-4 peaks over the first peak / over their mean) at 0.1 (#10: one branch when both are
    at most 5 %), 0.2 (#15's 1920 t_w entry) and 0.3, and #12's 1920 t_w ratio (0.2's retrace over the smaller
    amplitudes' largest; > 1.5). Returns {name: numbers}; each spread over the sets that repeated it."""
    print("== P1920 numbers: retrace 0.1, 0.2, 0.3 (first/mean), #12 ratio at 1920")
    out, spread = {}, {}
    for name, row in table.items():
        if name != "chosen" and not row["slow_amplitudes"]:
            continue
        runs = S.runs_of(CHOSEN if name == "chosen" else os.path.join(OVERLAY, name))
        r = {a: S.retrace(runs[("tension", a, 1920.0)][1]) for a in (0.025, 0.05, 0.1, 0.2, 0.3)}
        ratio = r[0.2][1] / max(r[a][1] for a in (0.025, 0.05, 0.1))
        out[name] = {"retrace": {str(a): r[a] for a in (0.1, 0.2, 0.3)}, "ratio_12": ratio}
        print(f"  {name:12s} " + "  ".join(f"{100 * r[a][0]:5.2f}/{100 * r[a][1]:5.2f} %" for a in (0.1, 0.2, 0.3))
              + f"  {ratio:5.2f}")
        repeated = row["slow_amplitudes"]
        for k, v, a in (("retrace_0.1_mean", r[0.1][1], 0.1), ("retrace_0.2_first", r[0.2][0], 0.2),
                        ("retrace_0.2_mean", r[0.2][1], 0.2), ("retrace_0.3_mean", r[0.3][1], 0.3),
                        ("ratio_12", ratio, 0.2)):
            if a in repeated:
                spread.setdefault(k, []).append(v)
    for k, v in spread.items():
        print(f"  {k} at 1920: min {min(v):.4g}, max {max(v):.4g} over {len(v)} (chosen included)")
    return out


def _compression(table):
    """Statements 22-24 (the compression cycles' elasticity, plastic onset, retrace at 0.2) per run set that
    repeated compression cycles, with the campaign's: each verdict and its numbers."""
    print("== compression: #22, #23, #24 per run set that repeated them")
    for name, row in table.items():
        if name == "chosen" or row.get("compression"):
            for st in row["statements"]:
                if st["n"] in (22, 23, 24):
                    print(f"  {name:12s} #{st['n']} {st['verdict']}  {st['project']}")


def _pulls():
    """Statement 21 (the tension branch's extent, ~ d0/5 within a factor 1.5) on each pull repeat and on the
    campaign's pull read to the same end: peak, where the tension stays below half and a third of it for
    good, and the verdict (both inside 0.133-0.3: ✓, one: ◐, none: ✗). Returns {name: numbers}."""
    out = {}
    found = pulls()
    if not found:
        return out
    with open(next(iter(found.values()))[:-len(".csv")] + ".json") as f:
        until = json.load(f)["until"]
    print(f"== #21 on the pulls to Dx = {until:g}: peak (Dx), below half / a third for good from, verdict")
    inside = [0.2 / S.APPROX, 0.2 * S.APPROX]
    for name, csv in [("chosen", os.path.join(CHOSEN, "fig17.csv"))] + [("x" + k, v) for k, v in sorted(found.items())]:
        rows = [r for r in S.read_csv(csv) if r[1] <= until]
        peak = min(rows, key=lambda r: r[2])
        branch = S.tension_extent(os.path.dirname(csv), os.path.basename(csv), until)
        n_in = sum(1 for x in branch if inside[0] <= x <= inside[1]) if branch else 0
        verdict = "–" if not branch else ("✓" if n_in == 2 else ("◐" if n_in else "✗"))
        out[name] = {"peak": peak[2], "peak_Dx": peak[1], "half": branch and branch[0],
                     "third": branch and branch[1], "verdict": verdict}
        print(f"  {name:12s} {-peak[2]:.4f} ({peak[1]:.3f})  {branch[0]:.3f} / {branch[1]:.3f}  {verdict}"
              if branch else f"  {name:12s} –")
    return out


def main(argv):
    numbers = None if argv == ["all"] else [int(x) for x in argv] or [10, 11, 12, 15]
    table = {"chosen": {"amplitudes": [0.1, 0.2, 0.3], "slow_amplitudes": [0.1, 0.2, 0.3],
                        "statements": S.statements(CHOSEN)}}
    for factor, runs in sorted(finished().items(), key=lambda kv: abs(float(kv[0]) - 1)):
        table["x" + factor] = {"amplitudes": sorted(a for m, a, p in runs if (m, p) == ("tension", 480.0)),
                               "slow_amplitudes": sorted(a for m, a, p in runs if (m, p) == ("tension", 1920.0)),
                               "compression": sorted(a for m, a, p in runs if m == "compression"),
                               "statements": S.statements(overlay(factor, runs))}
    for name, row in table.items():
        slow = f", at 1920 t_w {row['slow_amplitudes']}" if row["slow_amplitudes"] and name != "chosen" else ""
        slow += f", compression {row['compression']}" if row.get("compression") else ""
        print(f"== {name} (repeated amplitudes {row['amplitudes']}{slow})")
        for s in row["statements"]:
            if numbers is None or s["n"] in numbers:
                print(f"  #{s['n']} {s['verdict']}  {s['project']}")
    # The numbers the P480 runs decide, per run set: the retrace (range of cycles 2-4 peaks over the first
    # peak / over their mean; one branch: both <= 5 %) at 0.1 and 0.2 (#15's 480 t_w entry; #10 itself reads
    # the 1920 t_w run), and #12's 480 t_w ratio (0.2's over the smaller amplitudes' largest; > 1.5).
    print("== P480 numbers: retrace 0.1 (first/mean), retrace 0.2 (first/mean), #12 ratio at 480, "
          "cycle-2 peaks 0.1/0.2, retrace 0.3 (first/mean), #16's later-cycle change at 0.3")
    spread = {}
    for name, row in table.items():
        d = CHOSEN if name == "chosen" else os.path.join(OVERLAY, name)
        runs = S.runs_of(d)
        r = {a: S.retrace(runs[("tension", a, 480.0)][1]) for a in (0.025, 0.05, 0.1, 0.2)}
        ratio = r[0.2][1] / max(r[a][1] for a in (0.025, 0.05, 0.1))
        c2 = [runs[("tension", a, 480.0)][1][1]["peak"] for a in (0.1, 0.2)]
        row["p480"] = {"retrace_0.1": r[0.1], "retrace_0.2": r[0.2], "ratio_12": ratio, "cycle2_peak": c2}
        # at 0.3: #15's 480 t_w entry and #16's later-cycle change, 1920 t_w against 480 t_w (the campaign's
        # 1920 t_w run, not repeated)
        slow, fast = runs[("tension", 0.3, 1920.0)][1], runs[("tension", 0.3, 480.0)][1]
        r3 = S.retrace(fast)
        later = max(abs(y["peak"] / x["peak"] - 1) for x, y in zip(fast[1:], slow[1:]))
        row["p480"].update({"retrace_0.3": r3, "later_change_16": later})
        print(f"  {name:12s} {100 * r[0.1][0]:5.2f}/{100 * r[0.1][1]:5.2f} %  "
              f"{100 * r[0.2][0]:5.2f}/{100 * r[0.2][1]:5.2f} %  {ratio:5.2f}  {c2[0]:.4f}/{c2[1]:.4f}  "
              f"{100 * r3[0]:5.2f}/{100 * r3[1]:5.2f} %  {100 * later:5.1f} %")
        for k, v, a in (("retrace_0.1_mean", r[0.1][1], 0.1), ("retrace_0.2_mean", r[0.2][1], 0.2),
                        ("ratio_12", ratio, 0.2), ("retrace_0.3_first", r3[0], 0.3), ("retrace_0.3_mean", r3[1], 0.3),
                        ("later_change_16_at_0.3", later, 0.3)):
            if name == "chosen" or a in row["amplitudes"]:  # a set that did not repeat a is the campaign's there
                spread.setdefault(k, []).append(v)
    for k, v in spread.items():
        print(f"  {k}: min {min(v):.4g}, max {max(v):.4g} over {len(v)} (chosen included)")
    _rate_at(table)
    if any(row["slow_amplitudes"] for name, row in table.items() if name != "chosen"):
        for name, numbers in _p1920(table).items():
            table[name]["p1920"] = numbers
    if any(row.get("compression") for row in table.values()):
        _compression(table)
    table["pulls_21"] = _pulls()
    os.makedirs(HERE, exist_ok=True)
    with open(os.path.join(HERE, "verdicts.json"), "w") as f:
        json.dump(table, f, indent=1, ensure_ascii=False)


if __name__ == "__main__":
    main(sys.argv[1:])
