"""Sweep throughput: configurations per second per core, and the scaling from 1 to 2 Dask workers.

Run by hand:  python benchmarks/bench_sweep.py [--grid-only] [--rounds R] [--repeats N] [--large]
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
  ``dask worker --nthreads 1`` processes started here on loopback (``--scheduler``); beside
  them the same chunks on a plain process pool of 1 and 2 (no Dask, no files): what this
  machine gives two processes at that moment, the ceiling for any engine. Each engine
  runs alone (an idle cluster costs CPU too): started (timed), one first run (imports
  bikemass and builds the model in every worker; timed), ``--repeats`` timed runs, closed;
  all of it ``--rounds`` times so load changes hit every engine alike. Medians of the
  whole run and of its engine part (connecting, sending the chunks, computing,
  gathering, writing the chunk files: from the first progress call to the last); every
  table is checked to be identical, byte for byte.
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
from bikemass.sweep.evaluate import Chunk, _model, evaluate, evaluate_chunk
from bikemass.sweep.run import chunk_size

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


def _pool_run(pool, setup, chunks, vmax):
    """The sweep's chunks on a plain process pool (no Dask, no files): the ceiling for 2 workers."""
    t = time.perf_counter()
    list(pool.map(evaluate_chunk, [setup] * len(chunks), chunks, [vmax] * len(chunks)))
    return time.perf_counter() - t


def _engine(name, spec, folder, procs):
    """``(start-up seconds, run())`` of one engine; its cluster (if any) is closed by ``procs``."""
    from distributed import LocalCluster
    n = 2 if name.endswith("2") else 1
    t = time.perf_counter()
    if name.startswith("local"):
        cluster = LocalCluster(n_workers=n, **CLUSTER)
        procs.append(cluster)
        return time.perf_counter() - t, lambda timed: timed.run(scheduler=cluster.scheduler_address)
    if name.startswith("dask"):
        address = start_dask(n, procs)
        return time.perf_counter() - t, lambda timed: timed.run(scheduler=address)
    if name.startswith("pool"):
        from concurrent.futures import ProcessPoolExecutor
        from multiprocessing import get_context
        pool = ProcessPoolExecutor(n, mp_context=get_context("spawn"))
        procs.append(pool)
        setup = (spec.bike, spec.rider, spec.stiffness, spec.combine, spec.source)
        configs = spec.configurations()
        size = chunk_size(len(configs), n)
        chunks = [Chunk(a, configs[a:a + size]) for a in range(0, len(configs), size)]

        def run(timed):
            seconds = _pool_run(pool, setup, chunks, spec.max_speed)
            timed.whole.append(seconds), timed.engine.append(seconds)
        return 0.0, run
    return 0.0, lambda timed: timed.run()


def _close(procs):
    for p in reversed(procs):
        if hasattr(p, "terminate"):
            p.terminate()
        elif hasattr(p, "shutdown"):
            p.shutdown()
        else:
            p.close()
    for p in procs:
        if hasattr(p, "wait"):
            p.wait(timeout=30)
    procs.clear()


ENGINES = {"this process": "serial", "process pool (no Dask), 1": "pool1", "process pool (no Dask), 2": "pool2",
           "LocalCluster, 1 worker": "local1", "LocalCluster, 2 workers": "local2",
           "dask scheduler, 1 worker": "dask1", "dask scheduler, 2 workers": "dask2"}


def engines(spec, folder, rounds, repeats):
    """Each engine in turn, alone on the machine (an idle Dask cluster costs CPU too): start it
    (timed), one warm-up run (imports, model in every worker; timed), ``repeats`` timed runs,
    close it; all that ``rounds`` times, so load changes hit every engine alike."""
    timed = {label: Timed(spec, Path(folder) / name) for label, name in ENGINES.items()}
    starts = {label: [] for label in ENGINES}
    procs = []
    try:
        for _ in range(rounds):
            for label, name in ENGINES.items():
                start, run = _engine(name, spec, folder, procs)
                t = time.perf_counter()
                run(timed[label])
                starts[label].append((start, time.perf_counter() - t))
                timed[label].whole.pop(), timed[label].engine.pop()
                for _ in range(repeats):
                    run(timed[label])
                _close(procs)
    finally:
        _close(procs)
    return timed, starts


def scaling(spec, rounds, repeats, label):
    print(f"{label}, {len(spec.configurations()):,} configurations; {_load()}")
    with tempfile.TemporaryDirectory() as tmp:
        timed, starts = engines(spec, tmp, rounds, repeats)
    print(f"  medians of {rounds} x {repeats} runs: whole run (spec to results.csv); engine part; "
          "[start-up; first run: imports, model]")
    for name, t in timed.items():
        start, first = (statistics.median(x) for x in zip(*starts[name]))
        print("    {:28s} {:.3f} s; {:.3f} s   [{:.2f} s; {:.2f} s]".format(name, *t.medians(), start, first))
    for kind in ("process pool (no Dask)", "LocalCluster", "dask scheduler"):
        (w1, e1), (w2, e2) = timed[f"{kind}, 1" + " worker" * (kind != "process pool (no Dask)")].medians(), \
            timed[f"{kind}, 2" + " workers" * (kind != "process pool (no Dask)")].medians()
        print(f"  {kind}: 2 workers vs 1: {w1 / w2:.2f}x whole run, {e1 / e2:.2f}x engine part")
    tables = set().union(*(t.tables for t in timed.values()))
    print(f"  tables identical: {len(tables) == 1} ({len(tables)} distinct); {_load()}")


def main():
    logging.getLogger("distributed").setLevel(logging.WARNING)      # no INFO lines as clusters close
    rounds = int(sys.argv[sys.argv.index("--rounds") + 1]) if "--rounds" in sys.argv else 3
    repeats = int(sys.argv[sys.argv.index("--repeats") + 1]) if "--repeats" in sys.argv else 3
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
        scaling(grid, rounds, repeats, "scaling")
        if "--large" in sys.argv:
            scaling(read_spec(_write(tmp, "large.yaml", LARGE)), rounds, 1, "scaling, larger grid")


def _write(folder, name, text):
    path = Path(folder) / name
    path.write_text(text)
    return str(path)


if __name__ == "__main__":
    main()
