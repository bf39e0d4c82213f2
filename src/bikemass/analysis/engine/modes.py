"""Modes followed across speed and named: eigenvalues of a linear model over a speed grid.

:func:`follow_modes` solves the eigenvalue problem at all speeds at once
(:mod:`~bikemass.analysis.engine.eigen`), follows every root from speed to speed
(:mod:`~bikemass.analysis.engine.tracking`) and names the modes
(:mod:`~bikemass.analysis.engine.naming`).  Names are fixed at standstill: a grid that starts
above 0 m/s is extended down to 0 m/s (steps of at most :data:`START_STEP`) for the naming, and
the extension is dropped again.
"""

from dataclasses import dataclass

import numpy as np

from ...core.results import Result, quantity
from ...core.frozen import short_repr
from .eigen import damping_ratio, eigen_sweep, natural_frequency
from .naming import mode_names, settle_splits, split_rank, standstill_labels
from .tracking import reorder, track
from ...core.errors import InputError, short

START_STEP = 0.05
"""Largest speed step (m/s) of the extension down to standstill used for naming."""


@dataclass(frozen=True, eq=False)
class Modes(Result):
    """Eigenvalues (n, m) [1/s] and unit state eigenvectors (n, N, m) of named modes.

    Column ``i`` of ``eigenvalues`` (and ``eigenvectors[:, :, i]``) is mode ``labels[i]`` at every
    speed of ``speeds`` (m/s); the states are the model's dynamic states, in its order.  Arrays
    are read-only.
    """

    speeds: np.ndarray = quantity("m/s")
    labels: tuple = ()
    eigenvalues: np.ndarray = quantity("1/s (pairs: real, imaginary)", default=None)
    eigenvectors: np.ndarray = quantity("", default=None)

    def __getitem__(self, label):
        """Eigenvalues (n,) of mode ``label``."""
        return self.eigenvalues[:, self.labels.index(label)]

    @property
    def natural_frequency(self):
        """``|l|`` in rad/s, shape (n, m)."""
        return natural_frequency(self.eigenvalues)

    @property
    def damping_ratio(self):
        """``-Re(l) / |l|`` (dimensionless), shape (n, m)."""
        return damping_ratio(self.eigenvalues)

    def names(self):
        """What each root is at every speed (array (n, m) of str, columns as ``labels``): ``weave``
        while the weave roots are a pair, ``weave, real (upper|lower)`` when they are real,
        ``capsize``, ``caster``, ... (:func:`~bikemass.analysis.engine.naming.mode_names`)."""
        return mode_names(self.eigenvalues, self.labels)

    def units(self):
        """The ``units`` block of :meth:`to_dict`."""
        return {"speeds": "m/s", "eigenvalues": self.field_units()["eigenvalues"]}

    def __repr__(self):
        v = self.speeds
        return short_repr(self, ("speeds", f"{v[0]:g}..{v[-1]:g} m/s x {len(v)}"), ("labels", self.labels))

    def to_dict(self):
        """``{"speeds": [...], "modes": [{"label", "eigenvalues": [[re, im], ...]}, ...]}``."""
        return {"speeds": self.speeds.tolist(),
                "modes": [{"label": label,
                           "eigenvalues": np.stack([self[label].real, self[label].imag], -1).tolist()}
                          for label in self.labels]}


def check_speeds(speeds):
    """``speeds`` as a 1-D float array; InputError (a ValueError) unless numbers, at least one,
    finite, >= 0 and strictly increasing."""
    try:
        v = np.atleast_1d(np.asarray(speeds, dtype=float))
    except (TypeError, ValueError):
        raise InputError("speeds", short(speeds), "speeds in m/s: a 1-D array of numbers") from None
    if v.ndim != 1 or v.size == 0 or not np.all(np.isfinite(v)) or v[0] < 0 or np.any(np.diff(v) <= 0):
        raise InputError("speeds", short(speeds), "speeds must be at least one, finite, >= 0 and strictly increasing (m/s)")
    return v


def follow_modes(model, speeds):
    """:class:`Modes` of ``model`` (a :class:`~bikemass.models.linear.LinearModel`) at ``speeds`` (m/s)."""
    v = check_speeds(speeds)
    lead = np.linspace(0.0, v[0], int(np.ceil(v[0] / START_STEP)) + 1)[:-1]
    sweep = eigen_sweep(model, np.concatenate([lead, v]))
    values, vectors = reorder(sweep.eigenvalues, sweep.eigenvectors, track(sweep.eigenvalues, sweep.eigenvectors))
    labels = standstill_labels(values[0], vectors[0], dict(model.families), [s.name for s in model.dynamic_states])
    order = settle_splits(values, labels)
    values = np.take_along_axis(values, order, axis=1)
    vectors = np.take_along_axis(vectors, order[:, None, :], axis=2)
    ordered = split_rank(labels)
    columns = [labels.index(label) for label in ordered]
    return Modes(speeds=v, labels=tuple(ordered), eigenvalues=values[len(lead):, columns],
                 eigenvectors=vectors[len(lead):, :, columns])


