# The agglomerate as a meso-particle (issue #48): two agglomerates carved from a sintered block,
# their F(delta) cycles, the law fitted to them, collisions against meso-particle collisions.
#   yade -n -x studies/scripts/agglomerate.py all --quick          # the pipeline on small agglomerates
#   yade -n -x studies/scripts/agglomerate.py all --out results/agglomerate
#   yade -n -x studies/scripts/agglomerate.py JOB --help
import sys

from mesostudies.agglomerate import study

study.main(sys.argv[1:])
