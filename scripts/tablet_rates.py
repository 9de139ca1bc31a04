# Appendix F rate study: one amplitude in tension and compression at three cycle periods.
#   yade -n -x scripts/tablet_rates.py [--quick] [--out DIR] [--periods 30,120,480] [--amplitudes 0.2]
import sys

from mesostudies.tablet import campaign

campaign.main("rates", sys.argv[1:])
