"""A member model's parameter-level sweep against the Whipple bicycle's: marginal cost per configuration.

Run by hand:  python benchmarks/bench_member_sweep.py [--model tyre] [--before] [--against REV] [--repeat 3]

Both sweeps go through ``bm.sweep`` (spec to ``results.csv`` and Parquet, in this process) over the
benchmark's trail ``c`` x steer-axis tilt ``lam`` (issue 32's must-show).  The marginal cost of a
configuration is the difference of two sweeps' CPU times over the difference of their sizes (the
fixed costs of a sweep, its folder, its scenario and the tables' headers, cancel); the best of
``--repeat`` runs of each size is taken, the two models' sweeps (and ``--against``'s) alternating
within each repeat so that each ratio is taken under one load.  Printed: each model's marginal
cost (us of CPU a configuration), the ratio member / Whipple (issue 32: at most 10), and how many of
the member sweep's rows went through the engine (the batch path's undecided rows).

``--before``: also the member sweep the way it ran before the batch path (every configuration one
by one through the engine, ``bikemass.sweep.evaluate.evaluate``), on a smaller grid.

``--against REV``: also the member sweep with the batch path of git revision ``REV``
(``src/bikemass/analysis/engine/batch.py`` as it was there, loaded beside this one), the two
alternating within each repeat: the ratio of their marginal costs, measured under the same load.
"""

import argparse
import importlib.util
import os
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np

import bikemass as bm
from bikemass.sweep import evaluate as evaluate_module
from bikemass.sweep import members as members_module


def spec(folder, name, model, nc, nlam):
    """A c x lam grid spec of the benchmark with ``model`` (nc x nlam configurations)."""
    path = Path(folder) / f"{name}.yaml"
    lines = ["bike: benchmark", f"model: {model}", "vary:",
             f"  c: {{from: 0.0, to: 0.2, num: {nc}}}", f"  lam: {{from: 0.1, to: 0.5, num: {nlam}}}"]
    path.write_text("\n".join(lines) + "\n")
    return path


def cpu_of(path, out):
    """CPU seconds of one ``bm.sweep`` of ``path`` into a fresh folder ``out``."""
    start = time.process_time()
    bm.sweep(path, out, restart=True)
    return time.process_time() - start


def marginal(folder, runs, repeat):
    """The marginal CPU cost (us a configuration) of each run ``(model, small, large, variant)``: a
    ``model`` sweep between grids ``small`` and ``large`` ((nc, nlam) each), ``variant`` a batch
    function put in place of the member path's (None: its own).  The runs alternate within each
    repeat, so that each sees the same load; the best of ``repeat`` of each size is taken."""
    paths = [[spec(folder, f"{model}-{nc}x{nl}", model, nc, nl) for nc, nl in (small, large)]
             for model, small, large, _ in runs]
    best = [[float("inf"), float("inf")] for _ in runs]
    own = members_module.batch_critical_speeds
    try:
        for _ in range(repeat):
            for j, (_, _, _, variant) in enumerate(runs):
                members_module.batch_critical_speeds = own if variant is None else variant
                for k, path in enumerate(paths[j]):
                    best[j][k] = min(best[j][k], cpu_of(path, Path(folder) / f"out-{path.stem}"))
    finally:
        members_module.batch_critical_speeds = own
    counts = [[nc * nl for nc, nl in (small, large)] for _, small, large, _ in runs]
    return [1e6 * (b[1] - b[0]) / (c[1] - c[0]) for b, c in zip(best, counts)]


def batch_at(revision):
    """``batch_critical_speeds`` of ``bikemass.analysis.engine.batch`` as it was at git ``revision``."""
    root = Path(__file__).resolve().parent.parent
    source = subprocess.run(["git", "-C", str(root), "show", f"{revision}:src/bikemass/analysis/engine/batch.py"],
                            check=True, capture_output=True, text=True).stdout
    name = "bikemass.analysis.engine._batch_at_" + "".join(c if c.isalnum() else "_" for c in revision)
    module = importlib.util.module_from_spec(importlib.util.spec_from_loader(name, loader=None))
    module.__package__ = "bikemass.analysis.engine"
    exec(compile(source, f"{revision}:batch.py", "exec"), module.__dict__)
    return module.batch_critical_speeds


def counting_reference():
    """Wrap the member path's reference so that its calls (undecided rows) are counted: ``[calls, CPU s]``."""
    calls = [0, 0.0]
    original = members_module.evaluate_member_batch

    def counted(scenario, changes, count, max_speed, reference):
        def ref(config):
            start = time.process_time()
            row = reference(config)
            calls[0] += 1
            calls[1] += time.process_time() - start
            return row
        return original(scenario, changes, count, max_speed, ref)
    members_module.evaluate_member_batch = counted
    return calls


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", default="tyre")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--before", action="store_true", help="also the one-by-one route of before")
    parser.add_argument("--against", metavar="REV", help="also the batch path of git revision REV, alternating")
    args = parser.parse_args()
    print(f"load average {os.getloadavg()[0]:.2f}")
    with tempfile.TemporaryDirectory() as folder:
        calls = counting_reference()
        small, large = (40, 50), (100, 200)
        runs = [("whipple", (100, 100), (200, 500), None), (args.model, small, large, None)]
        if args.against is not None:
            runs.append((args.model, small, large, batch_at(args.against)))
        whipple, *costs = marginal(folder, runs, args.repeat)
        member, count = costs[0], [small[0] * small[1], large[0] * large[1]]
        print(f"whipple: {whipple:.2f} us of CPU a configuration (marginal, 10,000 -> 100,000)")
        one_run = calls[0] / args.repeat / len(costs)
        print(f"{args.model}: {member:.2f} us of CPU a configuration (marginal, {count[0]:,} -> {count[1]:,}); "
              f"{one_run:.0f} of {count[0] + count[1]:,} rows a run through the engine, "
              f"{1e3 * calls[1] / max(calls[0], 1):.1f} ms each "
              f"({1e6 * calls[1] / args.repeat / len(costs) / sum(count):.1f} us a configuration on average)")
        print(f"ratio {args.model} / whipple: {member / whipple:.2f} (issue 32: at most 10)")
        if args.against is not None:
            print(f"{args.model} with the batch path of {args.against}: {costs[1]:.2f} us of CPU a configuration; "
                  f"ratio {costs[1] / whipple:.2f} to whipple; this one / {args.against}: {member / costs[1]:.2f}")
        if args.before:
            evaluate_module.evaluate_member_columns = _one_by_one
            before, count = marginal(folder, [(args.model, (5, 10), (10, 20), None)], 1)[0], [50, 200]
            print(f"{args.model} one by one (before): {before:.0f} us of CPU a configuration "
                  f"({count[0]} -> {count[1]}); ratio {before / whipple:.0f} to whipple, "
                  f"{before / member:.0f} to the batch path")


def _one_by_one(scenario, changes, count, max_speed, reference):
    """The route before the batch path: every configuration through the engine."""
    rows = [reference({k: v[i] for k, v in changes.items()}) for i in range(count)]
    values = {k: np.array([np.nan if r[k] is None else r[k] for r in rows], dtype=float)
              for k in evaluate_module.NUMBERS}
    return evaluate_module.Outcomes(values, [r["error"] for r in rows])


if __name__ == "__main__":
    main()
