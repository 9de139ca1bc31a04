"""Bulk samples of any MesoMat and their uni-axial tests.

- ``bulk.protocol`` (pure Python): ``Protocol``, how a sample is made (material, stresses,
  speeds, sizes), and ``appendix_f()``, the long paper's;
- ``bulk.sample`` (YADE): the box of walls, the sample's state (``stats``), adhesive walls;
- ``bulk.sintering`` (YADE): ``prepare``, compaction, sintering, release, saved and described;
- ``bulk.uniaxial`` (YADE): ``make_unconfined``, ``make_confined`` (a die) and ``Test``: cosine
  cycles, cycles back to a force, pulls and compressions, through the walls or through grips of
  the sample's particles; ``Test.write_csv`` and ``Test.plot`` (``bulk.records``);
- ``bulk.pictures`` (YADE): the sample seen from the front, cracks and see-through holes;
- ``bulk.agglomerate`` (YADE): agglomerates carved out of a sintered sample (``carve``,
  ``carve_pair``, ``relax``, ``describe``), their centres, radii and meso-overlap, and moves that
  place one against another (``move_to_gap``, ``place_along``, ``directions``);
- ``bulk.pair_cycles`` (YADE): ``Pair`` and ``Wall``, two agglomerates (or one and a flat wall)
  pressed together and pulled apart in cycles under displacement control;
- ``bulk.collisions`` (YADE): ``Collision``, two agglomerates collided: e, the mass broken off,
  where the impact's energy went, a picture of the end.

``bulk.prepare`` is ``bulk.sintering.prepare``; the YADE modules are imported on first use.
"""
from . import protocol  # noqa: F401
from .protocol import Protocol, appendix_f  # noqa: F401


def __getattr__(name):
    if name == "prepare":
        from .sintering import prepare
        return prepare
    if name in ("sample", "sintering", "uniaxial", "records", "pictures", "agglomerate", "pair_cycles", "collisions"):
        import importlib
        return importlib.import_module(f"{__name__}.{name}")
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
