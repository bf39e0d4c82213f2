"""Critical speeds and strictly stable ranges without a grid: the part of the engine that sweeps,
sensitivities and uncertainty need for many configurations.

The crossings are the engine's (:mod:`~bikemass.analysis.engine.crossings`, or the closed form
of a two-coordinate model, :mod:`~bikemass.analysis.engine.closed_form`); between two crossings
the number of unstable roots is constant, so one count inside each interval (the Routh array of
the quartic, or the eigenvalues) gives every direction and every stable range.  The count in the
first interval also gives the modes unstable from the lowest speed, which no crossing reports (an
undamped oscillation on the axis at standstill that grows from there, or any mode already unstable
where the span starts).

Every crossing and every mode unstable from the start is named by the tracked mode whose root it is
(:func:`~bikemass.analysis.engine.tracked.root_name`), the same naming the stability analysis uses:
the weave speed is the weave's crossing, never another oscillation's.  The two-coordinate Whipple
bicycle's only oscillations are the weave and a capsize + caster pair, and on every thesis set and
random variants of them only the weave crosses (tests/test_engine_models.py), so its closed form
names every oscillatory crossing ``weave`` without following the modes.
"""

from dataclasses import dataclass

import numpy as np

from ...core.results import Result, quantity
from . import closed_form, scalar
from .crossings import DESTABILISING, OSCILLATORY, REAL, STABILISING, TOUCHING, Crossing, Eigenvalues, axis_crossings
from .naming import WEAVE_FAMILY, WOBBLE, family, is_weave
from .tracked import TrackedModes, root_name

START_OFFSET = 1e-3
"""Where the modes unstable from the lowest speed ``lo`` are told apart: at ``lo + START_OFFSET
(1 + lo)`` m/s, or halfway to the first crossing if that is nearer (the same roots are unstable
anywhere before it)."""


@dataclass(frozen=True, eq=False)
class StartInstability(Result):
    """A mode unstable from the lowest speed of the span on (no crossing of ``Re = 0`` reports it).

    Attributes
    ----------
    speed : float
        The span's lowest speed (m/s).
    kind : str
        ``"oscillatory"`` (a complex pair) or ``"real"``.
    frequency : float
        ``|Im|`` of the root just above the lowest speed (rad/s); 0 for a real root.
    mode : str
        The tracked mode (a pair by its family, as a crossing is named), ``""`` if not tracked.
    """

    speed: float = quantity("m/s")
    kind: str = ""
    frequency: float = quantity("rad/s", default=0.0)
    mode: str = ""


@dataclass(frozen=True, eq=False)
class CriticalSpeeds(Result):
    """Every crossing of ``Re = 0`` in ``(lo, hi]`` (ascending), the strictly stable ranges, and the
    modes unstable from ``lo``."""

    crossings: tuple = ()
    stable: tuple = quantity("m/s", default=())
    lo: float = quantity("m/s", default=0.0)
    hi: float = quantity("m/s", default=30.0)
    unstable_at_start: tuple = ()

    @property
    def weave_crossing(self):
        """The first crossing of the weave (:func:`~bikemass.analysis.engine.naming.is_weave`), or ``None``."""
        return next((c for c in self.crossings if c.kind == OSCILLATORY and is_weave(c.mode)), None)

    @property
    def capsize_crossing(self):
        """The first real crossing, or ``None``."""
        return next((c for c in self.crossings if c.kind == REAL), None)

    @property
    def weave_speed(self):
        """The first crossing of the weave (m/s), or ``None``."""
        return None if self.weave_crossing is None else self.weave_crossing.speed

    @property
    def wobble_speed(self):
        """The first crossing of wobble (m/s), or ``None``."""
        return next((c.speed for c in self.crossings if c.kind == OSCILLATORY and family(c.mode) == WOBBLE), None)

    @property
    def capsize_speed(self):
        """The first real crossing (m/s), or ``None``."""
        return None if self.capsize_crossing is None else self.capsize_crossing.speed

    @property
    def stable_from(self):
        """Start of the first strictly stable range (m/s), or ``None``."""
        return self.stable[0][0] if self.stable else None

    @property
    def stable_to(self):
        """End of the first strictly stable range (m/s), or ``None``."""
        return self.stable[0][1] if self.stable else None


def _start_roots(at, lo, end, count):
    """``(speed, roots)``: the ``count`` unstable roots of the first interval ``(lo, end)``, each pair
    once (its upper member), at a speed just above ``lo``, the most unstable first."""
    speed = lo + min(0.5 * (end - lo), START_OFFSET * (1 + lo))
    if not count:
        return speed, []
    roots = at(speed)
    roots = roots.tolist() if isinstance(roots, np.ndarray) else roots    # a handful: sorted in Python
    top = sorted(roots, key=lambda r: -r.real)[:count]
    return speed, sorted((r for r in top if r.imag >= 0), key=lambda r: -r.real)


def critical_speeds(model, hi=30.0, lo=0.0, tracked=None):
    """:class:`CriticalSpeeds` of a :class:`~bikemass.models.linear.LinearModel` on ``(lo, hi]`` (m/s).

    ``tracked`` (a :class:`~bikemass.analysis.engine.tracked.TrackedModes` of the model) names the
    crossings; without it a model beyond the two-coordinate closed form has its modes followed from
    standstill on the default grid's step up to its last crossing, and the closed form names an
    oscillatory crossing ``weave`` and leaves a real one unnamed (see the module docstring)."""
    if closed_form.applies(model):
        return closed_critical_speeds(scalar.model_pieces(model), hi, lo, tracked)
    at = tracked.at if tracked is not None else Eigenvalues(model)
    found = axis_crossings(model, lo, hi, at)
    def count(a, b):
        on_grid = _grid_count(tracked, a, b)
        return int(np.sum(at(0.5 * (a + b)).real > 0)) if on_grid is None else on_grid
    ends = [lo, *[s for s, _, _ in found], hi]
    counts = [count(a, b) if b > a else None for a, b in zip(ends, ends[1:])]
    start, start_roots = _start_roots(at, lo, ends[1], counts[0]) if hi > lo else (lo, [])
    if tracked is None and (found or start_roots):
        tracked = TrackedModes.up_to(model, lo, max([start, *[s for s, _, _ in found]]), at)
    name = lambda v, root: root_name(tracked, v, root)                         # noqa: E731
    return _assembled(found, counts, ends, lo, hi, start, start_roots, name, tracked)


GRID_CLEAR = 1e-8
"""A grid speed's roots count the unstable ones of the interval holding it when each is at least
GRID_CLEAR (1 + |root|) 1/s off the axis (the grid's roots are within 1e-10 of it of LAPACK's)."""


def _grid_count(tracked, a, b):
    """The number of roots with ``Re > 0`` between the crossings ``a`` and ``b`` (m/s) read off the
    tracked modes' grid, at its speed nearest the interval's middle that lies inside it (no crossing
    between them: every crossing is one of the interval's ends); ``None`` without such a speed, or
    where a root there is too near the axis to tell its side (the caller takes the eigenvalues at the
    middle)."""
    if tracked is None:
        return None
    v = tracked.modes.speeds
    first = int(np.searchsorted(v, a + GRID_CLEAR * (1 + abs(a)), side="right"))
    last = int(np.searchsorted(v, b - GRID_CLEAR * (1 + abs(b)), side="left")) - 1
    if first > last:
        return None
    roots = tracked.modes.eigenvalues[(first + last) // 2]
    if not np.all(np.abs(roots.real) > GRID_CLEAR * (1 + np.abs(roots))):
        return None
    return int(np.sum(roots.real > 0))


def whipple_critical_speeds(params, stiffness=None, hi=30.0, lo=0.0):
    """:class:`CriticalSpeeds` of the Whipple bicycle of ``params`` (a benchmark parameter set, rigid or
    with the quasi-static rear-frame stiffness ``stiffness``, N m/rad) on ``(lo, hi]`` (m/s): the
    scalar fast path (:mod:`~bikemass.analysis.engine.scalar`), no model built; the same numbers as
    :func:`critical_speeds` of its model.  The parameters are taken as they are (checked by the caller)."""
    return closed_critical_speeds(scalar.whipple_pieces(params, stiffness), hi, lo)


def closed_critical_speeds(p, hi=30.0, lo=0.0, tracked=None):
    """:class:`CriticalSpeeds` from the closed form's pieces ``p`` (:func:`scalar.pieces`), in floats."""
    found = scalar.axis_crossings(p, lo, hi, (REAL, OSCILLATORY))
    ends = [lo, *[s for s, _, _ in found], hi]
    counts = [scalar.unstable_count(p, 0.5 * (a + b)) if b > a else None for a, b in zip(ends, ends[1:])]
    if tracked is not None:
        at = tracked.at
    else:
        at = lambda v: scalar.roots(scalar.quartic(p, v))                         # noqa: E731
    start, start_roots = _start_roots(at, lo, ends[1], counts[0]) if hi > lo else (lo, [])
    if tracked is not None:
        name = lambda v, root: root_name(tracked, v, root)                         # noqa: E731
    else:
        name = lambda v, root: WEAVE_FAMILY if root.imag else ""                  # noqa: E731
    return _assembled(found, counts, ends, lo, hi, start, start_roots, name, tracked)


def _assembled(found, counts, ends, lo, hi, start, start_roots, name, tracked):
    """The :class:`CriticalSpeeds` of the crossings ``found`` and the unstable counts between them."""
    crossings = []
    for k, (speed, kind, w) in enumerate(found):
        before, after = counts[k], counts[k + 1]
        direction = (TOUCHING if before is None or after is None or before == after
                     else STABILISING if after < before else DESTABILISING)
        crossings.append(Crossing.frozen(speed, kind, direction, w,
                                         name(speed, 1j * w if kind == OSCILLATORY else 0j)))
    if tracked is not None:                       # in the order of the modes' labels
        start_roots = sorted(start_roots, key=lambda r: tracked.column_of(start, r))
    unstable = tuple(StartInstability.frozen(float(lo), OSCILLATORY if r.imag else REAL, float(r.imag),
                                             name(start, r)) for r in start_roots)
    stable = []
    for (a, b), n in zip(zip(ends, ends[1:]), counts):
        if n == 0:
            if stable and stable[-1][1] == a:
                stable[-1][1] = b
            else:
                stable.append([a, b])
    return CriticalSpeeds.frozen(tuple(crossings), tuple(tuple(r) for r in stable), float(lo), float(hi), unstable)
