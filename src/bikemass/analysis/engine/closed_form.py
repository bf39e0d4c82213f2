"""Critical speeds of a two-coordinate model in closed form (the fast path of the engine).

For ``M q'' + v C1 q' + (K + v^2 K2) q = 0`` with 2 x 2 matrices (the Whipple bicycle, rigid or
with the quasi-static flexible frame), ``det(M s^2 + v C1 s + K + v^2 K2) = a4 s^4 + a3 s^3 +
a2 s^2 + a1 s + a0`` with (``u = v^2``, ``x.y`` the symmetric bilinear form with ``x.x = 2 det x``)::

    a4 = det M               a3 = v (M.C1)          a2 = M.K + u (M.K2 + det C1)
    a1 = v (C1.K + u C1.K2)  a0 = det K + u K.K2 + u^2 det K2

* a **real** root crosses Re = 0 at ``s = 0``: ``a0 = 0``, a quadratic in ``u``;
* an **oscillatory** pair crosses at ``s = +-i w``: the real and imaginary parts of ``P(i w) = 0``
  give ``w^2 = a1 / a3 > 0`` and the Hurwitz determinant ``a3 a2 a1 - a4 a1^2 - a3^2 a0 = 0``,
  which is ``u`` times a quadratic in ``u``.

Every crossing is a root of one of two quadratics in ``v^2``.  All functions take stacked
matrices (leading batch dimensions) so that a chunk of configurations is one evaluation.
"""

import numpy as np

from .crossings import OSCILLATORY, REAL


def _dot(x, y):
    """Symmetric bilinear form on (stacks of) 2x2 matrices with ``_dot(x, x) = 2 det x``."""
    return (x[..., 0, 0] * y[..., 1, 1] + y[..., 0, 0] * x[..., 1, 1]
            - x[..., 0, 1] * y[..., 1, 0] - y[..., 0, 1] * x[..., 1, 0])


def _det(x):
    return x[..., 0, 0] * x[..., 1, 1] - x[..., 0, 1] * x[..., 1, 0]


def applies(model):
    """Whether ``model`` has the form above: two coordinates, ``C(v) = v C1``, ``K(v) = K + v^2 K2``."""
    mech = model.mechanics
    return (mech is not None and len(mech.M) == 2 and model.n_dynamic == 4 and len(mech.C) <= 2
            and not np.any(mech.C[0]) and len(mech.K) <= 3 and (len(mech.K) < 2 or not np.any(mech.K[1])))


def pieces(M, C1, K, K2):
    """The speed-independent pieces of the quartic's coefficients (see the module docstring)."""
    return {"a4": _det(M), "alpha": _dot(M, C1), "a20": _dot(M, K), "a21": _dot(M, K2) + _det(C1),
            "beta": _dot(C1, K), "gamma": _dot(C1, K2), "d0": _det(K), "d1": _dot(K, K2), "d2": _det(K2)}


def model_pieces(model):
    """:func:`pieces` of a model for which :func:`applies`."""
    mech = model.mechanics
    K2 = mech.K[2] if len(mech.K) > 2 else np.zeros((2, 2))
    return pieces(mech.M, mech.C[1], mech.K[0], K2)


def quadratic_roots(a, b, c):
    """Both roots of ``a u^2 + b u + c`` (arrays; ``nan`` where complex or absent), without cancellation."""
    a, b, c = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (a, b, c)))
    with np.errstate(divide="ignore", invalid="ignore"):
        disc = b * b - 4 * a * c
        q = -0.5 * (b + np.copysign(np.sqrt(np.where(disc >= 0, disc, np.nan)), b))
        r1 = np.where(a != 0, q / a, np.where(b != 0, -c / b, np.nan))
        r2 = np.where(a != 0, np.where(q != 0, c / q, np.nan), np.nan)
    return r1, r2


def candidates(p):
    """Crossing speeds (m/s) of stacked pieces ``p``: ``(real (..., 2), oscillatory (..., 2), w (..., 2))``,
    ``nan`` where a quadratic has no positive root; ``w`` the oscillatory crossings' frequencies (rad/s)."""
    real = np.stack(quadratic_roots(p["d2"], p["d1"], p["d0"]), axis=-1)
    alpha, gamma, beta = p["alpha"], p["gamma"], p["beta"]
    h2 = alpha * p["a21"] * gamma - p["a4"] * gamma ** 2 - alpha ** 2 * p["d2"]
    h1 = alpha * (p["a20"] * gamma + p["a21"] * beta) - 2 * p["a4"] * beta * gamma - alpha ** 2 * p["d1"]
    h0 = alpha * p["a20"] * beta - p["a4"] * beta ** 2 - alpha ** 2 * p["d0"]
    osc = np.stack(quadratic_roots(h2, h1, h0), axis=-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        w2 = (beta[..., None] + osc * gamma[..., None]) / alpha[..., None]
        ok = (osc > 0) & (w2 > 0) & (alpha[..., None] != 0)
        return (np.sqrt(np.where(real > 0, real, np.nan)), np.sqrt(np.where(ok, osc, np.nan)),
                np.sqrt(np.where(ok, w2, np.nan)))


def axis_crossings(model, lo, hi):
    """``[(speed, kind, frequency)]`` in ``(lo, hi]``, ascending, from the closed form."""
    real, osc, w = candidates(model_pieces(model))
    found = [(float(s), REAL, 0.0) for s in real if lo < s <= hi]
    found += [(float(s), OSCILLATORY, float(f)) for s, f in zip(osc, w) if lo < s <= hi]
    return sorted(found)


def quartic(p, v):
    """Coefficients ``(a4, a3, a2, a1, a0)`` of the characteristic quartic at speed ``v`` (m/s)."""
    u = v * v
    return (p["a4"], v * p["alpha"], p["a20"] + u * p["a21"], v * (p["beta"] + u * p["gamma"]),
            p["d0"] + u * p["d1"] + u * u * p["d2"])


def unstable_count(coefficients):
    """Number of roots with Re > 0 of a real quartic (highest power first): sign changes in the
    first column of the Routh array; ``np.roots`` where that column has a zero."""
    a4, a3, a2, a1, a0 = coefficients
    if a3 != 0:
        b1 = (a3 * a2 - a4 * a1) / a3
        if b1 != 0:
            c1 = (b1 * a1 - a3 * a0) / b1
            if c1 != 0 and a0 != 0:
                column = np.sign([a4, a3, b1, c1, a0])
                return int(np.sum(column[1:] != column[:-1]))
    return int(np.sum(np.roots(coefficients).real > 0))


def unstable_counts(coefficients):
    """Roots with Re > 0 (int array) of stacked real quartics ``coefficients`` (..., 5), highest power
    first: the Routh array's first column, vectorised; LAPACK on the companion matrix where that
    column has a zero or is not finite (a root on the axis, or a missing term)."""
    c = np.asarray(coefficients, dtype=float)
    a4, a3, a2, a1, a0 = np.moveaxis(c, -1, 0)
    with np.errstate(divide="ignore", invalid="ignore"):
        b1 = (a3 * a2 - a4 * a1) / a3
        c1 = (b1 * a1 - a3 * a0) / b1
    column = np.stack([a4, a3, b1, c1, a0], axis=-1)
    count = np.sum(np.sign(column[..., 1:]) != np.sign(column[..., :-1]), axis=-1)
    odd = ~np.all(np.isfinite(column) & (column != 0), axis=-1)
    if np.any(odd):
        rows = c[odd]
        companion = np.zeros((len(rows), 4, 4))
        companion[:, 0] = -rows[:, 1:] / rows[:, :1]
        companion[:, 1:, :3] = np.eye(3)
        count[odd] = np.sum(np.linalg.eigvals(companion).real > 0, axis=-1)
    return count


def batch_critical_speeds(p, vmax):
    """First weave speed, first capsize speed and the first strictly stable range of stacked pieces
    ``p`` (:func:`pieces` of (B,) configurations) on ``(0, vmax]`` m/s: a dict of (B,) float arrays
    ``weave_speed``, ``capsize_speed``, ``stable_from``, ``stable_to`` (``nan`` where there is none).
    One evaluation for the whole chunk: what a sweep's parameter-level chunk costs."""
    real, osc, _ = candidates(p)
    inside = lambda x: np.where((x > 0) & (x <= vmax), x, np.nan)     # noqa: E731
    real, osc = inside(real), inside(osc)
    with np.errstate(invalid="ignore"):
        weave, capsize = np.nanmin(np.where(np.isnan(osc), np.inf, osc), axis=-1), \
            np.nanmin(np.where(np.isnan(real), np.inf, real), axis=-1)
    weave, capsize = np.where(np.isinf(weave), np.nan, weave), np.where(np.isinf(capsize), np.nan, capsize)
    B = real.shape[0]
    cuts = np.sort(np.concatenate([real, osc], axis=-1), axis=-1)             # nan last
    ends = np.concatenate([np.zeros((B, 1)), np.where(np.isnan(cuts), vmax, cuts), np.full((B, 1), vmax)], axis=-1)
    lo, hi = ends[:, :-1], ends[:, 1:]
    mid = 0.5 * (lo + hi)
    u = mid * mid
    coefficients = np.stack([np.broadcast_to(p["a4"][:, None], mid.shape), mid * p["alpha"][:, None],
                             p["a20"][:, None] + u * p["a21"][:, None],
                             mid * (p["beta"][:, None] + u * p["gamma"][:, None]),
                             p["d0"][:, None] + u * p["d1"][:, None] + u * u * p["d2"][:, None]], axis=-1)
    stable = (unstable_counts(coefficients) == 0) & (hi > lo)
    first = np.argmax(stable, axis=-1)
    has = stable[np.arange(B), first]
    start = np.where(has, lo[np.arange(B), first], np.nan)
    # the run goes on while the next intervals are stable (or empty: a repeated cut)
    run = stable | (hi <= lo)
    after = np.arange(run.shape[1])[None, :] >= first[:, None]
    stops = np.where(after & ~run, lo, np.inf)
    stop = np.min(np.concatenate([stops, np.full((B, 1), vmax)], axis=-1), axis=-1)
    return {"weave_speed": weave, "capsize_speed": capsize, "stable_from": start,
            "stable_to": np.where(has, stop, np.nan)}
