"""Unconfined uni-axial tension and compression of the released tablet (Appendix F; inside ``yade``).

The library's tests (``mesocontact.bulk.uniaxial``) with the tablet's scales (sample.SCALES:
d0 = 0.01 mm, kp = 5, p_r of the paper): the four lateral walls erased, the sample relaxed with
the adhesive x walls held at p_r (``make_unconfined``, cached by ``stages.ensure('unconfined')``),
then cosine cycles (``Test.cycles``), cycles turning back at the start's force
(``Test.force_cycles``), a monotonic pull or compression, through the walls or through grips of
the sample's own particles (``Test.use_grips``). Recorded: Dx = (L - L0)/d0 (> 0 in tension)
and F = (f_right - f_left)/2 over kp d0 (> 0 in compression).
"""
from mesocontact.bulk import uniaxial as _lib
from mesocontact.bulk.uniaxial import MODES, check_mode, weakest_plane  # noqa: F401

from . import sample


def crossing_time():
    """L0/c, c = d0 sqrt(kp/m) of the mean particle [us]."""
    return _lib.crossing_time(sample.SCALES)


def make_unconfined(progress=True, tol_force=1e-4, tol_ke=1e-4, max_steps=200000):
    """The common start of the tests (bulk.uniaxial.make_unconfined), the x walls moving at up to
    0.01 mm/us while held at p_r."""
    return _lib.make_unconfined(progress, tol_force, tol_ke, max_steps, protocol=sample.SCALES, v_max=0.01)


def crossing_profile(spacing=0.25):
    """The contacts in overlap crossing each plane x = const (bulk.uniaxial.crossing_profile)."""
    return _lib.crossing_profile(spacing, sample.SCALES)


def grip_members(thickness=1.0):
    """The particles within ``thickness`` d0 of each loading wall's face: {wall id: ids}."""
    return _lib.grip_members(thickness, sample.SCALES)


class Test(_lib.Test):
    """bulk.uniaxial.Test on a tablet (its scales are the paper's: sample.SCALES)."""

    def __init__(self, progress=True, run=None, records=True, share=None):
        super().__init__(progress, run, records, share, protocol=sample.SCALES)

    # The campaign's pulls and compressions check Dx between chunks and leave the walls moving
    # (its committed runs were made so).
    def pull(self, speed, until=9.0, every=100, on_record=None, stop=None):
        return super().pull(speed, until, every, on_record, stop, exact=False)

    def compress(self, speed, until=3.0, every=100, on_record=None, stop=None):
        return super().compress(speed, until, every, on_record, stop, exact=False)
