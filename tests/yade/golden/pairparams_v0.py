# Writes pairparams_v0.yade.gz and its .json: a saved contact whose pair parameters have the first
# serialization layout (PairParams version 0, before phiD was stored). Run once with the plugin of
# commit 20d0512 (the last of that layout); test_param_table.py loads the file with the present one:
#   yade-meso -n -x tests/yade/golden/pairparams_v0.py tests/yade/golden
# contact() is also test_param_table.py's scene.
import json
import math
import os
import sys

from yade import O, utils
from yade import wrapper as w


def contact(mat_a, mat_b, steps, angVel=(0, 3, 1), vel=(0.01, 0.002, 0), overlap=1e-6):
    """Two spheres of radius 1 mm and MesoMat mat_a, mat_b (dicts), pressed by `overlap` and moved
    by vel, angVel for `steps` steps of 1 us on ScGeom6D; returns their interaction."""
    O.reset()
    a, b = O.materials.append(w.MesoMat(**mat_a)), O.materials.append(w.MesoMat(**mat_b))
    r = 1e-3
    O.bodies.append([utils.sphere((0, 0, 0), r, material=a), utils.sphere((2 * r - overlap, 0, 0), r, material=b)])
    O.bodies[0].state.vel, O.bodies[0].state.angVel = vel, angVel
    O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb()]),
                 w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom6D()], [w.Ip2_MesoMat_MesoMat_MesoPhys()],
                                   [w.Law2_ScGeom_MesoPhys_Meso()]),
                 w.NewtonIntegrator(damping=0)]
    O.dt = 1e-6
    O.run(steps, True)
    return O.interactions[0, 1]


# The two materials and what the file records of their contact (also pairparams_v1.py's).
A = dict(k1=100.0, kp=500.0, kc=50.0, phiF=0.1, gammaN=1e-3, density=2000.0, frictionAngle=math.atan(0.4),
         phiD=0.7, kt=40.0, gammaT=1e-3, kr=20.0, gammaR=5e-4, muR=0.1, ko=20.0, gammaO=5e-4, muO=0.1)
B = dict(k1=150.0, kp=600.0, kc=80.0, phiF=0.2, gammaN=2e-3, density=2000.0, frictionAngle=math.atan(0.5),
         phiD=0.9, kt=60.0, gammaT=2e-3, kr=30.0, gammaR=1e-3, muR=0.2, ko=30.0, gammaO=1e-3, muO=0.2)
NAMES = ["k1", "kp", "kc", "phiF", "gammaN", "kt", "kr", "ko", "muS", "muR", "muO", "deltaMax", "delta0"]
VECTORS = ["slidingSpring", "rollingSpring", "shearForce", "normalForce"]


def recorded(p, names=NAMES):
    """What the golden JSON keeps of a contact's MesoPhys p."""
    state = {k: getattr(p, k) for k in names}
    state.update({k: list(getattr(p, k)) for k in VECTORS})
    return state


if __name__ == "__main__":
    out = sys.argv[-1]
    state = recorded(contact(A, B, 300).phys)
    O.save(os.path.join(out, "pairparams_v0.yade.gz"))
    with open(os.path.join(out, "pairparams_v0.json"), "w") as f:
        json.dump({"written_by": "20d0512", "phiD_of_the_pair": 0.7, "contact": state}, f, indent=1)
    print("wrote", out)
