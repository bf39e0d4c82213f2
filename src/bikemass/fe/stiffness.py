"""Equivalent rear-frame stiffness S (2x2, N m/rad) on roll and steer at the head tube.

With the dropouts clamped, the rotational stiffness of the bottom head-tube
keypoint is the Schur complement of the frame stiffness onto its three
rotations (translations and every other node free): ``K_r = F_r^-1`` with
``F_r`` the 3x3 rotational flexibility obtained from three unit moments.
S is then built from ``K_r`` in two ways:

``condensed`` (default): the consistent stiffness in the generalised rotations
    roll ``phi`` (about x) and steer ``delta`` (about the head-tube axis ``s``,
    pointing down): the rotation is ``phi e_x + delta s + eta n`` with ``n``
    normal to both and ``eta`` free; S is the Schur complement eliminating
    ``eta``.  It is symmetric and its energy is exactly ``q^T S q / 2``.
``thesis``: Williams (2015) Eq. 3.31-3.34, read as unit rotations of the
    keypoint with every DOF not named held free, ``F_r = K_r^-1``:
    ``K_pp = 1 / (e_x^T F_r e_x)`` (unit roll, moment about x),
    ``K_dd = 1 / (s^T F_r s)`` (unit rotation about the head-tube axis, moment about it),
    ``K_pd = K_dp = s^T K_xz e_x`` with ``K_xz`` = ``K_r`` condensed onto the plane of
    ``e_x`` and ``s`` (the roll applied through its two components in the frame
    rotated so that z' = s, moment about z').
The condensed form holds the steer rotation while rolling and the roll while
steering; the thesis lets them relax in ``K_pp`` and ``K_dd`` but not in
``K_pd``, so its matrix is not the stiffness of any one energy.  ``K_pd`` is
the same in both; for the Jamis the thesis's ``K_pp`` is 2.5 % and ``K_dd`` 0.1 %
below the condensed values, for the more strongly coupled Cargo 2.7 % and 14 %
(see docs/fe.md).
"""

import numpy as np
import scipy.sparse.linalg as spla

from . import PROCEDURES
from .assembly import assemble
from .boundary import free_dofs
from .model import build_mesh


def head_tube_axis(structure):
    """Unit head-tube (steer) axis from the top to the bottom keypoint (points down)."""
    top, bottom = (np.asarray(structure.keypoints[k], float) for k in structure.head_tube)
    axis = bottom - top
    return axis / np.linalg.norm(axis)


def rotational_stiffness(mesh, timoshenko=True):
    """3x3 stiffness (N m/rad, benchmark axes) of the bottom head-tube keypoint's rotations.

    Runs on the caller's BLAS pool: the sparse LU hardly calls BLAS, so one thread gains
    nothing here (benchmarks/bench_fe.py), unlike the mode solve."""
    free = free_dofs(mesh, mesh.structure.dropouts)
    K, _ = assemble(mesh, timoshenko=timoshenko, mass=False)
    K = K[free][:, free].tocsc()
    node = mesh.keypoint_nodes[mesh.structure.head_tube[1]]
    rot = np.searchsorted(free, 6 * node + np.arange(3, 6))
    load = np.zeros((len(free), 3))
    load[rot, np.arange(3)] = 1.0
    try:
        flexibility = spla.splu(K).solve(load)[rot]
    except RuntimeError:        # SuperLU: "Factor is exactly singular"
        raise ValueError("a structure held by its dropouts (some tubes can move freely: is every tube "
                         "joined to the others at a shared keypoint?)") from None
    if not np.all(np.isfinite(flexibility)):
        raise ValueError("a structure held by its dropouts (its stiffness matrix is singular)")
    flexibility = (flexibility + flexibility.T) / 2
    return np.linalg.inv(flexibility)


def _schur(K, keep):
    drop = [i for i in range(K.shape[0]) if i not in keep]
    Kkk, Kkd, Kdd = K[np.ix_(keep, keep)], K[np.ix_(keep, drop)], K[np.ix_(drop, drop)]
    return Kkk - Kkd @ np.linalg.solve(Kdd, Kkd.T)


def stiffness_from_rotational(Kr, steer_axis, procedure="condensed"):
    """2x2 S [[K_pp, K_pd], [K_dp, K_dd]] from the 3x3 rotational stiffness ``Kr`` (see module doc)."""
    ex = np.array([1.0, 0.0, 0.0])
    s = np.asarray(steer_axis, float)
    n = np.cross(s, ex)
    n /= np.linalg.norm(n)
    if procedure == "condensed":
        A = np.column_stack([ex, s, n])
        return _schur(A.T @ Kr @ A, [0, 1])
    if procedure == "thesis":
        plane = np.column_stack([np.cross(n, s), s, n])   # x', z' = s, y' = n
        K_xz = _schur(plane.T @ Kr @ plane, [0, 1])
        roll, steer = plane[:, :2].T @ ex, np.array([0.0, 1.0])
        flexibility = np.linalg.inv(Kr)
        k_pd = steer @ K_xz @ roll
        return np.array([[1.0 / (ex @ flexibility @ ex), k_pd], [k_pd, 1.0 / (s @ flexibility @ s)]])
    raise ValueError(f"procedure {procedure!r}: expected one of {', '.join(PROCEDURES)}")


def equivalent_stiffness(structure, material=None, procedure="condensed", timoshenko=True):
    """S (2x2, N m/rad) of ``structure`` (optionally re-materialised), dropouts clamped.

    Uses one exact element per tube: the static result does not depend on the mesh.
    """
    mesh = build_mesh(structure, material)
    Kr = rotational_stiffness(mesh, timoshenko)
    return stiffness_from_rotational(Kr, head_tube_axis(structure), procedure)
