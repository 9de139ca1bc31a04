# Appendix F of the long paper (fig19): see studies/mesostudies/tablet/campaign/ (runs.py for the tests, cli.py for the options).
#   yade -n -x scripts/tablet_fig19.py [--quick] [--out DIR] ...
import sys

from mesostudies.tablet import campaign

campaign.main("fig19", sys.argv[1:])
