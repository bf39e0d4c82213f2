"""Eigenvalues and eigenvectors of a linear model's dynamic states over a vector of speeds.

The general path is LAPACK's ``geev`` on the stacked state matrices (``numpy.linalg.eig``, one
batched call).  A model with two mechanical coordinates and no other dynamic states (the Whipple
bicycle, rigid or with the quasi-static flexible frame) takes a fast path with the same numbers:
the roots of the quartic ``det(M s^2 + C(v) s + K(v))`` in closed form
(:mod:`~bikemass.analysis.engine.quartic`), each eigenvector ``[q, s q]`` with ``q`` spanning the
null space of that 2 x 2 matrix.
"""

from dataclasses import dataclass

import numpy as np

from .quartic import quartic_roots
from .tracking import assignments, track


def _det2_poly(a, b, c):
    """Coefficients (n, 5), highest first, of ``det(a s^2 + b s + c)`` for stacked 2x2 ``a, b, c``."""
    def cross(x, y):   # x11 y22 + y11 x22 - x12 y21 - y12 x21
        return (x[..., 0, 0] * y[..., 1, 1] + y[..., 0, 0] * x[..., 1, 1]
                - x[..., 0, 1] * y[..., 1, 0] - y[..., 0, 1] * x[..., 1, 0])
    return np.stack([cross(a, a) / 2, cross(a, b), cross(a, c) + cross(b, b) / 2,
                     cross(b, c), cross(c, c) / 2], axis=-1)


def has_quartic_path(model):
    """Whether ``model`` is a two-coordinate second-order model (the closed-form fast path)."""
    mech = model.mechanics
    return mech is not None and len(mech.M) == 2 and model.n_dynamic == 4


def characteristic_coefficients(mechanics, speeds):
    """Coefficients (n, 5), highest power first, of ``det(M s^2 + C(v) s + K(v))`` at ``speeds``."""
    v = np.asarray(speeds, dtype=float)
    M = np.broadcast_to(mechanics.M, v.shape + (2, 2))
    return _det2_poly(M, mechanics.damping(v), mechanics.stiffness(v))


def characteristic_of(M, C, K):
    """Coefficients (..., 5) of ``det(M s^2 + C s + K)`` of stacked 2x2 ``M``, ``C``, ``K``."""
    return _det2_poly(M, C, K)


def quartic_vectors(M, C, K, s):
    """Unit state eigenvectors (..., 4, 4), column i for eigenvalue ``s[..., i]``, of stacked 2x2 ``M``
    (broadcast), ``C`` and ``K`` (..., 2, 2) with roots ``s`` (..., 4)."""
    M, C, K = np.asarray(M), np.asarray(C), np.asarray(K)

    def entry(i, j):                              # (..., 4): entry (i, j) of M s^2 + C(v) s + K(v) at every root
        return (s * M[..., i, j, None] + C[..., i, j, None]) * s + K[..., i, j, None]

    # entry by entry, each (..., 4): no (..., 4, 4) complex temporaries (on the default grid each would be
    # over glibc's 128 kB mmap threshold: fresh pages from the kernel for every one)
    p00, p01, p10, p11 = entry(0, 0), entry(0, 1), entry(1, 0), entry(1, 1)
    row1 = np.abs(p00) + np.abs(p01) >= np.abs(p10) + np.abs(p11)   # null vector from the larger row
    phi = np.where(row1, -p01, p11)
    delta = np.where(row1, p00, -p10)
    zero = (phi == 0) & (delta == 0)
    phi = np.where(zero, 1.0, phi)
    parts = (phi, delta, s * phi, s * delta)
    # |x| as numpy's norm makes it (the same rounding: conj(x) x, the rows summed in order), then each row
    # scaled into its place: no stacked copy divided again (x / |x| is x times 1 / |x| in numpy's complex
    # arithmetic, so the result is the same to the bit)
    square = [(x.conj() * x).real for x in parts]
    inverse = 1 / np.sqrt(((square[0] + square[1]) + square[2]) + square[3])
    out = np.empty(s.shape[:-1] + (4, s.shape[-1]), dtype=complex)
    for r, x in enumerate(parts):
        np.multiply(x, inverse, out=out[..., r, :])
    return out


@dataclass(frozen=True, eq=False)
class EigenSweep:
    """Eigenvalues (n, m) [1/s] and unit eigenvectors (n, N, m) [columns] at speeds (n,) [m/s], in
    no particular column order (:mod:`~bikemass.analysis.engine.tracking` orders them)."""

    speeds: np.ndarray
    eigenvalues: np.ndarray
    eigenvectors: np.ndarray


def eigen_sweep(model, speeds):
    """:class:`EigenSweep` of ``model``'s dynamic states at every speed of ``speeds`` (m/s)."""
    v = np.atleast_1d(np.asarray(speeds, dtype=float))
    if has_quartic_path(model):
        mech = model.mechanics
        C, K = mech.damping(v), mech.stiffness(v)          # once, for the roots and the vectors
        s = quartic_roots(_det2_poly(np.broadcast_to(mech.M, v.shape + (2, 2)), C, K))
        return EigenSweep(v, s, quartic_vectors(mech.M, C, K, s))
    values, vectors = np.linalg.eig(model.dynamic_matrix(v))
    values = np.where(values.imag == 0, values.real + 0j, values)
    return EigenSweep(v, values.astype(complex, copy=False), vectors.astype(complex, copy=False))


def natural_frequency(eigenvalues):
    """Undamped natural frequency ``|l|`` (rad/s)."""
    return np.abs(eigenvalues)


def damping_ratio(eigenvalues):
    """Damping ratio ``-Re(l) / |l|``; ``nan`` where ``l = 0``."""
    mag = np.abs(eigenvalues)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(mag > 0, -eigenvalues.real / mag, np.nan)


CERTAIN_MOVE = 0.25
"""A step between neighbouring speeds keeps every root on its nearest successor, without eigenvectors,
when every root moves by less than this fraction of its distance to the nearest other root at either
speed."""


def _plain_values(A):
    """``numpy.linalg.eigvals`` of the stack ``A`` as complex, a real root with an imaginary part of +0."""
    values = np.linalg.eigvals(A)
    if values.dtype.kind != "c":
        return values.astype(complex)
    return np.where(values.imag == 0, values.real + 0j, values)


SMALL = 8192
"""Below this many distances (rows x roots x roots) they are computed at once; above, one column at a time."""


PAIRWISE = 4
"""Up to this many roots, the distances of a long sweep to the nearest other root are taken pair by pair
(each pair of roots once, the six of a quartic); beyond, by rotations of the columns."""

_PAIRS = {}


def _pairs(m):
    """``(first, second)``: the pairs ``i < j`` of ``m`` roots (int arrays)."""
    out = _PAIRS.get(m)
    if out is None:
        out = _PAIRS[m] = np.triu_indices(m, 1)
    return out


def _nearest_other(values):
    """Squared distance (k, m) from each root of each row of ``values`` (k, m) to the nearest other root
    of its row (``inf`` for a single root): one rotation of the columns at a time (numpy reduces a
    short last axis slowly)."""
    k, m = values.shape
    if m <= PAIRWISE and k * m * m > SMALL:
        first, second = _pairs(m)
        d = values[:, first] - values[:, second]                     # each pair of roots once
        d = d.real * d.real + d.imag * d.imag
        out = np.full(values.shape, np.inf)
        for i in range(m):                                            # the pairs holding root i
            for p in np.flatnonzero((first == i) | (second == i)):
                np.minimum(out[:, i], d[:, p], out=out[:, i])
        return out
    if k * m * m <= SMALL:
        d = values[:, :, None] - values[:, None, :]
        d = d.real * d.real + d.imag * d.imag
        d[:, np.arange(m), np.arange(m)] = np.inf
        return d.min(axis=2)
    out = np.full(values.shape, np.inf)
    for j in range(1, m):
        d = values - values[:, (np.arange(m) + j) % m]
        np.minimum(out, d.real * d.real + d.imag * d.imag, out=out)
    return out


def nearest_steps(values, at=None, sep=None):
    """``(steps, certain)``: each root's nearest successor at the next speed (n - 1, m) and whether that
    step is certain (n - 1,): the nearest successors are distinct and every root moves by less than
    :data:`CERTAIN_MOVE` of its distance to the nearest other root, at either speed.  ``at`` (k,) asks
    for those steps alone (rows ``at`` to ``at + 1``); ``sep`` (n, m), where given, holds the squared
    distances to the nearest other root (:func:`_nearest_other` of ``values``)."""
    n, m = values.shape
    k = np.arange(n - 1) if at is None else np.asarray(at, dtype=int)
    if not len(k):
        return np.zeros((0, m), dtype=int), np.zeros(0, dtype=bool)
    a, b = (values[:-1], values[1:]) if at is None else (values[k], values[k + 1])
    # squared distances (the same nearest, no square roots) from each root at speed k to root j at k + 1:
    # at once for a few steps, else one column j at a time (numpy reduces a short last axis slowly)
    if len(k) * m * m <= SMALL:
        d = b[:, None, :] - a[:, :, None]
        d = d.real * d.real + d.imag * d.imag
        steps = np.argmin(d, axis=2)
        move = np.take_along_axis(d, steps[:, :, None], axis=2)[..., 0]
    else:
        move, steps = np.full(a.shape, np.inf), np.zeros(a.shape, dtype=int)
        for j in range(m):
            d = a - b[:, j:j + 1]
            d = d.real * d.real + d.imag * d.imag
            nearer = d < move
            move = np.where(nearer, d, move)
            steps[nearer] = j
    if sep is None and at is None:
        sep = _nearest_other(values)
    elif sep is None:
        rows = np.unique(np.concatenate([k, k + 1]))
        sep = np.empty((n, m))
        sep[rows] = _nearest_other(values[rows])
    room = np.minimum(sep[k], np.take_along_axis(sep[k + 1], steps, axis=1))
    distinct = (np.sort(steps, axis=1) == np.arange(m)).all(axis=1)
    certain = distinct & (move < CERTAIN_MOVE ** 2 * room).all(axis=1)
    return steps, certain


FILL_EVERY = 12
"""Eigenvalues of a long sweep are LAPACK's at every FILL_EVERY-th speed; between them each root is
continued by Newton's method on the characteristic polynomial (:func:`filled_values`)."""
FILL_HALVINGS = 2
"""A cell of LAPACK speeds where the roots come close for their motion is halved (LAPACK at its middle
speed) up to this many times before LAPACK takes every speed in it."""
FILL_ITERATIONS = 4
"""Newton steps of the continuation (quadratic convergence from a guess a small fraction of the roots'
distances away)."""
FILL_TOL = 1e-12
"""A continued root is accepted when its last Newton step is below FILL_TOL (1 + |root|) 1/s."""
FILL_SPREAD = 1e6
"""Largest ratio of the largest to the smallest root modulus at the LAPACK speeds for which roots are
continued on the characteristic polynomial (wider: a very stiff tyre; LAPACK at every speed)."""


def _poly_from_roots(roots):
    """Real coefficients (k, m + 1), highest power first, of ``prod (s - r)`` for each row of ``roots``
    (k, m) (complex roots in conjugate pairs)."""
    k, m = roots.shape
    c = np.zeros((k, m + 1), dtype=complex)
    c[:, 0] = 1.0
    for j in range(m):
        c[:, 1:j + 2] = c[:, 1:j + 2] - roots[:, j:j + 1] * c[:, :j + 1]
    return c.real


def _lagrange_weights(x, t, width):
    """``(windows (q, width) int, weights (q, width))``: for each point ``t`` (q,) the ``width`` nodes of
    ``x`` (ascending) around it (as centred as the ends allow) and the Lagrange weights that give a
    polynomial of degree below ``width`` at ``t`` from its values at those nodes (the barycentric
    form: each window's weights once)."""
    first = np.clip(np.searchsorted(x, t) - width // 2, 0, len(x) - width)
    starts, which = np.unique(first, return_inverse=True)
    xs = x[starts[:, None] + np.arange(width)]                        # (u, width) each window's nodes
    diff = xs[:, :, None] - xs[:, None, :]
    diff[:, np.arange(width), np.arange(width)] = 1.0
    bary = 1.0 / np.prod(diff, axis=2)                                # (u, width)
    gap = t[:, None] - xs[which]                                      # (q, width), never 0 (t is no node)
    weights = np.prod(gap, axis=1)[:, None] * bary[which] / gap
    return first[:, None] + np.arange(width), weights


_INTERPOLATION = {}
"""The interpolation matrices of :func:`interpolation_matrix` last made (a handful: a grid's nodes are
the same for most models analysed on it)."""


def interpolation_matrix(x, t, width):
    """``W`` (q, len(x)): ``W @ f(x)`` is the polynomial of degree below ``width`` through the values of
    ``f`` at the nodes ``x`` nearest each point ``t`` (:func:`_lagrange_weights` spread over all the
    nodes), read-only; memoised on the nodes and points (a pure function of the grid)."""
    key = (x.tobytes(), t.tobytes(), width)
    W = _INTERPOLATION.get(key)
    if W is None:
        windows, weights = _lagrange_weights(x, t, width)
        W = np.zeros((len(t), len(x)))
        np.put_along_axis(W, windows, weights, axis=1)
        W.setflags(write=False)
        if len(_INTERPOLATION) >= 8:
            _INTERPOLATION.pop(next(iter(_INTERPOLATION)))
        _INTERPOLATION[key] = W
    return W


class _AtSpeeds:
    """``model``'s dynamic matrices at the speeds ``v`` (m/s), made for the rows asked for
    (``at[rows]``): a sweep that asks LAPACK about a sixth of its speeds builds no more of them."""

    def __init__(self, model, v):
        self.model, self.v = model, v
        self.shape = (len(v), model.n_dynamic, model.n_dynamic)

    def __getitem__(self, rows):
        return self.model.dynamic_matrix(self.v[rows])


def filled_values(model, v, A=None):
    """Eigenvalues (n, m) of the stacked dynamic matrices ``A`` (n, m, m; default ``model``'s, made for
    the speeds that need them) at speeds ``v`` (m/s), complex (a real root with imaginary part +0), in
    no particular column order at each speed.

    LAPACK's at every :data:`FILL_EVERY`-th speed (and the last); at the speeds between two of them
    (a model of one polynomial in speed: a closed loop with gains scheduled in speed takes LAPACK's
    roots at every speed)
    where every root stays far from the others (:func:`nearest_steps`), each root is continued from the
    straight line between its values there by Newton's method on the characteristic polynomial
    ``det(s I - A(v))``.  Its coefficients are polynomials in ``v`` (of degree at most ``d m``, ``A``
    of degree ``d``), so they are interpolated exactly (to rounding) from their values at the LAPACK
    speeds nearest ``v`` (those of the roots found there).  A speed where a root does not settle, or
    the roots' sum misses the trace, takes LAPACK's roots.

    Returns ``(values, candidates, proven)``: ``candidates`` (n - 1, m) is, for each step whose two
    speeds' roots were continued together, each root's successor (the same column inside a cell, the
    cell's assignment onto the next LAPACK speed), and -1 in the other rows (to be found by
    :func:`nearest_steps`); ``proven`` (n - 1,) marks the steps whose candidates are certain by a
    bound (:func:`_proven_cells`); :func:`checked_steps` checks the others."""
    A = _AtSpeeds(model, v) if A is None else A
    n, m = A.shape[0], A.shape[-1]
    candidates = np.full((max(n - 1, 0), m), -1)
    proven = np.zeros(max(n - 1, 0), dtype=bool)
    pieces = model.speed_pieces
    if len(pieces) != 1 or n < 2 * FILL_EVERY:     # gains scheduled in speed: A(v) is a polynomial piecewise
        return _plain_values(A[:]), candidates, proven
    width = m * (len(pieces[0][2].dynamic_coefficients) - 1) + 1
    nodes = np.unique(np.r_[np.arange(0, n, FILL_EVERY), n - 1])
    if len(nodes) < width + 1:
        return _plain_values(A[:]), candidates, proven
    at_nodes = _plain_values(A[nodes])
    size = np.abs(at_nodes)
    if not (np.all(np.isfinite(at_nodes)) and size.max() <= FILL_SPREAD * max(size.min(), 1e-300)):
        return _plain_values(A[:]), candidates, proven
    sep = _nearest_other(at_nodes)          # each LAPACK speed's distances, for its steps and the bound
    steps, certain = nearest_steps(at_nodes, sep=sep)
    for _ in range(FILL_HALVINGS):            # a cell where roots come close: LAPACK at its middle too
        wide = np.flatnonzero(~certain & (np.diff(nodes) > 2))
        if not len(wide):
            break
        middle = (nodes[wide] + nodes[wide + 1]) // 2
        merged = np.argsort(np.r_[nodes, middle], kind="stable")
        place = np.empty(len(merged), dtype=int)
        place[merged] = np.arange(len(merged))
        nodes = np.r_[nodes, middle][merged]
        at_middle = _plain_values(A[middle])
        at_nodes = np.concatenate([at_nodes, at_middle])[merged]
        sep = np.concatenate([sep, _nearest_other(at_middle)])[merged]
        # the cells not halved keep their steps; the halves' are found
        keep = np.ones(len(steps), dtype=bool)
        keep[wide] = False
        kept = np.flatnonzero(keep)
        halves = np.r_[place[wide], place[wide] + 1]
        new_steps, new_certain = np.empty((len(nodes) - 1, m), dtype=int), np.empty(len(nodes) - 1, dtype=bool)
        new_steps[place[kept]], new_certain[place[kept]] = steps[kept], certain[kept]
        new_steps[halves], new_certain[halves] = nearest_steps(at_nodes, halves, sep)
        steps, certain = new_steps, new_certain
    values = np.empty((n, m), dtype=complex)
    values[nodes] = at_nodes
    between = np.ones(n, dtype=bool)
    between[nodes] = False
    cell = np.searchsorted(nodes, np.arange(n), side="right") - 1     # the LAPACK speeds around each speed
    rows = np.flatnonzero(between & certain[np.minimum(cell, len(certain) - 1)])
    rest = np.flatnonzero(between & ~certain[np.minimum(cell, len(certain) - 1)])
    if len(rows):
        cell = cell[rows]
        a, b = nodes[cell], nodes[cell + 1]
        t = ((v[rows] - v[a]) / (v[b] - v[a]))[:, None]
        start, end = at_nodes[cell], np.take_along_axis(at_nodes[cell + 1], steps[cell], axis=1)
        s = start + t * (end - start)                                 # (q, m) guesses
        s = guess = np.where(s.imag == 0, s.real + 0j, s)
        c = interpolation_matrix(v[nodes], v[rows], width) @ _poly_from_roots(at_nodes)   # (q, m + 1)
        columns = [c[:, j:j + 1].astype(complex) for j in range(m + 1)]   # (q, 1) each, cast once
        p, dp = np.empty(s.shape, dtype=complex), np.empty(s.shape, dtype=complex)
        for _ in range(FILL_ITERATIONS):
            p[...], dp[...] = columns[0], 0.0
            for j in range(1, m + 1):                                 # Horner: p and p' at once, in place
                dp *= s
                dp += p
                p *= s
                p += columns[j]
            step = p / dp
            s = s - step
        ok = np.all(np.abs(step) <= FILL_TOL * (1 + np.abs(s)), axis=1)
        ok &= np.abs(s.sum(axis=1).real + c[:, 1]) <= 1e-10 * (1 + np.abs(s).sum(axis=1))
        ok &= np.all(np.isfinite(s), axis=1)
        values[rows] = np.where(s.imag == 0, s.real + 0j, s)
        rest = np.union1d(rest, rows[~ok])
        filled = np.zeros(n, dtype=bool)
        filled[rows[ok]] = True
        node = ~between
        candidates[filled[1:] & (filled[:-1] | node[:-1])] = np.arange(m)      # inside a cell: same column
        last = np.flatnonzero(filled[:-1] & node[1:])                            # onto the cell's end
        candidates[last] = steps[np.searchsorted(nodes, last, side="right") - 1]
        proven = _proven_cells(v, nodes, at_nodes, sep, steps, rows, cell, t[:, 0], ok, np.abs(s - guess), proven)
    if len(rest):
        values[rest] = _plain_values(A[rest])
    return values, candidates, proven


def _proven_cells(v, nodes, at_nodes, sep, steps, rows, cell, t, ok, deviation, proven):
    """``proven`` with every step of each cell of LAPACK speeds set whose continued roots are certain
    steps of :func:`checked_steps` by a bound, without their distances (``sep``: the squared distances
    to the nearest other root at the LAPACK speeds, :func:`_nearest_other` of ``at_nodes``).

    In a cell whose ends are a certain step (every root moves by ``move_i < R_i / 4``, ``R_i`` its
    distance to the nearest other root at either end), the straight lines between the roots' ends
    stay at least ``R_i / 2`` apart; each continued root is at most ``delta`` (the cell's largest
    distance from its line) off it, so at every speed of the cell the nearest other root is at
    least ``R_i / 2 - 2 delta`` away, and a root moves by at most ``move_i dt + 2 delta`` per step
    (``dt`` the cell's largest step as a fraction of it).  Where ``move_i dt + 2.5 delta < R_i / 8``
    for every root, each step moves every root by less than a quarter of its distance to the
    nearest other root: the test of :func:`checked_steps` holds."""
    starts = np.flatnonzero(np.r_[True, cell[1:] != cell[:-1]])
    which = cell[starts]
    first = np.zeros(len(rows), dtype=bool)
    first[starts] = True
    before = np.where(first, 0.0, np.r_[0.0, t[:-1]])
    ends = np.r_[starts[1:], len(rows)] - 1
    dt = np.maximum(np.maximum.reduceat(t - before, starts), 1.0 - t[ends])
    delta = np.maximum.reduceat(deviation.max(axis=1), starts)
    settled = np.logical_and.reduceat(ok, starts)
    end = np.take_along_axis(at_nodes[which + 1], steps[which], axis=1)
    move = np.abs(end - at_nodes[which])
    room = np.sqrt(np.minimum(sep[which], np.take_along_axis(sep[which + 1], steps[which], axis=1)))
    sure = settled & np.all(move * dt[:, None] + 2.5 * delta[:, None] < room / 8, axis=1)
    edges = np.zeros(len(proven) + 1)
    np.add.at(edges, nodes[which[sure]], 1.0)
    np.add.at(edges, nodes[which[sure] + 1], -1.0)
    return proven | (np.cumsum(edges)[:-1] > 0)


def checked_steps(values, candidates, proven=None):
    """``(steps, certain)`` as :func:`nearest_steps` gives them, where ``candidates`` (n - 1, m) proposes
    each root's successor (-1: none) and ``proven`` marks proposals known to be certain: another is
    certain under the same test (every root moves by
    less than :data:`CERTAIN_MOVE` of its distance to the nearest other root at either speed: then it
    is also every root's nearest successor), without the distances to every other root's successor."""
    n, m = values.shape
    steps = np.array(candidates)
    certain = np.zeros(max(n - 1, 0), dtype=bool) if proven is None else np.array(proven)
    proposed = np.flatnonzero((steps[:, 0] >= 0) & ~certain)
    if len(proposed):
        re, im = values.real, values.imag
        rows = np.unique(np.concatenate([proposed, proposed + 1]))
        sep = np.empty((n, m))
        sep[rows] = _nearest_other(values[rows])
        k, to = proposed, steps[proposed]
        nxt = np.take_along_axis(values[k + 1], to, axis=1)
        move = (nxt.real - re[k]) ** 2 + (nxt.imag - im[k]) ** 2
        room = np.minimum(sep[k], np.take_along_axis(sep[k + 1], to, axis=1))
        certain[k] = (move < CERTAIN_MOVE ** 2 * room).all(axis=1)
    other = np.flatnonzero(~certain)
    if len(other):
        steps[other], certain[other] = nearest_steps(values, other)
    return steps, certain


@dataclass(frozen=True, eq=False)
class TrackedSweep:
    """Eigenvalues (n, m) at speeds (n,) in LAPACK's column order, the tracked order (n, m) (as
    :func:`~bikemass.analysis.engine.tracking.track` gives it), and the unit eigenvectors (r, N, m) at
    the rows ``rows`` (r,) where they were needed (columns as ``values``)."""

    speeds: np.ndarray
    values: np.ndarray
    order: np.ndarray
    rows: np.ndarray
    vectors: np.ndarray

    def vectors_at(self, row):
        """Unit eigenvectors (N, m) at ``row`` (one of :attr:`rows`), columns as ``values[row]``."""
        return self.vectors[int(np.searchsorted(self.rows, row))]


def tracked_sweep(model, speeds, need=()):
    """:class:`TrackedSweep` of ``model`` at ``speeds`` (m/s), with eigenvectors at the rows ``need``.

    The same order as :func:`~bikemass.analysis.engine.tracking.track` on :func:`eigen_sweep`, at a
    fraction of its cost: the eigenvalues at every speed (LAPACK without eigenvectors), each step where
    the roots stay far apart for their motion (:func:`nearest_steps`: nearly all) taken as its nearest
    successors, and only the other steps (roots that meet, cross or split) given eigenvectors at both
    ends and assigned by :func:`~bikemass.analysis.engine.tracking.track`'s costs.  ``None`` where an
    eigenvalue is not finite (the caller takes :func:`eigen_sweep`)."""
    v = np.atleast_1d(np.asarray(speeds, dtype=float))
    A = _AtSpeeds(model, v)
    values, candidates, proven = filled_values(model, v, A)
    if not np.all(np.isfinite(values)):
        return None
    n, m = values.shape
    done = np.zeros(n, dtype=bool)
    steps, certain = checked_steps(values, candidates, proven)
    hard = np.flatnonzero(~certain)
    done[np.asarray(need, dtype=int)] = True
    done[hard], done[hard + 1] = True, True
    rows = np.flatnonzero(done)
    w, X = np.linalg.eig(A[rows])
    if not (np.all(np.isfinite(w)) and np.all(np.isfinite(X))):
        return None
    # each eigenvector put in the column of its root (the roots found without vectors stay: the steps
    # found on them hold)
    vectors = np.take_along_axis(X.astype(complex, copy=False), _matched(values[rows], w)[:, None, :], axis=2)
    return TrackedSweep(v, values, _composed(steps, hard, rows, values, vectors), rows, vectors)


def _composed(steps, hard, rows, values, vectors):
    """The tracked order (n, m) of the steps (n - 1, m) of a sweep, with the uncertain steps ``hard``
    assigned by :func:`~bikemass.analysis.engine.tracking.track`'s costs on the eigenvectors
    ``vectors`` (r, N, m) at ``rows`` (r,; both ends of every hard step among them)."""
    n, m = values.shape
    if len(hard):
        wanted = np.zeros(n, dtype=bool)
        wanted[hard] = True                                      # rows[p] hard: rows[p + 1] is its next row
        sub = track(values[rows], vectors, wanted[rows[:-1]])
        at = np.searchsorted(rows, hard)
        for k, p in zip(hard, at):
            steps[k][sub[p]] = sub[p + 1]
    order = np.empty((n, m), dtype=int)
    current, start = np.arange(m), 0
    for k in np.flatnonzero((steps != np.arange(m)).any(axis=1)):
        order[start:k + 1] = current
        current, start = steps[k][current], k + 1
    order[start:] = current
    return order


def _steps_kept(values):
    """:func:`nearest_steps` of a whole sweep ``values`` (n, m) whose roots mostly keep their columns
    (the quartic's closed form): each step that keeps every column with every root moving by less
    than :data:`CERTAIN_MOVE` of its distance to the nearest other root at either speed is certain
    as it is (each root's nearest successor is then its own column); only the other steps are
    searched."""
    n, m = values.shape
    d = values[1:] - values[:-1]
    move = d.real * d.real + d.imag * d.imag
    sep = _nearest_other(values)
    room = CERTAIN_MOVE ** 2 * np.minimum(sep[1:], sep[:-1])
    certain = move[:, 0] < room[:, 0]
    for j in range(1, m):                          # .all(axis=1), column by column (a short axis)
        certain &= move[:, j] < room[:, j]
    steps = np.empty((max(n - 1, 0), m), dtype=int)
    steps[:] = np.arange(m)
    other = np.flatnonzero(~certain)
    if len(other):
        steps[other], certain[other] = nearest_steps(values, other, sep)
    return steps, certain


def quartic_tracked_sweep(model, speeds, need=()):
    """``(sweep, C, K)``: :class:`TrackedSweep` of a model on the quartic path
    (:func:`has_quartic_path`) at ``speeds`` (m/s), with eigenvectors at the rows ``need``, and its
    damping and stiffness matrices (n, 2, 2) there (for :func:`quartic_vectors` at any other row);
    ``None`` where a root is not finite (the caller takes :func:`eigen_sweep`).

    The same order as :func:`~bikemass.analysis.engine.tracking.track` on :func:`eigen_sweep`: the
    quartic's roots at every speed, each step where every root moves by less than
    :data:`CERTAIN_MOVE` of its distance to the nearest other root (:func:`nearest_steps`: nearly all)
    taken as its nearest successors, and only the other steps (roots that meet, cross or split)
    given eigenvectors at both ends and assigned by ``track``'s costs."""
    v = np.atleast_1d(np.asarray(speeds, dtype=float))
    mech = model.mechanics
    C, K = mech.damping(v), mech.stiffness(v)
    s = quartic_roots(_det2_poly(np.broadcast_to(mech.M, v.shape + (2, 2)), C, K))
    if not np.all(np.isfinite(s)):
        return None
    n = len(v)
    steps, certain = _steps_kept(s)
    hard = np.flatnonzero(~certain)
    done = np.zeros(n, dtype=bool)
    done[np.asarray(need, dtype=int)] = True
    done[hard], done[hard + 1] = True, True
    rows = np.flatnonzero(done)
    vectors = quartic_vectors(mech.M, C[rows], K[rows], s[rows])
    return TrackedSweep(v, s, _composed(steps, hard, rows, s, vectors), rows, vectors), C, K


def matched_vectors(model, speeds, values):
    """Unit eigenvectors (n, N, m) of ``model`` at ``speeds`` (m/s) whose column ``c`` belongs to the
    eigenvalue ``values[:, c]`` (the nearest of LAPACK's at each speed; each once)."""
    w, X = np.linalg.eig(model.dynamic_matrix(np.asarray(speeds, dtype=float)))
    return np.take_along_axis(X.astype(complex, copy=False), _matched(values, w)[:, None, :], axis=2)


def _matched(values, w):
    """``pick`` (k, m): for each row, the column of ``w`` (k, m) holding the root of each column of
    ``values`` (the nearest, each once; the least total distance where nearest ones collide)."""
    d = np.abs(values[:, :, None] - w[:, None, :])                # our column c -> LAPACK's column j
    pick = np.argmin(d, axis=2)
    bad = np.flatnonzero(~(np.sort(pick, axis=1) == np.arange(values.shape[1])).all(axis=1))
    if len(bad):
        pick[bad] = assignments(d[bad])
    return pick
