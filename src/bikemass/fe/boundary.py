"""Supports: which keypoints are clamped (all six DOF) for each boundary condition.

* ``free``: nothing held (free-free; the rigid-body modes are skipped);
* ``fix-rear``: both dropout keypoints clamped;
* ``fix-head``: both head-tube keypoints (top and bottom) clamped;
* ``fix-both``: dropouts and head tube clamped.
"""

import numpy as np
from scipy.sparse.csgraph import connected_components
import scipy.sparse as sp

from . import BOUNDARY_CONDITIONS


def clamped_keypoints(structure, bc):
    """Keypoint names clamped under boundary condition ``bc``."""
    if bc not in BOUNDARY_CONDITIONS:
        raise ValueError(f"boundary condition {bc!r}: expected one of {', '.join(BOUNDARY_CONDITIONS)}")
    rear = tuple(structure.dropouts) if bc in ("fix-rear", "fix-both") else ()
    head = tuple(structure.head_tube) if bc in ("fix-head", "fix-both") else ()
    return rear + head


def free_dofs(mesh, clamped):
    """Sorted global DOF indices left free when the keypoints ``clamped`` are held in 6 DOF."""
    held = np.zeros(mesh.n_dof, bool)
    for key in clamped:
        node = mesh.keypoint_nodes[key]
        held[6 * node:6 * node + 6] = True
    return np.flatnonzero(~held)


def rigid_body_mode_count(mesh, clamped):
    """6 x the number of connected parts of the mesh that touch no clamped keypoint."""
    n = len(mesh.nodes)
    a, b = mesh.elements.T
    graph = sp.coo_matrix((np.ones(len(a)), (a, b)), shape=(n, n))
    count, labels = connected_components(graph, directed=False)
    held = {labels[mesh.keypoint_nodes[key]] for key in clamped}
    return 6 * (count - len(held))
