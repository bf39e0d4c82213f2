"""Time each member of the model family at one speed, beside a floor and a peer, in one run.

Run by hand:  python benchmarks/bench_models.py
"One evaluation" is what an analysis pays per configuration: the generated code at the parameters,
the state-space form (E^-1 A) and A(v) at one speed.  Beside it: models/whipple.py (the closed form of
Meijaard's Appendix A: the floor for the Whipple member) and BicycleParameters'
``form_state_space_matrices`` (Meijaard2007Model; MooreRiderLean2012Model, Moore's generated code,
for the leaning rider).  Then one call on 10 000 configurations (arrays), per configuration.
Best of several repeats; ratios are peer / bikemass.
"""

import timeit

import numpy as np

from bikemass.scenario.scenario import parameters
from bikemass.models.family import build, state_coefficients, values
from bikemass.models.moore2012 import from_moore_values
from bikemass.models.whipple import whipple_model

SPEED = 5.0


def best(fn, number=200):
    return min(timeit.repeat(fn, number=number, repeat=7)) / number


def main():
    from bicycleparameters.models import Meijaard2007Model, MooreRiderLean2012Model
    from bicycleparameters.parameter_dicts import mooreriderlean2012_browser_jason
    from bicycleparameters.parameter_sets import Meijaard2007ParameterSet, MooreRiderLean2012ParameterSet

    p = parameters("benchmark")
    lean = from_moore_values(mooreriderlean2012_browser_jason)
    whipple_peer = Meijaard2007Model(Meijaard2007ParameterSet({**p.to_dict(), "v": SPEED}, True))
    lean_peer = MooreRiderLean2012Model(MooreRiderLean2012ParameterSet(dict(mooreriderlean2012_browser_jason)))

    def ours(model, params):
        return lambda: build(model, params).state_matrix(SPEED)

    rows = [
        ("whipple", ours("whipple", p), [("models/whipple.py (closed form)", lambda: whipple_model(p).state_matrix(SPEED)),
                                         ("BicycleParameters Meijaard2007Model", lambda: whipple_peer.form_state_space_matrices(v=SPEED))]),
        ("rider-lean", ours("rider-lean", lean), [("BicycleParameters MooreRiderLean2012Model",
                                                   lambda: lean_peer.form_state_space_matrices(v=SPEED))]),
        ("tyre", ours("tyre", p), []),
        ("rider-lean+tyre", ours("rider-lean+tyre", lean), []),
    ]
    times = {name: best(fn) for name, fn, _ in rows}
    floor = times["whipple"]
    print(f"one configuration at {SPEED} m/s: build the model and A(v)")
    print(f"{'member':18s} {'bikemass':>10s}   {'x whipple':>9s}   beside (peer time, ratio peer / bikemass)")
    for name, _, peers in rows:
        t = times[name]
        beside = "; ".join(f"{label} {tp * 1e6:.0f} us ({tp / t:.2f})"
                           for label, tp in ((label, best(peer)) for label, peer in peers))
        print(f"{name:18s} {t * 1e6:8.0f}us   {t / floor:9.2f}   {beside}")
    n = 10_000
    rng = np.random.default_rng(1)
    batch = {k: v * rng.uniform(0.9, 1.1, n) for k, v in values("whipple", p).items()}
    per = best(lambda: state_coefficients("whipple", batch), number=3) / n
    print(f"whipple, {n} configurations in one call (arrays): {per * 1e6:.2f} us per configuration "
          f"({floor / per:.0f}x faster than one at a time)")


if __name__ == "__main__":
    main()
