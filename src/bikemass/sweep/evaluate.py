"""One chunk of configurations -> result rows.  Runs in the caller's process or on a Dask worker.

The :class:`~bikemass.scenario.inputs.Model` (parsed YAML, built bicycles, riders and
stiffnesses) lives as long as the process and is shared by every chunk of the same sweep.
BLAS runs on one thread (the worker, not the library, is the unit of parallelism):
:func:`bikemass.core.threads.one_blas_thread`.
"""

import json
import pickle

import numpy as np

from ..core.errors import InputError
from ..scenario.inputs import Model, file_unit
from ..analysis.engine.critical import critical_speeds
from ..models.whipple import whipple_model
from ..core.threads import one_blas_thread
from .table import csv_lines

OUTPUTS = ("weave_speed", "capsize_speed", "stable_from", "stable_to", "total_mass", "error")
_MODELS = {}


class Chunk:
    """Configurations ``start .. stop - 1`` of a sweep (a list of ``{key: value}``; ``units``:
    ``{key: unit}`` of the values that reach the model as ``"<number> <unit>"``).

    A plain object rather than a list, so Dask ships it as one pickled value instead of
    walking every configuration of it while building the task graph."""

    __slots__ = ("start", "configurations", "units")

    def __init__(self, start, configurations, units=None):
        self.start, self.configurations, self.units = start, configurations, units or {}

    @property
    def stop(self):
        return self.start + len(self.configurations)


def _model(setup):
    if setup not in _MODELS:
        bike, rider, stiffness, combine, source = setup
        _MODELS.clear()
        _MODELS[setup] = Model(bike, rider, stiffness, combine, origin=source)
    return _MODELS[setup]


def _bare_unit(model, key):
    """The unit of a bare value of ``key`` (:func:`~bikemass.scenario.inputs.file_unit`); None for a
    key the model does not have (its rows carry the error)."""
    try:
        return file_unit(model, key)
    except InputError:
        return None


def evaluate(model, changes, max_speed):
    """Result row (dict of :data:`OUTPUTS`) of one configuration; a configuration the model
    refuses gets its one-line reason in ``error`` and empty outputs."""
    try:
        p, S = model.build(changes)
        found = critical_speeds(whipple_model(p, S), max_speed)
    except (InputError, ValueError, np.linalg.LinAlgError) as exc:
        return {**{k: None for k in OUTPUTS}, "error": str(exc).replace("\n", " ")}
    values = (found.weave_speed, found.capsize_speed, found.stable_from, found.stable_to, p.mR + p.mB + p.mH + p.mF)
    # plain floats: a row kept in memory writes the same bytes as one read back from a chunk file
    return {**dict(zip(OUTPUTS, (None if x is None else float(x) for x in values))), "error": None}


def evaluate_chunk(setup, chunk, max_speed):
    """Rows for the configurations of a :class:`Chunk`; ``setup`` = (bike, rider, stiffness,
    combine, spec source)."""
    model = _model(setup)
    keys = {k for c in chunk.configurations[:1] for k in c}
    # a bare value takes the unit the file writes there (docs/analysis.md), a value with a unit keeps it
    units = {k: u for k in keys if (u := chunk.units.get(k) or _bare_unit(model, k))}
    with one_blas_thread():
        return [evaluate(model, {k: f"{float(v)!r} {units[k]}" if k in units and not isinstance(v, str) else v
                                 for k, v in c.items()}, max_speed)
                for c in chunk.configurations]


def finish_chunk(setup, chunk, max_speed, keys):
    """Everything a finished :class:`Chunk` leaves, made where it was computed: its result rows,
    the text of its chunk file (JSON) and its lines of ``results.csv``
    (:func:`bikemass.sweep.table.csv_lines`; ``keys`` = the varied keys).  Formatting on the
    workers keeps the one process that gathers the chunks from formatting every row itself."""
    rows = evaluate_chunk(setup, chunk, max_speed)
    return rows, json.dumps(rows), csv_lines(keys, chunk.configurations, rows)


def finish_chunk_pickled(setup, chunk, max_speed, keys):
    """:func:`finish_chunk` as one pickle (bytes): what a Dask task returns.  Dask sends a
    returned list of dicts row by row (a pickle and a frame each, about 45 us per row on the
    worker's event-loop thread, which takes the GIL from the next chunk's computation: one
    worker ran about 1.5x slower than a plain process); bytes go as one frame.  Dask pickles
    every task result anyway, so this trusts the workers no more than before."""
    return pickle.dumps(finish_chunk(setup, chunk, max_speed, keys), protocol=pickle.HIGHEST_PROTOCOL)
