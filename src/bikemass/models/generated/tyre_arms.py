"""The linear equations of motion of the bikemass model ``tyre+arms``: GENERATED, do not edit.

Written by ``python -m bikemass.models.derive`` (bikemass.models.derive, sympy 1.14.0) from the derivation
in ``bikemass.models.derive`` (Kane's method with sympy.physics.mechanics, linearised about the
upright straight run at speed v).  Descriptor form, states and inputs as listed below::

    E x' = sum_k v**k A[k] x + sum_k v**k B[k] u
"""

import math

import numpy as np


NAME = 'tyre+arms'
MEMBERS = ('tyre', 'arms')
PARAMETERS = (('w', 'm', 'wheelbase'), ('c', 'm', 'trail'), ('lam', 'rad', 'steer-axis tilt'), ('g', 'm/s^2', 'gravity'), ('rR', 'm', 'rear wheel radius'), ('mR', 'kg', 'rear wheel mass'), ('IRxx', 'kg m^2', 'rear wheel Ixx'), ('IRyy', 'kg m^2', 'rear wheel Iyy'), ('xB', 'm', 'rear frame CoM x'), ('zB', 'm', 'rear frame CoM z'), ('mB', 'kg', 'rear frame mass'), ('IBxx', 'kg m^2', 'rear frame Ixx'), ('IByy', 'kg m^2', 'rear frame Iyy'), ('IBzz', 'kg m^2', 'rear frame Izz'), ('IBxz', 'kg m^2', 'rear frame Ixz'), ('xH', 'm', 'front frame CoM x'), ('zH', 'm', 'front frame CoM z'), ('mH', 'kg', 'front frame mass'), ('IHxx', 'kg m^2', 'front frame Ixx'), ('IHyy', 'kg m^2', 'front frame Iyy'), ('IHzz', 'kg m^2', 'front frame Izz'), ('IHxz', 'kg m^2', 'front frame Ixz'), ('rF', 'm', 'front wheel radius'), ('mF', 'kg', 'front wheel mass'), ('IFxx', 'kg m^2', 'front wheel Ixx'), ('IFyy', 'kg m^2', 'front wheel Iyy'), ('k_arms', 'N m/rad', "arms' stiffness about the steer axis"), ('c_arms', 'N m s/rad', "arms' damping about the steer axis"), ('CaR', '1/rad', 'rear cornering coefficient'), ('CgR', '1/rad', 'rear camber coefficient'), ('sigmaR', 'm', 'rear relaxation length'), ('tpR', 'm', 'rear pneumatic trail'), ('CmgR', 'm/rad', 'rear twisting torque coefficient'), ('CaF', '1/rad', 'front cornering coefficient'), ('CgF', '1/rad', 'front camber coefficient'), ('sigmaF', 'm', 'front relaxation length'), ('tpF', 'm', 'front pneumatic trail'), ('CmgF', 'm/rad', 'front twisting torque coefficient'))
"""(name, SI unit, meaning) of every argument of coefficients, in order."""
STATES = (('roll-angle', 'rad'), ('steer-angle', 'rad'), ('roll-rate', 'rad/s'), ('steer-rate', 'rad/s'), ('lateral-velocity', 'm/s'), ('yaw-rate', 'rad/s'), ('rear-lateral-force', 'N'), ('front-lateral-force', 'N'), ('heading', 'rad'), ('lateral', 'm'))
"""(name, unit) of every state; the first N_DYNAMIC are dynamic."""
N_DYNAMIC = 8
INPUTS = (('roll-torque', 'N m'), ('steer-torque', 'N m'))
FAMILIES = (('bicycle', (0, 1, 2, 3)), ('tyre', (4, 5, 6, 7)))
"""Mode families: (name, indices of their dynamic states)."""
COORDINATES = 2
"""How many dynamic mechanical coordinates q lead the states (then their rates q')."""
SECOND_ORDER = False
"""Whether the dynamic states are exactly [q, q']."""


def _make(cos, sin):
    """The coefficient function computing with these functions (cos, sin)."""

    def coefficients(shape, dtype, w, c, lam, g, rR, mR, IRxx, IRyy, xB, zB, mB, IBxx, IByy, IBzz, IBxz, xH, zH, mH, IHxx, IHyy, IHzz, IHxz, rF, mF, IFxx, IFyy, k_arms, c_arms, CaR, CgR, sigmaR, tpR, CmgR, CaF, CgF, sigmaF, tpF, CmgF):
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
        x13 = IHxx*x4 + IHxz*x5
        x14 = IFxx*x4 - x11*x12 + x13 + x7*x8
        x15 = mB*x1
        x16 = mR*rR
        x17 = -x12 + x15 + x16 + x2 + x8
        x18 = IBxz + IHxz - c*x8 - x10*x12 - x12*x9 + x15*xB + x2*xB + x8*x9
        x19 = x5**2
        x20 = IHxz*x4 + IHzz*x5
        x21 = mF*x7
        x22 = mH*x11
        x23 = x21 + x22
        x24 = IFxx*x5 - c*x21 + x10*x22 + x20 + x21*x9 + x22*x9
        x25 = mB + mF + mH + mR
        x26 = mB*xB
        x27 = mF*x9
        x28 = mH*x9
        x29 = mH*x10
        x30 = c*mF
        x31 = x26 + x27 + x28 + x29 - x30
        x32 = x9**2
        x33 = g*x21
        x34 = g*x22
        x35 = 1/w
        x36 = -g*x9
        x37 = x35*x6*(-g*x26 - g*x29 + g*x30 + mF*x36 + mH*x36)
        x38 = x33 + x34 - x37
        x39 = mF*w + mH*xH + x26
        x40 = x35*x39
        x41 = g*x40
        x42 = CmgF*x41
        x43 = x42*x5
        x44 = g*(x25 - x40)
        x45 = CaF*g
        x46 = x40*x45
        x47 = IFyy/rF
        x48 = x47*x5
        x49 = IRyy/rR + x47
        x50 = x4*x47
        E = np.zeros(shape + (10, 10), dtype)
        A = np.zeros(shape + (2, 10, 10), dtype)
        B = np.zeros(shape + (1, 10, 2), dtype)
        E[..., 0, 0] = 1
        E[..., 1, 1] = 1
        E[..., 2, 2] = IBxx + IHxx + mB*x0 + mB*x1**2 + mF*rF**2 + mH*zH**2 + mR*x0 + 2*x1*x2 + x3
        E[..., 2, 3] = x14
        E[..., 2, 4] = x17
        E[..., 2, 5] = x18
        E[..., 3, 2] = x14
        E[..., 3, 3] = IFxx*x19 + IFxx*(1 - x19) + mF*x7**2 + mH*x11**2 + x13*x4 + x20*x5
        E[..., 3, 4] = x23
        E[..., 3, 5] = x24
        E[..., 4, 2] = x17
        E[..., 4, 3] = x23
        E[..., 4, 4] = x25
        E[..., 4, 5] = x31
        E[..., 5, 2] = x18
        E[..., 5, 3] = x24
        E[..., 5, 4] = x31
        E[..., 5, 5] = IBzz + IHzz + c**2*mF - 2*c*x27 + mB*xB**2 + mF*x32 + mH*x10**2 + mH*x32 + 2*x10*x28 + x3
        E[..., 6, 6] = sigmaR
        E[..., 7, 7] = sigmaF
        E[..., 8, 8] = 1
        E[..., 9, 9] = 1
        A[..., 0, 0, 2] = 1
        A[..., 0, 1, 3] = 1
        A[..., 0, 2, 0] = -g*x12 + g*x15 + g*x16 + g*x2 + g*x8
        A[..., 0, 2, 1] = x38
        A[..., 0, 3, 0] = x38 + x43
        A[..., 0, 3, 1] = -k_arms + x33*x4 + x34*x4 - x37*x4 + x4*x43
        A[..., 0, 3, 3] = -c_arms
        A[..., 0, 3, 7] = -tpF*x5 - x6
        A[..., 0, 4, 6] = 1
        A[..., 0, 4, 7] = 1
        A[..., 0, 5, 0] = CmgR*x44 + x42
        A[..., 0, 5, 1] = x4*x42
        A[..., 0, 5, 6] = -tpR
        A[..., 0, 5, 7] = -tpF + w
        A[..., 0, 6, 4] = -CaR*x44
        A[..., 0, 7, 3] = x46*x6
        A[..., 0, 7, 4] = -x46
        A[..., 0, 7, 5] = -x39*x45
        A[..., 0, 8, 5] = 1
        A[..., 0, 9, 4] = 1
        A[..., 1, 2, 3] = -x48
        A[..., 1, 2, 5] = -x17 - x49
        A[..., 1, 3, 2] = x48
        A[..., 1, 3, 5] = -x23 - x50
        A[..., 1, 4, 5] = -x25
        A[..., 1, 5, 2] = x49
        A[..., 1, 5, 3] = x50
        A[..., 1, 5, 5] = -x31
        A[..., 1, 6, 0] = CgR*x44
        A[..., 1, 6, 6] = -1
        A[..., 1, 7, 0] = CgF*x41
        A[..., 1, 7, 1] = x41*(CaF*x5 + CgF*x4)
        A[..., 1, 7, 7] = -1
        A[..., 1, 9, 8] = 1
        B[..., 0, 2, 0] = 1
        B[..., 0, 3, 1] = 1
        return E, A, B
    return coefficients


_arrays = _make(np.cos, np.sin)
_floats = _make(math.cos, math.sin)


def coefficients(w, c, lam, g, rR, mR, IRxx, IRyy, xB, zB, mB, IBxx, IByy, IBzz, IBxz, xH, zH, mH, IHxx, IHyy, IHzz, IHxz, rF, mF, IFxx, IFyy, k_arms, c_arms, CaR, CgR, sigmaR, tpR, CmgR, CaF, CgF, sigmaF, tpF, CmgF):
    """``(E, A, B)``: E (..., 10, 10), A (..., 2, 10, 10), B (..., 1, 10, 2), the leading
    dimensions those of the parameters (floats or arrays, SI, see PARAMETERS) broadcast together;
    complex where a parameter is (the complex step: exact derivatives)."""
    args = (w, c, lam, g, rR, mR, IRxx, IRyy, xB, zB, mB, IBxx, IByy, IBzz, IBxz, xH, zH, mH, IHxx, IHyy, IHzz, IHxz, rF, mF, IFxx, IFyy, k_arms, c_arms, CaR, CgR, sigmaR, tpR, CmgR, CaF, CgF, sigmaF, tpF, CmgF,)
    if all(type(a) is float for a in args):
        return _floats((), float, *args)
    return _arrays(np.broadcast_shapes(*(np.shape(a) for a in args)), np.result_type(float, *args), *args)
