"""Critical speeds as roots: where a mode's real part (or stability margin) crosses zero.

Each sign change of a mode on the speed grid brackets one root; ``brentq`` then
finds it to ``XTOL`` on the eigenvalue, at any speed, that continues the tracked
mode (the root nearest to the straight line between the two bracketing values).
Two crossings inside one grid step are not seen: use a finer grid.
"""

import numpy as np
from scipy.optimize import brentq

from .criteria import ZERO_TOL, margin
from .eigen import eigenvalues_at

XTOL = 1e-13
"""Absolute speed tolerance (m/s) of the root finder."""


def mode_margin(matrices, speeds, values, i, j, marginal=None):
    """Function ``v -> margin`` on ``[speeds[i], speeds[j]]`` of the mode whose tracked values are ``values``."""
    v0, v1 = speeds[i], speeds[j]

    def f(v):
        guess = values[i] + (values[j] - values[i]) * (v - v0) / (v1 - v0)
        roots = eigenvalues_at(matrices, v)
        return float(margin(roots[np.argmin(np.abs(roots - guess))], marginal))
    return f


def overall_margin(matrices, marginal=None):
    """Function ``v -> largest margin of all four eigenvalues`` (negative = all stable)."""
    return lambda v: float(np.max(margin(eigenvalues_at(matrices, v), marginal)))


def root_in(f, a, b):
    """Root of ``f`` in ``[a, b]``; the end nearer a zero value when ``f`` does not change sign."""
    fa, fb = f(a), f(b)
    if fa == 0 or fb == 0 or np.sign(fa) == np.sign(fb):
        return a if abs(fa) <= abs(fb) else b
    return brentq(f, a, b, xtol=XTOL, rtol=4 * np.finfo(float).eps)


def sign_changes(x):
    """Pairs ``(i, j)`` of grid indices bracketing each sign change of ``x`` (values within ZERO_TOL of 0 skipped)."""
    s = np.where(x > ZERO_TOL, 1, np.where(x < -ZERO_TOL, -1, 0))
    idx = np.flatnonzero(s)
    change = s[idx[1:]] != s[idx[:-1]]
    return list(zip(idx[:-1][change], idx[1:][change]))


def mode_crossings(matrices, modes, label):
    """Speeds (m/s, ascending) where mode ``label``'s real part crosses zero, as roots.

    Returns ``[(speed, direction)]`` with direction ``"stabilising"`` (Re goes negative)
    or ``"destabilising"``.
    """
    v, values = modes.speeds, modes[label]
    out = []
    for i, j in sign_changes(values.real):
        speed = root_in(mode_margin(matrices, v, values, i, j), v[i], v[j])
        out.append((speed, "stabilising" if values.real[i] > 0 else "destabilising"))
    return out
