"""Following the eigenvalues of an :class:`~bikemass.analysis.stability.eigen.EigenSweep` across speed.

Between neighbouring speeds every eigenvalue is matched to one at the next speed by
an optimal assignment on the cost::

    |lambda_j(k+1) - lambda_i(k)| / scale_k  +  (1 - MAC_ij)

where ``MAC_ij = |x_i^H x_j|^2`` is the overlap of the unit state eigenvectors and
``scale_k`` the largest eigenvalue modulus at the two speeds (at least 1 1/s).  The
distance term separates eigenvalues that are far apart; the eigenvector term decides
where eigenvalues cross (and, at ``v = 0``, between a root and its mirror image
``-lambda``, whose eigenvectors ``[q, +-lambda q]`` differ).  Where two real roots
merge into a complex pair or a pair splits, both partners are equally good: which
one continues which is settled by :mod:`~bikemass.analysis.stability.labels`.

Roots of a real polynomial move in complex-conjugate pairs, so a permutation that
breaks a pair (one member continuing as a real root while the other stays complex, or
a member changing partner) is penalised: otherwise, on a coarse grid, a pair passing
close to a real root can trade a member with it.  The optimal assignment of 4
eigenvalues is found for all speed steps at once by evaluating the 24 permutations
(without broken pairs it is the optimum ``scipy.optimize.linear_sum_assignment``
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


PAIR_PENALTY = 10.0
"""Cost added per broken conjugate pair (the largest real cost is about 3)."""


def partners(values):
    """Index (n, m) of each root's complex-conjugate partner; a real root is its own partner."""
    d = np.abs(values[:, :, None] - values[:, None, :].conj())
    d[:, np.arange(values.shape[1]), np.arange(values.shape[1])] = np.inf
    return np.where(values.imag == 0, np.arange(values.shape[1]), np.argmin(d, axis=2))


def pair_violations(values, perms):
    """Broken conjugate pairs (n-1, len(perms)) of each permutation at each step.

    The roots of a real polynomial move in conjugate pairs: while ``i`` and its partner
    stay complex their images must be partners again; a pair may only split into two
    real roots, and real roots may only merge with each other.  Only the pairing
    pattern at the two speeds matters, so each distinct pattern is evaluated once.
    """
    part = partners(values)                        # a real root is its own partner
    m = values.shape[1]
    both = np.hstack([part[:-1], part[1:]])
    _, first, which = np.unique(both @ m ** np.arange(2 * m), return_index=True, return_inverse=True)
    patterns = both[first]
    before, after = patterns[:, None, :m], patterns[:, None, m:]        # (u, 1, m)
    u = np.arange(len(patterns))[:, None, None]
    image = perms[None]                                                 # (1, P, m)
    image_of_partner = perms[np.arange(len(perms))[None, :, None], before]
    partner_of_image = after[u, 0, image]
    cplx_before = before != np.arange(m)
    cplx_after = after[u, 0, image] != image
    broken = cplx_before & cplx_after & (partner_of_image != image_of_partner)
    return broken.sum(axis=2)[which.ravel()]


def best_permutations(costs, values):
    """For each step, ``perm`` (n-1, m) minimising ``sum_i costs[k, i, perm[k, i]]`` plus
    :data:`PAIR_PENALTY` per conjugate pair it breaks (:func:`pair_violations`)."""
    m = costs.shape[-1]
    perms = np.array(list(permutations(range(m))))
    total = costs[:, np.arange(m), perms].sum(axis=-1) + PAIR_PENALTY * pair_violations(values, perms)
    return perms[np.argmin(total, axis=1)]


def track(sweep):
    """Column order (n, m): ``order[k, i]`` is the column of mode ``i`` at speed ``k``.

    Mode ``i`` starts as column ``i`` at the first speed.
    """
    n, m = sweep.eigenvalues.shape
    steps = best_permutations(step_costs(sweep), sweep.eigenvalues).tolist()
    order = [list(range(m))]
    for perm in steps:
        order.append([perm[j] for j in order[-1]])
    return np.array(order)


def reorder(sweep, order):
    """Eigenvalues (n, m) and eigenvectors (n, 4, m) with columns put in ``order``."""
    values = np.take_along_axis(sweep.eigenvalues, order, axis=1)
    vectors = np.take_along_axis(sweep.eigenvectors, order[:, None, :], axis=2)
    return values, vectors
