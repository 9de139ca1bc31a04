# Is the rate dependence of the cracked tension cycles viscosity, or the crack's sensitivity to any
# perturbation? The campaign's tension cycle (480 t_w) run again with its time step changed by 1e-6
# (far below any integration error): the spread of each cycle's peak among these runs is what a
# perturbation alone does; the committed 480 and 1920 t_w runs give the change with the rate.
#   yade -j1 -n -x studies/scripts/tablet_sensitivity.py --out results/tablet --amplitude 0.1 --factor 1.000001
#   python3 studies/scripts/tablet_sensitivity.py --gather results/tablet --docs campaigns/tablet/chosen
#       (writes sensitivity.json there)
import argparse
import glob
import json
import os
import sys

PERIOD, SLOW = 480, 1920  # the campaign's tension periods (crossing times)


def _peaks(path):
    with open(path) as f:
        return json.load(f)["peaks"]


def gather(out, docs):
    """Per amplitude with perturbed runs: each cycle's peak at 480 t_w (committed and perturbed) and
    1920 t_w, the perturbations' largest relative change against the committed run, and the rate's."""
    rows = {}
    for where in sorted(glob.glob(os.path.join(out, "runs", "perturbed-x*-tension-Dx*-P%d" % PERIOD))):
        name = os.path.basename(where)
        path = os.path.join(where, name + ".json")
        if not os.path.exists(path):  # a run still going
            continue
        factor, amp = name.split("-")[1][1:], float(name.split("-Dx")[1].split("-P")[0])
        base = os.path.join(docs, f"tension-Dx{amp:g}-P{PERIOD}.json")
        slow = os.path.join(docs, f"tension-Dx{amp:g}-P{SLOW}.json")
        if not (os.path.exists(base) and os.path.exists(slow)):
            continue
        r = rows.setdefault(f"{amp:g}", {"peaks_P480": _peaks(base), "peaks_P1920": _peaks(slow), "perturbed": {}})
        r["perturbed"][factor] = _peaks(path)
    for r in rows.values():
        b = r["peaks_P480"]
        change = lambda p: [abs(x / y - 1) for x, y in zip(p, b)]  # noqa: E731
        r["perturbation_change"] = [max(c) for c in zip(*(change(p) for p in r["perturbed"].values()))]
        r["rate_change"] = change(r["peaks_P1920"])
        r["rate_over_perturbation_cycles_2_4"] = [x / y if y > 0 else None for x, y in
                                                  zip(r["rate_change"][1:], r["perturbation_change"][1:])]
    return {"period": PERIOD, "slow_period": SLOW, "factor_note": "time step = 3 t_c/50 x factor", "amplitudes": rows}


def main(argv):
    p = argparse.ArgumentParser(prog="tablet_sensitivity.py")
    p.add_argument("--out", default="results/tablet", help="the campaign directory (its cached unconfined start)")
    p.add_argument("--amplitude", type=float, default=0.1)
    p.add_argument("--factor", type=float, default=1.000001, help="multiplies the campaign's tension time step")
    p.add_argument("--gather", metavar="OUT", help="only gather the perturbed runs of OUT (plain python3)")
    p.add_argument("--docs", default="campaigns/tablet/chosen",
                   help="with --gather: the committed runs; sensitivity.json goes there")
    a = p.parse_args(argv)
    if a.gather:
        res = gather(a.gather, a.docs)
        for amp, r in res["amplitudes"].items():
            print(f"Dx = {amp}: perturbations change the peaks by "
                  + ", ".join(f"{100 * c:.2f}" for c in r["perturbation_change"])
                  + " %; 1920 against 480 t_w by " + ", ".join(f"{100 * c:.2f}" for c in r["rate_change"]) + " %")
        with open(os.path.join(a.docs, "sensitivity.json"), "w") as f:
            json.dump(res, f, indent=1)
        return 0
    if not 0.5 < a.factor < 2:
        p.error(f"--factor {a.factor} is invalid: a perturbation of the step, between 0.5 and 2")
    from mesostudies.tablet.campaign import DT_FACTORS, run_cycles
    info, _ = run_cycles(a.out, "tension", a.amplitude, PERIOD, prefix=f"perturbed-x{a.factor:.10g}-",
                         dt_factor=DT_FACTORS["tension"] * a.factor)
    print("peaks", info["peaks"])
    return 0


if __name__ == "__main__":
    code = main(sys.argv[1:])
    if code:
        sys.exit(code)
