"""Issue 26's table in one run: every bikemass figure beside its peer or floor, measured now.

Run by hand:  python benchmarks/bench_scale.py [--only parameter,grid,geometry,workers,long] [--repeat 3]

* parameter: configurations per second per core (CPU time, best of ``--repeat``): the
  per-configuration reference path (``bikemass.sweep.evaluate.evaluate``, 2,050 c x lam grid),
  the array path (``evaluate_outcomes``, 100,000 configurations), the plain-numpy floor of the same
  closed form (``numpy_floor.critical``: weave, capsize, first stable range; no bikemass code),
  BicycleParameters' ``Bicycle.eig`` over 601 speeds (the cost of one configuration to a user of
  that package);
* grid: ``bikemass sweep`` of the 1,000 x 1,000 benchmark grid (c x lam) as a command, under
  ``/usr/bin/time -v`` (wall, CPU, peak resident memory), beside the floor over the same 10^6
  configurations in this process; and a 100 x 100 grid, whose peak memory set beside the big
  one's gives the gathering process's memory per row;
* geometry: ``bikemass sweep`` of a chart bicycle's stack x head angle with a person re-seated on
  every configuration (40 and 160 configurations): the marginal cost per configuration, wall and
  CPU; beside yeadon building a Human from 95 measurements plus one ``Bicycle.eig`` (what a
  configuration costs a user of the peers, who must build the rider and evaluate the bicycle);
* workers: the 2,050 grid by ``bikemass sweep`` with no workers, ``--workers 1`` and ``--workers 2``;
* long: a geometry-level sweep of more than a minute in this process (Jamis stay walls, steel
  frame: beam FE per configuration), with no workers, ``--workers 1`` and ``--workers 2``.

Start-up (``bikemass params jamis`` against ``python -c "import numpy"``): bench_startup.py;
the study with and without figures: bench_study.py.  The machine is shared: each section prints
the load average, and CPU time is the steadier number when other work competes for the cores.
"""

import argparse
import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from numpy_floor import critical

ROOT = Path(__file__).resolve().parents[1]
PERSON = "name: a person on the hoods\nbody: {height: 1.80 m, mass: 75 kg, sex: male}\nchain: {hands: hoods}\n"
GEOMETRY = """bike: specialized_diverge@56
rider: person.yaml
vary:
  chart.stack: {{from: 600, to: 630, num: {stacks}}}
  chart.head_tube_angle: {{from: 71.5, to: 73.5, num: {angles}}}
"""
GRID = "bike: benchmark\nvary:\n  c: {{from: 0.0, to: 0.2, num: {n}}}\n  lam: {{from: 0.1, to: 0.5, num: {n}}}\n"
LONG = """bike: jamis
rider: relaxed
stiffness: steel
vary:
  sections.seat_stay.wall: {from: 0.025, to: 0.065, num: 120}
  sections.chain_stay.wall: {from: 0.03, to: 0.05, num: 50}
"""


def load():
    return "load average {:.2f} {:.2f} {:.2f}".format(*os.getloadavg())


def best_cpu(fn, repeat):
    best = float("inf")
    for _ in range(repeat):
        t = time.process_time()
        fn()
        best = min(best, time.process_time() - t)
    return best


def timed_command(args, cwd):
    """``(wall s, CPU s, peak RSS MB)`` of ``bikemass ARGS`` under /usr/bin/time -v."""
    done = subprocess.run(["/usr/bin/time", "-v", sys.executable, "-m", "bikemass.cli.main", *args], cwd=cwd,
                          capture_output=True, text=True, check=True)
    field = lambda name: re.search(rf"{name}: (.*)", done.stderr).group(1)           # noqa: E731
    minutes, seconds = field(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\)").rsplit(":", 1)
    wall = float(seconds) + 60 * float(minutes.split(":")[-1]) + 3600 * (float(minutes.split(":")[0]) if minutes.count(":") else 0)
    cpu = float(field(r"User time \(seconds\)")) + float(field(r"System time \(seconds\)"))
    return wall, cpu, float(field(r"Maximum resident set size \(kbytes\)")) / 1024


def benchmark_columns(n):
    from bikemass.scenario.scenario import parameters
    base = parameters("benchmark").to_dict()
    c, lam = np.meshgrid(np.linspace(0.0, 0.2, n), np.linspace(0.1, 0.5, n), indexing="ij")
    p = {k: np.full(c.size, v) for k, v in base.items()}
    p["c"], p["lam"] = c.ravel(), lam.ravel()
    return p


def floor_seconds(count, repeat):
    """CPU seconds of the floor over ``count`` configurations, the best of whole arrays and of
    batches of 8192 (whichever suits the machine's memory better)."""
    n = int(round(count ** 0.5))
    p = benchmark_columns(n)
    whole = best_cpu(lambda: critical(p), repeat)
    batched = best_cpu(lambda: [critical({k: v[a:a + 8192] for k, v in p.items()}) for a in range(0, n * n, 8192)],
                       repeat)
    return min(whole, batched)


def bp_eig_seconds(repeat):
    import bicycleparameters as bp
    bike = bp.Bicycle("Benchmark", pathToData=str(Path(bp.__file__).parent / "app-data"))
    speeds = np.linspace(0, 30, 601)
    return best_cpu(lambda: bike.eig(speeds), repeat)


def yeadon_seconds(repeat):
    import yeadon
    meas = ROOT / "tests" / "data" / "yeadon" / "JasonYeadonMeas.txt"
    import contextlib
    import io

    def build():
        with contextlib.redirect_stdout(io.StringIO()):
            yeadon.Human(str(meas))
    return best_cpu(build, repeat)


def parameter_section(repeat):
    from bikemass.sweep import evaluate as ev
    from bikemass.sweep.spec import read_spec
    print(f"parameter level, configurations per second per core (CPU, best of {repeat}); {load()}")
    grid = read_spec(str(ROOT / "examples" / "sweeps" / "benchmark_c_lam.yaml"))
    model = ev._scenario(grid.scenario())
    configs = grid.configurations()
    reference = best_cpu(lambda: [ev.evaluate(model, c, 30.0) for c in configs], repeat) / len(configs)
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "g.yaml"
        path.write_text(GRID.format(n=317))                                    # 100,489 configurations
        big = read_spec(str(path))
        columns = big.columns(0, big.count)
        ev._scenario(big.scenario())
        arrays = best_cpu(lambda: ev.evaluate_outcomes(ev._scenario(big.scenario()), big, columns, big.count),
                          repeat) / big.count
    floor = floor_seconds(100_489, repeat) / 100_489
    peer = bp_eig_seconds(repeat)
    rows = [("bikemass, one by one (reference path)", reference), ("bikemass, as arrays (sweep chunks)", arrays),
            ("plain numpy floor, same closed form", floor), ("BicycleParameters Bicycle.eig, 601 speeds", peer)]
    for name, seconds in rows:
        print(f"  {name:44s} {1 / seconds:12,.0f} /s   {seconds / floor:8.1f} x the floor")
    print(f"  arrays vs one by one: {reference / arrays:.0f}x faster; BicycleParameters / arrays: {peer / arrays:,.0f}x")


def grid_section(repeat):
    print(f"1,000 x 1,000 grid, bikemass sweep (figures and Parquet included); {load()}")
    with tempfile.TemporaryDirectory() as tmp:
        (Path(tmp) / "big.yaml").write_text(GRID.format(n=1000))
        (Path(tmp) / "small.yaml").write_text(GRID.format(n=100))
        wall, cpu, rss = min(timed_command(["sweep", "big.yaml", "--out", f"big{i}", "--quiet"], tmp)
                             for i in range(repeat))
        floor = floor_seconds(10 ** 6, repeat)
        print(f"  bikemass sweep: {wall:.1f} s wall, {cpu:.1f} s CPU, peak {rss:.0f} MB (best of {repeat}); {load()}")
        print(f"  plain numpy floor over the same 10^6: {floor:.2f} s CPU")
        print(f"  ratio: {wall / floor:.1f}x (wall / floor), {cpu / floor:.1f}x (CPU / floor)")
        bare = [timed_command(["sweep", f"{name}.yaml", "--out", f"{name}-bare", "--quiet", "--no-figures"], tmp)[2]
                for name in ("small", "big")]
    print(f"  memory without figures (the figures read columns back): {bare[0]:.0f} MB at 10^4 rows, "
          f"{bare[1]:.0f} MB at 10^6: {(bare[1] - bare[0]) * 2 ** 20 / (10 ** 6 - 10 ** 4):.0f} bytes per row")


def geometry_section(repeat):
    print(f"geometry level, specialized_diverge@56 stack x head angle, a person re-seated; {load()}")
    results = {}
    with tempfile.TemporaryDirectory() as tmp:
        (Path(tmp) / "person.yaml").write_text(PERSON)
        for count, (stacks, angles) in ((40, (8, 5)), (160, (16, 10))):
            (Path(tmp) / f"g{count}.yaml").write_text(GEOMETRY.format(stacks=stacks, angles=angles))
            runs = [timed_command(["sweep", f"g{count}.yaml", "--out", f"o{count}-{i}", "--quiet"], tmp)
                    for i in range(repeat)]
            results[count] = min(runs)
            refused = (Path(tmp) / f"o{count}-0" / "results.csv").read_text().splitlines()[1:]
            bad = sum(1 for line in refused if not line.endswith(","))
            print(f"  {count:3d} configurations: {results[count][0]:.2f} s wall, {results[count][1]:.2f} s CPU "
                  f"(best of {repeat}); rows refused: {bad}")
    wall = (results[160][0] - results[40][0]) / 120
    cpu = (results[160][1] - results[40][1]) / 120
    peer = yeadon_seconds(repeat) + bp_eig_seconds(repeat)
    print(f"  marginal: {wall * 1e3:.1f} ms wall, {cpu * 1e3:.1f} ms CPU per configuration "
          f"({1 / cpu:.0f} per second per core)")
    print(f"  peers: yeadon Human (95 measurements) + BicycleParameters Bicycle.eig: {peer * 1e3:.1f} ms "
          f"({1 / peer:.1f} per second); bikemass {peer / cpu:.1f}x faster (CPU)")


def engines(spec_text, name, tmp, label, repeat=1):
    """Each engine ``repeat`` times, interleaved (no engine gets a quieter minute than another):
    the best and the median wall time of each."""
    (Path(tmp) / name).write_text(spec_text)
    kinds = (("this process", []), ("--workers 1", ["--workers", "1"]), ("--workers 2", ["--workers", "2"]))
    runs = {engine: [] for engine, _ in kinds}
    for i in range(repeat):
        for engine, extra in kinds:
            runs[engine].append(timed_command(["sweep", name, "--out", f"{name}-{engine[-1]}-{i}", "--quiet", *extra],
                                              tmp))
    for engine, measured in runs.items():
        walls = sorted(m[0] for m in measured)
        print(f"  {label}, {engine:13s} best {walls[0]:7.2f} s, median {np.median(walls):7.2f} s wall, "
              f"{min(m[1] for m in measured):7.2f} s CPU; {load()}")
    best = {engine: min(m[0] for m in measured) for engine, measured in runs.items()}
    median = {engine: float(np.median([m[0] for m in measured])) for engine, measured in runs.items()}
    for what, times in (("best", best), ("median", median)):
        one, two = times["--workers 1"], times["--workers 2"]
        print(f"  {what}: --workers 2 vs --workers 1: {one / two:.2f}x faster ({(two / one - 1) * 100:+.0f} % time); "
              f"vs this process: {times['this process'] / two:.2f}x")


def workers_section(repeat):
    print(f"engines, the 2,050 example grid (bikemass sweep, figures included); {load()}")
    with tempfile.TemporaryDirectory() as tmp:
        engines((ROOT / "examples" / "sweeps" / "benchmark_c_lam.yaml").read_text(), "grid.yaml", tmp, "2,050 grid",
                repeat)


def long_section(repeat):
    print(f"engines, a sweep of more than a minute here (Jamis walls, steel: beam FE per configuration); {load()}")
    with tempfile.TemporaryDirectory() as tmp:
        engines(LONG, "long.yaml", tmp, "6,000 walls")


SECTIONS = {"parameter": parameter_section, "grid": grid_section, "geometry": geometry_section,
            "workers": workers_section, "long": long_section}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", default=",".join(SECTIONS), help="comma-separated sections")
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    print(f"{os.cpu_count()} cores; {load()}")
    for name in args.only.split(","):
        SECTIONS[name](args.repeat)


if __name__ == "__main__":
    main()
