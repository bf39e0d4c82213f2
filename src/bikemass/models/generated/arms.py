"""The linear equations of motion of the bikemass model ``arms``: GENERATED, do not edit.

Written by ``python -m bikemass.models.derive`` (bikemass.models.derive, sympy 1.14.0) from the derivation
in ``bikemass.models.derive`` (Kane's method with sympy.physics.mechanics, linearised about the
upright straight run at speed v).  Descriptor form, states and inputs as listed below::

    E x' = sum_k v**k A[k] x + sum_k v**k B[k] u
"""

import math

import numpy as np


NAME = 'arms'
MEMBERS = ('arms',)
PARAMETERS = (('w', 'm', 'wheelbase'), ('c', 'm', 'trail'), ('lam', 'rad', 'steer-axis tilt'), ('g', 'm/s^2', 'gravity'), ('rR', 'm', 'rear wheel radius'), ('mR', 'kg', 'rear wheel mass'), ('IRxx', 'kg m^2', 'rear wheel Ixx'), ('IRyy', 'kg m^2', 'rear wheel Iyy'), ('xB', 'm', 'rear frame CoM x'), ('zB', 'm', 'rear frame CoM z'), ('mB', 'kg', 'rear frame mass'), ('IBxx', 'kg m^2', 'rear frame Ixx'), ('IByy', 'kg m^2', 'rear frame Iyy'), ('IBzz', 'kg m^2', 'rear frame Izz'), ('IBxz', 'kg m^2', 'rear frame Ixz'), ('xH', 'm', 'front frame CoM x'), ('zH', 'm', 'front frame CoM z'), ('mH', 'kg', 'front frame mass'), ('IHxx', 'kg m^2', 'front frame Ixx'), ('IHyy', 'kg m^2', 'front frame Iyy'), ('IHzz', 'kg m^2', 'front frame Izz'), ('IHxz', 'kg m^2', 'front frame Ixz'), ('rF', 'm', 'front wheel radius'), ('mF', 'kg', 'front wheel mass'), ('IFxx', 'kg m^2', 'front wheel Ixx'), ('IFyy', 'kg m^2', 'front wheel Iyy'), ('k_arms', 'N m/rad', "arms' stiffness about the steer axis"), ('c_arms', 'N m s/rad', "arms' damping about the steer axis"))
"""(name, SI unit, meaning) of every argument of coefficients, in order."""
STATES = (('roll-angle', 'rad'), ('steer-angle', 'rad'), ('roll-rate', 'rad/s'), ('steer-rate', 'rad/s'), ('heading', 'rad'), ('lateral', 'm'))
"""(name, unit) of every state; the first N_DYNAMIC are dynamic."""
N_DYNAMIC = 4
INPUTS = (('roll-torque', 'N m'), ('steer-torque', 'N m'))
FAMILIES = (('bicycle', (0, 1, 2, 3)),)
"""Mode families: (name, indices of their dynamic states)."""
COORDINATES = 2
"""How many dynamic mechanical coordinates q lead the states (then their rates q')."""
SECOND_ORDER = True
"""Whether the dynamic states are exactly [q, q']."""


def _make(cos, sin):
    """The coefficient function computing with these functions (cos, sin)."""

    def coefficients(shape, dtype, w, c, lam, g, rR, mR, IRxx, IRyy, xB, zB, mB, IBxx, IByy, IBzz, IBxz, xH, zH, mH, IHxx, IHyy, IHzz, IHxz, rF, mF, IFxx, IFyy, k_arms, c_arms):
        x0 = rR**2
        x1 = -rR - zB
        x2 = mB*rR
        x3 = IFxx + IRxx
        x4 = sin(lam)
        x5 = cos(lam)
        x6 = c*x5
        x7 = rF*x4 - x6
        x8 = mF*rF
        x9 = c + w
        x10 = -x9 + xH
        x11 = x10*x5 - x4*zH
        x12 = mH*zH
        x13 = mB*x1
        x14 = -IBxz - IHxz + c*mF*rF + mH*x10*zH + mH*x9*zH - x13*xB - x2*xB - x8*x9
        x15 = 1/w
        x16 = x15*x6
        x17 = IHxx*x4 + IHxz*x5
        x18 = IFxx*x4 - x11*x12 - x14*x16 + x17 + x7*x8
        x19 = x5**2
        x20 = IHxz*x4 + IHzz*x5
        x21 = mF*x7
        x22 = mH*x11
        x23 = IFxx*x5 - c*mF*x7 + x10*x22 + x20 + x21*x9 + x22*x9
        x24 = -x23
        x25 = x9**2
        x26 = mH*x9
        x27 = -IBzz - IHzz - c**2*mF + 2*c*mF*x9 - mB*xB**2 - mF*x25 - mH*x10**2 - mH*x25 - 2*x10*x26 - x3
        x28 = mR*rR
        x29 = g*x21
        x30 = g*x22
        x31 = -g*x9
        x32 = mB*xB
        x33 = mH*x10
        x34 = c*g*mF - g*x32 - g*x33 + mF*x31 + mH*x31
        x35 = -x16*x34 + x29 + x30
        x36 = 1/rR
        x37 = c*x19
        x38 = x15*x5
        x39 = IFyy/rF
        x40 = x39*x5
        x41 = IRyy*x36 + x39
        x42 = mH*zH - x13 - x2 - x28 - x41 - x8
        x43 = x39*x4
        x44 = -x21 - x22 - x43
        x45 = c*mF - mF*x9 - x26 - x32 - x33
        E = np.zeros(shape + (6, 6), dtype)
        A = np.zeros(shape + (3, 6, 6), dtype)
        B = np.zeros(shape + (1, 6, 2), dtype)
        E[..., 0, 0] = 1
        E[..., 1, 1] = 1
        E[..., 2, 2] = IBxx + IHxx + mB*x0 + mB*x1**2 + mF*rF**2 + mH*zH**2 + mR*x0 + 2*x1*x2 + x3
        E[..., 2, 3] = x18
        E[..., 3, 2] = x18
        E[..., 3, 3] = IFxx*x19 + IFxx*(1 - x19) + mF*x7**2 + mH*x11**2 - x16*x24 - x16*(c*x15*x27*x5 - x23) + x17*x4 + x20*x5
        E[..., 4, 4] = 1
        E[..., 5, 5] = 1
        A[..., 0, 0, 2] = 1
        A[..., 0, 1, 3] = 1
        A[..., 0, 2, 0] = -g*x12 + g*x13 + g*x2 + g*x28 + g*x8
        A[..., 0, 2, 1] = x35
        A[..., 0, 3, 0] = x35
        A[..., 0, 3, 1] = -k_arms + x29*x4 + x30*x4 - x34*x36*(-rR*x15*(c*x19*x36*x9 - x4*x6) + x15*x37*x9)
        A[..., 0, 3, 3] = -c_arms
        A[..., 0, 4, 3] = x16
        A[..., 1, 2, 3] = x14*x38 + x16*x42 - x40
        A[..., 1, 3, 2] = x16*x41 + x40
        A[..., 1, 3, 3] = x16*x44 + x16*(x16*x45 + x27*x38 + x43) + x24*x38
        A[..., 1, 4, 1] = x38
        A[..., 1, 5, 4] = 1
        A[..., 2, 2, 1] = x38*x42
        A[..., 2, 3, 1] = x38*x44 + x37*x45/w**2
        B[..., 0, 2, 0] = 1
        B[..., 0, 3, 1] = 1
        return E, A, B
    return coefficients


_arrays = _make(np.cos, np.sin)
_floats = _make(math.cos, math.sin)


def coefficients(w, c, lam, g, rR, mR, IRxx, IRyy, xB, zB, mB, IBxx, IByy, IBzz, IBxz, xH, zH, mH, IHxx, IHyy, IHzz, IHxz, rF, mF, IFxx, IFyy, k_arms, c_arms):
    """``(E, A, B)``: E (..., 6, 6), A (..., 3, 6, 6), B (..., 1, 6, 2), the leading
    dimensions those of the parameters (floats or arrays, SI, see PARAMETERS) broadcast together;
    complex where a parameter is (the complex step: exact derivatives)."""
    args = (w, c, lam, g, rR, mR, IRxx, IRyy, xB, zB, mB, IBxx, IByy, IBzz, IBxz, xH, zH, mH, IHxx, IHyy, IHzz, IHxz, rF, mF, IFxx, IFyy, k_arms, c_arms,)
    if all(type(a) is float for a in args):
        return _floats((), float, *args)
    return _arrays(np.broadcast_shapes(*(np.shape(a) for a in args)), np.result_type(float, *args), *args)
