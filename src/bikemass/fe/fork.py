"""The fork's beam model (steerer, crown, blades) and its lateral bending as a :class:`Compliance`.

The fork is the front frame's tubes named ``fork...`` or ``steerer`` (what the shipped bicycles and
the chart builder write); a bicycle without them gets the default fork of :func:`default_fork_tubes`
(docs/models-flexible.md).  The beam model joins the tubes at their keypoints and at the head tube's
keypoints where those lie on a tube (the bearings on the steerer, the steerer's foot on the crown);
the blade ends are tied to the hub (the axle and the wheel's hub are rigid: a rigid link); the
steerer is held in its two bearings (translations) and against turning about the steer axis.

:func:`fork_bending` loads it with a unit lateral force at the front contact's foot on the steer axis
(through the wheel, taken rigid), and reduces the hub's motion to a rotation about a line
(:mod:`bikemass.fe.twist`).
"""

from dataclasses import dataclass, replace

import numpy as np
import scipy.linalg

from ..core.frozen import frozen_fields
from ..mass.sections import RoundSection
from ..mass.tubes import Structure, Tube
from .assembly import assemble
from ..models.compliance import Compliance
from .model import build_mesh, with_material
from .twist import foot, line_of_rotation, modal_inertia

FORK_NAMES = ("fork", "steerer")
"""A front-frame tube belongs to the fork when its name starts with one of these."""
DEFAULT_HALF_WIDTH = 0.05
"""m: the default fork's blades either side of the plane of symmetry (crown and axle)."""
DEFAULT_SECTIONS = {"blade": RoundSection(0.025, 0.0009), "crown": RoundSection(0.025, 0.0009),
                    "steerer": RoundSection(0.0286, 0.0016)}
"""The default fork's sections: the ``steel-road`` tubeset of ``frames/chart_defaults.yaml`` (fork
blades 25.0 x 0.9 mm, steerer 28.6 x 1.6 mm), in the frame's material."""
AXLE_REACH = 0.1
"""m: blade ends within this distance of the front axle are the dropouts tied to the hub."""


@dataclass(frozen=True)
class Fork:
    """The fork's tubes (split at the bearings and junctions), its bearings (top, bottom keypoint
    names), its dropouts (the blade ends tied to the hub) and the hub (front axle, m)."""

    tubes: tuple
    bearings: tuple
    dropouts: tuple
    hub: np.ndarray
    keypoints: dict

    def __post_init__(self):
        frozen_fields(self, "tubes", "bearings", "dropouts", "keypoints")
        object.__setattr__(self, "hub", np.array(self.hub, float))
        self.hub.setflags(write=False)

    @property
    def mass(self):
        """The fork tubes' mass (kg)."""
        return float(sum(t.section.area * t.length * t.material.density for t in self.tubes))


def _on_segment(point, tube, tolerance=1e-6):
    """Whether ``point`` lies strictly inside ``tube`` (not at its ends)."""
    a, b = tube.start, tube.end
    t = np.dot(point - a, b - a) / np.dot(b - a, b - a)
    return 1e-9 < t < 1 - 1e-9 and np.linalg.norm(a + t * (b - a) - point) < tolerance


def _split(tubes, points):
    """``tubes`` cut at each of ``points`` ({name: position}) that lies inside one of them."""
    out = list(tubes)
    for key, point in points.items():
        for tube in list(out):
            if _on_segment(point, tube):
                out.remove(tube)
                out += [replace(tube, name=f"{tube.name}:{tube.start_key}-{key}", end_key=key, end=point),
                        replace(tube, name=f"{tube.name}:{key}-{tube.end_key}", start_key=key, start=point)]
                break
    return out


def default_fork_tubes(bike, material):
    """A fork for a bicycle that has none: a crown at the head tube's bottom, straight blades from
    :data:`DEFAULT_HALF_WIDTH` either side of it to the same either side of the front axle, and a
    steerer between the head tube's keypoints, with :data:`DEFAULT_SECTIONS` in ``material``."""
    top_key, bottom_key = bike.structure.head_tube
    top, bottom = (np.asarray(bike.structure.keypoints[k], float) for k in (top_key, bottom_key))
    axle = np.asarray(bike.geometry.front_axle, float)
    side = np.array([0.0, DEFAULT_HALF_WIDTH, 0.0])
    points = {"crown_left": bottom - side, "crown_right": bottom + side,
              "fork_end_left": axle - side, "fork_end_right": axle + side, top_key: top, bottom_key: bottom}

    def tube(name, a, b, section):
        return Tube(name, a, b, points[a], points[b], DEFAULT_SECTIONS[section], material, "front_frame")

    return [tube("fork_crown", "crown_left", "crown_right", "crown"),
            tube("fork_blade_left", "crown_left", "fork_end_left", "blade"),
            tube("fork_blade_right", "crown_right", "fork_end_right", "blade"),
            tube("steerer", bottom_key, top_key, "steerer")]


def fork_structure(bike, material=None):
    """The :class:`Fork` of ``bike`` (a :class:`~bikemass.bicycle.model.Bicycle` with a rear-frame
    structure); ``material`` replaces every fork tube's material (as for the frame)."""
    if bike.structure is None:
        raise ValueError(f"bicycle {bike.name!r} has no beam structure (frame YAML 'structure:'): "
                         "a fork needs the head tube's bearings")
    tubes = [t for t in bike.tubes if t.body == "front_frame" and t.name.startswith(FORK_NAMES)]
    if not tubes:
        tubes = default_fork_tubes(bike, material or bike.structure.tubes[0].material)
    bearings = tuple(bike.structure.head_tube)
    points = {k: np.asarray(bike.structure.keypoints[k], float) for k in bearings}
    tubes = _split(tubes, {**{t.start_key: t.start for t in tubes}, **{t.end_key: t.end for t in tubes}, **points})
    tubes = tuple(with_material(Structure(tuple(tubes), (), (), {}), material).tubes)
    keypoints = {k: p for t in tubes for k, p in ((t.start_key, t.start), (t.end_key, t.end))}
    missing = [k for k in bearings if k not in keypoints]
    if missing:
        raise ValueError(f"bicycle {bike.name!r}: the fork tubes ({', '.join(t.name for t in tubes)}) do not "
                         f"reach the head tube's keypoint(s) {', '.join(missing)} (the bearings)")
    axle = np.asarray(bike.geometry.front_axle, float)
    dropouts = tuple(sorted(k for k, n in _degrees(tubes).items()
                            if n == 1 and np.linalg.norm(keypoints[k] - axle) < AXLE_REACH))
    if not dropouts:
        raise ValueError(f"bicycle {bike.name!r}: no fork tube ends within {AXLE_REACH} m of the front axle")
    tubes = _pruned(tubes, set(dropouts) | set(bearings))
    keypoints = {k: p for t in tubes for k, p in ((t.start_key, t.start), (t.end_key, t.end))}
    return Fork(tubes, bearings, dropouts, axle, keypoints)


def _degrees(tubes):
    """``{keypoint: number of tubes ending there}``."""
    ends = {}
    for t in tubes:
        for k in (t.start_key, t.end_key):
            ends[k] = ends.get(k, 0) + 1
    return ends


def _pruned(tubes, anchors):
    """``tubes`` without the pieces that hang free (an end no other tube, bearing or dropout holds):
    the steerer above the top bearing belongs to the rigid front frame with the stem and bars."""
    tubes = list(tubes)
    while True:
        ends = _degrees(tubes)
        loose = [t for t in tubes if any(ends[k] == 1 and k not in anchors for k in (t.start_key, t.end_key))]
        if not loose:
            return tuple(tubes)
        tubes = [t for t in tubes if t not in loose]


def _rigid_link(mesh, slaves, master):
    """(n_dof, n_kept) matrix tying the nodes ``slaves`` rigidly to the node ``master``, and the kept DOF."""
    n = mesh.n_dof
    slave_dofs = {6 * s + i for s in slaves for i in range(6)}
    kept = [i for i in range(n) if i not in slave_dofs]
    column = {dof: j for j, dof in enumerate(kept)}
    T = np.zeros((n, len(kept)))
    for dof, j in column.items():
        T[dof, j] = 1.0
    m = 6 * master
    for s in slaves:
        d = mesh.nodes[s] - mesh.nodes[master]
        skew = np.array([[0, -d[2], d[1]], [d[2], 0, -d[0]], [-d[1], d[0], 0]])
        for i in range(3):
            T[6 * s + i, [column[m + j] for j in range(3)]] = np.eye(3)[i]
            T[6 * s + i, [column[m + 3 + j] for j in range(3)]] = -skew[i]      # u_s = u_m - [d x] theta_m
            T[6 * s + 3 + i, [column[m + 3 + j] for j in range(3)]] = np.eye(3)[i]
    return T, kept


def fork_bending(fork, contact, steer_axis, timoshenko=True, element_size=None):
    """The fork's lateral bending as a :class:`Compliance` (parent: the front frame).

    Parameters
    ----------
    fork : Fork
    contact : array_like (3,)
        The front contact point (m).
    steer_axis : array_like (3,)
        Unit steer axis, pointing down.
    timoshenko : bool
        Timoshenko beams (default) or Euler-Bernoulli.
    element_size : float or None
        Element length (m); ``None``: one element per tube, which is exact here (as in
        :func:`~bikemass.fe.twist.frame_twist`).
    """
    s = np.asarray(steer_axis, float)
    keypoints = {**fork.keypoints, "hub": fork.hub}
    mesh = build_mesh(Structure(fork.tubes, fork.dropouts, fork.bearings, keypoints), element_size=element_size)
    K, M = (X.toarray() for X in assemble(mesh, timoshenko=timoshenko))
    hub = mesh.keypoint_nodes["hub"]
    T, kept = _rigid_link(mesh, [mesh.keypoint_nodes[k] for k in fork.dropouts], hub)
    K = T.T @ K @ T
    column = {dof: j for j, dof in enumerate(kept)}
    held = [column[6 * mesh.keypoint_nodes[k] + i] for k in fork.bearings for i in range(3)]
    bottom = mesh.keypoint_nodes[fork.bearings[1]]
    twist = np.zeros(len(kept))                   # hold the steerer against turning about the steer axis
    for i in range(3):
        twist[column[6 * bottom + 3 + i]] = s[i]
    scale = np.mean(np.diag(K))
    K = K + scale * np.outer(twist, twist)        # the load has no moment about the axis: any value holds
    free = [j for j in range(len(kept)) if j not in held]
    Q = foot(np.asarray(contact, float), np.asarray(fork.keypoints[fork.bearings[1]], float), s)
    load = np.zeros(len(kept))
    arm = Q - fork.hub
    load[column[6 * hub + 1]] = 1.0
    load[[column[6 * hub + 3 + i] for i in range(3)]] = np.cross(arm, [0.0, 1.0, 0.0])
    x = np.zeros(len(kept))
    x[free] = scipy.linalg.solve(K[np.ix_(free, free)], load[free], assume_a="pos")
    u = T @ x
    h = u[6 * hub:6 * hub + 6]
    theta, point, direction = line_of_rotation(fork.hub, h[1], (h[3], h[5]))
    u_Q = h[1] + np.cross(h[3:], arm)[1]
    phi = u / theta
    phi[6 * hub:6 * hub + 6] = 0.0                # the hub node carries no tube mass (M has none there)
    L, J, m = modal_inertia(mesh.nodes, M, phi)
    return Compliance("fork bending", point, direction, u_Q / theta ** 2, L, J, m, (Q[0], Q[2]))
