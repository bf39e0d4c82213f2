"""Modes followed across speed and labelled: the result of an eigenvalue sweep.

:func:`follow_modes` solves the eigenvalue problem at all speeds at once
(:mod:`~bikemass.analysis.stability.eigen`), follows every root from speed to speed
(:mod:`~bikemass.analysis.stability.tracking`) and names the modes
(:mod:`~bikemass.analysis.stability.labels`).  Labels are fixed at standstill: a sweep that
starts above 0 m/s is extended down to 0 m/s (step at most ``START_STEP``) for the
labelling and the extension is dropped again.
"""

from dataclasses import dataclass

import numpy as np

from ...core.errors import InputError, short
from .eigen import ModalQuantities, eigen_sweep
from .labels import LABELS, mode_names, settle_splits, standstill_labels
from .tracking import reorder, track

START_STEP = 0.05
"""Largest speed step (m/s) of the extension down to standstill used for labelling."""


@dataclass(frozen=True)
class Modes(ModalQuantities):
    """Eigenvalues (n, 4) [1/s] and unit state eigenvectors (n, 4, 4) of labelled modes.

    Column ``i`` of ``eigenvalues`` (and ``eigenvectors[:, :, i]``) is mode
    ``labels[i]`` at every speed of ``speeds`` (m/s); state order
    ``[phi, delta, phi', delta']``.
    """

    speeds: np.ndarray
    labels: tuple
    eigenvalues: np.ndarray
    eigenvectors: np.ndarray

    def __getitem__(self, label):
        """Eigenvalues (n,) of mode ``label``."""
        return self.eigenvalues[:, self.labels.index(label)]

    def names(self):
        """What each root is at every speed (array (n, 4) of str, columns as ``labels``):
        ``weave`` while the weave roots are a pair, ``weave, real (upper|lower)`` when
        they are real, ``capsize``, ``caster`` (:func:`~bikemass.analysis.stability.labels.mode_names`)."""
        return mode_names(self.eigenvalues, self.labels)

    def to_dict(self):
        """``{"speeds": [...], "modes": [{"label", "eigenvalues": [[re, im], ...]}, ...]}``."""
        return {"speeds": self.speeds.tolist(),
                "modes": [{"label": label,
                           "eigenvalues": np.stack([self[label].real, self[label].imag], -1).tolist()}
                          for label in LABELS]}


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


def follow_modes(matrices, speeds):
    """:class:`Modes` of ``matrices`` (:class:`~bikemass.models.canonical.CanonicalMatrices`) at ``speeds`` (m/s)."""
    v = check_speeds(speeds)
    lead = np.linspace(0.0, v[0], int(np.ceil(v[0] / START_STEP)) + 1)[:-1]
    sweep = eigen_sweep(matrices, np.concatenate([lead, v]))
    values, vectors = reorder(sweep, track(sweep))
    labels = standstill_labels(values[0])
    order = settle_splits(values, labels)
    values = np.take_along_axis(values, order, axis=1)
    vectors = np.take_along_axis(vectors, order[:, None, :], axis=2)
    columns = [labels.index(label) for label in LABELS]
    return Modes(speeds=v, labels=LABELS, eigenvalues=values[len(lead):, columns],
                 eigenvectors=vectors[len(lead):, :, columns])

