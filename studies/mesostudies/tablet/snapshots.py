"""Snapshots of the tablet without a GUI, and where it comes apart (inside ``yade``): the
library's pictures (``mesocontact.bulk.pictures``) at the tablet's d0, axes in mm."""
from mesocontact.bulk import pictures as _lib
from mesocontact.bulk.pictures import depth_buffer, depth_colours, montage, walls_connected  # noqa: F401

from . import sample


def window(margin=1.0, stretch=0.0):
    return _lib.window(margin, stretch, d0=sample.D0)


def png(path, title="", win=None, pixel=None):
    """The spheres seen from -y, coloured by depth (bulk.pictures.png), axes in mm."""
    return _lib.png(path, title, win, pixel, d0=sample.D0, unit="mm")


def visible_gap(depth_behind=3.0, band=0.6, pixel=None):
    """Area [d0^2] of the largest crack seen from the front face (bulk.pictures.visible_gap)."""
    return _lib.visible_gap(depth_behind, band, pixel, d0=sample.D0)


def vtk(base, label):
    return _lib.vtk(base, label, comment="meso-particle tablet")


def see_through_holes(pixel=None):
    """Area [d0^2] of the holes one sees through the sample along y (bulk.pictures)."""
    return _lib.see_through_holes(pixel, d0=sample.D0)
