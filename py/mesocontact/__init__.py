"""The adhesive, visco-elasto-plastic meso-particle contact model (Singh, Magnanimo & Luding,
after Luding 2008) for YADE. The modules, by layer:

Theory and parameters (plain Python, no YADE):
- ``theory``: closed-form restitution, sticking limits and overlaps; the quasi-static force along
  a path of overlaps;
- ``params``: parameters from dimensionless groups and from measured quantities, time steps;
- ``calibrate``: the normal parameters fitted to measured restitution e(v) or to force-displacement
  cycles, a subpackage split by job: ``data`` (the measured points), ``problem`` (the model
  against them), ``identify`` (what the data can tell), ``profile`` (profile intervals),
  ``fitting`` (multi-start and bootstrap), ``cycles`` and ``cycles_identify`` (the fit to F(delta)
  and what it can tell), ``groups`` (the dimensionless groups), ``verify`` (a fit checked by YADE
  pair collisions);
- ``outputs``, ``scene_names``: result files that are whole or absent; names shared with readers;
- ``jobs``: a study's jobs behind one command line (Job records in a Registry: lookup, --help, cost).

Scenes and drivers (inside ``yade``):
- ``scene``: what every scene shares (engines, detection, time step, contact states, VTK);
- ``loop``: the one way Python is called from YADE's loop (PyRunners by label);
- ``pair``: pair collisions, sphere-sphere and sphere-wall;
- ``mpi``: the law under ``yade.mpy`` with contact history kept;
- ``batch``: scripts that also run as ``yade-batch`` jobs.
- ``bulk``: a sintered sample of any MesoMat (``bulk.prepare``, its ``Protocol`` in plain Python)
  and its uni-axial tests, unconfined or in a die (docs/bulk.md).

The papers' reproductions (the pair-figure atlas, the agglomerate tablet of Appendix F) are
studies built on this package, in the package ``mesostudies`` of the source tree's ``studies/``;
nothing here imports them.

The C++ classes (``MesoMat``, ``MesoPhys``, ``MesoTangentialPhys``, ``Ip2_MesoMat_MesoMat_MesoPhys``,
``Law2_ScGeom_MesoPhys_Meso``, ``MesoBackgroundDamping``, ``MesoContactStore`` and the geometry
functors ``Ig2_Facet_Sphere_MesoScGeom[6D]``, ``Ig2_Wall_Sphere_MesoScGeom``) come with the plugin
and appear in ``yade`` like built-in ones.
"""
__version__ = "0.1"
