"""Natural frequencies and mode shapes of the beam model.

Solves ``K x = omega^2 M x`` on the free DOF.  Small problems use a dense
generalised symmetric solver; larger ones ``eigsh`` in shift-invert mode around
a small negative shift, which keeps ``K - sigma M`` positive definite even when
``K`` is singular (free-free).  The rigid-body modes (6 per unsupported part)
are counted from the mesh topology and skipped, so they never masquerade as
elastic modes however close to zero they come out.
"""

from dataclasses import dataclass

import numpy as np
import scipy.linalg
import scipy.sparse.linalg as spla

from ..core.display import brief
from ..core.results import Result, quantity
from ..core.frozen import frozen_fields
from ..core.tables import Table
from ..core.threads import one_blas_thread
from .assembly import assemble
from .boundary import clamped_keypoints, free_dofs, rigid_body_mode_count
from .defaults import DEFAULT_ELEMENT_SIZE
from .model import FrameMesh, build_mesh

DENSE_LIMIT = 400
"""Free-DOF count up to which the dense solver is used."""


@dataclass(frozen=True, repr=False)
class Modes(Result):
    """Natural frequencies (Hz, ascending) and mass-normalised shapes (n_dof, n) on all DOF
    (read-only arrays)."""

    frequencies_hz: np.ndarray = quantity("Hz", "natural frequencies, ascending")
    shapes: np.ndarray                  # mass-normalised (phi^T M phi = 1), a column per mode
    mesh: FrameMesh
    bc: str

    def __post_init__(self):
        frozen_fields(self, "frequencies_hz", "shapes")

    def display_rows(self):
        """The frequencies (Hz), the boundary condition and the model's size (Jupyter's table, ``repr``)."""
        return [("frequencies_hz", ", ".join(f"{f:.4g}" for f in self.frequencies_hz), "Hz"),
                ("bc", self.bc, ""), ("shapes", brief(self.shapes), "mass-normalised")]

    def tables(self):
        """``{"modes": Table}``: one row per mode, ``mode`` (1, 2, ...) and ``frequency`` (Hz). The
        boundary condition is the frame's ``attrs``."""
        columns = {"mode": np.arange(1, len(self.frequencies_hz) + 1), "frequency": self.frequencies_hz}
        return {"modes": Table(columns, {"frequency": "Hz"}, {"bc": self.bc})}

    @staticmethod
    def units():
        """The ``units`` block of :meth:`to_dict`."""
        return {"frequencies": "Hz"}

    def to_dict(self):
        """``{"frequencies": [Hz, ...]}`` (the unit goes in the document's ``units`` block)."""
        return {"frequencies": [float(f) for f in self.frequencies_hz]}


def _lowest(K, M, count, shift):
    """The ``count`` lowest eigenpairs of (K, M), ascending."""
    if K.shape[0] <= DENSE_LIMIT:
        values, vectors = scipy.linalg.eigh(K.toarray(), M.toarray(), subset_by_index=[0, count - 1])
    else:
        start = np.random.default_rng(0).standard_normal(K.shape[0])   # fixed: same result every run
        values, vectors = spla.eigsh(K.tocsc(), k=count, M=M.tocsc(), sigma=shift, which="LM", v0=start)
        order = np.argsort(values)
        values, vectors = values[order], vectors[:, order]
    return values, vectors


@one_blas_thread()
def solve_modes(mesh, bc="free", count=10, timoshenko=True):
    """The first ``count`` elastic :class:`Modes` of ``mesh`` under ``bc`` (assembly and solve on one
    BLAS thread: :mod:`bikemass.core.threads`)."""
    clamped = clamped_keypoints(mesh.structure, bc)
    free = free_dofs(mesh, clamped)
    rigid = rigid_body_mode_count(mesh, clamped)
    K, M = assemble(mesh, timoshenko=timoshenko)
    K, M = K[free][:, free], M[free][:, free]
    if count + rigid > K.shape[0]:
        raise ValueError(f"{count} modes asked of a model with {K.shape[0] - rigid} elastic DOF")
    # Shift: minus a small fraction of the mean K/M diagonal ratio (about (2 pi f)^2 of the stiffest
    # element): far below the first elastic eigenvalue yet not so small that K - sigma M is ill-conditioned.
    scale = np.mean(K.diagonal()) / np.mean(M.diagonal())
    values, vectors = _lowest(K, M, count + rigid, shift=-1e-6 * scale)
    values, vectors = values[rigid:], vectors[:, rigid:]
    shapes = np.zeros((mesh.n_dof, count))
    shapes[free] = vectors
    return Modes(np.sqrt(np.clip(values, 0, None)) / (2 * np.pi), shapes, mesh, bc)


def frame_modes(structure, bc="free", count=10, material=None, element_size=DEFAULT_ELEMENT_SIZE,
                timoshenko=True):
    """Natural frequencies of ``structure`` (optionally re-materialised) under ``bc``."""
    return solve_modes(build_mesh(structure, material, element_size), bc, count, timoshenko)
