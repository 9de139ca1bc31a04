# The agglomerate as a meso-particle (issue #48): two agglomerates carved from a sintered block,
# their F(delta) cycles (with each other and against a flat wall), the law fitted to them,
# collisions against meso-particle collisions. Alone, or as yade-batch jobs (one table line per
# job, the job in the column 'job'; jobs sharing --out share its prepared agglomerates: prepare first):
#   yade -n -x studies/scripts/agglomerate.py all --quick          # the pipeline on small agglomerates
#   yade -n -x studies/scripts/agglomerate.py all --out results/agglomerate
#   yade -n -x studies/scripts/agglomerate.py JOB --help
#   yade-batch -j 2 --executable build/yade-meso --log 'results/agglomerate-@.log' \
#       studies/batch/agglomerate-more.table studies/scripts/agglomerate.py
import sys

from mesocontact import batch
from mesostudies.agglomerate import study

if not [a for a in sys.argv[1:] if not a.startswith("-")] and not batch.under_batch():  # --help: this header, the jobs
    batch.help_requested(sys.argv[1:], sys.argv[0], more="Jobs:\n" + study.JOBS.describe())
study.main(batch.argv(sys.argv[1:], positional="job", **study.batch_columns()))
