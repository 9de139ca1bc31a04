# Whether two copies of the tablet campaign's files hold the same runs: every CSV byte for byte,
# every JSON equal in every entry except the clocks (a rerun on another day must give the same
# physics; only its timing may differ). Plain python3:
#   python3 studies/scripts/tablet_same_runs.py DIR_A DIR_B [--json FILE]
# Exit code 0 when every common file agrees, 1 otherwise.
import argparse
import json
import os
import sys

# Entries that measure the machine, not the run.
CLOCKS = {"wall_clock_s", "ms_per_step", "start", "end", "seconds", "hours"}
# Files that are only the machine's record (plan and totals).
TIMING_FILES = {"campaign-plan.json", "campaign-time.json"}


def _flat(o, path=""):
    if isinstance(o, dict):
        for k, v in o.items():
            yield from _flat(v, f"{path}/{k}")
    elif isinstance(o, list):
        for i, v in enumerate(o):
            yield from _flat(v, f"{path}[{i}]")
    else:
        yield path, o


def json_differences(a, b):
    """The entries (paths) in which two JSON files differ, the clocks left out."""
    fa, fb = (dict(_flat(json.load(open(f)))) for f in (a, b))
    keep = lambda p: p.rsplit("/", 1)[-1] not in CLOCKS  # noqa: E731
    return sorted(p for p in set(fa) | set(fb) if keep(p) and fa.get(p) != fb.get(p))


def compare(da, db):
    common = sorted((set(os.listdir(da)) & set(os.listdir(db))) - TIMING_FILES)
    out = {"csv_identical": [], "json_same_but_clocks": [], "different": {}}
    for name in common:
        a, b = os.path.join(da, name), os.path.join(db, name)
        if name.endswith(".csv"):
            if open(a, "rb").read() == open(b, "rb").read():
                out["csv_identical"].append(name)
            else:
                out["different"][name] = "bytes"
        elif name.endswith(".json"):
            d = json_differences(a, b)
            if d:
                out["different"][name] = d[:10]
            else:
                out["json_same_but_clocks"].append(name)
    out["only_in_a"] = sorted(set(os.listdir(da)) - set(os.listdir(db)))
    out["only_in_b"] = sorted(set(os.listdir(db)) - set(os.listdir(da)))
    return out


def main(argv):
    p = argparse.ArgumentParser(prog="python3 studies/scripts/tablet_same_runs.py")
    p.add_argument("a")
    p.add_argument("b")
    p.add_argument("--json", help="write the comparison here")
    args = p.parse_args(argv)
    for d in (args.a, args.b):
        if not os.path.isdir(d):
            p.error(f"{d} is not a directory")
    out = compare(args.a, args.b)
    print(f"{len(out['csv_identical'])} CSV byte for byte, {len(out['json_same_but_clocks'])} JSON equal but "
          f"for the clocks, {len(out['different'])} different")
    for name, what in out["different"].items():
        print(f"  different: {name}: {what}")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(out, f, indent=1)
    return 1 if out["different"] else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
