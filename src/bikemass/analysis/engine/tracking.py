"""Following eigenvalues across speed: which root at one speed continues which at the next.

Between neighbouring speeds every eigenvalue is matched to one at the next speed by an optimal
assignment (``scipy.optimize.linear_sum_assignment``) on the cost::

    |l_j(k+1) - l_i(k)| / scale_k  +  (1 - MAC_ij)  +  HALF_PLANE_PENALTY [both complex, Im of opposite signs]

where ``MAC_ij = |x_i^H x_j|^2`` is the overlap of the unit state eigenvectors and ``scale_k`` the
largest eigenvalue modulus at the two speeds (at least 1 1/s).  The distance separates roots far
apart; the eigenvector term decides where roots cross (and, at ``v = 0``, between a root and its
mirror ``-l``).  The costs are symmetric under complex conjugation, so the optimum keeps conjugate
pairs together; the half-plane term breaks the one tie that symmetry leaves (a root of the upper
half-plane continuing as its partner's image).  Where a pair splits into two real roots both
partners continue equally well: naming settles which is which (:mod:`.naming`).
"""

import numpy as np
from scipy.optimize import linear_sum_assignment

HALF_PLANE_PENALTY = 10.0
"""Cost of matching an upper-half-plane root to a lower one (the largest other cost is about 3)."""


def step_costs(values, vectors):
    """Assignment costs (n - 1, m, m): row i = root i at speed k, column j = root j at speed k + 1."""
    dist = np.abs(values[1:, None, :] - values[:-1, :, None])
    scale = np.maximum(np.abs(values).max(axis=1), 1.0)
    scale = np.maximum(scale[1:], scale[:-1])[:, None, None]
    mac = np.abs(np.einsum("kai,kaj->kij", vectors[:-1].conj(), vectors[1:])) ** 2
    sign = np.sign(values.imag)
    flip = (sign[:-1, :, None] * sign[1:, None, :]) < 0
    return dist / scale + (1.0 - mac) + HALF_PLANE_PENALTY * flip


def track(values, vectors):
    """Column order (n, m): ``order[k, i]`` is the column, at speed ``k``, of the root that starts
    as column ``i`` at the first speed."""
    costs = step_costs(values, vectors)
    n, m = values.shape
    order = np.empty((n, m), dtype=int)
    order[0] = np.arange(m)
    for k, cost in enumerate(costs):
        _, step = linear_sum_assignment(cost)       # row i (speed k) -> column step[i] (speed k + 1)
        order[k + 1] = step[order[k]]
    return order


def reorder(values, vectors, order):
    """``values`` (n, m) and ``vectors`` (n, N, m) with their columns put in ``order``."""
    return (np.take_along_axis(values, order, axis=1),
            np.take_along_axis(vectors, order[:, None, :], axis=2))


def partners(values):
    """Index (n, m) of each root's complex-conjugate partner; a real root is its own partner."""
    d = np.abs(values[:, :, None] - values[:, None, :].conj())
    m = values.shape[1]
    d[:, np.arange(m), np.arange(m)] = np.inf
    return np.where(values.imag == 0, np.arange(m), np.argmin(d, axis=2))
