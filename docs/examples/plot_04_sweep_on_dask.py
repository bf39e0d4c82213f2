"""
A design sweep on Dask
======================

A sweep varies inputs over a grid (or a Latin hypercube or Sobol sample) and finds every
configuration's weave and capsize speeds. The configurations run in chunks on any Dask cluster:
here a small local one inside this process (two threads, no worker processes to start), which
``bm.sweep`` takes as ``scheduler=`` and leaves open, as a notebook's cluster serves many sweeps.
``bikemass sweep SPEC --workers N`` starts a cluster of worker processes instead.
"""

import tempfile
from pathlib import Path

import distributed

import bikemass as bm
from bikemass.sweep.figures import heatmap_figure
from bikemass.sweep.spec import read_spec

# %%
# The specification: the benchmark bicycle's trail against its steer-axis tilt (SI: m and rad).
folder = Path(tempfile.mkdtemp())
spec_file = folder / "trail_tilt.yaml"
spec_file.write_text("""\
name: benchmark, trail x steer-axis tilt
bike: benchmark
vary:
  c: {from: 0.0, to: 0.16, num: 17}
  lam: {from: 0.1, to: 0.5, num: 17}
""")

# %%
# The cluster and the sweep: 289 configurations, each chunk written to ``out/chunks`` as it
# finishes (a sweep that is interrupted resumes there).
cluster = distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=False,
                                   dashboard_address=None, silence_logs=40)
with distributed.Client(cluster, set_as_default=False) as client:
    rows = bm.sweep(spec_file, folder / "out", scheduler=client)
cluster.close()
stable = [r for r in rows if r["stable_from"] is not None]
print(f"{len(rows)} configurations, {len(stable)} with a stable speed range")
print(sorted(p.name for p in (folder / "out").iterdir()))

# %%
# Weave and capsize speed over the grid (blank: no such crossing).
fig = heatmap_figure(rows, read_spec(spec_file))
