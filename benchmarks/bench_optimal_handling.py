"""The optimal handling bicycles of Moore, Hubbard & Hess (2016, BMD, "An optimal handling bicycle") found
again by ``bm.optimise`` from the benchmark, each beside the published design scored by the same code.

Run by hand (never in CI; about a minute a speed):  python benchmarks/bench_optimal_handling.py [--speeds 4,5]

For each design speed: the published optimum (the paper's Table 2, printed to 3 decimals; 5 m/s: its
parameter file in tests/data/handling) scored by bikemass (the rider's gains by ``tuning: bmd2016``, the HQM
peak, the closed loop's largest real part), then the minimum of the HQM peak over c, w, lam, rF found by
``bm.optimise`` from the benchmark (the paper's variables; its bounds closed to a box: c in [-0.5, 0.5] m,
w in [0.327, 2] m (the paper's lower bound: the rear frame's and front assembly's centre of mass over the
rear contact), lam in [-1.5, 1.5] rad, rF in [0.03, 1] m), the closed loop held stable.
"""

import argparse
import tempfile
import time
import warnings
from pathlib import Path

import yaml

import bikemass as bm

TABLE_2 = {2.0: (0.328, 0.327, 0.524, 0.331), 4.0: (-0.206, 1.103, 0.265, 0.477),
           6.0: (0.026, 0.817, 0.058, 0.037), 8.0: (0.202, 0.993, 0.207, 0.080),
           10.0: (-0.124, 0.876, 0.127, 0.490)}
"""Moore, Hubbard & Hess (2016), Table 2: the optimal c, w, lam, rF (m, m, rad, m) for each design speed."""
OPTIMAL05 = Path(__file__).parents[1] / "tests" / "data" / "handling" / "Optimal05Benchmark.txt"
BOX = {"c": (-0.5, 0.5), "w": (0.327, 2.0), "lam": (-1.5, 1.5), "rF": (0.03, 1.0)}


def score(params, speed):
    """(HQM peak, closed loop's largest real part) with the bmd2016 gains."""
    result = bm.handling(params, [speed], tuning="bmd2016")
    return result.hqm_peak[0], result.max_real[0] if hasattr(result, "max_real") else float("nan")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--speeds", default="2,4,5,6,8,10")
    speeds = [float(s) for s in parser.parse_args().speeds.split(",")]
    warnings.simplefilter("ignore", bm.BikemassWarning)
    benchmark = bm.parameters("benchmark")
    folder = Path(tempfile.mkdtemp())
    print("speed  design      c (m)   w (m)  lam (rad)  rF (m)   HQM peak  max Re (1/s)  note")
    for v in speeds:
        if v == 5.0:
            published = bm.load_parameter_text(OPTIMAL05).parameters
        else:
            c, w, lam, rF = TABLE_2[v]
            published = benchmark.replace(c=c, w=w, lam=lam, rF=rF)
        peak, real = score(published, v)
        print(f"{v:5.1f}  published {published.c:8.3f} {published.w:7.3f} {published.lam:10.3f} {published.rF:7.3f}"
              f"  {peak:9.4f}  {real:12.4f}")
        spec = folder / f"spec{v:g}.yaml"
        spec.write_text(yaml.safe_dump({"bike": "benchmark", "speed": v, "tuning": "bmd2016", "minimise": "hqm-peak",
                                        "variables": {k: {"min": lo, "max": hi} for k, (lo, hi) in BOX.items()}}))
        start = time.perf_counter()
        result = bm.optimise(spec)
        seconds = time.perf_counter() - start
        x = result.variables
        print(f"{v:5.1f}  bikemass  {x['c']:8.3f} {x['w']:7.3f} {x['lam']:10.3f} {x['rF']:7.3f}  {result.objective:9.4f}"
              f"  {result.metrics['closed-loop-real']:12.4f}  {result.evaluations} designs, {seconds:.0f} s, "
              f"converged {result.converged}", flush=True)


if __name__ == "__main__":
    main()
