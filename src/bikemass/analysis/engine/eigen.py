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
