"""Frame tubes as plain data: what the mass model and the beam finite elements share.

A :class:`Tube` runs from one keypoint to another (benchmark frame, m) with a
cross-section and a material.  A :class:`Structure` names the tubes that carry
load in the rear-frame finite-element model and the keypoints where it is held.
"""

from dataclasses import dataclass

import numpy as np

from ..core.frozen import frozen_fields, readonly
from .materials import Material
from .sections import RoundSection, SquareSection


@dataclass(frozen=True)
class Tube:
    """A straight tube between keypoints ``start_key`` -> ``end_key`` (positions in m)."""

    name: str
    start_key: str
    end_key: str
    start: np.ndarray
    end: np.ndarray
    section: RoundSection | SquareSection
    material: Material
    body: str

    def __post_init__(self):
        object.__setattr__(self, "start", readonly(self.start, float))
        object.__setattr__(self, "end", readonly(self.end, float))

    def __repr__(self):
        return f"Tube({self.name!r}, {self.start_key} -> {self.end_key}, {self.length:.4f} m, {self.material.key})"

    @property
    def length(self):
        """Centre-line length (m)."""
        return float(np.linalg.norm(self.end - self.start))


@dataclass(frozen=True)
class Structure:
    """The rear-frame beam model's topology: structural tubes and support keypoints.

    Examples
    --------
    >>> import bikemass as bm
    >>> structure = bm.frame_structure("jamis")
    >>> print(type(structure).__name__, len(structure.tubes) > 0, structure.dropouts)
    Structure True ('dropout_left', 'dropout_right')
    """

    tubes: tuple
    dropouts: tuple
    """Keypoint names clamped for 'fix rear' and for the stiffness S."""
    head_tube: tuple
    """Keypoint names (top, bottom) of the head tube; S acts at the bottom one."""
    keypoints: dict
    """``{name: position (m)}`` of every keypoint the tubes use."""

    def __post_init__(self):
        frozen_fields(self, "tubes", "dropouts", "head_tube", "keypoints")

    def __repr__(self):
        return (f"Structure(tubes={len(self.tubes)}, dropouts={self.dropouts}, head_tube={self.head_tube}, "
                f"keypoints={len(self.keypoints)})")
