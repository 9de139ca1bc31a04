"""A long run saved on the way, so that it survives its process (inside ``yade``).

``save(path, state)`` writes the scene (O.save to ``path``, a .yade.gz) and the JSON-able ``state``
of the Python object driving it (``path``.json), each replaced whole; ``load(path)`` loads the
scene into O and returns the state, refusing a pair of files from different steps (a save
interrupted between them). The object rebinds its engines' callbacks itself (mesocontact.loop),
since a PyRunner's Python callable is not part of a scene. Used by ``pair_cycles.Pair.pull_apart``
and ``uniaxial.Test.cycles``: a run paused at a step boundary and saved there goes on exactly as
if never stopped (checked row for row by yade.agglomerate_quick and yade.cycles_resume)."""
import json
import os

try:
    from yade import O
except ImportError as _exc:  # pragma: no cover - outside yade
    raise ImportError("mesocontact.bulk.checkpoint needs YADE: run it inside `yade`") from _exc

from .. import outputs

SUFFIX = ".yade.gz"


def check_path(name, path, none=False):
    """Refuses a ``path`` that is not a str ending in .yade.gz (or None when ``none``), naming ``name``."""
    if none and path is None:
        return
    if not (isinstance(path, str) and path.endswith(SUFFIX)):
        raise ValueError(f"{name} = {path!r} is invalid: a path ending in {SUFFIX}{', or None' if none else ''}")


def save(path, state, name="path"):
    check_path(name, path)
    part = path[:-len(SUFFIX)] + ".part" + SUFFIX
    O.save(part)
    os.replace(part, path)
    outputs.write_atomic(path + ".json", json.dumps(dict(state, iter=O.iter)))


def load(path, name="path"):
    check_path(name, path)
    with open(path + ".json") as f:
        state = json.load(f)
    O.load(path)
    if O.iter != state["iter"]:
        raise ValueError(f"{name} = {path!r} is invalid: the scene is at step {O.iter}, its state at {state['iter']} "
                         f"(a save interrupted between the two files)")
    del state["iter"]
    return state


def remove(path):
    """The files of a finished run's checkpoint."""
    if path:
        for p in (path, path + ".json"):
            if os.path.exists(p):
                os.remove(p)
