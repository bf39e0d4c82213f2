"""A chunk of parameter-level configurations of a model with members, evaluated as arrays.

A sweep of the benchmark parameters (and the members' own inputs: ``CaF``, ``klean``, ...,
:func:`~bikemass.models.family.member_inputs`) of a model beyond the Whipple bicycle (``model: tyre``,
``rider-lean``, ...) took every configuration through the engine (:func:`bikemass.sweep.evaluate.evaluate`:
a scenario built, the compound matrices' polynomial eigenvalue problems, the modes followed from
standstill to name the crossings: about 17 ms a configuration for the tyre model).
:func:`evaluate_member_columns` takes a whole chunk at once: the base configuration's parameter values
(:meth:`~bikemass.scenario.scenario.Built.values`) with the varied benchmark parameters as (B,)
columns, the generated code's state coefficients of every row in one call
(:func:`~bikemass.models.family.state_coefficients`), and the batch critical speeds
(:func:`~bikemass.analysis.engine.batch.batch_critical_speeds`).

The substitution holds where a model's values are the benchmark parameters themselves plus member
values that do not depend on them (tyres, a leaning rider's upper body), and no coordinate is held:
each batch checks it on one configuration built the reference way (its values and its model's
dynamic coefficients, 1e-12 relative); if it fails, every row goes one by one.  A row the batch does
not take, or does not decide (:func:`~bikemass.analysis.engine.batch.batch_critical_speeds`'s
``decided``), goes through the reference, which also gives a refused row its reason.
"""

import numpy as np

from ..analysis.engine.batch import batch_critical_speeds
from ..core.errors import InputError
from ..models.family import member_inputs, state_coefficients
from ..models.members.spec import with_inputs
from ..models.parameters import NAMES
from ..models.plausibility import refused_parameters
from .table import NUMBERS, Outcomes
from .vectorised import SPEEDS, _real_column, completed

MASSES = ("mR", "mB", "mH", "mF")
"""The masses whose sum is a row's ``total_mass``, in the reference's order."""
BATCH = 1024
"""Rows whose critical speeds are found together (the batch path takes its cache-sized pieces itself):
measured on the tyre model, 24 us a row in batches of 1,024, 24 in 4,096, 25 in 8,192 and 33 in 256,
where each batch's fixed cost of some 2 ms begins to show."""
PROBE_TOL = 1e-12
"""Relative agreement of a probe configuration's values and coefficients with the reference's build."""


def evaluate_member_columns(scenario, changes, count, max_speed, reference):
    """:func:`evaluate_member_batch` of ``count`` configurations, :data:`BATCH` rows at a time."""
    parts = [evaluate_member_batch(scenario, {k: v[a:a + BATCH] for k, v in changes.items()},
                                   min(BATCH, count - a), max_speed, reference) for a in range(0, count, BATCH)]
    if len(parts) == 1:
        return parts[0]
    values = {k: np.concatenate([p.values[k] for p in parts]) for k in NUMBERS}
    return Outcomes(values, [e for p in parts for e in p.errors])


def _close(a, b):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and bool(np.all(np.abs(a - b) <= PROBE_TOL * (1 + np.abs(b))))


def _total_mass(p, base, columns):
    """The rows' total mass (kg) from the base configuration's parameter set ``p``, its code values ``base``
    and the varied ``columns``: a varied mass that is the set's own replaces it, one of a split set (the
    leaning rider's bicycle without the upper body) moves it by as much (the reference's order of sums)."""
    masses = [columns[m] if m in columns and getattr(p, m) == base[m] else
              getattr(p, m) + (columns[m] - base[m]) if m in columns else getattr(p, m) for m in MASSES]
    return masses[0] + masses[1] + masses[2] + masses[3]


def _substitutes(scenario, base, base_parameters, model, changes, row):
    """Whether configuration ``row`` of ``changes`` built the reference way has the values and dynamic
    coefficients of the base ``values`` with the varied parameters substituted."""
    config = {k: v[row] for k, v in changes.items()}
    try:
        built = scenario.build(config)
    except (InputError, ValueError, np.linalg.LinAlgError):
        return False
    values = {**base, **{k: float(v) for k, v in config.items()}}
    got = built.values()
    if set(got) != set(values) or not all(_close(got[k], values[k]) for k in values):
        return False
    p = built.parameters                          # the total mass as the batch makes it (from the 26 names alone)
    if not _close(p.mR + p.mB + p.mH + p.mF, _total_mass(base_parameters, base, {k: np.float64(v) for k, v in config.items()})):
        return False
    n = built.model.n_dynamic
    A, _ = state_coefficients(built.choice, values)
    return n == model.n_dynamic and A.shape[-1] == built.model.A.shape[-1] and \
        _close(A[:, :n, :n], built.model.dynamic_coefficients)


def _accepted(built, spec, key, column, usable):
    """Which rows' value of the member input ``key`` (``column``, SI) the member ``spec`` takes: each distinct
    value of the usable rows put into the built member's typed value once (its checks; a refused value's row
    goes to the reference, which gives its reason)."""
    ok = np.ones(len(column), dtype=bool)
    typed, inputs = built.members[spec.name], spec.hook("INPUTS")
    for value in np.unique(column[usable]):
        try:
            with_inputs(typed, {key: float(value)}, inputs)
        except InputError:
            ok &= column != value
    return ok


def evaluate_member_batch(scenario, changes, count, max_speed, reference):
    """:class:`~bikemass.sweep.table.Outcomes` of ``count`` configurations of ``scenario`` (a model with
    members), each one row of ``changes`` (``{benchmark name or member input: sequence of count values}``, SI).

    ``reference(configuration)`` -> the result row of one configuration ``{key: value}`` (the
    per-configuration path) takes every row the arrays do not decide.
    """
    values = {k: np.full(count, np.nan) for k in NUMBERS}
    usable = np.ones(count, dtype=bool)
    try:
        built = scenario.build()
        base = built.values()
    except (InputError, ValueError, np.linalg.LinAlgError):
        usable[:] = False
        base = None
    if base is not None:
        model = built.model
        inputs = member_inputs(scenario.model)
        columns, varied = {}, [k for k in changes if k in NAMES or k in inputs]
        for key in changes:
            if key not in NAMES and key not in inputs:
                usable[:] = False
                break
            columns[key], ok = _real_column(changes[key], count)
            usable &= ok
        if usable.any():
            usable &= ~refused_parameters({**{k: base[k] for k in NAMES},
                                           **{k: c for k, c in columns.items() if k in NAMES}}, count)
        for key in [k for k in columns if k in inputs]:   # each value of a member input checked by its member
            usable &= _accepted(built, inputs[key][0], key, columns[key], usable)
        rows = np.flatnonzero(usable)
        if len(rows) and not _substitutes(scenario, base, built.parameters, model, changes, int(rows[0])):
            usable[:] = False
            rows = rows[:0]
        if len(rows):
            row_values = {**base, **{k: columns[k][rows] for k in varied}}
            with np.errstate(all="ignore"):
                A, _ = state_coefficients(built.choice, row_values)
            n = model.n_dynamic
            P = np.ascontiguousarray(np.broadcast_to(A, (len(rows),) + A.shape[-3:])[..., :n, :n])
            found = batch_critical_speeds(P, model.families, max_speed)
            done = found["decided"]
            usable[rows[~done]] = False
            for k in SPEEDS:
                values[k][rows[done]] = found[k][done]
            total = _total_mass(built.parameters, base, columns)
            values["total_mass"][usable] = np.broadcast_to(total, (count,))[usable]
    return completed(values, usable, changes, reference)
