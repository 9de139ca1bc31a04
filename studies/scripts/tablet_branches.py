#!/usr/bin/env python3
"""The fraction of the tablet's contacts on each branch of the law through a cyclic test (plain python3):
    python3 studies/scripts/tablet_branches.py RUN-branches.csv OUT.png [--cycles N] [--period STEPS] [--title TEXT]
RUN-branches.csv: written by every cyclic tablet run next to its CSV; --period: steps per cycle (the
run's JSON has it as steps_per_cycle); without it the x axis is the step."""
import argparse
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [os.path.join(HERE, "..", "..", "py"), os.path.join(HERE, "..")]  # the library and the studies
from mesostudies.tablet import branchplot  # noqa: E402


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0], usage=__doc__.splitlines()[1].strip())
    ap.add_argument("csv")
    ap.add_argument("png")
    ap.add_argument("--cycles", type=float, default=None)
    ap.add_argument("--period", type=float, default=None)
    ap.add_argument("--title", default=None)
    a = ap.parse_args(argv)
    for name, v in (("--cycles", a.cycles), ("--period", a.period)):
        if v is not None and not v > 0:
            ap.error(f"{name} {v} is invalid: must be > 0")
    if a.cycles is not None and a.period is None:
        ap.error("--cycles needs --period (steps per cycle)")
    try:
        mean = branchplot.plot(a.csv, a.png, a.title or os.path.basename(a.csv), a.cycles, a.period)
    except (OSError, ValueError) as e:
        sys.exit(f"tablet_branches.py: {e}")
    print(f"{a.png}: mean fractions " + ", ".join(f"{b} {v:.3f}" for b, v in mean.items() if v > 0))


if __name__ == "__main__":
    main(sys.argv[1:])
