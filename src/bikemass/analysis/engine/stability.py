"""One call from a linear model to its modes, exact critical speeds and stable speed ranges."""

from dataclasses import dataclass

import numpy as np

from scipy.optimize import linear_sum_assignment

from ...frozen import freeze
from .crossings import OSCILLATORY, REAL, STABILISING, DESTABILISING, TOUCHING, Crossing, Eigenvalues
from .crossings import axis_crossings, circle_speeds
from . import closed_form
from .eigen import eigen_sweep
from .modes import follow_modes
from .naming import family
from .tracking import reorder, track
from .ranges import MARGINAL_THRESHOLD, grid_ranges, interval_ranges, intersect, is_stable, margin

DEFAULT_SPEEDS = (0.0, 30.0, 0.05)
"""The thesis's speed grid: start, stop, step (m/s)."""
WOBBLE = "wobble"
"""The family name of a steer-dominated high-frequency mode of a flexible model."""
CRITERIA = ("strict", "marginal")


def speed_grid(start=DEFAULT_SPEEDS[0], stop=DEFAULT_SPEEDS[1], step=DEFAULT_SPEEDS[2]):
    """``start, start + step, ..., stop`` (m/s), rounded to 1e-12 so that 4.3 prints as 4.3."""
    n = int(round((stop - start) / step)) + 1
    return np.round(start + step * np.arange(n), 12)


class _Tracked:
    """The root continuing each tracked mode at any speed inside the grid.

    Inside a grid cell the modes are followed again on a fine sub-grid (:data:`SUBSTEPS` steps,
    the same tracking as on the grid), so that roots that meet, split or trade places inside one
    grid step are still told apart; at a speed between sub-grid points the root nearest the
    straight line between the mode's two neighbouring values continues it.
    """

    SUBSTEPS = 32

    def __init__(self, model, modes, at):
        self.model, self.modes, self.at = model, modes, at
        self._cells = {}

    def _cell(self, k):
        cell = self._cells.get(k)
        if cell is None:
            s = self.modes.speeds
            sub = np.linspace(s[k], s[k + 1], self.SUBSTEPS + 1)
            sweep = eigen_sweep(self.model, sub)
            start = self.modes.eigenvalues[k]
            first = linear_sum_assignment(np.abs(start[:, None] - sweep.eigenvalues[0][None, :]))[1]
            order = track(sweep.eigenvalues, sweep.eigenvectors)[:, first]
            values, _ = reorder(sweep.eigenvalues, sweep.eigenvectors, order)
            cell = self._cells[k] = (sub, values)
        return cell

    def guess(self, v):
        """Each mode's value (m,) at speed ``v`` by interpolation on the fine sub-grid."""
        s, values = self.modes.speeds, self.modes.eigenvalues
        if len(s) == 1:
            return values[0]
        k = int(np.clip(np.searchsorted(s, v) - 1, 0, len(s) - 2))
        sub, vals = self._cell(k)
        j = int(np.clip(np.searchsorted(sub, v) - 1, 0, len(sub) - 2))
        t = (v - sub[j]) / (sub[j + 1] - sub[j])
        return vals[j] + t * (vals[j + 1] - vals[j])

    def root(self, v, column):
        roots = self.at(v)
        return roots[np.argmin(np.abs(roots - self.guess(v)[column]))]

    def column_of(self, v, root):
        return int(np.argmin(np.abs(self.guess(v) - root)))


def _named(tracked, speed, kind, frequency, labels):
    """The tracked mode that crosses at ``speed``: a label, or a pair's family (``"weave"``)."""
    root = 1j * frequency if kind == OSCILLATORY else 0.0
    first = tracked.column_of(speed, root)
    if kind == REAL:
        return labels[first]
    guess = tracked.guess(speed)
    guess[first] = np.inf
    second = int(np.argmin(np.abs(guess - np.conj(root))))
    a, b = labels[first], labels[second]
    return family(a) if family(a) == family(b) and a != b else " + ".join(sorted((a, b)))


@dataclass(frozen=True, eq=False)
class Stability:
    """Modes, critical speeds (m/s) and stable speed ranges of one linear model.

    ``crossings``: every :class:`~bikemass.analysis.engine.crossings.Crossing` of ``Re = 0`` on the
    grid's span, by speed.  ``ranges[criterion]`` and ``mode_ranges[label][criterion]`` are
    ``{"exact": ((start, stop), ...), "grid": (...)}`` with criterion ``"strict"`` or
    ``"marginal"`` (an eigenvalue of modulus below ``marginal`` rad/s also counts).  Exact ends
    are boundary speeds found without a grid; grid ends are the first and last stable grid speeds.
    """

    model: str
    modes: object
    marginal: float
    crossings: tuple
    ranges: object
    mode_ranges: object

    def speeds_of(self, kind, wobble=False):
        """Sorted speeds (m/s) of the crossings of ``kind``; oscillatory ones of the wobble family
        only with ``wobble``, the others without."""
        return tuple(c.speed for c in self.crossings if c.kind == kind
                     and (kind == REAL or (family(c.mode) == WOBBLE) == wobble))

    @property
    def weave_speeds(self):
        """Speeds (m/s) where an oscillatory pair other than wobble crosses ``Re = 0``, ascending."""
        return self.speeds_of(OSCILLATORY)

    @property
    def capsize_speeds(self):
        """Speeds (m/s) where a real root crosses ``Re = 0`` (capsize; also a branch of a split pair)."""
        return self.speeds_of(REAL)

    @property
    def wobble_speeds(self):
        """Speeds (m/s) where the wobble pair crosses ``Re = 0``, ascending."""
        return self.speeds_of(OSCILLATORY, wobble=True)

    def mode_crossings(self, label):
        """The crossings of the tracked mode ``label`` (a pair's crossing counts for both members)."""
        return tuple(c for c in self.crossings if c.mode == label or c.mode == family(label) != label)

    @property
    def weave_ranges(self):
        """``{criterion: {"exact"|"grid": ((start, stop), ...)}}`` where both weave roots are stable."""
        w1, w2 = self.mode_ranges["weave 1"], self.mode_ranges["weave 2"]
        return freeze({c: {k: intersect(w1[c][k], w2[c][k]) for k in w1[c]} for c in w1})

    def to_dict(self):
        """The ``bikemass stability --format json`` document (``modes`` adds ``weave``: both roots)."""
        plain = lambda x: [list(r) for r in x]
        return {
            "model": self.model,
            "weave_speeds": list(self.weave_speeds),
            "capsize_speeds": list(self.capsize_speeds),
            **({"wobble_speeds": list(self.wobble_speeds)} if self.wobble_speeds else {}),
            "crossings": [c.to_dict() for c in self.crossings],
            "marginal_threshold": self.marginal,
            "ranges": {c: {k: plain(r) for k, r in v.items()} for c, v in self.ranges.items()},
            "modes": {label: {c: {k: plain(r) for k, r in v.items()} for c, v in ranges.items()}
                      for label, ranges in {"weave": self.weave_ranges, **self.mode_ranges}.items()},
        }


def _directions(at, found, lo, hi):
    """Each crossing's direction from the number of unstable roots on either side."""
    speeds = sorted({s for s, _, _ in found})
    ends = [lo, *speeds, hi]
    count = {}
    for a, b in zip(ends, ends[1:]):
        count[(a, b)] = int(np.sum(at(0.5 * (a + b)).real > 0)) if b > a else None
    out = []
    for speed, kind, w in found:
        k = speeds.index(speed)
        before, after = count[(ends[k], speed)], count[(speed, ends[k + 2])]
        if before is None or after is None or before == after:
            out.append(TOUCHING)
        else:
            out.append(STABILISING if after < before else DESTABILISING)
    return out


def analyse(model, speeds=None, marginal=MARGINAL_THRESHOLD):
    """:class:`Stability` of a :class:`~bikemass.models.linear.LinearModel` over ``speeds`` (m/s;
    default the thesis's 0..30 m/s grid in steps of 0.05 m/s); ``marginal`` in rad/s."""
    modes = follow_modes(model, speed_grid() if speeds is None else speeds)
    v = modes.speeds
    lo, hi = float(v[0]), float(v[-1])
    at = Eigenvalues(model)
    tracked = _Tracked(model, modes, at)
    found = closed_form.axis_crossings(model, lo, hi) if closed_form.applies(model) else axis_crossings(model, lo, hi, at)
    crossings = tuple(Crossing(s, kind, direction, w, _named(tracked, s, kind, w, modes.labels))
                      for (s, kind, w), direction in zip(found, _directions(at, found, lo, hi)))
    axis = [c.speed for c in crossings]
    limits = {"strict": None, "marginal": marginal}
    boundaries = {"strict": axis, "marginal": sorted([*axis, *circle_speeds(model, marginal, lo, hi, at)])}
    ranges, mode_ranges = {}, {label: {} for label in modes.labels}
    for criterion, r in limits.items():
        ranges[criterion] = {
            "exact": interval_ranges(lo, hi, boundaries[criterion], lambda x: bool(np.all(margin(at(x), r) < 0))),
            "grid": grid_ranges(v, is_stable(modes.eigenvalues, r).all(axis=1))}
        for c, label in enumerate(modes.labels):
            mode_ranges[label][criterion] = {
                "exact": interval_ranges(lo, hi, boundaries[criterion],
                                         lambda x: bool(margin(tracked.root(x, c), r) < 0)),
                "grid": grid_ranges(v, is_stable(modes.eigenvalues[:, c], r))}
    return Stability(model.name, modes, float(marginal), crossings, freeze(ranges), freeze(mode_ranges))
