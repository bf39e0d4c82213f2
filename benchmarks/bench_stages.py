"""Where one richer model's ``bm.stability`` spends its time, stage by stage, beside its floor (issue 37).

Run by hand:  python benchmarks/bench_stages.py  [model, default rider-lean]  [rounds, default 300]

The Jamis + Relaxed built as ``model`` (``flexible`` with steel).  Each stage is timed alone, process CPU
time, the mean of ``rounds`` calls (a stage includes the ones it calls, so the stages add to more than the
whole):

* the floor: LAPACK's eigenvalues at the 601 speeds of the default grid (``numpy.linalg.eigvals``);
* the grid's eigenvalues (``filled_values``: LAPACK at some of the speeds, Newton between them), and
  what LAPACK alone costs on as many speeds;
* the tracked sweep (those eigenvalues, the steps' check, eigenvectors where roots meet, their tracking);
* the modes followed and named (``follow_modes``);
* the exact crossings (``axis_crossings``: the polynomial eigenvalue problems and each candidate verified);
* the whole ``bm.stability``;

and the number of Python-level calls (functions, numpy's included) one ``bm.stability`` makes.
"""

import sys
import time
import warnings

import numpy as np

import bikemass as bm
from bikemass.analysis.engine import eigen
from bikemass.analysis.engine.crossings import Eigenvalues, axis_crossings
from bikemass.analysis.engine.modes import follow_modes
from bikemass.analysis.engine.speeds import speed_grid


def cpu(fn, rounds):
    fn()
    t0 = time.process_time()
    for _ in range(rounds):
        fn()
    return (time.process_time() - t0) / rounds


def lapack_rows(model, v):
    """How many speeds the fill hands to LAPACK (``_plain_values`` counted on one call)."""
    counted, real = [], eigen._plain_values

    def counting(A):
        counted.append(len(A))
        return real(A)
    eigen._plain_values = counting
    try:
        eigen.filled_values(model, v)
    finally:
        eigen._plain_values = real
    return sum(counted)


def python_calls(fn):
    """Python-level calls (``call`` and ``c_call`` events) of one ``fn()``."""
    count = [0]

    def profile(frame, event, arg):
        if event in ("call", "c_call"):
            count[0] += 1
    sys.setprofile(profile)
    try:
        fn()
    finally:
        sys.setprofile(None)
    return count[0]


def main(member="rider-lean", rounds=300):
    warnings.simplefilter("ignore", bm.BikemassWarning)
    built = bm.Scenario("jamis", "relaxed", "steel" if member == "flexible" else None, model=member).build()
    model, v = built.model, speed_grid()
    rows = lapack_rows(model, v)
    stages = [
        ("floor: LAPACK eigenvalues at the 601 speeds", lambda: np.linalg.eigvals(model.dynamic_matrix(v))),
        (f"LAPACK alone at the fill's {rows} speeds", lambda: np.linalg.eigvals(model.dynamic_matrix(v[:rows]))),
        ("the grid's eigenvalues (filled_values)", lambda: eigen.filled_values(model, v)),
        ("the tracked sweep (tracked_sweep)", lambda: eigen.tracked_sweep(model, v, [0])),
        ("the modes followed and named (follow_modes)", lambda: follow_modes(model, v)),
        ("the exact crossings (axis_crossings)", lambda: axis_crossings(model, 0.0, 30.0, Eigenvalues(model))),
        ("the whole bm.stability", lambda: bm.stability(built)),
    ]
    import os
    print(f"Jamis + Relaxed, model {model.name} ({model.n_dynamic} states); mean of {rounds} calls, process CPU "
          f"time; load {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    for name, fn in stages:
        print(f"{name:50s} {cpu(fn, rounds) * 1e3:8.3f} ms")
    print(f"{'Python-level calls of one bm.stability':50s} {python_calls(lambda: bm.stability(built)):8d}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "rider-lean", int(sys.argv[2]) if len(sys.argv) > 2 else 300)
