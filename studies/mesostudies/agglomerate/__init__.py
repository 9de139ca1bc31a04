"""An agglomerate of primary particles seen from outside as one meso-particle (issue #48).

Two agglomerates are carved from one pressure-sintered block of Appendix F's primaries (the
tablet's particles and preparation, in a box of two cubes), so that their inner contacts keep the
sintering's history (``make``, with the library's ``mesocontact.bulk.agglomerate``); their
mesoscopic contact law F(delta) is measured under displacement control (the library's
``bulk.pair_cycles``), the meso-particle law is fitted to it (``compare``, with
mesocontact.calibrate), and head-on collisions of the agglomerates (``bulk.collisions``) are
compared with collisions of two meso-particles of the fitted law and with the closed form
(``study`` runs the jobs). Units are the tablet's: mm, us, mg. The modules that need YADE (make,
study) import it; ``compare`` is plain Python.
"""
