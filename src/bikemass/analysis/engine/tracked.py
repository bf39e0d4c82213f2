"""The root continuing each tracked mode at any speed, and the name of a root from the mode it continues.

:class:`TrackedModes` interpolates the modes followed on a speed grid
(:func:`~bikemass.analysis.engine.modes.follow_modes`) to any speed inside it; :func:`root_name` names
a root at a speed by the tracked mode it continues (a conjugate pair by the two modes of its
members), which is how every crossing of ``Re = 0`` and every mode unstable from the lowest speed is
named: by the stability analysis, and by the critical speeds alone that sweeps, sensitivities and
uncertainty use (:mod:`~bikemass.analysis.engine.critical`).
"""

import numpy as np

from .eigen import eigen_sweep, has_quartic_path, tracked_sweep
from .modes import follow_modes
from .naming import WOBBLE, family, is_weave, is_wobble
from .speeds import DEFAULT_SPEEDS, speed_grid
from .tracking import assignments, track

NAMING_STEP = DEFAULT_SPEEDS[2]
"""Speed step (m/s) of the grid on which modes are followed for naming when no analysis gives one
(the default grid's step: the names are those ``bm.stability`` gives on its default grid)."""


class TrackedModes:
    """The root continuing each tracked mode (:class:`~bikemass.analysis.engine.modes.Modes`) at any
    speed inside the grid.

    Where the roots move by less than a quarter of their smallest distance across a grid cell,
    the root nearest the straight line between the mode's values at the cell's ends continues it.
    In any other cell (roots that meet, split or trade places inside one grid step) the modes are
    followed again on a fine sub-grid of :data:`SUBSTEPS` steps (the same tracking as on the grid)
    and the straight line is drawn between sub-grid points.
    """

    SUBSTEPS = 32

    def __init__(self, model, modes, at):
        self.model, self.modes, self.at = model, modes, at
        self._cells, self._guesses, self._listed = {}, {}, {}

    @classmethod
    def up_to(cls, model, lo, top, at):
        """The modes of ``model`` followed from standstill on a grid of :data:`NAMING_STEP` from
        ``lo`` to at least ``top`` (m/s)."""
        stop = lo + NAMING_STEP * max(1, int(np.ceil((top - lo) / NAMING_STEP - 1e-9)))
        return cls(model, follow_modes(model, speed_grid(lo, stop, NAMING_STEP)), at)

    @property
    def labels(self):
        """The tracked modes' labels."""
        return self.modes.labels

    def _cell(self, k):
        cell = self._cells.get(k)
        if cell is None:
            s, values = self.modes.speeds, self.modes.eigenvalues
            ends = values[k:k + 2]
            if _far_apart(*ends.tolist()):
                cell = self._cells[k] = (s[k:k + 2], ends)
                return cell
            sub = np.linspace(s[k], s[k + 1], self.SUBSTEPS + 1)
            fast = None if has_quartic_path(self.model) else tracked_sweep(self.model, sub)
            if fast is not None:          # eigenvectors only where the roots meet (the same order)
                raw, order = fast.values, fast.order
            else:
                sweep = eigen_sweep(self.model, sub)
                raw, order = sweep.eigenvalues, track(sweep.eigenvalues, sweep.eigenvectors)
            start = self.modes.eigenvalues[k]
            first = assignments(np.abs(start[:, None] - raw[0][None, :])[None])[0]
            values = np.take_along_axis(raw, order[:, first], axis=1)
            cell = self._cells[k] = (sub, values)
        return cell

    def guess(self, v):
        """Each mode's value (m,) at speed ``v`` by interpolation on the fine sub-grid (a fresh array;
        memoised per speed: the ranges ask for every mode at one speed)."""
        v = float(v)
        out = self._guesses.get(v)
        if out is None:
            out = self._guesses[v] = self._guess(v)
        return out.copy()

    def _guess(self, v):
        s, values = self.modes.speeds, self.modes.eigenvalues
        if len(s) == 1:
            return values[0]
        k = min(max(int(np.searchsorted(s, v)) - 1, 0), len(s) - 2)
        sub, vals = self._cell(k)
        j = min(max(int(np.searchsorted(sub, v)) - 1, 0), len(sub) - 2)
        t = (v - sub[j]) / (sub[j + 1] - sub[j])
        return vals[j] + t * (vals[j + 1] - vals[j])

    def root(self, v, column):
        """The eigenvalue (1/s) at ``v`` continuing the mode of ``column``."""
        roots = self.at(v)
        return roots[np.argmin(np.abs(roots - self.guess(v)[column]))]

    def column_of(self, v, root):
        """The column of the mode whose value at ``v`` is nearest ``root`` (the first of equals)."""
        near = self.nearest_columns(v, (root,))
        if near is not None:
            return near[0]
        v = float(v)
        listed = self._listed.get(v)
        if listed is None:
            listed = self._listed[v] = self.guess(v).tolist()
        root = complex(root)
        distances = [abs(g - root) for g in listed]        # a handful: plain Python, no numpy calls
        if all(d == d for d in distances):
            return distances.index(min(distances))
        return int(np.argmin(distances))

    def nearest_columns(self, v, roots):
        """The columns of the modes continued by ``roots`` (complex, at speed ``v``, each column once, in
        turn), each the mode nearest its root on the straight line across the grid cell holding ``v``,
        when every one of them is isolated in that cell (:func:`_isolated`: then the fine sub-grid would
        give the same columns); else ``None``."""
        s, values = self.modes.speeds, self.modes.eigenvalues
        if len(s) < 2:
            return None
        v = float(v)
        k = min(max(int(np.searchsorted(s, v)) - 1, 0), len(s) - 2)
        a, b = values[k].tolist(), values[k + 1].tolist()
        t = (v - s[k]) / (s[k + 1] - s[k])
        line = [x + t * (y - x) for x, y in zip(a, b)]
        taken = []
        for root in roots:
            root = complex(root)
            distances = [abs(g - root) if c not in taken else float("inf") for c, g in enumerate(line)]
            if not all(d == d for d in distances):
                return None
            c = distances.index(min(distances))
            if not _isolated(a, b, c):
                return None
            taken.append(c)
        return taken


def _isolated(a, b, c):
    """Whether root ``c`` of a grid cell is isolated: it and every other root move from ``a`` to ``b``
    (lists of complex, the same modes) by less than a quarter of root ``c``'s distance to that root at
    either end.  Each root then stays within its own quarter across the cell, and the root of ``c`` at
    any speed inside is nearer the straight line of ``c`` than any other root is (:func:`_far_apart`
    asks this of every pair at once)."""
    move_c = abs(b[c] - a[c])
    for j in range(len(a)):
        if j != c and not max(move_c, abs(b[j] - a[j])) < 0.25 * min(abs(a[c] - a[j]), abs(b[c] - b[j])):
            return False
    return True


def _far_apart(a, b):
    """Whether every root moves from ``a`` to ``b`` (lists of complex, the same modes) by less than a
    quarter of the smallest distance between two roots at either end (False where any is NaN): plain
    Python for a handful of roots (numpy's calls cost more than the arithmetic)."""
    m = len(a)
    move = max([abs(y - x) for x, y in zip(a, b)], default=0.0)
    apart = min([abs(r[i] - r[j]) for r in (a, b) for i in range(m) for j in range(m) if i != j],
                default=float("inf"))
    return move == move and apart == apart and move < 0.25 * apart


def root_name(tracked, speed, root):
    """The name of the eigenvalue ``root`` (1/s) at ``speed`` (m/s), from the tracked modes.

    A real root is named by the mode it continues (``"capsize"``, ``"weave 1"``, ``"lean 1"``, ...); a
    complex pair by the family of its two members' modes (``"weave"``, ``"tyre"``) or, members of
    different modes, by both (``"capsize + weave 1"``).  A pair that is not the weave's
    (:func:`~bikemass.analysis.engine.naming.is_weave`) is named ``"wobble"`` when it is a
    steer-dominated oscillation of at least 3 Hz (:func:`~bikemass.analysis.engine.naming.is_wobble`).
    """
    labels = tracked.labels
    near = tracked.nearest_columns(speed, (root,) if root.imag == 0 else (root, np.conj(root)))
    if near is not None:
        first, second = near[0], near[-1]
    else:
        first = tracked.column_of(speed, root)
        if root.imag != 0:
            guess = tracked.guess(speed)
            guess[first] = np.inf
            second = int(np.argmin(np.abs(guess - np.conj(root))))
    if root.imag == 0:
        return labels[first]
    a, b = labels[first], labels[second]
    name = family(a) if family(a) == family(b) and a != b else " + ".join(sorted((a, b)))
    if not is_weave(name) and family(name) != WOBBLE and is_wobble(tracked.model, speed, root):
        return WOBBLE
    return name
