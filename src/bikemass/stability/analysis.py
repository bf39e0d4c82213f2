"""One call from canonical matrices to critical speeds and stable ranges."""

from dataclasses import dataclass

import numpy as np

from .critical import mode_crossings
from .criteria import MARGINAL_THRESHOLD
from .labels import LABELS
from .modes import Modes, follow_modes
from .ranges import intersect, mode_ranges, overall_ranges

DEFAULT_SPEEDS = (0.0, 30.0, 0.05)
"""The thesis's speed grid: start, stop, step (m/s)."""


def speed_grid(start=DEFAULT_SPEEDS[0], stop=DEFAULT_SPEEDS[1], step=DEFAULT_SPEEDS[2]):
    """``start, start + step, ..., stop`` (m/s), rounded to 1e-12 so that 4.3 prints as 4.3."""
    n = int(round((stop - start) / step)) + 1
    return np.round(start + step * np.arange(n), 12)


def _unique(speeds, tol=1e-8):
    out = []
    for s in sorted(speeds):
        if not out or s - out[-1] > tol:
            out.append(s)
    return out


@dataclass(frozen=True)
class Stability:
    """Critical speeds (m/s) and stable ranges of one bicycle.

    ``crossings[label]`` = ``[(speed, "stabilising" | "destabilising"), ...]``;
    ``ranges[criterion]`` and ``mode_ranges[label][criterion]`` =
    ``{"exact": [[start, stop], ...], "grid": [...]}`` with criterion ``"strict"``
    or ``"marginal"`` (modulus below ``marginal`` rad/s also counts).
    """

    modes: Modes
    marginal: float
    crossings: dict
    ranges: dict
    mode_ranges: dict

    def critical_speeds(self, *labels):
        """Sorted speeds (m/s) where any of ``labels`` crosses Re = 0 (pair members counted once)."""
        return _unique(s for label in labels for s, _ in self.crossings[label])

    @property
    def weave_speeds(self):
        return self.critical_speeds("weave 1", "weave 2")

    @property
    def capsize_speeds(self):
        return self.critical_speeds("capsize")

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
            "caster_speeds": self.critical_speeds("caster"),
            "crossings": [{"mode": label, "speed": s, "direction": d}
                          for label in LABELS for s, d in self.crossings[label]],
            "marginal_threshold": self.marginal,
            "ranges": self.ranges,
            "modes": {"weave": self.weave_ranges, **self.mode_ranges},
        }


def stability(matrices, speeds=None, marginal=MARGINAL_THRESHOLD):
    """:class:`Stability` of ``matrices`` over ``speeds`` (default: the 0..30 m/s, 0.05 grid)."""
    modes = follow_modes(matrices, speed_grid() if speeds is None else speeds)
    criteria = {"strict": None, "marginal": marginal}
    return Stability(
        modes=modes, marginal=marginal,
        crossings={label: mode_crossings(matrices, modes, label) for label in LABELS},
        ranges={name: overall_ranges(matrices, modes, m) for name, m in criteria.items()},
        mode_ranges={label: {name: mode_ranges(matrices, modes, label, m)
                             for name, m in criteria.items()} for label in LABELS})
