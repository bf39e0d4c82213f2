"""Exact discretisation of ``x' = A x + B u`` by the matrix exponential (``scipy.linalg.expm``).

Over one step ``dt`` with the input held (zero-order hold, a step) or linear between samples
(first-order hold, a sampled track)::

    x[k+1] = Phi x[k] + G0 u[k] + G1 (u[k+1] - u[k])

with ``Phi = exp(A dt)``, ``G0 = int_0^dt exp(A s) ds B`` and
``G1 = (1/dt) int_0^dt exp(A (dt - s)) s ds B``: the blocks of the exponential of
``[[A dt, B dt, 0], [0, 0, I], [0, 0, 0]]``.  No numerical integration: between samples the
solution is exact for inputs of that form.

That matrix has a small norm for the usual steps (0.01 s), where scipy's ``expm`` takes milliseconds
(scipy 1.17: 3.3 ms for a 10 x 10 of norm 0.3, 18 us for one of norm 6); there :func:`expm` sums the
Taylor series instead (norm at most :data:`TAYLOR_NORM`: 18 terms leave ``0.5^19 / 19!``, far below
rounding), and hands larger ones to scipy.
"""

import math

import numpy as np

from ...core.errors import InputError, short
from ...core.limits import MAX_SAMPLES
from ...core.real import finite_real

TAYLOR_NORM = 0.5
"""Largest 1-norm of a matrix whose exponential is summed as its Taylor series (18 terms)."""
TAYLOR_TERMS = 18


def expm(M):
    """``exp(M)`` of a square matrix: the Taylor series for a 1-norm up to :data:`TAYLOR_NORM`, scaled
    into it by a few squarings up to 1, scipy's Pade approximant beyond."""
    M = np.asarray(M, dtype=float)
    norm = float(np.abs(M).sum(axis=0).max(initial=0.0))
    if not norm <= 1.0:
        import scipy.linalg      # lazy: scipy only for a matrix of norm over 1 (stiff models, long steps)
        return scipy.linalg.expm(M)
    squarings = 0 if norm <= TAYLOR_NORM else math.ceil(math.log2(norm / TAYLOR_NORM))
    X = M / 2.0 ** squarings
    eye = np.eye(len(M))
    E = eye
    for k in range(TAYLOR_TERMS, 0, -1):
        E = eye + (X @ E) / k
    for _ in range(squarings):
        E = E @ E
    return E


def hold_matrices(A, B, dt):
    """``(Phi, G0, G1)`` of ``x' = A x + B u`` over a step ``dt`` (s)."""
    A, B = np.asarray(A, dtype=float), np.asarray(B, dtype=float).reshape(len(A), -1)
    n, m = B.shape
    M = np.zeros((n + 2 * m, n + 2 * m))
    M[:n, :n], M[:n, n:n + m], M[n:n + m, n + m:] = A * dt, B * dt, np.eye(m)
    E = expm(M)
    return E[:n, :n], E[:n, n:n + m], E[:n, n + m:]


def march(A, B, x0, u, dt):
    """States (n_t, n) at the samples ``0, dt, 2 dt, ...`` from ``x0`` with the input samples ``u``
    (n_t, m), linear between samples (exact for a constant or piecewise linear input whose kinks
    fall on samples)."""
    Phi, G0, G1 = hold_matrices(A, B, dt)
    u = np.asarray(u, dtype=float).reshape(len(u), -1)
    drive = u[:-1] @ (G0 - G1).T + u[1:] @ G1.T
    x = np.empty((len(u), len(A)))
    x[0] = x0
    for k in range(len(u) - 1):
        x[k + 1] = Phi @ x[k] + drive[k]
    return x


def sample_times(duration, step):
    """``0, step, 2 step, ...`` up to ``duration`` (s): the samples of a linear response and of a nonlinear
    run; InputError unless both are positive and finite with 2 to :data:`~bikemass.core.limits.MAX_SAMPLES`
    samples."""
    for key, value in (("duration", duration), ("step", step)):
        if not finite_real(value) or value <= 0:
            raise InputError(key, short(value), "a positive, finite time in s")
    count = math.floor(duration / step * (1 + 1e-12)) + 1
    if count > MAX_SAMPLES or count < 2:
        raise InputError("step", short(step), f"2 to {MAX_SAMPLES} samples from 0 to the duration "
                         f"{duration:g} s, got {count}")
    return step * np.arange(count)
