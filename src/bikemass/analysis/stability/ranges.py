"""Stable speed ranges, on the speed grid and exact (ends refined as roots).

A grid range is a run of consecutive grid speeds at which the criterion holds,
written ``[first, last]`` as in the thesis's tables.  The exact range of the same
run moves each end that is not an end of the grid to the root of the stability
margin in the neighbouring grid step (:mod:`~bikemass.analysis.stability.critical`).
"""

import numpy as np

from .critical import evaluator, mode_margin, overall_margin, root_in
from .criteria import is_stable


def runs(mask):
    """``[(first, last)]`` index pairs of the runs of True in a boolean array."""
    m = np.concatenate([[False], np.asarray(mask, dtype=bool), [False]])
    edges = np.flatnonzero(m[1:] != m[:-1])
    return [(int(a), int(b) - 1) for a, b in zip(edges[::2], edges[1::2])]


def grid_ranges(speeds, mask):
    """``[[start, stop], ...]`` (m/s) of the stable runs on the grid."""
    return [[float(speeds[a]), float(speeds[b])] for a, b in runs(mask)]


def exact_ranges(speeds, mask, margin_in_cell):
    """Stable runs with interior ends refined: ``margin_in_cell(k)`` is the margin function on ``[v_k, v_k+1]``."""
    out = []
    last = len(speeds) - 1
    for a, b in runs(mask):
        start = speeds[a] if a == 0 else root_in(margin_in_cell(a - 1), speeds[a - 1], speeds[a])
        stop = speeds[b] if b == last else root_in(margin_in_cell(b), speeds[b], speeds[b + 1])
        out.append([float(start), float(stop)])
    return out


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


def overall_ranges(at, modes, marginal=None):
    """``{"exact": [...], "grid": [...]}`` where every eigenvalue meets the criterion
    (``at``: canonical matrices or their :class:`~bikemass.analysis.stability.critical.SpeedEigenvalues`)."""
    mask = is_stable(modes.eigenvalues, marginal).all(axis=1)
    f = overall_margin(at, marginal)
    return {"exact": exact_ranges(modes.speeds, mask, lambda k: f),
            "grid": grid_ranges(modes.speeds, mask)}


def mode_ranges(at, modes, label, marginal=None):
    """``{"exact": [...], "grid": [...]}`` where mode ``label`` meets the criterion."""
    at = evaluator(at)
    values = modes[label]
    mask = is_stable(values, marginal)
    return {"exact": exact_ranges(modes.speeds, mask,
                                  lambda k: mode_margin(at, modes.speeds, values, k, k + 1, marginal)),
            "grid": grid_ranges(modes.speeds, mask)}
