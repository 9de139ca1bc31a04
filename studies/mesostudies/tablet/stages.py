"""The cached states of the tablet campaign, made once and shared by every job (inside ``yade``).

Two stages, each a saved simulation with a JSON description beside it in one directory:

- ``released``: the pressure-sintered, released tablet (``tablet.prepare``);
- ``unconfined``: the common start of the uni-axial tests, made from the released state
  (``uniaxial.make_unconfined``).

``ensure(stage, outdir, ...)`` loads the stage into ``O`` and returns its description, making it
(and the stage before it) first if the directory does not hold it. It holds a lock on the
directory while it looks and makes, so two jobs asking at once make a stage once: the second
waits and loads what the first saved. Files are written under temporary names and renamed (the
description last), so a half-written state is never loaded; a state without its description,
a truncated file or a file that is not the tablet described is removed and made again.
"""
import fcntl
import json
import os
from contextlib import contextmanager

from yade import O

from . import sample
from . import uniaxial as _uni

STAGES = ("released", "unconfined")
QUICK_N = 216


def path(stage, outdir, quick=False):
    if stage not in STAGES:
        raise ValueError(f"stage = {stage!r} is invalid: one of {STAGES}")
    return os.path.join(outdir, f"{stage}{'-quick' if quick else ''}.yade.gz")


@contextmanager
def _locked(outdir):
    os.makedirs(outdir, exist_ok=True)
    with open(os.path.join(outdir, ".stages.lock"), "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(lock, fcntl.LOCK_UN)


def _config(quick, material, kc_over_kp, n, packing="full", glue="loading", rel_std=0.05, seed=1, sinter=None):
    n = n or (QUICK_N if quick else 1728)
    kc = sample.particle_material(material)["kc"] / sample.KP if kc_over_kp is None else float(kc_over_kp)
    return {"n": int(n), "material": material, "kc_over_kp": kc, "packing": packing, "glue": glue,
            "rel_std": float(rel_std),
            "seed": int(seed), "sinter": float(sample.SINTER if sinter is None else sinter)}


class _Unreadable(Exception):
    """A stage file that cannot be used (truncated, not a tablet): made again."""


def _load(p, config):
    try:
        with open(p + ".json") as f:
            info = json.load(f)
        built = info["built"]
        have = {"n": int(built["n"]), "material": built["material"], "kc_over_kp": float(built["kc_over_kp"]),
                # older files: the first protocol
                "packing": built.get("packing", "full"), "glue": built.get("glue", "loading"),
                "rel_std": float(built.get("rel_std", 0.05)), "seed": int(built.get("seed", 1)),
                "sinter": float(built.get("sinter", sample.SINTER))}
    except (OSError, ValueError, KeyError, TypeError, AttributeError) as e:  # a number as text, a list, ...
        raise _Unreadable(f"{p}.json: {type(e).__name__}: {e}")
    if any(abs(have[k] - config[k]) > 1e-12 if k in ("kc_over_kp", "rel_std", "sinter") else have[k] != config[k]
           for k in config):
        raise ValueError(f"{p} holds a tablet with {have}, not the {config} asked for: use another output directory")
    try:
        O.load(p)
    # MemoryError: an earlier version of the plugin's classes; ValueError: a value the classes refuse
    except (RuntimeError, MemoryError, ValueError, TypeError) as e:
        raise _Unreadable(f"{p}: {type(e).__name__}: {e}")
    n = len(sample.sphere_ids())
    if n != config["n"] or not {"left", "right"} <= set(sample.wall_ids()):
        raise _Unreadable(f"{p}: not the tablet its JSON describes ({n} spheres, walls {sorted(sample.wall_ids())})")
    return info


def _try_load(p, config, progress):
    """The stage if its files are whole and usable; None (the files removed) if not."""
    if not os.path.exists(p + ".json"):
        if os.path.exists(p):  # a state without its description: left by a stopped job
            os.remove(p)
        return None
    if not os.path.exists(p):
        os.remove(p + ".json")
        return None
    try:
        return _load(p, config)
    except _Unreadable as e:
        if progress:
            print(f"stage {p} unusable ({e}): made again", flush=True)
        for f in (p, p + ".json"):
            if os.path.exists(f):
                os.remove(f)
        return None


def ensure(stage, outdir, quick=False, material="appendixF", kc_over_kp=None, n=None, progress=True,
           packing="full", glue="loading", rel_std=0.05, seed=1, sinter=None):
    """Loads ``stage`` ('released' or 'unconfined') of the tablet in ``outdir`` into O, making
    it first if it is missing; returns its description. quick: the 216-particle tablet;
    packing, glue, rel_std, seed: the preparation's options (tablet.prepare; seed: the gas's
    random positions and radii, another realization of the same protocol), sinter (d0 p_s/kp)."""
    config = _config(quick, material, kc_over_kp, n, packing, glue, rel_std, seed, sinter)
    p = path(stage, outdir, quick)
    with _locked(outdir):
        info = _try_load(p, config, progress)
        if info is not None:
            return info
        if stage == "released":
            if progress:
                print(f"preparing the released tablet {p} ({config})", flush=True)
            return sample.prepare(p, n=config["n"], material=material, kc_over_kp=config["kc_over_kp"],
                                  progress=progress, packing=packing, glue=glue, rel_std=rel_std, seed=seed,
                                  sinter=config["sinter"])
    info = ensure("released", outdir, quick, material, kc_over_kp, n, progress, packing, glue, rel_std, seed, sinter)
    with _locked(outdir):
        made = _try_load(p, config, progress)  # made meanwhile by another job
        if made is not None:
            return made
        if progress:
            print(f"making the unconfined start {p}", flush=True)
        info = dict(info, unconfined=_uni.make_unconfined(progress=progress))
        sample.save_atomic(p, info)
        return info
