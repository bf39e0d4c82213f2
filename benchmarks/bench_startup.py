"""Whole-command start-up time against ``python -c "import numpy"`` on the same machine.

Run by hand: ``python benchmarks/bench_startup.py``.  Each command is a fresh Python
process started the way the ``bikemass`` console script starts it (``from bikemass.cli.main
import main``), with this checkout's ``src`` first on the path; best of 5 wall-clock
runs.  Targets (issues 11 and 26): ``bikemass --help`` at most 1x, ``bikemass params
benchmark --format json`` at most 2.5x and ``bikemass params jamis`` (a bicycle built from its
parts: mass properties of every part) at most 3x the numpy import; ``python -c "import trimesh"``
is timed beside them (trimesh is imported only where a mesh is built: export, draw, union
overlaps).  It also lists which heavy modules each command loaded.
"""

import os
import subprocess
import sys
import time
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src"
REPEAT = 5
ENTRY = "import sys; from bikemass.cli.main import main; sys.argv[0] = 'bikemass'; sys.exit(main())"
HEAVY = ("numpy", "scipy", "yaml", "trimesh", "matplotlib")
COMMANDS = {
    "bikemass --help": (["--help"], 1.0),
    "bikemass params benchmark --format json": (["params", "benchmark", "--format", "json"], 2.5),
    "bikemass params jamis": (["params", "jamis"], 3.0),
    "bikemass stability benchmark --format json": (["stability", "benchmark", "--format", "json"], None),
}


def environment():
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(SRC), os.environ.get("PYTHONPATH", "")]))
    env.pop("PYTHONSTARTUP", None)
    return env


def best_of(argv, env):
    times = []
    for _ in range(REPEAT):
        t0 = time.perf_counter()
        subprocess.run(argv, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
        times.append(time.perf_counter() - t0)
    return min(times)


def loaded(args, env):
    """The heavy modules a command imports."""
    probe = ("import sys, atexit; atexit.register(lambda: sys.__stderr__.write("
             f"'LOADED ' + ' '.join(m for m in {HEAVY!r} if m in sys.modules) + '\\n')); " + ENTRY)
    done = subprocess.run([sys.executable, "-c", probe, *args], env=env, capture_output=True, text=True)
    line = [l for l in done.stderr.splitlines() if l.startswith("LOADED")]
    return line[-1][7:] or "-" if line else "?"


def main():
    env = environment()
    peer = best_of([sys.executable, "-c", "import numpy"], env)
    print(f"start-up, best of {REPEAT} (wall clock, {os.cpu_count()} cores; a shared machine varies)")
    peer_name = 'python -c "import numpy"'
    print(f"{peer_name:45s} {peer * 1000:7.0f} ms   1.00x")
    trimesh = best_of([sys.executable, "-c", "import trimesh"], env)
    trimesh_name = 'python -c "import trimesh"'
    print(f"{trimesh_name:45s} {trimesh * 1000:7.0f} ms  {trimesh / peer:5.2f}x")
    for name, (args, target) in COMMANDS.items():
        t = best_of([sys.executable, "-c", ENTRY, *args], env)
        verdict = "" if target is None else f"  (target <= {target}x: {'met' if t / peer <= target else 'MISSED'})"
        print(f"{name:45s} {t * 1000:7.0f} ms  {t / peer:5.2f}x{verdict}   loads: {loaded(args, env)}")


if __name__ == "__main__":
    main()
