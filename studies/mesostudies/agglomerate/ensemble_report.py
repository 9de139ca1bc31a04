"""The ensemble's table (issue #59; plain Python): per speed, over every block and direction run,
the mean and standard deviation of each restitution measure, the stuck and fragmented counts,
the broken bonds and mass, the re-contacts.

Measures (bulk.collisions, bulk.impact): ``e`` along the approach of the two largest fragments'
centres; ``e_normal`` along the normal forces' impulse (no spin); ``e_contact`` the contact point's
normal velocity (spin included: the issue's measure, not bounded at a rough contact); ``e_rigid``
the rigid motion's share of the impact's energy. A stuck pair counts e = 0 in every measure. A
collision is fragmentation when it breaks off more than FRAGMENTED of the mass.

    python3 -m mesostudies.agglomerate.ensemble_report results/ensemble [--json OUT.json]
"""
import json
import math
import os
import sys

MEASURES = ("e", "e_normal", "e_contact", "e_rigid")
FRAGMENTED = 0.01


def collected(out):
    """Every finished collision under ``out`` (<out>/block-s<seed>/ensemble/*.json)."""
    rows = []
    for d in sorted(os.listdir(out)) if os.path.isdir(out) else []:
        e = os.path.join(out, d, "ensemble")
        if d.startswith("block-s") and os.path.isdir(e):
            for f in sorted(os.listdir(e)):
                if f.endswith(".json"):
                    with open(os.path.join(e, f)) as fh:
                        rows.append(json.load(fh))
    return rows


def _value(r, key):
    if r["stuck"]:
        return 0.0
    v = r.get(key)
    return None if v is None else float(v)


def _stats(xs):
    xs = [x for x in xs if x is not None]
    if not xs:
        return None, None, 0
    m = sum(xs) / len(xs)
    sd = math.sqrt(sum((x - m) ** 2 for x in xs) / (len(xs) - 1)) if len(xs) > 1 else 0.0
    return m, sd, len(xs)


def table(rows):
    """{speed: summary} over the rows."""
    out = {}
    for v in sorted({r["v_rel_m_s"] for r in rows}):
        at = [r for r in rows if r["v_rel_m_s"] == v]
        s = {"n": len(at), "n_blocks": len({r["seed"] for r in at}),
             "n_directions": len({r["direction_index"] for r in at}),
             "stuck": sum(1 for r in at if r["stuck"]),
             "fragmented": sum(1 for r in at if r["broken_mass_fraction"] > FRAGMENTED),
             "broken_mass_mean": sum(r["broken_mass_fraction"] for r in at) / len(at),
             "bonds_broken_fraction_mean": sum(r["bonds_broken_fraction"] or 0 for r in at) / len(at),
             "recontacts_mean": sum(r["recontacts"] for r in at) / len(at),
             "runs_with_recontacts": sum(1 for r in at if r["recontacts"] > 0)}
        for key in MEASURES:
            m, sd, n = _stats([_value(r, key) for r in at])
            s[key] = {"mean": m, "sd": sd, "n": n,
                      "min": min((_value(r, key) for r in at if _value(r, key) is not None), default=None),
                      "max": max((_value(r, key) for r in at if _value(r, key) is not None), default=None)}
        out[v] = s
    return out


def _percent(x):
    """x in per cent; a rounding residue (1 - the fragments' share summed: |x| < 1e-12) reads 0."""
    return f"{100 * (x if abs(x) >= 1e-12 else 0.0):.2f} %"


def text(tab):
    lines = ["| v [m/s] | runs (blocks x directions) | e_rigid mean ± sd [min, max] | e mean ± sd | e_normal mean | "
             "e_contact mean [min, max] | stuck | fragmented | bonds broken | mass broken off | with re-contacts |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for v, s in tab.items():
        c, e, k = s["e_rigid"], s["e"], s["e_contact"]

        def f(x, fmt=".3f"):
            return "–" if x is None else format(x, fmt)
        lines.append(f"| {v:g} | {s['n']} ({s['n_blocks']} x {s['n_directions']}) | {f(c['mean'])} ± {f(c['sd'])} "
                     f"[{f(c['min'])}, {f(c['max'])}] | {f(e['mean'])} ± {f(e['sd'])} | {f(s['e_normal']['mean'])} | "
                     f"{f(k['mean'])} [{f(k['min'])}, {f(k['max'])}] | {s['stuck']} | {s['fragmented']} | "
                     f"{_percent(s['bonds_broken_fraction_mean'])} | {_percent(s['broken_mass_mean'])} | "
                     f"{s['runs_with_recontacts']} |")
    return "\n".join(lines)


def main(argv):
    out = argv[0] if argv else "results/ensemble"
    tab = table(collected(out))
    print(text(tab))
    if "--json" in argv:
        with open(argv[argv.index("--json") + 1], "w") as f:
            json.dump({str(k): v for k, v in tab.items()}, f, indent=1)


if __name__ == "__main__":
    main(sys.argv[1:])
