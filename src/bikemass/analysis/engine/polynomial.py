"""Real roots of ``det(sum_k v**k P[k]) = 0``: a polynomial eigenvalue problem in the speed ``v``.

The matrix polynomial is scaled (``v = s t`` with ``s`` balancing the norms of the first and last
coefficients, as Fan, Lin & Van Dooren 2004 do for quadratics), linearised in the first companion
form.  For a small model (two coordinates: ``shifted=True``) the leading coefficient, often singular (infinite eigenvalues), so the variable is first
moved by a Moebius map ``t = sigma + 1 / tau`` with a ``sigma`` where the polynomial is well
conditioned: the new leading coefficient is ``P(sigma)``, the companion matrix is an ordinary one
(``numpy.linalg.eigvals``, no scipy) and the infinite roots are those at ``tau = 0``.  Richer models,
and a small one where no such ``sigma`` is found among a few tries, take the QZ algorithm (``scipy.linalg.eig``, homogeneous
eigenvalues so that the infinite ones are recognised).  No grid: every speed where the determinant
vanishes is found, however close two of them are.
"""

from math import comb

import numpy as np

SHIFTS = (0.6180339887498949, -0.7548776662466927, 1.3247179572447460, -1.8392867552141612)
"""The ``sigma`` tried, in order (irrational-looking, so that no structured root sits on one)."""
SHIFT_COND = 1e6
"""Largest condition number of ``P(sigma)`` taken; above it for every shift, QZ."""
REAL_TOL = 1e-7
"""A pencil eigenvalue counts as a real speed when ``|Im v| <= REAL_TOL (1 + |v|)``."""


def _trimmed(P):
    """``P`` without trailing (highest-power) coefficients that are zero."""
    k = len(P)
    while k > 1 and not np.any(P[k - 1]):
        k -= 1
    return P[:k]


def real_roots(P, lo, hi, shifted=False):
    """Sorted real ``v`` in ``[lo, hi]`` with ``det(sum_k v**k P[k]) = 0`` (``P`` of shape (d + 1, m, m)).

    Returns an empty array when the determinant does not depend on ``v`` (degree 0).  Roots are
    as accurate as the QZ algorithm makes them (about 1e-12 relative for simple roots); callers
    refine them on the quantity they care about.  ``shifted``: try the Moebius map and an ordinary
    eigenvalue problem first (see the module docstring).
    """
    P = _trimmed(np.asarray(P, dtype=float))
    d, m = len(P) - 1, P.shape[-1]
    if d == 0 or m == 0:
        return np.empty(0)
    norms = np.sqrt(np.einsum("kij,kij->k", P, P))         # Frobenius norms of the coefficients
    s = (norms[0] / norms[-1]) ** (1.0 / d) if norms[0] > 0 else 1.0
    Q = P * (s ** np.arange(d + 1))[:, None, None]
    Q = Q / max(np.abs(Q).max(), 1e-300)
    t = _shifted_roots(Q) if shifted else None
    if t is None:
        t = _qz_roots(Q)
    real = np.abs(t.imag) <= REAL_TOL * (1 + np.abs(t))
    v = np.sort(s * t[real].real)
    return v[(v >= lo) & (v <= hi)]


def _companion_eigenvalues(R):
    """Eigenvalues of the monic matrix polynomial ``sum_j tau**j R[j]`` (``R[-1] = I``) by its block
    companion matrix."""
    d, m = len(R) - 1, R.shape[-1]
    L = np.zeros((d * m, d * m))
    L[:-m, m:] = np.eye((d - 1) * m)
    L[-m:] = -np.concatenate(list(R[:-1]), axis=1)
    return np.linalg.eigvals(L)


def _shifted_roots(Q):
    """Finite roots ``t`` of ``det(sum_k t**k Q[k]) = 0`` by the Moebius map ``t = sigma + 1 / tau``
    (see the module docstring), or ``None`` if ``Q(sigma)`` is ill conditioned at every shift."""
    d = len(Q) - 1
    for sigma in SHIFTS:
        lead = np.tensordot(sigma ** np.arange(d + 1), Q, axes=1)
        if not np.linalg.cond(lead) < SHIFT_COND:
            continue
        # t^d Q(sigma + 1/tau) tau^d ... : sum_k Q[k] (sigma tau + 1)^k tau^(d - k)
        R = np.zeros_like(Q)
        for k in range(d + 1):
            for i in range(k + 1):
                R[i + d - k] += comb(k, i) * sigma ** i * Q[k]
        R = np.linalg.solve(lead, R.reshape(d + 1, *Q.shape[1:]).transpose(1, 0, 2).reshape(len(lead), -1))
        R = R.reshape(len(lead), d + 1, -1).transpose(1, 0, 2)
        tau = _companion_eigenvalues(R)
        finite = np.abs(tau) > 1e-13 * max(1.0, float(np.abs(tau).max(initial=0.0)))
        return sigma + 1 / tau[finite]
    return None


TRIM_FROM = 20
"""Least size of a quadratic's coefficients whose pencil is trimmed (:func:`_pencil`): below it the
singular values cost more than they save (measured: the 15 x 15 compound of a 6-state model)."""


def _low_rank(X):
    """``(U, Vt)`` with ``X = U @ Vt`` and as few columns of ``U`` as ``X``'s numerical rank (its singular
    values above ``max(shape) eps`` times the largest, numpy's ``matrix_rank`` rule)."""
    W, sigma, Vt = np.linalg.svd(X)
    r = int(np.sum(sigma > sigma[0] * max(X.shape) * np.finfo(float).eps)) if sigma[0] > 0 else 0
    return W[:, :r] * sigma[:r], Vt[:r]


def _pencil(Q):
    """``(L0, L1)``: a linearisation of ``sum_k t**k Q[k]`` (``L0 z = t L1 z`` exactly where the polynomial
    is singular).  The companion pencil of size ``d m``; a quadratic whose leading coefficient has rank
    ``r < m`` (a richer model's ``A(v)`` has ``v**2`` only in the few entries of the speed-squared
    stiffness, its compound as few) the trimmed pencil of size ``m + r``: with ``Q[2] = U Vt`` and
    ``w = t Vt x``, ``-Q[0] x = t (Q[1] x + U w)`` and ``w = t Vt x`` (the same determinant, by the Schur
    complement of the identity block; QZ's cost falls with the cube of the size)."""
    d, m = len(Q) - 1, Q.shape[-1]
    if d == 2 and m >= TRIM_FROM:
        U, Vt = _low_rank(Q[2])
        r = U.shape[1]
        if r < m:
            L0 = np.zeros((m + r, m + r))
            L1 = np.zeros((m + r, m + r))
            L0[:m, :m] = -Q[0]
            L0[m:, m:] = np.eye(r)
            L1[:m, :m] = Q[1]
            L1[:m, m:] = U
            L1[m:, :m] = Vt
            return L0, L1
    L0 = np.zeros((d * m, d * m))
    L1 = np.eye(d * m)
    L0[:-m, m:] = np.eye((d - 1) * m)
    L0[-m:] = -np.concatenate(list(Q[:-1]), axis=1)
    L1[-m:, -m:] = Q[-1]
    return L0, L1


def _qz_roots(Q):
    """Finite roots ``t`` of ``det(sum_k t**k Q[k]) = 0`` by the QZ algorithm on a linearisation
    (:func:`_pencil`)."""
    from scipy.linalg import eig, lapack      # lazy: only for a polynomial ill conditioned at every shift
    L0, L1 = _pencil(Q)
    # LAPACK's dggev called directly (what scipy.linalg.eig calls, without its checks: a fifth less time on
    # a 30 x 30 pencil); scipy's own call where it reports a failure (it raises it)
    alphar, alphai, beta, _, _, _, info = lapack.dggev(L0, L1, compute_vl=0, compute_vr=0)
    if info == 0 and np.all(np.isfinite(alphar)) and np.all(np.isfinite(alphai)) and np.all(np.isfinite(beta)):
        alpha = alphar + 1j * alphai
    else:
        alpha, beta = eig(L0, L1, right=False, homogeneous_eigvals=True)
    finite = np.abs(beta) > 1e-13 * np.abs(alpha)
    return alpha[finite] / beta[finite]
