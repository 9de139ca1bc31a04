# Appendix F: the share of the tension peak that the background drag supplies (lab frame, contacts, none).
#   yade -n -x scripts/tablet_drag.py [--quick] [--out DIR]
import sys

from mesostudies.tablet import campaign

campaign.main("drag", sys.argv[1:])
