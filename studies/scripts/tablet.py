# The agglomerate tablet of Appendix F: every job of the campaign behind one command line, run
# alone or as yade-batch jobs (one table line per job). The jobs (the first argument, or the table
# column 'figure') and their options are mesostudies.tablet.cli's JOBS and OPTIONS:
#   yade -n -x studies/scripts/tablet.py fig16 --quick [--out DIR] [--amplitudes 0.1,0.2] ...
#   yade -n -x studies/scripts/tablet.py JOB --help
#   yade-batch -j 2 --executable build/yade-meso --log 'results/tablet-@.log' studies/batch/tablet-campaign.table \
#       studies/scripts/tablet.py
# Table columns: 'figure' and any option with underscores (amplitudes, periods, slow_amplitudes,
# out, sinter, seed, ...); cells are Python, so lists of numbers are quoted: '480,1920'. All jobs
# share --out (default results/tablet): the sample is prepared once, under a lock, by the first job
# that needs it, and the others wait for it; each run commits its own bundle in <out>/runs/ and,
# under yade-batch, its time in <out>/jobs.jsonl.
import os
import sys
import time

from mesocontact import batch
from mesostudies.tablet import campaign, cli

if not [a for a in sys.argv[1:] if not a.startswith("-")]:  # no job named: --help is this header and the jobs
    batch.help_requested(sys.argv[1:], sys.argv[0], more="Jobs:\n" + cli.JOBS.describe())
args = batch.argv(sys.argv[1:], positional="figure", figure=None, **cli.batch_columns())
if not args or args[0] not in cli.JOBS:
    sys.exit(f"tablet.py: the first argument (table column 'figure') must be one of {cli.JOBS.names()}, not "
             f"{args[0] if args else 'nothing'!r}")
t0 = time.time()
cli.main(args[0], args[1:])
if batch.under_batch():  # the job's time, for the campaign's total (campaign.totals)
    out = args[args.index("--out") + 1] if "--out" in args else "results/tablet"
    campaign.log_job(out, os.environ["YADE_BATCH"], args[0], t0, time.time())
