"""Eigenvalues and eigenvectors of the bicycle over a vector of speeds, in one batched call.

The state is ``x = [phi, delta, phi', delta']`` and ``x' = A(v) x`` with::

    A(v) = [[0, I], [-M^-1 (g K0 + v^2 K2), -v M^-1 C1]]

Its eigenvalues are the roots of the quartic ``det(M s^2 + v C1 s + g K0 + v^2 K2)``,
whose five coefficients are written out in closed form for all speeds at once and
solved by :func:`~bikemass.analysis.stability.quartic.quartic_roots`; each eigenvector is
``[q, s q]`` with ``q`` spanning the null space of that 2x2 matrix.  This gives the
same numbers as ``np.linalg.eig`` of the stacked state matrices (the tests hold
them together) several times faster.
"""

from dataclasses import dataclass

import numpy as np

from .quartic import quartic_roots


def state_matrices(matrices, speeds):
    """Stacked state matrices ``A(v)``, shape (n, 4, 4), for speeds (m/s)."""
    v = np.asarray(speeds, dtype=float)
    Minv = np.linalg.inv(matrices.M)
    A = np.zeros(v.shape + (4, 4))
    A[..., 0, 2] = A[..., 1, 3] = 1.0
    A[..., 2:, :2] = -Minv @ matrices.stiffness(v)
    A[..., 2:, 2:] = -v[..., None, None] * (Minv @ matrices.C1)
    return A


def _det2_poly(a, b, c):
    """Coefficients (n, 5), highest first, of ``det(a s^2 + b s + c)`` for stacked 2x2 ``a, b, c``."""
    def cross(x, y):   # x11 y22 + y11 x22 - x12 y21 - y12 x21
        return (x[..., 0, 0] * y[..., 1, 1] + y[..., 0, 0] * x[..., 1, 1]
                - x[..., 0, 1] * y[..., 1, 0] - y[..., 0, 1] * x[..., 1, 0])
    return np.stack([cross(a, a) / 2, cross(a, b), cross(a, c) + cross(b, b) / 2,
                     cross(b, c), cross(c, c) / 2], axis=-1)


def characteristic_coefficients(matrices, speeds):
    """Coefficients (n, 5), highest power first, of ``det(M s^2 + v C1 s + K(v))``."""
    v = np.asarray(speeds, dtype=float)
    M = np.broadcast_to(matrices.M, v.shape + (2, 2))
    return _det2_poly(M, v[..., None, None] * matrices.C1, matrices.stiffness(v))


def _eigenvectors(matrices, speeds, s):
    """Unit state eigenvectors (n, 4, 4), column i for eigenvalue ``s[:, i]``."""
    v = np.asarray(speeds, dtype=float)[:, None]
    K = matrices.stiffness(v)                     # (n, 1, 2, 2)
    M, C = matrices.M, matrices.C1

    def P(i, j):                                  # entry (i, j) of M s^2 + v C1 s + K(v)
        return (s * M[i, j] + v * C[i, j]) * s + K[..., i, j]

    p00, p01, p10, p11 = P(0, 0), P(0, 1), P(1, 0), P(1, 1)
    # null vector from the row with the larger entries: [-p01, p00] or [p11, -p10]
    row1 = np.abs(p00) + np.abs(p01) >= np.abs(p10) + np.abs(p11)
    phi = np.where(row1, -p01, p11)
    delta = np.where(row1, p00, -p10)
    zero = (phi == 0) & (delta == 0)
    phi = np.where(zero, 1.0, phi)
    x = np.stack([phi, delta, s * phi, s * delta], axis=1)   # (n, 4 states, 4 eigenvalues)
    return x / np.linalg.norm(x, axis=1, keepdims=True)


class ModalQuantities:
    """Natural frequency and damping ratio of an ``eigenvalues`` (n, 4) attribute."""

    @property
    def natural_frequency(self):
        """``|lambda|`` in rad/s, shape (n, 4)."""
        return natural_frequency(self.eigenvalues)

    @property
    def damping_ratio(self):
        """``-Re(lambda) / |lambda|`` (dimensionless), shape (n, 4)."""
        return damping_ratio(self.eigenvalues)


@dataclass(frozen=True)
class EigenSweep(ModalQuantities):
    """Eigenvalues (n, 4) [1/s] and unit eigenvectors (n, 4, 4) [columns] at speeds (n,) [m/s].

    Columns are in no particular order; :func:`~bikemass.analysis.stability.tracking.track`
    orders them into modes.
    """

    speeds: np.ndarray
    eigenvalues: np.ndarray
    eigenvectors: np.ndarray

    def to_dict(self):
        """Plain lists: speeds, eigenvalues as ``[re, im]`` pairs per speed."""
        ev = np.stack([self.eigenvalues.real, self.eigenvalues.imag], axis=-1)
        return {"speeds": self.speeds.tolist(), "eigenvalues": ev.tolist()}


def eigen_sweep(matrices, speeds):
    """:class:`EigenSweep` of ``matrices`` at every speed of ``speeds`` (m/s), vectorised."""
    v = np.atleast_1d(np.asarray(speeds, dtype=float))
    s = quartic_roots(characteristic_coefficients(matrices, v))
    return EigenSweep(speeds=v, eigenvalues=s, eigenvectors=_eigenvectors(matrices, v, s))


def eigenvalues_at(matrices, speed):
    """The four eigenvalues (1/s) at one speed (m/s)."""
    return quartic_roots(characteristic_coefficients(matrices, np.array([float(speed)])))[0]


def natural_frequency(eigenvalues):
    """Undamped natural frequency ``|lambda|`` (rad/s)."""
    return np.abs(eigenvalues)


def damping_ratio(eigenvalues):
    """Damping ratio ``-Re(lambda)/|lambda|``; ``nan`` where ``lambda = 0``."""
    mag = np.abs(eigenvalues)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(mag > 0, -eigenvalues.real / mag, np.nan)
