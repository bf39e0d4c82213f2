"""Parts (a solid, its mass and its placement) and their combination into one body.

A body's mass properties are computed from the parts' trimesh meshes by default
(``method="mesh"``) or from the closed-form solids (``method="exact"``).
Overlapping parts are summed, as a CAD assembly and the thesis do
(``overlap="sum"``), or counted once (``overlap="union"``: each part keeps only
the volume not already taken by the parts before it, computed with manifold3d).
"""

from dataclasses import dataclass, field

import numpy as np

from .inertia import MassProperties, combine
from .placement import Placement
from .solids import DEFAULT_SEGMENTS

METHODS = ("mesh", "exact")
OVERLAPS = ("sum", "union")


@dataclass(frozen=True, eq=False)
class Part:
    """A placed solid of given ``mass`` (kg); ``body`` names the rigid body it belongs to."""

    name: str
    solid: object
    mass: float
    placement: Placement = field(default_factory=Placement.identity)
    body: str = ""

    def __repr__(self):
        return f"Part({self.name!r}, body={self.body!r}, mass={self.mass:.6g} kg, solid={type(self.solid).__name__})"

    @classmethod
    def from_density(cls, name, solid, density, placement=None, body=""):
        """A part of uniform ``density`` (kg/m^3)."""
        return cls(name, solid, density * solid.volume, placement or Placement.identity(), body)

    @property
    def density(self):
        """kg/m^3 (infinite for point masses and lumped bodies)."""
        return self.mass / self.solid.volume if self.solid.volume else np.inf

    def exact(self):
        """Closed-form mass properties in the bicycle frame."""
        local = self.solid.exact_with_mass(self.mass)
        return local.transformed(self.placement.rotation, self.placement.translation)

    def mesh(self, segments=DEFAULT_SEGMENTS):
        """The placed watertight mesh, or ``None`` for point masses and lumped bodies."""
        m = self.solid.mesh(segments)
        if m is not None:
            m.apply_transform(self.placement.matrix())
        return m

    def mass_properties(self, method="mesh", segments=DEFAULT_SEGMENTS):
        """Mass properties in the bicycle frame of the solid's mesh (``method="mesh"``: round
        sections as ``segments``-sided polygons) or of the solid itself (``"exact"``), both in
        closed form (:meth:`~bikemass.mass.solids.Solid.faceted_with_mass`; the trimesh of the
        mesh gives the same numbers, tests/test_solids.py, without being built here)."""
        if method == "mesh":
            local = self.solid.faceted_with_mass(self.mass, segments)
        else:
            local = self.solid.exact_with_mass(self.mass)
        return local.transformed(self.placement.rotation, self.placement.translation)


def body_properties(parts, method="mesh", overlap="sum", segments=DEFAULT_SEGMENTS):
    """Combined mass properties of ``parts`` (see the module docstring for the options)."""
    parts = list(parts)
    if overlap == "sum":
        return combine(p.mass_properties(method, segments) for p in parts)
    return combine(_union_pieces(parts, segments))


def _union_pieces(parts, segments):
    """Each part's mass properties minus the volume already held by earlier parts."""
    # lazy: trimesh (and manifold3d behind its booleans) is slow to import; only overlap=union needs it
    import trimesh.boolean
    pieces, taken = [], None
    for p in parts:
        mesh = p.mesh(segments)
        if mesh is None:
            pieces.append(p.exact())
            continue
        own = mesh if taken is None else trimesh.boolean.difference([mesh, taken], engine="manifold")
        if own.volume > 0:
            pieces.append(MassProperties.from_trimesh(own, p.density))
        taken = mesh if taken is None else trimesh.boolean.union([taken, mesh], engine="manifold")
    return pieces
