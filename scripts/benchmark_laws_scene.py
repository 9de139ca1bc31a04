# Inside yade: times one dense, static packing under five contact laws, same steps, same threads.
# Writes a JSON report to the path in argv[1]. Run through scripts/benchmark_laws.py.
import json
import math
import random
import sys
import time

from yade import O, pack, wrapper as w

out_path = sys.argv[1]
n_target = int(sys.argv[2]) if len(sys.argv) > 2 else 6000
steps = int(sys.argv[3]) if len(sys.argv) > 3 else 400
R, RHO, K = 1e-3, 2000.0, 1e4
side = 2 * R * (n_target / 0.74 * 0.5) ** (1 / 3.0) * 1.0
m = 4 / 3 * math.pi * R ** 3 * RHO
dt = 0.02 * math.pi * math.sqrt(0.5 * m / (5 * K))  # stiffest branch kp = 5K


def law_setup(name):
    """(material, geometry functor, Ip2, Law2) of each contender; normal stiffness ~K for all."""
    six = name in ("meso-full", "cohesion-moment")
    ig2 = w.Ig2_Sphere_Sphere_ScGeom6D() if six else w.Ig2_Sphere_Sphere_ScGeom()
    if name == "cundall-strack":
        return w.FrictMat(young=K / R, poisson=0.3, density=RHO, frictionAngle=0.5), ig2, \
            w.Ip2_FrictMat_FrictMat_FrictPhys(), w.Law2_ScGeom_FrictPhys_CundallStrack()
    if name == "luding-basic":
        return w.LudingMat(k1=K, kp=5 * K, kc=K, ks=0.2 * K, PhiF=0.05, G0=1e-4, frictionAngle=0.5, density=RHO), ig2, \
            w.Ip2_LudingMat_LudingMat_LudingPhys(), w.Law2_ScGeom_LudingPhys_Basic()
    if name == "meso-normal":
        return w.MesoMat(k1=K, kp=5 * K, kc=K, phiF=0.05, gammaN=1e-4, fa=1e-4, kca=1e3, adhesion="reversible",
                         density=RHO), ig2, w.Ip2_MesoMat_MesoMat_MesoPhys(), w.Law2_ScGeom_MesoPhys_Meso()
    if name == "meso-full":
        return w.MesoMat(k1=K, kp=5 * K, kc=K, phiF=0.05, gammaN=1e-4, fa=1e-4, kca=1e3, adhesion="reversible",
                         frictionAngle=0.5, kt=0.2 * K, gammaT=2e-5, kr=0.1 * K, gammaR=5e-6, muR=0.1, ko=0.1 * K,
                         gammaO=5e-6, muO=0.1, density=RHO), ig2, w.Ip2_MesoMat_MesoMat_MesoPhys(), w.Law2_ScGeom_MesoPhys_Meso()
    if name == "cohesion-moment":
        return w.CohFrictMat(young=K / R, poisson=0.2, density=RHO, frictionAngle=0.5, momentRotationLaw=True,
                             alphaKr=0.1, alphaKtw=0.1, etaRoll=0.1, etaTwist=0.1, isCohesive=False), ig2, \
            w.Ip2_CohFrictMat_CohFrictMat_CohFrictPhys(), \
            w.Law2_ScGeom6D_CohFrictPhys_CohesionMoment(always_use_moment_law=True, useIncrementalForm=True)
    raise ValueError(name)


def scene(name):
    O.reset()
    mat, ig2, ip2, law = law_setup(name)
    O.materials.append(mat)
    # A regular hexagonal packing with a small overlap. Every body is blocked but moves with a small
    # constant velocity and spin, so the contacts are the same under every law while relative
    # velocities, slips and dashpots are exercised; forces do not feed back into the motion.
    O.bodies.append(pack.regularHexa(pack.inAlignedBox((0, 0, 0), (side, side, side)), radius=R, gap=-2e-6, material=mat))
    rnd = random.Random(1)
    for b in O.bodies:
        b.state.blockedDOFs = "xyzXYZ"
        b.state.vel = tuple(rnd.uniform(-1e-3, 1e-3) for _ in range(3))
        b.state.angVel = tuple(rnd.uniform(-1.0, 1.0) for _ in range(3))
    collider = w.InsertionSortCollider([w.Bo1_Sphere_Aabb(aabbEnlargeFactor=1.01)], verletDist=0.05 * R)
    ig2.interactionDetectionFactor = 1.01  # the non-contact range of the meso law; the same for all
    O.engines = [w.ForceResetter(), collider, w.InteractionLoop([ig2], [ip2], [law]),
                 w.NewtonIntegrator(damping=0.3, gravity=(0, 0, 0))]
    O.dt = dt


def timed(name):
    scene(name)
    O.run(20, True)  # contacts and their physics are created
    O.timingEnabled = True
    for e in O.engines:
        e.execTime, e.execCount = 0, 0
    t0 = time.time()
    O.run(steps, True)
    wall = time.time() - t0
    times = {e.__class__.__name__: e.execTime for e in O.engines}
    O.timingEnabled = False
    return times, wall, O.interactions.countReal()


names = ["cundall-strack", "luding-basic", "meso-normal", "meso-full", "cohesion-moment"]
if len(sys.argv) > 4:  # a subset, e.g. for profiling
    names = sys.argv[4].split(",")
reps = int(sys.argv[5]) if len(sys.argv) > 5 else 3
report = {"threads": O.numThreads, "steps": steps, "repetitions": reps, "bodies": 0, "laws": {}}
# The laws take turns, several rounds; each keeps its best round (machine noise only slows down).
for rep in range(reps):
    for name in names:
        times, wall, contacts = timed(name)
        step_ns = sum(times.values()) / steps
        L = report["laws"].setdefault(name, {"step_ns": math.inf})
        if step_ns < L["step_ns"]:
            L.update(contacts=contacts, step_ns=step_ns, interaction_loop_ns=times["InteractionLoop"] / steps, wall_s=wall)
        if rep == reps - 1:
            O.step()  # forces of one more step, kept for the serial/parallel comparison
            L["positions"] = [tuple(O.forces.f(b.id)) + tuple(O.forces.t(b.id)) for b in O.bodies]
        report["bodies"] = len(O.bodies)
        print(f"[{O.numThreads} thr, round {rep + 1}/{reps}] {name:16s} step {step_ns / 1e3:9.1f} us, interaction loop "
              f"{times['InteractionLoop'] / steps / 1e3:8.1f} us, {contacts} contacts", flush=True)
report["mesoPhys_bytes"] = w.MesoPhys().byteSize
report["frictPhys_bytes"] = w.MesoPhys().frictPhysByteSize
with open(out_path, "w") as f:
    json.dump(report, f)
