# Copies a tablet campaign's data and figures into the documentation (see campaign.report):
#   yade -n -x studies/scripts/tablet_report.py OUT DOCS
import sys

from mesocontact import batch
from mesostudies.tablet import campaign

batch.help_requested(sys.argv[1:], sys.argv[0], nargs=2)

campaign.report(sys.argv[1], sys.argv[2])
