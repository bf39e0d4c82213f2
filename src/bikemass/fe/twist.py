"""Reducing a beam model to a :class:`~bikemass.models.compliance.Compliance`, and the rear frame's twist
(docs/models-flexible.md).

The beam model is loaded as the front wheel's contact loads it -- a unit lateral force at the front
contact -- and solved statically.  The part that carries the front assembly moves as a rigid body
(the steer axis for the rear frame, the hub for the fork), and any small out-of-plane rigid motion of
a bicycle symmetric about its x-z plane is a rotation about a line in that plane: that line is the
compliance's axis, the rotation ``theta`` its coordinate, and the static field per unit ``theta`` is its
Ritz vector ``phi``.  From it:

* stiffness ``k = F u / theta**2`` (N m/rad): the strain energy of the static field, ``F u / 2``, equals
  ``k theta**2 / 2`` (``u`` the load point's displacement along the force ``F``);
* the tubes' inertia, with the beam model's consistent mass matrix ``M`` and the rigid-body fields
  ``r_y`` (translation along y) and ``r_x``, ``r_z`` (rotations about the x and z axes through the
  benchmark origin): the modal linear momentum ``L = r_y' M phi`` (kg m/rad), its moment about the
  origin ``J_k = r_k' M phi`` (kg m^2/rad) and the modal mass ``m = phi' M phi`` (kg m^2/rad^2).  These
  four numbers are all the linear equations of motion need of a deformation field that rides on a
  moving body (Kane's method: :mod:`bikemass.models.members.flexible.derivation`).

:func:`frame_twist` does this for the rear frame (dropouts clamped, the load through the head-tube
bearings); :mod:`bikemass.fe.fork` for the fork.
"""

import numpy as np
import scipy.sparse.linalg as spla

from .assembly import assemble
from .boundary import free_dofs
from ..models.compliance import Compliance
from .model import build_mesh
from .stiffness import head_tube_axis


def rigid_fields(nodes):
    """Rigid-body fields on the nodes (N, 3), each (6 N,): translation along y, rotation about x and
    about z through the origin (nodal translations ``e x r``, nodal rotations ``e``)."""
    n = len(nodes)
    out = {}
    out["y"] = np.zeros((n, 6))
    out["y"][:, 1] = 1.0
    for key, axis in (("x", np.array([1.0, 0, 0])), ("z", np.array([0, 0, 1.0]))):
        f = np.zeros((n, 6))
        f[:, :3] = np.cross(axis, nodes)
        f[:, 3:] = axis
        out[key] = f
    return {k: v.ravel() for k, v in out.items()}


def modal_inertia(nodes, M, phi):
    """``(L, (Jx, Jz), m)`` of the field ``phi`` (6 N,) with the consistent mass ``M`` (module doc)."""
    r = rigid_fields(nodes)
    Mphi = M @ phi
    return float(r["y"] @ Mphi), (float(r["x"] @ Mphi), float(r["z"] @ Mphi)), float(phi @ Mphi)


def line_of_rotation(origin, translation, rotation):
    """The line of a small out-of-plane rigid motion: ``translation`` (y, m) of the point ``origin`` and
    ``rotation`` (x, z components, rad).  Returns ``(theta, point (x, z), direction (x, z))`` with
    ``theta = |rotation|`` and the direction along ``rotation``: the motion is ``theta`` about that line."""
    wx, wz = rotation
    theta = float(np.hypot(wx, wz))
    if theta == 0:
        raise ValueError("a pure translation has no axis of rotation")
    # the point p with (w x (origin - p))_y = translation, nearest the origin
    d = translation / theta ** 2 * np.array([wz, -wx])
    point = np.array([origin[0], origin[2]]) - d
    return theta, point, np.array([wx, wz]) / theta


def foot(point, base, axis):
    """The foot of the perpendicular from ``point`` on the line through ``base`` along unit ``axis``."""
    return base + np.dot(point - base, axis) * axis


def frame_twist(structure, contact, material=None, timoshenko=True, element_size=None):
    """The rear frame's twist as a :class:`Compliance` (parent: the rear frame, held at its dropouts).

    The front assembly turns in two bearings at the head tube's keypoints; a unit lateral force at the
    front ``contact`` (3,) reaches them as a force on the steer axis at the foot ``Q`` of the
    perpendicular from the contact (its moment about the steer axis goes to the steering, not to the
    frame), split between the bearings by the lever rule.  The steer axis then moves sideways as a
    rotation about a line at right angles to it in the plane of symmetry: the twist axis.

    Parameters
    ----------
    structure : Structure
        The rear frame's beam structure (dropouts, head tube).
    contact : array_like (3,)
        The front contact point (m).
    material : Material or None
        Every tube in this material; ``None`` keeps each tube's own.
    timoshenko : bool
        Timoshenko beams (default) or Euler-Bernoulli.
    element_size : float or None
        Element length (m); ``None``: one element per tube, which is exact here (the static field
        of end-loaded beams is the elements' own interpolation, which the consistent mass integrates
        exactly).
    """
    mesh = build_mesh(structure, material, element_size)
    top, bottom = (np.asarray(structure.keypoints[k], float) for k in structure.head_tube)
    s = head_tube_axis(structure)
    Q = foot(np.asarray(contact, float), bottom, s)
    length = float(np.dot(bottom - top, s))
    share_top = -float(np.dot(Q - bottom, s)) / length          # lever rule about the bottom bearing
    forces = np.zeros(mesh.n_dof)
    for key, share in ((structure.head_tube[0], share_top), (structure.head_tube[1], 1.0 - share_top)):
        forces[6 * mesh.keypoint_nodes[key] + 1] += share
    free = free_dofs(mesh, structure.dropouts)
    K, M = assemble(mesh, timoshenko=timoshenko)
    u = np.zeros(mesh.n_dof)
    u[free] = spla.splu(K[free][:, free].tocsc()).solve(forces[free])
    u_top, u_bottom = (u[6 * mesh.keypoint_nodes[k] + 1] for k in structure.head_tube)
    # a rotation theta about n (at right angles to s, in the plane) moves the steer axis' points by
    # theta n x (tau s) = -theta tau e_y, tau measured along s from the axis' point Z
    normal = np.array([s[2], 0.0, -s[0]])                        # n x s = -e_y
    theta = (u_top - u_bottom) / length
    Z = bottom + (u_bottom / theta) * s
    u_Q = -theta * float(np.dot(Q - Z, s))
    phi = u / theta
    L, J, m = modal_inertia(mesh.nodes, M, phi)
    sign = 1.0 if theta > 0 else -1.0                            # theta > 0 along the direction kept
    return Compliance("frame twist", (Z[0], Z[2]), (sign * normal[0], sign * normal[2]), u_Q / theta ** 2,
                      sign * L, (sign * J[0], sign * J[1]), m, (Q[0], Q[2]))
