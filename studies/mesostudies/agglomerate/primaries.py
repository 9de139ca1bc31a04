"""The agglomerates' primary particles and how their block is sintered: Appendix F's material
and protocol (the library's ``bulk.protocol.appendix_f``, in mm, us, mg), with the preparation
the tablet study chose (packed without friction and adhesion, all six walls adhesive through
sintering, radii spread 0.1). Pure Python."""
from mesocontact.bulk import protocol as _protocol

SCALES = _protocol.appendix_f()   # d0, kp and the energy scale of every agglomerate run
D0 = SCALES.d0                    # the primaries' mean diameter [mm]
KP = SCALES.kp                    # their limit stiffness [mg/us^2 = 1e6 N/m]
PREPARATION = {"packing": "frictionless", "glue": "sinter", "rel_std": 0.1}


def protocol(n, seed, aspect):
    """The block's Protocol: n primaries, this seed, box sides in the ratios ``aspect``."""
    return _protocol.appendix_f(n=n, seed=seed, aspect=tuple(aspect), **PREPARATION)
