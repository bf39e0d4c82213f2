"""What seating a rider on a bicycle costs: bikemass's body builders and chain seating against
yeadon building the same measured rider, in the same process.

Run by hand (never in CI):  python benchmarks/bench_seating.py [--repeat N]

Prints best-of-N wall times (s) and their ratio to yeadon building a Human from Jason's
95 measurements (tests/data/yeadon):
1. a placement pose loaded without a bicycle (the thesis's Relaxed, as written);
2. the same pose seated on the Cargo (contacts measured, posture re-solved by least squares);
3. a height/mass body built (the body cache cleared first), and seated on the Jamis by the chain
   (hands on the hoods);
4. Jason's yeadon body built by bikemass (uncached: both the yeadon Human cache and the body
   cache cleared first; with only the Human's cleared the body cache answered, 0.00 ms), and
   seated on the Jamis (both cached, as when a pose is read again).
"""

import argparse
import contextlib
import io
from pathlib import Path

from bench_riders import best_time          # the sibling script (run from benchmarks/ or by path)

from bikemass.bicycle import load_bicycle
from bikemass.core.config import Node
from bikemass.rider import load_rider
from bikemass.rider.body import _BODIES, load_body
from bikemass.rider.seating import seat_rider
from bikemass.rider.yeadon_body import _human_of

JASON = Path(__file__).parents[1] / "tests" / "data" / "yeadon" / "JasonYeadonMeas.txt"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    repeat = parser.parse_args().repeat
    import yeadon

    jamis, cargo = load_bicycle("jamis"), load_bicycle("cargo")
    person = {"body": {"height": 1.80, "mass": 75.0, "sex": "male"}, "chain": {"hands": "hoods"}}
    jason = {"body": {"yeadon": str(JASON)}, "chain": {"hands": "hoods"}}

    def peer():
        with contextlib.redirect_stdout(io.StringIO()):
            yeadon.Human(str(JASON))

    cases = [
        ("yeadon.Human(Jason) (peer)", peer),
        ("relaxed, no bicycle", lambda: load_rider("relaxed")),
        ("relaxed seated on the Cargo", lambda: seat_rider("relaxed", cargo)),
        ("height/mass body built (uncached)", lambda: (_BODIES.clear(),
                                                        load_body(Node(person["body"], "bench.yaml", "body")))),
        ("height/mass body seated on the Jamis", lambda: seat_rider(person, jamis)),
        ("Jason's yeadon body built (uncached)", lambda: (_human_of.cache_clear(), _BODIES.clear(),
                                                          load_body(Node(jason["body"], "bench.yaml", "body")))),
        ("Jason seated on the Jamis", lambda: seat_rider(jason, jamis)),
    ]
    times = [(name, best_time(fn, repeat)) for name, fn in cases]
    reference = times[0][1]
    print(f"best of {repeat}; ratio = time / yeadon building Jason")
    for name, t in times:
        print(f"{name:40s} {t * 1000:9.2f} ms   {t / reference:7.2f}")


if __name__ == "__main__":
    main()
