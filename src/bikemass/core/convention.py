"""The one place that fixes axes and signs.

Benchmark frame (Meijaard et al. 2007), used everywhere in bikemass:

* origin at the rear-wheel ground contact point,
* x forward, y to the right, z **down** (so heights are negative z),
* inertia tensors about a body's centre of mass, products of inertia are
  tensor elements: ``I[0, 2] = Ixz = -integral(x z dm)`` (benchmark rear frame
  ``IBxz = +2.4 kg m^2``); trimesh uses the same convention.
* steer-axis tilt ``lam = pi/2 - head_angle`` (rad).

Thesis segment angles (Williams 2015, Table 3-3): an angle ``a`` is a clockwise
rotation about y seen from +y with x to the right and height up; at ``a = 0`` a
segment hangs straight down (+z), so its axis is ``(-sin a, 0, cos a)``.
"""

import numpy as np

def rotation_about_y(angle_rad: float) -> np.ndarray:
    """Right-handed rotation matrix about +y by ``angle_rad`` (rad)."""
    c, s = np.cos(angle_rad), np.sin(angle_rad)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def thesis_segment_axis(angle_deg: float) -> np.ndarray:
    """Unit axis of a thesis segment (Table 3-3 angle, degrees): ``(-sin a, 0, cos a)``."""
    a = np.radians(angle_deg)
    return np.array([-np.sin(a), 0.0, np.cos(a)])


def thesis_segment_rotation(angle_deg: float) -> np.ndarray:
    """Rotation taking a local +z axis onto :func:`thesis_segment_axis` (about y)."""
    return rotation_about_y(-np.radians(angle_deg))


def steer_axis_tilt(head_angle_rad: float) -> float:
    """Steer-axis tilt ``lam = pi/2 - head_angle`` (rad)."""
    return np.pi / 2 - head_angle_rad


def steer_axis(lam: float) -> np.ndarray:
    """Unit vector along the steer axis pointing down toward the ground (tilted back by lam)."""
    return np.array([np.sin(lam), 0.0, np.cos(lam)])
