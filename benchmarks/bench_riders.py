"""Time to build and evaluate the five thesis riders, against yeadon building a Human.

Run by hand (never in CI):  python benchmarks/bench_riders.py [--repeat N]

Prints
1. the best-of-N wall time to load and evaluate all five riders (mesh and exact),
   and yeadon (peer, same process) building a 40-solid Human from 95 measurements;
2. mesh vs exact agreement of every solid type at the default resolution,
   placed at random positions and rotations: relative error of mass and volume,
   and the largest inertia-component error over the largest principal moment.
"""

import argparse
import contextlib
import io
import time
import warnings

import numpy as np

from bikemass.mass.parts import Part
from bikemass.mass.placement import Placement
from bikemass.rider import load_rider, shipped_poses
from bikemass.mass.solids import DEFAULT_SEGMENTS, Box, Cylinder, Hoop, RoundTube, SquareTube, TrapezoidalPrism


def best_time(fn, repeat):
    """Best wall time of ``repeat`` calls (s)."""
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return min(times)


def all_riders(method):
    return [load_rider(p).properties(method) for p in shipped_poses()]


def yeadon_measurements():
    """95 synthetic yeadon measurements (m): level lengths growing with the level number
    (yeadon lengths are measured from the segment's origin), perimeters 0.30, widths
    0.30 / 2.8 (a valid stadium), depths 0.08.  Only the work done matters here."""
    import yeadon
    meas = {}
    for name in yeadon.human.Human.measnames:
        kind, level = name[-1], name[2]
        length = 0.1 * (1 + int(level)) if level.isdigit() else 0.1
        meas[name] = {"L": length, "p": 0.30, "w": 0.30 / 2.8, "d": 0.08}[kind]
    return meas


def yeadon_human(meas):
    import yeadon
    with warnings.catch_warnings(), contextlib.redirect_stdout(io.StringIO()):
        warnings.simplefilter("ignore")
        return yeadon.Human(meas)


SOLIDS = {
    "cylinder": Cylinder(0.191, 0.295),
    "round_tube": RoundTube(0.0286, 0.0009, 0.55),
    "hoop": Hoop(0.55, 0.622, 0.025),
    "square_tube": SquareTube(0.04, 0.002, 0.5),
    "trapezoidal_prism": TrapezoidalPrism(0.253, 0.366, 0.253, 0.466),
    "box": Box(0.3, 0.2, 0.1),
}


def random_placement(rng):
    q = rng.normal(size=4)
    w, x, y, z = q / np.linalg.norm(q)
    R = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                  [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                  [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
    return Placement(R, rng.uniform(-2, 2, size=3))


def agreement(solid, rng, trials=20):
    """Max relative errors (mass, volume, inertia / largest principal moment) over random placements."""
    worst = np.zeros(3)
    for _ in range(trials):
        part = Part.from_density("s", solid, 1000.0, random_placement(rng))
        mesh, exact = part.mass_properties("mesh"), part.exact()
        volume = part.mesh().volume
        scale = np.linalg.eigvalsh(exact.inertia).max()
        errors = [abs(mesh.mass - exact.mass) / exact.mass, abs(volume - solid.volume) / solid.volume,
                  np.abs(mesh.inertia - exact.inertia).max() / scale]
        worst = np.maximum(worst, errors)
    return worst


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()

    poses = shipped_poses()
    print(f"Riders: {', '.join(poses)} (best of {args.repeat})")
    mesh = best_time(lambda: all_riders("mesh"), args.repeat)
    exact = best_time(lambda: all_riders("exact"), args.repeat)
    meas = yeadon_measurements()
    human = yeadon_human(meas)
    peer = best_time(lambda: yeadon_human(meas), args.repeat)
    n_solids = sum(len(seg.solids) for seg in human.segments)
    print(f"  bikemass, 5 riders, mesh  (load YAML, build, trimesh):  {mesh * 1e3:8.1f} ms"
          f"  ({mesh / len(poses) * 1e3:.1f} ms per rider, 11 parts)")
    print(f"  bikemass, 5 riders, exact (load YAML, build, closed form): {exact * 1e3:6.1f} ms"
          f"  ({exact / len(poses) * 1e3:.1f} ms per rider)")
    print(f"  yeadon 2.x, one Human ({n_solids} solids from 95 measurements): {peer * 1e3:6.1f} ms")
    print(f"  ratio per rider, bikemass mesh / yeadon Human:  {mesh / len(poses) / peer:.2f}")
    print(f"  ratio per rider, bikemass exact / yeadon Human: {exact / len(poses) / peer:.2f}")

    rng = np.random.default_rng(2015)
    print(f"\nMesh vs exact at the default resolution ({DEFAULT_SEGMENTS} sides per circle), "
          "max over 20 random placements:")
    print(f"  {'solid':<18} {'mass (rel)':>11} {'volume (rel)':>13} {'inertia / Imax':>15}")
    for name, solid in SOLIDS.items():
        m, v, i = agreement(solid, rng)
        print(f"  {name:<18} {m:11.1e} {v:13.1e} {i:15.1e}")


if __name__ == "__main__":
    main()
