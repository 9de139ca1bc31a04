"""The papers' reproductions, built on the ``mesocontact`` library (which never imports them):

- ``figures``: every pair-collision figure of both papers (long paper Figs. 5-15, short paper Figs.
  5-6): ``common``, ``long``, ``appendix``, ``short``, ``atlas`` (all of them behind one command);
- ``tablet``: the agglomerate tablet of Appendix F (Figs. 16-19): ``sample``, ``stages``,
  ``uniaxial``, ``snapshots``, ``roughness``, ``campaign`` (its runs, plots, report and command
  line), and the plain-Python readers of a campaign's files ``measures``, ``statements``,
  ``branchplot``, ``summary``.

They run from a checkout (``build/yade-meso`` puts ``py/`` and ``studies/`` on the path); the
Debian package carries the library only.
"""
