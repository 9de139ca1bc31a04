# Makes the committed runs of campaigns/tablet/chosen the campaign's run bundles again (see campaign.restore),
# so that the figure scripts regather without repeating runs:
#   yade -n -x studies/scripts/tablet_restore.py DOCS OUT
import sys

from mesocontact import batch
from mesostudies.tablet import campaign

batch.help_requested(sys.argv[1:], sys.argv[0], nargs=2)

try:
    names = campaign.restore(sys.argv[1], sys.argv[2])
except (ValueError, OSError) as e:  # a missing DOCS, DOCS = OUT, an unwritable OUT: the reason, not a traceback
    sys.exit(f"tablet_restore.py: {e}")
if not names:
    print(f"restored no runs: {sys.argv[1]} holds no run JSON with its CSV, or every run is already "
          f"in {sys.argv[2]}/runs",
          flush=True)
else:
    print(f"restored {len(names)} runs into {sys.argv[2]}/runs: {', '.join(names)}", flush=True)
