"""Design sweeps: many configurations of one bicycle, rider and stiffness, on one core or a Dask cluster.

``read_spec(path)`` -> :class:`~bikemass.sweep.spec.SweepSpec`; ``run_sweep(spec, out, ...)``
writes ``results.csv`` (and Parquet), figures and, if asked, Sobol indices.
"""

from .run import run_sweep
from .spec import SweepSpec, read_spec

__all__ = ["SweepSpec", "read_spec", "run_sweep"]
