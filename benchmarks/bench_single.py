"""One configuration, fast: each row times bikemass beside its peer or floor in this process,
alternately (a shared machine's load hits both alike), and prints the ratio (issue 37).

Run by hand:  python benchmarks/bench_single.py  [rounds, default 15]  [members: only the richer members' rows;
stability: only ``bm.stability(p)``'s two rows]

Rows (median of the rounds, process CPU time, so that other processes' load counts less):

* one Whipple configuration's exact critical speeds (``whipple_critical_speeds``: the scalar fast
  path, from the parameters) / one 4 x 4 ``numpy.linalg.eigvals`` (target <= 5);
* its matrices ``M, C1, K0, K2`` in Python floats from the generated model family's code (the run-time
  path, ``models.whipple_generated``) / from the hand-written closed form of Meijaard et al. (2007),
  Appendix A (``models.canonical``, kept as the test oracle), no target;
* ``bm.stability(p)`` (the whole analysis on the 601-speed grid; the marginal and per-mode ranges are
  made when first read) / BicycleParameters' ``Bicycle.eig`` at the same 601 speeds (target <= 0.1);
  and the same with those ranges read (``ranges["marginal"]``, ``mode_ranges``), no target;
* ``bm.sensitivity(p)`` (26 exact derivatives of both speeds) / BicycleParameters' central differences:
  for each of the 26 parameters, ``Meijaard2007Model.calc_eigen`` at the 601 speeds on either side of a
  relative step of 1e-6 and the speeds where the largest real part changes sign, interpolated on the
  grid (target <= 0.003);
* ``bm.simulate`` 10 s in 0.01 s from a roll rate / the floor: one ``numpy.linalg.eig`` of the same
  4 x 4 dynamic A and ``V exp(L t) V^-1 x0`` at all 1,001 samples at once;
* ``bm.stability`` of the Jamis + Relaxed as rider-lean, tyre and flexible (steel) members (the whole
  analysis) / a plain loop over the same model: LAPACK eigenvalues at the 601 speeds at once, then
  ``brentq`` on the largest real part in every grid cell where its sign changes (target <= 1);
* ``bm.uncertainty`` by Monte Carlo (200 draws of the benchmark's trail and rear mass, the draws'
  modes followed at once) per draw / BicycleParameters' loop per draw (a model of each draw, its
  eigenvalues at the same 101 speeds and its mode sorting).
"""

import sys
import time

import numpy as np

import bikemass as bm
try:
    from bikemass.analysis.engine.critical import whipple_critical_speeds
except ImportError:                     # before issue 37 (to time main the same way): the model's path
    from bikemass.analysis.engine.critical import critical_speeds
    from bikemass.models.whipple import whipple_model

    def whipple_critical_speeds(p):
        return critical_speeds(whipple_model(p))
from bikemass.analysis.engine.speeds import speed_grid
from bikemass.models.parameters import NAMES


def cpu(fn, repeat):
    t0 = time.process_time()
    for _ in range(repeat):
        fn()
    return (time.process_time() - t0) / repeat


def alternately(a, b, rounds, repeat_a, repeat_b):
    ta, tb = [], []
    for _ in range(rounds):
        ta.append(cpu(a, repeat_a))
        tb.append(cpu(b, repeat_b))
    return float(np.median(ta)), float(np.median(tb))


def bicycle_eig(p, speeds):
    """BicycleParameters' ``Bicycle.eig`` at ``speeds`` of the benchmark bicycle (its own data)."""
    sys.path.insert(0, str(__import__("pathlib").Path(__file__).parent))
    from bench_stability import _bicycle_eig
    return _bicycle_eig(p, speeds)


def peer_sensitivity(p, speeds, rel=1e-6):
    """Central differences of BicycleParameters' eigenvalues: weave and capsize speeds by sign changes
    of the largest real part on the grid (linear interpolation), two models per parameter."""
    from bicycleparameters.models import Meijaard2007Model
    from bicycleparameters.parameter_sets import Meijaard2007ParameterSet
    base = {**p.to_dict(), "v": 0.0}

    def crossings(values):
        model = Meijaard2007Model(Meijaard2007ParameterSet(values, True))
        evals, _ = model.calc_eigen(v=speeds)
        top = evals.real.max(axis=1)
        down = np.flatnonzero((top[:-1] > 0) & (top[1:] <= 0))
        up = np.flatnonzero((top[:-1] <= 0) & (top[1:] > 0))
        at = lambda i: speeds[i] + (speeds[i + 1] - speeds[i]) * top[i] / (top[i] - top[i + 1])   # noqa: E731
        return (at(down[0]) if len(down) else np.nan, at(up[0]) if len(up) else np.nan)

    def run():
        out = {}
        for name in NAMES:
            if name == "g":
                continue
            h = rel * (abs(base[name]) or 1.0)
            hi, lo = crossings({**base, name: base[name] + h}), crossings({**base, name: base[name] - h})
            out[name] = [(a - b) / (2 * h) for a, b in zip(hi, lo)]
        return out
    return run


def plain_loop(model, speeds):
    """The plain analysis a user would write: eigenvalues at every speed, brentq on the largest real part."""
    from scipy.optimize import brentq

    def top(x):
        return np.linalg.eigvals(model.dynamic_matrix([x])[0]).real.max()

    def run():
        largest = np.linalg.eigvals(model.dynamic_matrix(speeds)).real.max(axis=1)
        cells = np.flatnonzero(np.sign(largest[:-1]) != np.sign(largest[1:]))
        return [brentq(top, speeds[i], speeds[i + 1]) for i in cells]
    return run


def peer_draws(p, speeds, draws):
    """BicycleParameters' loop: a Meijaard2007Model of each draw (c and mB drawn) and its eigenvalues at
    the band speeds, with its own mode sorting."""
    from bicycleparameters.models import Meijaard2007Model, sort_eigenmodes
    from bicycleparameters.parameter_sets import Meijaard2007ParameterSet
    rng = np.random.default_rng(0)
    base = {**p.to_dict(), "v": 0.0}

    def run():
        for c, mB in zip(base["c"] + 0.002 * rng.normal(size=draws), base["mB"] + rng.normal(size=draws)):
            model = Meijaard2007Model(Meijaard2007ParameterSet({**base, "c": c, "mB": mB}, True))
            sort_eigenmodes(*model.calc_eigen(v=speeds))
    return run


def main(rounds=15, only=None):
    import os
    print(f"one configuration, median of {rounds} alternate rounds (process CPU time); load "
          f"{os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    speeds = speed_grid()
    rows = []
    if only == "stability":
        stability_rows(rows, rounds, speeds)
    else:
        if only != "members":
            whipple_rows(rows, rounds, speeds)
        member_rows(rows, rounds, speeds)

    print(f"{'measure':45s} {'bikemass':>10s}  {'peer / floor':40s} {'':>10s} {'ratio':>8s}  target")
    for name, a, peer_name, b, target in rows:
        verdict = "" if target is None else f"<= {target:g} ({'met' if a / b <= target else 'MISSED'})"
        print(f"{name:45s} {a * 1e3:8.3f}ms  {peer_name:40s} {b * 1e3:8.3f}ms {a / b:8.4f}  {verdict}")


def member_rows(rows, rounds, speeds):
    """The richer members' rows: ``bm.stability`` of a built scenario / the plain loop over its model."""
    for member in ("rider-lean", "tyre", "flexible"):
        built = bm.Scenario("jamis", "relaxed", "steel" if member == "flexible" else None, model=member).build()
        ours, plain = alternately(lambda built=built: bm.stability(built), plain_loop(built.model, speeds),
                                  max(3, rounds // 3), 2, 2)
        rows.append((f"bm.stability, Jamis + Relaxed, {member}", ours, "601-speed eigvals + brentq loop", plain, 1.0))


def stability_rows(rows, rounds, speeds):
    """``bm.stability`` of the benchmark bicycle (and with every range read) / BicycleParameters."""
    p = bm.parameters("benchmark")
    eig = bicycle_eig(p, speeds)
    ours, peer = alternately(lambda: bm.stability(p), eig, rounds, 4, 1)
    rows.append(("bm.stability(p), 601 speeds", ours, "BicycleParameters Bicycle.eig", peer, 0.1))

    def every_range():
        result = bm.stability(p)
        return result.ranges["marginal"]["exact"], result.mode_ranges["capsize"]
    ours, peer = alternately(every_range, eig, rounds, 4, 1)
    rows.append(("bm.stability(p), every range read", ours, "BicycleParameters Bicycle.eig", peer, None))


def whipple_rows(rows, rounds, speeds):
    """The Whipple bicycle's rows (one configuration, sensitivity, simulation, Monte Carlo)."""
    p = bm.parameters("benchmark")
    model = bm.linear_model(p)
    A4 = model.state_matrix(5.0)[:4, :4]

    ours, floor = alternately(lambda: whipple_critical_speeds(p), lambda: np.linalg.eigvals(A4), rounds, 300, 300)
    rows.append(("one Whipple configuration's critical speeds", ours, "one 4x4 eigvals", floor, 5.0))

    from bikemass.models.canonical import canonical_entries
    from bikemass.models.whipple_generated import second_order_entries
    ours, oracle = alternately(lambda: second_order_entries(p), lambda: canonical_entries(p), rounds, 1000, 1000)
    rows.append(("Whipple M, C1, K0, K2 (generated code)", ours, "hand-written closed form (test oracle)", oracle,
                 None))

    stability_rows(rows, rounds, speeds)

    peer_run = peer_sensitivity(p, speeds)
    ours, peer = alternately(lambda: bm.sensitivity(p), peer_run, max(3, rounds // 5), 50, 1)
    rows.append(("bm.sensitivity(p), 25 parameters", ours, "BicycleParameters central differences", peer, 0.003))

    t = 0.01 * np.arange(1001)
    x0 = np.array([0.0, 0.0, 0.5, 0.0])

    A46 = model.state_matrix(4.6)[:4, :4]

    def eig_floor():
        w, V = np.linalg.eig(A46)
        return (V @ (np.exp(np.outer(w, t)) * np.linalg.solve(V, x0)[:, None])).real
    ours, floor = alternately(lambda: bm.simulate(p, 4.6, {"roll-rate": 0.5}, duration=10.0), eig_floor,
                              rounds, 20, 20)
    rows.append(("bm.simulate 10 s, 1001 samples", ours, "vectorised eigen-decomposition", floor, None))

    scenario, spreads = bm.Scenario("benchmark"), {"c": 0.002, "mB": 1.0}
    draws = 200
    bands = np.linspace(0.0, 10.0, 101)
    ours, peer = alternately(lambda: bm.uncertainty(scenario, spreads, method="montecarlo", samples=draws),
                             peer_draws(p, bands, draws), max(3, rounds // 5), 1, 1)
    rows.append(("Monte Carlo, 200 draws (bands on 101 speeds)", ours / draws, "BicycleParameters loop, per draw",
                 peer / draws, None))


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 15, sys.argv[2] if len(sys.argv) > 2 else None)
