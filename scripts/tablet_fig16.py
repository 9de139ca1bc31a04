# Appendix F of the long paper (fig16): see py/mesocontact/campaign.py.
#   yade -n -x scripts/tablet_fig16.py [--quick] [--out DIR] ...
import sys

from mesocontact import campaign

campaign.main("fig16", sys.argv[1:])
