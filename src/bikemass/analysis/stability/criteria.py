"""When is an eigenvalue stable?  One signed margin per criterion (negative = stable).

* strict: ``Re(lambda) < 0``;
* marginal (Williams 2015, Sec. 4.1): ``Re(lambda) < 0`` or ``|lambda| < threshold``
  (2 rad/s by default: slow enough for a rider to control).

``Re`` counts as negative only below ``-ZERO_TOL``: at ``v = 0`` the bicycle is
conservative and an oscillatory pair has ``Re = 0`` exactly (the thesis's tables
count it as not stable); rounding must not turn that into stability.
"""

import numpy as np

MARGINAL_THRESHOLD = 2.0
"""Default modulus (rad/s) below which an unstable eigenvalue counts as marginally stable."""
ZERO_TOL = 1e-10
"""Real parts within this distance of zero (1/s) count as zero on the grid."""


def margin(values, marginal=None):
    """Signed stability margin of eigenvalues (1/s): ``Re`` or ``min(Re, |lambda| - marginal)``."""
    values = np.asarray(values)
    if marginal is None:
        return values.real
    return np.minimum(values.real, np.abs(values) - marginal)


def is_stable(values, marginal=None):
    """Boolean array: each eigenvalue stable under the criterion (``marginal=None`` = strict)."""
    values = np.asarray(values)
    stable = values.real < -ZERO_TOL
    if marginal is not None:
        stable |= np.abs(values) < marginal
    return stable
