"""One chunk of configurations -> result rows.  Runs in the caller's process or on a Dask worker.

The :class:`~bikemass.analysis.inputs.Model` (parsed YAML, built bicycles, riders and
stiffnesses) lives as long as the process and is shared by every chunk of the same sweep.
BLAS runs on one thread (the worker, not the library, is the unit of parallelism):
:func:`bikemass.threads.one_blas_thread`.
"""

import numpy as np

from ..errors import InputError

OUTPUTS = ("weave_speed", "capsize_speed", "stable_from", "stable_to", "total_mass", "error")
_MODELS = {}


def _model(setup):
    from ..analysis.inputs import Model
    if setup not in _MODELS:
        bike, rider, stiffness, combine, source = setup
        _MODELS.clear()
        _MODELS[setup] = Model(bike, rider, stiffness, combine, origin=source)
    return _MODELS[setup]


def evaluate(model, changes, max_speed):
    """Result row (dict of :data:`OUTPUTS`) of one configuration; a configuration the model
    refuses gets its one-line reason in ``error`` and empty outputs."""
    from ..analysis.crossings import critical_speeds
    from ..analysis.model import system, values_of
    try:
        p, S = model.build(changes)
        found = critical_speeds(system(values_of(p), S), max_speed)
    except (InputError, ValueError, np.linalg.LinAlgError) as exc:
        return {**{k: None for k in OUTPUTS}, "error": str(exc).replace("\n", " ")}
    return {"weave_speed": found.weave_speed, "capsize_speed": found.capsize_speed,
            "stable_from": found.stable_from, "stable_to": found.stable_to,
            "total_mass": float(p.mR + p.mB + p.mH + p.mF), "error": None}


def evaluate_chunk(setup, configurations, max_speed):
    """Rows for ``configurations`` (list of ``{key: value}``); ``setup`` = (bike, rider, stiffness,
    combine, spec source)."""
    from ..threads import one_blas_thread
    with one_blas_thread():
        return [evaluate(_model(setup), c, max_speed) for c in configurations]
