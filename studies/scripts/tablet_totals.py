# The measured time of a tablet campaign, from the jobs' records (<out>/jobs.jsonl): each job's
# time and steps, the single-job hours, the wall time; written to <out>/campaign-time.json.
#   yade -j1 -n -x studies/scripts/tablet_totals.py [--out DIR] [--since EPOCH_S] [--lanes N] [--wall-seconds S]
import argparse
import json
import os
import sys

from mesocontact import outputs
from mesostudies.tablet import campaign

p = argparse.ArgumentParser(prog="tablet_totals.py")
p.add_argument("--out", default="results/tablet")
p.add_argument("--since", type=float, default=None, help="only jobs that started at or after this time (epoch s)")
p.add_argument("--lanes", type=int, default=None)
p.add_argument("--wall-seconds", type=float, default=None,
               help="the whole command's wall time (preparation and plan included), as measured by the caller")
a = p.parse_args(sys.argv[1:])
try:
    t = campaign.totals(a.out, a.since, a.lanes)
except (OSError, ValueError) as e:
    p.error(str(e))
if a.wall_seconds is not None:
    t["command_wall_hours"] = a.wall_seconds / 3600
    print(f"the whole command (preparation and plan included): {t['command_wall_hours']:.2f} h of wall time",
          flush=True)
outputs.write_atomic(os.path.join(a.out, "campaign-time.json"), json.dumps(t, indent=1))
