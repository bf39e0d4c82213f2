"""Time the rear-frame FE: S (thesis + condensed) and 4 x 10 modes for the Jamis, and PyNite beside it.

Run by hand: ``python benchmarks/bench_fe.py``.  Target (issue 5): under 2 s at
2 mm elements.  The peer comparison is a static solve (unit loads in 6 directions
at the bottom head-tube keypoint, dropouts clamped, Euler-Bernoulli) with the
same mesh in both codes, timed in this process.
"""

import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from bikemass.fe import DEFAULT_ELEMENT_SIZE, build_mesh, equivalent_stiffness, frame_modes  # noqa: E402
from bikemass.fe.assembly import assemble  # noqa: E402
from bikemass.fe.boundary import BOUNDARY_CONDITIONS, free_dofs  # noqa: E402
from bikemass.fe.properties import beam_properties  # noqa: E402
from thesis_frames import jamis_structure  # noqa: E402


def best_of(fn, repeat=3):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


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


if __name__ == "__main__":
    main()
