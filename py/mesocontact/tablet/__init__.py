"""The agglomerate tablet of Appendix F, by job (the sample's own names are reachable here too):

- ``sample``: the particles, walls and materials; the preparation (compaction, sintering, release);
- ``stages``: the prepared states, made once under a lock and reused;
- ``uniaxial``: unconfined tension and compression, the pull;
- ``snapshots``: pictures of the sample and the planes where it tears;
- ``roughness``: the roughness of the fracture faces, from a snapshot (plain Python, no YADE);
- ``campaign`` (a subpackage: ``common``, ``runs``, ``plots``, ``report``, ``cli``): Figs. 16-19,
  the time-step and factor studies, the docs report, plan and totals;
- ``measures``, ``statements``, ``branchplot``: the paper's statements as numbers and the contact
  branches, from a campaign's files (plain Python, no YADE).

``tablet.prepare``, ``tablet.MATERIALS`` & co. are ``tablet.sample``'s, imported when first used,
so that the plain-Python modules load without YADE.
"""


import importlib

_SUBMODULES = ("sample", "stages", "uniaxial", "snapshots", "roughness", "campaign", "measures", "statements",
               "branchplot")


def __getattr__(name):
    # a submodule not yet imported is the import system's to find, not the sample's
    if name.startswith("__") or name in _SUBMODULES:
        raise AttributeError(name)
    try:
        sample = importlib.import_module(__name__ + ".sample")
    except ImportError as exc:  # an AttributeError, so that hasattr() and introspection stay safe
        raise AttributeError(f"{__name__}.{name}: {exc}") from exc
    try:
        return getattr(sample, name)
    except AttributeError:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}") from None
