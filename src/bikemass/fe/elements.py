"""Two-node 3D beam elements (12 DOF): Timoshenko or Euler-Bernoulli, batched over elements.

Local axes: x along the element from node 1 to node 2; DOF order per node
``(u, v, w, rx, ry, rz)``.  Bending in the x-y plane uses ``(v, rz)`` with
``rz = dv/dx``; bending in the x-z plane uses ``(w, ry)`` with ``ry = -dw/dx``.

Bending follows the exact homogeneous solution of Timoshenko's equations: the
deflection is cubic and the section rotation is ``theta = w' - gamma`` with the
constant shear strain ``gamma = w' - theta = -EI theta'' / (kappa G A) = -6 a3 EI / (kappa G A)``
(``a3`` the cubic coefficient; from the stationary energy
``int EI theta'^2 + kappa G A gamma^2 dx / 2``).  With ``Phi = 12 EI / (kappa G A L^2)`` the resulting stiffness is
nodally exact for a prismatic beam (static results do not depend on the mesh),
and the consistent mass (translation + rotary inertia) is integrated from the
same interpolation.  ``Phi = 0`` gives the Euler-Bernoulli (Hermite) element.
All quantities SI: lengths m, moduli Pa, density kg/m^3.
"""

import numpy as np

_HILBERT4 = 1.0 / (np.arange(4)[:, None] + np.arange(4)[None, :] + 1.0)
_HILBERT3 = _HILBERT4[:3, :3]


def _plane_matrices(length, EI, rhoA, rhoI, phi):
    """Bending stiffness and consistent mass (n, 4, 4) on ``(w1, theta1, w2, theta2)``.

    Works in the scaled coordinates ``xi = x / L`` and ``L theta``: the deflection
    ``w = b0 + b1 xi + b2 xi^2 + b3 xi^3`` and ``L theta = b1 + 2 b2 xi + (3 xi^2 + phi/2) b3``.
    """
    n = length.size
    ones, zeros = np.ones(n), np.zeros(n)
    # Nodal values (w1, L theta1, w2, L theta2) as functions of b: q = C b.
    C = np.stack([
        np.stack([ones, zeros, zeros, zeros], -1),
        np.stack([zeros, ones, zeros, phi / 2], -1),
        np.stack([ones, ones, ones, ones], -1),
        np.stack([zeros, ones, 2 * ones, 3 + phi / 2], -1),
    ], -2)
    B = np.linalg.inv(C)
    # Strain energy: EI/L^3 [ int (2 b2 + 6 b3 xi)^2 dxi + 3 phi b3^2 ].
    H = np.zeros((n, 4, 4))
    H[:, 2, 2] = 4.0
    H[:, 2, 3] = H[:, 3, 2] = 6.0
    H[:, 3, 3] = 12.0 + 3.0 * phi
    Bt = B.transpose(0, 2, 1)
    k = (EI / length**3)[:, None, None] * (Bt @ H @ B)
    # Rotation coefficients: L theta = c0 + c1 xi + c2 xi^2 with c = P b.
    P = np.zeros((n, 3, 4))
    P[:, 0, 1] = 1.0
    P[:, 0, 3] = phi / 2
    P[:, 1, 2] = 2.0
    P[:, 2, 3] = 3.0
    PB = P @ B
    m = ((rhoA * length)[:, None, None] * (Bt @ _HILBERT4 @ B)
         + (rhoI / length)[:, None, None] * (PB.transpose(0, 2, 1) @ _HILBERT3 @ PB))
    # Back from (w, L theta) to (w, theta).
    scale = np.stack([ones, length, ones, length], -1)
    outer = scale[:, :, None] * scale[:, None, :]
    return k * outer, m * outer


def local_matrices(length, E, G, density, area, I, J, polar, kappa, timoshenko=True):
    """Local stiffness and consistent mass matrices, each of shape (n, 12, 12).

    Per element (arrays of length n): ``length`` (m), ``E``, ``G`` (Pa), ``density``
    (kg/m^3), ``area`` (m^2), ``I`` second moment about either principal axis
    (m^4; the sections here have Iy = Iz), ``J`` torsion constant (m^4), ``polar``
    polar second moment Iy + Iz (m^4, rotary inertia in torsion), ``kappa`` shear
    coefficient.  ``timoshenko=False`` drops shear deformation (Phi = 0) but keeps
    rotary inertia.
    """
    length = np.asarray(length, float)
    n = length.size
    E, G, density, area, I, J, polar, kappa = (np.broadcast_to(np.asarray(a, float), (n,))
                                               for a in (E, G, density, area, I, J, polar, kappa))
    phi = 12 * E * I / (kappa * G * area * length**2) if timoshenko else np.zeros(n)
    kb, mb = _plane_matrices(length, E * I, density * area, density * I, phi)

    K = np.zeros((n, 12, 12))
    M = np.zeros((n, 12, 12))
    bar_k = np.array([[1.0, -1.0], [-1.0, 1.0]])
    bar_m = np.array([[2.0, 1.0], [1.0, 2.0]]) / 6.0
    for idx, stiff, mass in (((0, 6), E * area / length, density * area * length),
                             ((3, 9), G * J / length, density * polar * length)):
        ix = np.ix_(idx, idx)
        K[(slice(None),) + ix] = stiff[:, None, None] * bar_k
        M[(slice(None),) + ix] = mass[:, None, None] * bar_m
    # x-y plane: (v1, rz1, v2, rz2), rz = +dv/dx;  x-z plane: (w1, ry1, w2, ry2), ry = -dw/dx.
    for idx, sign in (((1, 5, 7, 11), np.array([1.0, 1.0, 1.0, 1.0])),
                      ((2, 4, 8, 10), np.array([1.0, -1.0, 1.0, -1.0]))):
        ix = np.ix_(idx, idx)
        flip = sign[:, None] * sign[None, :]
        K[(slice(None),) + ix] = kb * flip
        M[(slice(None),) + ix] = mb * flip
    return K, M


def direction_cosines(start, end):
    """Rotation matrices (n, 3, 3) whose rows are the local x, y, z axes in global coordinates.

    Local x runs from ``start`` to ``end``; local y is horizontal-ish (x cross the
    global axis least aligned with it, normalised); for the axisymmetric bending
    properties used here the choice of y only orients the output, not the result.
    """
    axis = np.asarray(end, float) - np.asarray(start, float)
    ex = axis / np.linalg.norm(axis, axis=1, keepdims=True)
    ref = np.eye(3)[np.argmin(np.abs(ex), axis=1)]
    ez = np.cross(ex, ref)
    ez /= np.linalg.norm(ez, axis=1, keepdims=True)
    ey = np.cross(ez, ex)
    return np.stack([ex, ey, ez], axis=1)


def to_global(local, rotation):
    """``T^T k T`` for a batch of 12x12 local matrices and (n, 3, 3) rotations."""
    n = rotation.shape[0]
    T = np.zeros((n, 12, 12))
    for b in range(4):
        T[:, 3 * b:3 * b + 3, 3 * b:3 * b + 3] = rotation
    return T.transpose(0, 2, 1) @ local @ T
