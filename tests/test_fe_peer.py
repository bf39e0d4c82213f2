"""Cross-check against PyNiteFEA (independent Euler-Bernoulli frame code) on the Jamis frame.

With shear deformation switched off our element is the exact Euler-Bernoulli
element, as is PyNite's, so static results agree to round-off; 1e-4 is the
issue's bar (observed ~1e-11).
"""

import numpy as np
import pytest

from bikemass.fe import build_mesh
from bikemass.fe.assembly import assemble
from bikemass.fe.boundary import free_dofs
from bikemass.fe.properties import beam_properties
from bikemass.fe.stiffness import head_tube_axis, rotational_stiffness, stiffness_from_rotational
from thesis_frames import jamis_structure

Pynite = pytest.importorskip("Pynite")
DIRECTIONS = ("FX", "FY", "FZ", "MX", "MY", "MZ")


def pynite_flexibility(structure, load_key, element_size=None):
    """Displacements (keypoints x 6 DOF) for a unit load in each of the six directions at ``load_key``."""
    model = Pynite.FEModel3D()
    for key, point in structure.keypoints.items():
        model.add_node(key, *point)
    for i, tube in enumerate(structure.tubes):
        mat = tube.material
        p = beam_properties(tube.section, mat.nu)
        model.add_material(f"m{i}", mat.E, mat.G, mat.nu, mat.density)
        model.add_section(f"s{i}", p.area, p.I, p.I, p.J)
        model.add_member(tube.name, tube.start_key, tube.end_key, f"m{i}", f"s{i}")
    for key in structure.dropouts:
        model.def_support(key, True, True, True, True, True, True)
    for d in DIRECTIONS:
        model.add_node_load(load_key, d, 1.0, case=d)
        model.add_load_combo(d, {d: 1.0})
    model.analyze_linear(check_statics=False)
    out = np.zeros((6, len(structure.keypoints), 6))
    for j, key in enumerate(structure.keypoints):
        node = model.nodes[key]
        for i, d in enumerate(DIRECTIONS):
            out[i, j] = [getattr(node, a)[d] for a in ("DX", "DY", "DZ", "RX", "RY", "RZ")]
    return out


def our_flexibility(structure, load_key, element_size=None):
    mesh = build_mesh(structure, element_size=element_size)
    K, _ = assemble(mesh, timoshenko=False, mass=False)
    free = free_dofs(mesh, structure.dropouts)
    loads = np.zeros((mesh.n_dof, 6))
    node = mesh.keypoint_nodes[load_key]
    loads[6 * node:6 * node + 6] = np.eye(6)
    u = np.zeros((mesh.n_dof, 6))
    u[free] = np.linalg.solve(K[free][:, free].toarray(), loads[free])
    keypoints = [mesh.keypoint_nodes[k] for k in structure.keypoints]
    return u.T.reshape(6, -1, 6)[:, keypoints]


@pytest.mark.parametrize("material", ["steel", "aluminum"])
@pytest.mark.parametrize("element_size", [None, 0.05])
def test_keypoint_displacements_match_pynite(material, element_size):
    structure = jamis_structure(material)
    ours = our_flexibility(structure, "5", element_size)
    theirs = pynite_flexibility(structure, "5")
    for i in range(6):  # each load case; translations and rotations each against their largest value
        for part in (slice(0, 3), slice(3, 6)):
            peak = np.abs(theirs[i][:, part]).max()
            assert np.abs(ours[i][:, part] - theirs[i][:, part]).max() < 1e-4 * peak


def test_condensed_stiffness_matches_pynite():
    structure = jamis_structure()
    flex = pynite_flexibility(structure, "5")[3:, list(structure.keypoints).index("5"), 3:]
    theirs = stiffness_from_rotational(np.linalg.inv((flex + flex.T) / 2), head_tube_axis(structure))
    ours = stiffness_from_rotational(rotational_stiffness(build_mesh(structure), timoshenko=False),
                                     head_tube_axis(structure))
    np.testing.assert_allclose(ours, theirs, rtol=1e-4)
