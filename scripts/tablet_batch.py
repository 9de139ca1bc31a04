# The tablet campaign (Appendix F) as yade-batch jobs, one table line per job:
#   yade-batch -j 2 --executable build/yade-meso --log 'results/tablet-@.log' batch/tablet-campaign.table scripts/tablet_batch.py
# Columns: figure ('prepare', 'fig16' ... 'fig19', 'rates', 'drag', 'timestep') and any option of
# the tablet scripts with underscores (amplitudes, periods, slow_amplitudes, out, quick, speed,
# material, kc_over_kp, n, no_run, factors, runs, packing, glue, rel_std, seed, sinter, drag, table); cells are Python, so lists of numbers are quoted: '480,1920'.
# All jobs share --out (default results/tablet): the sample is prepared once, under a lock, by
# the first job that needs it, and the others wait for it; each run commits its own bundle in
# <out>/runs/ and its time in <out>/jobs.jsonl. Run alone, the first argument names the figure: yade -n -x scripts/tablet_batch.py fig16 --quick
import os
import sys
import time

from mesocontact import batch
from mesostudies.tablet import campaign

batch.help_requested(sys.argv[1:], sys.argv[0])

args = batch.argv(sys.argv[1:], positional="figure", figure=None, amplitudes=None, periods=None, slow_amplitudes=None,
                  out=None, quick=False, speed=None, material=None, kc_over_kp=None, n=None, no_run=False, factors=None, runs=None,
                  packing=None, glue=None, drag=None, table=False, report=None, rel_std=None, seed=None, sinter=None)
if not args or args[0] not in campaign.FIGURES:
    sys.exit(f"tablet_batch.py: the first argument (table column 'figure') must be one of {campaign.FIGURES}, not "
             f"{args[0] if args else 'nothing'!r}")
t0 = time.time()
campaign.main(args[0], args[1:])
if batch.under_batch():  # the job's time, for the campaign's total (campaign.totals)
    out = args[args.index("--out") + 1] if "--out" in args else "results/tablet"
    campaign.log_job(out, os.environ["YADE_BATCH"], args[0], t0, time.time())
