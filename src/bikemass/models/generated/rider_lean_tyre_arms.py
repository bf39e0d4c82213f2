"""The linear equations of motion of the bikemass model ``rider-lean+tyre+arms``: GENERATED, do not edit.

Written by ``python -m bikemass.models.derive`` (bikemass.models.derive, sympy 1.14.0) from the derivation
in ``bikemass.models.derive`` (Kane's method with sympy.physics.mechanics, linearised about the
upright straight run at speed v).  Descriptor form, states and inputs as listed below::

    E x' = sum_k v**k A[k] x + sum_k v**k B[k] u
"""

import math

import numpy as np


NAME = 'rider-lean+tyre+arms'
MEMBERS = ('rider-lean', 'tyre', 'arms')
PARAMETERS = (('w', 'm', 'wheelbase'), ('c', 'm', 'trail'), ('lam', 'rad', 'steer-axis tilt'), ('g', 'm/s^2', 'gravity'), ('rR', 'm', 'rear wheel radius'), ('mR', 'kg', 'rear wheel mass'), ('IRxx', 'kg m^2', 'rear wheel Ixx'), ('IRyy', 'kg m^2', 'rear wheel Iyy'), ('xB', 'm', 'rear frame CoM x'), ('zB', 'm', 'rear frame CoM z'), ('mB', 'kg', 'rear frame mass'), ('IBxx', 'kg m^2', 'rear frame Ixx'), ('IByy', 'kg m^2', 'rear frame Iyy'), ('IBzz', 'kg m^2', 'rear frame Izz'), ('IBxz', 'kg m^2', 'rear frame Ixz'), ('xH', 'm', 'front frame CoM x'), ('zH', 'm', 'front frame CoM z'), ('mH', 'kg', 'front frame mass'), ('IHxx', 'kg m^2', 'front frame Ixx'), ('IHyy', 'kg m^2', 'front frame Iyy'), ('IHzz', 'kg m^2', 'front frame Izz'), ('IHxz', 'kg m^2', 'front frame Ixz'), ('rF', 'm', 'front wheel radius'), ('mF', 'kg', 'front wheel mass'), ('IFxx', 'kg m^2', 'front wheel Ixx'), ('IFyy', 'kg m^2', 'front wheel Iyy'), ('mU', 'kg', 'upper body mass'), ('xU', 'm', 'upper body CoM x'), ('zU', 'm', 'upper body CoM z'), ('IUxx', 'kg m^2', 'upper body Ixx'), ('IUyy', 'kg m^2', 'upper body Iyy'), ('IUzz', 'kg m^2', 'upper body Izz'), ('IUxz', 'kg m^2', 'upper body Ixz'), ('zhip', 'm', 'hip (lean) axis z'), ('klean', 'N m/rad', 'lean stiffness'), ('clean', 'N m s/rad', 'lean damping'), ('k_arms', 'N m/rad', "arms' stiffness about the steer axis"), ('c_arms', 'N m s/rad', "arms' damping about the steer axis"), ('CaR', '1/rad', 'rear cornering coefficient'), ('CgR', '1/rad', 'rear camber coefficient'), ('sigmaR', 'm', 'rear relaxation length'), ('tpR', 'm', 'rear pneumatic trail'), ('CmgR', 'm/rad', 'rear twisting torque coefficient'), ('CaF', '1/rad', 'front cornering coefficient'), ('CgF', '1/rad', 'front camber coefficient'), ('sigmaF', 'm', 'front relaxation length'), ('tpF', 'm', 'front pneumatic trail'), ('CmgF', 'm/rad', 'front twisting torque coefficient'))
"""(name, SI unit, meaning) of every argument of coefficients, in order."""
STATES = (('roll-angle', 'rad'), ('steer-angle', 'rad'), ('lean-angle', 'rad'), ('roll-rate', 'rad/s'), ('steer-rate', 'rad/s'), ('lean-rate', 'rad/s'), ('lateral-velocity', 'm/s'), ('yaw-rate', 'rad/s'), ('rear-lateral-force', 'N'), ('front-lateral-force', 'N'), ('heading', 'rad'), ('lateral', 'm'))
"""(name, unit) of every state; the first N_DYNAMIC are dynamic."""
N_DYNAMIC = 10
INPUTS = (('roll-torque', 'N m'), ('steer-torque', 'N m'), ('lean-torque', 'N m'))
FAMILIES = (('bicycle', (0, 1, 3, 4)), ('lean', (2, 5)), ('tyre', (6, 7, 8, 9)))
"""Mode families: (name, indices of their dynamic states)."""
COORDINATES = 3
"""How many dynamic mechanical coordinates q lead the states (then their rates q')."""
SECOND_ORDER = False
"""Whether the dynamic states are exactly [q, q']."""


def _make(cos, sin):
    """The coefficient function computing with these functions (cos, sin)."""

    def coefficients(shape, dtype, w, c, lam, g, rR, mR, IRxx, IRyy, xB, zB, mB, IBxx, IByy, IBzz, IBxz, xH, zH, mH, IHxx, IHyy, IHzz, IHxz, rF, mF, IFxx, IFyy, mU, xU, zU, IUxx, IUyy, IUzz, IUxz, zhip, klean, clean, k_arms, c_arms, CaR, CgR, sigmaR, tpR, CmgR, CaF, CgF, sigmaF, tpF, CmgF):
        x0 = rR + zhip
        x1 = -zU + zhip
        x2 = mU*x1
        x3 = -x0*x2
        x4 = -x0
        x5 = x2*x4
        x6 = rR**2
        x7 = -rR - zB
        x8 = mU*rR
        x9 = mU*x0
        x10 = mB*rR
        x11 = x1*x8
        x12 = IUxx + mU*x1**2
        x13 = IFxx + IRxx
        x14 = sin(lam)
        x15 = cos(lam)
        x16 = c*x15
        x17 = rF*x14 - x16
        x18 = mF*rF
        x19 = c + w
        x20 = -x19 + xH
        x21 = -x14*zH + x15*x20
        x22 = mH*zH
        x23 = IHxx*x14 + IHxz*x15
        x24 = IFxx*x14 + x17*x18 - x21*x22 + x23
        x25 = x11 + x12
        x26 = mB*x7
        x27 = mR*rR
        x28 = x10 + x18 + x2 - x22 + x26 + x27 + x8
        x29 = x28 - x9
        x30 = IUxz + x2*xU
        x31 = IBxz + IHxz - c*x18 + x10*xB + x18*x19 - x19*x22 - x20*x22 + x26*xB + x30 + x8*xU
        x32 = x15**2
        x33 = 1 - x32
        x34 = IHxz*x14 + IHzz*x15
        x35 = mF*x17
        x36 = mH*x21
        x37 = x35 + x36
        x38 = IFxx*x15 - c*x35 + x19*x35 + x19*x36 + x20*x36 + x34
        x39 = mU*x4
        x40 = mB + mF + mH + mR + mU
        x41 = mF*x19
        x42 = mH*x19
        x43 = mH*x20
        x44 = c*mF
        x45 = mB*xB
        x46 = mU*xU
        x47 = x45 + x46
        x48 = x41 + x42 + x43 - x44 + x47
        x49 = x19**2
        x50 = g*x2
        x51 = g*x35
        x52 = g*x36
        x53 = 1/w
        x54 = -g*x19
        x55 = x16*x53*(-g*x43 + g*x44 - g*x45 - g*x46 + mF*x54 + mH*x54)
        x56 = x51 + x52 - x55
        x57 = mF*w + mH*xH + x47
        x58 = x53*x57
        x59 = g*x58
        x60 = CmgF*x59
        x61 = x15*x60
        x62 = k_arms*x14
        x63 = c_arms*x14
        x64 = g*(x40 - x58)
        x65 = CaF*g
        x66 = x58*x65
        x67 = IFyy/rF
        x68 = x15*x67
        x69 = IRyy/rR + x67
        x70 = x14*x67
        E = np.zeros(shape + (12, 12), dtype)
        A = np.zeros(shape + (2, 12, 12), dtype)
        B = np.zeros(shape + (1, 12, 3), dtype)
        E[..., 0, 0] = 1
        E[..., 1, 1] = 1
        E[..., 2, 2] = 1
        E[..., 3, 3] = IBxx + IHxx + mB*x6 + mB*x7**2 + mF*rF**2 + mH*zH**2 + mR*x6 + mU*x6 - x0*x8 + 2*x10*x7 + 2*x11 + x12 + x13 + x3 + x4*x8 - x4*x9 + x5
        E[..., 3, 4] = x24
        E[..., 3, 5] = x25 + x3
        E[..., 3, 6] = x29
        E[..., 3, 7] = x31 - x9*xU
        E[..., 4, 3] = x24
        E[..., 4, 4] = IFxx*x32 + IFxx*x33 + mF*x17**2 + mH*x21**2 + x14*x23 + x15*x34
        E[..., 4, 6] = x37
        E[..., 4, 7] = x38
        E[..., 5, 3] = x25 + x5
        E[..., 5, 5] = x12
        E[..., 5, 6] = x2
        E[..., 5, 7] = x30
        E[..., 6, 3] = x28 + x39
        E[..., 6, 4] = x37
        E[..., 6, 5] = x2
        E[..., 6, 6] = x40
        E[..., 6, 7] = x48
        E[..., 7, 3] = x31 + x39*xU
        E[..., 7, 4] = x38
        E[..., 7, 5] = x30
        E[..., 7, 6] = x48
        E[..., 7, 7] = IBzz + IHzz + IUzz + c**2*mF - 2*c*x41 + mB*xB**2 + mF*x49 + mH*x20**2 + mH*x49 + mU*xU**2 + x13 + 2*x20*x42
        E[..., 8, 8] = sigmaR
        E[..., 9, 9] = sigmaF
        E[..., 10, 10] = 1
        E[..., 11, 11] = 1
        A[..., 0, 0, 3] = 1
        A[..., 0, 1, 4] = 1
        A[..., 0, 2, 5] = 1
        A[..., 0, 3, 0] = g*x10 + g*x18 - g*x22 + g*x26 + g*x27 + g*x8 - g*x9 + x50
        A[..., 0, 3, 1] = x56
        A[..., 0, 3, 2] = x50
        A[..., 0, 4, 0] = x56 + x61
        A[..., 0, 4, 1] = -k_arms + x14*x51 + x14*x52 - x14*x55 + x14*x61
        A[..., 0, 4, 2] = x62
        A[..., 0, 4, 4] = -c_arms
        A[..., 0, 4, 5] = x63
        A[..., 0, 4, 9] = -tpF*x15 - x16
        A[..., 0, 5, 0] = x50
        A[..., 0, 5, 1] = x62
        A[..., 0, 5, 2] = g*mU*x1 - k_arms*x33 - klean
        A[..., 0, 5, 4] = x63
        A[..., 0, 5, 5] = -c_arms*x33 - clean
        A[..., 0, 6, 8] = 1
        A[..., 0, 6, 9] = 1
        A[..., 0, 7, 0] = CmgR*x64 + x60
        A[..., 0, 7, 1] = x14*x60
        A[..., 0, 7, 8] = -tpR
        A[..., 0, 7, 9] = -tpF + w
        A[..., 0, 8, 6] = -CaR*x64
        A[..., 0, 9, 4] = x16*x66
        A[..., 0, 9, 6] = -x66
        A[..., 0, 9, 7] = -x57*x65
        A[..., 0, 10, 7] = 1
        A[..., 0, 11, 6] = 1
        A[..., 1, 3, 4] = -x68
        A[..., 1, 3, 7] = -x29 - x69
        A[..., 1, 4, 3] = x68
        A[..., 1, 4, 7] = -x37 - x70
        A[..., 1, 5, 7] = -x2
        A[..., 1, 6, 7] = -x40
        A[..., 1, 7, 3] = x69
        A[..., 1, 7, 4] = x70
        A[..., 1, 7, 7] = -x48
        A[..., 1, 8, 0] = CgR*x64
        A[..., 1, 8, 8] = -1
        A[..., 1, 9, 0] = CgF*x59
        A[..., 1, 9, 1] = x59*(CaF*x15 + CgF*x14)
        A[..., 1, 9, 9] = -1
        A[..., 1, 11, 10] = 1
        B[..., 0, 3, 0] = 1
        B[..., 0, 4, 1] = 1
        B[..., 0, 5, 2] = 1
        return E, A, B
    return coefficients


_arrays = _make(np.cos, np.sin)
_floats = _make(math.cos, math.sin)


def coefficients(w, c, lam, g, rR, mR, IRxx, IRyy, xB, zB, mB, IBxx, IByy, IBzz, IBxz, xH, zH, mH, IHxx, IHyy, IHzz, IHxz, rF, mF, IFxx, IFyy, mU, xU, zU, IUxx, IUyy, IUzz, IUxz, zhip, klean, clean, k_arms, c_arms, CaR, CgR, sigmaR, tpR, CmgR, CaF, CgF, sigmaF, tpF, CmgF):
    """``(E, A, B)``: E (..., 12, 12), A (..., 2, 12, 12), B (..., 1, 12, 3), the leading
    dimensions those of the parameters (floats or arrays, SI, see PARAMETERS) broadcast together;
    complex where a parameter is (the complex step: exact derivatives)."""
    args = (w, c, lam, g, rR, mR, IRxx, IRyy, xB, zB, mB, IBxx, IByy, IBzz, IBxz, xH, zH, mH, IHxx, IHyy, IHzz, IHxz, rF, mF, IFxx, IFyy, mU, xU, zU, IUxx, IUyy, IUzz, IUxz, zhip, klean, clean, k_arms, c_arms, CaR, CgR, sigmaR, tpR, CmgR, CaF, CgF, sigmaF, tpF, CmgF,)
    if all(type(a) is float for a in args):
        return _floats((), float, *args)
    return _arrays(np.broadcast_shapes(*(np.shape(a) for a in args)), np.result_type(float, *args), *args)
