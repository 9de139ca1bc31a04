# Appendix F of the long paper (fig18): see studies/mesostudies/tablet/campaign/ (runs.py for the tests, cli.py for the options).
#   yade -n -x scripts/tablet_fig18.py [--quick] [--out DIR] ...
import sys

from mesostudies.tablet import campaign

campaign.main("fig18", sys.argv[1:])
