"""One call from a linear model to its modes, exact critical speeds and stable speed ranges."""

from dataclasses import dataclass

import numpy as np

from ...core.display import brief
from ...core.results import Result, quantity
from ...core.tables import Table
from ...core.frozen import FrozenMap, LazyMap, freeze, short_repr
from .critical import critical_speeds
from .crossings import OSCILLATORY, REAL, Crossing, Eigenvalues, circle_speeds
from .modes import follow_modes
from .naming import WOBBLE, family, is_weave
from .tracked import TrackedModes
from .speeds import speed_grid
from .ranges import MARGINAL_THRESHOLD, grid_ranges, interval_ranges, intersect, is_stable, margin

CRITERIA = ("strict", "marginal")


@dataclass(frozen=True, eq=False)
class Prevented(Result):
    """What prevents a stable speed range where there is none: at the grid speed where the fewest
    roots are unstable, the modes still unstable there (named as people read them: ``wobble``,
    ``fork-bending``, ``weave, real (upper)``) and one root of each (the upper of a pair).

    Attributes
    ----------
    speed : float
        The grid speed (m/s) where the fewest roots have ``Re > 0`` (the first such speed).
    modes : tuple of str
        The unstable modes there.
    roots : tuple of complex
        One unstable root (1/s) of each mode: its real part is the growth rate, its imaginary
        part the frequency (rad/s).
    """

    speed: float = quantity("m/s")
    modes: tuple = ()
    roots: tuple = quantity("1/s", default=())

    def to_dict(self):
        """``{"speed", "unstable_modes", "roots": [[re, im], ...]}``."""
        return {"speed": self.speed, "unstable_modes": list(self.modes),
                "roots": [[float(r.real), float(r.imag)] for r in self.roots]}

    def text(self):
        """One line: ``at 4.5 m/s, wobble (+1.2 1/s, 7.35 Hz) stays unstable``."""
        parts = [f"{m} ({r.real:+.3g} 1/s{f', {abs(r.imag) / (2 * np.pi):.3g} Hz' if r.imag else ', real'})"
                 for m, r in zip(self.modes, self.roots)]
        return f"at {self.speed:g} m/s, where fewest roots are unstable: {', '.join(parts)}"


def prevented(modes):
    """:class:`Prevented` of :class:`~bikemass.analysis.engine.modes.Modes` with no stable grid speed."""
    unstable = modes.eigenvalues.real > 0
    k = int(np.argmin(unstable.sum(axis=1)))
    names, roots = modes.names()[k], modes.eigenvalues[k]
    found = {}
    for c in np.flatnonzero(unstable[k]):
        if names[c] not in found or roots[c].imag > found[names[c]].imag:
            found[names[c]] = complex(roots[c])
    ordered = sorted(found.items(), key=lambda item: -item[1].real)
    return Prevented(float(modes.speeds[k]), tuple(m for m, _ in ordered), tuple(r for _, r in ordered))


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
        grid speeds.  The marginal ranges are computed when first read (their boundary speeds are a
        polynomial eigenvalue problem of their own), then kept.
    mode_ranges : mapping
        ``{label: {criterion: {"exact"|"grid": ((start, stop), ...)}}}`` (m/s) of each mode, computed
        when first read, then kept.
    stiffness : numpy.ndarray of shape (2, 2) or None
        The rear frame's stiffness S (N m/rad) of a quasi-static flexible frame; ``None``: rigid.
    unstable_at_start : tuple of StartInstability
        Every mode unstable from the grid's first speed on (a pair once), which no crossing reports:
        the weave's real roots of a bicycle at standstill, an undamped oscillation that grows from
        standstill, any mode already unstable where a grid starts above 0.

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
    unstable_at_start: tuple = ()

    def tables(self):
        """``{"eigenvalues": Table, "crossings": Table}``: the modes' eigenvalues at every speed (as
        :meth:`Modes.tables`) with ``stable`` (every real part below -1e-10 1/s, the grid ranges'
        criterion) and ``marginally_stable`` (an eigenvalue slower than :attr:`marginal` rad/s also
        counts); and one row per crossing
        of ``Re = 0`` (speed, kind, direction, mode, frequency). The critical speeds, the stable
        speeds and the model's name are the frames' ``attrs``."""
        eig = self.modes.tables()["eigenvalues"]
        columns = {**eig.columns, "stable": np.all(is_stable(self.eigenvalues), axis=1),
                   "marginally_stable": np.all(is_stable(self.eigenvalues, self.marginal), axis=1)}
        attrs = {"model": self.model.name, "weave_speeds": tuple(self.weave_speeds),
                 "capsize_speeds": tuple(self.capsize_speeds), "stable_speeds": tuple(self.stable_speeds),
                 "marginal": self.marginal, **eig.attrs}
        crossings = Table({"speed": [c.speed for c in self.crossings], "kind": [c.kind for c in self.crossings],
                           "direction": [c.direction for c in self.crossings],
                           "mode": [c.mode for c in self.crossings],
                           "frequency": [c.frequency for c in self.crossings]},
                          {"speed": "m/s", "frequency": "rad/s"}, {"model": self.model.name})
        return {"eigenvalues": Table(columns, eig.units, attrs), "crossings": crossings}

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

    def _oscillatory(self, test):
        return tuple(c.speed for c in self.crossings if c.kind == OSCILLATORY and test(c.mode))

    @property
    def weave_speeds(self):
        """Speeds (m/s) where the weave crosses ``Re = 0`` (the pair continuing the Whipple bicycle's
        weave roots: :func:`~bikemass.analysis.engine.naming.is_weave`), ascending."""
        return self._oscillatory(is_weave)

    @property
    def capsize_speeds(self):
        """Speeds (m/s) where a real root crosses ``Re = 0`` (capsize; also a branch of a split pair)."""
        return tuple(c.speed for c in self.crossings if c.kind == REAL)

    @property
    def wobble_speeds(self):
        """Speeds (m/s) where the wobble pair crosses ``Re = 0``, ascending."""
        return self._oscillatory(lambda mode: family(mode) == WOBBLE)

    @property
    def other_crossings(self):
        """The oscillatory crossings that are not the weave's (wobble, a tyre's oscillation, the
        leaning rider's, ...), each named by its mode."""
        return tuple(c for c in self.crossings if c.kind == OSCILLATORY and not is_weave(c.mode))

    @property
    def caster_speeds(self):
        """Speeds (m/s) where the root tracked as the caster mode crosses ``Re = 0``, ascending."""
        return tuple(c.speed for c in self.mode_crossings("caster"))

    @property
    def stable_speeds(self):
        """``((start, stop), ...)`` (m/s) where every mode is strictly stable (exact ends)."""
        return self.ranges["strict"]["exact"]

    @property
    def prevented_by(self):
        """Where no speed of the span is strictly stable, the modes that prevent it
        (:class:`Prevented`: at the grid speed where the fewest roots are unstable); ``None`` when a
        stable range exists."""
        return None if self.stable_speeds else prevented(self.modes)

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
            "unstable_at_start": [u.to_dict() for u in self.unstable_at_start],
            **({"no_stable_range": self.prevented_by.to_dict()} if not self.stable_speeds else {}),
            "marginal_threshold": self.marginal,
            "ranges": ranges(self.ranges),
            "modes": {label: ranges(r) for label, r in {"weave": self.weave_ranges, **self.mode_ranges}.items()},
        }

    def units(self):
        """The ``units`` block of :meth:`to_dict`."""
        return {"weave_speeds": "m/s", "capsize_speeds": "m/s", "wobble_speeds": "m/s", **Crossing.field_units(),
                "roots": "1/s (real, imaginary)",
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
        if self.other_crossings:
            rows.append(("other oscillations crossing",
                         ", ".join(f"{c.speed:.4f} ({c.mode})" for c in self.other_crossings), "m/s"))
        if self.unstable_at_start:
            rows.append((f"unstable from {v[0]:g} m/s",
                         ", ".join(u.mode or u.kind for u in self.unstable_at_start), ""))
        if not self.stable_speeds:
            rows.append(("no stable speeds", self.prevented_by.text(), ""))
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
    tracked = TrackedModes(model, modes, at)
    critical = critical_speeds(model, hi, lo, tracked)
    crossings = critical.crossings
    axis = [c.speed for c in crossings]
    memo = {}

    def boundaries(criterion):           # the marginal criterion's circle speeds: only when first asked for
        if criterion not in memo:
            memo[criterion] = axis if criterion == "strict" else \
                sorted([*axis, *circle_speeds(model, marginal, lo, hi, at)])
        return memo[criterion]

    def stable(r):                       # (n, m): each root on the grid stable under the criterion r
        return is_stable(modes.eigenvalues, r)

    def marginal_ranges():
        exact = interval_ranges(lo, hi, boundaries("marginal"), lambda x: bool(np.all(margin(at(x), marginal) < 0)))
        return {"exact": _pairs(exact), "grid": _pairs(grid_ranges(v, _every(stable(marginal))))}

    def each_mode():
        out = {label: {} for label in modes.labels}
        for criterion, r in (("strict", None), ("marginal", marginal)):
            mask = stable(r)
            inside = _inside_values(lo, hi, boundaries(criterion), modes, tracked)
            for c, label in enumerate(modes.labels):
                out[label][criterion] = FrozenMap({
                    "exact": _pairs(_joined([(a, b) for a, b, values in inside if margin(values[c], r) < 0])),
                    "grid": _pairs(grid_ranges(v, mask[:, c]))})
        return {label: FrozenMap(r) for label, r in out.items()}

    # the strict ranges now; the marginal ones (the circle speeds: a polynomial eigenvalue problem) and each
    # mode's own when first read (LazyMap: the same values, computed once); every field immutable as built
    ranges = FrozenMap({"strict": FrozenMap({"exact": _pairs(critical.stable),
                                             "grid": _pairs(grid_ranges(v, _every(stable(None))))}),
                        "marginal": LazyMap(marginal_ranges)})
    return StabilityResult.frozen(model, modes, float(marginal), crossings, ranges, LazyMap(each_mode),
                                  freeze(stiffness), critical.unstable_at_start)


def _every(mask):
    """``mask.all(axis=1)`` of a boolean (n, m) with a handful of columns (one ``&`` per column: numpy's
    reduction over a short axis costs more per row)."""
    out = mask[:, 0]
    for j in range(1, mask.shape[1]):
        out = out & mask[:, j]
    return out


def _pairs(intervals):
    """``((start, stop), ...)`` of ``[[start, stop], ...]`` (what :func:`freeze` makes of them)."""
    return tuple(tuple(x) for x in intervals)


INSIDE = 1e-6
"""A grid speed stands for an interval between boundary speeds when it is at least INSIDE (1 + v)
m/s from both ends (no mode changes sign inside: every boundary is one)."""


def _inside_values(lo, hi, boundaries, modes, tracked):
    """``[(a, b, values)]`` of the intervals between ``lo``, the ``boundaries`` and ``hi`` (as
    :func:`~bikemass.analysis.engine.ranges.interval_ranges` makes them): every tracked mode's value
    (m,) inside, at the middle grid speed of the interval when it holds one (no eigenvalue problem),
    else at its midpoint (the root continuing each mode there)."""
    v, E = modes.speeds, modes.eigenvalues
    ends = [lo, *[b for b in boundaries if lo < b < hi], hi]
    out = []
    for a, b in zip(ends, ends[1:]):
        if not b > a:
            continue
        first = int(np.searchsorted(v, a + INSIDE * (1 + abs(a)), side="left"))
        last = int(np.searchsorted(v, b - INSIDE * (1 + abs(b)), side="right")) - 1
        if first <= last:
            values = E[(first + last) // 2]
        else:
            mid = 0.5 * (a + b)
            values = np.array([tracked.root(mid, c) for c in range(E.shape[1])])
        out.append((float(a), float(b), values))
    return out


def _joined(intervals):
    """``[[start, stop], ...]``: sorted intervals with those that touch joined."""
    out = []
    for a, b in intervals:
        if out and out[-1][1] == a:
            out[-1][1] = b
        else:
            out.append([a, b])
    return out
