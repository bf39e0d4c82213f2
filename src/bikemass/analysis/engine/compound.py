"""Second compound matrices: where eigenvalues sum to zero or multiply to a given value.

For an n x n matrix ``A`` with eigenvalues ``l_1 .. l_n`` on the basis ``e_p ^ e_q`` (p < q) of
the exterior square (size n (n - 1) / 2):

* the **additive** compound ``A^[2]`` has eigenvalues ``l_i + l_j`` (i < j): it is singular
  exactly when two eigenvalues sum to zero, e.g. a complex pair on the imaginary axis
  (Stephanos 1900; Fuller 1968; Govaerts, *Numerical Methods for Bifurcations*, 2000, Sec. 4.4);
* the **multiplicative** compound ``C_2(A)`` (the 2 x 2 minors) has eigenvalues ``l_i l_j``
  (i < j): ``C_2(A) - r^2 I`` is singular when a complex pair has modulus ``r``.

Both are linear (bilinear) in ``A``, so a polynomial ``A(v)`` gives polynomial compounds.
"""

from functools import lru_cache

import numpy as np


@lru_cache(maxsize=None)
def pairs(n):
    """Index arrays ``(p, q)`` of the n (n - 1) / 2 pairs p < q, in lexicographic order (read-only,
    made once per size)."""
    p, q = np.triu_indices(n, k=1)
    p.setflags(write=False)
    q.setflags(write=False)
    return p, q


def additive_compound(A):
    """``A^[2]`` of a square matrix (or a stack of them, shape (..., n, n))."""
    A = np.asarray(A)
    p, q = pairs(A.shape[-1])
    P, Q, R, S = p[:, None], q[:, None], p[None, :], q[None, :]
    return (A[..., P, R] * (Q == S) - A[..., Q, R] * (P == S)
            + (P == R) * A[..., Q, S] - (Q == R) * A[..., P, S])


def multiplicative_compound(X, Y=None):
    """The symmetric bilinear compound ``C_2(X, Y)`` (``C_2(X, X)`` = the 2 x 2 minors of X)."""
    X = np.asarray(X)
    Y = X if Y is None else np.asarray(Y)
    p, q = pairs(X.shape[-1])
    P, Q, R, S = p[:, None], q[:, None], p[None, :], q[None, :]
    return 0.5 * (X[..., P, R] * Y[..., Q, S] + Y[..., P, R] * X[..., Q, S]
                  - X[..., P, S] * Y[..., Q, R] - Y[..., P, S] * X[..., Q, R])


def additive_coefficients(coefficients):
    """Coefficients of ``v**k`` of ``A(v)^[2]`` from those of ``A(v)`` (shape (d + 1, n, n))."""
    return additive_compound(coefficients)


def multiplicative_coefficients(coefficients):
    """Coefficients (2 d + 1, m, m) of ``C_2(A(v))`` from those of ``A(v)`` (d + 1, n, n)."""
    d = len(coefficients) - 1
    n = coefficients.shape[-1]
    m = n * (n - 1) // 2
    P = np.asarray(coefficients)
    every = multiplicative_compound(P[:, None], P[None, :])       # (d + 1, d + 1, m, m): every pair at once
    out = np.zeros((2 * d + 1, m, m))
    for k in range(d + 1):                                         # summed in the same order as pair by pair
        for j in range(d + 1):
            out[k + j] += every[k, j]
    return out
