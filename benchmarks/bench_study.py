"""Wall time, CPU time and peak memory of ``bikemass study``, without and with figures.

Run by hand: ``python benchmarks/bench_study.py [--repeat 3]``.  Each measurement runs
the command in a fresh process (``python -m bikemass.cli.main study --out TMP ...``) under a
small wrapper process whose ``getrusage(RUSAGE_CHILDREN)`` then holds the study's CPU
time and the peak resident memory of its largest process (the main process or one of
its forked workers).  Targets on this 2-core machine: issue 6's, under 5 s without figures
(set before the study had its handling and flexible-frame parts) and under 60 s with; issue
26's, the study with figures at most 2x the study without (the last line: the ratio of the
best wall times).  Other work on the machine slows the wall time; CPU time is the steadier
number.

The floor of the figures: the CPU time of a bare matplotlib figure with what an eigenvalue
figure holds (its size and dpi, ten curves of 601 points, a legend outside the axes, a grid,
mathtext labels and a title, matplotlib's own PNG writer; no bikemass code) at a layout fixed
once for the kind (``subplots_adjust`` to the study's eigenvalue margins, as issue 37 asks: no
constrained-layout solver per figure), times the number of figures the study draws; beside it,
the same bare figure laid out by constrained layout, and what the study's figures cost (the CPU
time with figures minus without).  Every case runs ``--repeat`` times: the best and the spread
(slowest / best) of the wall times are shown, and the ratio of the best and of the medians.
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from io import BytesIO

import numpy as np

WRAPPER = r"""
import json, resource, subprocess, sys, time
t0 = time.perf_counter()
subprocess.run(sys.argv[1:], check=True, stdout=subprocess.DEVNULL)
wall = time.perf_counter() - t0
r = resource.getrusage(resource.RUSAGE_CHILDREN)
print(json.dumps({"wall": wall, "cpu": r.ru_utime + r.ru_stime, "rss_mb": r.ru_maxrss / 1024}))
"""
TARGETS = {"without figures": 5.0, "with figures": 60.0}
RATIO = 2.0
SIZE = (7.0, 4.6)
"""An eigenvalue figure's size (inches: bikemass.plots.stability.SIZE)."""
MARGINS = (0.78, 0.48, 2.04, 0.24)
"""The study's eigenvalue figures' margins (inches: bikemass.study.figures.MARGINS), the floor's layout."""


def measure(figures, env=None):
    with tempfile.TemporaryDirectory() as out:
        cmd = [sys.executable, "-m", "bikemass.cli.main", "study", "--out", out] + ([] if figures else ["--no-figures"])
        text = subprocess.run([sys.executable, "-c", WRAPPER, *cmd], check=True, capture_output=True,
                              text=True, env={**os.environ, **(env or {})}).stdout
    return json.loads(text)


def bare_figure_seconds(constrained, repeat=8):
    """CPU seconds of one bare matplotlib figure like an eigenvalue figure, drawn and saved as PNG:
    laid out by constrained layout, or at the study's fixed eigenvalue margins."""
    from matplotlib.figure import Figure
    speeds = np.linspace(0.0, 10.0, 601)
    left, bottom, right, top = MARGINS

    def draw():
        fig = Figure(figsize=SIZE, layout="constrained" if constrained else None)
        if not constrained:
            fig.subplots_adjust(left=left / SIZE[0], bottom=bottom / SIZE[1], right=1 - right / SIZE[0],
                                top=1 - top / SIZE[1])
        ax = fig.subplots()
        for i in range(10):
            ax.plot(speeds, np.sin(speeds + i) * (i + 1), "-" if i % 2 else "--", label=f"mode {i}")
        ax.axhline(0, color="k", lw=0.7)
        ax.set_xlabel("forward speed $v$ (m/s)")
        ax.set_ylabel("eigenvalue $\\lambda$ (1/s)")
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)
        ax.grid(alpha=0.25, lw=0.5)
        ax.set_title("a bicycle, a rider, a frame", fontsize=10)
        fig.savefig(BytesIO(), format="png", dpi=150)
    draw()
    start = time.process_time()
    for _ in range(repeat):
        draw()
    return (time.process_time() - start) / repeat


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3, help="runs of each case (best and spread shown)")
    args = parser.parse_args()
    print(f"bikemass study, {os.cpu_count()} cores; {args.repeat} runs of each case, load average "
          f"{os.getloadavg()[0]:.2f} before")
    print(f"{'':34s} {'wall (s)':>9s} {'spread':>7s} {'CPU (s)':>8s} {'peak RSS (MB)':>14s} {'target (s)':>11s}")
    cases = [("without figures", False, None),
             ("without figures, 1 BLAS thread", False, {"OPENBLAS_NUM_THREADS": "1"}),
             ("with figures", True, None)]
    runs = {}
    for name, figures, env in cases:
        runs[name] = sorted((measure(figures, env) for _ in range(args.repeat)), key=lambda m: m["wall"])
        best = runs[name][0]
        target = TARGETS.get(name, TARGETS["without figures"])
        verdict = "ok" if best["wall"] < target else "SLOW"
        print(f"{name:34s} {best['wall']:9.2f} {runs[name][-1]['wall'] / best['wall']:7.2f} {best['cpu']:8.2f} "
              f"{best['rss_mb']:14.0f} {target:9.0f} {verdict}")
    # lazy: only the count is needed from bikemass, after the study's own runs
    from bikemass.study.figures import figure_count
    fixed, constrained, count = bare_figure_seconds(False), bare_figure_seconds(True), figure_count()
    with_, without = runs["with figures"], runs["without figures"]
    drawn = min(m["cpu"] for m in with_) - min(m["cpu"] for m in without)
    print(f"figures: {count}, {drawn:.1f} s CPU ({drawn / count * 1e3:.0f} ms each); the floor, {count} bare "
          f"matplotlib figures at a fixed layout: {fixed * count:.1f} s CPU ({fixed * 1e3:.0f} ms each): "
          f"{drawn / (fixed * count):.2f}x (laid out by constrained layout: {constrained * 1e3:.0f} ms each)")
    ratio = with_[0]["wall"] / without[0]["wall"]
    median = with_[len(with_) // 2]["wall"] / without[len(without) // 2]["wall"]
    print(f"with figures / without: {ratio:.2f}x wall (best), {median:.2f}x (medians), "
          f"{min(m['cpu'] for m in with_) / min(m['cpu'] for m in without):.2f}x CPU (target: at most 2x wall) "
          f"{'ok' if ratio <= RATIO else 'SLOW'}; load average {os.getloadavg()[0]:.2f} after")


if __name__ == "__main__":
    main()
