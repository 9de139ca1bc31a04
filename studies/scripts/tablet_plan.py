# The plan of a tablet campaign table before it runs: jobs, steps, hours from a measured ms per step
# (also written to <out>/campaign-plan.json).
#   yade -j1 -n -x studies/scripts/tablet_plan.py [TABLE] [--out DIR] [--lanes N]
import argparse
import json
import os
import sys

from mesocontact import outputs
from mesostudies.tablet import campaign, cli

p = argparse.ArgumentParser(prog="tablet_plan.py")
p.add_argument("table", nargs="?", default="studies/batch/tablet-campaign.table")
p.add_argument("--out", default="results/tablet")
p.add_argument("--lanes", type=int, default=2)
a = p.parse_args(sys.argv[1:])
if a.lanes < 1:
    p.error(f"--lanes {a.lanes} is invalid: at least 1")
plan = campaign.plan(a.table, a.out, cli.JOBS, a.lanes)
outputs.write_atomic(os.path.join(a.out, "campaign-plan.json"), json.dumps(plan, indent=1))
