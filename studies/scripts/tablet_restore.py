# Makes the committed runs of campaigns/tablet/chosen the campaign's run bundles again (see campaign.restore),
# so that the figure scripts regather without repeating runs:
#   yade -n -x studies/scripts/tablet_restore.py DOCS OUT
import sys

from mesocontact import batch
from mesostudies.tablet import campaign

batch.help_requested(sys.argv[1:], sys.argv[0], nargs=2)

names = campaign.restore(sys.argv[1], sys.argv[2])
print(f"restored {len(names)} runs into {sys.argv[2]}/runs: {', '.join(names)}", flush=True)
