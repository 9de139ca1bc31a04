# What the tablet under yade.mpy exchanges per step, measured on this scene (issue #19's scaling
# estimate, docs/mpi.md):
#   mpiexec -n N yade -j1 -n -x studies/scripts/tablet_mpi_traffic.py [--quick] [--out DIR] [--steps S]
# Loads the unconfined start in DIR (made if missing), splits it as the campaign does
# (mesocontact.mpi.split_slabs: walls on the master, N-1 slabs along x), runs S steps with the
# walls at rest and writes DIR/mpi-traffic-N.json: per worker the particles it owns, its real
# contacts, the contacts with a body of another worker (both copies counted once per side),
# the bodies whose states it sends to each other worker per step and the bytes of those
# messages (yade's C++ messages: 8 bytes per value), the bytes of the wall forces it sends to
# the master (a pickled list, as mpy sends it), and the wall-clock per step.
# Without mpiexec it prints the serial wall-clock per step of the same steps.
import argparse
import json
import os
import pickle
import sys
import time

from yade import O, mpy
from yade import wrapper as w
from mesocontact import mpi
from mesostudies.tablet import sample as tablet
from mesostudies.tablet import stages, uniaxial

p = argparse.ArgumentParser(prog="mpiexec -n N yade -j1 -n -x studies/scripts/tablet_mpi_traffic.py")
p.add_argument("--quick", action="store_true", help="the 216-particle tablet")
p.add_argument("--out", default="results/tablet", help="where the unconfined start is (made if missing)")
p.add_argument("--steps", type=int, default=1000, help="steps to time")
a = p.parse_args(sys.argv[1:])


def measure():
    stages.ensure("unconfined", a.out, quick=a.quick, progress=False)
    uniaxial.Test(progress=False)  # its step restores the forces, as before every test
    if mpy.numThreads == 1:  # started without mpiexec: the serial step, for comparison
        t0 = time.time()
        O.run(a.steps, True)
        print(f"serial: {(time.time() - t0) / a.steps * 1e3:.3f} ms per step over {a.steps} steps", flush=True)
        os._exit(0)
    mpi.split_slabs(mpy)
    mpy.mpirun(1)  # the first parallel step makes the contacts real on every side
    me = mpy.rank
    info = {"rank": me}
    if me > 0:
        own = {b.id for b in O.bodies if b and not b.isSubdomain and b.subdomain == me}
        real = [i for i in O.interactions if i.isReal]
        walls = {b.id for b in O.bodies if b and isinstance(b.shape, w.Box)}
        info.update(
            particles=len(own - walls), contacts=len(real),
            boundary_contacts=sum(1 for i in real if not (i.id1 in own or i.id1 in walls)
                                  or not (i.id2 in own or i.id2 in walls)),
            wall_contacts=sum(1 for i in real if i.id1 in walls or i.id2 in walls),
            states_sent={str(k): len(O.subD.intersections[k]) for k in range(1, mpy.numThreads)
                         if k != me and O.subD.intersections[k]},
            state_bytes={str(k): 8 * len(O.subD.getStateValues(k)) for k in range(1, mpy.numThreads)
                         if k != me and O.subD.intersections[k]},
            force_bytes=len(pickle.dumps([[i, O.forces.f(i), O.forces.t(i)] for i in O.subD.mirrorIntersections[0]])),
            forces_sent=len(O.subD.mirrorIntersections[0]))
    t0 = time.time()
    mpy.mpirun(a.steps)
    info["s_per_step"] = (time.time() - t0) / a.steps
    everyone = mpy.comm.gather(info, root=0)
    if me == 0:
        out = {"ranks": mpy.numThreads, "quick": a.quick, "particles": len(tablet.sphere_ids()),
               "steps": a.steps, "per_rank": everyone}
        name = os.path.join(a.out, f"mpi-traffic-{mpy.numThreads}{'-quick' if a.quick else ''}.json")
        with open(name, "w") as f:
            json.dump(out, f, indent=1)
        for r in everyone:
            print(r, flush=True)
        print(f"written {name}", flush=True)


mpi.run_ranks(mpy, measure)
