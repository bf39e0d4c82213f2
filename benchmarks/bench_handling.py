"""Time the handling analyses of issue 24 against BicycleParameters and scipy in one run.

Run by hand:  python benchmarks/bench_handling.py
Best of several repeats, every library in this process on the same parameter file (the benchmark
bicycle as BicycleParameters ships it).

* A Bode curve of 1000 frequencies: ``bm.frequency_response`` (model built from the parameters,
  then the response), alone and with its figure, against BicycleParameters' ``Bicycle.plot_bode``
  (its ``state_space`` and dtk's ``bode``, which inverts ``j w I - A`` at each frequency and
  draws the figure: its data path cannot be had without the figure).
* A transfer function: ``bm.transfer_function`` against ``scipy.signal.ss2zpk`` on the same
  matrices (polynomial numerator and denominator, then their roots).
* The rider's gains at one speed (the published procedure, 5 m/s) and the whole ``bm.handling``
  at one speed (gains, closed loop, HQM peak), against nothing: HumanControl is MATLAB/Simulink.

Issue 24 asks for each of the three to cost well under a second.
"""

import contextlib
import io
import timeit
import warnings
from pathlib import Path

import numpy as np


def best(fn, number=1, repeat=7):
    return min(timeit.repeat(fn, number=number, repeat=repeat)) / number


def main():
    import matplotlib
    matplotlib.use("agg")                  # BicycleParameters draws with pyplot
    import bicycleparameters as bp
    import scipy.signal

    import bikemass as bm
    from bikemass.analysis.handling.rider import rider_plant
    from bikemass.analysis.handling.tuning import tune_gains
    from bikemass.models.whipple import whipple_model

    data = Path(bp.__file__).parent / "app-data"
    params = bm.load_parameter_text(data / "bicycles" / "Benchmark" / "Parameters" / "BenchmarkBenchmark.txt").parameters
    with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
        warnings.simplefilter("ignore")
        bike = bp.Bicycle("Benchmark", pathToData=str(data))
    w = np.logspace(0, 2, 1000)
    speed = 5.0

    def ours_bode():
        return bm.frequency_response(params, speed, "steer-torque", "roll-angle", w)

    def ours_bode_figure():
        return bm.plot_bode(ours_bode())

    def peer_bode():
        import matplotlib.pyplot as plt
        magnitude, phase, fig = bike.plot_bode(speed, 1, 0)
        plt.close(fig)
        return magnitude, phase

    magnitude, phase = peer_bode()
    assert np.abs(ours_bode().magnitude - magnitude).max() < 1e-6, "Bode magnitudes differ"

    model = whipple_model(params)
    A, B, C, D = model.state_space(speed, ["steer-angle"])

    def ours_tf():
        return bm.transfer_function(params, speed, "steer-torque", "steer-angle")

    def peer_tf():
        return scipy.signal.ss2zpk(A[:4, :4], B[:4, 1:2], C[:, :4], D[:, 1:2])

    z, p, k = peer_tf()
    assert np.allclose(np.sort_complex(z), ours_tf().zeros, rtol=1e-6), "zeros differ"

    plant = rider_plant(model, speed)
    rows = [("Bode curve, 1000 frequencies", best(ours_bode, 20), best(peer_bode, 3), "Bicycle.plot_bode"),
            ("... with its figure (not rendered)", best(ours_bode_figure, 5), best(peer_bode, 3), "Bicycle.plot_bode"),
            ("transfer function (zeros, poles, gain)", best(ours_tf, 50), best(peer_tf, 200), "scipy ss2zpk")]
    print(f"benchmark bicycle at {speed:g} m/s, steer torque in")
    print(f"{'':40s} {'bikemass':>10s} {'peer':>10s} {'peer/bikemass':>14s}  peer")
    for name, ours, theirs, peer in rows:
        print(f"{name:40s} {ours * 1e3:8.2f}ms {theirs * 1e3:8.2f}ms {theirs / ours:13.2f}x  {peer}")
    gains = best(lambda: tune_gains(plant), 1, 5)
    survey = best(lambda: bm.handling(params, [speed]), 1, 5)
    print(f"{'rider gains, one speed (published procedure)':40s} {gains * 1e3:8.2f}ms")
    print(f"{'bm.handling, one speed (+ closed loop, HQM)':40s} {survey * 1e3:8.2f}ms")
    slowest = max(rows[0][1], rows[2][1], gains)
    print(f"slowest of the three asked for: {slowest * 1e3:.1f} ms = {slowest:.3f} of a second")


if __name__ == "__main__":
    main()
