"""Time a 601-speed sweep (0..30 m/s, step 0.05) of the benchmark bicycle: bikemass vs BicycleParameters.

Run by hand:  python benchmarks/bench_stability.py
Both libraries run in this process on the same parameters; best of several repeats.
The last line is the whole stability analysis (tracked and named modes, every crossing of
Re = 0 found exactly, exact and grid ranges, strict and marginal: the marginal and per-mode ranges
are made when first read, so they are read here) against
BicycleParameters' ``Bicycle.eig`` at the same 601 speeds (issue 14 asks for <= 0.25).
Then the same analysis with the machine's default BLAS pool and on one BLAS thread
(issue 10: does the stability core gain from :func:`bikemass.core.threads.one_blas_thread`?).
"""

import tempfile
import timeit
from pathlib import Path

import numpy as np

from bikemass.scenario.scenario import parameters
from bikemass.models.parameter_export import format_parameters
from bikemass.analysis.engine.eigen import eigen_sweep
from bikemass.analysis.engine.modes import follow_modes
from bikemass.analysis.engine.stability import analyse
from bikemass.analysis.engine.speeds import speed_grid
from bikemass.models.whipple import whipple_model


def best(fn, number):
    return min(timeit.repeat(fn, number=number, repeat=7)) / number


def main():
    from bicycleparameters.models import Meijaard2007Model, sort_eigenmodes
    from bicycleparameters.parameter_sets import Meijaard2007ParameterSet

    p = parameters("benchmark")
    speeds = speed_grid()                       # 601 speeds
    peer = Meijaard2007Model(Meijaard2007ParameterSet({**p.to_dict(), "v": 0.0}, True))

    def ours_eig():
        return eigen_sweep(whipple_model(p), speeds)

    def ours_tracked():
        return follow_modes(whipple_model(p), speeds)

    def peer_eig():
        return peer.calc_eigen(v=speeds)

    def peer_tracked():
        return sort_eigenmodes(*peer.calc_eigen(v=speeds))

    # same numbers first
    ref = np.sort_complex(np.round(peer_eig()[0], 9))
    got = np.sort_complex(np.round(ours_eig().eigenvalues, 9))
    assert np.allclose(got, ref, atol=1e-8), "eigenvalues differ"

    rows = [("eigenvalues + eigenvectors", best(ours_eig, 50), best(peer_eig, 10)),
            ("... + modes tracked (and labelled)", best(ours_tracked, 50), best(peer_tracked, 5))]
    print(f"601-speed sweep, benchmark bicycle ({len(speeds)} speeds)")
    print(f"{'':38s} {'bikemass':>10s} {'BicycleParameters':>18s} {'ratio':>7s}")
    for name, ours, theirs in rows:
        print(f"{name:38s} {ours * 1e3:8.2f}ms {theirs * 1e3:16.2f}ms {theirs / ours:6.1f}x")
    full, eig = map(min, interleaved(lambda: _api_stability(p), _bicycle_eig(p, speeds), rounds=15))
    print(f"full stability analysis (crossings, exact + grid ranges): {full * 1e3:.2f} ms; "
          f"BicycleParameters Bicycle.eig, 601 speeds: {eig * 1e3:.2f} ms; ratio {full / eig:.3f}")
    default, one = interleaved(lambda: _api_stability(p), lambda: _one_thread(_api_stability, p), rounds=30)
    print(f"full stability analysis, default BLAS pool vs one thread (30 rounds, median / max): "
          f"{np.median(default) * 1e3:.2f} / {max(default) * 1e3:.2f} ms vs "
          f"{np.median(one) * 1e3:.2f} / {max(one) * 1e3:.2f} ms; ratio {np.median(default) / np.median(one):.2f}")


def _api_stability(p):
    """``bm.stability(params)``: the model built and analysed, every range read (the marginal and
    per-mode ranges are made when first read)."""
    result = analyse(whipple_model(p))
    result.ranges["marginal"]["exact"], result.mode_ranges["capsize"]
    return result


def _bicycle_eig(p, speeds):
    """BicycleParameters' ``Bicycle`` read from the bikemass export of ``p``: its ``eig`` at ``speeds``."""
    import contextlib
    import io
    import warnings

    from bicycleparameters import Bicycle
    folder = Path(tempfile.mkdtemp()) / "bicycles" / "Benchmark" / "Parameters"
    folder.mkdir(parents=True)
    (folder / "BenchmarkBenchmark.txt").write_text(format_parameters(p, "bicycleparameters"))
    with contextlib.redirect_stdout(io.StringIO()), warnings.catch_warnings():
        warnings.simplefilter("ignore")
        bike = Bicycle("Benchmark", pathToData=str(folder.parents[2]))
    return lambda: bike.eig(speeds)


def _one_thread(fn, *args):
    from bikemass.core.threads import one_blas_thread
    with one_blas_thread():
        return fn(*args)


def interleaved(a, b, rounds):
    """Times (s) of ``a`` and ``b``, run alternately (a shared machine's load hits both alike)."""
    ta, tb = [], []
    for _ in range(rounds):
        ta.append(timeit.timeit(a, number=1))
        tb.append(timeit.timeit(b, number=1))
    return ta, tb


if __name__ == "__main__":
    main()
