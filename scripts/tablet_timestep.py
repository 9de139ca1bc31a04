# Appendix F: the time step justified (one cycle at three time steps, tension and compression).
#   yade -n -x scripts/tablet_timestep.py [--quick] [--out DIR]
import sys

from mesostudies.tablet import campaign

campaign.main("timestep", sys.argv[1:])
