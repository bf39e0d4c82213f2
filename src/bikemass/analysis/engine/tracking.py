"""Following eigenvalues across speed: which root at one speed continues which at the next.

Between neighbouring speeds every eigenvalue is matched to one at the next speed by an optimal
assignment on the cost (every permutation at once for a handful of roots, :func:`assignments`;
``scipy.optimize.linear_sum_assignment`` beyond)::

    |l_j(k+1) - l_i(k)| / scale_k  +  (1 - MAC_ij)  +  HALF_PLANE_PENALTY [both complex, Im of opposite signs]

where ``MAC_ij = |x_i^H x_j|^2`` is the overlap of the unit state eigenvectors and ``scale_k`` the
largest eigenvalue modulus at the two speeds (at least 1 1/s).  The distance separates roots far
apart; the eigenvector term decides where roots cross (and, at ``v = 0``, between a root and its
mirror ``-l``).  Where a pair splits into two real roots both partners continue equally well:
naming settles which is which (:mod:`.naming`).

Most steps keep every root in its column, and that is certain without the overlaps of different
roots: ``1 - MAC`` lies in [0, 1], so a root's cost to another column is at least its distance and
half-plane terms; where its own column's full cost is below that for every root, the identity is
the one optimum.  Only the other steps (roots that meet, cross or trade places: a tenth or fewer on
the thesis grid) get their full cost matrices (:func:`_kept`); the assignments are the same.

Roots of a real matrix move in complex-conjugate pairs: while a pair stays complex its members'
images must be partners again; a pair may only split into two real roots, and real roots only
merge with each other.  The costs are symmetric under conjugation, so the optimum mostly keeps
pairs by itself, and the half-plane term stops a root from continuing as its partner's image.
But where a pair passes close to a real root, the assignment that trades one member with the
real root and the one that trades the other cost the same, and the solver may pick either.  Such
a step is repaired exactly: the roots involved (the broken pairs, their images' partners, and so
on until closed; a handful) are assigned again by trying every permutation of them, and the
cheapest that breaks no pair wins.
"""

import numpy as np
from itertools import permutations

HALF_PLANE_PENALTY = 10.0
"""Cost of matching an upper-half-plane root to a lower one (the largest other cost is about 3)."""


BRUTE_FORCE_MAX = 4
"""Up to this many roots (24 permutations: the Whipple bicycle's) every assignment of a sweep is found at
once by trying every permutation on all steps together (numpy, no scipy); beyond, the permutations
outnumber what scipy's solver costs per step."""


def assignments(costs):
    """The optimal assignment of each cost matrix of the stack ``costs`` (k, m, m): (k, m) int, row i
    assigned to column ``out[:, i]`` (the least total cost; the first permutation in lexicographic
    order among equal ones)."""
    costs = np.asarray(costs, dtype=float)
    k, m = costs.shape[0], costs.shape[-1]
    if k == 0:
        return np.zeros((0, m), dtype=int)
    # where every row's least cost is in a column of its own and strictly below the rest of the row, that
    # choice is the one optimal assignment (any other pays more in some row and less in none): taken at
    # once; only the other steps (roots that meet or cross) go to the exact search below
    best = np.argmin(costs, axis=2)                                              # (k, m)
    strict = (costs <= costs.min(axis=2)[:, :, None]).sum(axis=(1, 2)) == m     # each row's least once
    distinct = (np.sort(best, axis=1) == np.arange(m)).all(axis=1)
    hard = np.flatnonzero(~(strict & distinct))
    if len(hard) < k:
        if len(hard):
            best[hard] = _searched(costs[hard])
        return best
    return _searched(costs)


def _searched(costs):
    """:func:`assignments` by the exact search: every permutation, or scipy's solver."""
    k, m = costs.shape[0], costs.shape[-1]
    if m <= BRUTE_FORCE_MAX:
        perms = _permutations(m)                                      # (p, m)
        totals = costs[:, np.arange(m)[None, :], perms].sum(axis=-1)  # (k, p)
        return perms[np.argmin(totals, axis=1)]
    from scipy.optimize import linear_sum_assignment      # lazy: scipy only for models of over 4 roots
    return np.array([linear_sum_assignment(c)[1] for c in costs], dtype=int).reshape(k, m)


_PERMUTATIONS = {}


def _permutations(m):
    out = _PERMUTATIONS.get(m)
    if out is None:
        out = _PERMUTATIONS[m] = np.array(list(permutations(range(m))), dtype=int).reshape(-1, m)
    return out


def _least(x):
    """``x.min(axis=-1)`` for a short last axis (a handful of roots): one elementwise minimum per column
    (a reduction over a short axis costs numpy far more per row)."""
    out = x[..., 0]
    for j in range(1, x.shape[-1]):
        out = np.minimum(out, x[..., j])
    return out


def _first_least(x):
    """``x.argmin(axis=-1)`` for a short last axis without NaN: the first column of the least value."""
    best, where = x[..., 0], np.zeros(x.shape[:-1], dtype=int)
    for j in range(1, x.shape[-1]):
        better = x[..., j] < best
        best = np.where(better, x[..., j], best)
        where = np.where(better, j, where)
    return where


def _largest(x):
    """``x.max(axis=-1)`` for a short last axis (as :func:`_least`)."""
    out = x[..., 0]
    for j in range(1, x.shape[-1]):
        out = np.maximum(out, x[..., j])
    return out


def _any(mask):
    """``mask.any(axis=-1)`` for a short last axis (as :func:`_least`)."""
    out = mask[..., 0]
    for j in range(1, mask.shape[-1]):
        out = out | mask[..., j]
    return out


def _scale(a, b):
    """The larger of the largest root moduli at two speeds (rows of ``a`` and ``b``), at least 1 1/s."""
    return np.maximum(np.maximum(_largest(np.abs(b)), 1.0), np.maximum(_largest(np.abs(a)), 1.0))


def step_costs(values, vectors):
    """Assignment costs (n - 1, m, m): row i = root i at speed k, column j = root j at speed k + 1."""
    return _costs(values[:-1], values[1:], vectors[:-1], vectors[1:])


def _costs(a, b, x, y):
    """The costs (k, m, m) from the roots ``a`` (k, m) with vectors ``x`` (k, N, m) to ``b`` with ``y``:
    each step of :func:`step_costs` on its own (the same arithmetic, step by step)."""
    dist = np.abs(b[:, None, :] - a[:, :, None])
    scale = _scale(a, b)
    mac = np.abs(np.matmul(np.swapaxes(x, 1, 2).conj(), y)) ** 2     # x_i^H y_j
    flip = (np.sign(a.imag)[:, :, None] * np.sign(b.imag)[:, None, :]) < 0
    return dist / scale[:, None, None] + (1.0 - mac) + HALF_PLANE_PENALTY * flip


CERTAIN = 1e-9
"""Margin by which a root's cost to its own column must beat every other column's least possible cost
for a step to be taken as keeping every column without its full cost matrix (:func:`_kept`); far above
the rounding of the two ways the overlap is computed (1e-15)."""


def _kept(values, vectors):
    """Boolean (n - 1,): the steps whose one optimal assignment is every root to its own column, decided
    without the overlaps of different roots: the overlap term ``1 - MAC`` is between 0 and 1, so a
    root's cost to another column is at least its distance and half-plane terms; where its own column's
    full cost is below that for every root (by :data:`CERTAIN`), the row minima form the identity and
    nothing else is optimal (as :func:`assignments` would find on the full matrices)."""
    a, b = values[:-1], values[1:]
    largest = np.maximum(_largest(np.abs(values)), 1.0)       # _scale(a, b), each speed's modulus taken once
    scale = np.maximum(largest[1:], largest[:-1])
    lower = np.empty(a.shape + a.shape[-1:])                   # |b_j - a_i|, row by row: no (k, m, m)
    for i in range(a.shape[1]):                                  # complex temporary (see partners)
        np.abs(b - a[:, i, None], out=lower[:, i])
    sign = np.sign(values.imag)
    lower = lower / scale[:, None, None] + \
        HALF_PLANE_PENALTY * ((sign[:-1, :, None] * sign[1:, None, :]) < 0)
    own = 0                                                     # x_i^H y_i, (n - 1, m): state by state
    for r in range(vectors.shape[1]):
        own = own + vectors[:-1, r].conj() * vectors[1:, r]
    own_mac = own.real ** 2 + own.imag ** 2
    m = values.shape[1]
    diagonal = np.arange(m)
    own = lower[:, diagonal, diagonal] + (1.0 - own_mac)
    lower[:, diagonal, diagonal] = np.inf
    return ~_any(~(own + CERTAIN < _least(lower)))          # NaN: not kept


def broken_pairs(step, before, after):
    """Rows whose conjugate pair ``step`` breaks (``before``/``after``: partner indices at the two speeds)."""
    return np.flatnonzero(_breaks(step[None], before[None], after[None])[0])


def _breaks(steps, before, after):
    """Boolean (k, m): row i's pair broken by ``steps[k]`` (all arrays stacked over k)."""
    rows = np.arange(steps.shape[1])
    k = np.arange(len(steps))[:, None]
    partner_of_image = after[k, steps]
    image_of_partner = steps[k, before]
    return (before != rows) & (partner_of_image != steps) & (partner_of_image != image_of_partner)


def _repaired(step, cost, before, after):
    """``step`` with its broken pairs repaired by the cheapest valid permutation of the rows involved."""
    rows = set(broken_pairs(step, before, after).tolist())
    while True:                                   # close the set: partners, and rows onto images' partners
        grown = set(rows)
        for i in rows:
            grown.add(int(before[i]))
            grown.update(int(r) for r in np.flatnonzero(step == after[step[i]]))
        if grown == rows:
            break
        rows = grown
    rows = sorted(rows)
    images = step[rows]
    best, best_cost = step, np.inf
    for q in permutations(images):
        trial = step.copy()
        trial[rows] = q
        c = cost[np.arange(len(step)), trial].sum()
        if c < best_cost and not len(broken_pairs(trial, before, after)):
            best, best_cost = trial, c
    return best


def track(values, vectors, only=None):
    """Column order (n, m): ``order[k, i]`` is the column, at speed ``k``, of the root that starts
    as column ``i`` at the first speed.  ``only`` (n - 1,) bool: assign those steps alone, every
    other step taken as keeping every column (rows of a sweep that are not neighbours)."""
    part = partners(values)
    n, m = values.shape
    # the full cost matrices (the eigenvector overlaps of every pair of roots) only where a step may do
    # anything but keep every column: roots that meet, cross or trade places
    steps = np.broadcast_to(np.arange(m), (max(n - 1, 0), m)).copy()
    hard = np.flatnonzero(~_kept(values, vectors)) if n > 1 else np.zeros(0, dtype=int)
    if only is not None:
        hard = hard[np.asarray(only, dtype=bool)[hard]]
    if len(hard):
        steps[hard] = assignments(_costs(values[hard], values[hard + 1], vectors[hard], vectors[hard + 1]))
    broken = _any(_breaks(steps, part[:-1], part[1:]))
    for k in np.flatnonzero(broken if only is None else broken & only):
        cost = _costs(values[k:k + 1], values[k + 1:k + 2], vectors[k:k + 1], vectors[k + 1:k + 2])[0]
        steps[k] = _repaired(steps[k], cost, part[k], part[k + 1])
    # row i (speed k) -> column steps[k, i] (speed k + 1); order[k + 1] = steps[k] o ... o steps[0]: constant
    # across the steps that keep every column (nearly all of them), composed at the few others
    order = np.empty((n, m), dtype=int)
    current, start = np.arange(m), 0
    for k in np.flatnonzero(_any(steps != np.arange(m))):
        order[start:k + 1] = current
        current, start = steps[k][current], k + 1
    order[start:] = current
    return order


def reorder(values, vectors, order):
    """``values`` (n, m) and ``vectors`` (n, N, m) with their columns put in ``order``."""
    return (np.take_along_axis(values, order, axis=1),
            np.take_along_axis(vectors, order[:, None, :], axis=2))


SHORT = 512
"""Up to this many distances (rows x roots x roots) :func:`partners` takes them at once and numpy's
``argmin`` (the first of equal ones, as :func:`_first_least`)."""


def partners(values):
    """Index (n, m) of each root's complex-conjugate partner; a real root is its own partner."""
    m = values.shape[1]
    image = values.conj()
    if values.size * m <= SHORT:                          # a few rows (a sweep's hard steps): at once
        x = values[:, :, None] - image[:, None, :]
        d = x.real * x.real + x.imag * x.imag
        d[:, np.arange(m), np.arange(m)] = np.inf
        return np.where(values.imag == 0, np.arange(m), np.argmin(d, axis=2))
    d = np.empty(values.shape + (m,))                     # squared distances: the same nearest
    for i in range(m):                                    # row by row: no (n, m, m) complex temporary, which
        x = values[:, i, None] - image                    # on the default grid would be over glibc's 128 kB
        np.add(x.real * x.real, x.imag * x.imag, out=d[:, i])     # mmap threshold (fresh kernel pages)
    d[:, np.arange(m), np.arange(m)] = np.inf
    nearest = np.argmin(d, axis=2) if np.isnan(d).any() else _first_least(d)
    return np.where(values.imag == 0, np.arange(m), nearest)
