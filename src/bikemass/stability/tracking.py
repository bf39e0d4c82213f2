"""Following the eigenvalues of an :class:`~bikemass.stability.eigen.EigenSweep` across speed.

Between neighbouring speeds every eigenvalue is matched to one at the next speed by
an optimal assignment on the cost::

    |lambda_j(k+1) - lambda_i(k)| / scale_k  +  (1 - MAC_ij)

where ``MAC_ij = |x_i^H x_j|^2`` is the overlap of the unit state eigenvectors and
``scale_k`` the largest eigenvalue modulus at the two speeds (at least 1 1/s).  The
distance term separates eigenvalues that are far apart; the eigenvector term decides
where eigenvalues cross (and, at ``v = 0``, between a root and its mirror image
``-lambda``, whose eigenvectors ``[q, +-lambda q]`` differ).  Where two real roots
merge into a complex pair or a pair splits, both partners are equally good: which
one continues which is settled by :mod:`~bikemass.stability.labels`.

The optimal assignment of 4 eigenvalues is found for all speed steps at once by
evaluating the 24 permutations (the same optimum ``scipy.optimize.linear_sum_assignment``
finds one step at a time).
"""

from itertools import permutations

import numpy as np


def step_costs(sweep):
    """Assignment costs (n-1, m, m): row i = eigenvalue i at speed k, column j = at speed k+1."""
    lam, vec = sweep.eigenvalues, sweep.eigenvectors
    dist = np.abs(lam[1:, None, :] - lam[:-1, :, None])
    scale = np.maximum(np.abs(lam).max(axis=1), 1.0)
    scale = np.maximum(scale[1:], scale[:-1])[:, None, None]
    mac = np.abs(np.einsum("kai,kaj->kij", vec[:-1].conj(), vec[1:])) ** 2
    return dist / scale + (1.0 - mac)


def best_permutations(costs):
    """For each step, ``perm`` (n-1, m) minimising ``sum_i costs[k, i, perm[k, i]]``."""
    m = costs.shape[-1]
    perms = np.array(list(permutations(range(m))))
    total = costs[:, np.arange(m), perms].sum(axis=-1)          # (n-1, m!)
    return perms[np.argmin(total, axis=1)]


def track(sweep):
    """Column order (n, m): ``order[k, i]`` is the column of mode ``i`` at speed ``k``.

    Mode ``i`` starts as column ``i`` at the first speed.
    """
    n, m = sweep.eigenvalues.shape
    steps = best_permutations(step_costs(sweep)).tolist()
    order = [list(range(m))]
    for perm in steps:
        order.append([perm[j] for j in order[-1]])
    return np.array(order)


def reorder(sweep, order):
    """Eigenvalues (n, m) and eigenvectors (n, 4, m) with columns put in ``order``."""
    values = np.take_along_axis(sweep.eigenvalues, order, axis=1)
    vectors = np.take_along_axis(sweep.eigenvectors, order[:, None, :], axis=2)
    return values, vectors
