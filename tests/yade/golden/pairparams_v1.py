# Writes pairparams_v1.yade.gz and its .json: a saved contact and materials of the layout before
# gammaN2 (PairParams version 1 with phiD, MesoMat version 0). Run once with the plugin of commit
# add2ac8 (a layout of that kind); test_param_table.py loads the file with the present one:
#   yade-meso -n -x tests/yade/golden/pairparams_v1.py tests/yade/golden
import json
import math
import os
import sys

sys.path.insert(0, sys.argv[-1])  # the golden folder, where pairparams_v0.py lies
from yade import O  # noqa: E402
from pairparams_v0 import contact  # noqa: E402

if __name__ == "__main__":
    out = sys.argv[-1]
    A = dict(k1=100.0, kp=500.0, kc=50.0, phiF=0.1, gammaN=1e-3, density=2000.0, frictionAngle=math.atan(0.4),
             phiD=0.7, kt=40.0, gammaT=1e-3, kr=20.0, gammaR=5e-4, muR=0.1, ko=20.0, gammaO=5e-4, muO=0.1)
    B = dict(k1=150.0, kp=600.0, kc=80.0, phiF=0.2, gammaN=2e-3, density=2000.0, frictionAngle=math.atan(0.5),
             phiD=0.9, kt=60.0, gammaT=2e-3, kr=30.0, gammaR=1e-3, muR=0.2, ko=30.0, gammaO=1e-3, muO=0.2)
    p = contact(A, B, 300).phys
    names = ["k1", "kp", "kc", "phiF", "gammaN", "phiD", "kt", "kr", "ko", "muS", "muR", "muO", "deltaMax", "delta0"]
    vectors = ["slidingSpring", "rollingSpring", "shearForce", "normalForce"]
    state = {k: getattr(p, k) for k in names}
    state.update({k: list(getattr(p, k)) for k in vectors})
    O.save(os.path.join(out, "pairparams_v1.yade.gz"))
    with open(os.path.join(out, "pairparams_v1.json"), "w") as f:
        json.dump({"written_by": "add2ac8", "contact": state,
                   "materials": [{k: getattr(m, k) for k in A if k != "density"} for m in O.materials]}, f, indent=1)
    print("wrote", out)
