"""Real roots of ``det(sum_k v**k P[k]) = 0``: a polynomial eigenvalue problem in the speed ``v``.

The matrix polynomial is scaled (``v = s t`` with ``s`` balancing the norms of the first and last
coefficients, as Fan, Lin & Van Dooren 2004 do for quadratics), linearised in the first companion
form and solved by the QZ algorithm (``scipy.linalg.eig`` on the pencil, homogeneous eigenvalues
so that the infinite ones of a singular leading coefficient are recognised).  No grid: every
speed where the determinant vanishes is found, however close two of them are.
"""

import numpy as np
from scipy.linalg import eig

REAL_TOL = 1e-7
"""A pencil eigenvalue counts as a real speed when ``|Im v| <= REAL_TOL (1 + |v|)``."""


def _trimmed(P):
    """``P`` without trailing (highest-power) coefficients that are zero."""
    k = len(P)
    while k > 1 and not np.any(P[k - 1]):
        k -= 1
    return P[:k]


def real_roots(P, lo, hi):
    """Sorted real ``v`` in ``[lo, hi]`` with ``det(sum_k v**k P[k]) = 0`` (``P`` of shape (d + 1, m, m)).

    Returns an empty array when the determinant does not depend on ``v`` (degree 0).  Roots are
    as accurate as the QZ algorithm makes them (about 1e-12 relative for simple roots); callers
    refine them on the quantity they care about.
    """
    P = _trimmed(np.asarray(P, dtype=float))
    d, m = len(P) - 1, P.shape[-1]
    if d == 0 or m == 0:
        return np.empty(0)
    norms = np.array([np.linalg.norm(p) for p in P])
    s = (norms[0] / norms[-1]) ** (1.0 / d) if norms[0] > 0 else 1.0
    Q = P * (s ** np.arange(d + 1))[:, None, None]
    Q = Q / max(np.abs(Q).max(), 1e-300)
    L0 = np.zeros((d * m, d * m))
    L1 = np.eye(d * m)
    L0[:-m, m:] = np.eye((d - 1) * m)
    L0[-m:] = -np.concatenate(list(Q[:-1]), axis=1)
    L1[-m:, -m:] = Q[-1]
    w = eig(L0, L1, right=False, homogeneous_eigvals=True)
    alpha, beta = w
    finite = np.abs(beta) > 1e-13 * np.abs(alpha)
    t = alpha[finite] / beta[finite]
    real = np.abs(t.imag) <= REAL_TOL * (1 + np.abs(t))
    v = np.sort(s * t[real].real)
    return v[(v >= lo) & (v <= hi)]
