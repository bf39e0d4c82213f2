"""The linear model as plain matrices of a parameter mapping, safe for complex values.

Complex values let :func:`matrix_derivatives` differentiate by the complex step
(``f'(p) = Im f(p + i h) / h`` with ``h = 1e-30``): no subtraction, so the derivatives
of ``M, C1, K_static, K2`` (and of the state matrix) are exact to rounding.
"""

from dataclasses import dataclass
from types import SimpleNamespace

import numpy as np

from ..models.canonical import CanonicalMatrices, canonical_matrices
from ..models.parameters import NAMES

STEP = 1e-30
"""Complex step (dimensionless multiple of i)."""
MATRICES = ("M", "C1", "K0", "K2")


@dataclass(frozen=True)
class System:
    """``M q'' + v C1 q' + (K + v^2 K2) q = 0``; ``K`` = static stiffness (N m/rad, flexible frame
    included), ``K0 = K / g`` (kg m), ``g`` (m/s^2)."""

    M: np.ndarray
    C1: np.ndarray
    K: np.ndarray
    K2: np.ndarray
    g: complex

    @property
    def K0(self):
        return self.K / self.g

    def canonical(self):
        """The real :class:`~bikemass.models.canonical.CanonicalMatrices` (``K0 = K / g``) for the stability code."""
        return CanonicalMatrices(M=np.real(self.M), C1=np.real(self.C1), K0=np.real(self.K0),
                                 K2=np.real(self.K2), g=float(np.real(self.g)))

    def state_matrix(self, v):
        """``A(v)`` (4x4) for states ``[phi, delta, phi', delta']`` at speed ``v`` (m/s)."""
        Minv = np.linalg.inv(self.M)
        A = np.zeros((4, 4), dtype=np.result_type(self.M, self.K, self.C1, float))
        A[0, 2] = A[1, 3] = 1.0
        A[2:, :2] = -Minv @ (self.K + v ** 2 * self.K2)
        A[2:, 2:] = -v * Minv @ self.C1
        return A

    def state_matrix_speed_derivative(self, v):
        """``dA/dv`` (4x4, per m/s)."""
        Minv = np.linalg.inv(self.M)
        dA = np.zeros((4, 4), dtype=np.result_type(self.M, self.K, float))
        dA[2:, :2] = -2 * v * Minv @ self.K2
        dA[2:, 2:] = -Minv @ self.C1
        return dA


def system(values, S=None):
    """:class:`System` of a mapping ``{name: value}`` with the 26 benchmark names (values may be
    complex); ``S`` = 2x2 rear-frame stiffness (N m/rad) or ``None`` for a rigid frame."""
    g = values["g"]
    # g enters only as g K0 (K0 itself does not depend on g)
    m = canonical_matrices(SimpleNamespace(**{**values, "g": float(np.real(g))}))
    K = g * m.K0
    if S is not None:
        K = K - K.T @ np.linalg.solve(K + np.asarray(S), K)
    return System(M=m.M, C1=m.C1, K=K, K2=m.K2, g=g)


def values_of(params):
    """``{name: float}`` of a :class:`~bikemass.models.parameters.BenchmarkParameters`."""
    return {name: float(getattr(params, name)) for name in NAMES}


def matrix_derivatives(params, S=None, names=NAMES):
    """``{name: {"M", "C1", "K0", "K2": 2x2 derivative}}`` (complex step) for each of ``names``;
    ``K0`` is ``K_static / g`` (the rigid frame's ``K0``)."""
    base = values_of(params)
    out = {}
    for name in names:
        s = system({**base, name: base[name] + 1j * STEP}, S)
        out[name] = {k: np.imag(getattr(s, k)) / STEP for k in MATRICES}
    return out


def state_matrix_derivatives(params, v, S=None, names=NAMES):
    """``{name: dA/dp}`` (4x4) at speed ``v`` by the complex step."""
    base = values_of(params)
    return {name: system({**base, name: base[name] + 1j * STEP}, S).state_matrix(v).imag / STEP
            for name in names}


STIFFNESS_ENTRIES = {"S_phiphi": ((0, 0),), "S_phidelta": ((0, 1), (1, 0)), "S_deltadelta": ((1, 1),)}
"""Entries of the symmetric rear-frame stiffness S (N m/rad); ``S_phidelta`` moves both off-diagonals."""


def stiffness_state_derivatives(params, v, S):
    """``{entry: dA/dS_entry}`` (4x4, per N m/rad) at speed ``v``; empty for a rigid frame."""
    if S is None:
        return {}
    base = values_of(params)
    out = {}
    for name, cells in STIFFNESS_ENTRIES.items():
        Sc = np.array(S, dtype=complex)
        for cell in cells:
            Sc[cell] += 1j * STEP
        out[name] = system(base, Sc).state_matrix(v).imag / STEP
    return out
