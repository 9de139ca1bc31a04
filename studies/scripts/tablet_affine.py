# What an affine stretch along x would do to the contacts of a saved tablet: each particle contact
# (centre distance l, normal n) opens by eps l nx^2 under a uniform strain eps, so it reaches its
# tensile limit delta_min = (k2 - k1)/(k2 + kc) deltaMax (the largest tension of its k2 line) at
# eps = (delta - delta_min)/(l nx^2) and lets go (delta = 0) at eps = delta/(l nx^2). Printed and
# written as Dx = eps L0/d0 for the contacts along x (nx^2 > 0.5), with the overlaps' means:
#   yade -j1 -n -x studies/scripts/tablet_affine.py STATE.yade.gz OUT.json
import json
import sys

import numpy as np
from yade import O

from mesocontact import outputs
from mesostudies.tablet import affine
from mesostudies.tablet import sample as tablet

if len(sys.argv) != 3:
    sys.exit("usage: yade -j1 -n -x studies/scripts/tablet_affine.py STATE.yade.gz OUT.json")
O.load(sys.argv[1])
c, L0 = affine.contacts_of_scene()  # delta, delta0, k2, kc, l, nx^2, deltaMax, k1
# columns as before: overlap, delta0, delta_min = (k2 - k1)/(k2 + kc) deltaMax, deltaMax, l, nx^2
a = np.column_stack([c[:, 0], c[:, 1], (c[:, 2] - c[:, 7]) / (c[:, 2] + c[:, 3]) * c[:, 6], c[:, 6], c[:, 4], c[:, 5]])
d0 = tablet.D0
along = a[a[:, 5] > 0.5]
to_limit = (along[:, 0] - along[:, 2]) / (along[:, 4] * along[:, 5]) * L0 / d0
to_zero = along[:, 0] / (along[:, 4] * along[:, 5]) * L0 / d0
pct = (10, 25, 50, 75)
out = {"state": sys.argv[1], "contacts": len(a), "along_x": len(along), "L0_d0": L0 / d0,
       "mean_overlap_d0": float(a[:, 0].mean() / d0), "mean_deltaMax_d0": float(a[:, 3].mean() / d0),
       "mean_delta0_d0": float(a[:, 1].mean() / d0), "mean_delta_min_d0": float(a[:, 2].mean() / d0),
       "mean_overlap_above_limit_d0": float((a[:, 0] - a[:, 2]).mean() / d0),
       "Dx_to_tensile_limit": {str(q): float(np.percentile(to_limit, q)) for q in pct},
       "Dx_to_detachment": {str(q): float(np.percentile(to_zero, q)) for q in pct}}
outputs.write_atomic(sys.argv[2], json.dumps(out, indent=1))
print(json.dumps(out, indent=1))
