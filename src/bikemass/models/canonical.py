"""Canonical matrices of the linearised Whipple bicycle (Meijaard et al. 2007, Appendix A).

The hand-written formulas of the paper: the TEST ORACLE of the run-time path, which takes the
matrices from the generated model family's code (:mod:`bikemass.models.whipple_generated`;
tests/test_whipple_generated.py holds the two equal).  :class:`CanonicalMatrices` (the result type)
is shared by both; nothing else of this module runs outside the tests.

Equations of motion about the upright straight run at speed ``v`` (m/s)::

    M q'' + v C1 q' + (g K0 + v**2 K2) q = f,     q = [roll phi, steer delta] (rad)

``M`` in kg m^2, ``C1`` in kg m^2 (per m/s), ``K0`` in kg m (times g gives N m/rad),
``K2`` in kg (times v**2 gives N m/rad).  ``K0`` is kept without g, as the paper
prints it (and the thesis's Table 3-13).
"""

import math
from dataclasses import dataclass, replace

import numpy as np

from ..core.results import Result, quantity
from ..core.frozen import freeze


@dataclass(frozen=True, repr=False)
class CanonicalMatrices(Result):
    """``M, C1, K0, K2`` (2x2 read-only arrays) and gravity ``g`` (m/s^2) of one bicycle.

    Examples
    --------
    >>> import bikemass as bm
    >>> m = bm.matrices(bm.parameters("benchmark"))
    >>> print(type(m).__name__, m.M.shape, f"{m.M[0, 0]:.6f} {m.units()['M']}")
    CanonicalMatrices (2, 2) 80.817220 kg m^2
    """

    M: np.ndarray = quantity("kg m^2", "mass matrix")
    C1: np.ndarray = quantity("kg m^2 (per m/s)", "velocity-dependent damping-like matrix (times v)")
    K0: np.ndarray = quantity("kg m (times g: N m/rad)", "gravity-dependent stiffness matrix (times g)")
    K2: np.ndarray = quantity("kg (times v^2: N m/rad)", "velocity-dependent stiffness matrix (times v^2)")
    g: float = quantity("m/s^2", "gravity")

    def __post_init__(self):
        for name in ("M", "C1", "K0", "K2"):           # read-only arrays (copied only when writable)
            a = getattr(self, name)
            if type(a) is not np.ndarray or a.flags.writeable:
                object.__setattr__(self, name, freeze(np.asarray(a)))

    @property
    def gK0(self):
        """Static (gravity) stiffness ``g K0`` in N m/rad (read-only)."""
        return _readonly(self.g * self.K0)

    def stiffness(self, v):
        """``g K0 + v**2 K2`` for speeds ``v`` (array -> shape (n, 2, 2))."""
        v = np.asarray(v, dtype=float)
        return self.gK0 + v[..., None, None] ** 2 * self.K2

    def replace(self, **changes):
        """A copy with some matrices changed."""
        return replace(self, **changes)

    def to_dict(self):
        """Plain nested lists, keys ``M C1 K0 K2 g``."""
        return {"M": self.M.tolist(), "C1": self.C1.tolist(), "K0": self.K0.tolist(),
                "K2": self.K2.tolist(), "g": float(self.g)}


def canonical_matrices(p):
    """:class:`CanonicalMatrices` of a :class:`~bikemass.models.parameters.BenchmarkParameters` set.

    Any object with the 26 attributes works; arrays of one shape (B,) give stacked matrices
    (B, 2, 2) (a sweep's chunk of configurations at once), complex values complex matrices.
    """
    M, C1, K0, K2 = canonical_entries(p)
    return CanonicalMatrices(M=_matrix(M), C1=_matrix(C1), K0=_matrix(K0), K2=_matrix(K2), g=p.g)


def canonical_entries(p):
    """The entries of ``M, C1, K0, K2`` as nested ``((a, b), (c, d))`` rows, of whatever type the
    parameters are: Python floats for floats (one configuration without any array: the scalar
    fast path of :mod:`bikemass.analysis.engine.scalar`), arrays of shape (B,) for a batch, complex
    for complex steps.  The one place the formulas of Meijaard et al. (2007), Appendix A, are written."""
    sl, cl = _sin_cos(p.lam)
    # whole bicycle (T) about the rear contact point
    mT = p.mR + p.mB + p.mH + p.mF
    xT = (p.xB * p.mB + p.xH * p.mH + p.w * p.mF) / mT
    zT = (-p.rR * p.mR + p.zB * p.mB + p.zH * p.mH - p.rF * p.mF) / mT
    ITxx = (p.IRxx + p.IBxx + p.IHxx + p.IFxx + p.mR * p.rR ** 2 + p.mB * p.zB ** 2
            + p.mH * p.zH ** 2 + p.mF * p.rF ** 2)
    ITxz = p.IBxz + p.IHxz - p.mB * p.xB * p.zB - p.mH * p.xH * p.zH + p.mF * p.w * p.rF
    ITzz = (p.IRxx + p.IBzz + p.IHzz + p.IFxx + p.mB * p.xB ** 2 + p.mH * p.xH ** 2
            + p.mF * p.w ** 2)   # wheels: Izz = Ixx
    # front assembly (A = H + F) about its own centre of mass
    mA = p.mH + p.mF
    xA = (p.xH * p.mH + p.w * p.mF) / mA
    zA = (p.zH * p.mH - p.rF * p.mF) / mA
    IAxx = p.IHxx + p.IFxx + p.mH * (p.zH - zA) ** 2 + p.mF * (p.rF + zA) ** 2
    IAxz = p.IHxz - p.mH * (p.xH - xA) * (p.zH - zA) + p.mF * (p.w - xA) * (p.rF + zA)
    IAzz = p.IHzz + p.IFxx + p.mH * (p.xH - xA) ** 2 + p.mF * (p.w - xA) ** 2
    uA = (xA - p.w - p.c) * cl - zA * sl          # front CoM distance ahead of the steer axis
    IAll = mA * uA ** 2 + IAxx * sl ** 2 + 2 * IAxz * sl * cl + IAzz * cl ** 2
    IAlx = -mA * uA * zA + IAxx * sl + IAxz * cl
    IAlz = mA * uA * xA + IAxz * sl + IAzz * cl
    mu = p.c / p.w * cl
    SR, SF = _spin_momentum(p.IRyy, p.rR), _spin_momentum(p.IFyy, p.rF)
    ST = SR + SF
    SA = mA * uA + mu * mT * xT

    M = ((ITxx, IAlx + mu * ITxz),
         (IAlx + mu * ITxz, IAll + 2 * mu * IAlz + mu ** 2 * ITzz))
    K0 = ((mT * zT, -SA), (-SA, -SA * sl))
    K2 = ((0.0, (ST - mT * zT) / p.w * cl),
          (0.0, (SA + SF * sl) / p.w * cl))
    C1 = ((0.0, mu * ST + SF * cl + ITxz / p.w * cl - mu * mT * zT),
          (-(mu * ST + SF * cl), IAlz / p.w * cl + mu * (SA + ITzz / p.w * cl)))
    return M, C1, K0, K2


def _sin_cos(x):
    """``(sin x, cos x)``: the math module's for a Python float (no numpy scalar on the scalar path)."""
    if type(x) is float:
        return math.sin(x), math.cos(x)
    return np.sin(x), np.cos(x)


def _matrix(rows):
    """A 2x2 matrix from entries that may be arrays of one shape (B,): shape (2, 2) or (B, 2, 2)."""
    if all(type(x) is float for row in rows for x in row):
        return _readonly(np.array(rows))
    entries = np.broadcast_arrays(*(np.asarray(x) for row in rows for x in row))
    return _readonly(np.stack(entries, axis=-1).reshape(*entries[0].shape, 2, 2))


def _readonly(a):
    """``a`` (a new array nobody else holds) made read-only in place, without a copy."""
    a.setflags(write=False)
    return a


def _spin_momentum(spin_inertia, radius):
    """A wheel's angular momentum per unit forward speed, ``Iyy / r`` (kg m); 0 for a point wheel
    (``r = 0``, which carries no spin inertia: the limit of the two-mass-skate bicycle).  Radii
    may be arrays (a batch); complex values pass through (the sensitivities differentiate by
    complex steps)."""
    if type(radius) is float:
        return spin_inertia / radius if radius != 0 else 0 * spin_inertia
    r = np.asarray(radius)
    if r.ndim == 0:
        return spin_inertia / radius if radius != 0 else 0 * spin_inertia
    return np.where(r != 0, spin_inertia / np.where(r != 0, r, 1.0), 0 * spin_inertia)
