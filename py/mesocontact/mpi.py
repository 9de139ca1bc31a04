"""The meso-particle law under YADE's distributed engine ``yade.mpy``, contact history kept.

mpy splits a scene by erasing, on every rank, the bodies it does not own and importing again
those its own bodies can touch (the mirrors, and the master's walls). Every contact with such a
body is therefore made anew at the first split: deltaMax becomes the present overlap, the
springs restart at zero, and a run that was prepared serially and loaded continues as another
material would. ``keep_contacts`` wraps mpy's collision step: before each one it keeps this
rank's real contacts (their geometry and physics objects, by body ids, in the C++ store
``MesoContactStore.keep``), after it it gives them back to the same pairs wherever mpy made the
pair again without them (``restore``). When mpy's reallocation (``REALLOCATE_FREQUENCY > 0``, off
by default) moves bodies to another worker, their contacts go along (``exportContacts`` /
``importContacts``, the scene's own serialization) and their pairs are made on the new worker at
once.

    from yade import mpy
    from mesocontact import mpi
    mpi.keep_contacts(mpy)
    ...assign b.subdomain, label the collider "collider" and the integrator "newton"...
    mpy.mpirun(steps)

The engines must carry the labels mpy looks up (``collider``, ``newton``): without them mpy
drives a collider of its own that the scene does not run.
"""
from yade import O
from yade import wrapper as w

from .loop import runner

_KEPT = {"restored": 0, "collisions": 0, "reallocations": 0, "moved": 0, "sent": 0, "received": 0}
_ARRIVING = []  # bytes of contacts sent by other ranks with the bodies mpy moved here
_STORE = []  # this process's MesoContactStore, made on first use (yade's classes need a running yade)


def store():
    """The MesoContactStore through which this process keeps its contacts across mpy's steps."""
    if not _STORE:
        _STORE.append(w.MesoContactStore())
    return _STORE[0]


# The yade.mpy whose functions keep_contacts wraps, as ctest's mpi tests run it: the wrappers call
# them with the arguments they were given and rely on mpy.rank, numThreads and comm.
TESTED_YADE = ("2023.02a",)
_WRAPPED = {"parallelCollide": (), "reallocateBodiesToSubdomains": ("_filter", "blocking")}


def check_mpy(mpy):
    """Refuses (RuntimeError) an mpy whose functions that keep_contacts replaces are missing or take
    other parameters than the wrappers pass on; warns once when YADE is not a version the wrappers
    were tested with. Returns YADE's version."""
    import inspect
    import warnings
    from yade import config
    version = getattr(config, "version", "unknown")
    for name, params in _WRAPPED.items():
        fn = getattr(mpy, name, None)
        got = tuple(inspect.signature(fn).parameters) if callable(fn) else None
        if got != params:
            found = "missing" if got is None else "(" + ", ".join(got) + ")"
            raise RuntimeError(f"yade.mpy.{name} of YADE {version} is {found}: "
                               f"mesocontact.mpi wraps mpy.{name}({', '.join(params)}) of YADE "
                               f"{', '.join(TESTED_YADE)}")
    if version not in TESTED_YADE:
        warnings.warn(f"mesocontact.mpi: YADE {version}'s yade.mpy has not been tested with its contact keeping "
                      f"(tested: {', '.join(TESTED_YADE)}); run ctest -R mpi to check it", stacklevel=3)
    return version


def keep_contacts(mpy):
    """Makes every collision step of ``mpy`` (the module) keep the state of the contacts it
    remakes, and every reallocation (``mpy.REALLOCATE_FREQUENCY > 0``) send the contacts of the
    bodies it moves to their new worker. Idempotent. Returns a dict counting, on this rank, the
    collision steps, the contacts given back, the reallocations, the bodies moved away, the bytes
    of contacts sent with them and the contacts received (for logs and tests)."""
    if getattr(mpy.parallelCollide, "_keeps_contacts", False):
        return _KEPT
    check_mpy(mpy)
    collide, reallocate = mpy.parallelCollide, mpy.reallocateBodiesToSubdomains
    kept = store()

    def parallelCollide():
        kept.keep()
        for data in _ARRIVING:
            _KEPT["received"] += kept.importContacts(data)
        _ARRIVING.clear()
        collide()
        _KEPT["collisions"] += 1
        _KEPT["restored"] += kept.restore()

    def reallocateBodiesToSubdomains(*args, **kwargs):
        # mpy ships a moved body's interactions only with the partners its new worker already
        # holds, and makes the others anew at the next collision step (until then the body misses
        # their forces). So each worker sends every contact of the bodies it gave away, and one
        # more collision step makes their pairs at once, with that state.
        owned = [b.id for b in O.bodies if b and not b.isSubdomain and b.subdomain == mpy.rank] if mpy.rank else []
        reallocate(*args, **kwargs)
        _KEPT["reallocations"] += 1
        gone = [[] for _ in range(mpy.numThreads)]
        for b in (O.bodies[i] for i in owned):
            if b and b.subdomain != mpy.rank:
                gone[b.subdomain].append(b.id)
        _KEPT["moved"] += sum(len(ids) for ids in gone)
        sent = [kept.exportContacts(ids) if ids else b"" for ids in gone]
        _KEPT["sent"] += sum(len(data) for data in sent)
        _ARRIVING.extend(data for data in mpy.comm.alltoall(sent) if data)
        mpy.parallelCollide()

    parallelCollide._keeps_contacts = True
    mpy.parallelCollide, mpy.reallocateBodiesToSubdomains = parallelCollide, reallocateBodiesToSubdomains
    return _KEPT


def check_labels():
    """The labels mpy needs, or a ValueError naming the missing one."""
    for label, kind in (("collider", w.InsertionSortCollider), ("newton", w.NewtonIntegrator)):
        if not any(e.label == label and isinstance(e, kind) for e in O.engines):
            raise ValueError(f"label {label!r}: yade.mpy needs the scene's {kind.__name__} labelled {label!r}")


def follow_master_bodies(mpy):
    """After mpy's split: makes every worker move its copies of the master's kinematic bodies (the
    loading walls) as the master's Newton does (pos += vel dt). A worker's NewtonIntegrator moves
    only its own bodies, and with ``MASTER_UPDATE_STATES = False`` (mpy's default) the master sends
    no states, so a wall driven by a motion engine (which sets only its velocity, on every rank)
    would stand still on the workers. Installed right after the NewtonIntegrator; nothing on the
    master. Returns the ids followed on this rank."""
    if not getattr(O, "splitted", False):
        raise RuntimeError("follow_master_bodies: call it after mpy.splitScene()")
    ids = [] if mpy.rank == 0 else [
        b.id for b in O.bodies if b and not b.isSubdomain and b.subdomain == 0 and not b.dynamic]
    engines = [e for e in O.engines if e.label != "followMaster"]

    def follow():
        dt = O.dt
        for i in ids:
            s = O.bodies[i].state
            s.pos = s.pos + s.vel * dt  # NewtonIntegrator's leapfrog for a body without forces

    at = next(k for k, e in enumerate(engines) if isinstance(e, w.NewtonIntegrator))
    O.engines = engines[:at + 1] + [runner(follow, 1, "followMaster")] + engines[at + 1:]
    return ids


def slab_cuts(workers):
    """The x positions between ``workers`` slabs of equal sphere counts of the scene, where
    split_slabs cuts it."""
    xs = sorted(b.state.pos[0] for b in O.bodies if b is not None and isinstance(b.shape, w.Sphere))
    return [xs[len(xs) * k // workers] for k in range(1, workers)]


def split_slabs(mpy, keep=True):
    """Splits the loaded scene (spheres between boxes, such as a sample between loading walls) over
    the ranks of ``mpy``: the master holds the boxes, each worker a slab along x with an equal share
    of the spheres (for a test loaded along x, a slab's boundary crosses the fewest contacts that
    the loading stretches). Keeps every contact's state (keep_contacts; keep=False only to show
    what is lost without it) and lets the workers move their copies of the boxes
    (follow_master_bodies). Run it on every rank, after loading the scene and before mpy.mpirun.
    Returns the box ids this rank follows."""
    workers = mpy.numThreads - 1
    if workers < 1:
        raise ValueError(f"ranks = {workers + 1}: split_slabs needs a master and at least one worker")
    if any(b is not None and isinstance(b.shape, w.Facet) for b in O.bodies):
        raise ValueError("this scene has facets: split_slabs hands only box walls to the master (a sample made with "
                         "Protocol(walls='facets') is not supported under MPI; use walls='boxes')")
    if keep:
        keep_contacts(mpy)
    check_labels()
    O.splitted = O.splittedOnce = False  # a freshly loaded scene: mpy splits it as new
    cuts = slab_cuts(workers)
    for b in O.bodies:
        if isinstance(b.shape, w.Box):
            b.subdomain = 0
        else:
            b.subdomain = 1 + sum(b.state.pos[0] >= c for c in cuts)
    mpy.splitScene()
    return follow_master_bodies(mpy)


def run_ranks(mpy, body):
    """Runs ``body()`` on every rank of an mpiexec job, then ends the process: exit code 0 when
    the master's body returned a true value or None, 1 otherwise (the master's verdict, so that
    mpiexec reports it). An exception on any rank aborts the whole job: the other ranks would
    wait for it forever. Never returns."""
    import os
    import sys
    import traceback
    try:
        ok = body()
        ok = mpy.comm.bcast(ok is None or bool(ok), root=0)
    except BaseException:
        traceback.print_exc()
        sys.stdout.flush()
        mpy.comm.Abort(1)
    sys.stdout.flush()
    mpy.MPI.Finalize()
    os._exit(0 if ok else 1)  # before yade's exit, which would call MPI again
