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
from mesostudies.tablet import sample as tablet

if len(sys.argv) != 3:
    sys.exit("usage: yade -j1 -n -x studies/scripts/tablet_affine.py STATE.yade.gz OUT.json")
O.load(sys.argv[1])
rows = []
for i in O.interactions:
    b1, b2 = O.bodies[i.id1], O.bodies[i.id2]
    if not (i.isReal and hasattr(b1.shape, "radius") and hasattr(b2.shape, "radius")):
        continue
    branch = b2.state.pos - b1.state.pos
    delta = b1.shape.radius + b2.shape.radius - branch.norm()  # the overlap from the positions (saved states keep no geometry)
    if delta <= 0:
        continue
    ph = i.phys
    rows.append((delta, ph.delta0, (ph.k2 - ph.k1) / (ph.k2 + ph.kc) * ph.deltaMax, ph.deltaMax, branch.norm(),
                 (branch[0] / branch.norm()) ** 2))
a = np.array(rows)
xs = [b.state.pos[0] - b.shape.radius for b in O.bodies if hasattr(b.shape, "radius")]
xe = [b.state.pos[0] + b.shape.radius for b in O.bodies if hasattr(b.shape, "radius")]
L0, d0 = max(xe) - min(xs), tablet.D0
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
