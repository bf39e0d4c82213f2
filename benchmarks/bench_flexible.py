"""Time the flexible member at one speed beside a floor, in one run.

Run by hand:  python benchmarks/bench_flexible.py
"One evaluation" is what an analysis pays per configuration: the generated code at the parameters, the
state-space form (E^-1 A) and A(v) at one speed, for the Jamis with the Relaxed rider and a steel frame
and fork.  The floor: the rigid bicycle's closed form (models/whipple.py, Meijaard's Appendix A) and the
derived Whipple member.  Beside them the flexible member's combinations, and the beam models' reduction
(compliances(bike, material): once per bicycle and material, not per speed).  Best of several repeats;
ratios are the flexible member's time over the floor's.
"""

import timeit

import bikemass as bm
from bikemass.models.family import build
from bikemass.fe.flexible import compliances
from bikemass.rider.lean_split import rider_lean_parameters
from bikemass.models.whipple import whipple_model

SPEED = 8.0


def best(fn, number=200):
    return min(timeit.repeat(fn, number=number, repeat=7)) / number


def main():
    bike = bm.load_bicycle("jamis")
    params = bm.parameters(bike, bm.load_rider("relaxed"))
    lean = rider_lean_parameters(bike, bm.seated_rider(bike, "relaxed"))
    steel = compliances(bike, "steel")
    floors = {"models/whipple.py (closed form)": lambda: whipple_model(params).state_matrix(SPEED),
              "whipple (derived member)": lambda: build("whipple", params).state_matrix(SPEED)}
    members = {"flexible": lambda: build("flexible", params, compliances=steel).state_matrix(SPEED),
               "tyre+flexible": lambda: build("tyre+flexible", params, compliances=steel).state_matrix(SPEED),
               "rider-lean+tyre+flexible": lambda: build("rider-lean+tyre+flexible", lean,
                                                         compliances=steel).state_matrix(SPEED)}
    floor_times = {name: best(fn) for name, fn in floors.items()}
    floor = floor_times["models/whipple.py (closed form)"]
    print(f"one configuration at {SPEED} m/s (Jamis, Relaxed, steel): build the model and A(v)")
    print(f"{'model':34s} {'time':>9s}   {'/ closed form':>13s}")
    for name, t in floor_times.items():
        print(f"{name:34s} {t * 1e6:7.0f}us   {t / floor:13.2f}")
    for name, fn in members.items():
        t = best(fn)
        print(f"{name:34s} {t * 1e6:7.0f}us   {t / floor:13.2f}")
    reduction = best(lambda: compliances(bike, "steel"), number=5)
    print(f"the reduction, compliances(jamis, steel): {reduction * 1e3:.1f} ms once per bicycle and material "
          f"({reduction / floor:.0f} x the closed form)")


if __name__ == "__main__":
    main()
