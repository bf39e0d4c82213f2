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

and the number of Python-level calls (functions, numpy's included) one ``bm.stability`` makes.  Then the
least any continuation of this kind spends in numpy, each piece timed alone: LAPACK at every
``FILL_EVERY``-th speed, ``FILL_ITERATIONS`` Newton steps by Horner's rule for every root at every other
speed (one (q, m) array operation per term), the distances to the nearest other root and each step's
nearest successor over the whole grid; their sum beside the floor is what is left of the floor for
everything else (the steps where roots meet, the naming, the exact crossings, the ranges).
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


def continuation_pieces(model, v):
    """``[(name, function)]``: the pieces every continuation of the grid between LAPACK speeds needs
    (see the module docstring), each on the grid's own eigenvalues."""
    n = len(v)
    nodes = np.unique(np.r_[np.arange(0, n, eigen.FILL_EVERY), n - 1])
    between = np.setdiff1d(np.arange(n), nodes)
    values = eigen._plain_values(model.dynamic_matrix(v))
    width = model.n_dynamic * (len(model.speed_pieces[0][2].dynamic_coefficients) - 1) + 1
    c = eigen.interpolation_matrix(v[nodes], v[between], width) @ eigen._poly_from_roots(values[nodes])
    columns = [c[:, j:j + 1].astype(complex) for j in range(c.shape[1])]
    start = values[between] * (1 + 1e-3)

    def newton():
        s = start.copy()
        p, dp = np.empty(s.shape, dtype=complex), np.empty(s.shape, dtype=complex)
        for _ in range(eigen.FILL_ITERATIONS):
            p[...], dp[...] = columns[0], 0.0
            for column in columns[1:]:
                dp *= s
                dp += p
                p *= s
                p += column
            s -= p / dp
        return s
    sep = eigen._nearest_other(values)
    return [(f"LAPACK at every {eigen.FILL_EVERY}th speed ({len(nodes)})",
             lambda: eigen._plain_values(model.dynamic_matrix(v[nodes]))),
            (f"{eigen.FILL_ITERATIONS} Newton steps at the other {len(between)}", newton),
            ("nearest other root at every speed", lambda: eigen._nearest_other(values)),
            ("nearest successor of every step", lambda: eigen.nearest_steps(values, sep=sep))]


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
    floor = cpu(stages[0][1], rounds)
    print("the least a continuation spends in numpy, piece by piece:")
    least = 0.0
    for name, fn in continuation_pieces(model, v):
        t = cpu(fn, rounds)
        least += t
        print(f"  {name:48s} {t * 1e3:8.3f} ms")
    print(f"  {'their sum':48s} {least * 1e3:8.3f} ms ({least / floor:.2f} of the floor; "
          f"{(floor - least) * 1e3:.3f} ms left for the rest)")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "rider-lean", int(sys.argv[2]) if len(sys.argv) > 2 else 300)
