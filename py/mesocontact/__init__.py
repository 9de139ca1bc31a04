"""The adhesive, visco-elasto-plastic meso-particle contact model (Singh, Magnanimo & Luding,
after Luding 2008) for YADE.

- ``mesocontact.theory``: closed-form restitution, sticking limits and overlaps (plain Python);
- ``mesocontact.params``: parameters from dimensionless groups, time steps (plain Python);
- ``mesocontact.pair``: pair-collision scenes and driver (inside ``yade``);
- ``mesocontact.figures``: the papers' figures (matplotlib);
- ``mesocontact.tablet``, ``stages``, ``uniaxial``, ``snapshots``, ``campaign``: the agglomerate tablet of
  Appendix F, its unconfined uni-axial tests and Figs. 16-19 (inside ``yade``).

The C++ classes (``MesoMat``, ``MesoPhys``, ``Ip2_MesoMat_MesoMat_MesoPhys``,
``Law2_ScGeom_MesoPhys_Meso``) come with the plugin and appear in ``yade`` like built-in ones.
"""
__version__ = "0.1"
