"""Time the rear-frame FE: S (thesis + condensed) and 4 x 10 modes for the Jamis, and PyNite beside it.

Run by hand: ``python benchmarks/bench_fe.py [--repeat 10]``.  Target (issue 5): under
2 s at 2 mm elements.  The peer comparison is a static solve (unit loads in 6
directions at the bottom head-tube keypoint, dropouts clamped, Euler-Bernoulli) with
the same mesh in both codes, timed in this process.

BLAS threads (issue 10): the stiffness solve (``rotational_stiffness``: assembly + sparse
LU) and the fix-rear modes (``solve_modes``: assembly + ``eigsh``) at several element
sizes, each run ``--repeat`` times with the machine's default BLAS pool (for
``solve_modes`` its ``__wrapped__``: the same code without its
:func:`bikemass.core.threads.one_blas_thread`, as bikemass ran before) and on one thread, the
two alternating so that other load on the machine hits both alike.  Median and max,
since the stall is random.
"""

import argparse
import statistics
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from bikemass.fe import DEFAULT_ELEMENT_SIZE, build_mesh, equivalent_stiffness, frame_modes  # noqa: E402
from bikemass.fe.assembly import assemble  # noqa: E402
from bikemass.fe.boundary import BOUNDARY_CONDITIONS, free_dofs  # noqa: E402
from bikemass.fe.modes import solve_modes  # noqa: E402
from bikemass.fe.properties import beam_properties  # noqa: E402
from bikemass.fe.stiffness import rotational_stiffness  # noqa: E402
from thesis_frames import jamis_structure  # noqa: E402


def best_of(fn, repeat=3):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def paired_times(default, limited, repeat):
    """``(default times, limited times)`` in s, the two calls alternating ``repeat`` times."""
    times = ([], [])
    for _ in range(repeat):
        for fn, out in zip((default, limited), times):
            t0 = time.perf_counter()
            fn()
            out.append(time.perf_counter() - t0)
    return times


def blas_threads():
    from threadpoolctl import threadpool_info
    return sorted({p["num_threads"] for p in threadpool_info() if p["user_api"] == "blas"})


def thread_comparison(structure, repeat):
    from bikemass.core.threads import one_blas_thread

    print(f"BLAS threads: default pool ({'/'.join(map(str, blas_threads()))} threads) vs one thread, "
          f"{repeat} repeats, median / max in ms; 'shipped': what bikemass runs")
    print(f"  {'job':30s} {'DOF':>6s} {'default med':>12s} {'max':>8s} {'one med':>9s} {'max':>8s}"
          f" {'ratio med':>10s} {'ratio max':>10s}  shipped")
    jobs = [("stiffness, one element/tube", None, rotational_stiffness, ())]
    jobs += [(f"stiffness, {s * 1000:g} mm", s, rotational_stiffness, ()) for s in (0.02, 0.005, 0.002)]
    jobs += [(f"modes fix-rear x10, {s * 1000:g} mm", s, solve_modes, ("fix-rear", 10)) for s in (0.02, 0.005, 0.002)]
    for label, size, fn, args in jobs:
        mesh = build_mesh(structure, element_size=size)
        raw = getattr(fn, "__wrapped__", fn)       # the function without a limit of its own

        def one_thread():
            with one_blas_thread():
                raw(mesh, *args)
        default, one = paired_times(lambda: raw(mesh, *args), one_thread, repeat)
        d_med, d_max, o_med, o_max = (1000 * f(t) for t in (default, one) for f in (statistics.median, max))
        shipped = "one" if raw is not fn else "default"
        print(f"  {label:30s} {mesh.n_dof:6d} {d_med:12.1f} {d_max:8.1f} {o_med:9.1f} {o_max:8.1f}"
              f" {d_med / o_med:9.1f}x {d_max / o_max:9.1f}x  {shipped}")


def full_run(structure, size):
    equivalent_stiffness(structure, procedure="thesis")
    equivalent_stiffness(structure, procedure="condensed")
    for bc in BOUNDARY_CONDITIONS:
        frame_modes(structure, bc, 10, element_size=size)


def ours_static(structure, size):
    mesh = build_mesh(structure, element_size=size)
    K, _ = assemble(mesh, timoshenko=False, mass=False)
    free = free_dofs(mesh, structure.dropouts)
    import scipy.sparse.linalg as spla
    loads = np.zeros((len(free), 6))
    node = mesh.keypoint_nodes["5"]
    loads[np.searchsorted(free, 6 * node + np.arange(6)), np.arange(6)] = 1.0
    return spla.splu(K[free][:, free].tocsc()).solve(loads)


def pynite_static(structure, size):
    from Pynite import FEModel3D
    model = FEModel3D()
    for key, point in structure.keypoints.items():
        model.add_node(key, *point)
    mat = structure.tubes[0].material
    model.add_material("m", mat.E, mat.G, mat.nu, mat.density)
    for tube in structure.tubes:
        p = beam_properties(tube.section, mat.nu)
        model.add_section(tube.name, p.area, p.I, p.I, p.J)
        count = max(1, int(np.ceil(tube.length / size - 1e-9))) if size else 1
        chain = [tube.start_key]
        for i in range(1, count):
            chain.append(model.add_node(f"{tube.name}_{i}", *(tube.start + i / count * (tube.end - tube.start))))
        chain.append(tube.end_key)
        for i in range(count):
            model.add_member(f"{tube.name}#{i}", chain[i], chain[i + 1], "m", tube.name)
    for key in structure.dropouts:
        model.def_support(key, True, True, True, True, True, True)
    for d in ("FX", "FY", "FZ", "MX", "MY", "MZ"):
        model.add_node_load("5", d, 1.0, case=d)
        model.add_load_combo(d, {d: 1.0})
    model.analyze_linear(check_statics=False, check_stability=False)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=10, help="runs per job in the BLAS-thread comparison")
    args = parser.parse_args()
    structure = jamis_structure()
    print("Jamis rear frame: S (thesis + condensed) + 10 modes x 4 boundary conditions")
    for size in (DEFAULT_ELEMENT_SIZE, 0.002):
        dofs = build_mesh(structure, element_size=size).n_dof
        print(f"  element {size * 1000:5.1f} mm ({dofs:6d} DOF): {best_of(lambda: full_run(structure, size)):.3f} s"
              f"   (target at 2 mm: < 2 s)")
    print("Static solve, 6 unit loads, Euler-Bernoulli, same mesh: bikemass vs PyNiteFEA")
    for size in (None, DEFAULT_ELEMENT_SIZE, 0.01):
        ours = best_of(lambda: ours_static(structure, size))
        theirs = best_of(lambda: pynite_static(structure, size), repeat=2)
        label = "one element per tube" if size is None else f"element {size * 1000:.0f} mm"
        print(f"  {label:22s} bikemass {ours * 1000:8.1f} ms   PyNite {theirs * 1000:9.1f} ms"
              f"   ratio {theirs / ours:7.1f}x")
    thread_comparison(structure, args.repeat)


if __name__ == "__main__":
    main()
