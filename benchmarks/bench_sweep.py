"""Sweep throughput: configurations per second per core, and the scaling from 1 to 2 Dask workers.

Run by hand:  python benchmarks/bench_sweep.py [--grid-only] [--repeats N] [--large]
Each cost is set beside BicycleParameters' ``Bicycle.eig`` over the thesis's 601 speeds
(0..30 m/s) in this process, the cost of one configuration for a user of that package.
Numbers vary with machine load (the load average is printed); the ratios are what to compare.

* parameter level: the 2,050-configuration grid over c (41 values) and lam (50) on the
  benchmark (``examples/sweeps/benchmark_c_lam.yaml``), evaluated one by one in this process;
* geometry level: Jamis seat- and chain-stay walls, steel frame (beam S), Relaxed rider:
  each configuration rebuilds the bicycle's mass properties and beam stiffness;
* scaling, the same 2,050-configuration sweep (``run_sweep``, spec to ``results.csv``) in
  this process, on local Dask clusters (``--workers N``'s engine) of 1 and of 2
  single-threaded worker processes, and on a ``dask scheduler`` with 1 and with 2
  ``dask worker --nthreads 1`` processes started here on loopback (``--scheduler``). The
  clusters' start-up and their first run (which imports bikemass and builds the model in
  every worker) are timed apart; the timed runs then go round all engines ``--repeats``
  times (so load changes hit every engine alike): what a user with a running cluster sees.
  Medians of the whole run and of its engine part (connecting, sending the chunks,
  computing, gathering, writing the chunk files: from the first progress call to the
  last); every table is checked to be identical, byte for byte.
* ``--large``: the same scaling on a 20,100-configuration grid (c 201 x lam 100).
"""

import logging
import os
import socket
import statistics
import subprocess
import sys
import tempfile
import time
import timeit
from pathlib import Path

import numpy as np

from bikemass.sweep import read_spec, run_sweep
from bikemass.sweep.evaluate import _model, evaluate

ROOT = Path(__file__).resolve().parents[1]
GRID = ROOT / "examples" / "sweeps" / "benchmark_c_lam.yaml"
LARGE = """bike: benchmark
vary:
  c: {from: 0.0, to: 0.2, num: 201}
  lam: {from: 0.1, to: 0.5, num: 100}
"""
WALLS = """bike: jamis
rider: relaxed
stiffness: steel
vary:
  sections.seat_stay.wall: [0.025, 0.035, 0.045, 0.055]
  sections.chain_stay.wall: [0.03, 0.05]
"""
CLUSTER = dict(threads_per_worker=1, processes=True, host="127.0.0.1", dashboard_address="127.0.0.1:0",
               silence_logs=40)


def bp_eig_seconds():
    """Best time of BicycleParameters' Bicycle.eig over 601 speeds (benchmark bicycle)."""
    import bicycleparameters as bp
    data = Path(bp.__file__).parent / "app-data"
    bike = bp.Bicycle("Benchmark", pathToData=str(data))
    speeds = np.linspace(0, 30, 601)
    return min(timeit.repeat(lambda: bike.eig(speeds), number=3, repeat=5)) / 3


def per_configuration(spec, repeat=3):
    """Best seconds per configuration, evaluated serially in this process (YAML parsed; the
    bicycle, rider and stiffness rebuilt in each repeat)."""
    configs = spec.configurations()
    setup = (spec.bike, spec.rider, spec.stiffness, spec.combine, spec.source)
    best = float("inf")
    for _ in range(repeat):
        from bikemass.sweep import evaluate as module
        module._MODELS.clear()
        model = _model(setup)
        t = time.perf_counter()
        for c in configs:
            evaluate(model, c, spec.max_speed)
        best = min(best, (time.perf_counter() - t) / len(configs))
    return best


class Timed:
    """Wall time of a run and of its engine part (first to last progress call)."""

    def __init__(self, spec, folder):
        self.spec, self.folder, self.count = spec, Path(folder), 0
        self.whole, self.engine, self.tables = [], [], set()

    def run(self, **engine):
        marks = []
        out = self.folder / f"run{self.count}"
        self.count += 1
        t = time.perf_counter()
        run_sweep(self.spec, out, progress=lambda n: marks.append(time.perf_counter()), **engine)
        self.whole.append(time.perf_counter() - t)
        self.engine.append(marks[-1] - marks[0])
        self.tables.add((out / "results.csv").read_bytes())

    def medians(self):
        return statistics.median(self.whole), statistics.median(self.engine)


def _load():
    return "load average {:.2f} {:.2f} {:.2f}".format(*os.getloadavg())


def _free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def start_dask(n, procs):
    """A ``dask scheduler`` and ``n`` ``dask worker --nthreads 1`` processes on loopback (this
    source tree on their path; appended to ``procs``); returns the scheduler's address."""
    from distributed import Client
    address = f"tcp://127.0.0.1:{_free_port()}"
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT / "src"), os.environ.get("PYTHONPATH", "")])}
    quiet = dict(env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    dask = [sys.executable, "-m", "dask"]
    procs.append(subprocess.Popen(dask + ["scheduler", "--host", "127.0.0.1", "--port", address.rsplit(":", 1)[1],
                                          "--no-dashboard"], **quiet))
    for _ in range(n):
        procs.append(subprocess.Popen(dask + ["worker", address, "--nthreads", "1", "--no-dashboard"], **quiet))
    with Client(address, timeout="60s") as client:
        client.wait_for_workers(n, timeout=120)
    return address


def engines(spec, folder, repeats):
    """Timed runs on: this process; LocalClusters of 1 and 2 workers; a dask scheduler with 1 and
    with 2 dask worker processes.  Clusters are started (and timed) first and warmed up by one
    run each; the timed runs then go round all engines ``repeats`` times, so load changes hit
    every engine alike."""
    from distributed import LocalCluster
    clusters, procs, addresses = [], [], {}
    try:
        for n in (1, 2):
            t = time.perf_counter()
            clusters.append(LocalCluster(n_workers=n, **CLUSTER))
            start = time.perf_counter() - t
            addresses[f"local cluster, {n} worker" + "s" * (n > 1)] = clusters[-1].scheduler_address
            t = time.perf_counter()
            run_sweep(spec, Path(folder) / f"warm-local{n}", scheduler=clusters[-1].scheduler_address)
            print(f"  LocalCluster of {n}: start-up {start:.2f} s, first run (imports, model) "
                  f"{time.perf_counter() - t:.2f} s")
        for n in (1, 2):
            t = time.perf_counter()
            address = addresses[f"dask scheduler, {n} worker" + "s" * (n > 1)] = start_dask(n, procs)
            start = time.perf_counter() - t
            t = time.perf_counter()
            run_sweep(spec, Path(folder) / f"warm-dask{n}", scheduler=address)
            print(f"  dask scheduler + {n} dask worker: start-up {start:.2f} s, first run (imports, model) "
                  f"{time.perf_counter() - t:.2f} s")
        timed = {name: Timed(spec, Path(folder) / f"e{i}") for i, name in enumerate(["this process", *addresses])}
        for _ in range(repeats):
            timed["this process"].run()
            for name, address in addresses.items():
                timed[name].run(scheduler=address)
    finally:
        for cluster in clusters:
            cluster.close()
        for p in reversed(procs):
            p.terminate()
        for p in procs:
            p.wait(timeout=30)
    return timed


def scaling(spec, repeats, label):
    print(f"{label}, {len(spec.configurations()):,} configurations; {_load()}")
    with tempfile.TemporaryDirectory() as tmp:
        timed = engines(spec, tmp, repeats)
    print(f"  medians of {repeats} runs (whole run, spec to results.csv; engine part):")
    for name, t in timed.items():
        print("    {:28s} {:.3f} s; {:.3f} s".format(name, *t.medians()))
    for kind in ("local cluster", "dask scheduler"):
        (w1, e1), (w2, e2) = timed[f"{kind}, 1 worker"].medians(), timed[f"{kind}, 2 workers"].medians()
        print(f"  {kind}: 2 workers vs 1: {w1 / w2:.2f}x whole run, {e1 / e2:.2f}x engine part")
    tables = set().union(*(t.tables for t in timed.values()))
    print(f"  tables identical: {len(tables) == 1}; {_load()}")


def main():
    logging.getLogger("distributed").setLevel(logging.WARNING)      # no INFO lines as clusters close
    repeats = int(sys.argv[sys.argv.index("--repeats") + 1]) if "--repeats" in sys.argv else 7
    grid = read_spec(str(GRID))
    print(f"{_load()}, {os.cpu_count()} cores")
    eig = bp_eig_seconds()
    print(f"BicycleParameters Bicycle.eig, 601 speeds: {eig * 1e3:.2f} ms per call")
    par = per_configuration(grid)
    print(f"parameter level (2,050 c x lam, benchmark): {par * 1e3:.3f} ms per configuration, "
          f"{1 / par:.0f} per second per core, {par / eig:.4f} of one Bicycle.eig")
    with tempfile.TemporaryDirectory() as tmp:
        if "--grid-only" not in sys.argv:
            walls = read_spec(_write(tmp, "walls.yaml", WALLS))
            geo = per_configuration(walls, repeat=1)
            print(f"geometry level (Jamis stay walls, steel S, Relaxed): {geo * 1e3:.1f} ms per configuration, "
                  f"{1 / geo:.1f} per second per core, {geo / eig:.1f} x one Bicycle.eig")
        scaling(grid, repeats, "scaling")
        if "--large" in sys.argv:
            scaling(read_spec(_write(tmp, "large.yaml", LARGE)), max(3, repeats // 2), "scaling, larger grid")


def _write(folder, name, text):
    path = Path(folder) / name
    path.write_text(text)
    return str(path)


if __name__ == "__main__":
    main()
