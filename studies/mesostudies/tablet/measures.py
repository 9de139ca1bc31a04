"""What the paper's sentences on the tablet's cycles mean, as numbers (plain Python).

A cyclic run's rows are (iter, Dx, F) with Dx = (L - L0)/d0 (> 0 in tension) and F/(kp d0) on the
loading walls (> 0 in compression); each cycle goes from Dx = 0 to the amplitude and back in
``steps_per_cycle`` steps. Per cycle:

- ``peak``: the force of largest magnitude in the test's direction (tension: the most negative);
- ``loop``: the area the cycle encloses in the (Dx, F) plane, |closed integral of F dDx| [kp d0^2],
  the energy the sample dissipates in it;
- ``elastic``: (F_max - F_min) x amplitude / 2, the energy a linear spring through the cycle's
  two extremes stores [kp d0^2] -- the scale of "reversible": loop/elastic is the share of the
  cycle's energy lost;
- ``set``: the permanent set, where the force returns to the test's starting force F0 (the
  sample at rest under the release stress) on the way back, |Dx| over the amplitude (0 if the
  force stays on the loading side of F0 all the way back to Dx = 0: no set).
"""


def split_cycles(rows, steps_per_cycle, n_cycles=None):
    """The rows of each cycle, the rows on a cycle's boundary in both cycles; cycles counted from
    the first row's iter."""
    if steps_per_cycle <= 0:
        raise ValueError(f"steps_per_cycle = {steps_per_cycle} is invalid: must be > 0")
    start = rows[0][0]
    n = n_cycles or int(round((rows[-1][0] - start) / steps_per_cycle))
    out = [[] for _ in range(n)]
    for r in rows:
        pos = (r[0] - start) / steps_per_cycle
        k = int(pos)
        if k < n:
            out[k].append(r)
        if k > 0 and pos == k and k - 1 < n:
            out[k - 1].append(r)
    return out


def loop_area(cycle):
    """|closed integral of F dDx| over the cycle's rows (trapezoids, closed from the last row back
    to the first)."""
    a = 0.0
    pts = list(cycle) + [cycle[0]]
    for p, q in zip(pts, pts[1:]):
        a += 0.5 * (p[2] + q[2]) * (q[1] - p[1])
    return abs(a)


def peak(cycle, mode):
    return min(r[2] for r in cycle) if mode == "tension" else max(r[2] for r in cycle)


def permanent_set(cycle, mode, f0=0.0):
    """|Dx| where the force first returns to f0 on the way back from the amplitude (linear between
    rows), over the amplitude; 0 if it does not before Dx = 0."""
    sign = -1.0 if mode == "tension" else 1.0  # the side of f0 the force is on while the walls load the sample
    far = max(range(len(cycle)), key=lambda k: abs(cycle[k][1]))
    amp = abs(cycle[far][1])
    back = cycle[far:]
    for p, q in zip(back, back[1:]):
        a, b = sign * (p[2] - f0), sign * (q[2] - f0)
        if a > 0 and b <= 0:
            t = a / (a - b)
            return abs(p[1] + t * (q[1] - p[1])) / amp
    return 0.0


def retrace(peaks):
    """Whether cycles 2, 3, ... of a run retrace one branch: the range (max - min) of their peaks
    over the first peak and over their own mean, as magnitudes ((None, None) with one cycle)."""
    later = list(peaks[1:])
    if not later:
        return None, None
    spread = max(later) - min(later)
    mean = sum(later) / len(later)
    return abs(spread / peaks[0]), (abs(spread / mean) if mean else None)


def cycle_measures(rows, steps_per_cycle, mode, n_cycles=None):
    """peak, loop, elastic, loop/elastic and set of every cycle of a run (see the module); F0 is
    the run's first row's force."""
    out = []
    for c in split_cycles(rows, steps_per_cycle, n_cycles):
        pk = peak(c, mode)
        amp = max(abs(r[1]) for r in c)
        el = 0.5 * (max(r[2] for r in c) - min(r[2] for r in c)) * amp
        lp = loop_area(c)
        out.append({"peak": pk, "amplitude": amp, "loop": lp, "elastic": el,
                    "loop_over_elastic": lp / el if el else None,
                    "set": permanent_set(c, mode, rows[0][2])})
    return out
