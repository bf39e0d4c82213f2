"""The linear equations of motion of the bikemass model ``flexible``: GENERATED, do not edit.

Written by ``python -m bikemass.models.derive`` (bikemass.models.derive, sympy 1.14.0) from the derivation
in ``bikemass.models.derive`` (Kane's method with sympy.physics.mechanics, linearised about the
upright straight run at speed v).  Descriptor form, states and inputs as listed below::

    E x' = sum_k v**k A[k] x + sum_k v**k B[k] u
"""

import math

import numpy as np


NAME = 'flexible'
MEMBERS = ('flexible',)
PARAMETERS = (('w', 'm', 'wheelbase'), ('c', 'm', 'trail'), ('lam', 'rad', 'steer-axis tilt'), ('g', 'm/s^2', 'gravity'), ('rR', 'm', 'rear wheel radius'), ('mR', 'kg', 'rear wheel mass'), ('IRxx', 'kg m^2', 'rear wheel Ixx'), ('IRyy', 'kg m^2', 'rear wheel Iyy'), ('xB', 'm', 'rear frame CoM x'), ('zB', 'm', 'rear frame CoM z'), ('mB', 'kg', 'rear frame mass'), ('IBxx', 'kg m^2', 'rear frame Ixx'), ('IByy', 'kg m^2', 'rear frame Iyy'), ('IBzz', 'kg m^2', 'rear frame Izz'), ('IBxz', 'kg m^2', 'rear frame Ixz'), ('xH', 'm', 'front frame CoM x'), ('zH', 'm', 'front frame CoM z'), ('mH', 'kg', 'front frame mass'), ('IHxx', 'kg m^2', 'front frame Ixx'), ('IHyy', 'kg m^2', 'front frame Iyy'), ('IHzz', 'kg m^2', 'front frame Izz'), ('IHxz', 'kg m^2', 'front frame Ixz'), ('rF', 'm', 'front wheel radius'), ('mF', 'kg', 'front wheel mass'), ('IFxx', 'kg m^2', 'front wheel Ixx'), ('IFyy', 'kg m^2', 'front wheel Iyy'), ('xr', 'm', 'frame twist axis, x of a point'), ('zr', 'm', 'frame twist axis, z of a point'), ('nrx', '1', 'frame twist axis, direction x'), ('nrz', '1', 'frame twist axis, direction z'), ('kr', 'N m/rad', 'frame twist stiffness'), ('mtr', 'kg', "frame tubes' modal particle, mass"), ('xtr', 'm', "frame tubes' modal particle, x"), ('ztr', 'm', "frame tubes' modal particle, z"), ('dtr', 'm/rad', "frame tubes' modal particle, sideways per radian"), ('cr', 'N m s/rad', 'frame twist damping'), ('xf', 'm', 'fork bending axis, x of a point'), ('zf', 'm', 'fork bending axis, z of a point'), ('nfx', '1', 'fork bending axis, direction x'), ('nfz', '1', 'fork bending axis, direction z'), ('kf', 'N m/rad', 'fork bending stiffness'), ('mtf', 'kg', "fork tubes' modal particle, mass"), ('xtf', 'm', "fork tubes' modal particle, x"), ('ztf', 'm', "fork tubes' modal particle, z"), ('dtf', 'm/rad', "fork tubes' modal particle, sideways per radian"), ('cf', 'N m s/rad', 'fork bending damping'), ('cs', 'N m s/rad', 'steering bearing damping'))
"""(name, SI unit, meaning) of every argument of coefficients, in order."""
STATES = (('roll-angle', 'rad'), ('steer-angle', 'rad'), ('frame-twist', 'rad'), ('fork-bending', 'rad'), ('roll-rate', 'rad/s'), ('steer-rate', 'rad/s'), ('frame-twist-rate', 'rad/s'), ('fork-bending-rate', 'rad/s'), ('heading', 'rad'), ('lateral', 'm'))
"""(name, unit) of every state; the first N_DYNAMIC are dynamic."""
N_DYNAMIC = 8
INPUTS = (('roll-torque', 'N m'), ('steer-torque', 'N m'))
FAMILIES = (('bicycle', (0, 1, 4, 5)), ('wobble', (2, 3, 6, 7)))
"""Mode families: (name, indices of their dynamic states)."""
COORDINATES = 4
"""How many dynamic mechanical coordinates q lead the states (then their rates q')."""
SECOND_ORDER = True
"""Whether the dynamic states are exactly [q, q']."""


def _make(cos, sin):
    """The coefficient function computing with these functions (cos, sin)."""

    def coefficients(shape, dtype, w, c, lam, g, rR, mR, IRxx, IRyy, xB, zB, mB, IBxx, IByy, IBzz, IBxz, xH, zH, mH, IHxx, IHyy, IHzz, IHxz, rF, mF, IFxx, IFyy, xr, zr, nrx, nrz, kr, mtr, xtr, ztr, dtr, cr, xf, zf, nfx, nfz, kf, mtf, xtf, ztf, dtf, cf, cs):
        x0 = rR**2
        x1 = -rR - zB
        x2 = zr**2
        x3 = -rR - zr
        x4 = x3**2
        x5 = rF + zf
        x6 = mF*rR
        x7 = -x5
        x8 = mF*zf
        x9 = mF*zr
        x10 = mF*x3
        x11 = mF*x7
        x12 = 2*x8
        x13 = mH*zH
        x14 = 2*x13
        x15 = mB*rR
        x16 = 2*x6
        x17 = 2*x3
        x18 = mH*rR
        x19 = mH*zr
        x20 = IFxx + IRxx
        x21 = sin(lam)
        x22 = w - xf
        x23 = cos(lam)
        x24 = x21*x5 + x22*x23
        x25 = c + w
        x26 = x25 - xr
        x27 = -c - x22
        x28 = mB*x1
        x29 = -x25 + xH
        x30 = mH*x3
        x31 = IBxz + IHxz - mF*x22*zf - mF*x26*zf - mF*x27*zf - mF*xr*zf - mH*x26*zH - mH*x29*zH - mH*xr*zH + x10*x22 + x10*x26 + x10*x27 + x10*xr + x15*xB + x18*x26 + x18*x29 + x18*xr + x19*x26 + x19*x29 + x19*xr + x22*x6 + x22*x9 + x26*x30 + x26*x6 + x26*x9 + x27*x6 + x27*x9 + x28*xB + x29*x30 + x30*xr + x6*xr + x9*xr
        x32 = mF*x22*x7 + mF*x26*x7 + mF*x27*x7 + mF*x7*xr - x31
        x33 = 1/w
        x34 = rF*x21
        x35 = x21*zf
        x36 = -x23*x27 + x35
        x37 = x21*x7
        x38 = -x22*x23 + x37
        x39 = x34 + x36 + x38
        x40 = -x39
        x41 = x33*x40
        x42 = -x36
        x43 = IFxx*x21
        x44 = -x21*zH + x23*x29
        x45 = IHxx*x21 + IHxz*x23
        x46 = x10*x42 - x13*x44 + x18*x44 + x19*x44 + x30*x44 + x42*x6 - x42*x8 + x42*x9 + x43 + x45
        x47 = nrz*x22
        x48 = nrx*x5 + x47
        x49 = nrz*x27
        x50 = nrx*rF
        x51 = nrx*zf
        x52 = nrx*x7
        x53 = nrx*zr
        x54 = nrz*x26
        x55 = x53 + x54
        x56 = x47 + x49 - x50 - x51 - x52 + x55
        x57 = x33*x56
        x58 = nrz*x27 - x51
        x59 = IFxx*nrx
        x60 = dtr*mtr
        x61 = -nrx*zH + nrz*x29
        x62 = IHxx*nrx + IHxz*nrz
        x63 = rR*x60 + x10*x55 + x10*x58 - x13*x55 - x13*x61 + x18*x55 + x18*x61 + x19*x55 + x19*x61 + x30*x55 + x30*x61 + x55*x6 - x55*x8 + x55*x9 + x58*x6 - x58*x8 + x58*x9 + x59 + x60*(-rR - ztr) + x62
        x64 = nfz*x22
        x65 = nfx*x5 + x64
        x66 = nfx*rF
        x67 = nfx*x7
        x68 = -nfz*x22 + x67
        x69 = -x66 - x68
        x70 = x33*x69
        x71 = dtf*mtf
        x72 = IFxx*nfx + rR*x71 + x3*x71 + x71*zr - x71*ztf
        x73 = -x38
        x74 = mF*x73
        x75 = mF*x42
        x76 = mF*xr
        x77 = mF*x22
        x78 = mF*x26
        x79 = mF*x27
        x80 = -x31 - x5*x76 - x5*x77 - x5*x78 - x5*x79
        x81 = x23**2
        x82 = 1 - x81
        x83 = -x45
        x84 = IHxz*x21 + IHzz*x23
        x85 = -x84
        x86 = IFxx*x23
        x87 = mH*xr
        x88 = mH*x26
        x89 = mH*x29
        x90 = x42*x76 + x42*x77 + x42*x78 + x42*x79 + x44*x87 + x44*x88 + x44*x89 + x84 + x86
        x91 = -x24*x76 - x24*x77 - x24*x78 - x24*x79 - x90
        x92 = xr**2
        x93 = x26**2
        x94 = 2*x76
        x95 = 2*x77
        x96 = 2*x87
        x97 = -IBzz - IHzz - mB*xB**2 - mF*x22**2 - mF*x27**2 - mF*x92 - mF*x93 - mH*x29**2 - mH*x92 - mH*x93 - x20 - x22*x94 - x26*x94 - x26*x95 - x26*x96 - 2*x27*x78 - x27*x94 - x27*x95 - 2*x29*x88 - x29*x96
        x98 = x73*x76 + x73*x77 + x73*x78 + x73*x79 + x90
        x99 = -x41*x97 - x98
        x100 = -x62
        x101 = IHxz*nrx + IHzz*nrz
        x102 = -x101
        x103 = IFxx*nrz
        x104 = x101 + x103 + x55*x76 + x55*x77 + x55*x78 + x55*x79 + x55*x87 + x55*x88 + x55*x89 + x58*x76 + x58*x77 + x58*x78 + x58*x79 + x60*xtr + x61*x87 + x61*x88 + x61*x89
        x105 = -x104 - x48*x76 - x48*x77 - x48*x78 - x48*x79
        x106 = mH*x44
        x107 = nrx*x43 + nrz*x86 + x106*x55 + x106*x61 + x55*x75 + x58*x75
        x108 = x25 - xtf
        x109 = -x108
        x110 = IFxx*nfz + x109*x71 + x26*x71 + x71*xr
        x111 = -x110 - x65*x76 - x65*x77 - x65*x78 - x65*x79
        x112 = x21*ztf
        x113 = x109*x23 - x112
        x114 = nfx*x43 + nfz*x86 + x113*x71
        x115 = nrz*x22 - x52
        x116 = mF*x55
        x117 = mF*x115
        x118 = mF*x58
        x119 = x104 + x115*x76 + x115*x77 + x115*x78 + x115*x79
        x120 = -x119 - x57*x97
        x121 = nrx**2
        x122 = nrz**2
        x123 = x55**2
        x124 = mH*x55
        x125 = nrx*ztf
        x126 = nrz*x109 - x125
        x127 = nfx*x59 + nfz*x103 + x126*x71 + x55*x71
        x128 = -x68
        x129 = mF*x128
        x130 = x110 + x128*x76 + x128*x77 + x128*x78 + x128*x79
        x131 = -x130 - x70*x97
        x132 = nfx**2
        x133 = nfz**2
        x134 = mR*rR
        x135 = g*mtf
        x136 = 1/rR
        x137 = rF*x23
        x138 = -rR*x23 + x137 - x23*x3 + x23*x7 + x23*zf - x23*zr
        x139 = rR*x33
        x140 = mB*xB
        x141 = -x26
        x142 = g*mF*x141 + g*mH*x141 + g*mtf*x108 + g*mtf*x109 - g*x140 - g*x76 - g*x77 - g*x79 - g*x87 - g*x89
        x143 = x136*x142
        x144 = g*x74
        x145 = g*x75
        x146 = g*x106
        x147 = x144 + x145 + x146
        x148 = g*(-nrz*x141 + x53)
        x149 = nrz*rF
        x150 = -nrz*rR - nrz*x3 + nrz*x7 + nrz*zf - nrz*zr + x149
        x151 = w*x136
        x152 = g*x117
        x153 = g*x118
        x154 = mH*x61
        x155 = g*x154
        x156 = g*x60 + x152 + x153 + x155
        x157 = g*x71
        x158 = nfx*x23
        x159 = nfz*x21
        x160 = x158 - x159
        x161 = -nfx*x21 - nfz*x23
        x162 = x160*x21 + x161*x23
        x163 = x161*x21
        x164 = -x160*x23 + x163
        x165 = -x164
        x166 = x165*x7
        x167 = g*mF
        x168 = -x162
        x169 = -rF*x168 + rR*x168 + x162*x7 + x168*x3 - x168*zf + x168*zr
        x170 = rF*x164
        x171 = x170 + x64 - x67
        x172 = x23*x26 + x23*xr + x34 + x35 + x37
        x173 = x135*(x108*x21 + x109*x21)
        x174 = nrx*x23
        x175 = nrz*x21 - x174
        x176 = x23*x50
        x177 = nrz*x34
        x178 = nrz*xr + x50 + x51 + x52 - x53
        x179 = x178*x41
        x180 = -nrx*x22*x23 - nrx*x23*x27 + nrx*x34 + nrx*x35 + nrx*x37
        x181 = -x176 + x177
        x182 = nrx*x141 + nrx*x26
        x183 = g*mH
        x184 = x135*(nrx*x108 + nrx*x109) + x167*x182 + x182*x183
        x185 = x166 + x168*x26 + x168*x27 + x168*xr - x170
        x186 = x137*x164 - x160*x7 + x168*x34 - x168*x42 + x185*x41
        x187 = -nfx*x37 + x164*x34 + x21*x64
        x188 = x157*x21
        x189 = g*x116
        x190 = g*x124
        x191 = x126*x21
        x192 = -x172*x57 + x175*x7 + x175*zf + x181 + x23*x55
        x193 = x122 - 1
        x194 = nrx*x162 + nrz*x165
        x195 = x149*x164 + x168*x50 - x168*x55 - x168*x58 + x185*x57 - x194*x7
        x196 = -nfx*x52 + nrx*x64 + x164*x50
        x197 = nrx*x157
        x198 = g*x129
        x199 = x160*x23 - x163
        x200 = rF*x165
        x201 = -nfz*rF*x21 - rF*x160 + x172*x70 + x23*x66
        x202 = nfx*nrz
        x203 = nfz*nrx
        x204 = -nfz*nrx*rF + nrz*x66 - rF*(x202 - x203) + x178*x70
        x205 = x132 - 1
        x206 = nfx*x159
        x207 = nfz*x158
        x208 = x133 - 1
        x209 = nfz*x170 + x168*x66 + x185*x70
        x210 = IFyy/rF
        x211 = x210*x23
        x212 = IRyy*x136 + x210
        x213 = mF*x7 + mF*zf + mH*zH - x10 - x134 - x15 - x18 - x19 - x212 - x28 - x30 - x6 - x9
        x214 = nrz*x210
        x215 = nfz*x210
        x216 = x162*x33
        x217 = x21*x210
        x218 = x23*x33
        x219 = -x140 - x76 - x77 - x78 - x79 - x87 - x88 - x89
        x220 = x217 + x218*x97 - x219*x41
        x221 = -x106 - x217 - x74 - x75
        x222 = -x98
        x223 = nrx*x210
        x224 = nrz*x33
        x225 = -x219*x57 + x223 + x224*x97
        x226 = nrz*x21*x210
        x227 = x174*x210
        x228 = nfx*x210
        x229 = -x216*x97 - x219*x70 + x228
        x230 = x159*x210
        x231 = x158*x210
        x232 = -x116 - x117 - x118 - x124 - x154 - x223 - x60
        x233 = -x119
        x234 = x203*x210
        x235 = x202*x210
        x236 = -x129 - x228 - x71
        x237 = -x130
        x238 = w**(-2)
        x239 = x219*x238
        x240 = x239*x40
        x241 = x239*x56
        x242 = x239*x69
        E = np.zeros(shape + (10, 10), dtype)
        A = np.zeros(shape + (3, 10, 10), dtype)
        B = np.zeros(shape + (1, 10, 2), dtype)
        E[..., 0, 0] = 1
        E[..., 1, 1] = 1
        E[..., 2, 2] = 1
        E[..., 3, 3] = 1
        E[..., 4, 4] = IBxx + IHxx + mB*x0 + mB*x1**2 + mF*x0 + mF*x2 + mF*x4 + mF*zf**2 + mH*x0 + mH*x2 + mH*x4 + mH*zH**2 + mR*x0 - rR*x11 - rR*x12 - rR*x14 + 2*x1*x15 + x10*x5 - x11*x3 - x11*x5 - x11*zr - x12*x3 - x12*zr - x14*x3 - x14*zr + x16*x3 + x16*zr + x17*x18 + x17*x19 + x17*x9 + 2*x18*zr + x20 + x5*x6 - x5*x8 + x5*x9 + x7*x8
        E[..., 4, 5] = x10*x24 - x11*x24 - x11*x42 + x24*x6 - x24*x8 + x24*x9 + x32*x41 + x46
        E[..., 4, 6] = x10*x48 - x11*x48 - x11*x55 - x11*x58 + x32*x57 + x48*x6 - x48*x8 + x48*x9 + x63
        E[..., 4, 7] = x10*x65 - x11*x65 + x32*x70 + x6*x65 - x65*x8 + x65*x9 + x72
        E[..., 5, 4] = x10*x73 + x41*x80 + x46 + x5*x74 + x5*x75 + x6*x73 - x73*x8 + x73*x9
        E[..., 5, 5] = IFxx*x81 + IFxx*x82 + mF*x42**2 + mH*x44**2 - x21*x83 - x23*x85 + x24*x74 + x24*x75 + x41*x91 + x41*x99 + x42*x74
        E[..., 5, 6] = -x100*x21 - x102*x23 + x105*x41 + x107 + x48*x74 + x48*x75 + x55*x74 + x57*x99 + x58*x74
        E[..., 5, 7] = x111*x41 + x114 + x65*x74 + x65*x75 + x70*x99
        E[..., 6, 4] = x10*x115 + x115*x6 - x115*x8 + x115*x9 + x116*x5 + x117*x5 + x118*x5 + x57*x80 + x63
        E[..., 6, 5] = -nrx*x83 - nrz*x85 + x107 + x115*x75 + x116*x24 + x117*x24 + x118*x24 + x120*x41 + x57*x91
        E[..., 6, 6] = IFxx*x121 + IFxx*x122 + dtr**2*mtr + mF*x123 + mF*x58**2 + mH*x123 + mH*x61**2 - nrx*x100 - nrz*x102 + x105*x57 + x115*x116 + x116*x48 + 2*x116*x58 + x117*x48 + x117*x58 + x118*x48 + x120*x57 + 2*x124*x61
        E[..., 6, 7] = x111*x57 + x116*x65 + x117*x65 + x118*x65 + x120*x70 + x127
        E[..., 7, 4] = x10*x128 + x128*x6 - x128*x8 + x128*x9 + x129*x5 + x70*x80 + x72
        E[..., 7, 5] = x114 + x128*x75 + x129*x24 + x131*x41 + x70*x91
        E[..., 7, 6] = x105*x70 + x116*x128 + x118*x128 + x127 + x129*x48 + x131*x57
        E[..., 7, 7] = IFxx*x132 + IFxx*x133 + dtf**2*mtf + x111*x70 + x129*x65 + x131*x70
        E[..., 8, 8] = 1
        E[..., 9, 9] = 1
        A[..., 0, 0, 4] = 1
        A[..., 0, 1, 5] = 1
        A[..., 0, 2, 6] = 1
        A[..., 0, 3, 7] = 1
        A[..., 0, 4, 0] = g*x10 - g*x11 - g*x13 + g*x134 + g*x15 + g*x18 + g*x19 + g*x28 + g*x30 + g*x6 - g*x8 + g*x9
        A[..., 0, 4, 1] = -x113*x135 + x135*(-x108*x23 - x112) - x143*(-x138 - x139*(-w*x136*x138 - x39)) + x147
        A[..., 0, 4, 2] = mF*x148 + mH*x148 - x126*x135 + x135*(-nrz*x108 - x125) - x143*(-x139*(-x150*x151 + x56) - x150) + x156
        A[..., 0, 4, 3] = -x143*(-x139*(x151*x169 + x171) + x169) + x157 + x167*(-x162*x22 - x166)
        A[..., 0, 5, 0] = x142*x41 + x147
        A[..., 0, 5, 1] = -x143*(-x139*(-rF*x82 - x136*x172*x40 + x21*x22*x23 + x21*x23*x27 - x7*x82 - x82*zf) - x172*x41) + x144*x21 + x145*x21 + x146*x21 - x173*x41
        A[..., 0, 5, 2] = nrx*x144 + nrx*x145 + nrx*x146 - x143*(rF*x175 - x139*(w*x136*(rF*x175 + x176 - x177 - x179) - x180) - x179 - x181) - x184*x41
        A[..., 0, 5, 3] = -x143*(-x139*(-x151*x186 + x187) - x186) + x167*(-x160*x22 + x165*x73) + x188
        A[..., 0, 5, 5] = -cs
        A[..., 0, 6, 0] = x142*x57 + x156 + x189 + x190
        A[..., 0, 6, 1] = x135*(x108*x175 + x191) - x135*(-x109*x175 + x191) - x143*(-x139*(w*x136*x192 - x180) + x192) + x167*(x115*x21 - x175*x22) + x167*(-x175*x27 + x21*x58) - x173*x57 + x183*(-x175*x29 + x21*x61)
        A[..., 0, 6, 2] = -kr*x121 - kr*x122 + nrx*x152 + nrx*x153 + nrx*x155 + nrx*x189 + nrx*x190 - x143*(-x139*(nrx*x47 + nrx*x49 + nrx*x54 - rF*x121 - x136*x178*x56 + x193*x7 + x193*zf - x193*zr) - x178*x57) - x184*x57
        A[..., 0, 6, 3] = -x143*(-x139*(-x151*x195 + x196) - x195) + x167*(x115*x165 - x194*x22) + x197
        A[..., 0, 6, 6] = -cr*x121 - cr*x122
        A[..., 0, 7, 0] = x142*x33*(rF*x199 + x171 - x200) + x157 + x198
        A[..., 0, 7, 1] = -x143*(-x139*(-x151*x201 - x165*x34 + x187 + x199*x34) - x201) - x173*x70 + x188 + x198*x21
        A[..., 0, 7, 2] = nrx*x198 - x143*(-x139*(-x151*x204 - x165*x50 + x196 + x199*x50) - x204) - x184*x70 + x197
        A[..., 0, 7, 3] = g*mF*x128*x165 - kf*x132 - kf*x133 - x143*(-x139*(-x151*x209 + 2*x165*x170 + x199*x200 + x22*(-x21*(x205*x23 - x206) + x23*(x205*x21 + x207)) + x7*(-x21*(x207 - x208*x21) + x23*(x206 + x208*x23))) - x209)
        A[..., 0, 7, 7] = -cf*x132 - cf*x133
        A[..., 0, 8, 5] = -x41
        A[..., 0, 8, 6] = -x57
        A[..., 0, 8, 7] = -x70
        A[..., 1, 4, 5] = -x211 - x213*x41 + x23*x32*x33
        A[..., 1, 4, 6] = nrz*x32*x33 - x213*x57 - x214
        A[..., 1, 4, 7] = -x213*x70 - x215 - x216*x32
        A[..., 1, 5, 4] = x211 - x212*x41
        A[..., 1, 5, 5] = -x220*x41 - x221*x41 + x222*x23*x33
        A[..., 1, 5, 6] = nrz*x222*x33 - x221*x57 - x225*x41 - x226 + x227
        A[..., 1, 5, 7] = -x216*x222 - x221*x70 - x229*x41 - x230 + x231
        A[..., 1, 6, 4] = -x212*x57 + x214
        A[..., 1, 6, 5] = -x220*x57 + x226 - x227 + x23*x233*x33 - x232*x41
        A[..., 1, 6, 6] = nrz*x233*x33 - x225*x57 - x232*x57
        A[..., 1, 6, 7] = -x216*x233 - x229*x57 - x232*x70 - x234 + x235
        A[..., 1, 7, 4] = -x212*x70 + x215
        A[..., 1, 7, 5] = -x220*x70 + x23*x237*x33 + x230 - x231 - x236*x41
        A[..., 1, 7, 6] = nrz*x237*x33 - x225*x70 + x234 - x235 - x236*x57
        A[..., 1, 7, 7] = -x216*x237 - x229*x70 - x236*x70
        A[..., 1, 8, 1] = x218
        A[..., 1, 8, 2] = x224
        A[..., 1, 8, 3] = -x216
        A[..., 1, 9, 8] = 1
        A[..., 2, 4, 1] = x213*x218
        A[..., 2, 4, 2] = x213*x224
        A[..., 2, 4, 3] = -x213*x216
        A[..., 2, 5, 1] = x218*x221 - x23*x240
        A[..., 2, 5, 2] = -nrz*x240 + x221*x224
        A[..., 2, 5, 3] = x162*x219*x238*x40 - x216*x221
        A[..., 2, 6, 1] = x218*x232 - x23*x241
        A[..., 2, 6, 2] = -nrz*x241 + x224*x232
        A[..., 2, 6, 3] = x162*x219*x238*x56 - x216*x232
        A[..., 2, 7, 1] = x218*x236 - x23*x242
        A[..., 2, 7, 2] = -nrz*x242 + x224*x236
        A[..., 2, 7, 3] = x162*x219*x238*x69 - x216*x236
        B[..., 0, 4, 0] = 1
        B[..., 0, 5, 1] = 1
        return E, A, B
    return coefficients


_arrays = _make(np.cos, np.sin)
_floats = _make(math.cos, math.sin)


def coefficients(w, c, lam, g, rR, mR, IRxx, IRyy, xB, zB, mB, IBxx, IByy, IBzz, IBxz, xH, zH, mH, IHxx, IHyy, IHzz, IHxz, rF, mF, IFxx, IFyy, xr, zr, nrx, nrz, kr, mtr, xtr, ztr, dtr, cr, xf, zf, nfx, nfz, kf, mtf, xtf, ztf, dtf, cf, cs):
    """``(E, A, B)``: E (..., 10, 10), A (..., 3, 10, 10), B (..., 1, 10, 2), the leading
    dimensions those of the parameters (floats or arrays, SI, see PARAMETERS) broadcast together;
    complex where a parameter is (the complex step: exact derivatives)."""
    args = (w, c, lam, g, rR, mR, IRxx, IRyy, xB, zB, mB, IBxx, IByy, IBzz, IBxz, xH, zH, mH, IHxx, IHyy, IHzz, IHxz, rF, mF, IFxx, IFyy, xr, zr, nrx, nrz, kr, mtr, xtr, ztr, dtr, cr, xf, zf, nfx, nfz, kf, mtf, xtf, ztf, dtf, cf, cs,)
    if all(type(a) is float for a in args):
        return _floats((), float, *args)
    return _arrays(np.broadcast_shapes(*(np.shape(a) for a in args)), np.result_type(float, *args), *args)
