# Appendix F of the long paper (prepare): see studies/mesostudies/tablet/campaign/ (runs.py for the tests, cli.py for the options).
#   yade -n -x scripts/tablet_prepare.py [--quick] [--out DIR] ...
import sys

from mesostudies.tablet import campaign

campaign.main("prepare", sys.argv[1:])
