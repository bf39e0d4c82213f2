"""Speed grids: the thesis's default grid, a grid from start, stop and step, and speeds given as
values, each checked and bounded (:mod:`bikemass.core.limits`) before any array is made."""

import numbers

import numpy as np

from ...core.errors import InputError
from ...core.limits import MAX_SPEED, MAX_SPEEDS, MIN_SPEED_STEP
from .modes import check_speeds

DEFAULT_SPEEDS = (0.0, 30.0, 0.05)
"""The thesis's speed grid: start, stop, step (m/s)."""


def speed_count(start, stop, step):
    """How many speeds ``start, start + step, ...`` lie within ``stop`` (m/s).

    A last step that lands on ``stop`` to within 1e-9 of the count counts; one beyond it does not.

    Examples
    --------
    >>> speed_count(0.0, 30.0, 0.05)
    601
    >>> speed_count(0.0, 1.0, 0.3)
    4
    """
    steps = (stop - start) / step
    return int(np.floor(steps + 1e-9 * max(1.0, steps))) + 1


def speed_grid(start=DEFAULT_SPEEDS[0], stop=DEFAULT_SPEEDS[1], step=DEFAULT_SPEEDS[2]):
    """``start, start + step, ...`` up to ``stop`` (m/s; never beyond it), rounded to 1e-12 so
    that 4.3 prints as 4.3.

    Examples
    --------
    >>> speed_grid(0.0, 1.0, 0.3).tolist()
    [0.0, 0.3, 0.6, 0.9]
    """
    return np.round(start + step * np.arange(speed_count(start, stop, step)), 12)


def speed_range(start, stop, step, max_speeds=MAX_SPEEDS, source="speeds", given=None, limit_name="max_speeds="):
    """The grid :func:`speed_grid` of ``start, stop, step`` (m/s), checked against the limits of
    :mod:`bikemass.core.limits` before any array is made: the library's ``bm.speeds`` and the
    command line's ``--speeds START:STOP:STEP`` alike.

    Parameters
    ----------
    start, stop, step : float
        ``0 <= start < stop <= MAX_SPEED`` and ``MIN_SPEED_STEP <= step <= stop - start`` (m/s).
    max_speeds : int
        Most speeds on the grid.
    source, given, limit_name : str
        What an InputError names: the argument (``speeds``, ``--speeds``), the value as given
        (default ``start:stop:step``) and how to raise ``max_speeds`` (``None``: it cannot be raised there).

    Returns
    -------
    numpy.ndarray of shape (n,)

    Raises
    ------
    InputError
        Outside the limits above, or more than ``max_speeds`` speeds.

    Examples
    --------
    >>> speed_range(0, 2, 0.5).tolist()
    [0.0, 0.5, 1.0, 1.5, 2.0]
    """
    limit = _checked_limit(max_speeds)
    given = f"{start!r}:{stop!r}:{step!r}" if given is None else given
    if not all(isinstance(x, numbers.Real) and not isinstance(x, bool) for x in (start, stop, step)) or \
            not (0 <= start < stop <= MAX_SPEED and MIN_SPEED_STEP <= step <= stop - start):
        raise InputError(source, given, f"START:STOP:STEP in m/s with 0 <= START < STOP <= {MAX_SPEED:g}, "
                         f"{MIN_SPEED_STEP:g} <= STEP <= STOP - START")
    count = speed_count(start, stop, step)
    if count > limit:
        raise InputError(source, given, f"at most {limit} speeds, got {count}"
                         + (f" (raise with {limit_name})" if limit_name else ""))
    return speed_grid(start, stop, step)


def _checked_limit(max_speeds):
    """``max_speeds`` checked: a whole number of speeds >= 1."""
    if isinstance(max_speeds, bool) or not isinstance(max_speeds, int) or max_speeds < 1:
        raise InputError("max_speeds", repr(max_speeds), "a whole number of speeds >= 1")
    return max_speeds


def speed_values(values, max_speeds=MAX_SPEEDS):
    """``values`` checked as speeds (m/s; the default grid for ``None``), their number first.

    Parameters
    ----------
    values : array_like of shape (n,) or None
        Increasing speeds >= 0 (m/s).
    max_speeds : int
        Most speeds taken; more is an InputError before any array is made of them.

    Returns
    -------
    numpy.ndarray of shape (n,)

    Raises
    ------
    InputError
        For more than ``max_speeds`` speeds, or speeds that are not finite, >= 0 and increasing.
    """
    if values is None:
        return speed_grid()
    _checked_limit(max_speeds)
    try:
        count = len(values)
    except TypeError:
        count = 1
    if count > max_speeds:
        raise InputError("speeds", f"{count} speeds", f"at most {max_speeds} speeds (raise max_speeds=; each "
                         "speed holds the model's eigenvalues and eigenvectors)")
    return check_speeds(values)
