# Inside yade: times one dense, static packing under five contact laws, same steps, same threads.
# Writes a JSON report to the path in argv[1]. Run through scripts/benchmark_laws.py.
#
# usage: yade -jN -n -x benchmark_laws_scene.py OUT [BODIES] [STEPS] [LAWS] [ROUNDS] [SPLIT]
# Every law has its scene (O.addScene), built once; the laws then take turns in bursts of STEPS
# timed steps (after a few untimed ones that warm the caches up), ROUNDS times. A shared machine
# has slow periods of seconds: the laws of one round see much the same machine, so ratios are
# taken within rounds.
# Every burst is followed by one with a one-thread InteractionLoop (with several threads: the
# speed-up of the loop that runs the Law2, from neighbouring bursts).
# SPLIT=1 also gives every law a second scene in which YADE's separate IGeomDispatcher,
# IPhysDispatcher and LawDispatcher replace the InteractionLoop: YADE's engine timing then
# reports the Law2 time on its own.
import json
import math
import random
import sys
import time

from yade import O, pack, wrapper as w

out_path = sys.argv[1]
n_target = int(sys.argv[2]) if len(sys.argv) > 2 else 6000
steps = int(sys.argv[3]) if len(sys.argv) > 3 else 40
names = sys.argv[4].split(",") if len(sys.argv) > 4 else ["cundall-strack", "luding-basic", "meso-normal", "meso-full",
                                                          "meso-full-rotations",
                                                          "cohesion-moment"]
rounds = int(sys.argv[5]) if len(sys.argv) > 5 else 15
split = len(sys.argv) > 6 and sys.argv[6] == "1"
WARM = 5  # untimed steps at the start of every burst
R, RHO, K = 1e-3, 2000.0, 1e4
side = 2 * R * (n_target / 0.74 * 0.5) ** (1 / 3.0)
m = 4 / 3 * math.pi * R ** 3 * RHO
dt = 0.02 * math.pi * math.sqrt(0.5 * m / (5 * K))  # stiffest branch kp = 5K


def law_setup(name):
    """(material, geometry functor, Ip2, Law2) of each contender; normal stiffness ~K for all."""
    six = name in ("meso-full", "meso-full-rotations", "cohesion-moment")
    ig2 = w.Ig2_Sphere_Sphere_ScGeom6D() if six else w.Ig2_Sphere_Sphere_ScGeom()
    if name == "meso-full":  # as the README sets it up: the law reads no relative rotation of ScGeom6D
        ig2.updateRotations = False
    if name == "cundall-strack":
        return w.FrictMat(young=K / R, poisson=0.3, density=RHO, frictionAngle=0.5), ig2, \
            w.Ip2_FrictMat_FrictMat_FrictPhys(), w.Law2_ScGeom_FrictPhys_CundallStrack()
    if name == "luding-basic":
        return w.LudingMat(k1=K, kp=5 * K, kc=K, ks=0.2 * K, PhiF=0.05, G0=1e-4, frictionAngle=0.5, density=RHO), ig2, \
            w.Ip2_LudingMat_LudingMat_LudingPhys(), w.Law2_ScGeom_LudingPhys_Basic()
    if name == "meso-normal":
        return w.MesoMat(k1=K, kp=5 * K, kc=K, phiF=0.05, gammaN=1e-4, fa=1e-4, kca=1e3, adhesion="reversible",
                         density=RHO), ig2, w.Ip2_MesoMat_MesoMat_MesoPhys(), w.Law2_ScGeom_MesoPhys_Meso()
    if name in ("meso-full", "meso-full-rotations"):
        return w.MesoMat(k1=K, kp=5 * K, kc=K, phiF=0.05, gammaN=1e-4, fa=1e-4, kca=1e3, adhesion="reversible",
                         frictionAngle=0.5, kt=0.2 * K, gammaT=2e-5, kr=0.1 * K, gammaR=5e-6, muR=0.1, ko=0.1 * K,
                         gammaO=5e-6, muO=0.1, density=RHO), \
            ig2, w.Ip2_MesoMat_MesoMat_MesoPhys(), w.Law2_ScGeom_MesoPhys_Meso()
    if name == "cohesion-moment":
        return w.CohFrictMat(young=K / R, poisson=0.2, density=RHO, frictionAngle=0.5, momentRotationLaw=True,
                             alphaKr=0.1, alphaKtw=0.1, etaRoll=0.1, etaTwist=0.1, isCohesive=False), ig2, \
            w.Ip2_CohFrictMat_CohFrictMat_CohFrictPhys(), \
            w.Law2_ScGeom6D_CohFrictPhys_CohesionMoment(always_use_moment_law=True, useIncrementalForm=True)
    raise ValueError(name)


def build(name, separate_dispatchers):
    """Builds the law's scene in the current scene slot and creates its contacts."""
    mat, ig2, ip2, law = law_setup(name)
    O.materials.append(mat)
    # A regular hexagonal packing with a small overlap. Every body is blocked but moves with a small
    # constant velocity and spin (reversed after every burst, so that the packing stays put however
    # long the benchmark runs): the contacts are the same under every law while relative velocities,
    # slips and dashpots are exercised; forces do not feed back into the motion.
    O.bodies.append(pack.regularHexa(pack.inAlignedBox((0, 0, 0), (side, side, side)), radius=R, gap=-2e-6,
                                     material=mat))
    rnd = random.Random(1)
    for b in O.bodies:
        b.state.blockedDOFs = "xyzXYZ"
        b.state.vel = tuple(rnd.uniform(-1e-3, 1e-3) for _ in range(3))
        b.state.angVel = tuple(rnd.uniform(-1.0, 1.0) for _ in range(3))
    collider = w.InsertionSortCollider([w.Bo1_Sphere_Aabb(aabbEnlargeFactor=1.01)], verletDist=0.05 * R)
    ig2.interactionDetectionFactor = 1.01  # the non-contact range of the meso law; the same for all
    newton = w.NewtonIntegrator(damping=0.3, gravity=(0, 0, 0))
    O.engines = [w.ForceResetter(), collider, w.InteractionLoop([ig2], [ip2], [law]), newton]
    O.dt = dt
    O.run(20, True)  # contacts and their physics are created
    if separate_dispatchers:
        # YADE's stand-alone IGeomDispatcher uses the functor that the InteractionLoop cached in each
        # interaction (it cannot start a scene); the packing is static, so no pair is new after this.
        O.engines = [w.ForceResetter(), collider, w.IGeomDispatcher([ig2]), w.IPhysDispatcher([ip2]),
                     w.LawDispatcher([law]), newton]
        O.run(2, True)


def burst():
    """Runs one burst on the current scene; returns the engines' times [ns] (YADE's engine timing).
    The first steps after a switch of scenes find the caches holding another scene: untimed."""
    O.run(WARM, True)
    for e in O.engines:
        e.execTime, e.execCount = 0, 0
    O.run(steps, True)
    times = {e.__class__.__name__: e.execTime for e in O.engines}
    for b in O.bodies:
        b.state.vel, b.state.angVel = -b.state.vel, -b.state.angVel
    return times


# Scene slots: (law, separate dispatchers?) -> scene id. Scene 0 is the one YADE starts with.
slots = {}
for name in names:
    for sep in ([False, True] if split else [False]):
        slots[(name, sep)] = O.addScene() if slots else 0
        O.switchToScene(slots[(name, sep)])
        build(name, sep)
        print(f"[{O.numThreads} thr] built {name}{' (separate dispatchers)' if sep else ''}: {len(O.bodies)} spheres, "
              f"{O.interactions.countReal()} contacts", flush=True)

report = {"threads": O.numThreads, "steps": steps, "rounds": rounds, "laws": {}}
O.timingEnabled = True
t0 = time.time()
for rnd in range(rounds):
    # The order rotates, so that no law always follows the same one.
    for k in range(len(names)):
        name = names[(k + rnd) % len(names)]
        L = report["laws"].setdefault(name, {"step_ns": [], "interaction_loop_ns": [], "law2_ns": [],
                                             "split_step_ns": [],
                                             "serial_loop_ns": []})
        O.switchToScene(slots[(name, False)])
        times = burst()
        L["step_ns"].append(sum(times.values()) / steps)
        L["interaction_loop_ns"].append(times["InteractionLoop"] / steps)
        # The same scene right after with a one-thread InteractionLoop (the other engines keep their threads):
        # the speed-up of the loop that runs the Law2, measured in pairs of neighbouring bursts. Also with one
        # thread in all, so that every run makes the same steps (the serial/parallel comparison).
        loop = O.engines[2]
        loop.ompThreads = 1
        L["serial_loop_ns"].append(burst()["InteractionLoop"] / steps)
        loop.ompThreads = -1
        if split:
            O.switchToScene(slots[(name, True)])
            times = burst()
            L["split_step_ns"].append(sum(times.values()) / steps)
            L["law2_ns"].append(times["LawDispatcher"] / steps)
    print(f"[{O.numThreads} thr] round {rnd + 1}/{rounds} ({time.time() - t0:.0f} s): "
          + ", ".join(f"{n} {report['laws'][n]['step_ns'][-1] / 1e3:.0f}" for n in names) + " us/step", flush=True)
O.timingEnabled = False

for name in names:
    O.switchToScene(slots[(name, False)])
    L = report["laws"][name]
    L["contacts"] = O.interactions.countReal()
    O.step()  # forces of one more step, kept for the serial/parallel comparison
    L["forces"] = [tuple(O.forces.f(b.id)) + tuple(O.forces.t(b.id)) for b in O.bodies]
report["bodies"] = len(O.bodies)
probe = w.MesoPhys()
report["mesoPhys_bytes"] = probe.byteSize
report["mesoTangentialPhys_bytes"] = w.MesoTangentialPhys().byteSize
report["frictPhys_bytes"] = probe.frictPhysByteSize
with open(out_path, "w") as f:
    json.dump(report, f)
