"""A bracketing root finder (Brent's method), so that critical speeds need no scipy.optimize.

Brent (1973), "Algorithms for minimization without derivatives", Ch. 4: inverse
quadratic interpolation or secant steps while they shrink the bracket fast enough,
bisection otherwise.  It stops when the bracket around the current best point is
narrower than ``xtol + rtol |x|`` (the stopping rule of ``scipy.optimize.brentq``).
"""

import numpy as np

XTOL = 1e-13
"""Absolute tolerance (m/s) of every critical speed."""
RTOL = 4 * np.finfo(float).eps
"""Relative tolerance of every critical speed."""


def brent(f, a, b, fa=None, fb=None, xtol=XTOL, rtol=RTOL, maxiter=200):
    """Root of ``f`` in ``[a, b]``; ``f(a)`` and ``f(b)`` (given or evaluated) must differ in sign."""
    fa = f(a) if fa is None else fa
    fb = f(b) if fb is None else fb
    if fa == 0:
        return a
    if fb == 0:
        return b
    if (fa > 0) == (fb > 0):
        raise ValueError("f(a) and f(b) must have opposite signs")
    c, fc = a, fa                 # b: best estimate; c: the other end of the bracket; a: previous b
    d = e = b - a
    for _ in range(maxiter):
        if (fb > 0) == (fc > 0):
            c, fc = a, fa
            d = e = b - a
        if abs(fc) < abs(fb):
            a, fa = b, fb
            b, fb = c, fc
            c, fc = a, fa
        tol = (xtol + rtol * abs(b)) / 2
        half = (c - b) / 2
        if fb == 0 or abs(half) <= tol:
            return b
        if abs(e) >= tol and abs(fa) > abs(fb):
            s = fb / fa
            if a == c:                                    # secant
                p, q = 2 * half * s, 1 - s
            else:                                         # inverse quadratic interpolation
                q, r = fa / fc, fb / fc
                p = s * (2 * half * q * (q - r) - (b - a) * (r - 1))
                q = (q - 1) * (r - 1) * (s - 1)
            if p > 0:
                q = -q
            p = abs(p)
            if 2 * p < min(3 * half * q - abs(tol * q), abs(e * q)):
                e, d = d, p / q
            else:
                d = e = half
        else:
            d = e = half
        a, fa = b, fb
        b += d if abs(d) > tol else (tol if half > 0 else -tol)
        fb = f(b)
    raise RuntimeError(f"no convergence in {maxiter} iterations")
