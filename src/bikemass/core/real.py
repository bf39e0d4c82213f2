"""Is a value a finite real number?  The one test the argument checks share: a bool is no number,
and an integer beyond the float range (``10**400``) is not finite (``math.isfinite`` would raise
OverflowError on it)."""

import math
import numbers


def finite_real(x):
    """Whether ``x`` is a real number (not a bool) whose float value is finite.

    Examples
    --------
    >>> finite_real(2.5), finite_real(True), finite_real(float("nan")), finite_real(10 ** 400)
    (True, False, False, False)
    """
    if isinstance(x, bool) or not isinstance(x, numbers.Real):
        return False
    try:
        return math.isfinite(x)
    except OverflowError:
        return False
