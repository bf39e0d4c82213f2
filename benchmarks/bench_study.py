"""Wall time, CPU time and peak memory of ``bikemass study``, without and with figures.

Run by hand: ``python benchmarks/bench_study.py [--repeat 3]``.  Each measurement runs
the command in a fresh process (``python -m bikemass.cli.main study --out TMP ...``) under a
small wrapper process whose ``getrusage(RUSAGE_CHILDREN)`` then holds the study's CPU
time and the peak resident memory of its largest process (the main process or one of
its forked workers).  Targets (issue 6, this 2-core machine): under 5 s without
figures, under 60 s with.  Other work on the machine slows the wall time; CPU time is
the steadier number.
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile

WRAPPER = r"""
import json, resource, subprocess, sys, time
t0 = time.perf_counter()
subprocess.run(sys.argv[1:], check=True, stdout=subprocess.DEVNULL)
wall = time.perf_counter() - t0
r = resource.getrusage(resource.RUSAGE_CHILDREN)
print(json.dumps({"wall": wall, "cpu": r.ru_utime + r.ru_stime, "rss_mb": r.ru_maxrss / 1024}))
"""
TARGETS = {"without figures": 5.0, "with figures": 60.0}


def measure(figures, env=None):
    with tempfile.TemporaryDirectory() as out:
        cmd = [sys.executable, "-m", "bikemass.cli.main", "study", "--out", out] + ([] if figures else ["--no-figures"])
        text = subprocess.run([sys.executable, "-c", WRAPPER, *cmd], check=True, capture_output=True,
                              text=True, env={**os.environ, **(env or {})}).stdout
    return json.loads(text)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3, help="runs without figures (best is shown)")
    args = parser.parse_args()
    print(f"bikemass study, {os.cpu_count()} cores; best of {args.repeat} without figures, 1 run with")
    print(f"{'':34s} {'wall (s)':>9s} {'CPU (s)':>8s} {'peak RSS (MB)':>14s} {'target (s)':>11s}")
    cases = [("without figures", False, None, args.repeat),
             ("without figures, 1 BLAS thread", False, {"OPENBLAS_NUM_THREADS": "1"}, args.repeat),
             ("with figures", True, None, 1)]
    for name, figures, env, repeat in cases:
        best = min((measure(figures, env) for _ in range(repeat)), key=lambda m: m["wall"])
        target = TARGETS.get(name, TARGETS["without figures"])
        verdict = "ok" if best["wall"] < target else "SLOW"
        print(f"{name:34s} {best['wall']:9.2f} {best['cpu']:8.2f} {best['rss_mb']:14.0f} "
              f"{target:9.0f} {verdict}")


if __name__ == "__main__":
    main()
