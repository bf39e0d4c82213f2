"""The linear equations of motion of the bikemass model ``rider-lean+arms``: GENERATED, do not edit.

Written by ``python -m bikemass.models.derive`` (bikemass.models.derive, sympy 1.14.0) from the derivation
in ``bikemass.models.derive`` (Kane's method with sympy.physics.mechanics, linearised about the
upright straight run at speed v).  Descriptor form, states and inputs as listed below::

    E x' = sum_k v**k A[k] x + sum_k v**k B[k] u
"""

import math

import numpy as np


NAME = 'rider-lean+arms'
MEMBERS = ('rider-lean', 'arms')
PARAMETERS = (('w', 'm', 'wheelbase'), ('c', 'm', 'trail'), ('lam', 'rad', 'steer-axis tilt'), ('g', 'm/s^2', 'gravity'), ('rR', 'm', 'rear wheel radius'), ('mR', 'kg', 'rear wheel mass'), ('IRxx', 'kg m^2', 'rear wheel Ixx'), ('IRyy', 'kg m^2', 'rear wheel Iyy'), ('xB', 'm', 'rear frame CoM x'), ('zB', 'm', 'rear frame CoM z'), ('mB', 'kg', 'rear frame mass'), ('IBxx', 'kg m^2', 'rear frame Ixx'), ('IByy', 'kg m^2', 'rear frame Iyy'), ('IBzz', 'kg m^2', 'rear frame Izz'), ('IBxz', 'kg m^2', 'rear frame Ixz'), ('xH', 'm', 'front frame CoM x'), ('zH', 'm', 'front frame CoM z'), ('mH', 'kg', 'front frame mass'), ('IHxx', 'kg m^2', 'front frame Ixx'), ('IHyy', 'kg m^2', 'front frame Iyy'), ('IHzz', 'kg m^2', 'front frame Izz'), ('IHxz', 'kg m^2', 'front frame Ixz'), ('rF', 'm', 'front wheel radius'), ('mF', 'kg', 'front wheel mass'), ('IFxx', 'kg m^2', 'front wheel Ixx'), ('IFyy', 'kg m^2', 'front wheel Iyy'), ('mU', 'kg', 'upper body mass'), ('xU', 'm', 'upper body CoM x'), ('zU', 'm', 'upper body CoM z'), ('IUxx', 'kg m^2', 'upper body Ixx'), ('IUyy', 'kg m^2', 'upper body Iyy'), ('IUzz', 'kg m^2', 'upper body Izz'), ('IUxz', 'kg m^2', 'upper body Ixz'), ('zhip', 'm', 'hip (lean) axis z'), ('klean', 'N m/rad', 'lean stiffness'), ('clean', 'N m s/rad', 'lean damping'), ('k_arms', 'N m/rad', "arms' stiffness about the steer axis"), ('c_arms', 'N m s/rad', "arms' damping about the steer axis"))
"""(name, SI unit, meaning) of every argument of coefficients, in order."""
STATES = (('roll-angle', 'rad'), ('steer-angle', 'rad'), ('lean-angle', 'rad'), ('roll-rate', 'rad/s'), ('steer-rate', 'rad/s'), ('lean-rate', 'rad/s'), ('heading', 'rad'), ('lateral', 'm'))
"""(name, unit) of every state; the first N_DYNAMIC are dynamic."""
N_DYNAMIC = 6
INPUTS = (('roll-torque', 'N m'), ('steer-torque', 'N m'), ('lean-torque', 'N m'))
FAMILIES = (('bicycle', (0, 1, 3, 4)), ('lean', (2, 5)))
"""Mode families: (name, indices of their dynamic states)."""
COORDINATES = 3
"""How many dynamic mechanical coordinates q lead the states (then their rates q')."""
SECOND_ORDER = True
"""Whether the dynamic states are exactly [q, q']."""


def _make(cos, sin):
    """The coefficient function computing with these functions (cos, sin)."""

    def coefficients(shape, dtype, w, c, lam, g, rR, mR, IRxx, IRyy, xB, zB, mB, IBxx, IByy, IBzz, IBxz, xH, zH, mH, IHxx, IHyy, IHzz, IHxz, rF, mF, IFxx, IFyy, mU, xU, zU, IUxx, IUyy, IUzz, IUxz, zhip, klean, clean, k_arms, c_arms):
        x0 = -zU + zhip
        x1 = rR + zhip
        x2 = mU*x1
        x3 = -x0*x2
        x4 = -x1
        x5 = mU*x0
        x6 = x4*x5
        x7 = rR**2
        x8 = -rR - zB
        x9 = mU*rR
        x10 = mB*rR
        x11 = x0*x9
        x12 = IUxx + mU*x0**2
        x13 = IFxx + IRxx
        x14 = mB*x8
        x15 = c + w
        x16 = mF*rF
        x17 = -x15 + xH
        x18 = IUxz + x5*xU
        x19 = IBxz + IHxz - c*mF*rF - mH*x15*zH - mH*x17*zH + x10*xB + x14*xB + x15*x16 + x18 + x9*xU
        x20 = mU*x1*xU - x19
        x21 = 1/w
        x22 = cos(lam)
        x23 = c*x22
        x24 = x21*x23
        x25 = sin(lam)
        x26 = rF*x25 - x23
        x27 = x17*x22 - x25*zH
        x28 = mH*zH
        x29 = IHxx*x25 + IHxz*x22
        x30 = IFxx*x25 + x16*x26 - x27*x28 + x29
        x31 = x11 + x12
        x32 = mU*xU
        x33 = x22**2
        x34 = 1 - x33
        x35 = IHxz*x25 + IHzz*x22
        x36 = mF*x26
        x37 = mH*x27
        x38 = IFxx*x22 - c*mF*x26 + x15*x36 + x15*x37 + x17*x37 + x35
        x39 = -x38
        x40 = x15**2
        x41 = mH*x15
        x42 = -IBzz - IHzz - IUzz - c**2*mF + 2*c*mF*x15 - mB*xB**2 - mF*x40 - mH*x17**2 - mH*x40 - mU*xU**2 - x13 - 2*x17*x41
        x43 = -x18
        x44 = -x24*x43
        x45 = mR*rR
        x46 = g*x5
        x47 = g*x36
        x48 = g*x37
        x49 = -g*x15
        x50 = mB*xB
        x51 = mH*x17
        x52 = c*g*mF - g*x32 - g*x50 - g*x51 + mF*x49 + mH*x49
        x53 = -x24*x52 + x47 + x48
        x54 = 1/rR
        x55 = c*x33
        x56 = k_arms*x25
        x57 = c_arms*x25
        x58 = x21*x22
        x59 = IFyy/rF
        x60 = x22*x59
        x61 = IRyy*x54 + x59
        x62 = mH*zH + mU*x1 - x10 - x14 - x16 - x45 - x5 - x61 - x9
        x63 = x25*x59
        x64 = -x36 - x37 - x63
        x65 = c*mF - mF*x15 - x32 - x41 - x50 - x51
        E = np.zeros(shape + (8, 8), dtype)
        A = np.zeros(shape + (3, 8, 8), dtype)
        B = np.zeros(shape + (1, 8, 3), dtype)
        E[..., 0, 0] = 1
        E[..., 1, 1] = 1
        E[..., 2, 2] = 1
        E[..., 3, 3] = IBxx + IHxx + mB*x7 + mB*x8**2 + mF*rF**2 + mH*zH**2 + mR*x7 + mU*x7 - rR*x2 + 2*x10*x8 + 2*x11 + x12 + x13 - x2*x4 + x3 + x4*x9 + x6
        E[..., 3, 4] = -x20*x24 + x30
        E[..., 3, 5] = x3 + x31
        E[..., 4, 3] = -x24*(-x19 - x32*x4) + x30
        E[..., 4, 4] = IFxx*x33 + IFxx*x34 + mF*x26**2 + mH*x27**2 + x22*x35 - x24*x39 - x24*(c*x21*x22*x42 - x38) + x25*x29
        E[..., 4, 5] = x44
        E[..., 5, 3] = x31 + x6
        E[..., 5, 4] = x44
        E[..., 5, 5] = x12
        E[..., 6, 6] = 1
        E[..., 7, 7] = 1
        A[..., 0, 0, 3] = 1
        A[..., 0, 1, 4] = 1
        A[..., 0, 2, 5] = 1
        A[..., 0, 3, 0] = g*x10 + g*x14 + g*x16 - g*x2 - g*x28 + g*x45 + g*x9 + x46
        A[..., 0, 3, 1] = x53
        A[..., 0, 3, 2] = x46
        A[..., 0, 4, 0] = x53
        A[..., 0, 4, 1] = -k_arms + x25*x47 + x25*x48 - x52*x54*(-rR*x21*(c*x15*x33*x54 - x23*x25) + x15*x21*x55)
        A[..., 0, 4, 2] = x56
        A[..., 0, 4, 4] = -c_arms
        A[..., 0, 4, 5] = x57
        A[..., 0, 5, 0] = x46
        A[..., 0, 5, 1] = x56
        A[..., 0, 5, 2] = g*mU*x0 - k_arms*x34 - klean
        A[..., 0, 5, 4] = x57
        A[..., 0, 5, 5] = -c_arms*x34 - clean
        A[..., 0, 6, 4] = x24
        A[..., 1, 3, 4] = x20*x58 + x24*x62 - x60
        A[..., 1, 4, 3] = x24*x61 + x60
        A[..., 1, 4, 4] = x24*x64 + x24*(x24*x65 + x42*x58 + x63) + x39*x58
        A[..., 1, 5, 4] = x21*x22*x43 - x24*x5
        A[..., 1, 6, 1] = x58
        A[..., 1, 7, 6] = 1
        A[..., 2, 3, 1] = x58*x62
        A[..., 2, 4, 1] = x58*x64 + x55*x65/w**2
        A[..., 2, 5, 1] = -x5*x58
        B[..., 0, 3, 0] = 1
        B[..., 0, 4, 1] = 1
        B[..., 0, 5, 2] = 1
        return E, A, B
    return coefficients


_arrays = _make(np.cos, np.sin)
_floats = _make(math.cos, math.sin)


def coefficients(w, c, lam, g, rR, mR, IRxx, IRyy, xB, zB, mB, IBxx, IByy, IBzz, IBxz, xH, zH, mH, IHxx, IHyy, IHzz, IHxz, rF, mF, IFxx, IFyy, mU, xU, zU, IUxx, IUyy, IUzz, IUxz, zhip, klean, clean, k_arms, c_arms):
    """``(E, A, B)``: E (..., 8, 8), A (..., 3, 8, 8), B (..., 1, 8, 3), the leading
    dimensions those of the parameters (floats or arrays, SI, see PARAMETERS) broadcast together;
    complex where a parameter is (the complex step: exact derivatives)."""
    args = (w, c, lam, g, rR, mR, IRxx, IRyy, xB, zB, mB, IBxx, IByy, IBzz, IBxz, xH, zH, mH, IHxx, IHyy, IHzz, IHxz, rF, mF, IFxx, IFyy, mU, xU, zU, IUxx, IUyy, IUzz, IUxz, zhip, klean, clean, k_arms, c_arms,)
    if all(type(a) is float for a in args):
        return _floats((), float, *args)
    return _arrays(np.broadcast_shapes(*(np.shape(a) for a in args)), np.result_type(float, *args), *args)
