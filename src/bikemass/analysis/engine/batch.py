"""Critical speeds of a whole chunk of configurations of any model at once: the batch path of a sweep.

:func:`~bikemass.analysis.engine.critical.critical_speeds` takes one model at a time (polynomial
eigenvalue problems of the compound matrices, the modes followed from standstill to name the
crossings: about 15 ms for the tyre model).  :func:`batch_critical_speeds` takes B configurations'
dynamic coefficients ``A(v) = sum_k v**k P[k]`` stacked as (B, d + 1, n, n) and finds, for every
row, the numbers a sweep's row holds: the first crossing of the weave, the first real crossing
(capsize), and the first strictly stable range, in arrays:

1. **The characteristic polynomial as polynomials in speed.**  ``det(s I - A(v)) = sum_j a_j(v) s**j``
   with each ``a_j`` a polynomial in ``v``, by the Faddeev-LeVerrier recursion on matrix polynomials
   (``M_k = A M_(k-1) + a_(n-k+1) I``, ``a_(n-k) = -tr(A M_k) / k``: batched matrix products only),
   after one diagonal similarity per row that evens out the states' scales (the tyres' forces beside
   angles).
2. **Routh's array on a speed grid.**  At every speed of a grid on ``(0, hi]`` the Routh array of
   the polynomial (elementwise over rows and speeds) gives the number of roots with ``Re > 0``
   (sign changes of its first column) and the sign of the Hurwitz determinant ``H_(n-1)`` (the
   product of that column: zero exactly where two roots sum to zero, a pair on the imaginary
   axis); ``a_0 = det(-A)`` is zero where a real root passes through zero.  A sign change of
   ``a_0`` or ``H_(n-1)`` between two grid speeds brackets a crossing.
3. **Refinement** of each bracket: the Illinois method on the polynomial (``a_0`` or ``H_(n-1)``),
   then Newton's method on the matrices themselves, to the engine's accuracy: ``det A(v) = 0``
   for a real crossing; ``det(i w I - A(v)) = 0`` in ``(v, w)`` for a pair (the log-derivative
   ``tr((i w I - A)^-1 dA)`` of the determinant, Lancaster 1964), starting from ``w**2`` of
   Routh's auxiliary polynomial.  A bracket of ``H_(n-1)`` whose auxiliary ``w**2`` is negative
   is a real pair ``l, -l`` (no root on the axis) and is dropped, as the engine drops it.
4. **Counts between crossings** (Routh's array at each midpoint, as the engine counts eigenvalues
   there) give the stable ranges.
5. **Naming a pair.**  The engine names a crossing by the tracked mode it continues; a batch does
   not follow modes, so it names only what is unambiguous: a pair slower than
   :data:`WEAVE_MAX_FREQUENCY` with at least :data:`WEAVE_SHARE` of its participation factors
   ``|x_k y_k|`` (right and left null vectors of ``i w I - A(v)``: the diagonal of its inverse near
   the root) on the bicycle's states is the weave.  Any other pair before a row's first weave
   crossing leaves the row undecided (the wobble crosses at 5-9 Hz, and a weave crossing at high
   speed may reach 5 Hz: only the modes followed from standstill tell them apart there).

A row is **decided** only when every step is clean: every Routh array finite, every refinement
converged, no grid speed where ``|a_0|`` or ``|H_(n-1)|`` dips towards zero without a sign change
(two crossings inside one grid step), every pair up to the first weave crossing named.  The
caller takes every other row through the engine (:func:`critical_speeds`), the reference this
path is tested against (tests/test_sweep_members.py: rows equal to 1e-9 m/s).
"""

import numpy as np

from .naming import BICYCLE

GRID_STEP = 0.25
"""Speed step (m/s) of the grid on which crossings are bracketed."""
WEAVE_MAX_FREQUENCY = 2 * np.pi * 2.0
"""Highest frequency (rad/s, 2 Hz) of a crossing pair the batch names the weave; the wobble band begins
at :data:`~bikemass.analysis.engine.naming.WOBBLE_MIN_FREQUENCY` (3 Hz).  Measured with the engine's
names (tests/test_sweep_members.py): first weave crossings of the tyre, rider-lean and rider-lean+tyre
models of perturbed benchmark and Jamis sets at 0.2-1.4 Hz, wobble crossings at 5.2-8.8 Hz."""
WEAVE_SHARE = 0.4
"""Least share of a crossing pair's participation on the bicycle's states for the batch to name it the
weave (measured: 0.48-0.95 at the weave crossings of those models)."""
NEWTON_TOL = 1e-13
"""Relative step (of ``1 + v``) at which Newton's method has converged."""


def balance_rows(P):
    """``D^-1 P[k] D`` for each row (B, d + 1, n, n): a diagonal similarity per row (powers of 2,
    a few sweeps of Osborne's iteration on ``sum_k |P[k]|``) that evens out the scales of the
    states; every eigenvalue at every speed is unchanged."""
    S = np.abs(P).sum(axis=1)                                  # (B, n, n)
    B, n = S.shape[0], S.shape[-1]
    d = np.ones((B, n))
    off = ~np.eye(n, dtype=bool)
    for _ in range(6):
        for i in range(n):
            T = S * d[:, None, :] / d[:, :, None]
            c = np.sum(np.where(off[:, i], T[:, :, i], 0.0), axis=1)
            r = np.sum(np.where(off[i], T[:, i, :], 0.0), axis=1)
            with np.errstate(divide="ignore", invalid="ignore"):
                f = np.where((c > 0) & (r > 0), np.exp2(np.round(0.5 * np.log2(r / c))), 1.0)
            d[:, i] *= f
    return P * d[:, None, None, :] / d[:, None, :, None]


def characteristic(P):
    """Coefficients ``a`` (B, n + 1, n d + 1) of ``det(s I - A(v)) = sum_j sum_i a[:, j, i] s**j v**i``
    for ``A(v) = sum_k v**k P[:, k]`` (Faddeev-LeVerrier on matrix polynomials)."""
    B, d1, n, _ = P.shape
    d = d1 - 1
    a = np.zeros((B, n + 1, n * d + 1))
    a[:, n, 0] = 1.0
    eye = np.eye(n)
    M = np.zeros((B, 1, n, n))                             # M_0 = 0
    for k in range(1, n + 1):
        # M_k = A M_(k-1) + a_(n-k+1) I   (degree (k - 1) d in v)
        deg = (k - 1) * d
        new = np.zeros((B, deg + 1, n, n))
        if k > 1:
            for i in range(d1):
                new[:, i:i + M.shape[1]] += P[:, i:i + 1] @ M
        new += a[:, n - k + 1, :deg + 1, None, None] * eye
        M = new
        # a_(n-k) = -tr(A M_k) / k   (degree k d)
        tr = np.zeros((B, k * d + 1))
        for i in range(d1):
            tr[:, i:i + deg + 1] += np.einsum("bpq,bkqp->bk", P[:, i], M)
        a[:, n - k, :k * d + 1] = -tr / k
    return a


def at_speeds(a, v):
    """``a_j(v)`` (..., n + 1) of the coefficients ``a`` (B, n + 1, D + 1) at speeds ``v`` (B, ...)."""
    out = np.zeros(v.shape + (a.shape[1],))
    vv = v[..., None]
    shape = (a.shape[0],) + (1,) * (v.ndim - 1) + (a.shape[1],)
    for i in range(a.shape[2] - 1, -1, -1):
        out = out * vv + a[:, :, i].reshape(shape)
    return out


def routh(c):
    """``(count, hurwitz, w2)`` of monic polynomials with ascending coefficients ``c`` (..., n + 1):
    the number of roots with ``Re > 0`` (int, -1 where the array breaks down), ``H_(n-1)`` (the
    product of the first column after its leading 1) and ``w**2`` of the auxiliary polynomial of the
    ``s**2`` row (where ``H_(n-1) = 0`` the pair on the axis is ``+-i w``)."""
    n = c.shape[-1] - 1
    desc = c[..., ::-1] / c[..., n:n + 1]
    a = [desc[..., j] for j in range(0, n + 1, 2)]
    b = [desc[..., j] for j in range(1, n + 1, 2)]
    hurwitz = b[0].copy()
    w2 = np.full(c.shape[:-1], np.nan)
    changes = np.signbit(b[0]).astype(np.int64)          # the column starts with a[0] = 1 > 0
    ok = np.isfinite(b[0]) & (b[0] != 0)
    with np.errstate(divide="ignore", invalid="ignore"):
        for k in range(2, n + 1):
            new = [(b[0] * a[j + 1] - a[0] * b[j + 1]) / b[0] if j + 1 < len(b) else a[j + 1]
                   for j in range(len(a) - 1)]
            if k <= n - 1:
                hurwitz = hurwitz * new[0]
            if k == n - 2 and len(new) > 1:           # the s**2 row: new[0] s**2 + new[1]
                w2 = new[1] / new[0]
            changes += np.signbit(new[0]) != np.signbit(b[0])
            ok &= np.isfinite(new[0]) & (new[0] != 0)
            a, b = b, new
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
    (numpy refuses the whole stack for one singular matrix)."""
    with np.errstate(all="ignore"):
        try:
            return np.linalg.inv(A) if D is None else np.linalg.solve(A, D)
        except np.linalg.LinAlgError:
            out = np.full(np.broadcast_shapes(A.shape, A.shape if D is None else D.shape), np.nan, dtype=A.dtype)
            for i in range(len(A)):
                try:
                    out[i] = np.linalg.inv(A[i]) if D is None else np.linalg.solve(A[i], D[i])
                except np.linalg.LinAlgError:
                    pass
            return out


def _illinois(f, a, b, fa, fb, iterations=40, tol=1e-9):
    """Roots of ``f`` (vectorised) in brackets ``[a, b]`` with ``fa``, ``fb`` of opposite signs."""
    for _ in range(iterations):
        with np.errstate(all="ignore"):
            x = np.where(fb != fa, b - fb * (b - a) / (fb - fa), 0.5 * (a + b))
        x = np.where((x > np.minimum(a, b)) & (x < np.maximum(a, b)), x, 0.5 * (a + b))
        fx = f(x)
        same = np.signbit(fx) == np.signbit(fb)
        # Illinois: halve the retained end's value when the same end is kept twice
        fa = np.where(same, fa * 0.5, fb)
        a = np.where(same, a, b)
        b, fb = x, fx
        if np.all(np.abs(b - a) <= tol * (1 + np.abs(b))):
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
        done[rows] = ~good | (np.abs(step) <= 1e-11 * (1 + np.abs(x)))
        stuck[rows] = ~good & (g == 0)
    return v, done & ~stuck & np.isfinite(v)


def _newton_pair(P, v, w, steps=6):
    """``(v, w, converged)``: Newton's method on ``det(i w I - A(v)) = 0`` in ``(v, w)`` (log-derivatives)."""
    v, w = v.copy(), w.copy()
    eye = np.eye(P.shape[-1])
    done = np.zeros(len(v), dtype=bool)
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
        v[rows], w[rows] = np.where(good, x + dv, x), np.where(good, y + dw, y)
        # no step: i w I - A(v) singular to working precision, (v, w) is the root
        singular = ~np.all(np.isfinite(X.reshape(len(rows), -1)), axis=1)
        done[rows] = (good & (np.abs(dv) <= 1e-11 * (1 + np.abs(x))) & (np.abs(dw) <= 1e-9 * (1 + np.abs(y)))) | singular
    return v, w, done & np.isfinite(v) & np.isfinite(w)


def _share(P, v, w, bicycle):
    """The participation of the bicycle's states (indices ``bicycle``) in the pair ``i w`` of ``A(v)``:
    ``|x_k y_k|`` summed, from the diagonal of ``(i w' I - A(v))^-1`` just off the root."""
    n = P.shape[-1]
    M = 1j * (w * (1 + 1e-7))[:, None, None] * np.eye(n) - _matrix(P, v)
    X = _solve(M, None)
    p = np.abs(np.diagonal(X, axis1=1, axis2=2))
    return p[:, list(bicycle)].sum(axis=1) / p.sum(axis=1)


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
    (True, 4.3004)
    """
    P = np.asarray(P, dtype=float)
    B, n = P.shape[0], P.shape[-1]
    bicycle = dict(families).get(BICYCLE, tuple(range(min(4, n))))
    out = {k: np.full(B, np.nan) for k in ("weave_speed", "capsize_speed", "stable_from", "stable_to")}
    decided = np.all(np.isfinite(P.reshape(B, -1)), axis=1)
    if not B:
        out["decided"] = decided
        return out
    with np.errstate(all="ignore"):
        Pb = balance_rows(np.where(decided[:, None, None, None], P, 0.0))
        a = characteristic(Pb)
    count_steps = max(2, int(np.ceil(hi / step)))
    grid = np.linspace(0.0, hi, count_steps + 1)
    grid[0] = min(1e-6 * (1 + hi), 0.5 * grid[1])
    V = np.broadcast_to(grid, (B, len(grid)))
    c = at_speeds(a, V)                                  # (B, G, n + 1)
    _, H, _ = routh(c)
    a0 = c[..., 0]
    decided &= np.all(np.isfinite(H), axis=1) & np.all(np.isfinite(a0), axis=1)
    crossings = []                                   # (row, speed, kind, w, share) of each refined crossing
    for kind, f in (("real", a0), ("pair", H)):
        decided &= ~_dips(f)
        sign = np.signbit(f)
        rows, cells = np.nonzero(sign[:, 1:] != sign[:, :-1])
        if kind == "real":
            decided[rows[(f[rows, cells] == 0) | (f[rows, cells + 1] == 0)]] = False
        keep = decided[rows]
        rows, cells = rows[keep], cells[keep]
        if not len(rows):
            continue
        lo, hi_ = grid[cells], grid[cells + 1]
        flo, fhi = f[rows, cells], f[rows, cells + 1]
        arow = a[rows]
        if kind == "real":
            x = _illinois(lambda x: at_speeds(arow, x)[..., 0], lo, hi_, flo, fhi)
            x, ok = _newton_real(Pb[rows], x)
            ok &= (x > lo - 1e-6) & (x < hi_ + 1e-6)
            decided[rows[~ok]] = False
            crossings += [(r, s, 0, 0.0) for r, s in zip(rows[ok].tolist(), x[ok].tolist())]
        else:
            x = _illinois(lambda x: routh(at_speeds(arow, x))[1], lo, hi_, flo, fhi)
            _, _, w2 = routh(at_speeds(arow, x))
            real_pair = w2 <= 0
            rows, x, w2, lo, hi_ = rows[~real_pair], x[~real_pair], w2[~real_pair], lo[~real_pair], hi_[~real_pair]
            if not len(rows):
                continue
            v, w, ok = _newton_pair(Pb[rows], x, np.sqrt(w2))
            ok &= (v > lo - 1e-6) & (v < hi_ + 1e-6) & (w > 0)
            decided[rows[~ok]] = False
            share = _share(Pb[rows], v, w, bicycle)
            name = np.where((w < WEAVE_MAX_FREQUENCY) & (share >= WEAVE_SHARE), 1, 3)    # 3: not named
            crossings += [(r, s, k, ww) for r, s, k, ww, good in
                          zip(rows.tolist(), v.tolist(), name.tolist(), w.tolist(), ok.tolist()) if good]
    _assemble(out, decided, crossings, a, hi, B)
    out["decided"] = decided
    return out


def _dips(f):
    """Rows (B,) where ``|f|`` on the grid has a local minimum whose parabola through it and its two
    neighbours reaches zero without ``f`` changing sign there: two crossings inside a grid step may
    hide in it."""
    s = np.where(np.signbit(f), -1.0, 1.0)
    g = np.abs(f)
    left, mid, right = g[:, :-2], g[:, 1:-1], g[:, 2:]
    same = (s[:, :-2] == s[:, 1:-1]) & (s[:, 1:-1] == s[:, 2:])
    local = same & (mid <= left) & (mid <= right)
    curv = left + right - 2 * mid
    with np.errstate(all="ignore"):
        lowest = mid - (right - left) ** 2 / (8 * curv)
    suspect = local & ((curv <= 0) | (lowest <= 0.05 * mid) | ~np.isfinite(lowest))
    # a dip down to a tiny fraction of the curve's scale without a sign change
    return np.any(suspect & (mid < 0.2 * np.maximum(left, right)), axis=1)


def _assemble(out, decided, crossings, a, hi, B):
    """Fill ``out``'s rows from their refined crossings: counts at the midpoints give the stable ranges."""
    by_row = {}
    for r, s, k, w in crossings:
        by_row.setdefault(r, []).append((s, k))
    rows = np.flatnonzero(decided)
    width = 1 + max((len(by_row.get(r, ())) for r in rows.tolist()), default=0)
    ends = np.full((len(rows), width + 1), hi)
    ends[:, 0] = 0.0
    for i, r in enumerate(rows.tolist()):
        found = sorted(by_row.get(r, ()))
        for j, (s, k) in enumerate(found):
            ends[i, j + 1] = s
        first = next(((s, k) for s, k in found if k in (1, 3)), None)     # the first pair not named other
        if first is not None and first[1] == 3:
            decided[r] = False                      # a pair before the first weave that could not be named
            continue
        if first is not None:
            out["weave_speed"][r] = first[0]
        capsize = [s for s, k in found if k == 0]
        if capsize:
            out["capsize_speed"][r] = capsize[0]
    mids = 0.5 * (ends[:, 1:] + ends[:, :-1])
    count, _, _ = routh(at_speeds(a[rows], mids))
    empty = ends[:, 1:] <= ends[:, :-1]
    for i, r in enumerate(rows.tolist()):
        if not decided[r]:
            continue
        if np.any((count[i] < 0) & ~empty[i]):
            decided[r] = False
            continue
        span = None
        for j in range(width):
            if empty[i, j]:
                continue
            if count[i, j] == 0:
                if span is None:
                    span = [ends[i, j], ends[i, j + 1]]
                elif span[1] == ends[i, j]:
                    span[1] = ends[i, j + 1]
                else:
                    break
            elif span is not None:
                break
        if span is not None:
            out["stable_from"][r], out["stable_to"][r] = span
