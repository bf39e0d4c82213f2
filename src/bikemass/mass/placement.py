"""Placements: a rotation and a translation putting a solid's local frame into the bicycle frame."""

from dataclasses import dataclass

import numpy as np

from ..core.convention import thesis_segment_rotation

_EYE = np.eye(3)
_ORTHONORMAL_TOLERANCE = 1e-9 + 1e-5 * _EYE
"""|R^T R - I| allowed entry by entry: what ``np.allclose(R.T @ R, I, atol=1e-9)`` allows (its
relative 1e-5 counts on the unit diagonal), without its cost (a placement is made for every
part of every configuration)."""


def _det(R):
    """Determinant of a 3x3 array (the rule of Sarrus, on Python floats: cheaper than LAPACK here)."""
    (a, b, c), (d, e, f), (g, h, i) = R.tolist()
    return a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)


@dataclass(frozen=True, eq=False)
class Placement:
    """x_frame = rotation @ x_local + translation (m)."""

    rotation: np.ndarray
    translation: np.ndarray

    def __post_init__(self):
        R = np.array(self.rotation, dtype=float).reshape(3, 3)
        if not (np.abs(R.T @ R - _EYE) <= _ORTHONORMAL_TOLERANCE).all() or _det(R) < 0:
            raise ValueError("rotation must be a proper orthonormal 3x3 matrix")
        t = np.array(self.translation, dtype=float).reshape(3)
        R.setflags(write=False)
        t.setflags(write=False)
        object.__setattr__(self, "rotation", R)
        object.__setattr__(self, "translation", t)

    @classmethod
    def identity(cls):
        return cls(np.eye(3), np.zeros(3))

    @classmethod
    def at(cls, position):
        """A pure translation to ``position`` (m)."""
        return cls(np.eye(3), position)

    @classmethod
    def along(cls, origin, direction, side=(0.0, 1.0, 0.0)):
        """Local z along ``direction`` from ``origin``; local y as close as possible to ``side``.

        Used for tubes between keypoints and for limbs; for a direction parallel to
        ``side`` the global x axis is used instead.
        """
        z = np.asarray(direction, dtype=float)
        z = z / np.sqrt(z @ z)
        s = np.asarray(side, dtype=float)
        y = s - (s @ z) * z
        if np.sqrt(y @ y) < 1e-9:
            s = np.array([1.0, 0.0, 0.0])
            y = s - (s @ z) * z
        y = y / np.sqrt(y @ y)
        (y0, y1, y2), (z0, z1, z2) = y.tolist(), z.tolist()
        x = (y1 * z2 - y2 * z1, y2 * z0 - y0 * z2, y0 * z1 - y1 * z0)     # y x z, as np.cross does it
        return cls(np.array([[x[0], y0, z0], [x[1], y1, z1], [x[2], y2, z2]]), origin)

    @classmethod
    def thesis_segment(cls, location, angle_deg):
        """Williams (2015) Table 3-3 placement: top-plane centre ``location``, angle about y (deg)."""
        return cls(thesis_segment_rotation(angle_deg), location)

    def apply(self, points):
        """Map local points (..., 3) into the frame."""
        return np.asarray(points) @ self.rotation.T + self.translation

    def then(self, outer):
        """This placement followed by ``outer`` (outer ∘ self)."""
        return Placement(outer.rotation @ self.rotation, outer.apply(self.translation))

    def matrix(self):
        """4x4 homogeneous transform (for trimesh)."""
        T = np.eye(4)
        T[:3, :3] = self.rotation
        T[:3, 3] = self.translation
        return T
