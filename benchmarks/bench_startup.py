"""Whole-command start-up time against ``python -c "import numpy"`` on the same machine.

Run by hand: ``python benchmarks/bench_startup.py``.  Each command is a fresh Python
process started the way the ``bikemass`` console script starts it (``from bikemass.cli.main
import main``), with this checkout's ``src`` first on the path; best of 5 wall-clock
runs (wall clock and CPU time; the ratios on CPU time).  Targets (issues 11, 26 and 37): ``bikemass --help`` at most 1x, ``bikemass params
benchmark`` and ``bikemass stability benchmark`` at most 2.5x and ``bikemass params jamis`` (a bicycle built from its
parts: mass properties of every part) at most 3x the numpy import; ``python -c "import trimesh"``
is timed beside them (trimesh is imported only where a mesh is built: export, draw, union
overlaps).  It also lists which heavy modules each command loaded.
"""

import os
import resource
import subprocess
import sys
import time
from pathlib import Path

SRC = Path(os.environ.get("BIKEMASS_SRC") or Path(__file__).resolve().parents[1] / "src")
"""The checkout timed (``BIKEMASS_SRC=/path/to/src`` times another, e.g. main for a before)."""
REPEAT = 5
ENTRY = "import sys; from bikemass.cli.main import main; sys.argv[0] = 'bikemass'; sys.exit(main())"
HEAVY = ("numpy", "scipy", "yaml", "trimesh", "matplotlib")
COMMANDS = {
    "bikemass --help": (["--help"], 1.0),
    "bikemass params benchmark --format json": (["params", "benchmark", "--format", "json"], 2.5),
    "bikemass params jamis": (["params", "jamis"], 3.0),
    "bikemass stability benchmark --format json": (["stability", "benchmark", "--format", "json"], 2.5),
    "bikemass params benchmark": (["params", "benchmark"], 2.5),
    "bikemass stability benchmark": (["stability", "benchmark"], 2.5),
    "bikemass simulate benchmark --speed 5": (["simulate", "benchmark", "--speed", "5"], None),
    "bikemass eig benchmark": (["eig", "benchmark"], None),
}


def environment():
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(SRC), os.environ.get("PYTHONPATH", "")]))
    env.pop("PYTHONSTARTUP", None)
    return env


def best_of(argv, env):
    """``(wall, cpu)``: the best of :data:`REPEAT` runs' wall-clock time and the best of their CPU times
    (user + system of the child: what the command costs, less disturbed by other processes' load)."""
    times, cpus = [], []
    for _ in range(REPEAT):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        subprocess.run(argv, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
        times.append(time.perf_counter() - t0)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpus.append(after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime)
    return min(times), min(cpus)


def loaded(args, env):
    """The heavy modules a command imports."""
    probe = ("import sys, atexit; atexit.register(lambda: sys.__stderr__.write("
             f"'LOADED ' + ' '.join(m for m in {HEAVY!r} if m in sys.modules) + '\\n')); " + ENTRY)
    done = subprocess.run([sys.executable, "-c", probe, *args], env=env, capture_output=True, text=True)
    line = [row for row in done.stderr.splitlines() if row.startswith("LOADED")]
    return line[-1][7:] or "-" if line else "?"


def main():
    env = environment()
    peer, peer_cpu = best_of([sys.executable, "-c", "import numpy"], env)
    print(f"start-up, best of {REPEAT} (wall clock and CPU time of the process, {os.cpu_count()} cores, load "
          f"{os.getloadavg()[0]:.1f}; the ratios and targets are on CPU time, which other processes disturb less)")
    peer_name = 'python -c "import numpy"'
    print(f"{peer_name:45s} {peer * 1000:7.0f} ms wall {peer_cpu * 1000:6.0f} ms CPU   1.00x")
    trimesh, trimesh_cpu = best_of([sys.executable, "-c", "import trimesh"], env)
    trimesh_name = 'python -c "import trimesh"'
    print(f"{trimesh_name:45s} {trimesh * 1000:7.0f} ms wall {trimesh_cpu * 1000:6.0f} ms CPU  "
          f"{trimesh_cpu / peer_cpu:5.2f}x")
    for name, (args, target) in COMMANDS.items():
        t, c = best_of([sys.executable, "-c", ENTRY, *args], env)
        r = c / peer_cpu
        verdict = "" if target is None else f"  (target <= {target}x: {'met' if r <= target else 'MISSED'})"
        print(f"{name:45s} {t * 1000:7.0f} ms wall {c * 1000:6.0f} ms CPU  {r:5.2f}x{verdict}   "
              f"loads: {loaded(args, env)}")


if __name__ == "__main__":
    main()
