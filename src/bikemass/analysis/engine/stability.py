"""One call from a linear model to its modes, exact critical speeds and stable speed ranges."""

from dataclasses import dataclass, replace

import numpy as np

from scipy.optimize import linear_sum_assignment

from ...core.display import brief
from ...core.results import Result, quantity
from ...core.frozen import freeze, short_repr
from .critical import critical_speeds
from .crossings import OSCILLATORY, REAL, Crossing, Eigenvalues, circle_speeds
from .eigen import eigen_sweep
from .modes import follow_modes
from .naming import WOBBLE, family, is_wobble
from .tracking import reorder, track
from .speeds import speed_grid
from .ranges import MARGINAL_THRESHOLD, grid_ranges, interval_ranges, intersect, is_stable, margin

CRITERIA = ("strict", "marginal")


class _Tracked:
    """The root continuing each tracked mode at any speed inside the grid.

    Where the roots move by less than a quarter of their smallest distance across a grid cell,
    the root nearest the straight line between the mode's values at the cell's ends continues it.
    In any other cell (roots that meet, split or trade places inside one grid step) the modes are
    followed again on a fine sub-grid of :data:`SUBSTEPS` steps (the same tracking as on the grid)
    and the straight line is drawn between sub-grid points.
    """

    SUBSTEPS = 32

    def __init__(self, model, modes, at):
        self.model, self.modes, self.at = model, modes, at
        self._cells = {}

    def _cell(self, k):
        cell = self._cells.get(k)
        if cell is None:
            s, values = self.modes.speeds, self.modes.eigenvalues
            ends = values[k:k + 2]
            apart = np.where(np.eye(ends.shape[1], dtype=bool), np.inf, np.abs(ends[:, :, None] - ends[:, None, :]))
            if np.max(np.abs(ends[1] - ends[0])) < 0.25 * np.min(apart):
                cell = self._cells[k] = (s[k:k + 2], ends)
                return cell
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


def _named(model, tracked, speed, kind, frequency, labels):
    """The tracked mode that crosses at ``speed``: a label, a pair's family (``"weave"``), or
    ``"wobble"`` for a steer-dominated high-frequency pair (:func:`is_wobble`) of another family."""
    root = 1j * frequency if kind == OSCILLATORY else 0.0
    first = tracked.column_of(speed, root)
    if kind == REAL:
        return labels[first]
    guess = tracked.guess(speed)
    guess[first] = np.inf
    second = int(np.argmin(np.abs(guess - np.conj(root))))
    a, b = labels[first], labels[second]
    name = family(a) if family(a) == family(b) and a != b else " + ".join(sorted((a, b)))
    if name not in ("weave", WOBBLE) and is_wobble(model, speed, frequency):
        return WOBBLE
    return name


@dataclass(frozen=True, eq=False)
class StabilityResult(Result):
    """Modes, critical speeds and stable speed ranges of one linear model (``bm.stability``).

    Attributes
    ----------
    model : LinearModel
        The model analysed (``model.name``: ``"whipple"``, ``"whipple+flexible-static"``, ...).
    modes : Modes
        Eigenvalues (1/s) and eigenvectors over ``speeds`` (m/s), followed and named.
    marginal : float
        Modulus (rad/s) below which an unstable eigenvalue counts as marginally stable.
    crossings : tuple of Crossing
        Every crossing of ``Re = 0`` in the grid's span, by speed: exact, found without a grid.
    ranges : mapping
        ``{"strict"|"marginal": {"exact"|"grid": ((start, stop), ...)}}`` (m/s) where every mode
        is stable; ``exact`` ends are boundary speeds, ``grid`` ends the first and last stable
        grid speeds.
    mode_ranges : mapping
        ``{label: {criterion: {"exact"|"grid": ((start, stop), ...)}}}`` (m/s) of each mode.
    stiffness : numpy.ndarray of shape (2, 2) or None
        The rear frame's stiffness S (N m/rad) of a quasi-static flexible frame; ``None``: rigid.

    See Also
    --------
    bikemass.stability : Makes one.
    bikemass.plot_eigenvalues : Draws one.

    Examples
    --------
    >>> import bikemass as bm
    >>> result = bm.stability(bm.parameters("benchmark"))
    >>> result.labels
    ('weave 1', 'weave 2', 'capsize', 'caster')
    >>> [(c.kind, c.direction, round(c.speed, 4)) for c in result.crossings]
    [('oscillatory', 'stabilising', 4.2924), ('real', 'destabilising', 6.0243)]
    >>> result.ranges["strict"]["grid"]                # the first and last stable grid speeds
    ((4.3, 6.0),)
    """

    model: object
    modes: object
    marginal: float = quantity("rad/s")
    crossings: tuple = ()
    ranges: object = quantity("m/s", default=None)
    mode_ranges: object = quantity("m/s", default=None)
    stiffness: object = quantity("N m/rad", default=None)

    @property
    def speeds(self):
        """Speeds (m/s), shape (n,)."""
        return self.modes.speeds

    @property
    def eigenvalues(self):
        """Eigenvalues (1/s), complex, shape (n, m); columns in :attr:`labels` order."""
        return self.modes.eigenvalues

    @property
    def labels(self):
        """Column labels of :attr:`eigenvalues` (weave 1, weave 2, capsize, caster, ...)."""
        return self.modes.labels

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

    @property
    def caster_speeds(self):
        """Speeds (m/s) where the root tracked as the caster mode crosses ``Re = 0``, ascending."""
        return tuple(c.speed for c in self.mode_crossings("caster"))

    @property
    def stable_speeds(self):
        """``((start, stop), ...)`` (m/s) where every mode is strictly stable (exact ends)."""
        return self.ranges["strict"]["exact"]

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
        plain = lambda x: [list(r) for r in x]      # noqa: E731
        ranges = lambda r: {c: {k: plain(v) for k, v in byk.items()} for c, byk in r.items()}   # noqa: E731
        return {
            "model": self.model.name,
            "weave_speeds": list(self.weave_speeds),
            "capsize_speeds": list(self.capsize_speeds),
            **({"wobble_speeds": list(self.wobble_speeds)} if self.wobble_speeds else {}),
            "crossings": [c.to_dict() for c in self.crossings],
            "marginal_threshold": self.marginal,
            "ranges": ranges(self.ranges),
            "modes": {label: ranges(r) for label, r in {"weave": self.weave_ranges, **self.mode_ranges}.items()},
        }

    def units(self):
        """The ``units`` block of :meth:`to_dict`."""
        return {"weave_speeds": "m/s", "capsize_speeds": "m/s", "wobble_speeds": "m/s", **Crossing.field_units(),
                "marginal_threshold": "rad/s", "ranges": "m/s", "modes": "m/s"}

    def display_rows(self):
        """What Jupyter's table shows: the model, the grid, the critical speeds, the stable ranges."""
        v = self.speeds
        speeds = lambda xs: ", ".join(f"{x:.4f}" for x in xs) or "none"            # noqa: E731
        spans = lambda r: ", ".join(f"{a:.4f}..{b:.4f}" for a, b in r) or "none"   # noqa: E731
        rows = [("model", self.model.name, ""), ("speeds", f"{v[0]:g}..{v[-1]:g} x {len(v)}", "m/s"),
                ("modes", ", ".join(self.labels), ""), ("weave speeds", speeds(self.weave_speeds), "m/s"),
                ("capsize speeds", speeds(self.capsize_speeds), "m/s")]
        if self.wobble_speeds:
            rows.append(("wobble speeds", speeds(self.wobble_speeds), "m/s"))
        return rows + [("stable (strict)", spans(self.stable_speeds), "m/s"),
                       (f"stable (marginal, |lambda| < {self.marginal:g} rad/s)",
                        spans(self.ranges["marginal"]["exact"]), "m/s"),
                       ("frame stiffness S", "rigid" if self.stiffness is None else brief(self.stiffness), "N m/rad")]

    def __repr__(self):
        v = self.speeds
        fmt = lambda xs: "(" + ", ".join(f"{x:.4f}" for x in xs) + ")"    # noqa: E731
        return short_repr(self, ("model", self.model.name), ("speeds", f"{v[0]:g}..{v[-1]:g} m/s x {len(v)}"),
                          ("weave_speeds", fmt(self.weave_speeds)), ("capsize_speeds", fmt(self.capsize_speeds)),
                          ("stable", "(" + ", ".join(f"{a:.4f}..{b:.4f}" for a, b in self.stable_speeds) + ")"))


def analyse(model, speeds=None, marginal=MARGINAL_THRESHOLD, stiffness=None):
    """:class:`Stability` of a :class:`~bikemass.models.linear.LinearModel` over ``speeds`` (m/s;
    default the thesis's 0..30 m/s grid in steps of 0.05 m/s); ``marginal`` in rad/s; ``stiffness`` the
    quasi-static frame's S (N m/rad) the model was built with, kept in the result."""
    modes = follow_modes(model, speed_grid() if speeds is None else speeds)
    v = modes.speeds
    lo, hi = float(v[0]), float(v[-1])
    at = Eigenvalues(model)
    tracked = _Tracked(model, modes, at)
    critical = critical_speeds(model, hi, lo)
    crossings = tuple(replace(c, mode=_named(model, tracked, c.speed, c.kind, c.frequency, modes.labels))
                      for c in critical.crossings)
    axis = [c.speed for c in crossings]
    limits = {"strict": None, "marginal": marginal}
    boundaries = {"strict": axis, "marginal": sorted([*axis, *circle_speeds(model, marginal, lo, hi, at)])}
    ranges, mode_ranges = {}, {label: {} for label in modes.labels}
    for criterion, r in limits.items():
        exact = (critical.stable if r is None else
                 interval_ranges(lo, hi, boundaries[criterion], lambda x: bool(np.all(margin(at(x), r) < 0))))
        ranges[criterion] = {"exact": exact, "grid": grid_ranges(v, is_stable(modes.eigenvalues, r).all(axis=1))}
        for c, label in enumerate(modes.labels):
            mode_ranges[label][criterion] = {
                "exact": interval_ranges(lo, hi, boundaries[criterion],
                                         lambda x: bool(margin(tracked.root(x, c), r) < 0)),
                "grid": grid_ranges(v, is_stable(modes.eigenvalues[:, c], r))}
    return StabilityResult(model, modes, float(marginal), crossings, ranges, mode_ranges, stiffness)
