# Copies a tablet campaign's data and figures into the documentation (see campaign.report):
#   yade -n -x scripts/tablet_report.py OUT DOCS
import sys

from mesocontact import campaign

campaign.report(sys.argv[1], sys.argv[2])
