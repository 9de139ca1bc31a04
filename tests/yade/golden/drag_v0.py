# Writes drag_v0.yade.gz and its .json: a saved scene with MesoBackgroundDamping (relative to the
# contacts, energy tracked) in the engine's first serialization layout, before sumInLaw existed.
# Run once with the plugin of commit 798c4df (the last of that layout); test_saveload.py loads the
# file with the present one and continues it:
#   yade-meso -j1 -n -x tests/yade/golden/drag_v0.py tests/yade/golden
import json
import os
import sys

from yade import O, Vector3, utils
from yade import wrapper as w


def scene():
    """Eight pressed, moving spheres on a box with the contact-relative drag, 200 steps of 1 us."""
    O.reset()
    O.materials.append(w.MesoMat(k1=100.0, kp=500.0, kc=50.0, phiF=0.1, gammaN=1e-3, density=2000.0, frictionAngle=0.4,
                                 kt=40.0, gammaT=1e-3))
    r = 1e-3
    ids = O.bodies.append([utils.sphere((i * 1.98 * r, j * 1.98 * r, k * 1.98 * r + r), r)
                           for i in range(2) for j in range(2) for k in range(2)])
    O.bodies.append(utils.box((r, r, -0.5 * r), (4 * r, 4 * r, 0.5 * r), fixed=True))
    for n, b in enumerate(ids):
        O.bodies[b].state.vel = Vector3(0.01 * (n % 3), -0.005 * (n % 2), 0.002 * n)
    O.engines = [w.ForceResetter(), w.InsertionSortCollider([w.Bo1_Sphere_Aabb(), w.Bo1_Box_Aabb()]),
                 w.InteractionLoop([w.Ig2_Sphere_Sphere_ScGeom6D(), w.Ig2_Box_Sphere_ScGeom6D()],
                                   [w.Ip2_MesoMat_MesoMat_MesoPhys()], [w.Law2_ScGeom_MesoPhys_Meso()]),
                 w.MesoBackgroundDamping(gammaB=2e-3, gammaBR=1e-3, reference="contacts", label="drag"),
                 w.NewtonIntegrator(damping=0)]
    O.dt = 1e-6
    O.trackEnergy = True
    O.run(200, True)


if __name__ == "__main__":
    out = sys.argv[-1]
    scene()
    O.save(os.path.join(out, "drag_v0.yade.gz"))
    drag = O.engines[3]
    with open(os.path.join(out, "drag_v0.json"), "w") as f:
        json.dump({"written_by": "798c4df", "gammaB": drag.gammaB, "gammaBR": drag.gammaBR, "reference": drag.reference,
                   "bodies": len(O.bodies), "iter": O.iter, "mesoBackground": O.energy["mesoBackground"]}, f, indent=1)
    print("wrote", out)
