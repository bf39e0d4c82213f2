"""Critical speeds and strictly stable ranges without a grid: the part of the engine that sweeps,
sensitivities and uncertainty need for many configurations.

The crossings are the engine's (:mod:`~bikemass.analysis.engine.crossings`, or the closed form
of a two-coordinate model, :mod:`~bikemass.analysis.engine.closed_form`); between two crossings
the number of unstable roots is constant, so one count inside each interval (the Routh array of
the quartic, or the eigenvalues) gives every direction and every stable range.
"""

from dataclasses import dataclass

import numpy as np

from ...core.results import Result, quantity
from . import closed_form
from .crossings import DESTABILISING, OSCILLATORY, REAL, STABILISING, TOUCHING, Crossing, Eigenvalues, axis_crossings
from .naming import WOBBLE, crossing_is_wobble


@dataclass(frozen=True, eq=False)
class CriticalSpeeds(Result):
    """Every crossing of ``Re = 0`` in ``(lo, hi]`` (ascending) and the strictly stable ranges."""

    crossings: tuple = ()
    stable: tuple = quantity("m/s", default=())
    lo: float = quantity("m/s", default=0.0)
    hi: float = quantity("m/s", default=30.0)

    def first(self, kind, wobble=False):
        """Speed (m/s) of the first crossing of ``kind`` (oscillatory: of wobble only with ``wobble``,
        of the others without), or ``None``."""
        return next((c.speed for c in self.crossings if c.kind == kind
                     and (kind == REAL or (c.mode == WOBBLE) == wobble)), None)

    @property
    def weave_speed(self):
        """The first oscillatory crossing other than wobble (m/s), or ``None``."""
        return self.first(OSCILLATORY)

    @property
    def wobble_speed(self):
        """The first crossing of wobble (m/s), or ``None``."""
        return self.first(OSCILLATORY, wobble=True)

    @property
    def capsize_speed(self):
        """The first real crossing (m/s), or ``None``."""
        return self.first(REAL)

    @property
    def stable_from(self):
        """Start of the first strictly stable range (m/s), or ``None``."""
        return self.stable[0][0] if self.stable else None

    @property
    def stable_to(self):
        """End of the first strictly stable range (m/s), or ``None``."""
        return self.stable[0][1] if self.stable else None


def critical_speeds(model, hi=30.0, lo=0.0):
    """:class:`CriticalSpeeds` of a :class:`~bikemass.models.linear.LinearModel` on ``(lo, hi]`` (m/s).

    Beyond the two-coordinate closed form (the Whipple bicycle, which has no wobble) an oscillatory
    crossing of wobble is named so (:func:`~bikemass.analysis.engine.naming.crossing_is_wobble`), and
    :attr:`CriticalSpeeds.weave_speed` skips it, as :attr:`StabilityResult.weave_speeds` does."""
    closed = closed_form.applies(model)
    if closed:
        pieces = closed_form.model_pieces(model)
        found = closed_form.axis_crossings(model, lo, hi)
        count = lambda v: closed_form.unstable_count(closed_form.quartic(pieces, v))   # noqa: E731
    else:
        at = Eigenvalues(model)
        found = axis_crossings(model, lo, hi, at)
        count = lambda v: int(np.sum(at(v).real > 0))          # noqa: E731
    ends = [lo, *[s for s, _, _ in found], hi]
    counts = [count(0.5 * (a + b)) if b > a else None for a, b in zip(ends, ends[1:])]
    crossings = []
    for k, (speed, kind, w) in enumerate(found):
        before, after = counts[k], counts[k + 1]
        direction = (TOUCHING if before is None or after is None or before == after
                     else STABILISING if after < before else DESTABILISING)
        wobble = not closed and kind == OSCILLATORY and crossing_is_wobble(model, speed, w)
        crossings.append(Crossing(speed, kind, direction, w, WOBBLE if wobble else ""))
    stable = []
    for (a, b), n in zip(zip(ends, ends[1:]), counts):
        if n == 0:
            if stable and stable[-1][1] == a:
                stable[-1][1] = b
            else:
                stable.append([a, b])
    return CriticalSpeeds(tuple(crossings), tuple(tuple(r) for r in stable), float(lo), float(hi))
