"""One call from canonical matrices to critical speeds and stable ranges."""

from dataclasses import dataclass

import numpy as np

from .critical import SpeedEigenvalues, all_crossings, speeds_of_kind
from .criteria import MARGINAL_THRESHOLD
from .labels import LABELS
from .modes import Modes, follow_modes
from .ranges import intersect, mode_ranges, overall_ranges

DEFAULT_SPEEDS = (0.0, 30.0, 0.05)
"""The thesis's speed grid: start, stop, step (m/s)."""


def speed_count(start, stop, step):
    """How many speeds ``start, start + step, ...`` lie within ``stop`` (m/s; a last step that
    lands on ``stop`` to within 1e-9 of the count counts, one beyond it does not)."""
    steps = (stop - start) / step
    return int(np.floor(steps + 1e-9 * max(1.0, steps))) + 1


def speed_grid(start=DEFAULT_SPEEDS[0], stop=DEFAULT_SPEEDS[1], step=DEFAULT_SPEEDS[2]):
    """``start, start + step, ...`` up to ``stop`` (m/s; never beyond it), rounded to 1e-12 so
    that 4.3 prints as 4.3."""
    return np.round(start + step * np.arange(speed_count(start, stop, step)), 12)


@dataclass(frozen=True)
class Stability:
    """Critical speeds (m/s) and stable ranges of one bicycle.

    ``crossings``: every :class:`~bikemass.stability.critical.Crossing` of ``Re = 0`` by
    speed (``speed``, ``kind`` oscillatory|real, ``direction``, tracked ``mode`` label);
    ``ranges[criterion]`` and ``mode_ranges[label][criterion]`` =
    ``{"exact": [[start, stop], ...], "grid": [...]}`` with criterion ``"strict"``
    or ``"marginal"`` (modulus below ``marginal`` rad/s also counts).
    """

    modes: Modes
    marginal: float
    crossings: tuple
    ranges: dict
    mode_ranges: dict

    @property
    def weave_speeds(self):
        """Sorted speeds (m/s) where an oscillatory pair crosses ``Re = 0``, whatever its label."""
        return speeds_of_kind(self.crossings, "oscillatory")

    @property
    def capsize_speeds(self):
        """Sorted speeds (m/s) where a real root crosses ``Re = 0`` (also a branch of a split weave pair)."""
        return speeds_of_kind(self.crossings, "real")

    def mode_crossings(self, label):
        """The crossings of the tracked mode ``label``."""
        return [c for c in self.crossings if c.mode == label]

    @property
    def weave_ranges(self):
        """``{criterion: {"exact"|"grid": [[start, stop], ...]}}`` where both weave roots are stable."""
        w1, w2 = self.mode_ranges["weave 1"], self.mode_ranges["weave 2"]
        return {c: {k: intersect(w1[c][k], w2[c][k]) for k in w1[c]} for c in w1}

    def to_dict(self):
        """The ``bikemass stability --format json`` document (``modes`` adds ``weave``: both roots)."""
        return {
            "weave_speeds": self.weave_speeds,
            "capsize_speeds": self.capsize_speeds,
            "crossings": [c.to_dict() for c in self.crossings],
            "marginal_threshold": self.marginal,
            "ranges": self.ranges,
            "modes": {"weave": self.weave_ranges, **self.mode_ranges},
        }


def critical_speeds(matrices, speeds=None):
    """Every :class:`~bikemass.stability.critical.Crossing` of ``Re = 0`` (tuple by speed), without
    the ranges: the part of :func:`stability` a sweep over many configurations needs."""
    modes = follow_modes(matrices, speed_grid() if speeds is None else speeds)
    return tuple(all_crossings(SpeedEigenvalues(matrices), modes))


def stability(matrices, speeds=None, marginal=MARGINAL_THRESHOLD):
    """:class:`Stability` of ``matrices`` over ``speeds`` (default: the 0..30 m/s, 0.05 grid)."""
    modes = follow_modes(matrices, speed_grid() if speeds is None else speeds)
    at = SpeedEigenvalues(matrices)
    criteria = {"strict": None, "marginal": marginal}
    return Stability(
        modes=modes, marginal=marginal, crossings=tuple(all_crossings(at, modes)),
        ranges={name: overall_ranges(at, modes, m) for name, m in criteria.items()},
        mode_ranges={label: {name: mode_ranges(at, modes, label, m)
                             for name, m in criteria.items()} for label in LABELS})
