"""Critical speeds of a whole chunk of configurations of any model at once: the batch path of a sweep.

:func:`~bikemass.analysis.engine.critical.critical_speeds` takes one model at a time (polynomial
eigenvalue problems of the compound matrices, the modes followed from standstill to name the
crossings: about 15 ms for the tyre model).  :func:`batch_critical_speeds` takes B configurations'
dynamic coefficients ``A(v) = sum_k v**k P[k]`` stacked as (B, d + 1, n, n) and finds, for every
row, the numbers a sweep's row holds: the first crossing of the weave, the first real crossing
(capsize), and the first strictly stable range, in arrays:

1. **The characteristic polynomial as polynomials in speed.**  ``det(s I - A(v)) = sum_j a_j(v) s**j``
   with each ``a_j`` a polynomial in ``v``, by the Faddeev-LeVerrier recursion on matrix polynomials
   (``M_k = M_(k-1) A + a_(n-k+1) I``, ``a_(n-k) = -tr(M_k A) / k``: batched matrix products only),
   after one diagonal similarity per row that evens out the states' scales (the tyres' forces beside
   angles); :data:`CHUNK` rows at a time, with step 2, so that the temporaries stay in the cache.
2. **Routh's array on a speed grid.**  At every speed of a grid on ``(0, hi]`` the Routh array of
   the polynomial (elementwise over rows and speeds) tells whether the speed is stable (its first
   column finite and positive: no root with ``Re >= 0``) and gives the sign of the Hurwitz determinant ``H_(n-1)`` (the
   product of that column: zero exactly where two roots sum to zero, a pair on the imaginary
   axis); ``a_0 = det(-A)`` is zero where a real root passes through zero.  A sign change of
   ``a_0`` or ``H_(n-1)`` between two grid speeds brackets a crossing.
   A grid speed where ``|a_0|`` or ``|H_(n-1)|`` dips without a sign change is searched (golden
   section on the polynomial) for a pair of crossings hidden inside two grid steps.
   The search of a dip ends as soon as that dip is decided (:func:`_split_dips`).
3. **Refinement** of each bracket: the Illinois method on the polynomial (``a_0`` or ``H_(n-1)``)
   to :data:`REAL_TOL` or :data:`PAIR_TOL`, Newton's method on the polynomial itself (``a_0(v)``, or the
   characteristic polynomial at ``s = i w`` in ``(v, w)``, starting from ``w**2`` of Routh's
   auxiliary polynomial), then Newton's method on the matrices themselves, to the engine's
   accuracy: ``det A(v) = 0`` for a real crossing; ``det(i w I - A(v)) = 0`` in ``(v, w)`` for a pair
   (the log-derivative ``tr((i w I - A)^-1 dA)`` of the determinant, Lancaster 1964); its first step
   within :data:`FINAL_STEP` ends it, one solve a crossing.  A bracket of ``H_(n-1)`` whose
   auxiliary ``w**2`` is negative is a real pair ``l, -l`` (no root on the axis) and is dropped, as
   the engine drops it.
4. **Counts between crossings** (Routh's array at each midpoint, as the engine counts eigenvalues
   there) give the stable ranges.  Only the crossings that can change a row's numbers are refined:
   each kind's first, and every one before the grid's first stable run ends (the rest, a wobble at
   25 m/s, when the first weave crossing is among those refined).
5. **Naming a pair.**  The engine names a crossing by the tracked mode it continues; a batch does
   not follow modes, so it names only what is unambiguous: a pair slower than
   :data:`WEAVE_MAX_FREQUENCY` (3 Hz) with at least :data:`WEAVE_SHARE` of its participation factors
   ``|x_k y_k|`` (right and left null vectors of ``i w I - A(v)``: the diagonal of its inverse near
   the root) on the bicycle's states is the weave; so is a faster pair with that share that is the
   slowest oscillation of ``A(v)`` there while a faster one lies in the wobble band (the weave is the
   slower of the two wherever both oscillate: the eigenvalues of ``A(v)`` at that one speed).  Any
   other pair before a row's first weave crossing leaves the row undecided (the wobble crosses at
   3.7-9 Hz, and a weave crossing at high speed may reach 5 Hz: only the modes followed from
   standstill tell them apart there).

A row is **decided** only when every step is clean: every Routh array finite, every refinement
converged, no dip of ``|a_0|`` or ``|H_(n-1)|`` whose least value is too near zero to tell whether
it crosses (:data:`AMBIGUOUS`), every pair up to the first weave crossing named.  The
caller takes every other row through the engine (:func:`critical_speeds`), the reference this
path is tested against (tests/test_sweep_members.py: rows equal to 1e-9 m/s).
"""

import numpy as np

from .naming import BICYCLE, WOBBLE_MAX_FREQUENCY, WOBBLE_MIN_FREQUENCY

GRID_STEP = 0.5
"""Speed step (m/s) of the grid on which crossings are bracketed."""
WEAVE_MAX_FREQUENCY = WOBBLE_MIN_FREQUENCY
"""Highest frequency (rad/s, 3 Hz) of a crossing pair the batch names the weave: the engine names no pair
below it wobble (:data:`~bikemass.analysis.engine.naming.WOBBLE_MIN_FREQUENCY`).  Measured with the engine's
names (tests/test_sweep_members.py): first weave crossings of the tyre, rider-lean and rider-lean+tyre
models of perturbed benchmark and Jamis sets at 0.2-1.4 Hz, wobble crossings at 5.2-8.8 Hz."""
WEAVE_SHARE = 0.4
"""Least share of a crossing pair's participation on the bicycle's states for the batch to name it the
weave (measured: 0.48-0.95 at the weave crossings of those models)."""
REAL_TOL = 1e-4
"""Relative width (of ``1 + v``) to which the Illinois method brackets a real crossing on ``a_0(v)``;
Newton's method on that polynomial then takes it to within :data:`FINAL_STEP`, and one step of Newton's
method on the matrices confirms it."""
PAIR_TOL = 1e-6
"""Relative width to which the Illinois method brackets a pair's crossing on ``H_(n-1)`` (a product of
Routh's column: rounding noise within about 1e-7 m/s of its root).  Not wider: ``w**2`` of Routh's
auxiliary polynomial, the start in ``w``, can be far off (30.9 rad/s for 23.0 at 1.4e-6 m/s from the
root), and Newton's method on the matrices from a start 1e-4 away then failed on 6 of 300 perturbed
Jamis sets with the rider-lean+tyre model (a crossing at 18.9 m/s, and one at 29.9 m/s at 0.2 rad/s
that went to the capsize root instead)."""
FINAL_STEP = 1e-8
"""A Newton step smaller than this (relative to ``1 + v``) is the last: Newton's method converges
quadratically, so the speed after it is exact to rounding (about 1e-16 relative), and the matrix is
not evaluated at the root itself, where it is singular."""


def balance_rows(P):
    """``D^-1 P[k] D`` for each row (B, d + 1, n, n): a diagonal similarity per row (powers of 2,
    two sweeps of Osborne's iteration on ``sum_k |P[k]|``) that evens out the scales of the
    states; every eigenvalue at every speed is unchanged."""
    S = np.abs(P[:, 0])                                        # (B, n, n)
    for k in range(1, P.shape[1]):
        S += np.abs(P[:, k])
    B, n = S.shape[0], S.shape[-1]
    S[:, np.arange(n), np.arange(n)] = 0.0                      # off the diagonal only
    St = np.ascontiguousarray(np.swapaxes(S, 1, 2))             # St[:, i] = column i of S
    d = np.ones((B, n))
    for _ in range(2):
        for i in range(n):
            # column i's and row i's off-diagonal sums of D^-1 S D: d_i sum_k S[k, i] / d_k, sum_k S[i, k] d_k / d_i
            c = d[:, i] * np.einsum("bk,bk->b", St[:, i], 1.0 / d)
            r = np.einsum("bk,bk->b", S[:, i], d) / d[:, i]
            with np.errstate(divide="ignore", invalid="ignore"):
                f = np.where((c > 0) & (r > 0), np.exp2(np.round(0.5 * np.log2(r / c))), 1.0)
            d[:, i] *= f
    return P * (d[:, None, :] / d[:, :, None])[:, None]


CHUNK = 128
"""Rows whose characteristic polynomials are computed together: the recursion's matrices of 128 rows
(about 0.5 MB) stay in the cache (measured on the tyre model: 9 us a row in chunks of 64-256, 11-19 in
one chunk of 1,024)."""


def characteristic(P):
    """Coefficients ``a`` (B, n + 1, n d + 1) of ``det(s I - A(v)) = sum_j sum_i a[:, j, i] s**j v**i``
    for ``A(v) = sum_k v**k P[:, k]`` (Faddeev-LeVerrier on matrix polynomials: ``M_1 = I``,
    ``a_(n-k) = -tr(M_k A) / k``, ``M_(k+1) = M_k A + a_(n-k) I``), :data:`CHUNK` rows at a time."""
    B, d1, n, _ = P.shape
    a = np.zeros((B, n + 1, n * (d1 - 1) + 1))
    for start in range(0, B, CHUNK):
        _characteristic(P[start:start + CHUNK], a[start:start + CHUNK])
    return a


def _characteristic(P, a):
    """:func:`characteristic` of rows ``P`` into ``a``.  ``M_k`` commutes with ``A``, so the recursion
    takes ``M_k A``; ``M_k`` is held tall, its coefficients of ``v**0 .. v**deg`` one under the other
    (B, (deg + 1) n, n), so that ``M_k P[:, i]`` is one matrix product a row (not one for each power of
    ``v``: 20 % less time) and its trace and the added ``a_(n-k) I`` are strided views of the diagonals.
    The last two coefficients need only traces: ``a_1 = -tr(M_(n-1) A) / (n - 1)`` and, as
    ``M_n = M_(n-1) A + a_1 I``, ``a_0 = -(tr(M_(n-1) A**2) + a_1 tr A) / n``, sums of elementwise
    products with ``A`` and ``A**2`` in place of the two largest products (a third of the work)."""
    B, d1, n, _ = P.shape
    d = d1 - 1
    a[:, n, 0] = 1.0
    Ps = [np.ascontiguousarray(P[:, i]) for i in range(d1)]             # (B, n, n)
    W = np.broadcast_to(np.eye(n), (B, n, n))                            # M_1 = I, degree 0 in v
    for k in range(1, n - 1):
        p = W.shape[1] // n                                              # powers of v in M_k
        AW = np.empty((B, (p + d) * n, n))
        np.matmul(W, Ps[0], out=AW[:, :p * n])
        AW[:, p * n:] = 0.0
        for i in range(1, d1):
            AW[:, i * n:(i + p) * n] += W @ Ps[i]
        diagonal = AW.reshape(B, p + d, n * n)[:, :, ::n + 1]
        c = diagonal.sum(axis=2) * (-1.0 / k)
        a[:, n - k, :p + d] = c
        diagonal += c[:, :, None]
        W = AW
    p = W.shape[1] // n                                                  # W = M_(n-1)
    flat = np.ascontiguousarray(np.broadcast_to(W, (B, p * n, n))).reshape(B, p, n * n)

    def traces(X):                                                       # tr(M_(n-1)[j] X) (B, p)
        return (flat @ np.swapaxes(X, 1, 2).reshape(B, n * n, 1))[..., 0]
    last = np.zeros((B, p + d))
    for i in range(d1):
        last[:, i:i + p] += traces(Ps[i])
    a1 = last * (-1.0 / max(n - 1, 1))
    if n == 1:
        a[:, 0, :p + d] = a1
        return
    a[:, 1, :p + d] = a1
    squared = np.zeros((B, p + 2 * d))
    for i in range(d1):
        for j in range(d1):
            squared[:, i + j:i + j + p] += traces(Ps[i] @ Ps[j])
        squared[:, i:i + p + d] += a1 * np.trace(Ps[i], axis1=1, axis2=2)[:, None]
    a[:, 0, :p + 2 * d] = squared * (-1.0 / n)


def _powers(v, degree, slope=False):
    """``v**i`` (..., degree + 1) of speeds ``v`` (...), or their derivatives ``i v**(i-1)`` if ``slope``."""
    X = np.empty(v.shape + (degree + 1,))
    X[..., 0] = 1.0
    for i in range(1, degree + 1):
        np.multiply(X[..., i - 1], v, out=X[..., i])
    if slope:
        X[..., 1:] = X[..., :-1] * np.arange(1, degree + 1)
        X[..., 0] = 0.0
    return X


def at_speeds(a, rows, v, j=None):
    """``a_j(v)`` (n + 1, ...) of rows ``rows`` (K,) of the coefficients ``a`` (B, n + 1, D + 1) at speeds
    ``v`` (K,) or (K, W): one stacked product of each row's coefficients with the powers of its speeds
    (half the time of Horner's steps on so few numbers); only ``a_j`` (1, ...) if ``j`` is given."""
    g = a[rows] if j is None else a[rows, j:j + 1]                        # (K, n + 1, D + 1)
    X = _powers(v, a.shape[2] - 1)
    if v.ndim == 1:
        return np.swapaxes(g @ X[:, :, None], 0, 1)[..., 0]
    return np.moveaxis(g @ np.swapaxes(X, 1, 2), 1, 0)


def _with_slope(a, rows, v, j=None):
    """:func:`at_speeds` of speeds ``v`` (K,) and the coefficients' derivatives in ``v``: ``(a_j, da_j/dv)``."""
    g = a[rows] if j is None else a[rows, j:j + 1]
    D = a.shape[2] - 1
    X = np.stack([_powers(v, D), _powers(v, D, slope=True)], axis=2)   # (K, D + 1, 2)
    c = np.moveaxis(g @ X, 1, 0)                                          # (n + 1, K, 2)
    return c[..., 0], c[..., 1]


def _polish_real(a, rows, v, steps=3):
    """Newton's method on the polynomial ``a_0(v)`` from ``v`` (K,): the start of :func:`_newton_real`
    on the matrices, near enough for one step of it (its first step then within :data:`FINAL_STEP`)."""
    for _ in range(steps):
        c, dc = _with_slope(a, rows, v, 0)
        with np.errstate(all="ignore"):
            step = c[0] / dc[0]
        v = np.where(np.isfinite(step), v - step, v)
    return v


def _polish_pair(a, rows, v, w, steps=3):
    """Newton's method on the characteristic polynomial ``p(i w; v) = 0`` in ``(v, w)`` (both real) from
    ``(v, w)`` (K,): the start of :func:`_newton_pair` on the matrices, near enough for one step of it
    where ``H_(n-1)``'s rounding would leave it 1e-7 away."""
    n = a.shape[1] - 1
    for _ in range(steps):
        c, dc = _with_slope(a, rows, v)
        z = 1j * w
        p, ps, pv = c[n] + 0j, np.zeros(len(v), dtype=complex), dc[n] + 0j
        for j in range(n - 1, -1, -1):
            ps = ps * z + p
            p = p * z + c[j]
            pv = pv * z + dc[j]
        gw = 1j * ps
        with np.errstate(all="ignore"):
            det = pv.real * gw.imag - pv.imag * gw.real          # pv dv + gw dw = -p, dv and dw real
            dv = (p.imag * gw.real - p.real * gw.imag) / det
            dw = (p.real * pv.imag - p.imag * pv.real) / det
        good = np.isfinite(dv) & np.isfinite(dw)
        v, w = np.where(good, v + dv, v), np.where(good, w + dw, w)
    return v, w


def routh(c):
    """``(count, hurwitz, w2)`` of polynomials with ascending coefficients ``c`` (..., n + 1):
    the number of roots with ``Re > 0`` (int, -1 where the array breaks down), ``H_(n-1)`` (the
    product of the first column after its leading 1, the polynomial made monic) and ``w**2`` of the
    auxiliary polynomial of the ``s**2`` row (where ``H_(n-1) = 0`` the pair on the axis is ``+-i w``)."""
    return routh_rows(np.moveaxis(c, -1, 0))


def routh_rows(c, only_hurwitz=False, stable=False):
    """:func:`routh` of coefficients held first (n + 1, ...), ascending: each row of Routh's array is
    an (entries, ...) array, and each new row ``a[1:] - (a_0 / b_0) b[1:]`` of the two above it two
    operations on all its entries at once.  ``only_hurwitz``: ``H_(n-1)`` alone (the rows up to the
    ``s**1`` row, no count: what the Illinois method and a dip's search evaluate); ``stable``:
    ``(stable, H_(n-1))``, no roots with ``Re >= 0`` (the whole first column finite and positive) in
    place of the count (what the grid needs)."""
    n = c.shape[0] - 1
    shape = c.shape[1:]
    with np.errstate(divide="ignore", invalid="ignore"):
        desc = c[::-1] / c[n] if not np.all(c[n] == 1) else c[::-1]      # s**n first, monic
        first = np.empty((n + 1,) + shape)                                 # the array's first column
        first[0] = 1.0
        w2 = np.full(shape, np.nan)
        upper, lower = desc[0::2], desc[1::2]                              # the s**n and s**(n-1) rows
        first[1] = lower[0]
        for k in range(2, n if only_hurwitz else n + 1):
            new = np.empty((len(upper) - 1,) + shape)
            tail = min(len(lower) - 1, len(new))
            if tail:
                np.multiply(upper[0] / lower[0], lower[1:1 + tail], out=new[:tail])
                np.subtract(upper[1:1 + tail], new[:tail], out=new[:tail])
            new[tail:] = upper[1 + tail:]
            first[k] = new[0]
            if k == n - 2:                                                 # the s**2 row: new[0] s**2 + new[1]
                w2 = new[1] / new[0]
            upper, lower = lower, new
        hurwitz = np.prod(first[1:n], axis=0)
        if only_hurwitz:
            return hurwitz
        if stable:
            return np.all(first > 0, axis=0) & np.isfinite(first[n]) & np.isfinite(hurwitz), hurwitz
        sign = np.signbit(first)
        changes = np.count_nonzero(sign[1:] != sign[:-1], axis=0)
        ok = np.all(np.isfinite(first) & (first != 0), axis=0)
    return np.where(ok, changes, -1), hurwitz, w2


def _matrix(P, v):
    """``A(v)`` (K, n, n) of rows ``P`` (K, d + 1, n, n) at speeds ``v`` (K,)."""
    A = P[:, -1].copy()
    for k in range(P.shape[1] - 2, -1, -1):
        A = A * v[:, None, None] + P[:, k]
    return A


def _derivative(P, v):
    """``dA/dv`` (K, n, n) at speeds ``v``."""
    d = P.shape[1] - 1
    D = np.zeros(P.shape[:1] + P.shape[2:])
    for k in range(d, 0, -1):
        D = D * v[:, None, None] + k * P[:, k]
    return D


def _solve(A, D):
    """``A^-1 D`` of stacked matrices (``D`` None: ``A^-1``), ``nan`` in the rows where ``A`` is singular
    (numpy refuses a whole stack for one singular matrix: those rows are found by their determinants,
    zero exactly where LAPACK's factorisation meets a zero pivot, and the others solved again)."""
    with np.errstate(all="ignore"):
        try:
            return np.linalg.inv(A) if D is None else np.linalg.solve(A, D)
        except np.linalg.LinAlgError:
            pass
        out = np.full(A.shape if D is None else D.shape, np.nan, dtype=np.result_type(A, D))
        det = np.linalg.det(A)
        good = np.flatnonzero(np.isfinite(det) & (det != 0))
        if len(good) == len(A):                  # no zero determinant: halve the stack until the row is alone
            if len(A) == 1:
                return out
            half = len(A) // 2
            return np.concatenate([_solve(A[:half], None if D is None else D[:half]),
                                   _solve(A[half:], None if D is None else D[half:])])
        if len(good):
            out[good] = _solve(A[good], None if D is None else D[good])
        return out


def _illinois(f, a, b, fa, fb, iterations=30, tol=1e-7):
    """Roots of ``f(rows, x)`` (vectorised over brackets) in brackets ``[a, b]`` with ``fa``, ``fb`` of
    opposite signs, to ``tol (1 + |x|)``: each iteration evaluates only the brackets still open.  A
    bracket whose same end is kept three times running is halved instead (the ends' values 10**17
    apart, ``H_(n-1)`` from standstill to 0.5 m/s: the Illinois method's halving of one value took 60
    iterations there)."""
    a, b, fa, fb = a.copy(), b.copy(), fa.copy(), fb.copy()
    kept = np.zeros(len(a), dtype=np.int64)
    active = np.arange(len(a))
    for _ in range(iterations):
        A, B, FA, FB = a[active], b[active], fa[active], fb[active]
        with np.errstate(all="ignore"):
            x = np.where(FB != FA, B - FB * (B - A) / (FB - FA), 0.5 * (A + B))
        x = np.where((x > np.minimum(A, B)) & (x < np.maximum(A, B)) & (kept[active] < 3), x, 0.5 * (A + B))
        fx = f(active, x)
        same = np.signbit(fx) == np.signbit(FB)
        # Illinois: halve the retained end's value when the same end is kept twice
        fa[active], a[active] = np.where(same, FA * 0.5, FB), np.where(same, A, B)
        b[active], fb[active] = x, fx
        kept[active] = np.where(same, kept[active] + 1, 0)
        active = active[(np.abs(x - a[active]) > tol * (1 + np.abs(x))) & (fx != 0)]
        if not len(active):
            break
    return b


def _newton_real(P, v, steps=4):
    """``(v, converged)``: Newton's method on ``det A(v) = 0`` (rows ``P``, starts ``v``)."""
    v = v.copy()
    done, stuck = np.zeros(len(v), dtype=bool), np.zeros(len(v), dtype=bool)
    for _ in range(steps):
        rows = np.flatnonzero(~done)
        if not len(rows):
            break
        p, x = P[rows], v[rows]
        g = np.trace(_solve(_matrix(p, x), _derivative(p, x)), axis1=1, axis2=2)       # d log det / dv
        with np.errstate(all="ignore"):
            step = 1.0 / g
        good = np.isfinite(step)
        v[rows] = np.where(good, x - step, x)
        # no step: A(x) singular to working precision (x is the root) or a derivative of zero (a double root)
        done[rows] = ~good | (np.abs(step) <= FINAL_STEP * (1 + np.abs(x)))
        stuck[rows] = ~good & (g == 0)
    return v, done & ~stuck & np.isfinite(v)


def _newton_pair(P, v, w, steps=6):
    """``(v, w, converged, diagonal)``: Newton's method on ``det(i w I - A(v)) = 0`` in ``(v, w)``
    (log-derivatives), and ``|diag((i w I - A(v))^-1)|`` (K, n) at each row's last iterate, next to the
    root: proportional to the participation factors ``|x_k y_k|`` of the pair (``nan`` where not found)."""
    v, w = v.copy(), w.copy()
    eye = np.eye(P.shape[-1])
    done = np.zeros(len(v), dtype=bool)
    diagonal = np.full((len(v), P.shape[-1]), np.nan)
    for _ in range(steps):
        rows = np.flatnonzero(~done)
        if not len(rows):
            break
        p, x, y = P[rows], v[rows], w[rows]
        X = _solve(1j * y[:, None, None] * eye - _matrix(p, x), None)
        with np.errstate(all="ignore"):
            gv = -np.einsum("kij,kji->k", X, _derivative(p, x))     # d log det / dv
            gw = 1j * np.trace(X, axis1=1, axis2=2)                   # d log det / dw
            det = gv.real * gw.imag - gv.imag * gw.real               # gv dv + gw dw = -1, dv and dw real
            dv, dw = -gw.imag / det, gv.imag / det
        good = np.isfinite(dv) & np.isfinite(dw)
        diagonal[rows] = np.abs(np.diagonal(X, axis1=1, axis2=2))
        v[rows], w[rows] = np.where(good, x + dv, x), np.where(good, y + dw, y)
        # no step: i w I - A(v) singular to working precision, (v, w) is the root
        singular = ~np.all(np.isfinite(X.reshape(len(rows), -1)), axis=1)
        done[rows] = (good & (np.abs(dv) <= FINAL_STEP * (1 + np.abs(x))) & (np.abs(dw) <= FINAL_STEP * (1 + np.abs(y)))) \
            | singular
    return v, w, done & np.isfinite(v) & np.isfinite(w), diagonal


def _share(P, v, w, bicycle, diagonal):
    """The participation of the bicycle's states (indices ``bicycle``) in the pair ``i w`` of ``A(v)``:
    ``|x_k y_k|`` summed, from the diagonal of ``(i w I - A(v))^-1`` next to the root (Newton's last
    iterate's, or where that was singular, at ``w (1 + 1e-7)``)."""
    again = ~np.all(np.isfinite(diagonal), axis=1)
    if again.any():
        n = P.shape[-1]
        M = 1j * (w[again] * (1 + 1e-7))[:, None, None] * np.eye(n) - _matrix(P[again], v[again])
        diagonal = diagonal.copy()
        diagonal[again] = np.abs(np.diagonal(_solve(M, None), axis1=1, axis2=2))
    return diagonal[:, list(bicycle)].sum(axis=1) / diagonal.sum(axis=1)


def _at_start(lo, v, ok, start):
    """Brackets of the grid's first cell (from ``start``) whose crossing is at the first grid speed or
    below it, or not found: the roots of an undamped model at standstill (on the axis at ``v = 0``,
    their real parts growing with ``v``), whose signs at the first grid speed are rounding.  The engine
    puts such a root at the span's start, where it is no crossing; so does the batch."""
    return (lo == start) & (~ok | (v <= 2 * start))


def _pairs(a, Pb, rows, lo, hi, flo, fhi, bicycle, decided, start):
    """``(rows, speeds, kinds)`` of the pair crossings in brackets ``[lo, hi]`` of ``H_(n-1)`` (kind 1 the
    weave, 3 not named; a bracket of a real pair ``l, -l`` dropped); rows whose refinement fails are
    marked undecided."""
    if not len(rows):
        return rows, lo, np.zeros(0, dtype=int)
    x = _illinois(lambda i, x: routh_rows(at_speeds(a, rows[i], x), True), lo, hi, flo, fhi, tol=PAIR_TOL)
    _, _, w2 = routh_rows(at_speeds(a, rows, x))
    pair = w2 > 0
    rows, x, w2, lo, hi = rows[pair], x[pair], w2[pair], lo[pair], hi[pair]
    if not len(rows):
        return rows, lo, np.zeros(0, dtype=int)
    v, w = _polish_pair(a, rows, x, np.sqrt(w2))
    near = np.isfinite(v) & np.isfinite(w) & (v > lo - 1e-6) & (v < hi + 1e-6) & (w > 0)
    v, w, ok, diagonal = _newton_pair(Pb[rows], np.where(near, v, x), np.where(near, w, np.sqrt(w2)))
    ok &= (v > lo - 1e-6) & (v < hi + 1e-6) & (w > 0)
    at_start = _at_start(lo, v, ok, start)
    decided[rows[~ok & ~at_start]] = False
    ok &= ~at_start
    share = _share(Pb[rows], v, w, bicycle, diagonal)
    name = np.where((w < WEAVE_MAX_FREQUENCY) & (share >= WEAVE_SHARE), 1, 3)    # 3: not named
    fast = np.flatnonzero((name == 3) & ok & (share >= WEAVE_SHARE))
    if len(fast):
        name[fast[_slowest_of_two(Pb[rows[fast]], v[fast], w[fast])]] = 1
    return rows[ok], v[ok], name[ok]


def _slowest_of_two(P, v, w):
    """Whether the pair ``i w`` on the axis at ``v`` is the slowest oscillation of ``A(v)`` while a faster
    one lies in the wobble band (:data:`~bikemass.analysis.engine.naming.WOBBLE_MIN_FREQUENCY` to
    :data:`~bikemass.analysis.engine.naming.WOBBLE_MAX_FREQUENCY`): then the weave, which is slower than
    the wobble wherever both oscillate, is the pair itself (K,) bool."""
    roots = np.linalg.eigvals(_matrix(P, v))
    upper = roots.imag > 1e-6 * (1 + np.abs(roots))
    own = np.abs(roots - 1j * w[:, None]) <= 1e-6 * (1 + w[:, None])
    others = upper & ~own
    slowest = ~np.any(others & (roots.imag <= w[:, None]), axis=1) & (own.sum(axis=1) == 1)
    band = others & (roots.imag >= WOBBLE_MIN_FREQUENCY) & (roots.imag <= WOBBLE_MAX_FREQUENCY)
    return slowest & band.any(axis=1)


def batch_critical_speeds(P, families, hi, step=GRID_STEP):
    """The critical speeds of B configurations at once (see the module docstring).

    Parameters
    ----------
    P : numpy.ndarray of shape (B, d + 1, n, n)
        Each row's dynamic coefficients: ``A(v) = sum_k v**k P[:, k]``.
    families : tuple of (str, tuple of int)
        The model's mode families (:attr:`~bikemass.models.linear.LinearModel.families`); the
        bicycle's states name the weave.
    hi : float
        Critical speeds on ``(0, hi]`` (m/s).
    step : float
        The bracketing grid's step (m/s).

    Returns
    -------
    dict
        ``{"weave_speed", "capsize_speed", "stable_from", "stable_to"}`` (B,) arrays (m/s, ``nan``
        where there is none) and ``"decided"`` (B,) bool: the rows whose numbers this path stands
        for (the others need the engine).

    Examples
    --------
    >>> import numpy as np, bikemass as bm
    >>> model = bm.Scenario("benchmark", model="tyre").build().model
    >>> out = batch_critical_speeds(np.asarray(model.dynamic_coefficients)[None], model.families, 30.0)
    >>> bool(out["decided"][0]), round(float(out["weave_speed"][0]), 4)
    (True, 4.3123)
    """
    P = np.asarray(P, dtype=float)
    B, n = P.shape[0], P.shape[-1]
    bicycle = dict(families).get(BICYCLE, tuple(range(min(4, n))))
    out = {k: np.full(B, np.nan) for k in ("weave_speed", "capsize_speed", "stable_from", "stable_to")}
    decided = np.all(np.isfinite(P.reshape(B, -1)), axis=1)
    if not B:
        out["decided"] = decided
        return out
    count_steps = max(2, int(np.ceil(hi / step)))
    grid = np.linspace(0.0, hi, count_steps + 1)
    grid[0] = min(1e-6 * (1 + hi), 0.5 * grid[1])
    # the characteristic polynomial and Routh's array on the grid, CHUNK rows at a time (their temporaries
    # stay in the cache: 2.5 us a row against 6.5 for the grid in one piece); the grid's product as
    # stacked products of small matrices (one large product starts BLAS's threads, whose waiting costs
    # more CPU than the product)
    a = np.zeros((B, n + 1, n * (P.shape[1] - 1) + 1))
    powers = np.ascontiguousarray((grid[:, None] ** np.arange(a.shape[2])).T)       # (D + 1, G)
    stable = np.empty((B, len(grid)), dtype=bool)
    H, a0 = np.empty((B, len(grid))), np.empty((B, len(grid)))
    with np.errstate(all="ignore"):
        Pb = balance_rows(np.where(decided[:, None, None, None], P, 0.0))
        for start in range(0, B, CHUNK):
            rows = slice(start, start + CHUNK)
            _characteristic(Pb[rows], a[rows])
            c = np.ascontiguousarray(np.moveaxis(a[rows] @ powers, 1, 0))         # (n + 1, rows, G)
            stable[rows], H[rows] = routh_rows(c, stable=True)
            a0[rows] = c[0]
    decided &= np.all(np.isfinite(H), axis=1) & np.all(np.isfinite(a0), axis=1)
    # the grid's first stable run [z, e): a crossing in a cell at or after e changes none of the row's
    # numbers once its first weave and real crossings are found (where no grid speed is stable, every one may)
    z = np.where(stable.any(axis=1), np.argmax(stable, axis=1), len(grid))
    after = ~stable & (np.arange(len(grid))[None, :] > z[:, None])
    e = np.where(after.any(axis=1), np.argmax(after, axis=1), len(grid))
    crossings = []                                   # (rows, speeds, kinds) of the refined crossings
    functions = {"real": lambda rows, x: at_speeds(a, rows, x, 0)[0],
                 "pair": lambda rows, x: routh_rows(at_speeds(a, rows, x), True)}
    skipped = np.zeros(B, dtype=bool)
    for kind, f in (("real", a0), ("pair", H)):
        sign = np.signbit(f)
        rows, cells = np.nonzero(sign[:, 1:] != sign[:, :-1])
        decided[rows[(f[rows, cells] == 0) | (f[rows, cells + 1] == 0)]] = False
        lo, hi_ = grid[cells], grid[cells + 1]
        flo, fhi = f[rows, cells], f[rows, cells + 1]
        first = np.r_[True, rows[1:] != rows[:-1]]             # each row's first bracket of this kind
        later = ~first & (cells + 1 > e[rows])
        extra = _split_dips(f, grid, functions[kind], decided)
        if extra is not None:
            rows, lo, hi_, flo, fhi = (np.concatenate([x, y]) for x, y in zip((rows, lo, hi_, flo, fhi), extra))
            dipped = np.zeros(B, dtype=bool)
            dipped[extra[0]] = True
            later = np.r_[later, np.zeros(len(extra[0]), dtype=bool)] & ~dipped[rows]     # such a row: every one
        keep = decided[rows]
        rows, lo, hi_, flo, fhi, later = rows[keep], lo[keep], hi_[keep], flo[keep], fhi[keep], later[keep]
        if kind == "real":
            skipped[rows[later]] = True
            now = ~later
            x = _illinois(lambda i, x, rows=rows, now=now: at_speeds(a, rows[now][i], x, 0)[0], lo[now], hi_[now], flo[now], fhi[now],
                          tol=REAL_TOL)
            v = _polish_real(a, rows[now], x)
            near = np.isfinite(v) & (v > lo[now] - 1e-6) & (v < hi_[now] + 1e-6)
            x, ok = _newton_real(Pb[rows[now]], np.where(near, v, x))
            ok &= (x > lo[now] - 1e-6) & (x < hi_[now] + 1e-6)
            at_start = _at_start(lo[now], x, ok, grid[0])
            decided[rows[now][~ok & ~at_start]] = False
            ok &= ~at_start
            crossings.append((rows[now][ok], x[ok], np.zeros(int(ok.sum()), dtype=int)))
            continue
        found = _pairs(a, Pb, rows[~later], lo[~later], hi_[~later], flo[~later], fhi[~later], bicycle, decided,
                       grid[0])
        crossings.append(found)
        # a row whose first weave is not among the pairs refined has the rest refined too
        named = np.zeros(B, dtype=bool)
        named[found[0][found[2] != 0]] = True
        again = later & ~named[rows]
        skipped[rows[later & ~again]] = True
        if again.any():
            crossings.append(_pairs(a, Pb, rows[again], lo[again], hi_[again], flo[again], fhi[again], bicycle,
                                    decided, grid[0]))
    # a row with crossings left out gets the grid speed e as an end (no crossing): the count between its last
    # crossing and e is that of the grid speed e, not stable, so the first stable range ends where it does
    rows = np.flatnonzero(skipped & (e < len(grid)))
    crossings.append((rows, grid[e[rows]], np.full(len(rows), -1)))
    _assemble(out, decided, crossings, a, hi, B)
    out["decided"] = decided
    return out


GOLDEN = 0.5 * (3 - np.sqrt(5))
DIP = 0.5
"""A grid speed where ``|f|`` is a local minimum below DIP times its larger neighbour, without a sign
change around it, is searched for a hidden pair of crossings."""
AMBIGUOUS = 1e-9
"""A dip's least ``|f|`` below this fraction of its neighbours' leaves the row undecided (a crossing
that only touches, or two too close to tell apart in the polynomial's rounding)."""


def _split_dips(f, grid, function, decided, iterations=48):
    """The brackets ``(rows, lo, hi, flo, fhi)`` of pairs of crossings hidden between grid speeds:
    at every dip of ``|f|`` (:data:`DIP`) the least ``s f`` (``s`` the sign around it) is found by a
    golden-section search of ``function(rows, speeds)`` on the two grid steps around it; where it is
    of the other sign the dip holds two crossings, one on each side of it.  Rows whose dip's least
    value is too close to zero to tell (:data:`AMBIGUOUS`) are marked undecided.  ``None`` if no dip.

    A dip's search ends when its least value is of the other sign by more than that margin, when its
    bracket is 1e-9 m/s wide, or when the four points of its bracket are convex and bound the least
    value above the margin (:func:`_convex_floor`): each search runs only as long as its own dip needs."""
    g = np.abs(f)
    left, mid, right = g[:, :-2], g[:, 1:-1], g[:, 2:]
    sign = np.signbit(f)
    same = (sign[:, :-2] == sign[:, 1:-1]) & (sign[:, 1:-1] == sign[:, 2:])
    rows, k = np.nonzero(same & (mid <= left) & (mid <= right) & (mid < DIP * np.maximum(left, right)))
    if not len(rows):
        return None
    s = np.where(sign[rows, k + 1], -1.0, 1.0)
    scale = np.maximum(left[rows, k], right[rows, k])
    margin = AMBIGUOUS * scale
    a, b = grid[k], grid[k + 2]
    fa, fb = s * f[rows, k], s * f[rows, k + 2]
    x1, x2 = a + GOLDEN * (b - a), b - GOLDEN * (b - a)
    f1, f2 = s * function(rows, x1), s * function(rows, x2)
    active = np.arange(len(rows))
    for _ in range(iterations):
        A, X1, X2, Bb, FA, F1, F2, FB = (y[active] for y in (a, x1, x2, b, fa, f1, f2, fb))
        least = np.minimum(F1, F2)
        done = (least < -margin[active]) | (Bb - A <= 1e-9 * (1 + Bb)) | \
            (_convex_floor(A, X1, X2, Bb, FA, F1, F2, FB) > 2 * margin[active])
        keep = ~done
        active = active[keep]
        if not len(active):
            break
        A, X1, X2, Bb, FA, F1, F2, FB = (y[keep] for y in (A, X1, X2, Bb, FA, F1, F2, FB))
        lower = F1 < F2
        Bb, FB = np.where(lower, X2, Bb), np.where(lower, F2, FB)
        A, FA = np.where(lower, A, X1), np.where(lower, FA, F1)
        X1, X2 = np.where(lower, A + GOLDEN * (Bb - A), X2), np.where(lower, X1, Bb - GOLDEN * (Bb - A))
        new = s[active] * function(rows[active], np.where(lower, X1, X2))
        F1, F2 = np.where(lower, new, F2), np.where(lower, F1, new)
        a[active], x1[active], x2[active], b[active] = A, X1, X2, Bb
        fa[active], f1[active], f2[active], fb[active] = FA, F1, F2, FB
    x = np.where(f1 < f2, x1, x2)
    least = np.minimum(f1, f2)
    unclear = np.abs(least) <= margin
    decided[rows[unclear]] = False
    two = (least < 0) & ~unclear
    rows, k, x, s, least = rows[two], k[two], x[two], s[two], least[two]
    fx = s * least
    return (np.concatenate([rows, rows]), np.concatenate([grid[k], x]), np.concatenate([x, grid[k + 2]]),
            np.concatenate([f[rows, k], fx]), np.concatenate([fx, f[rows, k + 2]]))


def _convex_floor(a, x1, x2, b, fa, f1, f2, fb):
    """A lower bound on ``[a, b]`` of a function with values ``fa, f1, f2, fb`` at ``a < x1 < x2 < b``
    if it is convex there (``-inf`` where the four values are not): on ``[a, x1]`` and ``[x2, b]`` the
    function lies above the line through ``x1`` and ``x2``, on ``[x1, x2]`` above the lines through
    ``a, x1`` and through ``x2, b``, lowest where those two meet."""
    with np.errstate(all="ignore"):
        s01, s12, s23 = (f1 - fa) / (x1 - a), (f2 - f1) / (x2 - x1), (fb - f2) / (b - x2)
        outer = np.minimum(f1 - np.maximum(s12, 0.0) * (x1 - a), f2 + np.minimum(s12, 0.0) * (b - x2))
        meet = np.clip(np.where(s23 != s01, x1 + (f2 - s23 * (x2 - x1) - f1) / (s01 - s23), x1), x1, x2)
        inner = np.maximum(f1 + s01 * (meet - x1), f2 + s23 * (meet - x2))
        floor = np.minimum(outer, inner)
    return np.where((s01 <= s12) & (s12 <= s23) & np.isfinite(floor), floor, -np.inf)


def _assemble(out, decided, crossings, a, hi, B):
    """Fill ``out``'s decided rows from their refined crossings ``[(rows, speeds, kinds)]`` (kind 0
    real, 1 the weave, 3 a pair not named, -1 an end of an interval that is no crossing): the first weave and real crossings, and the first stable
    range from Routh counts at the midpoints between crossings (as the engine counts there)."""
    if crossings:
        rows, speeds, kinds = (np.concatenate(x) for x in zip(*crossings))
    else:
        rows, speeds, kinds = np.empty(0, dtype=int), np.empty(0), np.empty(0, dtype=int)
    keep = decided[rows]
    rows, speeds, kinds = rows[keep], speeds[keep], kinds[keep]
    order = np.lexsort((speeds, rows))
    rows, speeds, kinds = rows[order], speeds[order], kinds[order]
    starts = np.searchsorted(rows, np.arange(B))
    rank = np.arange(len(rows)) - starts[rows]                   # each crossing's place in its row
    # the first pair of a row that is the weave or not named: a row whose first such pair is not named is undecided
    pairs = (kinds == 1) | (kinds == 3)                          # kind -1: an end that is no crossing
    first_pair = np.full(B, len(rows))
    np.minimum.at(first_pair, rows[pairs], np.flatnonzero(pairs))
    has_pair = first_pair < len(rows)
    which = np.flatnonzero(has_pair)
    unnamed = kinds[first_pair[which]] == 3
    decided[which[unnamed]] = False
    named = which[~unnamed]
    out["weave_speed"][named] = speeds[first_pair[named]]
    first_real = np.full(B, len(rows))
    np.minimum.at(first_real, rows[kinds == 0], np.flatnonzero(kinds == 0))
    real = np.flatnonzero(first_real < len(rows))
    out["capsize_speed"][real] = speeds[first_real[real]]
    # ends of the intervals between crossings, lo = 0 and hi, and the count of unstable roots inside each
    width = 1 + (int(np.max(rank)) + 1 if len(rank) else 0)
    ends = np.full((B, width + 1), float(hi))
    ends[:, 0] = 0.0
    ends[rows, rank + 1] = speeds
    mids = 0.5 * (ends[:, 1:] + ends[:, :-1])
    live = np.flatnonzero(decided)
    count = np.full((B, width), -1)
    if len(live):
        count[live] = routh_rows(at_speeds(a, live, mids[live]))[0]
    empty = ends[:, 1:] <= ends[:, :-1]
    decided &= ~np.any((count < 0) & ~empty, axis=1)
    stable = (count == 0) & ~empty
    # the first stable interval, merged with the stable ones that follow it without a gap
    has = stable.any(axis=1) & decided
    first = np.argmax(stable, axis=1)
    idx = np.arange(width)[None, :]
    after = idx >= first[:, None]
    # an interval ends the range at the first later interval that is neither stable nor empty
    stop_mask = after & ~stable & ~empty
    last = np.where(stop_mask.any(axis=1), np.argmax(stop_mask, axis=1), width)
    # the range's end: the end of the last stable interval before ``last``
    covered = after & (idx < last[:, None]) & stable
    end_at = width - 1 - np.argmax(covered[:, ::-1], axis=1)
    r = np.flatnonzero(has)
    out["stable_from"][r] = ends[r, first[r]]
    out["stable_to"][r] = ends[r, end_at[r] + 1]
