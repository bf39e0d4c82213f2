"""Solids with exact closed-form mass properties and watertight trimesh meshes.

Every solid lives in its own local frame.  Prismatic solids (cylinder, round
tube, square tube, trapezoidal prism) start at their local origin, the centre of
one end face, and run along +z for their ``length``; the hoop and the box are
centred on their origin.  Lengths in m, density in kg/m^3.

Round sections are tessellated as regular polygons of equal area
(circumradius scaled by sqrt(2 pi / (N sin(2 pi / N)))): mesh volume and mass
are then exact and the polar moment's relative error is (2 pi / N)^4 / 180 to
leading order (5.2e-7 at the default N = 64).

``faceted_with_mass(mass, segments)`` gives the mass properties of that mesh in closed form,
without building it (the mesh route's numbers, to rounding, with neither trimesh nor a mesh):
a regular N-gon of circumradius R has the polar second moment of area
``N R^4 sin(2 pi / N) (2 + cos(2 pi / N)) / 12`` about its centre (N triangles from the
centre, each ``A (|P|^2 + |Q|^2 + P.Q) / 6``), split equally between x and y (a regular polygon
of three or more sides has an isotropic second moment); every other solid's mesh is the solid
itself (flat faces), so its closed form is :meth:`Solid.exact_with_mass`.
"""

from dataclasses import dataclass

import numpy as np

from .inertia import MassProperties

DEFAULT_SEGMENTS = 64
"""Polygon sides of a round section at the default mesh resolution."""


def _positive(**values):
    for name, v in values.items():
        if not (isinstance(v, (int, float, np.floating)) and np.isfinite(v) and v > 0):
            raise ValueError(f"{name} must be a positive number (m), got {v!r}")


def equal_area_circle(radius, segments):
    """(N, 2) vertices of a regular N-gon (counter-clockwise) with the area of a circle of ``radius``."""
    n = segments
    R = radius * np.sqrt(2 * np.pi / (n * np.sin(2 * np.pi / n)))
    a = 2 * np.pi * np.arange(n) / n
    return R * np.column_stack([np.cos(a), np.sin(a)])


def ring_prism(bottom, top, length, inner_bottom=None, inner_top=None):
    """Watertight mesh between two counter-clockwise rings at z = 0 and z = ``length``.

    ``bottom``/``top`` are (N, 2) outer rings; optional inner rings of the same N
    make a hollow prism.  Side faces join vertex i to i+1 of each ring.
    """
    # lazy: trimesh is slow to import (more than numpy); only meshes need it
    import trimesh
    n = len(bottom)
    i = np.arange(n)
    j = (i + 1) % n
    z0, zL = np.zeros((n, 1)), np.full((n, 1), length)
    rings = [np.hstack([bottom, z0]), np.hstack([top, zL])]
    o0, oL = i, i + n
    faces = [np.column_stack([o0, o0[j], oL[j]]), np.column_stack([o0, oL[j], oL])]
    if inner_bottom is None:
        rings.append([[0.0, 0.0, 0.0], [0.0, 0.0, length]])
        c0, cL = 2 * n, 2 * n + 1
        faces += [np.column_stack([np.full(n, c0), o0[j], o0]),
                  np.column_stack([np.full(n, cL), oL, oL[j]])]
    else:
        rings += [np.hstack([inner_bottom, z0]), np.hstack([inner_top, zL])]
        i0, iL = i + 2 * n, i + 3 * n
        faces += [np.column_stack([i0, iL[j], i0[j]]), np.column_stack([i0, iL, iL[j]]),
                  np.column_stack([o0, i0[j], o0[j]]), np.column_stack([o0, i0, i0[j]]),
                  np.column_stack([oL, oL[j], iL[j]]), np.column_stack([oL, iL[j], iL])]
    return trimesh.Trimesh(np.vstack(rings), np.vstack(faces), process=False)


class Solid:
    """Base class: ``volume`` (m^3), ``exact(density)`` and ``mesh(segments)`` in the local frame."""

    kind = "solid"

    def exact(self, density):
        """Closed-form mass properties in the local frame for ``density`` (kg/m^3)."""
        raise NotImplementedError

    def exact_with_mass(self, mass):
        """Closed-form mass properties in the local frame for a total ``mass`` (kg)."""
        return self.exact(mass / self.volume)

    def mesh(self, segments=DEFAULT_SEGMENTS):
        """A watertight trimesh of the solid in the local frame."""
        raise NotImplementedError

    def faceted_with_mass(self, mass, segments=DEFAULT_SEGMENTS):
        """Mass properties in the local frame of :meth:`mesh` (``segments`` sides to a round
        section) for a total ``mass`` (kg), in closed form: the solid's own unless it is round."""
        return self.exact_with_mass(mass)


@dataclass(frozen=True)
class _Annular(Solid):
    """Hollow (or solid, ``inner_radius = 0``) circular prism along z from 0 to ``length``."""

    outer_radius: float
    inner_radius: float
    length: float

    def __post_init__(self):
        _positive(outer_radius=self.outer_radius, length=self.length)
        if not 0 <= self.inner_radius < self.outer_radius:
            raise ValueError(f"inner radius {self.inner_radius!r} must be >= 0 and below the "
                             f"outer radius {self.outer_radius!r} (wall thicker than the radius?)")

    @property
    def volume(self):
        return np.pi * (self.outer_radius**2 - self.inner_radius**2) * self.length

    def _offset(self):
        return 0.0

    def exact(self, density):
        m = density * self.volume
        r2 = self.outer_radius**2 + self.inner_radius**2
        ixx = m * (3 * r2 + self.length**2) / 12
        return MassProperties(m, [0, 0, self.length / 2 + self._offset()], np.diag([ixx, ixx, m * r2 / 2]))

    def faceted_with_mass(self, mass, segments=DEFAULT_SEGMENTS):
        """The mesh's mass properties: equal-area regular polygons (see the module docstring)."""
        theta = 2 * np.pi / segments
        per_r4 = np.pi ** 2 * (2 + np.cos(theta)) / (3 * segments * np.sin(theta))   # J / r^4 of the polygon
        polar = per_r4 * (self.outer_radius ** 4 - self.inner_radius ** 4)           # m^4
        area = np.pi * (self.outer_radius ** 2 - self.inner_radius ** 2)
        ixx = mass * (polar / (2 * area) + self.length ** 2 / 12)
        return MassProperties(mass, [0, 0, self.length / 2 + self._offset()],
                              np.diag([ixx, ixx, mass * polar / area]))

    def mesh(self, segments=DEFAULT_SEGMENTS):
        outer = equal_area_circle(self.outer_radius, segments)
        inner = equal_area_circle(self.inner_radius, segments) if self.inner_radius > 0 else None
        m = ring_prism(outer, outer, self.length, inner, inner)
        m.apply_translation([0, 0, self._offset()])
        return m


@dataclass(frozen=True, init=False)   # frozen like its base: no attribute can be set
class Cylinder(_Annular):
    """Solid cylinder of ``diameter`` and ``length`` (m), from its top face centre along +z."""

    kind = "cylinder"

    def __init__(self, diameter, length):
        _positive(diameter=diameter)
        super().__init__(diameter / 2, 0.0, length)


@dataclass(frozen=True, init=False)   # frozen like its base: no attribute can be set
class RoundTube(_Annular):
    """Hollow round tube: ``outer_diameter``, ``wall``, ``length`` (m), along +z."""

    kind = "round_tube"

    def __init__(self, outer_diameter, wall, length):
        _positive(outer_diameter=outer_diameter, wall=wall)
        super().__init__(outer_diameter / 2, outer_diameter / 2 - wall, length)


@dataclass(frozen=True, init=False)   # frozen like its base: no attribute can be set
class Hoop(_Annular):
    """Annular disc (wheel hoop): ``inner_diameter`` (0 = full disc), ``outer_diameter``,
    ``thickness`` (m) along z, centred on its origin (the hub centre)."""

    kind = "hoop"

    def __init__(self, inner_diameter, outer_diameter, thickness):
        _positive(outer_diameter=outer_diameter, thickness=thickness)
        super().__init__(outer_diameter / 2, inner_diameter / 2, thickness)

    def _offset(self):
        return -self.length / 2


@dataclass(frozen=True)
class SquareTube(Solid):
    """Hollow square tube: outer ``side``, ``wall``, ``length`` (m), sides along local x and y."""

    side: float
    wall: float
    length: float
    kind = "square_tube"

    def __post_init__(self):
        _positive(side=self.side, wall=self.wall, length=self.length)
        if not self.wall < self.side / 2:
            raise ValueError(f"wall {self.wall!r} must be thinner than half the side {self.side!r}")

    @property
    def inner_side(self):
        return self.side - 2 * self.wall

    @property
    def volume(self):
        return (self.side**2 - self.inner_side**2) * self.length

    def exact(self, density):
        L, s, si = self.length, self.side, self.inner_side
        mo, mi = density * s * s * L, density * si * si * L
        ixx = (mo * (s**2 + L**2) - mi * (si**2 + L**2)) / 12
        izz = (mo * s**2 - mi * si**2) / 6
        return MassProperties(mo - mi, [0, 0, L / 2], np.diag([ixx, ixx, izz]))

    def mesh(self, segments=DEFAULT_SEGMENTS):
        sq = np.array([[1, 1], [-1, 1], [-1, -1], [1, -1]], dtype=float) / 2
        return ring_prism(sq * self.side, sq * self.side, self.length, sq * self.inner_side, sq * self.inner_side)


@dataclass(frozen=True)
class TrapezoidalPrism(Solid):
    """Prism along +z from 0 to ``length``: constant ``depth`` along x, width along y
    varying linearly from ``width_top`` (z = 0) to ``width_bottom`` (z = length); the
    thesis torso (depth 253 mm, width 366 mm at the shoulders, 253 mm at the hips)."""

    depth: float
    width_top: float
    width_bottom: float
    length: float
    kind = "trapezoidal_prism"

    def __post_init__(self):
        _positive(depth=self.depth, width_top=self.width_top,
                  width_bottom=self.width_bottom, length=self.length)

    @property
    def volume(self):
        return self.depth * self.length * (self.width_top + self.width_bottom) / 2

    def exact(self, density):
        d, L, a = self.depth, self.length, self.width_top
        b = (self.width_bottom - a) / L                # width slope dw/dz
        rho_d = density * d
        m = rho_d * L * (a + b * L / 2)
        mz = rho_d * (a * L**2 / 2 + b * L**3 / 3)     # integral z dm
        mzz = rho_d * (a * L**3 / 3 + b * L**4 / 4)    # integral z^2 dm
        mxx = rho_d * d**2 / 12 * L * (a + b * L / 2)  # integral x^2 dm
        w0, w1 = a, a + b * L
        # integral y^2 dm = rho d / 12 * integral w^3 dz; w^3 integrated exactly (Simpson is exact)
        myy = rho_d / 12 * L / 6 * (w0**3 + 4 * ((w0 + w1) / 2) ** 3 + w1**3)
        zc = mz / m
        czz = mzz - m * zc**2
        return MassProperties(m, [0, 0, zc], np.diag([myy + czz, mxx + czz, mxx + myy]))

    def mesh(self, segments=DEFAULT_SEGMENTS):
        unit = np.array([[1, 1], [-1, 1], [-1, -1], [1, -1]], dtype=float) / 2
        top = unit * [self.depth, self.width_top]
        bottom = unit * [self.depth, self.width_bottom]
        return ring_prism(top, bottom, self.length)


@dataclass(frozen=True)
class Box(Solid):
    """Rectangular block of sizes ``size_x``, ``size_y``, ``size_z`` (m), centred on its origin."""

    size_x: float
    size_y: float
    size_z: float
    kind = "box"

    def __post_init__(self):
        _positive(size_x=self.size_x, size_y=self.size_y, size_z=self.size_z)

    @property
    def volume(self):
        return self.size_x * self.size_y * self.size_z

    def exact(self, density):
        m = density * self.volume
        a, b, c = self.size_x**2, self.size_y**2, self.size_z**2
        return MassProperties(m, np.zeros(3), np.diag([b + c, a + c, a + b]) * m / 12)

    def mesh(self, segments=DEFAULT_SEGMENTS):
        # lazy: trimesh is slow to import (more than numpy); only meshes need it
        import trimesh.creation
        return trimesh.creation.box(extents=[self.size_x, self.size_y, self.size_z])


@dataclass(frozen=True)
class PointMass(Solid):
    """A point at the origin: mass only, no volume, no mesh."""

    kind = "point_mass"
    volume = 0.0

    def exact_with_mass(self, mass):
        return MassProperties.point(mass, np.zeros(3))

    def mesh(self, segments=DEFAULT_SEGMENTS):
        return None


@dataclass(frozen=True, eq=False)
class Lumped(Solid):
    """A body known only by its mass properties (measured or published), in its local frame."""

    properties: MassProperties
    kind = "lumped"
    volume = 0.0

    def exact_with_mass(self, mass):
        return self.properties

    def mesh(self, segments=DEFAULT_SEGMENTS):
        return None
