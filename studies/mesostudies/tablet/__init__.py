"""The agglomerate tablet of Appendix F, by job:

- ``sample``: the particles, walls and materials; the preparation (compaction, sintering, release);
- ``stages``: the prepared states, made once under a lock and reused;
- ``uniaxial``: unconfined tension and compression, the pull;
- ``snapshots``: pictures of the sample and the planes where it tears;
- ``roughness``: the roughness of the fracture faces, from a snapshot (plain Python, no YADE);
- ``campaign`` (a subpackage: ``common``, ``runs``, ``plots``, ``report``): Figs. 16-19,
  the time-step and factor studies, the docs report, plan and totals;
- ``cli``: the jobs' registry (``JOBS``, mesocontact.jobs) and command line, at the top: it imports
  the modules it dispatches to (``campaign``, ``affine``, ``profile``, ``slaved``), none of them it;
- ``measures``, ``statements``, ``branchplot``: the paper's statements as numbers and the contact
  branches, from a campaign's files (plain Python, no YADE).
"""
