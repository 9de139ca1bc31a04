"""Calibration: the law's normal parameters from measured restitution e(v), or from
force-displacement cycles F(delta) (``fit_cycles``); plain Python with numpy and scipy, no YADE.
docs/calibration.md explains the method and what it showed.

    from mesocontact import calibrate
    d = calibrate.load_data("drops.csv")                       # columns v, e[, sigma] (SI)
    f = calibrate.fit(d, radius=1e-3, density=2500, values=dict(k1=100))
    print(f.report())

The closed form (theory.pair_collision, every regime, both adhesion modes and k2 rules) makes a
fit a least-squares problem of a few parameters: milliseconds per evaluation, seconds per fit
with its intervals. e(v) depends on k1, kp, kc, phiF, fa (and kca, m_r, a12) only through five
dimensionless groups (eta, beta, kca/k1, fa/(k1 phiF a12) and v/v_p, docs/model.md §2), so some
parameter sets are undetermined by any e(v) data; the fit finds which from the Jacobian, in the
logarithms of the free parameters, and says so.

The package, by job: ``data`` (the data and the collisions they come from), ``problem`` (the
least-squares problem, its starts and solves), ``identify`` (what the Jacobian says the data
determine), ``profile`` (profile-likelihood intervals, the bootstrap), ``fitting`` (``fit`` and
its result ``Fit``), ``cycles`` (``fit_cycles`` on F(delta), its result ``CycleFit``), ``groups``
(parameters from dimensionless groups, from e and a contact time), ``verify`` (the fit through
YADE, its picture). Every public name is reachable here.
"""
from .data import (AGAINST, PARAMETERS, SIGMA_MIN, UNITS, Data, DataError, Setup, check_data, geometry,  # noqa: F401
                   load_data)
from .fitting import RESTARTS, Fit, fit  # noqa: F401
from .cycles import CYCLE_PARAMETERS, CYCLE_STARTS, MAGNITUDES, CycleFit, fit_cycles  # noqa: F401
from .groups import contact_duration, from_groups, from_restitution_and_contact_time, material  # noqa: F401
from .identify import EDGE_FACTOR, EDGE_POINTS, NULL_RCOND, UNDETERMINED_FACTOR, Z95, v_p_edge  # noqa: F401
from .problem import EXPLORE_KEPT, EXPLORE_NFEV, SCREEN_CANDIDATES, SCREEN_POLISHED  # noqa: F401
from .profile import MUTATIONS, PROFILE_CHI2, PROFILE_GRID, PROFILE_STARTS  # noqa: F401
from .verify import plot, yade_check  # noqa: F401
