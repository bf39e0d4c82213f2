"""A chunk of parameter-level configurations evaluated as arrays: the fast path of a sweep.

A configuration that changes only benchmark parameters (and perhaps the stiffness choice) is 26
numbers to critical speeds.  :func:`bikemass.sweep.evaluate.evaluate`, the reference, takes one at a
time: a parameter set, its checks, a :class:`~bikemass.models.linear.LinearModel`, the closed form
(about 100 us each).  :func:`evaluate_columns` takes a whole chunk as one evaluation (about 2 us a
configuration): the varied parameters as (B,) columns and the others as one float each, the checks
of :func:`~bikemass.models.plausibility.check_parameters` as array tests
(:func:`~bikemass.models.plausibility.refused_parameters`),
:func:`~bikemass.models.whipple_generated.whipple_matrices` stacked (the generated family's code), the flexible frame's static stiffness
``g K0 - (g K0)^T (g K0 + S)^-1 g K0`` as stacked 2x2 solves, and
:func:`~bikemass.analysis.engine.closed_form.batch_critical_speeds`.

A row the arrays do not take goes through the reference instead, which gives it its outcome (a
refused row its one-line reason, in the reference's words): a value that is not a real number, a
parameter set the checks refuse, a stiffness choice that fails, a singular ``g K0 + S``, matrices
that are not finite.  Every row's outcome is therefore the reference's, and the numbers agree with
the general engine (eigenvalues and polynomial eigenvalue problems, no closed form) to 1e-10 m/s
(tests/test_sweep_vectorised.py).
"""

import numbers
from types import SimpleNamespace

import numpy as np

from ..analysis.engine.closed_form import batch_critical_speeds, pieces
from ..core.errors import InputError
from ..models.parameters import NAMES
from ..models.plausibility import refused_parameters
from ..models.whipple_generated import whipple_matrices
from ..scenario.inputs import STIFFNESS_KEY
from .table import NUMBERS, Outcomes

SPEEDS = NUMBERS[:4]
"""The critical speeds among the outputs (``total_mass`` and ``error`` follow)."""


def takes(keys):
    """True if every key in ``keys`` is a benchmark parameter or ``stiffness``: configurations this
    module evaluates as arrays."""
    return all(key in NAMES or key == STIFFNESS_KEY for key in keys)


def _real_column(values, count):
    """``(float64 array, usable mask)`` of one varied parameter's values; an entry that is not a
    real number (a bool, a string, a complex) is ``nan`` and not usable."""
    if isinstance(values, np.ndarray) and values.dtype.kind in "fiu":
        return values.astype(float, copy=False), np.ones(count, dtype=bool)
    values = list(values)
    if set(map(type, values)) <= {float}:           # the common case, checked at C speed
        return np.array(values, dtype=float), np.ones(count, dtype=bool)
    usable = np.fromiter((isinstance(v, numbers.Real) and not isinstance(v, bool) for v in values),
                         dtype=bool, count=count)
    if usable.all():
        return np.asarray(values, dtype=float), usable
    return np.array([float(v) if ok else np.nan for v, ok in zip(values, usable)]), usable


def _static_stiffness(gK0, S):
    """Stacked ``gK0 - gK0^T (gK0 + S)^-1 gK0`` (N m/rad) and the (B,) mask of rows where
    ``gK0 + S`` could be solved; ``S`` None: ``gK0`` itself."""
    solvable = np.ones(len(gK0), dtype=bool)
    if S is None:
        return gK0, solvable
    A = gK0 + np.asarray(S, dtype=float)
    try:
        X = np.linalg.solve(A, gK0)
    except np.linalg.LinAlgError:            # a singular row: solve row by row, mark the singular ones
        X = np.full_like(gK0, np.nan)
        for i in range(len(A)):
            try:
                X[i] = np.linalg.solve(A[i], gK0[i])
            except np.linalg.LinAlgError:
                solvable[i] = False
    return gK0 - np.swapaxes(gK0, -1, -2) @ X, solvable


def _speeds(columns, S, count, max_speed):
    """The (B,) mask of the rows of ``count`` parameter sets given as ``columns`` (arrays of B or
    floats) with frame stiffness ``S`` that could be computed, and their :data:`SPEEDS` (a dict
    of arrays, one value per computed row)."""
    with np.errstate(all="ignore"):          # a row that overflows is not finite: the reference takes it
        return _finite_speeds(columns, S, count, max_speed)


def _finite_speeds(columns, S, count, max_speed):
    m = whipple_matrices(SimpleNamespace(**columns))
    shape = (count, 2, 2)
    M, C1, K2 = (np.broadcast_to(x, shape) for x in (m.M, m.C1, m.K2))
    gK0 = np.broadcast_to(columns["g"], (count,))[:, None, None] * np.broadcast_to(m.K0, shape)
    gK0, done = _static_stiffness(gK0, S)
    p = pieces(M, C1, gK0, K2)
    for value in p.values():
        done &= np.isfinite(value)
    return done, batch_critical_speeds({k: v[done] for k, v in p.items()}, max_speed)


BATCH = 8192
"""Rows evaluated together: the temporaries of a batch (a few hundred kB each) are reused from
the heap; a chunk of 50,000 rows at once made each of them fresh pages (measured: a third of the
evaluation's time in the kernel, zero in batches of 8,192)."""


def evaluate_columns(model, changes, count, max_speed, reference):
    """:func:`evaluate_batch` of ``count`` configurations, :data:`BATCH` rows at a time."""
    parts = [evaluate_batch(model, {k: v[a:a + BATCH] for k, v in changes.items()}, min(BATCH, count - a),
                            max_speed, reference) for a in range(0, count, BATCH)]
    if len(parts) == 1:
        return parts[0]
    values = {k: np.concatenate([p.values[k] for p in parts]) for k in NUMBERS}
    return Outcomes(values, [e for p in parts for e in p.errors])


def evaluate_batch(model, changes, count, max_speed, reference):
    """:class:`Outcomes` of ``count`` configurations of ``model``, each one row of ``changes``.

    Parameters
    ----------
    model : bikemass.scenario.scenario.Scenario
        The sweep's bicycle, rider and stiffness with the Whipple model (``parameters()``,
        ``frame_stiffness(choice)`` and ``stiffness``; its parameter set and stiffnesses are cached).
    changes : dict
        ``{key: sequence of count values}``: benchmark parameters (SI) and ``stiffness`` choices
        (:func:`takes` the keys).
    count : int
        B, the number of configurations.
    max_speed : float
        Critical speeds on ``(0, max_speed]`` (m/s).
    reference : callable
        ``reference(configuration)`` -> the result row (a dict of
        :data:`~bikemass.sweep.table.OUTPUTS`) of one configuration ``{key: value}``: the
        per-configuration path, for the rows the arrays do not take.

    Returns
    -------
    Outcomes
    """
    values = {k: np.full(count, np.nan) for k in NUMBERS}
    base = model.parameters().to_dict()
    columns, usable = dict(base), np.ones(count, dtype=bool)
    varied = [k for k in changes if k in NAMES]
    for key in varied:
        columns[key], ok = _real_column(changes[key], count)
        usable &= ok
    if varied:
        usable &= ~refused_parameters(columns, count)
    if STIFFNESS_KEY in changes:
        choices = list(changes[STIFFNESS_KEY])
        groups = {choice: np.flatnonzero([c == choice for c in choices]) for choice in dict.fromkeys(choices)}
    else:
        groups = {model.stiffness: np.arange(count)}
    for choice, rows in groups.items():
        try:
            S = model.frame_stiffness(choice)
        except (InputError, ValueError, TypeError, np.linalg.LinAlgError):
            usable[rows] = False                     # the reference gives these rows their error
            continue
        rows = rows[usable[rows]]
        if not len(rows):
            continue
        picked = {k: v[rows] if isinstance(v, np.ndarray) else v for k, v in columns.items()}
        done, speeds = _speeds(picked, S, len(rows), max_speed)
        usable[rows[~done]] = False
        for k in SPEEDS:
            values[k][rows[done]] = speeds[k]
    total = columns["mR"] + columns["mB"] + columns["mH"] + columns["mF"]    # the reference's order
    values["total_mass"][usable] = np.broadcast_to(total, (count,))[usable]
    return completed(values, usable, changes, reference)


def completed(values, usable, changes, reference):
    """:class:`Outcomes` of a chunk: ``values`` (``{column: array}``) where ``usable``, and every other
    row evaluated by ``reference`` (the one-by-one route: its numbers, or its error message)."""
    errors = [None] * len(usable)
    for i in np.flatnonzero(~usable).tolist():
        row = reference({k: v[i] for k, v in changes.items()})
        errors[i] = row["error"]
        for k in NUMBERS:
            values[k][i] = np.nan if row[k] is None else row[k]
    return Outcomes(values, errors)
