"""The geometry the benchmark model needs, and its consistency with a frame's keypoints.

All lengths in m, angles in rad, benchmark frame (x forward, y right, z down,
origin at the rear contact).  The steer axis meets the ground at ``x = w + c``
and is tilted back from vertical by ``lam = pi/2 - head_angle``.
"""

import contextlib
import contextvars
from dataclasses import dataclass

import numpy as np

from ..core.convention import steer_axis, steer_axis_tilt
from ..core.frozen import readonly

STEER_AXIS_TOLERANCE = 0.002
"""How far (m) a head-tube keypoint may sit from the steer axis of wheelbase/trail/head angle."""
_CHANGED = contextvars.ContextVar("bikemass_changed_geometry", default=frozenset())
"""The ``geometry`` keys a sweep or a Monte Carlo draw changed (:func:`changed_geometry`)."""
AXIS_KEYS = frozenset({"wheelbase", "trail", "head_angle"})
"""The keys that place the steer axis."""


@contextlib.contextmanager
def changed_geometry(keys):
    """Within the block, the keypoint checks that a change of the ``geometry`` keys ``keys``
    (``trail``, ``head_angle``, ...) contradicts by construction are left out: they check a file
    as written (its own copy is checked unchanged), while a sweep or a draw that moves the trail
    by 3 mm asks for exactly that bicycle, keypoints and all (the frame's tubes stay where the
    file puts them; the model's trail is the changed one)."""
    token = _CHANGED.set(frozenset(keys))
    try:
        yield
    finally:
        _CHANGED.reset(token)


HEAD_ANGLE_TOLERANCE = 0.002
"""How far (rad) the head-tube keypoints' angle may differ from ``head_angle`` (3-decimal rounding)."""
AXLE_TOLERANCE = 0.001
"""How far (m) ``rear_axle``/``front_axle`` keypoints and wheel tire radii may be off."""
DEFAULT_GRAVITY = 9.81
"""m/s^2, as Meijaard et al. (2007)."""


@dataclass(frozen=True)
class Geometry:
    """Wheelbase ``w``, trail ``c``, head angle, wheel radii (m, rad) and gravity (m/s^2)."""

    wheelbase: float
    trail: float
    head_angle: float
    rear_wheel_radius: float
    front_wheel_radius: float
    gravity: float = DEFAULT_GRAVITY

    @property
    def lam(self):
        """Steer-axis tilt (rad)."""
        return steer_axis_tilt(self.head_angle)

    @property
    def rear_axle(self):
        """The rear axle (0, 0, -rR) in m, read-only."""
        return readonly([0.0, 0.0, -self.rear_wheel_radius])

    @property
    def front_axle(self):
        """The front axle (w, 0, -rF) in m, read-only."""
        return readonly([self.wheelbase, 0.0, -self.front_wheel_radius])

    @property
    def steer_ground_point(self):
        """Where the steer axis meets the ground, (w + c, 0, 0)."""
        return readonly([self.wheelbase + self.trail, 0.0, 0.0])

    def fork_offset(self):
        """Perpendicular distance of the front axle ahead of the steer axis (m)."""
        return self.front_wheel_radius * np.sin(self.lam) - self.trail * np.cos(self.lam)

    def distance_from_steer_axis(self, point):
        """Distance (m) of ``point`` from the steer axis."""
        d = np.asarray(point, dtype=float) - self.steer_ground_point
        axis = steer_axis(self.lam)
        return float(np.linalg.norm(d - (d @ axis) * axis))


def read_geometry(node):
    """:class:`Geometry` from the ``geometry`` mapping; checks ``fork_offset`` against the trail."""
    node.check_keys(required=("wheelbase", "trail", "head_angle", "rear_wheel_radius",
                              "front_wheel_radius"),
                    optional=("fork_offset", "gravity", "axle_tolerance"))
    head_angle = node["head_angle"].number("angle", positive=True)
    if head_angle > np.pi / 2:
        node.fail(f"a head angle in (0, pi/2] rad, got {head_angle!r}", "head_angle")
    geometry = Geometry(node["wheelbase"].number("length", positive=True), node["trail"].number("length"),
                        head_angle, node["rear_wheel_radius"].number("length", positive=True),
                        node["front_wheel_radius"].number("length", positive=True),
                        node["gravity"].number("acceleration", positive=True) if node.has("gravity") else DEFAULT_GRAVITY)
    changed = _CHANGED.get()
    if node.has("fork_offset"):
        offset = node["fork_offset"].number("length")
        if not changed & {"trail", "head_angle", "front_wheel_radius"} \
                and abs(offset - geometry.fork_offset()) > AXLE_TOLERANCE:
            node.fail(f"a trail consistent with head_angle, front_wheel_radius and fork_offset "
                      f"(they give {(geometry.front_wheel_radius * np.sin(geometry.lam) - offset) / np.cos(geometry.lam):.4f} m, "
                      f"not {geometry.trail:.4f} m)", "trail")
    return geometry


def check_keypoints(geometry, node, keypoints, head_tube=None, dropouts=None):
    """Fail (naming the ``geometry`` key) where the keypoints contradict the geometry.

    * ``rear_axle`` / ``front_axle`` keypoints, if present, at (0, 0, -rR) / (w, 0, -rF);
    * the ``head_tube`` keypoint pair on the steer axis and at the head angle;
    * the ``dropouts`` midpoint within ``axle_tolerance`` (m, default 0.001) of the rear axle;

    each left out where :func:`changed_geometry` says a key it depends on was changed.
    """
    changed = _CHANGED.get()
    for key, expected, radius_key in (("rear_axle", geometry.rear_axle, "rear_wheel_radius"),
                                      ("front_axle", geometry.front_axle, "front_wheel_radius")):
        moved = {radius_key} | ({"wheelbase"} if key == "front_axle" else set())
        if key in keypoints and not changed & moved and np.linalg.norm(keypoints[key] - expected) > AXLE_TOLERANCE:
            node.fail(f"a value consistent with keypoint {key} {np.round(keypoints[key], 4).tolist()} "
                      f"(the geometry puts the axle at {np.round(expected, 4).tolist()})", radius_key)
    if head_tube and not changed & AXIS_KEYS:
        top, bottom = (keypoints[k] for k in head_tube)
        up = top - bottom
        angle = np.arctan2(-up[2], abs(up[0]))
        if abs(angle - geometry.head_angle) > HEAD_ANGLE_TOLERANCE:
            node.fail(f"the head-tube keypoints' angle {angle:.4f} rad (within "
                      f"{HEAD_ANGLE_TOLERANCE} rad), got {geometry.head_angle:.4f} rad", "head_angle")
        for key in head_tube:
            miss = geometry.distance_from_steer_axis(keypoints[key])
            if miss > STEER_AXIS_TOLERANCE:
                ground = bottom[0] - bottom[2] * up[0] / up[2]
                node.fail(f"a trail putting the steer axis through the head-tube keypoints "
                          f"(they meet the ground at x = {ground:.4f} m, so c = "
                          f"{ground - geometry.wheelbase:.4f} m; keypoint {key} is "
                          f"{miss * 1000:.1f} mm off the axis)", "trail")
    if dropouts and "rear_wheel_radius" not in changed:
        tolerance = node["axle_tolerance"].number("length", positive=True) if node.has("axle_tolerance") else AXLE_TOLERANCE
        middle = (keypoints[dropouts[0]] + keypoints[dropouts[1]]) / 2
        miss = np.linalg.norm(middle - geometry.rear_axle)
        if miss > tolerance:
            node.fail(f"a rear wheel radius putting the axle within axle_tolerance = {tolerance} m of "
                      f"the dropouts' midpoint {np.round(middle, 4).tolist()} (it is {miss * 1000:.1f} mm away)",
                      "rear_wheel_radius")
