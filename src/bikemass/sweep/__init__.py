"""Design sweeps: many configurations of one bicycle, rider and stiffness, on one core or a Dask cluster.

``read_spec(path)`` -> :class:`~bikemass.sweep.spec.SweepSpec`; ``run_sweep(spec, out, ...)``
writes ``results.csv`` (and Parquet) a chunk at a time and returns a
:class:`~bikemass.sweep.result.SweepResult` (the rows, read back on demand).  docs/sweep.md.
"""

from .result import SweepResult
from .run import run_sweep
from .spec import SweepSpec, read_spec

__all__ = ["SweepResult", "SweepSpec", "read_spec", "run_sweep"]
