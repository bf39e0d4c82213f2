"""Sweep throughput: configurations per second per core, and the scaling from 1 to 2 Dask workers.

Run by hand:  python benchmarks/bench_sweep.py [--grid-only]
Each line is set beside BicycleParameters' ``Bicycle.eig`` over the thesis's 601 speeds
(0..30 m/s) in this process, the cost of one configuration for a user of that package.
Numbers vary with machine load; the ratios are what to compare.

* parameter level: the 2,050-configuration grid over c (41 values) and lam (50) on the
  benchmark, evaluated one by one in this process (critical speeds and stable range, exact);
* geometry level: Jamis seat- and chain-stay walls, steel frame (beam S), Relaxed rider:
  each configuration rebuilds the bicycle's mass properties and beam stiffness;
* scaling: the same 2,050-configuration sweep on a local Dask cluster of 1 and of 2
  single-threaded worker processes (cluster started and warmed up before timing).
"""

import os
import sys
import tempfile
import time
import timeit
from pathlib import Path

import numpy as np

from bikemass.sweep import read_spec, run_sweep
from bikemass.sweep.evaluate import _model, evaluate

GRID = """bike: benchmark
vary:
  c: {from: 0.0, to: 0.2, num: 41}
  lam: {from: 0.1, to: 0.5, num: 50}
"""
WALLS = """bike: jamis
rider: relaxed
stiffness: steel
vary:
  sections.seat_stay.wall: {from: 0.0006, to: 0.0015, num: 4}
  sections.chain_stay.wall: {from: 0.0008, to: 0.0016, num: 2}
"""


def bp_eig_seconds():
    """Best time of BicycleParameters' Bicycle.eig over 601 speeds (benchmark bicycle)."""
    import bicycleparameters as bp
    data = Path(bp.__file__).parent / "app-data"
    bike = bp.Bicycle("Benchmark", pathToData=str(data))
    speeds = np.linspace(0, 30, 601)
    return min(timeit.repeat(lambda: bike.eig(speeds), number=3, repeat=5)) / 3


def per_configuration(spec, repeat=3):
    """Best seconds per configuration, evaluated serially in this process (model warm)."""
    configs = spec.configurations()
    model = _model((spec.bike, spec.rider, spec.stiffness, spec.combine, spec.source))
    evaluate(model, configs[0], spec.max_speed)
    best = float("inf")
    for _ in range(repeat):
        model._bicycles.clear(), model._bodies.clear(), model._stiffness.clear(), model._params.clear()
        model._riders.clear(), model._seated.clear(), model._parts.clear()
        t = time.perf_counter()
        for c in configs:
            evaluate(model, c, spec.max_speed)
        best = min(best, (time.perf_counter() - t) / len(configs))
    return best


def sweep_seconds(spec, workers):
    """Wall time of the whole sweep on a warm local cluster of ``workers`` processes."""
    from distributed import LocalCluster
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                      dashboard_address="127.0.0.1:0", silence_logs=40) as cluster, tempfile.TemporaryDirectory() as tmp:
        run_sweep(spec, Path(tmp) / "warm", scheduler=cluster.scheduler_address)     # workers import, build
        best = float("inf")
        for k in range(3):
            t = time.perf_counter()
            rows = run_sweep(spec, Path(tmp) / f"run{k}", scheduler=cluster.scheduler_address)
            best = min(best, time.perf_counter() - t)
        return best, rows


def main():
    with tempfile.TemporaryDirectory() as tmp:
        grid = read_spec(_write(tmp, "grid.yaml", GRID))
        walls = read_spec(_write(tmp, "walls.yaml", WALLS))
        eig = bp_eig_seconds()
        print(f"BicycleParameters Bicycle.eig, 601 speeds: {eig * 1e3:.2f} ms per call")
        par = per_configuration(grid)
        print(f"parameter level (2,050 c x lam, benchmark): {par * 1e3:.3f} ms per configuration, "
              f"{1 / par:.0f} per second per core, {par / eig:.3f} of one Bicycle.eig")
        if "--grid-only" not in sys.argv:
            geo = per_configuration(walls, repeat=1)
            print(f"geometry level (Jamis stay walls, steel S, Relaxed): {geo * 1e3:.1f} ms per configuration, "
                  f"{1 / geo:.1f} per second per core, {geo / eig:.1f} x one Bicycle.eig")
        one, rows1 = sweep_seconds(grid, 1)
        two, rows2 = sweep_seconds(grid, 2)
        assert rows1 == rows2, "the tables differ"
        print(f"2,050-configuration sweep on a local Dask cluster: 1 worker {one:.2f} s, 2 workers {two:.2f} s, "
              f"speed-up {one / two:.2f}x on {os.cpu_count()} cores (tables identical)")


def _write(folder, name, text):
    path = Path(folder) / name
    path.write_text(text)
    return str(path)


if __name__ == "__main__":
    main()
