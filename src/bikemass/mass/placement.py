"""Placements: a rotation and a translation putting a solid's local frame into the bicycle frame."""

from dataclasses import dataclass

import numpy as np

from ..core.convention import thesis_segment_rotation


@dataclass(frozen=True, eq=False)
class Placement:
    """x_frame = rotation @ x_local + translation (m)."""

    rotation: np.ndarray
    translation: np.ndarray

    def __post_init__(self):
        R = np.array(self.rotation, dtype=float).reshape(3, 3)
        if not np.allclose(R.T @ R, np.eye(3), atol=1e-9) or np.linalg.det(R) < 0:
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
        z = z / np.linalg.norm(z)
        s = np.asarray(side, dtype=float)
        y = s - (s @ z) * z
        if np.linalg.norm(y) < 1e-9:
            s = np.array([1.0, 0.0, 0.0])
            y = s - (s @ z) * z
        y /= np.linalg.norm(y)
        return cls(np.column_stack([np.cross(y, z), y, z]), origin)

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
