"""Sparse global stiffness and mass matrices of a :class:`~bikemass.fe.model.FrameMesh`.

Global DOF ``6 * node + (ux, uy, uz, rx, ry, rz)`` in the benchmark frame (m, rad).
"""

import numpy as np
import scipy.sparse as sp

from .elements import direction_cosines, local_matrices, to_global


def element_dofs(elements):
    """(n, 12) global DOF indices of each element."""
    base = 6 * np.asarray(elements)
    return (base[:, :, None] + np.arange(6)).reshape(len(base), 12)


def assemble(mesh, timoshenko=True, mass=True):
    """``(K, M)`` as CSR matrices (N/m, N m/rad; kg, kg m^2); ``M`` is None if ``mass=False``."""
    start, end = mesh.nodes[mesh.elements[:, 0]], mesh.nodes[mesh.elements[:, 1]]
    length = np.linalg.norm(end - start, axis=1)
    p = mesh.properties
    k_local, m_local = local_matrices(length, p["E"], p["G"], p["density"], p["area"], p["I"],
                                      p["J"], p["polar"], p["kappa"], timoshenko=timoshenko)
    rotation = direction_cosines(start, end)
    dofs = element_dofs(mesh.elements)
    rows = np.repeat(dofs, 12, axis=1).ravel()
    cols = np.tile(dofs, (1, 12)).ravel()
    shape = (mesh.n_dof, mesh.n_dof)

    def build(local):
        values = to_global(local, rotation).ravel()
        return sp.csr_matrix(sp.coo_matrix((values, (rows, cols)), shape=shape))

    return build(k_local), (build(m_local) if mass else None)
