"""Frame tubes as plain data: what the mass model and the beam finite elements share.

A :class:`Tube` runs from one keypoint to another (benchmark frame, m) with a
cross-section and a material.  A :class:`Structure` names the tubes that carry
load in the rear-frame finite-element model and the keypoints where it is held.
"""

from dataclasses import dataclass

import numpy as np

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

    @property
    def length(self):
        """Centre-line length (m)."""
        return float(np.linalg.norm(self.end - self.start))


@dataclass(frozen=True)
class Structure:
    """The rear-frame beam model's topology: structural tubes and support keypoints."""

    tubes: tuple
    dropouts: tuple
    """Keypoint names clamped for 'fix rear' and for the stiffness S."""
    head_tube: tuple
    """Keypoint names (top, bottom) of the head tube; S acts at the bottom one."""
    keypoints: dict
    """``{name: position (m)}`` of every keypoint the tubes use."""
