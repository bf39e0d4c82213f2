"""Hollow tube cross-sections shared by the mass model and the beam finite elements.

Lengths in m; area in m^2; second moments in m^4.  Local section axes: the tube
axis is local z, the section lies in the local x-y plane.
"""

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class RoundSection:
    """Round tube of ``outer_diameter`` and ``wall`` thickness (m); ``wall = D/2`` is a solid bar."""

    outer_diameter: float
    wall: float

    @property
    def inner_diameter(self):
        return self.outer_diameter - 2 * self.wall

    @property
    def area(self):
        """Cross-section area (m^2)."""
        return np.pi / 4 * (self.outer_diameter**2 - self.inner_diameter**2)

    @property
    def second_moment(self):
        """Second moment of area about a diameter, I = pi (D^4 - d^4) / 64 (m^4)."""
        return np.pi / 64 * (self.outer_diameter**4 - self.inner_diameter**4)

    @property
    def polar_moment(self):
        """Polar second moment of area = St Venant torsion constant of a round tube (m^4)."""
        return 2 * self.second_moment


@dataclass(frozen=True)
class SquareSection:
    """Square tube of outer ``side`` and ``wall`` thickness (m), sides along local x and y."""

    side: float
    wall: float

    @property
    def inner_side(self):
        return self.side - 2 * self.wall

    @property
    def area(self):
        """Cross-section area (m^2)."""
        return self.side**2 - self.inner_side**2

    @property
    def second_moment(self):
        """Second moment of area about a centroidal axis parallel to a side (m^4)."""
        return (self.side**4 - self.inner_side**4) / 12

    @property
    def polar_moment(self):
        """Polar second moment of area Ix + Iy (m^4); not the torsion constant."""
        return 2 * self.second_moment
