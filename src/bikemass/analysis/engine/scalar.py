"""The closed form of :mod:`~bikemass.analysis.engine.closed_form` for one configuration, in plain
Python floats: no array is made, no model is built (the parameters' matrices, from the generated
model family's code in floats, go straight to the quartic's coefficients), so one configuration's critical speeds cost a few microseconds of
arithmetic plus, when a mode is unstable from the lowest speed, one 4 x 4 eigenvalue problem.

The formulas are closed_form's (see its docstring for the quartic and the two quadratics in
``v^2``); the tests hold the two equal on the thesis's sets and random variants of them.
"""

import math

import numpy as np

from ...models.whipple_generated import flat_entries

_NAN = float("nan")


def _dot(x, y):
    """``x.y`` of two 2x2 matrices given as nested rows (``x.x = 2 det x``)."""
    return x[0][0] * y[1][1] + y[0][0] * x[1][1] - x[0][1] * y[1][0] - y[0][1] * x[1][0]


def _det(x):
    return x[0][0] * x[1][1] - x[0][1] * x[1][0]


def pieces(M, C1, K, K2):
    """The speed-independent pieces of the quartic (closed_form.pieces) of 2x2 matrices given as nested
    rows of Python numbers (or arrays: ``.tolist()`` is taken)."""
    M, C1, K, K2 = (x.tolist() if isinstance(x, np.ndarray) else x for x in (M, C1, K, K2))
    return {"a4": _det(M), "alpha": _dot(M, C1), "a20": _dot(M, K), "a21": _dot(M, K2) + _det(C1),
            "beta": _dot(C1, K), "gamma": _dot(C1, K2), "d0": _det(K), "d1": _dot(K, K2), "d2": _det(K2)}


def model_pieces(model):
    """:func:`pieces` of a model for which closed_form.applies."""
    mech = model.mechanics
    K2 = mech.K[2] if len(mech.K) > 2 else ((0.0, 0.0), (0.0, 0.0))
    return pieces(mech.M, mech.C[1], mech.K[0], K2)


def static_stiffness(G, S):
    """``G - G^T (G + S)^-1 G`` of 2x2 nested rows (the quasi-static frame, models.flexible_static)."""
    a, b, c, d = G[0][0] + S[0][0], G[0][1] + S[0][1], G[1][0] + S[1][0], G[1][1] + S[1][1]
    det = a * d - b * c
    inv = ((d / det, -b / det), (-c / det, a / det))
    X = [[inv[i][0] * G[0][j] + inv[i][1] * G[1][j] for j in range(2)] for i in range(2)]   # (G + S)^-1 G
    return tuple(tuple(G[i][j] - (G[0][i] * X[0][j] + G[1][i] * X[1][j]) for j in range(2)) for i in range(2))


def whipple_pieces(params, stiffness=None):
    """:func:`pieces` of the Whipple bicycle of a parameter set (floats), rigid or with the quasi-static
    rear-frame stiffness ``stiffness`` (2x2, N m/rad), without building its model."""
    m00, m01, m10, m11, c00, c01, c10, c11, k00, k01, k10, k11, s00, s01, s10, s11 = flat_entries(params)
    g = params.g
    g00, g01, g10, g11 = g * k00, g * k01, g * k10, g * k11
    if stiffness is not None:
        (g00, g01), (g10, g11) = static_stiffness(((g00, g01), (g10, g11)),
                                                  np.asarray(stiffness, dtype=float).tolist())
    # pieces(M, C1, G, K2) written out (the same products in the same order: _dot, _det)
    return {"a4": m00 * m11 - m01 * m10,
            "alpha": m00 * c11 + c00 * m11 - m01 * c10 - c01 * m10,
            "a20": m00 * g11 + g00 * m11 - m01 * g10 - g01 * m10,
            "a21": (m00 * s11 + s00 * m11 - m01 * s10 - s01 * m10) + (c00 * c11 - c01 * c10),
            "beta": c00 * g11 + g00 * c11 - c01 * g10 - g01 * c10,
            "gamma": c00 * s11 + s00 * c11 - c01 * s10 - s01 * c10,
            "d0": g00 * g11 - g01 * g10,
            "d1": g00 * s11 + s00 * g11 - g01 * s10 - s01 * g10,
            "d2": s00 * s11 - s01 * s10}


def quadratic_roots(a, b, c):
    """Both roots of ``a u^2 + b u + c`` (nan where complex or absent), as closed_form.quadratic_roots."""
    disc = b * b - 4 * a * c
    if not disc >= 0:
        return _NAN, _NAN
    q = -0.5 * (b + math.copysign(math.sqrt(disc), b))
    if a != 0:
        return q / a, (c / q if q != 0 else _NAN)
    return (-c / b if b != 0 else _NAN), _NAN


def candidates(p):
    """``(real, oscillatory, w)``: the crossing speeds (m/s) of the two quadratics and the oscillatory
    crossings' frequencies (rad/s), nan where there is none (closed_form.candidates)."""
    real = tuple(math.sqrt(u) if u > 0 else _NAN for u in quadratic_roots(p["d2"], p["d1"], p["d0"]))
    alpha, gamma, beta, a4 = p["alpha"], p["gamma"], p["beta"], p["a4"]
    h2 = alpha * p["a21"] * gamma - a4 * gamma * gamma - alpha * alpha * p["d2"]
    h1 = alpha * (p["a20"] * gamma + p["a21"] * beta) - 2 * a4 * beta * gamma - alpha * alpha * p["d1"]
    h0 = alpha * p["a20"] * beta - a4 * beta * beta - alpha * alpha * p["d0"]
    osc, w = [], []
    for u in quadratic_roots(h2, h1, h0):
        w2 = (beta + u * gamma) / alpha if alpha != 0 else _NAN
        ok = u > 0 and w2 > 0
        osc.append(math.sqrt(u) if ok else _NAN)
        w.append(math.sqrt(w2) if ok else _NAN)
    return real, tuple(osc), tuple(w)


def axis_crossings(p, lo, hi, kinds=("real", "oscillatory")):
    """``[(speed, kind, frequency)]`` in ``(lo, hi]``, ascending (closed_form.axis_crossings); ``kinds``
    the crossing kinds' names, real first."""
    real, osc, w = candidates(p)
    found = [(s, kinds[0], 0.0) for s in real if lo < s <= hi]
    found += [(s, kinds[1], f) for s, f in zip(osc, w) if lo < s <= hi]
    return sorted(found)


def quartic(p, v):
    """Coefficients ``(a4, a3, a2, a1, a0)`` of the characteristic quartic at speed ``v`` (m/s)."""
    u = v * v
    return (p["a4"], v * p["alpha"], p["a20"] + u * p["a21"], v * (p["beta"] + u * p["gamma"]),
            p["d0"] + u * p["d1"] + u * u * p["d2"])


def unstable_count(p, v):
    """Roots with Re > 0 of the quartic at ``v``: sign changes of the Routh array's first column, the
    roots themselves where that column has a zero (closed_form.unstable_count); ``None`` for a quartic
    that overflows (absurd parameters: no count, hence no stable range)."""
    a4, a3, a2, a1, a0 = c = quartic(p, v)
    if not abs(a4) + abs(a3) + abs(a2) + abs(a1) + abs(a0) < math.inf:
        return None
    if a3 != 0:
        b1 = (a3 * a2 - a4 * a1) / a3
        if b1 != 0:
            c1 = (b1 * a1 - a3 * a0) / b1
            if a4 != 0 and c1 != 0 and a0 != 0 and abs(a4) + abs(a3) + abs(b1) + abs(c1) + abs(a0) < math.inf:
                return (((a4 > 0) != (a3 > 0)) + ((a3 > 0) != (b1 > 0)) + ((b1 > 0) != (c1 > 0))
                        + ((c1 > 0) != (a0 > 0)))
    return sum(r.real > 0 for r in roots(c))


def roots(coefficients):
    """The four roots (Python complex numbers) of a quartic, highest power first: LAPACK on the companion
    matrix (a pure-Python closed form with Newton's polish costs more than the call)."""
    return _lapack_roots(coefficients).tolist()


def _lapack_roots(coefficients):
    """The four roots (complex array) of a quartic, highest power first: LAPACK on the companion matrix."""
    a4, a3, a2, a1, a0 = coefficients
    return np.linalg.eigvals(np.array([[-a3 / a4, -a2 / a4, -a1 / a4, -a0 / a4], [1.0, 0.0, 0.0, 0.0],
                                       [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0]]))
