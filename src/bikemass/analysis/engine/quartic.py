"""Roots of many real quartics at once (vectorised: no Python loop over polynomials).

Ferrari's closed form (via the resolvent cubic, complex arithmetic) gives starting
values; a few Aberth-Ehrlich sweeps then polish all four roots together to
machine precision.  Roots that are real to rounding are returned with zero
imaginary part.
"""

import numpy as np

_OMEGA = np.exp(2j * np.pi * np.arange(3) / 3)


def _cube_root(w):
    """The principal cube root of complex ``w`` (as ``w ** (1/3)``) from its modulus and argument:
    numpy's complex power costs ten times as much."""
    size = np.cbrt(np.abs(w))
    angle = np.angle(w) / 3
    return size * np.cos(angle) + 1j * (size * np.sin(angle))


def _cubic_roots(p, q):
    """The three roots of ``t**3 + p t + q`` (complex, shape (n, 3)) for real ``p``, ``q`` (n,)."""
    half = -q / 2
    d = np.sqrt(half * half + p * p * p / 27 + 0j)
    d = np.where(half * d.real >= 0, d, -d)                 # the larger of -q/2 +- d
    c = _cube_root(half + d)[:, None] * _OMEGA
    with np.errstate(divide="ignore", invalid="ignore"):
        t = c - p[:, None] / (3 * c)
    return np.where(c == 0, 0j, t)


def _ferrari(b, c, d, e):
    """Approximate roots of the monic quartic ``x^4 + b x^3 + c x^2 + d x + e`` (shape (n, 4)); the
    resolvent's coefficients in real arithmetic, no ``**`` (numpy's pow costs 50 times a product)."""
    b2 = b * b
    p = c - 3 * b2 / 8
    q = d - b * c / 2 + b2 * b / 8
    r = e - b * d / 4 + b2 * c / 16 - 3 * (b2 * b2) / 256
    # resolvent m^3 + p m^2 + (p^2/4 - r) m - q^2/8 = 0, shifted m = t - p/3
    m = _cubic_roots(-p * p / 12 - r, -(p * p * p) / 108 + p * r / 3 - q * q / 8) - p[:, None] / 3
    size = np.abs(m)                                            # a non-zero root if any: the largest
    if np.isnan(size).any():
        pick = np.argmax(size, axis=1)
    else:                                                       # the first of equals, as argmax, column by column
        pick = np.where(size[:, 2] > np.maximum(size[:, 0], size[:, 1]), 2, (size[:, 1] > size[:, 0]).astype(int))
    m = m[np.arange(len(m)), pick]
    s = np.sqrt(2 * m)
    with np.errstate(divide="ignore", invalid="ignore"):
        h = np.where(s == 0, 0, q / (2 * s))
    # y^2 + s y + (p/2 + m - h) = 0  and  y^2 - s y + (p/2 + m + h) = 0, then x = y - b/4
    half, base, shift = s / 2, p / 2 + m, b / 4
    square = half * half
    out = np.empty(b.shape + (4,), dtype=complex)
    # sign +1 then -1: base -+ h and -+half - shift, the signs applied without a product (exact either way)
    for k, (inner, centre) in enumerate(((base - h, -half - shift), (base + h, half - shift))):
        disc = np.sqrt(square - inner)
        np.add(centre, disc, out=out[:, 2 * k])
        np.subtract(centre, disc, out=out[:, 2 * k + 1])
    return out


_FIRST, _SECOND = [0, 0, 0, 1, 1, 2], [1, 2, 3, 2, 3, 3]
"""The six pairs ``(i, j)``, ``i < j``, of four roots, in the order the repulsion sums them."""


def _aberth(coeffs, z, sweeps):
    """Polish all roots ``z`` (n, 4) of the monic polynomials ``coeffs`` (n, 5, highest first, the first 1)."""
    a = [c[:, None] for c in coeffs.T[1:]]
    for _ in range(sweeps):
        p = z + a[0]                            # Horner for p and p' (monic: p = 1, p' = 0 to begin), in place
        dp = p + z
        p *= z
        p += a[1]
        dp *= z
        dp += p
        p *= z
        p += a[2]
        dp *= z
        dp += p
        p *= z
        p += a[3]
        with np.errstate(divide="ignore", invalid="ignore"):
            columns = z.T                       # the six pairs, one row each; 1 / (z_i - z_j), 0 where they coincide
            d = np.empty((6, len(z)), dtype=complex)
            for k, (i, j) in enumerate(zip(_FIRST, _SECOND)):
                np.subtract(columns[i], columns[j], out=d[k])
            inv = 1 / d
            inv[d == 0] = 0
            i01, i02, i03, i12, i13, i23 = inv
            # sum over j != i of 1 / (z_i - z_j), each in the order of the pairs (0 1, 0 2, 0 3, 1 2, 1 3, 2 3):
            # (i01 + i02) + i03, (-i01 + i12) + i13, (-i02 - i12) + i23, (-i03 - i13) - i23 (negation is exact:
            # -a + b is b - a and -a - b is -(a + b), to the bit)
            repulsion = np.empty((4, len(z)), dtype=complex)
            np.add(i01, i02, out=repulsion[0])
            repulsion[0] += i03
            np.subtract(i12, i01, out=repulsion[1])
            repulsion[1] += i13
            np.add(i02, i12, out=repulsion[2])
            np.subtract(i23, repulsion[2], out=repulsion[2])
            np.add(i03, i13, out=repulsion[3])
            repulsion[3] += i23
            np.negative(repulsion[3], out=repulsion[3])
            w = p / dp
            step = w / (1 - w * repulsion.T)
        z = np.where(np.isfinite(step), z - step, z)
    return z


def quartic_roots(coeffs, sweeps=1):
    """Roots (n, 4) of real quartics with coefficients ``coeffs`` (n, 5), highest power first."""
    coeffs = np.asarray(coeffs, dtype=float)
    monic = coeffs[:, 1:] / coeffs[:, :1]
    z = _ferrari(*monic.T)
    z = _aberth(np.concatenate([np.ones((len(z), 1)), monic], axis=1), z, sweeps)
    real = np.abs(z.imag) <= 1e-13 * (1 + np.abs(z))
    return np.where(real, z.real + 0j, z)
