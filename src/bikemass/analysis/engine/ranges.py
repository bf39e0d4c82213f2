"""Stable speed ranges: exact (ends at the model's own boundary speeds) and on the speed grid.

Criteria (Williams 2015, Sec. 4.1): **strict**, every eigenvalue has ``Re < 0``; **marginal**, also
an eigenvalue with modulus below ``r`` (2 rad/s by default: slow enough for a rider to control).
On the grid ``Re`` counts as negative only below ``-ZERO_TOL``: at ``v = 0`` the bicycle is
conservative and an oscillatory pair has ``Re = 0`` exactly (the thesis's tables count it as not
stable); rounding must not turn that into stability.

The exact ranges need no grid.  Between two consecutive boundary speeds (every crossing of
``Re = 0``, and for the marginal criterion every speed where an eigenvalue's modulus is ``r``:
:mod:`~bikemass.analysis.engine.crossings`) nothing changes sign, so one evaluation inside each
interval decides it; stable intervals next to each other join.  A window narrower than any grid
step is found like any other.  A mode's own range is decided the same way, on the root that
continues the tracked mode inside the interval.
"""

import numpy as np

MARGINAL_THRESHOLD = 2.0
"""Default modulus (rad/s) below which an unstable eigenvalue counts as marginally stable."""
ZERO_TOL = 1e-10
"""Real parts within this distance of zero (1/s) count as zero on the grid."""


def margin(values, marginal=None):
    """Signed stability margin of eigenvalues (1/s, negative = stable): ``Re`` or ``min(Re, |l| - r)``."""
    values = np.asarray(values)
    if marginal is None:
        return values.real
    return np.minimum(values.real, np.abs(values) - marginal)


def is_stable(values, marginal=None):
    """Boolean array: each eigenvalue stable under the criterion (``marginal=None`` = strict)."""
    values = np.asarray(values)
    stable = values.real < -ZERO_TOL
    if marginal is not None:
        stable |= np.abs(values) < marginal
    return stable


def runs(mask):
    """``[(first, last)]`` index pairs of the runs of True in a boolean array."""
    m = np.concatenate([[False], np.asarray(mask, dtype=bool), [False]])
    edges = np.flatnonzero(m[1:] != m[:-1])
    return [(int(a), int(b) - 1) for a, b in zip(edges[::2], edges[1::2])]


def grid_ranges(speeds, mask):
    """``[[start, stop], ...]`` (m/s) of the stable runs on the grid (first and last stable speeds)."""
    return [[float(speeds[a]), float(speeds[b])] for a, b in runs(mask)]


def interval_ranges(lo, hi, boundaries, stable_at):
    """``[[start, stop], ...]``: the union of the intervals between ``lo``, the sorted ``boundaries``
    and ``hi`` on which ``stable_at(midpoint)`` holds."""
    ends = [lo, *[b for b in boundaries if lo < b < hi], hi]
    out = []
    for a, b in zip(ends, ends[1:]):
        if b > a and stable_at(0.5 * (a + b)):
            if out and out[-1][1] == a:
                out[-1][1] = b
            else:
                out.append([a, b])
    return [[float(a), float(b)] for a, b in out]


def intersect(a, b):
    """Intersection of two sorted lists of closed intervals ``[[start, stop], ...]``."""
    out, i, j = [], 0, 0
    while i < len(a) and j < len(b):
        lo, hi = max(a[i][0], b[j][0]), min(a[i][1], b[j][1])
        if lo <= hi:
            out.append([lo, hi])
        if a[i][1] < b[j][1]:
            i += 1
        else:
            j += 1
    return out
