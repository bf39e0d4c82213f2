"""One chunk of configurations -> its lines of the results table.  Runs in the caller's process or
on a Dask worker.

A chunk is an index range of the spec's configurations; the worker makes the configurations
itself (:meth:`~bikemass.sweep.spec.SweepSpec.columns`), so a task carries the spec and two
numbers whatever its size.  Configurations that change only benchmark parameters (and the
stiffness choice) are evaluated as arrays (:mod:`bikemass.sweep.vectorised`); any other, one
by one (:func:`evaluate`, the reference the array paths are tested against): the Whipple model's
(rigid or with the quasi-static frame) by :mod:`bikemass.sweep.vectorised`, a model with members by
:mod:`bikemass.sweep.members` (the rows its batch does not decide one by one).

The :class:`~bikemass.scenario.scenario.Scenario` (parsed YAML, built bicycles, riders,
stiffnesses and models) lives as long as the process and is shared by every chunk of the same
sweep.
BLAS runs on one thread (the worker, not the library, is the unit of parallelism):
:func:`bikemass.core.threads.one_blas_thread`.
"""

import pickle
from dataclasses import dataclass

import numpy as np

from ..analysis.engine.critical import critical_speeds
from ..core.errors import InputError
from ..core.threads import one_blas_thread
from ..core.units import Quantity, factor
from ..models.family import member_inputs
from ..models.parameters import NAMES
from .members import evaluate_member_columns
from .table import NUMBERS, OUTPUTS, Outcomes, chunk_text
from .vectorised import evaluate_columns, takes

_SCENARIOS = {}


@dataclass(frozen=True)
class Chunk:
    """Configurations ``start .. stop - 1`` of a sweep."""

    start: int
    stop: int

    @property
    def size(self):
        return self.stop - self.start


@dataclass(frozen=True)
class Finished:
    """What a computed chunk leaves: ``text`` (its lines of ``results.csv``), the number of
    configurations the model ``refused`` and the first refusal ``(index, reason)`` or ``None``."""

    chunk: Chunk
    text: str
    refused: int
    first_refusal: tuple


def _scenario(scenario, inputs=None):
    """The process's own instance of ``scenario`` (a value): one per sweep, its caches kept, as
    long as its input files have the contents of digest ``inputs`` (a file edited between two
    sweeps is read again, in this process or on a long-lived Dask worker)."""
    key = (scenario, inputs)
    if key not in _SCENARIOS:
        _SCENARIOS.clear()
        _SCENARIOS[key] = scenario
    return _SCENARIOS[key]


def _bare_unit(scenario, key):
    """The unit of a bare value of ``key`` (:func:`~bikemass.scenario.inputs.file_unit`); None for a
    key the scenario does not have (its rows carry the error)."""
    try:
        return scenario.file_unit(key)
    except InputError:
        return None


def evaluate(scenario, changes, max_speed):
    """Result row (dict of :data:`OUTPUTS`) of one configuration; a configuration the model
    refuses gets its one-line reason in ``error`` and empty outputs."""
    try:
        built = scenario.build(changes)
        found = critical_speeds(built.model, max_speed)
    except (InputError, ValueError, np.linalg.LinAlgError) as exc:
        return {**{k: None for k in OUTPUTS}, "error": str(exc).replace("\n", " ")}
    p = built.parameters
    values = (found.weave_speed, found.capsize_speed, found.stable_from, found.stable_to, p.mR + p.mB + p.mH + p.mF)
    return {**dict(zip(OUTPUTS, (None if x is None else float(x) for x in values))), "error": None}


def _with_units(changes, units):
    """A configuration's values as the model reads them: a :class:`~bikemass.core.units.Quantity` for a
    value with a unit (typed: read as ``"<number> <unit>"`` would be, no text made and parsed)."""
    return {k: Quantity(float(v), units[k]) if k in units and not isinstance(v, str) else v
            for k, v in changes.items()}


def evaluate_outcomes(scenario, spec, columns, count):
    """:class:`~bikemass.sweep.table.Outcomes` of ``count`` configurations given as ``columns``."""
    if takes(spec.keys) and not scenario.model.members:     # parameters and stiffness: SI, no unit
        return evaluate_columns(scenario, columns, count, spec.max_speed,
                                lambda c: evaluate(scenario, c, spec.max_speed))
    inputs = member_inputs(scenario.model) if scenario.model.members else {}
    if all(k in NAMES or k in inputs for k in spec.keys):    # benchmark parameters and member inputs, in SI
        si = {k: np.asarray(columns[k], dtype=float) * factor(spec.units[k], inputs[k][1])
              if k in inputs and spec.units.get(k) else columns[k] for k in spec.keys}
        return evaluate_member_columns(scenario, si, count, spec.max_speed,
                                       lambda c: evaluate(scenario, c, spec.max_speed))
    # a bare value takes the unit the file writes there (docs/analysis.md), a value with a unit keeps it
    units = {k: u for k in spec.keys if (u := spec.units.get(k) or _bare_unit(scenario, k))}
    rows = [evaluate(scenario, _with_units({k: columns[k][i] for k in spec.keys}, units), spec.max_speed)
            for i in range(count)]
    values = {k: np.array([np.nan if r[k] is None else r[k] for r in rows], dtype=float) for k in NUMBERS}
    return Outcomes(values, [r["error"] for r in rows])


def finish_chunk(spec, chunk):
    """:class:`Finished` of a :class:`Chunk` of ``spec``: computed and formatted where it runs
    (formatting on the workers keeps the one process that gathers the chunks from formatting
    every row itself)."""
    columns = spec.columns(chunk.start, chunk.stop)
    with one_blas_thread():
        outcomes = evaluate_outcomes(_scenario(spec.scenario(), spec.inputs), spec, columns, chunk.size)
    refused = [i for i, e in enumerate(outcomes.errors) if e is not None]
    first = (chunk.start + refused[0], outcomes.errors[refused[0]]) if refused else None
    return Finished(chunk, chunk_text(spec.keys, columns, outcomes), len(refused), first)


def finish_chunk_pickled(spec, chunk):
    """:func:`finish_chunk` as one pickle (bytes): what a Dask task returns.  Dask sends a
    returned structure piece by piece on the worker's event-loop thread, which takes the GIL
    from the next chunk's computation; bytes go as one frame.  Dask pickles every task result
    anyway, so this trusts the workers no more than before."""
    return pickle.dumps(finish_chunk(spec, chunk), protocol=pickle.HIGHEST_PROTOCOL)
