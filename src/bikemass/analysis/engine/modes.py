"""Modes followed across speed and named: eigenvalues of a linear model over a speed grid.

:func:`follow_modes` solves the eigenvalue problem at all speeds at once
(:mod:`~bikemass.analysis.engine.eigen`), follows every root from speed to speed
(:mod:`~bikemass.analysis.engine.tracking`) and names the modes
(:mod:`~bikemass.analysis.engine.naming`).  Names are fixed at standstill: a grid that starts
above 0 m/s is extended down to 0 m/s (steps of at most :data:`START_STEP`) for the naming, and
the extension is dropped again.  A model with modes besides the bicycle's names its wobble by what
moves at :data:`~bikemass.analysis.engine.naming.REFERENCE_SPEED` (8 m/s): its grid is extended up
to that speed (steps of at most :data:`START_STEP`), or the speed inserted, for the naming alone.
"""

from dataclasses import dataclass

import numpy as np

from ...core.results import Result, quantity
from ...core.tables import Table, complex_columns
from ...core.frozen import freeze, short_repr
from .eigen import (characteristic_of, damping_ratio, eigen_sweep, has_quartic_path, matched_vectors,
                    natural_frequency, quartic_tracked_sweep, quartic_vectors, tracked_sweep)
from .quartic import quartic_roots
from .naming import REFERENCE_SPEED, mode_names, settle_splits, split_rank, standstill_labels
from .tracking import track
from ...core.errors import InputError, short
from ...core.limits import MAX_SPEED

START_STEP = 0.05
"""Largest speed step (m/s) of the extension down to standstill used for naming."""


@dataclass(frozen=True, eq=False)
class Modes(Result):
    """Eigenvalues (n, m) [1/s] and unit state eigenvectors (n, N, m) of named modes.

    Column ``i`` of ``eigenvalues`` (and ``eigenvectors[:, :, i]``) is mode ``labels[i]`` at every
    speed of ``speeds`` (m/s); the states are the model's dynamic states, in its order.  Arrays
    are read-only.

    Examples
    --------
    >>> import bikemass as bm
    >>> modes = bm.eigenvalues(bm.parameters("benchmark"), speeds=[0.0, 5.0])
    >>> print(type(modes).__name__, modes.labels, modes.eigenvalues.shape)
    Modes ('weave 1', 'weave 2', 'capsize', 'caster') (2, 4)
    """

    speeds: np.ndarray = quantity("m/s")
    labels: tuple = ()
    eigenvalues: np.ndarray = quantity("1/s (pairs: real, imaginary)", default=None)
    eigenvectors: np.ndarray = quantity("", default=None)

    def __getattr__(self, name):
        # the eigenvectors of a sweep that tracked its roots without them at most speeds
        # (:func:`lazily`): made on first read, then kept (an instance's own attribute)
        make = self.__dict__.get("_make_vectors") if name == "eigenvectors" else None
        if make is None:
            raise AttributeError(name)
        vectors = make()
        vectors.setflags(write=False)
        object.__setattr__(self, "eigenvectors", vectors)
        object.__setattr__(self, "_make_vectors", None)
        return vectors

    def __getstate__(self):
        state = dict(self.__dict__)
        state["eigenvectors"] = self.eigenvectors
        state.pop("_make_vectors", None)
        return state

    @classmethod
    def lazily(cls, speeds, labels, eigenvalues, make_vectors):
        """Modes whose :attr:`eigenvectors` are made by ``make_vectors()`` when first read (a
        read-only array of shape (n, N, m)), then kept; every other field as given (immutable)."""
        obj = cls.frozen(speeds, labels, eigenvalues, None)
        del obj.__dict__["eigenvectors"]
        obj.__dict__["_make_vectors"] = make_vectors
        return obj

    def __getitem__(self, label):
        """Eigenvalues (n,) of mode ``label``."""
        return self.eigenvalues[:, self.labels.index(label)]

    @property
    def natural_frequency(self):
        """``|l|`` in rad/s, shape (n, m), read-only."""
        return freeze(natural_frequency(self.eigenvalues))

    @property
    def damping_ratio(self):
        """``-Re(l) / |l|`` (dimensionless), shape (n, m), read-only."""
        return freeze(damping_ratio(self.eigenvalues))

    def names(self):
        """What each root is at every speed (array (n, m) of str, columns as ``labels``): ``weave``
        while the weave roots are a pair, ``weave, real (upper|lower)`` when they are real,
        ``capsize``, ``caster``, ... (:func:`~bikemass.analysis.engine.naming.mode_names`)."""
        return mode_names(self.eigenvalues, self.labels)

    def units(self):
        """The ``units`` block of :meth:`to_dict`."""
        return {"speeds": "m/s", "eigenvalues": self.field_units()["eigenvalues"]}

    def tables(self):
        """``{"eigenvalues": Table}``: one row per speed, the real and imaginary part of each mode's
        eigenvalue (``"weave 1 real"``, ``"weave 1 imaginary"``, ..., 1/s)."""
        columns, units = {"speed": self.speeds}, {"speed": "m/s"}
        for label in self.labels:
            c, u = complex_columns(label, self[label], "1/s")
            columns.update(c)
            units.update(u)
        return {"eigenvalues": Table(columns, units, {"labels": self.labels})}

    def __repr__(self):
        v = self.speeds
        return short_repr(self, ("speeds", f"{v[0]:g}..{v[-1]:g} m/s x {len(v)}"), ("labels", self.labels))

    def to_dict(self):
        """``{"speeds": [...], "modes": [{"label", "eigenvalues": [[re, im], ...]}, ...]}``."""
        return {"speeds": self.speeds.tolist(),
                "modes": [{"label": label,
                           "eigenvalues": np.stack([self[label].real, self[label].imag], -1).tolist()}
                          for label in self.labels]}


# no class attribute for the eigenvectors' default (the generated __init__ keeps its own): an instance
# made lazily (Modes.lazily) has none of its own until they are read, and __getattr__ makes them then
del Modes.eigenvectors


def check_speeds(speeds):
    """``speeds`` as a 1-D float array; InputError (a ValueError) unless numbers, at least one,
    finite, >= 0, strictly increasing and at most :data:`~bikemass.core.limits.MAX_SPEED`."""
    try:
        v = np.atleast_1d(np.asarray(speeds, dtype=float))
    except (TypeError, ValueError, OverflowError):
        raise InputError("speeds", short(speeds), "speeds in m/s: a 1-D array of numbers") from None
    if v.ndim != 1 or v.size == 0 or not np.all(np.isfinite(v)) or v[0] < 0 or np.any(np.diff(v) <= 0):
        raise InputError("speeds", short(speeds), "speeds must be at least one, finite, >= 0 and strictly increasing (m/s)")
    if v[-1] > MAX_SPEED:
        raise InputError("speeds", short(speeds), f"speeds of at most {MAX_SPEED:g} m/s (as the command line's), "
                         f"got {v[-1]:g}")
    return v


def naming_grid(v, reference=None):
    """``(grid, keep, at)``: the speeds ``v`` (m/s) extended down to standstill, up to ``reference``
    (m/s; ``None``: no reference) or with it inserted, in steps of at most :data:`START_STEP`; the
    indices of ``v`` in the grid and the index of the reference speed (``None`` without one)."""
    if reference is None and v[0] == 0:          # from standstill, nothing to add: the grid itself
        return v, np.arange(len(v)), None
    lead = np.linspace(0.0, v[0], int(np.ceil(v[0] / START_STEP)) + 1)[:-1]
    tail = np.empty(0)
    if reference is not None and v[-1] < reference:
        tail = np.linspace(v[-1], reference, int(np.ceil((reference - v[-1]) / START_STEP)) + 1)[1:]
    grid = np.concatenate([lead, v, tail])
    keep = np.arange(len(lead), len(lead) + len(v))
    if reference is None:
        return grid, keep, None
    near = np.flatnonzero(np.abs(grid - reference) <= 1e-9)
    if len(near):
        return grid, keep, int(near[0])
    at = int(np.searchsorted(grid, reference))
    return np.insert(grid, at, reference), np.where(keep >= at, keep + 1, keep), at


def follow_modes(model, speeds):
    """:class:`Modes` of ``model`` (a :class:`~bikemass.models.linear.LinearModel`) at ``speeds`` (m/s)."""
    v = check_speeds(speeds)
    families = dict(model.families)
    grid, keep, at = naming_grid(v, REFERENCE_SPEED if len(families) > 1 else None)
    fast = (_follow_quartic if has_quartic_path(model) else _follow_fast)(model, v, families, grid, keep, at)
    if fast is not None:
        return fast
    sweep = eigen_sweep(model, grid)
    order = track(sweep.eigenvalues, sweep.eigenvectors)
    rows = np.arange(len(order))[:, None]
    values = sweep.eigenvalues[rows, order]
    reference = None if at is None else (values[at], sweep.eigenvectors[at][:, order[at]])
    labels = standstill_labels(values[0], sweep.eigenvectors[0][:, order[0]], families,
                               [s.name for s in model.dynamic_states], reference)
    ordered = split_rank(labels)
    columns = [labels.index(label) for label in ordered]
    # one gather of the sweep's arrays: the tracked order, then the splits settled, then the labels' order
    order = order[rows, settle_splits(values, labels)][keep][:, columns]
    rows = rows[keep]
    values = sweep.eigenvalues[rows, order]
    vectors = sweep.eigenvectors[rows, :, order].transpose(0, 2, 1)
    values.setflags(write=False)                 # made here: read-only as they are, no frozen copy
    vectors.setflags(write=False)
    return Modes.frozen(freeze(v), tuple(ordered), values, vectors)


def _follow_fast(model, v, families, grid, keep, at):
    """:func:`follow_modes` of a model beyond the quartic path by :func:`~bikemass.analysis.engine.eigen.tracked_sweep`
    (eigenvectors only where roots meet, at standstill and at the reference speed; the modes'
    eigenvectors made when first read), ``None`` where that sweep is not finite."""
    sweep = tracked_sweep(model, grid, [0] if at is None else [0, at])
    if sweep is None:
        return None
    order = sweep.order
    rows = np.arange(len(order))[:, None]
    values = sweep.values[rows, order]
    reference = None if at is None else (values[at], sweep.vectors_at(at)[:, order[at]])
    labels = standstill_labels(values[0], sweep.vectors_at(0)[:, order[0]], families,
                               [s.name for s in model.dynamic_states], reference)
    ordered = split_rank(labels)
    columns = [labels.index(label) for label in ordered]
    order = order[rows, settle_splits(values, labels)][keep][:, columns]
    values = sweep.values[rows[keep], order]
    values.setflags(write=False)
    return Modes.lazily(freeze(v), tuple(ordered), values, lambda: matched_vectors(model, v, values))


def _follow_quartic(model, v, families, grid, keep, at):
    """:func:`follow_modes` of a model on the quartic path by
    :func:`~bikemass.analysis.engine.eigen.quartic_tracked_sweep` (the roots tracked on eigenvalues,
    eigenvectors only where roots meet, at standstill and at the reference speed; the modes'
    eigenvectors made when first read: each the null vector of ``M s^2 + C s + K`` at its root, the
    same arithmetic as on every row at once), ``None`` where a root is not finite."""
    tracked = quartic_tracked_sweep(model, grid, [0] if at is None else [0, at])
    if tracked is None:
        return None
    sweep, C, K = tracked
    order = sweep.order
    rows = np.arange(len(order))[:, None]
    values = sweep.values[rows, order]
    reference = None if at is None else (values[at], sweep.vectors_at(at)[:, order[at]])
    labels = standstill_labels(values[0], sweep.vectors_at(0)[:, order[0]], families,
                               [s.name for s in model.dynamic_states], reference)
    ordered = split_rank(labels)
    columns = [labels.index(label) for label in ordered]
    order = order[rows, settle_splits(values, labels)]
    whole = len(keep) == len(grid)               # speeds from standstill: the naming grid is the grid
    order = order[:, columns] if whole else order[keep][:, columns]
    values = sweep.values[rows if whole else rows[keep], order]
    values.setflags(write=False)
    M, C, K = model.mechanics.M, C[keep], K[keep]
    return Modes.lazily(freeze(v), tuple(ordered), values, lambda: quartic_vectors(M, C, K, values))


def follow_many(models, speeds):
    """Eigenvalues (D, n, m) of the modes of ``D`` models of one kind at ``speeds`` (m/s), columns in
    the labels' order of each: ``follow_modes(model, speeds).eigenvalues`` of every model, found at
    once where that is possible (a Monte Carlo's draws): two-coordinate models (the quartic path)
    whose speed polynomials have the same degrees, on speeds from 0.  The roots of all quartics are one
    evaluation, and the models' sequences are tracked as one (each step's assignment is the
    same as alone; a model's own order is taken relative to its first speed).  Returns ``None``
    for models that do not qualify (the caller follows them one by one) and the labels of each."""
    v = check_speeds(speeds)
    mechs = [m.mechanics for m in models]
    if not models or v[0] != 0 or not all(has_quartic_path(m) for m in models) or \
            len({(len(x.C), len(x.K)) for x in mechs}) != 1 or len({tuple(m.families) for m in models}) != 1:
        return None
    D, n = len(models), len(v)
    M = np.stack([x.M for x in mechs])[:, None]                                   # (D, 1, 2, 2)
    C = np.stack([x.damping(v) for x in mechs])                                    # (D, n, 2, 2)
    K = np.stack([x.stiffness(v) for x in mechs])
    coefficients = characteristic_of(np.broadcast_to(M, C.shape), C, K).reshape(D * n, 5)
    s = quartic_roots(coefficients).reshape(D, n, 4)
    vectors = quartic_vectors(M, C, K, s).reshape(D * n, 4, 4)
    values = s.reshape(D * n, 4)
    order = track(values, vectors).reshape(D, n, 4)
    out, labelled = np.empty((D, n, 4), dtype=complex), []
    families = dict(models[0].families)
    for d in range(D):
        own = order[d][:, np.argsort(order[d][0])]            # relative to the model's first speed
        vals = np.take_along_axis(s[d], own, axis=1)
        vecs = np.take_along_axis(vectors.reshape(D, n, 4, 4)[d], own[:, None, :], axis=2)
        labels = standstill_labels(vals[0], vecs[0], families)
        vals = np.take_along_axis(vals, settle_splits(vals, labels), axis=1)
        ordered = split_rank(labels)
        out[d] = vals[:, [labels.index(label) for label in ordered]]
        labelled.append(tuple(ordered))
    return out, labelled
