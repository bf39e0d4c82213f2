"""Sweep throughput: configurations per second per core, and the scaling from 1 to 2 Dask workers.

Run by hand:  python benchmarks/bench_sweep.py [--grid-only] [--rounds R] [--large]
Each cost is set beside BicycleParameters' ``Bicycle.eig`` over the thesis's 601 speeds
(0..30 m/s) in this process, the cost of one configuration for a user of that package.
Numbers vary with machine load (the load average is printed); the ratios are what to compare.

* parameter level: the 2,050-configuration grid over c (41 values) and lam (50) on the
  benchmark (``examples/sweeps/benchmark_c_lam.yaml``), evaluated one by one in this process;
* geometry level: Jamis seat- and chain-stay walls, steel frame (beam S), Relaxed rider:
  each configuration rebuilds the bicycle's mass properties and beam stiffness;
* scaling, the same 2,050-configuration sweep (``run_sweep``, spec to ``results.csv``) on
  three kinds of engine, each with 1 and with 2 single-threaded workers: a plain process
  pool running the same chunk tasks (no Dask, no files: what the machine gives two
  processes, the ceiling for any engine), the local Dask cluster of ``--workers N``
  (``bikemass.sweep.run.local_cluster``), and a ``dask scheduler`` with ``dask worker
  --nthreads 1`` processes started here on loopback (``--scheduler``; started with the
  settings docs/analysis.md recommends, ``QUIET_CLUSTER`` as environment variables). The
  1- and the 2-worker engine of a kind are started side by side (timed), run once each
  (imports, the model in every worker; timed), then ``--rounds`` rounds of four runs in
  the order 1, 2, 2, 1 workers, so that both see the same machine: the speed of this
  machine drifts from one second to the next (the same work in one process took 0.25 s
  or 0.5 s), and only runs this close together can be compared. Printed: medians of the
  whole run and of its engine part (connecting, sending the chunks, computing, gathering,
  writing the chunk files: from the first progress call to the last), and the ratio of
  each round, (1 + 1) / (2 + 2); every table is checked to be identical, byte for byte.
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
from bikemass.sweep.evaluate import Chunk, _scenario, finish_chunk
from bikemass.sweep.layout import split
from bikemass.sweep.run import QUIET_CLUSTER, chunk_size, local_cluster
from bikemass.sweep.vectorised import takes

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


def bp_eig_seconds():
    """Best time of BicycleParameters' Bicycle.eig over 601 speeds (benchmark bicycle)."""
    import bicycleparameters as bp
    data = Path(bp.__file__).parent / "app-data"
    bike = bp.Bicycle("Benchmark", pathToData=str(data))
    speeds = np.linspace(0, 30, 601)
    return min(timeit.repeat(lambda: bike.eig(speeds), number=3, repeat=5)) / 3


def per_configuration(spec, repeat=3):
    """Best seconds per configuration, the whole spec as one chunk in this process (YAML parsed
    and the bicycle, rider and stiffness built before the clock starts, in each repeat; arrays
    for parameter-level sweeps)."""
    best = float("inf")
    for _ in range(repeat):
        from bikemass.sweep import evaluate as module
        module._SCENARIOS.clear()
        _scenario(spec.scenario()).parameters()
        t = time.perf_counter()
        finish_chunk(spec, Chunk(0, spec.count))
        best = min(best, (time.perf_counter() - t) / spec.count)
    return best


class Timed:
    """Runs of one engine: wall time of each whole run and of its engine part (first to last
    progress call), and every table it wrote."""

    def __init__(self, spec, folder, **engine):
        self.spec, self.folder, self.engine_options, self.count = spec, Path(folder), engine, 0
        self.whole, self.engine, self.tables = [], [], set()

    def run(self):
        marks = []
        out = self.folder / f"run{self.count}"
        self.count += 1
        t = time.perf_counter()
        run_sweep(self.spec, out, progress=lambda n: marks.append(time.perf_counter()), **self.engine_options)
        self.whole.append(time.perf_counter() - t)
        self.engine.append(marks[-1] - marks[0])
        self.tables.add((out / "results.csv").read_bytes())


class Pooled(Timed):
    """The sweep's chunk tasks on a plain process pool (no Dask, no files, no table): what this
    machine gives 1 or 2 processes at that moment, the ceiling for any engine."""

    def __init__(self, spec, pool, workers):
        super().__init__(spec, ".")
        self.pool = pool
        size = chunk_size(spec.count, workers, cheap=takes(spec.keys))
        self.chunks = [Chunk(a, b) for a, b in split([(0, spec.count)], size)]

    def run(self):
        n = len(self.chunks)
        t = time.perf_counter()
        list(self.pool.map(finish_chunk, [self.spec] * n, self.chunks))
        self.whole.append(time.perf_counter() - t)
        self.engine.append(self.whole[-1])


def _load():
    return "load average {:.2f} {:.2f} {:.2f}".format(*os.getloadavg())


def _free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def start_dask(n, stack):
    """A ``dask scheduler`` and ``n`` ``dask worker --nthreads 1`` processes on loopback (this
    source tree on their path; stopped when ``stack`` closes); returns the scheduler's address."""
    from distributed import Client
    address = f"tcp://127.0.0.1:{_free_port()}"
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT / "src"), os.environ.get("PYTHONPATH", "")])}
    env.update(dask_environment(QUIET_CLUSTER))
    quiet = dict(env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    dask = [sys.executable, "-m", "dask"]
    procs = [subprocess.Popen(dask + ["scheduler", "--host", "127.0.0.1", "--port", address.rsplit(":", 1)[1],
                                      "--no-dashboard"], **quiet)]
    procs += [subprocess.Popen(dask + ["worker", address, "--nthreads", "1", "--no-dashboard"], **quiet)
              for _ in range(n)]
    stack.callback(_stop, procs)
    with Client(address, timeout="60s") as client:
        client.wait_for_workers(n, timeout=120)
    return address


def dask_environment(settings):
    """Dask settings as the environment variables ``dask scheduler`` and ``dask worker`` read."""
    return {"DASK_" + key.upper().replace(".", "__").replace("-", "_"): str(value) for key, value in settings.items()}


def _stop(procs):
    for p in reversed(procs):
        p.terminate()
    for p in procs:
        p.wait(timeout=30)


KINDS = ("process pool (no Dask)", "LocalCluster", "dask scheduler")


def _engines(kind, spec, folder, stack):
    """The 1- and the 2-worker engine of ``kind``, both started (closed with ``stack``)."""
    if kind.startswith("process pool"):
        from concurrent.futures import ProcessPoolExecutor
        from multiprocessing import get_context
        pools = [stack.enter_context(ProcessPoolExecutor(n, mp_context=get_context("spawn"))) for n in (1, 2)]
        return [Pooled(spec, pool, n) for pool, n in zip(pools, (1, 2))]
    if kind == "LocalCluster":
        addresses = [stack.enter_context(local_cluster(n)).scheduler_address for n in (1, 2)]
    else:
        addresses = [start_dask(n, stack) for n in (1, 2)]
    return [Timed(spec, Path(folder) / f"{n}", scheduler=a) for n, a in zip((1, 2), addresses)]


def scaling(spec, rounds, label):
    """For each kind of engine: its 1- and 2-worker versions started side by side (timed),
    one first run each (imports, model in every worker; timed), then ``rounds`` rounds of
    four runs in the order 1, 2, 2, 1; the ratio of each round is (1 + 1) / (2 + 2).  The
    machine's speed drifts from second to second (the same work in one process takes
    0.25 s or 0.5 s), so only runs this close together can be compared."""
    from contextlib import ExitStack
    print(f"{label}, {spec.count:,} configurations; {_load()}")
    print(f"  {rounds} rounds of runs 1, 2, 2, 1 workers; medians: whole run (spec to results.csv); "
          "engine part; [start-up of both; first runs]")
    tables = set()
    for kind in KINDS:
        with tempfile.TemporaryDirectory() as folder, ExitStack() as stack:
            t = time.perf_counter()
            one, two = _engines(kind, spec, folder, stack)
            start = time.perf_counter() - t
            t = time.perf_counter()
            one.run(), two.run()
            first = time.perf_counter() - t
            for timed in (one, two):
                timed.whole.clear(), timed.engine.clear()
            for _ in range(rounds):
                one.run(), two.run(), two.run(), one.run()
            for n, timed in ((1, one), (2, two)):
                print("    {:34s} {:.3f} s; {:.3f} s".format(f"{kind}, {n}", statistics.median(timed.whole),
                                                          statistics.median(timed.engine))
                      + (f"   [{start:.2f} s; {first:.2f} s]" if n == 1 else ""))
            tables |= one.tables | two.tables
        for part in ("whole", "engine"):
            a, b = getattr(one, part), getattr(two, part)
            ratios = [(a[2 * i] + a[2 * i + 1]) / (b[2 * i] + b[2 * i + 1]) for i in range(rounds)]
            print(f"  {kind}, 2 workers vs 1, {part + (' run' if part == 'whole' else ' part')}: "
                  f"median {statistics.median(ratios):.2f}x, rounds from {min(ratios):.2f}x to {max(ratios):.2f}x, "
                  f"{sum(r >= 1.5 for r in ratios)} of {rounds} at 1.5x or more")
    print(f"  tables identical: {len(tables) == 1} ({len(tables)} distinct); {_load()}")


def main():
    logging.getLogger("distributed").setLevel(logging.WARNING)      # no INFO lines as clusters close
    rounds = int(sys.argv[sys.argv.index("--rounds") + 1]) if "--rounds" in sys.argv else 10
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
        scaling(grid, rounds, "scaling")
        if "--large" in sys.argv:
            scaling(read_spec(_write(tmp, "large.yaml", LARGE)), max(1, rounds // 5), "scaling, larger grid")


def _write(folder, name, text):
    path = Path(folder) / name
    path.write_text(text)
    return str(path)


if __name__ == "__main__":
    main()
