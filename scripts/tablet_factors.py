# The factor study of the tested tablet (campaigns/tablet/factors.md): the Fig. 17 pull of one
# preparation (--packing, --glue) with the drag relative to --drag, then the table of every run
# made so far in <out>/factors/ (factors.md, factors.json); --table only gathers the table.
# --report DOCS copies the files to DOCS/factors/ and writes the table from them.
# All six runs on two lanes: yade-batch -j 2 --executable build/yade-meso batch/tablet-factors.table scripts/tablet_batch.py
#   yade -j1 -n -x scripts/tablet_factors.py [--packing full|frictionless] [--glue loading|all] [--drag contacts|lab] [--out DIR] [--quick] [--table]
import sys

from mesostudies.tablet import campaign

campaign.main("factors", sys.argv[1:])
