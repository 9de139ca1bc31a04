# One figure of the papers, or all of them (docs/figures.md): YADE over the closed form, CSV + PNG.
#   yade -n -x studies/scripts/figure.py N [--paper long|short] [--out DIR] [--quick]
#   yade -n -x studies/scripts/figure.py --all [--no-tablet] [--out DIR] [--quick]
#   yade-batch --executable build/yade-meso studies/batch/figures.table studies/scripts/figure.py
#       (columns: the options)
# long: Figs. 5-19 of "A contact model for sticking of adhesive meso-particles" (16-19 are the
# tablet of Appendix F, hours of computing, runs cached in --tablet-out); short: Figs. 5-6 of "Sticking
# of adhesive particles in elasto-plastic collisions". --quick: a few points per figure.
import argparse
import os
import sys

from mesocontact import batch
from mesostudies.figures import atlas

p = argparse.ArgumentParser(prog="yade -n -x studies/scripts/figure.py",
                            description="Figures of the papers: YADE pair collisions over the closed form (CSV + PNG).",
                            epilog="figures (paper-number):\n" + atlas.JOBS.describe(),
                            formatter_class=argparse.RawDescriptionHelpFormatter)
p.add_argument("number", nargs="?", type=int, help="figure number in the chosen paper")
p.add_argument("--paper", choices=("long", "short"), default="long", help="which paper (default: long)")
p.add_argument("--out", default="results/figures", help="output directory (default: results/figures)")
p.add_argument("--all", action="store_true", help="every figure of both papers")
p.add_argument("--no-tablet", action="store_true", help="with --all: leave out the tablet figures 16-19")
p.add_argument("--quick", action="store_true", help="a few points per figure (for tests)")
p.add_argument("--tablet-out", default="results/tablet",
               help="figures 16-19: the tablet campaign's directory, whose runs are read back (default: "
                    "results/tablet)")
a = p.parse_args(batch.argv(sys.argv[1:], positional="number", number=None, paper="long", out="results/figures",
                            all=False, no_tablet=False, quick=False, tablet_out=None))
if a.all == (a.number is not None):
    p.error("give a figure number or --all (not both)")
for option, path in (("--out", a.out), ("--tablet-out", a.tablet_out)):
    if path and os.path.exists(path) and not os.path.isdir(path):  # found now, not after the first figure's runs
        p.error(f"{option} {path}: exists and is not a directory")
if not a.all:
    try:
        atlas.known(a.paper, a.number)
    except ValueError as e:
        p.error(str(e))
    atlas.figure(a.paper, a.number, a.out, a.quick, a.tablet_out)
else:
    atlas.everything(a.out, a.quick, tablet=not a.no_tablet, tablet_out=a.tablet_out)
